use super::super::contour::Raster;
use super::seabed::seabed_blocks;
use super::*;
use tidepath::geom::Vec3;

#[test]
fn seabed_blocks_paint_every_cell_its_own_colour() {
    let raster = Raster::sample(0.0, 0.0, 10.0, 8.0, 21, 17, |x, y| {
        -500.0 + 300.0 * (-((x - 5.0).powi(2) + (y - 4.0).powi(2)) / 2.0).exp()
    });
    let (z_min, z_max) = raster.finite_range().unwrap();
    let s = Seabed { raster, z_min, z_max, levels: vec![], step: 100.0 };
    let (cx, cy) = (20, 16);
    // Paint the blocks in order (background first) and compare with each cell's colour.
    let mut painted = vec![None; cx * cy];
    let blocks = seabed_blocks(&s);
    for &(i0, i1, j0, j1, c) in &blocks {
        for j in j0..j1 {
            for i in i0..i1 {
                painted[j * cx + i] = Some(c);
            }
        }
    }
    let r = &s.raster;
    for j in 0..cy {
        for i in 0..cx {
            let z = 0.25 * (r.at(i, j) + r.at(i + 1, j) + r.at(i, j + 1) + r.at(i + 1, j + 1));
            assert_eq!(painted[j * cx + i], Some(style::elevation_color(z, z_min, z_max)), "cell ({i}, {j})");
        }
    }
    assert!(blocks.len() < cx * cy / 2, "{} blocks for {} cells", blocks.len(), cx * cy);
}

#[test]
fn segment_speeds_are_length_over_time_with_the_vertical() {
    use super::speed::segment_speeds;
    let line = [
        Vec3::new(0.0, 0.0, 0.0),
        Vec3::new(30.0, 0.0, -40.0),
        Vec3::new(30.0, 0.0, -40.0),
        Vec3::new(30.0, 10.0, -40.0),
    ];
    // 50 m in 25 s, 0 m in 10 s, then a segment of no duration: no speed.
    let v = segment_speeds(&line, &[0.0, 25.0, 35.0, 35.0]);
    assert_eq!(v[..2], [2.0, 0.0]);
    assert!(v[2].is_nan());
}

#[test]
fn speed_ticks_are_round_and_labelled_at_their_step() {
    use super::speed::round_ticks;
    // A span whose nice step would be 0.25 (labels "1.5, 1.8, 2.0, 2.2") gets 0.2.
    let (ticks, step) = round_ticks(1.26, 2.31);
    assert_eq!(step, 0.2);
    let labels: Vec<String> = ticks.iter().map(|&v| style::fmt_num(v, step)).collect();
    assert_eq!(labels, ["1.4", "1.6", "1.8", "2.0", "2.2"]);
    assert!(round_ticks(1.0, 1.0).0.is_empty());
}

#[test]
fn a_path_at_one_speed_gets_a_bar_labelled_at_that_speed() {
    use super::speed::SpeedPath;
    let line = [Vec3::new(0.0, 0.0, -10.0), Vec3::new(100.0, 0.0, -10.0), Vec3::new(200.0, 0.0, -10.0)];
    let sp = SpeedPath {
        index: 0,
        line: &line,
        flown: false,
        waypoints: &line,
        speeds: vec![1.5, 1.5],
        lo: 1.5,
        hi: 1.5,
        still_water: Some(1.2),
    };
    let bar = sp.colour_bar();
    let labels: Vec<String> = bar.ticks.iter().map(|&v| style::fmt_num(v, bar.step)).collect();
    assert_eq!(labels, ["1.50"]);
    assert!(sp.legend_label("p").label.ends_with("(faster throughout than its 1.2 m/s through still water)"));
}

#[test]
fn a_uniform_sea_gets_one_colour_and_a_bar_labelled_at_its_height() {
    use super::waves::WaveMap;
    use tidepath::geom::Aabb;
    use tidepath::world::Waves;
    let mut w = World::open(Aabb::new(Vec3::new(0.0, 0.0, -50.0), Vec3::new(1_000.0, 500.0, 0.0)));
    assert!(WaveMap::sample(&w, (0.0, 0.0, 1_000.0, 500.0), 0.0).is_none(), "a map without waves");
    w.waves = Waves::Uniform(1.2);
    let m = WaveMap::sample(&w, (0.0, 0.0, 1_000.0, 500.0), 0.0).unwrap();
    assert_eq!((m.lo, m.hi), (1.2, 1.2));
    // Nothing to tell apart: the middle of the palette, no land or gap in the legend.
    assert_eq!(m.color(1.2), style::wave_color(0.5, 0.0, 1.0));
    assert!(m.legend().is_empty());
    let bar = m.colour_bar();
    let labels: Vec<String> = bar.ticks.iter().map(|&v| style::fmt_num(v, bar.step)).collect();
    assert_eq!((bar.title.as_str(), labels), ("significant wave height (m)", vec!["1.20".to_string()]));
}

#[test]
fn the_wave_bar_is_labelled_at_round_heights_and_its_round_ends() {
    use super::waves::WaveMap;
    use tidepath::geom::Aabb;
    use tidepath::world::waves::WaveGrid;
    use tidepath::world::{RegularGrid2, Waves};
    let mut w = World::open(Aabb::new(Vec3::new(0.0, 0.0, -50.0), Vec3::new(1_000.0, 500.0, 0.0)));
    let g = RegularGrid2::new(0.0, 0.0, 1_000.0, 500.0, 2, 2, "w").unwrap();
    w.waves = Waves::Grid(WaveGrid::new(g, vec![0.0], vec![vec![0.5, 2.0, 0.5, 2.0]], "w").unwrap());
    let bar = WaveMap::sample(&w, (0.0, 0.0, 1_000.0, 500.0), 0.0).unwrap().colour_bar();
    // 0.5 to 2 m: steps of 0.5 inside, and both ends are multiples of it.
    let labels: Vec<String> = bar.ticks.iter().map(|&v| style::fmt_num(v, bar.step)).collect();
    assert_eq!(labels, ["0.5", "1.0", "1.5", "2.0"]);
    // West is calm, east is high: the palette's ends.
    assert_eq!((bar.colour)(0.5), style::wave_color(0.0, 0.0, 1.0));
    assert_eq!((bar.colour)(2.0), style::wave_color(1.0, 0.0, 1.0));
}
