use super::*;

fn paper() -> CellNumbering {
    // acopf2016's check: a = 1, M = N = 20, origin at (0, 0).
    CellNumbering { origin: (0.0, 0.0), cell: 1.0, columns: 20, rows: 20 }
}

#[test]
fn the_papers_first_and_last_cells() {
    let g = paper();
    assert_eq!(g.centre(1), Some((0.5, 0.5)));
    assert_eq!(g.centre(400), Some((19.5, 19.5)));
    assert_eq!(g.number(0.5, 0.5), Some(1));
    assert_eq!(g.number(19.5, 19.5), Some(400));
}

#[test]
fn the_last_cell_of_a_row_is_the_mod_zero_case() {
    let g = paper();
    // s = 20: mod(20, 20) = 0, the east end of the first row (eq. 3 read literally gives -0.5).
    assert_eq!(g.centre(20), Some((19.5, 0.5)));
    // s = 21: the west end of the second row.
    assert_eq!(g.centre(21), Some((0.5, 1.5)));
    assert_eq!(g.centre(40), Some((19.5, 1.5)));
    // A shifted, scaled grid: origin (100, -50), a = 10, M = 7: s = 14 is column 7 of row 2.
    let h = CellNumbering { origin: (100.0, -50.0), cell: 10.0, columns: 7, rows: 3 };
    assert_eq!(h.centre(14), Some((165.0, -35.0)));
    assert_eq!(h.centre(15), Some((105.0, -25.0)));
}

#[test]
fn every_cell_round_trips() {
    for g in [paper(), CellNumbering { origin: (100.0, -50.0), cell: 10.0, columns: 7, rows: 3 }] {
        for s in 1..=g.len() {
            let (x, y) = g.centre(s).unwrap();
            assert_eq!(g.number(x, y), Some(s), "{g:?} cell {s} at ({x}, {y})");
            // Any point of the cell, not only its centre: a quarter cell south-west of it.
            assert_eq!(g.number(x - 0.25 * g.cell, y - 0.25 * g.cell), Some(s));
        }
    }
}

#[test]
fn out_of_range_numbers_and_points_have_no_cell() {
    let g = paper();
    assert_eq!(g.centre(0), None);
    assert_eq!(g.centre(401), None);
    assert_eq!(g.number(-0.1, 5.0), None);
    assert_eq!(g.number(5.0, 20.1), None);
    assert_eq!(g.number(f64::NAN, 5.0), None);
    // The grid's own east and north edges belong to its last column and row.
    assert_eq!(g.number(20.0, 20.0), Some(400));
    assert_eq!(g.number(1.0, 0.0), Some(2));
    let empty = CellNumbering { columns: 0, ..g };
    assert_eq!((empty.centre(1), empty.number(0.0, 0.0)), (None, None));
}
