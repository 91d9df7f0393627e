use super::super::contour::Raster;
use super::seabed::seabed_blocks;
use super::*;

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
