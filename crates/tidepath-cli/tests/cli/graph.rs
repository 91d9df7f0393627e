//! `plan --graph FILE`: the search graph of a planner that builds one, as GraphML or JSON by
//! the extension, written with the run's other outputs (all or none) and drawn faintly on the
//! `--plot` figure; a flag the run cannot honour is refused before planning, naming it, with
//! nothing written.

use std::path::Path;
use std::process::{Command, Output};

use tidepath_io::graph_file::{read_graphml, read_json};
use tidepath_io::GraphReport;

fn tidepath(args: &[&str], cwd: &Path) -> Output {
    Command::new(env!("CARGO_BIN_EXE_tidepath")).args(args).current_dir(cwd).output().expect("tidepath runs")
}

fn stderr(o: &Output) -> String {
    String::from_utf8_lossy(&o.stderr).into_owned()
}

/// The run's files: (name, contents) of everything in `dir`, temporaries included.
fn files(dir: &Path) -> Vec<(String, String)> {
    let mut out: Vec<(String, String)> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| {
            let e = e.unwrap();
            (e.file_name().to_string_lossy().into_owned(), std::fs::read_to_string(e.path()).unwrap_or_default())
        })
        .collect();
    out.sort();
    out
}

/// Exit 2 with one line on stderr naming every one of `words`, and the folder as it was.
fn refused(args: &[&str], dir: &Path, words: &[&str]) {
    let before = files(dir);
    let o = tidepath(args, dir);
    let e = stderr(&o);
    assert_eq!(o.status.code(), Some(2), "{args:?}: {e}");
    assert_eq!(e.trim_end().lines().count(), 1, "{e}");
    for w in words {
        assert!(e.contains(w), "{args:?}: expected {w:?} in {e}");
    }
    assert_eq!(files(dir), before, "{args:?} changed the folder");
}

const RRT: [&str; 6] = ["plan", "headland", "--planner", "rrt-star", "--samples", "300"];

#[test]
fn graphml_and_json_carry_the_same_tree_and_the_figure_draws_it() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let o = tidepath(&[&RRT[..], &["--graph", "t.graphml", "--plot", "p.svg", "--out", "p.json"]].concat(), d);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let xml = std::fs::read_to_string(d.join("t.graphml")).unwrap();
    let from_xml = read_graphml(&xml, "t.graphml").unwrap();
    assert_eq!(from_xml.len(), 1);
    let g = &from_xml[0];
    assert_eq!((g.mission.as_str(), g.kind.as_str()), ("mission", "tree"));
    assert_eq!(xml.matches("<node ").count(), g.vertices.len());
    assert_eq!(xml.matches("<edge ").count(), g.edges.len());
    assert!(xml.contains("<graph id=\"mission\" edgedefault=\"directed\">"));
    assert_eq!(g.edges.len() + 1, g.vertices.len(), "a tree has one edge fewer than vertices");
    // The figure draws it, and says how big it is; the plan file does not carry it.
    let svg = std::fs::read_to_string(d.join("p.svg")).unwrap();
    assert!(svg.contains(&format!("search tree ({} vertices)", g.vertices.len())), "no graph legend");
    assert!(!std::fs::read_to_string(d.join("p.json")).unwrap().contains("vertices"));
    // The same run (same seed) as JSON: the same graph.
    let o = tidepath(&[&RRT[..], &["--graph", "t.json"]].concat(), d);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let text = std::fs::read_to_string(d.join("t.json")).unwrap();
    let v: serde_json::Value = serde_json::from_str(&text).unwrap();
    assert_eq!((v["version"].as_u64(), v["frame"].as_str()), (Some(1), Some("metres")));
    assert_same(&read_json(&text, "t.json").unwrap(), &from_xml);
}

/// The same graphs, coordinates to the last bit or so: serde_json's default number parser
/// (tidepath's build) may round the last bit of a double the writer gave exactly.
fn assert_same(a: &[GraphReport], b: &[GraphReport]) {
    assert_eq!(a.len(), b.len());
    for (g, h) in a.iter().zip(b) {
        assert_eq!((&g.mission, &g.kind, &g.edges, g.start, g.goal), (&h.mission, &h.kind, &h.edges, h.start, h.goal));
        assert_eq!(g.vertices.len(), h.vertices.len());
        for (p, q) in g.vertices.iter().zip(&h.vertices) {
            assert!(p.iter().zip(q).all(|(x, y)| (x - y).abs() <= 1e-12 * x.abs().max(1.0)), "{p:?} != {q:?}");
        }
    }
}

#[test]
fn plot_graph_draws_the_graph_without_a_file() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let prm = ["plan", "headland", "--planner", "prm-star", "--samples", "300"];
    let o = tidepath(&[&prm[..], &["--plot-graph", "--plot", "p.svg"]].concat(), d);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let svg = std::fs::read_to_string(d.join("p.svg")).unwrap();
    assert!(svg.contains("roadmap (") && svg.contains(" edges)"), "no roadmap legend");
    assert_eq!(files(d).len(), 1);
    // Without the flag the figure has no graph.
    let o = tidepath(&[&RRT[..], &["--plot", "q.svg"]].concat(), d);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    assert!(!std::fs::read_to_string(d.join("q.svg")).unwrap().contains("search tree"));
}

#[test]
fn an_unknown_extension_is_refused_naming_the_flag_and_the_file() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    refused(&[&RRT[..], &["--graph", "g.svg", "--out", "p.json"]].concat(), d, &["--graph", "g.svg", ".graphml"]);
    refused(&[&RRT[..], &["--graph", "g"]].concat(), d, &["--graph", "'g'"]);
}

#[test]
fn a_planner_without_a_graph_is_refused_before_planning() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let astar = ["plan", "headland", "--planner", "astar"];
    refused(&[&astar[..], &["--graph", "g.graphml", "--out", "p.json"]].concat(), d, &["--graph", "astar", "rrt-star"]);
    refused(&[&astar[..], &["--plot-graph", "--plot", "p.svg"]].concat(), d, &["--plot-graph", "astar"]);
    // --plot-graph draws on the figure: without one it means nothing.
    refused(&[&RRT[..], &["--plot-graph", "--out", "p.json"]].concat(), d, &["--plot-graph", "--plot"]);
}

#[test]
fn a_failed_run_leaves_no_graph_and_keeps_an_old_one() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    // Refused before planning: the --out folder does not exist.
    refused(&[&RRT[..], &["--graph", "g.graphml", "--out", "nope/p.json"]].concat(), d, &["--out", "nope"]);
    // An old graph file stays as it was when another output fails.
    std::fs::write(d.join("g.json"), "old").unwrap();
    refused(&[&RRT[..], &["--graph", "g.json", "--plot", "nope/p.svg"]].concat(), d, &["--plot", "nope"]);
    refused(&[&RRT[..], &["--graph", "g.json", "--samples", "0"]].concat(), d, &["--samples"]);
    assert_eq!(std::fs::read_to_string(d.join("g.json")).unwrap(), "old");
}
