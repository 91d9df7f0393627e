use super::*;
use crate::world::grid::RegularGrid2;

fn grid() -> WaveGrid {
    // 3 x 2 nodes, 10 m apart; two layers an hour apart.
    let g = RegularGrid2::new(0.0, 0.0, 10.0, 10.0, 3, 2, "w").unwrap();
    let early = vec![1.0, 2.0, 3.0, 1.0, 2.0, 3.0];
    let late = vec![3.0, 4.0, 5.0, 3.0, 4.0, 5.0];
    WaveGrid::new(g, vec![0.0, 3600.0], vec![early, late], "world.waves").unwrap()
}

#[test]
fn height_is_bilinear_in_space_and_linear_in_time() {
    let w = Waves::Grid(grid());
    // Halfway between nodes of 1 and 2 m, at the first layer: 1.5 m.
    assert_eq!(w.height(Vec3::new(5.0, 5.0, 0.0), 0.0), 1.5);
    // Half an hour later the layers (1.5 and 3.5 m there) are mixed half and half: 2.5 m.
    assert_eq!(w.height(Vec3::new(5.0, 5.0, 0.0), 1800.0), 2.5);
    // Before the first and after the last layer the nearest one holds.
    assert_eq!(w.height(Vec3::new(20.0, 0.0, 0.0), -50.0), 3.0);
    assert_eq!(w.height(Vec3::new(20.0, 0.0, 0.0), 1e9), 5.0);
    assert_eq!(w.height_bound(), 5.0);
    assert!(!w.is_steady() && w.varies());
    assert_eq!(Waves::Uniform(1.2).height(Vec3::ZERO, 7.0), 1.2);
    assert_eq!(Waves::None.height(Vec3::ZERO, 7.0), 0.0);
}

#[test]
fn bad_layers_name_the_field_and_value() {
    let g = RegularGrid2::new(0.0, 0.0, 10.0, 10.0, 2, 2, "w").unwrap();
    let err = WaveGrid::new(g.clone(), vec![0.0], vec![vec![1.0, -0.5, 1.0, 1.0]], "world.waves").unwrap_err();
    assert!(err.to_string().contains("world.waves.height") && err.to_string().contains("-0.5"), "{err}");
    let err = WaveGrid::new(g.clone(), vec![0.0], vec![vec![1.0, f64::NAN, 1.0, 1.0]], "world.waves").unwrap_err();
    assert!(err.to_string().contains("NaN"), "{err}");
    let err = WaveGrid::new(g, vec![0.0], vec![vec![1.0; 3]], "world.waves").unwrap_err();
    assert!(err.to_string().contains("3 values"), "{err}");
}

#[test]
fn gaps_are_found_on_points_and_segments() {
    let w = Waves::Grid(grid().with_gaps(vec![2], "world.waves").unwrap());
    // Node 2 is (20, 0): the right cell touches it, the left does not.
    assert!(w.has_data(Vec3::new(5.0, 5.0, 0.0)));
    assert!(!w.has_data(Vec3::new(15.0, 5.0, 0.0)));
    assert!(w.first_gap_on(Vec3::new(1.0, 1.0, 0.0), Vec3::new(9.0, 9.0, 0.0)).is_none());
    let (x, _) = w.first_gap_on(Vec3::new(1.0, 5.0, 0.0), Vec3::new(19.0, 5.0, 0.0)).unwrap();
    assert!(x > 10.0, "{x}");
    // The gap node does not count in the colour range.
    assert_eq!(w.range_hint(&Aabb::new(Vec3::ZERO, Vec3::new(20.0, 10.0, 0.0))), (1.0, 5.0));
}
