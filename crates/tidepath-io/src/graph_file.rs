//! A planner's search graphs (its tree or roadmap, one per mission) as `plan --graph FILE`
//! writes them, in the format of the extension:
//!
//! * `.graphml`: GraphML, as OMPL's `PlannerData::printGraphML` writes it, for Gephi, yEd,
//!   networkx or igraph: one `<graph>` per mission whose `id` is the mission's name, directed
//!   for a tree (every edge from parent to child), undirected for a roadmap; nodes carry `x`,
//!   `y`, `z` (doubles, metres; OMPL writes one `coords` string instead) and `role` (`start`,
//!   `goal` or `none`), edges a `weight`: their Euclidean length in metres. Node ids are `n0`,
//!   `n1`, ... numbered through the whole file, as GraphML wants them unique in the document:
//!   with one mission `nK` is vertex K.
//! * `.json`: `{"format": "tidepath-graph", "version": 1, "frame": "metres", "missions":
//!   [{"mission", "kind", "start", "goal", "vertices": [[x, y, z], ...], "edges": [[i, j],
//!   ...]}]}`, indices counted from 0 within each mission.
//!
//! Coordinates are in the scenario's frame (x east, y north, z up, metres). A geographic
//! scenario's file also gives each vertex in longitude, latitude and depth (positive down):
//! GraphML nodes get `lon`, `lat`, `depth` keys, JSON missions a `lonlat` list beside
//! `vertices`, and the file says where its metres are (`geographic`: projection and origin),
//! as the plan file does.
//!
//! The readers ([`read_json`], [`read_graphml`]) give back what the writers wrote, for tests
//! and tools; they check indices and numbers, not everything a hand-made file could hold.
//!
//! A graph can have 100 000 edges and more: the plan file never carries it, only the file
//! `--graph` names (GraphML of 100 000 vertices is about 25 MB).

use std::collections::HashMap;
use std::path::Path;

use quick_xml::events::{BytesDecl, BytesEnd, BytesStart, BytesText, Event};
use serde::Deserialize;

use crate::{GraphReport, PlanReport};
use tidepath::error::{Error, Result};

/// The version of the JSON graph file this build writes.
pub const GRAPH_FORMAT_VERSION: u32 = 1;

/// The extensions `--graph` takes.
pub const EXTENSIONS: &str = ".graphml, .json";

const GRAPHML_NS: &str = "http://graphml.graphdrawing.org/xmlns";

/// The graph file formats, by extension.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum GraphFormat {
    GraphMl,
    Json,
}

impl GraphFormat {
    /// The format of an output path by its extension; `flag` names the option in errors.
    pub fn of(path: &Path, flag: &str) -> Result<Self> {
        let ext = path.extension().and_then(|e| e.to_str()).unwrap_or("").to_ascii_lowercase();
        match ext.as_str() {
            "graphml" => Ok(GraphFormat::GraphMl),
            "json" => Ok(GraphFormat::Json),
            _ => Err(Error::input(flag, format!("'{}': unknown extension (known: {EXTENSIONS})", path.display()))),
        }
    }
}

/// The report's search graphs in `format`.
pub fn write(report: &PlanReport, format: GraphFormat) -> Result<String> {
    match format {
        GraphFormat::GraphMl => graphml(report),
        GraphFormat::Json => Ok(json(report)),
    }
}

/// A number as JSON: shortest text that reads back to the same double; `null` if not finite.
fn json_num(v: f64) -> String {
    serde_json::to_string(&v).expect("a number serialises")
}

fn json_str(s: &str) -> String {
    serde_json::to_string(s).expect("a string serialises")
}

fn json_opt(v: Option<u32>) -> String {
    v.map_or("null".to_string(), |v| v.to_string())
}

/// A list, one item per line (a graph's lists are long; one number per line would be longer).
fn json_rows<T>(out: &mut String, key: &str, rows: &[T], row: impl Fn(&T) -> String, last: bool) {
    let end = if last { "" } else { "," };
    if rows.is_empty() {
        out.push_str(&format!("      \"{key}\": []{end}\n"));
        return;
    }
    out.push_str(&format!("      \"{key}\": [\n"));
    for (k, r) in rows.iter().enumerate() {
        out.push_str("        ");
        out.push_str(&row(r));
        out.push_str(if k + 1 < rows.len() { ",\n" } else { "\n" });
    }
    out.push_str(&format!("      ]{end}\n"));
}

fn triple(p: &[f64; 3]) -> String {
    format!("[{}, {}, {}]", json_num(p[0]), json_num(p[1]), json_num(p[2]))
}

/// The JSON graph file (see the module documentation).
pub fn json(report: &PlanReport) -> String {
    let mut out = String::from("{\n");
    out.push_str("  \"format\": \"tidepath-graph\",\n");
    out.push_str(&format!("  \"version\": {GRAPH_FORMAT_VERSION},\n"));
    out.push_str("  \"frame\": \"metres\",\n");
    out.push_str(&format!("  \"planner\": {},\n", json_str(&report.planner)));
    out.push_str(&format!("  \"scenario\": {},\n", json_str(&report.scenario)));
    out.push_str(&format!("  \"seed\": {},\n", report.seed));
    if let Some(g) = &report.geographic {
        out.push_str(&format!(
            "  \"geographic\": {{\"projection\": {}, \"origin_lon\": {}, \"origin_lat\": {}}},\n",
            json_str(&g.projection),
            json_num(g.origin_lon),
            json_num(g.origin_lat)
        ));
    }
    if report.graphs.is_empty() {
        out.push_str("  \"missions\": []\n}\n");
        return out;
    }
    out.push_str("  \"missions\": [\n");
    for (k, g) in report.graphs.iter().enumerate() {
        out.push_str("    {\n");
        out.push_str(&format!("      \"mission\": {},\n", json_str(&g.mission)));
        out.push_str(&format!("      \"kind\": {},\n", json_str(&g.kind)));
        out.push_str(&format!("      \"start\": {},\n", json_opt(g.start)));
        out.push_str(&format!("      \"goal\": {},\n", json_opt(g.goal)));
        json_rows(&mut out, "vertices", &g.vertices, triple, false);
        if let Some(ll) = &g.lonlat {
            json_rows(&mut out, "lonlat", ll, triple, false);
        }
        json_rows(&mut out, "edges", &g.edges, |e| format!("[{}, {}]", e[0], e[1]), true);
        out.push_str(if k + 1 < report.graphs.len() { "    },\n" } else { "    }\n" });
    }
    out.push_str("  ]\n}\n");
    out
}

type Xml = quick_xml::Writer<Vec<u8>>;

fn xml_error(e: std::io::Error) -> Error {
    Error::input("--graph", format!("writing GraphML: {e}"))
}

fn xml_start(w: &mut Xml, tag: &str, attrs: &[(&str, &str)], empty: bool) -> Result<()> {
    let mut e = BytesStart::new(tag);
    for (k, v) in attrs {
        // The writer escapes markup (`&`, `<`, `"`, ...); characters XML cannot hold at all
        // are written as visible escapes.
        e.push_attribute((*k, crate::export::xml_text(v).as_str()));
    }
    w.write_event(if empty { Event::Empty(e) } else { Event::Start(e) }).map_err(xml_error)
}

fn xml_end(w: &mut Xml, tag: &str) -> Result<()> {
    w.write_event(Event::End(BytesEnd::new(tag))).map_err(xml_error)
}

/// `<data key="KEY">VALUE</data>`.
fn xml_data(w: &mut Xml, key: &str, value: &str) -> Result<()> {
    w.create_element("data")
        .with_attribute(("key", key))
        .write_text_content(BytesText::new(&crate::export::xml_text(value)))
        .map_err(xml_error)?;
    Ok(())
}

/// A double as GraphML (XML Schema `double`) writes it: the shortest text that reads back to
/// the same value; `NaN`, `INF`, `-INF` for the others.
fn xml_double(v: f64) -> String {
    if v.is_nan() {
        "NaN".into()
    } else if v.is_infinite() {
        if v > 0.0 { "INF" } else { "-INF" }.into()
    } else {
        format!("{v}")
    }
}

/// The GraphML file (see the module documentation).
pub fn graphml(report: &PlanReport) -> Result<String> {
    let mut w = quick_xml::Writer::new_with_indent(Vec::new(), b' ', 1);
    w.write_event(Event::Decl(BytesDecl::new("1.0", Some("UTF-8"), None))).map_err(xml_error)?;
    xml_start(
        &mut w,
        "graphml",
        &[
            ("xmlns", GRAPHML_NS),
            ("xmlns:xsi", "http://www.w3.org/2001/XMLSchema-instance"),
            (
                "xsi:schemaLocation",
                "http://graphml.graphdrawing.org/xmlns http://graphml.graphdrawing.org/xmlns/1.0/graphml.xsd",
            ),
        ],
        false,
    )?;
    let geographic = report.geographic.as_ref().filter(|_| report.graphs.iter().any(|g| g.lonlat.is_some()));
    let mut desc = format!(
        "tidepath search graphs: planner {}, scenario {}, seed {}; x, y, z in metres (x east, y north, z up); edge weight: Euclidean length (m)",
        report.planner, report.scenario, report.seed
    );
    if let Some(g) = geographic {
        desc.push_str(&format!(
            "; lon, lat in degrees and depth in m (positive down), {} about {}, {}",
            g.projection, g.origin_lon, g.origin_lat
        ));
    }
    w.create_element("desc").write_text_content(BytesText::new(&crate::export::xml_text(&desc))).map_err(xml_error)?;
    let mut keys: Vec<(&str, &str, &str)> =
        vec![("x", "node", "double"), ("y", "node", "double"), ("z", "node", "double")];
    if geographic.is_some() {
        keys.extend([("lon", "node", "double"), ("lat", "node", "double"), ("depth", "node", "double")]);
    }
    keys.extend([("weight", "edge", "double"), ("kind", "graph", "string")]);
    for (id, what, ty) in &keys {
        xml_start(&mut w, "key", &[("id", id), ("for", what), ("attr.name", id), ("attr.type", ty)], true)?;
    }
    xml_start(
        &mut w,
        "key",
        &[("id", "role"), ("for", "node"), ("attr.name", "role"), ("attr.type", "string")],
        false,
    )?;
    w.create_element("default").write_text_content(BytesText::new("none")).map_err(xml_error)?;
    xml_end(&mut w, "key")?;
    let mut first = 0usize;
    for g in &report.graphs {
        let edgedefault = if g.directed() { "directed" } else { "undirected" };
        xml_start(&mut w, "graph", &[("id", &g.mission), ("edgedefault", edgedefault)], false)?;
        xml_data(&mut w, "kind", &g.kind)?;
        for (i, p) in g.vertices.iter().enumerate() {
            let id = format!("n{}", first + i);
            xml_start(&mut w, "node", &[("id", &id)], false)?;
            xml_data(&mut w, "x", &xml_double(p[0]))?;
            xml_data(&mut w, "y", &xml_double(p[1]))?;
            xml_data(&mut w, "z", &xml_double(p[2]))?;
            if let Some(q) = g.lonlat.as_ref().and_then(|ll| ll.get(i)).filter(|_| geographic.is_some()) {
                xml_data(&mut w, "lon", &xml_double(q[0]))?;
                xml_data(&mut w, "lat", &xml_double(q[1]))?;
                xml_data(&mut w, "depth", &xml_double(q[2]))?;
            }
            let role = if g.start == Some(i as u32) {
                "start"
            } else if g.goal == Some(i as u32) {
                "goal"
            } else {
                "none"
            };
            xml_data(&mut w, "role", role)?;
            xml_end(&mut w, "node")?;
        }
        for e in &g.edges {
            let (s, t) = (format!("n{}", first + e[0] as usize), format!("n{}", first + e[1] as usize));
            xml_start(&mut w, "edge", &[("source", &s), ("target", &t)], false)?;
            xml_data(&mut w, "weight", &xml_double(g.edge_length(*e)))?;
            xml_end(&mut w, "edge")?;
        }
        xml_end(&mut w, "graph")?;
        first += g.vertices.len();
    }
    xml_end(&mut w, "graphml")?;
    let mut text = String::from_utf8(w.into_inner()).expect("the writer writes the UTF-8 it is given");
    text.push('\n');
    Ok(text)
}

/// One mission of a JSON graph file.
#[derive(Deserialize)]
struct RawMission {
    mission: String,
    kind: String,
    start: Option<u32>,
    goal: Option<u32>,
    vertices: Vec<[f64; 3]>,
    #[serde(default)]
    lonlat: Option<Vec<[f64; 3]>>,
    edges: Vec<[u32; 2]>,
}

#[derive(Deserialize)]
struct RawGraphFile {
    format: String,
    version: u32,
    frame: String,
    missions: Vec<RawMission>,
}

/// Refuses a graph whose indices point past its vertices.
fn check_indices(g: &GraphReport, source: &str) -> Result<()> {
    let n = g.vertices.len();
    let bad = |i: u32| i as usize >= n;
    if let Some(e) = g.edges.iter().find(|e| bad(e[0]) || bad(e[1])) {
        return Err(Error::input(
            source,
            format!("mission '{}': edge {e:?} names a vertex past the last of {n}", g.mission),
        ));
    }
    if let Some(i) = [g.start, g.goal].into_iter().flatten().find(|&i| bad(i)) {
        return Err(Error::input(source, format!("mission '{}': vertex {i} is past the last of {n}", g.mission)));
    }
    Ok(())
}

/// The graphs of a JSON graph file. The numbers are the writer's to the last bit or so:
/// serde_json's default number parser may round a double's last bit.
pub fn read_json(text: &str, source: &str) -> Result<Vec<GraphReport>> {
    let raw: RawGraphFile = serde_json::from_str(text).map_err(|e| Error::input(source, e.to_string()))?;
    if raw.format != "tidepath-graph" {
        return Err(Error::input(source, format!("format '{}' is not a tidepath graph file", raw.format)));
    }
    if raw.version == 0 || raw.version > GRAPH_FORMAT_VERSION {
        return Err(Error::input(source, format!("version {} is not one this tidepath reads", raw.version)));
    }
    if raw.frame != "metres" {
        return Err(Error::input(source, format!("frame '{}': expected \"metres\"", raw.frame)));
    }
    let mut out = Vec::with_capacity(raw.missions.len());
    for m in raw.missions {
        let g = GraphReport {
            mission: m.mission,
            kind: m.kind,
            vertices: m.vertices,
            edges: m.edges,
            start: m.start,
            goal: m.goal,
            lonlat: m.lonlat,
        };
        check_indices(&g, source)?;
        out.push(g);
    }
    Ok(out)
}

/// What the GraphML reader is inside of.
#[derive(Clone, Copy, PartialEq)]
enum Owner {
    Graph,
    Node,
    Edge,
}

/// The graphs of a GraphML file this module wrote (GraphML of other tools reads as long as its
/// nodes carry `x`, `y`, `z`). The XML must be well formed (one-line errors name the byte);
/// the kind is the graph's `kind` data, else "tree" for directed graphs and "roadmap" for
/// undirected ones.
pub fn read_graphml(text: &str, source: &str) -> Result<Vec<GraphReport>> {
    let mut reader = quick_xml::Reader::from_str(text);
    reader.config_mut().trim_text(true);
    let mut keys: HashMap<String, String> = HashMap::new();
    let mut graphs: Vec<GraphReport> = Vec::new();
    // Node id to (graph, index in it).
    let mut nodes: HashMap<String, (usize, u32)> = HashMap::new();
    let mut pending: Vec<(usize, String, String)> = Vec::new();
    let mut owner: Vec<Owner> = Vec::new();
    let mut data_key: Option<String> = None;
    let mut text_buf = String::new();
    let err = |at: u64, m: String| Error::input(source, format!("at byte {at}: {}", tidepath::text::one_line(&m)));
    let mut depth = 0usize;
    let mut seen_root = false;
    loop {
        let at = reader.buffer_position();
        let ev = reader.read_event().map_err(|e| err(at, format!("malformed XML: {e}")))?;
        let (start, empty) = match &ev {
            Event::Start(e) => (Some(e.clone()), false),
            Event::Empty(e) => (Some(e.clone()), true),
            _ => (None, false),
        };
        if let Some(e) = start {
            if depth == 0 {
                if seen_root || e.local_name().as_ref() != b"graphml" {
                    return Err(err(at, "expected one <graphml> root element".into()));
                }
                seen_root = true;
            }
            if !empty {
                depth += 1;
            }
            let mut attrs: HashMap<String, String> = HashMap::new();
            for a in e.attributes() {
                let a = a.map_err(|x| err(at, format!("malformed attribute: {x}")))?;
                let v = a.unescape_value().map_err(|x| err(at, format!("malformed attribute: {x}")))?;
                attrs.insert(String::from_utf8_lossy(a.key.local_name().as_ref()).into_owned(), v.into_owned());
            }
            let attr = |k: &str| attrs.get(k).cloned().ok_or_else(|| err(at, format!("<{k}> attribute missing")));
            match e.local_name().as_ref() {
                b"key" => {
                    keys.insert(attr("id")?, attrs.get("attr.name").cloned().unwrap_or(attr("id")?));
                }
                b"graph" => {
                    let directed = attrs.get("edgedefault").map(String::as_str) != Some("undirected");
                    graphs.push(GraphReport {
                        mission: attr("id")?,
                        kind: if directed { "tree" } else { "roadmap" }.into(),
                        ..GraphReport::default()
                    });
                    owner.push(Owner::Graph);
                }
                b"node" => {
                    let g = graphs.len().checked_sub(1).ok_or_else(|| err(at, "<node> outside a <graph>".into()))?;
                    let index = graphs[g].vertices.len() as u32;
                    if nodes.insert(attr("id")?, (g, index)).is_some() {
                        return Err(err(at, format!("node id '{}' used twice", attr("id")?)));
                    }
                    graphs[g].vertices.push([f64::NAN; 3]);
                    owner.push(Owner::Node);
                }
                b"edge" => {
                    let g = graphs.len().checked_sub(1).ok_or_else(|| err(at, "<edge> outside a <graph>".into()))?;
                    pending.push((g, attr("source")?, attr("target")?));
                    graphs[g].edges.push([u32::MAX; 2]);
                    owner.push(Owner::Edge);
                }
                b"data" if !empty => {
                    data_key = Some(attr("key")?);
                    text_buf.clear();
                }
                _ => {}
            }
            if empty && matches!(e.local_name().as_ref(), b"graph" | b"node" | b"edge") {
                owner.pop();
            }
            continue;
        }
        match ev {
            Event::Text(t) => {
                let s = t.decode().map_err(|x| err(at, format!("malformed text: {x}")))?;
                text_buf.push_str(&s);
            }
            Event::End(e) => {
                depth = depth.saturating_sub(1);
                match e.local_name().as_ref() {
                    b"data" => {
                        let key = data_key.take().unwrap_or_default();
                        let name = keys.get(&key).cloned().unwrap_or(key);
                        let g = graphs.len().wrapping_sub(1);
                        let number = || -> Result<f64> {
                            let v = text_buf.trim();
                            match v {
                                "NaN" => Ok(f64::NAN),
                                "INF" => Ok(f64::INFINITY),
                                "-INF" => Ok(f64::NEG_INFINITY),
                                _ => v.parse().map_err(|_| err(at, format!("'{v}' is not a number"))),
                            }
                        };
                        match (owner.last(), name.as_str()) {
                            (Some(Owner::Graph), "kind") => graphs[g].kind = text_buf.trim().to_string(),
                            (Some(Owner::Node), "x" | "y" | "z" | "lon" | "lat" | "depth" | "role") => {
                                let i = graphs[g].vertices.len() - 1;
                                match name.as_str() {
                                    "x" => graphs[g].vertices[i][0] = number()?,
                                    "y" => graphs[g].vertices[i][1] = number()?,
                                    "z" => graphs[g].vertices[i][2] = number()?,
                                    "role" => match text_buf.trim() {
                                        "start" => graphs[g].start = Some(i as u32),
                                        "goal" => graphs[g].goal = Some(i as u32),
                                        _ => {}
                                    },
                                    geo => {
                                        let n = graphs[g].vertices.len();
                                        let ll = graphs[g].lonlat.get_or_insert_with(Vec::new);
                                        ll.resize(n, [f64::NAN; 3]);
                                        let slot = match geo {
                                            "lon" => 0,
                                            "lat" => 1,
                                            _ => 2,
                                        };
                                        ll[i][slot] = number()?;
                                    }
                                }
                            }
                            _ => {}
                        }
                    }
                    b"graph" | b"node" | b"edge" => {
                        owner.pop();
                    }
                    _ => {}
                }
            }
            Event::Eof => break,
            _ => {}
        }
    }
    if !seen_root {
        return Err(Error::input(source, "no <graphml> element"));
    }
    // Edges name their nodes by id; resolved once every node is known.
    let mut next = vec![0usize; graphs.len()];
    for (g, s, t) in pending {
        let find = |id: &str| match nodes.get(id) {
            Some(&(h, i)) if h == g => Ok(i),
            Some(_) => Err(Error::input(source, format!("edge to node '{id}' of another graph"))),
            None => Err(Error::input(source, format!("edge to unknown node '{id}'"))),
        };
        graphs[g].edges[next[g]] = [find(&s)?, find(&t)?];
        next[g] += 1;
    }
    for g in &mut graphs {
        if let Some(ll) = &mut g.lonlat {
            ll.resize(g.vertices.len(), [f64::NAN; 3]);
        }
        check_indices(g, source)?;
    }
    Ok(graphs)
}

#[cfg(test)]
mod tests;
