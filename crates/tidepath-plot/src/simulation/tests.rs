//! The simulation figure: well-formed SVG, one panel per phase (at most twelve), a failed phase
//! marked, degrees on a geographic world's maps; worlds and phases built by hand.
//!
//! Set `TIDEPATH_PLOT_DIR` to also write the SVGs there, to look at them.

use super::*;
use tidepath::geo::GeoFrame;
use tidepath::geom::{Aabb, Vec2};
use tidepath::world::terrain::{GaussianPeaks, Peak};
use tidepath::world::{Current, Dims, Shape, Terrain};

/// What a made-up simulation is like.
#[derive(Clone, Copy)]
struct Case {
    phases: usize,
    three_d: bool,
    geographic: bool,
    fail_last: bool,
}

/// The owned data a figure borrows: per phase its world, routes, piece and label.
struct Sim {
    worlds: Vec<World>,
    unseen: Vec<Vec<Obstacle>>,
    old: Vec<Vec<Vec3>>,
    new: Vec<Vec<Vec3>>,
    pieces: Vec<Option<Vec<Vec3>>>,
    labels: Vec<String>,
    times: Vec<f64>,
    positions: Vec<Vec3>,
    failed: Vec<bool>,
    track: Vec<Vec3>,
    track_times: Vec<f64>,
    start: Vec3,
    goal: Vec3,
    outcome: String,
}

const SPEED: f64 = 2.0;

/// Flies `dist` metres along `route`: the points passed (from its first) and the route left
/// (from where the vehicle stops).
fn fly(route: &[Vec3], mut dist: f64) -> (Vec<Vec3>, Vec<Vec3>) {
    let mut flown = vec![route[0]];
    for k in 1..route.len() {
        let (a, b) = (route[k - 1], route[k]);
        let len = a.distance(b);
        if dist < len {
            let p = a.lerp(b, dist / len);
            flown.push(p);
            let mut rest = vec![p];
            rest.extend_from_slice(&route[k..]);
            return (flown, rest);
        }
        dist -= len;
        flown.push(b);
    }
    (flown, vec![route[route.len() - 1]])
}

/// A 4 km x 3 km domain (40 km x 30 km when geographic) with a fixed column, two moving
/// circles, a ship sighted at phase 2 and, in 3-D, a seamount; the vehicle replans a detour
/// at every odd phase and keeps its route at the even ones.
fn simulate(case: Case) -> Sim {
    let s = if case.geographic { 10.0 } else { 1.0 };
    let v3 = |x: f64, y: f64| Vec3::new(x * s, y * s, if case.three_d { -60.0 } else { 0.0 });
    let mut base = World::open(Aabb::new(Vec3::new(0.0, 0.0, -300.0), Vec3::new(4000.0 * s, 3000.0 * s, 0.0)));
    if case.three_d {
        base.terrain = Terrain::Peaks(GaussianPeaks {
            base: -280.0,
            peaks: vec![Peak { x: 2000.0 * s, y: 800.0 * s, height: 320.0, sigma_x: 500.0 * s, sigma_y: 400.0 * s }],
            ceiling: None,
        });
    } else {
        base.dims = Dims::Two;
        base.bounds.min.z = 0.0;
    }
    if case.geographic {
        base.frame = Some(GeoFrame::new(-123.4, 48.3, "frame").unwrap());
    }
    let circle = |x: f64, y: f64, r: f64| Shape::Circle { center: Vec2::new(x * s, y * s), radius: r * s };
    base.obstacles = vec![
        Obstacle::fixed(circle(2000.0, 2300.0, 300.0)),
        Obstacle { shape: circle(1200.0, 200.0, 200.0), velocity: Vec3::new(0.0, 0.9 * s, 0.0), window: None },
        Obstacle { shape: circle(3100.0, 2900.0, 220.0), velocity: Vec3::new(-0.3 * s, -0.8 * s, 0.0), window: None },
    ];
    base.current = Current::Uniform(Vec3::new(0.2, 0.1, 0.0));
    let ship =
        Obstacle { shape: circle(3600.0, 300.0, 150.0), velocity: Vec3::new(-1.2 * s, 1.0 * s, 0.0), window: None };

    let (start, goal) = (v3(200.0, 1500.0), v3(3800.0, 1500.0));
    let mut route = vec![start, v3(1400.0, 1300.0), v3(2600.0, 1500.0), goal];
    let length: f64 = route.windows(2).map(|w| w[0].distance(w[1])).sum();
    let dt = (length / SPEED / (case.phases as f64 + 0.5)).round();
    let mut sim = Sim {
        worlds: vec![],
        unseen: vec![],
        old: vec![],
        new: vec![],
        pieces: vec![],
        labels: vec![],
        times: vec![],
        positions: vec![],
        failed: vec![],
        track: vec![start],
        track_times: vec![0.0],
        start,
        goal,
        outcome: String::new(),
    };
    for k in 0..case.phases {
        let t = k as f64 * dt;
        let mut world = base.clone();
        if k >= 2 {
            world.obstacles.push(ship.clone());
        }
        if k >= 3 {
            world.current = Current::Uniform(Vec3::new(-0.1, 0.35, 0.0));
        }
        let old = if k == 0 { vec![] } else { route.clone() };
        let pos = route[0];
        let failed = case.fail_last && k + 1 == case.phases;
        let (new, piece, what) = if k == 0 {
            (route.clone(), None, "departure plan, 4 waypoints".to_string())
        } else if failed {
            (vec![], None, "ship 3 sighted at 900 m; route blocked; windows 20, 40, 80 → no feasible piece".into())
        } else if k % 2 == 1 {
            let next = route[1.min(route.len() - 1)];
            let d = (next - pos).truncate();
            let side = Vec3::new(-d.y, d.x, 0.0).normalize_or_zero() * 180.0 * s;
            let piece = vec![pos, pos.lerp(next, 0.5) + side, next];
            let mut new = piece.clone();
            new.extend_from_slice(&route[2.min(route.len())..]);
            let what = match k {
                1 => "obstacle 1 moved onto the route; route blocked; replanned window 20 → feasible".to_string(),
                _ => format!("obstacle {} course change; route blocked; replanned window 20 → feasible", k % 3),
            };
            (new, Some(piece), what)
        } else {
            let what = match k {
                2 => "ship 3 sighted at 1500 m; route still clear; kept",
                4 => "new current forecast (0.36 m/s); route still clear; kept",
                _ => "obstacle 2 moved; route still clear; kept",
            };
            (route.clone(), None, what.to_string())
        };
        sim.labels.push(format!("phase {k}, t = {t:.0} s: {what}"));
        sim.unseen.push(if k < 2 { vec![ship.clone()] } else { vec![] });
        sim.worlds.push(world);
        sim.old.push(old);
        sim.pieces.push(piece);
        sim.times.push(t);
        sim.positions.push(pos);
        sim.failed.push(failed);
        if failed {
            sim.new.push(new);
            sim.outcome = format!("phase {k}: no feasible window up to the goal: ship 3 blocks the strait");
            break;
        }
        sim.new.push(new.clone());
        // Fly to the next phase (or, after the last, to the goal).
        let dist = if k + 1 == case.phases { f64::INFINITY } else { dt * SPEED };
        let (flown, rest) = fly(&new, dist);
        let mut t_at = t;
        for w in flown.windows(2) {
            t_at += w[0].distance(w[1]) / SPEED;
            sim.track.push(w[1]);
            sim.track_times.push(t_at);
        }
        route = rest;
        sim.outcome = format!("reached the goal at t = {t_at:.0} s");
    }
    sim
}

impl Sim {
    fn figure(&self, title: &str) -> SimulationFigure<'_> {
        let phases = (0..self.worlds.len())
            .map(|k| SimPanel {
                label: self.labels[k].clone(),
                known: &self.worlds[k],
                unseen: self.unseen[k].clone(),
                time: self.times[k],
                position: self.positions[k],
                old_route: &self.old[k],
                new_route: &self.new[k],
                piece: self.pieces[k].as_deref(),
                failed: self.failed[k],
            })
            .collect();
        SimulationFigure {
            title: title.into(),
            epoch: None,
            safety_distance: 60.0,
            start: self.start,
            goal: self.goal,
            track: &self.track,
            track_times: &self.track_times,
            phases,
            outcome: self.outcome.clone(),
            focus: vec![],
        }
    }
}

fn save(name: &str, svg: &str) {
    if let Some(dir) = std::env::var_os("TIDEPATH_PLOT_DIR") {
        std::fs::create_dir_all(&dir).unwrap();
        std::fs::write(std::path::Path::new(&dir).join(name), svg).unwrap();
    }
}

/// Checks that `svg` is well-formed XML (one root, tags nested and closed, quoted attributes,
/// entities only where allowed, no forbidden characters) and returns the element names in
/// document order.
fn parse_xml(svg: &str) -> Vec<String> {
    let entity_ok = |rest: &str| {
        let end = rest.find(';').expect("unterminated entity");
        let e = &rest[1..end];
        assert!(
            ["amp", "lt", "gt", "quot", "apos"].contains(&e)
                || e.strip_prefix("#x").is_some_and(|h| u32::from_str_radix(h, 16).is_ok())
                || e.strip_prefix('#').is_some_and(|d| d.parse::<u32>().is_ok()),
            "bad entity &{e};"
        );
    };
    let check_text = |t: &str| {
        for (i, c) in t.char_indices() {
            assert!(!c.is_control() || matches!(c, '\n' | '\r' | '\t'), "control character {c:?}");
            if c == '&' {
                entity_ok(&t[i..]);
            }
        }
    };
    let (mut stack, mut names, mut roots) = (Vec::<String>::new(), Vec::new(), 0);
    let mut rest = svg.trim();
    while !rest.is_empty() {
        if let Some(r) = rest.strip_prefix("<?") {
            rest = &r[r.find("?>").expect("unterminated declaration") + 2..];
        } else if let Some(r) = rest.strip_prefix("<!--") {
            rest = &r[r.find("-->").expect("unterminated comment") + 3..];
        } else if let Some(r) = rest.strip_prefix("</") {
            let end = r.find('>').expect("unterminated end tag");
            assert_eq!(stack.pop().as_deref(), Some(r[..end].trim()), "mismatched end tag");
            rest = &r[end + 1..];
        } else if let Some(r) = rest.strip_prefix('<') {
            let end = r.find('>').expect("unterminated tag");
            let (tag, empty) = match r[..end].strip_suffix('/') {
                Some(t) => (t, true),
                None => (&r[..end], false),
            };
            let name_end = tag.find(char::is_whitespace).unwrap_or(tag.len());
            let name = &tag[..name_end];
            assert!(!name.is_empty() && name.chars().all(|c| c.is_alphanumeric() || "-_:.".contains(c)), "{name:?}");
            // Attributes: name="value" pairs, each name once.
            let mut attrs = tag[name_end..].trim();
            let mut seen = Vec::new();
            while !attrs.is_empty() {
                let eq = attrs.find('=').expect("attribute without value");
                let key = attrs[..eq].trim();
                assert!(!seen.contains(&key), "attribute {key} twice in <{name}>");
                seen.push(key);
                let v = attrs[eq + 1..].trim_start();
                let q = v.chars().next().expect("attribute value");
                assert!(q == '"' || q == '\'', "unquoted attribute {key}");
                let close = v[1..].find(q).expect("unterminated attribute") + 1;
                assert!(!v[1..close].contains('<'), "'<' in attribute {key}");
                check_text(&v[1..close]);
                attrs = v[close + 1..].trim_start();
            }
            if stack.is_empty() {
                roots += 1;
            }
            names.push(name.to_string());
            if !empty {
                stack.push(name.to_string());
            }
            rest = &r[end + 1..];
        } else {
            let end = rest.find('<').unwrap_or(rest.len());
            assert!(!stack.is_empty() || rest[..end].trim().is_empty(), "text outside the root");
            check_text(&rest[..end]);
            rest = &rest[end..];
        }
    }
    assert!(stack.is_empty(), "unclosed elements {stack:?}");
    assert_eq!(roots, 1, "one root element");
    names
}

fn count(svg: &str, s: &str) -> usize {
    svg.matches(s).count()
}

/// The phases that got a panel, from their `data-phase` attributes.
fn panel_phases_in(svg: &str) -> Vec<usize> {
    svg.split("data-phase=\"").skip(1).map(|r| r[..r.find('"').unwrap()].parse().unwrap()).collect()
}

#[test]
fn five_phases_give_five_panels_in_well_formed_svg() {
    let sim = simulate(Case { phases: 5, three_d: false, geographic: false, fail_last: false });
    let svg = render_simulation_figure(&sim.figure("demo — simulate, rrt-star")).unwrap();
    save("sim-5.svg", &svg);
    let names = parse_xml(&svg);
    assert_eq!(names.iter().filter(|n| *n == "svg").count(), 1 + 1 + 5, "root, overview, panels");
    assert_eq!(count(&svg, "class=\"sim-overview\""), 1);
    assert_eq!(count(&svg, "class=\"sim-panel"), 5);
    assert_eq!(panel_phases_in(&svg), vec![0, 1, 2, 3, 4]);
    assert_eq!(count(&svg, "sim-failed"), 0);
    for text in ["Outcome: reached the goal", "x east (m)", "obstacle not yet seen", "replanned piece", "route ahead"] {
        assert!(svg.contains(text), "{text:?} missing");
    }
    // Every phase is named in the overview's legend by its label's first part.
    assert!(svg.contains("phase 2, t = 660 s: ship 3 sighted at 1500 m\n"));
    assert!(!svg.contains("NaN") && !svg.contains("inf\""), "non-finite number in the SVG");
    // The replanned pieces' bands, phase 1's (magenta) and phase 3's (violet).
    assert_eq!(count(&svg, "stroke-width=\"11\""), 2);
    assert!(svg.contains("opacity=\"0.4\" stroke=\"#C81E82\" stroke-width=\"11\""));
}

#[test]
fn more_than_twelve_phases_draw_the_first_eleven_and_the_last() {
    let sim = simulate(Case { phases: 20, three_d: false, geographic: false, fail_last: false });
    let svg = render_simulation_figure(&sim.figure("many changes")).unwrap();
    save("sim-20.svg", &svg);
    parse_xml(&svg);
    assert_eq!(count(&svg, "class=\"sim-panel"), 12);
    let mut want: Vec<usize> = (0..11).collect();
    want.push(19);
    assert_eq!(panel_phases_in(&svg), want);
    assert!(svg.contains("8 of 20 phases (phases 11 to 18) have no panel here"), "the figure says what is left out");
    assert_eq!(panel_phases(12), (0..12).collect::<Vec<_>>());
    assert_eq!(panel_phases(13), (0..11).chain([12]).collect::<Vec<_>>());
    assert!(left_out_note(13).unwrap().starts_with("1 of 13 phases (phase 11)"));
}

#[test]
fn a_failed_phase_is_marked() {
    let sim = simulate(Case { phases: 4, three_d: true, geographic: false, fail_last: true });
    let mut fig = sim.figure("blocked");
    fig.focus = vec![Focus { at: sim.positions[3] + Vec3::new(300.0, 0.0, 0.0), label: "bottleneck".into() }];
    let svg = render_simulation_figure(&fig).unwrap();
    save("sim-failed.svg", &svg);
    parse_xml(&svg);
    assert_eq!(count(&svg, "class=\"sim-panel"), 4);
    assert_eq!(count(&svg, "class=\"sim-panel sim-failed\""), 1);
    assert!(svg.contains("class=\"sim-panel sim-failed\" id=\"sim-phase-3\""));
    for text in ["phase 3: no feasible route", "the mission ended here: no feasible route", "bottleneck"] {
        assert!(svg.contains(&format!("\n{text}\n</text>")), "{text:?} missing");
    }
    assert!(svg.contains("Outcome: phase 3: no feasible window"));
    assert!(svg.contains("seabed elevation (m)"), "3-D world's seabed has its colour bar on the overview");
}

#[test]
fn a_geographic_world_gets_degrees_on_every_map() {
    let sim = simulate(Case { phases: 3, three_d: false, geographic: true, fail_last: false });
    let svg = render_simulation_figure(&sim.figure("geographic")).unwrap();
    save("sim-geo.svg", &svg);
    parse_xml(&svg);
    // The overview and each of the three panels name their axes in degrees.
    assert_eq!(count(&svg, "\nlongitude\n</text>"), 4);
    assert_eq!(count(&svg, "\nlatitude\n</text>"), 4);
    assert!(svg.contains("°W\n</text>") && svg.contains("°N\n</text>"));
    assert!(!svg.contains("x east"));
}

#[test]
fn bad_input_is_refused_and_labels_stay_well_formed() {
    let sim = simulate(Case { phases: 2, three_d: false, geographic: false, fail_last: false });
    let mut fig = sim.figure("a <title> & \u{7} bell");
    fig.phases[1].label = format!("phase 1: {} <b> & \"q\"", "very-long-word-".repeat(40));
    let svg = render_simulation_figure(&fig).unwrap();
    parse_xml(&svg);
    fig.track_times = &sim.track_times[1..];
    assert!(render_simulation_figure(&fig).is_err(), "times not matching the track");
    fig.track_times = &sim.track_times;
    fig.phases.clear();
    assert!(render_simulation_figure(&fig).is_err(), "no phase");
}

#[test]
fn labels_wrap_inside_their_width() {
    let text = "phase 2, t = 812 s: obstacle 1 sighted at 1500 m; route blocked; replanned window 20 → feasible";
    let lines = parts::wrap_label(text, 300.0, 13.0, 6);
    assert!(lines.len() >= 2);
    assert!(lines.iter().all(|l| style::text_width(l, 13.0) * 1.12 <= 300.0), "{lines:?}");
    assert_eq!(lines.join(" "), text);
    let long = parts::wrap_label(&"x".repeat(500), 200.0, 13.0, 3);
    assert_eq!(long.len(), 3);
    assert!(long[2].ends_with('…'));
    assert_eq!(parts::short_label("phase 2, t = 812 s: sighted; blocked", 60), "phase 2, t = 812 s: sighted");
}
