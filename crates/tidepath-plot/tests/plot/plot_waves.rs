//! In a world with waves (acopf2016's wave glider), the plan view's background is the
//! significant wave height as a colour map with its colour bar, in place of the depths; land
//! and places without wave data are drawn over it, the current's arrows stay on top, and a
//! glider's path is coloured by its speed over ground from its own clock.

use tidepath::geom::{Aabb, Vec3};
use tidepath::vehicle::GliderSpeed;
use tidepath::world::terrain::CellGrid;
use tidepath::world::waves::WaveGrid;
use tidepath::world::{Current, Dims, RegularGrid2, Terrain, Waves, World};
use tidepath_plot::style::wave_color;
use tidepath_plot::{render_plan_figure, PlanFigure, PlotPath};

/// Heights of the five columns of cells, west to east.
const COLUMNS: [f64; 5] = [0.5, 1.0, 1.5, 2.0, 2.5];

/// 5 km x 2 km at the surface, cells of 1 km: waves rising eastwards (nodes at the cells'
/// centres, as `kind = "cells"` gives them), a current of 0.4 m/s to the north; `later`
/// adds a layer an hour on with every height 1 m higher.
fn world(later: bool) -> World {
    let mut w = World::open(Aabb::new(Vec3::new(0.0, 0.0, 0.0), Vec3::new(5_000.0, 2_000.0, 0.0)));
    w.dims = Dims::Two;
    w.current = Current::Uniform(Vec3::new(0.0, 0.4, 0.0));
    let grid = RegularGrid2::new(500.0, 500.0, 1_000.0, 1_000.0, 5, 2, "world.waves").unwrap();
    let layer: Vec<f64> = [COLUMNS, COLUMNS].concat();
    let (times, layers) = if later {
        (vec![0.0, 3_600.0], vec![layer.clone(), layer.iter().map(|h| h + 1.0).collect()])
    } else {
        (vec![0.0], vec![layer])
    };
    w.waves = Waves::Grid(WaveGrid::new(grid, times, layers, "world.waves").unwrap());
    w
}

/// Filled `<rect>`s of the SVG as (x, y, width, height, fill), in drawing order (outlines,
/// such as the map's frame, left out).
fn rects(svg: &str) -> Vec<(f64, f64, f64, f64, String)> {
    let attr = |l: &str, name: &str| -> Option<String> {
        let start = l.find(&format!(" {name}=\""))? + name.len() + 3;
        Some(l[start..].split('"').next()?.to_string())
    };
    svg.lines()
        .filter(|l| l.trim_start().starts_with("<rect"))
        .filter_map(|l| {
            let num = |n: &str| attr(l, n)?.parse::<f64>().ok();
            Some((num("x")?, num("y")?, num("width")?, num("height")?, attr(l, "fill")?))
        })
        .filter(|r| r.4 != "none")
        .collect()
}

fn hex(c: plotters::style::RGBColor) -> String {
    format!("#{:02X}{:02X}{:02X}", c.0, c.1, c.2)
}

/// The fill seen at pixel (x, y): the last rect drawn over it.
fn fill_at(rs: &[(f64, f64, f64, f64, String)], x: f64, y: f64) -> Option<&str> {
    rs.iter().rev().find(|r| x >= r.0 && x <= r.0 + r.2 && y >= r.1 && y <= r.1 + r.3).map(|r| r.4.as_str())
}

/// The 41 shades of the wave palette.
fn palette() -> Vec<String> {
    (0..=40).map(|k| hex(wave_color(k as f64 / 40.0, 0.0, 1.0))).collect()
}

/// Land and no wave data.
const LAND: &str = "#B0946C";
const NO_DATA: &str = "#C8C8C8";

/// The map's box (x, y, width, height in pixels): the widest rect in a wave, land or no-data
/// colour, the background block under the other shades, which spans the map.
fn map_box(rs: &[(f64, f64, f64, f64, String)]) -> (f64, f64, f64, f64) {
    let mut shades = palette();
    shades.extend([LAND.to_string(), NO_DATA.to_string()]);
    let r = rs.iter().filter(|r| shades.contains(&r.4)).max_by(|a, b| a.2.total_cmp(&b.2)).expect("no wave colour");
    assert!(r.2 > 300.0 && r.3 > 100.0, "no wave map found: {} x {}", r.2, r.3);
    (r.0, r.1, r.2, r.3)
}

/// Polylines stroked with `color` at `width` pixels.
fn strokes(svg: &str, color: &str, width: u32) -> usize {
    svg.lines()
        .filter(|l| {
            l.contains("<polyline")
                && l.contains(&format!("stroke=\"{color}\""))
                && l.contains(&format!("stroke-width=\"{width}\""))
        })
        .count()
}

fn figure<'a>(world: &'a World, pts: &'a [Vec3], times: &'a [f64]) -> PlanFigure<'a> {
    let mut fig = PlanFigure::new("wave glider", world, pts[0], pts[pts.len() - 1], 0.0);
    fig.paths = vec![PlotPath::new("glider", pts).with_times(times)];
    fig.speed_path = Some(0);
    fig
}

/// Eastwards along y = 1000 m, a waypoint at every cell centre, timed by the glider's speed
/// in the waves at each segment's middle (the current is across the track: c_along = 0).
fn glider_path() -> (Vec<Vec3>, Vec<f64>) {
    let pts: Vec<Vec3> = (0..5).map(|i| Vec3::new(500.0 + 1_000.0 * i as f64, 1_000.0, 0.0)).collect();
    let g = GliderSpeed::default();
    let mut times = vec![0.0];
    for i in 0..4 {
        // Midway between columns i and i + 1 the height is their mean.
        let v = g.ground_speed(0.5 * (COLUMNS[i] + COLUMNS[i + 1]), 0.0).unwrap();
        times.push(times[i] + 1_000.0 / v);
    }
    (pts, times)
}

#[test]
fn waves_are_a_colour_map_rising_the_way_the_field_does() {
    let w = world(false);
    let (pts, times) = glider_path();
    let svg = render_plan_figure(&figure(&w, &pts, &times)).unwrap();
    super::save("plan_waves.svg", &svg);
    assert!(svg.contains("significant wave height (m)"), "no wave colour bar");
    assert!(!svg.contains("seabed elevation"), "the depth map drawn beside the waves");
    // A steady field at one time: the caption gives no time.
    assert!(svg.contains(">\nPlan view\n</text>"), "caption");

    let rs = rects(&svg);
    let (x0, y0, wd, ht) = map_box(&rs);
    let palette = palette();
    // West of the first node (x < 500 m) the 0.5 m edge holds; east of the last, 2.5 m.
    let at = |fx: f64| fill_at(&rs, x0 + fx * wd, y0 + 0.3 * ht).unwrap_or("nothing").to_string();
    assert_eq!(at(0.03), hex(wave_color(0.5, 0.5, 2.5)), "west edge");
    assert_eq!(at(0.97), hex(wave_color(2.5, 0.5, 2.5)), "east edge");
    assert_ne!(at(0.03), at(0.97));
    // In between the shade climbs the palette eastwards, never back.
    let rank: Vec<usize> =
        (1..20).map(|k| palette.iter().position(|c| *c == at(k as f64 / 20.0)).expect("a wave colour")).collect();
    assert!(rank.windows(2).all(|p| p[0] <= p[1]) && rank[0] < rank[18], "{rank:?}");

    // The current arrows, dark on a pale halo, so the palette's dark end cannot hide them.
    let arrows = strokes(&svg, "#141E2D", 1);
    assert!(arrows >= 100, "{arrows} current arrows");
    assert!(strokes(&svg, "#FFFFFF", 3) >= 100, "arrows without halo");

    // The glider's path, coloured by its speed over ground (0.24 to 0.37 m/s) from its clock,
    // with no still-water speed to mark.
    assert!(svg.contains("speed over ground (m/s)"), "no speed colour bar");
    assert!(svg.contains("glider, coloured by speed over ground"));
    assert!(!svg.contains("through still water"));
}

#[test]
fn land_gaps_and_a_changing_sea_are_said() {
    let mut w = world(true);
    // The middle cell of the north row is land (a cells map's '#').
    let mut z = vec![-50.0; 10];
    z[7] = 5.0;
    w.terrain = Terrain::Cells(CellGrid::new([0.0, 0.0], [1_000.0; 2], [5, 2], z, "world.terrain").unwrap());
    // The south-east node has no data: the south-east corner cell of the nodes is grey.
    let Waves::Grid(g) = std::mem::take(&mut w.waves) else { unreachable!() };
    w.waves = Waves::Grid(g.with_gaps(vec![4], "world.waves").unwrap());
    let (pts, times) = glider_path();
    let svg = render_plan_figure(&figure(&w, &pts, &times)).unwrap();
    super::save("plan_waves_land.svg", &svg);
    // Drawn at the departure, and said so (the field changes within the hour).
    assert!(svg.contains("Plan view at t = 0 s (departure)"), "caption without the time");
    assert!(svg.contains(">\nland\n</text>") && svg.contains(">\nno wave data\n</text>"), "legend");
    let rs = rects(&svg);
    // The land and no-data colours are painted (at least one cell each, beyond the legend).
    assert!(rs.iter().filter(|r| r.4 == LAND && r.2 > 40.0).count() >= 1, "no land cell");
    assert!(rs.iter().filter(|r| r.4 == NO_DATA && r.2 > 40.0).count() >= 1, "no grey gap");
    // The bar spans both layers (0.5 to 3.5 m), so the map at departure (0.5 to 2.5 m) keeps
    // clear of the bar's top colour: the west edge is the bottom of the scale, and x = 3312.5 m
    // (the centre of raster cell 79 of 120), 1.5 + 0.8125 * 0.5 = 1.906 m, is 0.469 of the way up.
    let (x0, y0, wd, ht) = map_box(&rs);
    let at = |fx: f64| fill_at(&rs, x0 + fx * wd, y0 + 0.3 * ht).unwrap_or("nothing").to_string();
    assert_eq!(at(0.03), hex(wave_color(0.0, 0.0, 3.0)), "west edge");
    assert_eq!(at(79.5 / 120.0), hex(wave_color(1.906, 0.5, 3.5)), "x = 3312.5 m");
    let top = hex(wave_color(3.5, 0.5, 3.5));
    assert!(rs.iter().any(|r| r.4 == top), "the bar does not reach the later layer's 3.5 m");
    assert!(!rs.iter().any(|r| r.4 == top && r.3 > 100.0), "the map shows the later layer");
}
