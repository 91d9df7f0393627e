use super::*;
use crate::plan_json::GeoReport;
use crate::PlanAbout;
use tidepath::geom::Vec3;
use tidepath::planner::{Plan, SearchGraph, SearchStats, Status};

/// A report with a small tree (mission 0) and a small roadmap (mission 1), named with markup.
fn report() -> PlanReport {
    let tree = SearchGraph {
        mission: 0,
        kind: "tree",
        vertices: vec![Vec3::new(0.0, 0.0, -5.0), Vec3::new(3.0, 4.0, -5.0), Vec3::new(0.1, -2.5, 1e-9)],
        edges: vec![[0, 1], [0, 2]],
        start: Some(0),
        goal: Some(1),
    };
    let roadmap = SearchGraph {
        mission: 1,
        kind: "roadmap",
        vertices: vec![Vec3::new(10.0, 0.0, 0.0), Vec3::new(10.0, 7.0, 0.0)],
        edges: vec![[1, 0]],
        start: Some(0),
        goal: None,
    };
    let plan = Plan {
        planner: "toy".into(),
        status: Status::Feasible,
        reason: String::new(),
        missions: Vec::new(),
        cost: 0.0,
        stats: SearchStats::default(),
        graphs: vec![tree, roadmap],
        fleet: None,
    };
    let mut r = PlanReport::new(&plan, PlanAbout { scenario: "s & <t>".into(), ..PlanAbout::default() });
    r.graphs[0].mission = "alpha <1> & \"b\"".into();
    r.graphs[1].mission = "beta".into();
    r
}

#[test]
fn graphml_reads_back_with_its_counts_roles_and_weights() {
    let r = report();
    let text = graphml(&r).unwrap();
    assert!(text.starts_with("<?xml version=\"1.0\" encoding=\"UTF-8\"?>"), "{text}");
    assert_eq!(text.matches("<node ").count(), 5);
    assert_eq!(text.matches("<edge ").count(), 3);
    assert!(text.contains("<graph id=\"alpha &lt;1&gt; &amp; &quot;b&quot;\" edgedefault=\"directed\">"), "{text}");
    assert!(text.contains("<graph id=\"beta\" edgedefault=\"undirected\">"), "{text}");
    // Node ids are unique in the document: the roadmap's continue after the tree's.
    assert!(text.contains("<edge source=\"n4\" target=\"n3\">"), "{text}");
    assert!(text.contains("<data key=\"weight\">5</data>"), "{text}");
    let back = read_graphml(&text, "g.graphml").unwrap();
    assert_eq!(back, r.graphs);
    assert_eq!(back[0].edge_length([0, 1]), 5.0);
}

#[test]
fn json_reads_back() {
    let r = report();
    let text = json(&r);
    let v: serde_json::Value = serde_json::from_str(&text).unwrap();
    assert_eq!(v["frame"], "metres");
    assert_eq!(v["missions"][0]["start"], 0);
    assert_eq!(v["missions"][1]["goal"], serde_json::Value::Null);
    assert_eq!(v["missions"][0]["edges"][1], serde_json::json!([0, 2]));
    assert_eq!(read_json(&text, "g.json").unwrap(), r.graphs);
}

#[test]
fn a_geographic_report_gives_vertices_in_degrees_too() {
    let mut r = report();
    r.geographic = Some(GeoReport {
        projection: "azimuthal-equidistant-wgs84".into(),
        origin_lon: -124.0,
        origin_lat: 48.0,
        epoch: None,
        paths: Vec::new(),
        flown: None,
    });
    for g in &mut r.graphs {
        g.lonlat = Some(g.vertices.iter().map(|p| [-124.0 + p[0] * 1e-5, 48.0 + p[1] * 1e-5, -p[2]]).collect());
    }
    let xml = graphml(&r).unwrap();
    assert!(xml.contains("<key id=\"lon\" for=\"node\" attr.name=\"lon\" attr.type=\"double\"/>"), "{xml}");
    assert_eq!(read_graphml(&xml, "g").unwrap(), r.graphs);
    let js = json(&r);
    assert!(js.contains("\"geographic\": {\"projection\": \"azimuthal-equidistant-wgs84\""), "{js}");
    assert_eq!(read_json(&js, "g").unwrap(), r.graphs);
}

#[test]
fn graphs_stay_out_of_the_plan_file() {
    let r = report();
    let text = r.to_json();
    assert!(!text.contains("vertices") && !text.contains("\"graphs\""), "{text}");
}

#[test]
fn only_graphml_and_json_are_graph_formats() {
    assert_eq!(GraphFormat::of(Path::new("a/b.GraphML"), "--graph").unwrap(), GraphFormat::GraphMl);
    assert_eq!(GraphFormat::of(Path::new("b.json"), "--graph").unwrap(), GraphFormat::Json);
    let e = GraphFormat::of(Path::new("b.svg"), "--graph").unwrap_err().to_string();
    assert_eq!(e, "--graph: 'b.svg': unknown extension (known: .graphml, .json)");
}

#[test]
fn bad_files_are_refused_in_one_line() {
    let r = report();
    let xml = graphml(&r).unwrap();
    let cut = &xml[..xml.len() / 2];
    assert!(read_graphml(cut, "g").is_err());
    let e = read_graphml(&xml.replace("target=\"n3\"", "target=\"n1\""), "g").unwrap_err().to_string();
    assert!(e.contains("of another graph"), "{e}");
    let js = json(&r).replace("[0, 2]", "[0, 9]");
    let e = read_json(&js, "g.json").unwrap_err().to_string();
    assert!(e.contains("past the last of 3"), "{e}");
}
