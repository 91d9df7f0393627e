//! Time ticks on a fleet's plan figure: one bar across each vehicle's path at every multiple
//! of the figure's step, on the plan view (and on the profile of a 3-D world); none on a
//! one-mission plan or on several planners' paths of one mission.
//!
//! Set `TIDEPATH_PLOT_DIR` to also write the SVGs there, to look at them.

use tidepath::geom::{Aabb, Vec3};
use tidepath::world::{Dims, World};
use tidepath_plot::style::path_color;
use tidepath_plot::{render_plan_figure, PlanFigure, PlotPath};

/// The tick bars drawn in colour `color`: two-point lines 2 px wide and at most 16 px long
/// (a path's line is 3 px wide on the plan view; a profile's line, 2 px wide, is longer).
fn bars(svg: &str, color: plotters::style::RGBColor) -> usize {
    let stroke = format!("stroke=\"#{:02X}{:02X}{:02X}\" stroke-width=\"2\" points=\"", color.0, color.1, color.2);
    svg.split("<polyline")
        .filter_map(|e| e.split_once(&stroke))
        .filter(|(_, rest)| {
            let pts: Vec<f64> =
                rest.split('"').next().unwrap_or("").split([' ', ',']).filter_map(|v| v.parse().ok()).collect();
            pts.len() == 4 && (pts[2] - pts[0]).hypot(pts[3] - pts[1]) <= 16.0
        })
        .count()
}

fn save(name: &str, svg: &str) {
    if let Ok(dir) = std::env::var("TIDEPATH_PLOT_DIR") {
        std::fs::write(std::path::Path::new(&dir).join(name), svg).unwrap();
    }
}

fn world(dims: Dims) -> World {
    let z0 = if dims == Dims::Two { 0.0 } else { -500.0 };
    let mut w = World::open(Aabb::new(Vec3::new(0.0, 0.0, z0), Vec3::new(4000.0, 4000.0, 0.0)));
    w.dims = dims;
    w
}

/// East 3000 m in 2000 s, and north 3000 m in 3000 s: at most 10 ticks along the longest
/// (3000 s) is every 5 min, so 6 ticks east (300 .. 1800 s) and 9 north (300 .. 2700 s).
#[test]
fn a_fleet_gets_one_tick_per_step_on_each_path() {
    let z = -100.0;
    let east = [Vec3::new(500.0, 2000.0, z), Vec3::new(2000.0, 2000.0, z), Vec3::new(3500.0, 2000.0, z)];
    let north = [Vec3::new(2000.0, 500.0, z), Vec3::new(2000.0, 3500.0, z)];
    let (t_east, t_north) = ([0.0, 1000.0, 2000.0], [0.0, 3000.0]);
    for (dims, panels) in [(Dims::Two, 1), (Dims::Three, 2)] {
        let w = world(dims);
        let mut fig = PlanFigure::new("fleet", &w, east[0], east[2], 0.0);
        fig.paths =
            vec![PlotPath::new("east", &east).with_times(&t_east), PlotPath::new("north", &north).with_times(&t_north)];
        let svg = render_plan_figure(&fig).unwrap();
        save(&format!("time_ticks_{panels}.svg"), &svg);
        // The plan view has them, and the profile of a 3-D world.
        assert_eq!((bars(&svg, path_color(0)), bars(&svg, path_color(1))), (6 * panels, 9 * panels), "{dims:?}");
        assert!(svg.contains("time ticks every 5 min"));
        for label in ["5m", "30m", "45m"] {
            assert!(svg.contains(&format!(">\n{label}\n</text>")), "{label}");
        }
        // One vehicle, or two planners' paths of one mission: no ticks, no note.
        for paths in [
            vec![PlotPath::new("east", &east).with_times(&t_east)],
            vec![PlotPath::new("a", &east).with_times(&t_east), PlotPath::new("b", &east).with_times(&t_east)],
        ] {
            fig.paths = paths;
            let svg = render_plan_figure(&fig).unwrap();
            assert_eq!((bars(&svg, path_color(0)), bars(&svg, path_color(1))), (0, 0));
            assert!(!svg.contains("time ticks"));
        }
    }
}
