//! The readers at the edges of what they are asked: a box edge between two rows, a box smaller
//! than one cell, a box as large as the file. Fixtures hold the plane
//! `-200 + 100 (lon + 125) + 50 (lat - 48)` on 0.1-degree nodes over 125..123.8 W, 48..49 N.

use std::path::PathBuf;

use tidepath_io::geodata::currents::read_currents;
use tidepath_io::geodata::netcdf::read_bathymetry;
use tidepath_io::geodata::{esri_ascii, geotiff, DataFile, GeoBox, GeoGrid};

fn fixture(name: &str) -> DataFile {
    DataFile::Path(PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("tests/data/geo").join(name))
}

fn same_nodes(a: &GeoGrid, b: &GeoGrid, what: &str) {
    assert_eq!((a.nx(), a.ny()), (b.nx(), b.ny()), "{what}: {:?} {:?} vs {:?} {:?}", a.lon, a.lat, b.lon, b.lat);
    for (x, y) in a.lon.iter().zip(&b.lon).chain(a.lat.iter().zip(&b.lat)) {
        assert!((x - y).abs() < 1e-6, "{what}: axis {x} vs {y}");
    }
    for (x, y) in a.values.iter().zip(&b.values) {
        assert!((x - y).abs() < 1e-3 || (x.is_nan() && y.is_nan()), "{what}: {x} vs {y}");
    }
}

/// The box of the issue's example, its edges between rows and columns: the ESRI ASCII reader
/// keeps the bracketing nodes as NetCDF does, so both read the same nodes and values.
#[test]
fn an_esri_box_edge_between_rows_reads_the_same_seabed_as_netcdf() {
    let b = GeoBox::new(-124.95, 48.05, -124.45, 48.45, "box").unwrap();
    let nc = read_bathymetry(&fixture("bathy_classic.nc"), None, None, Some(&b), 1).unwrap();
    let asc = esri_ascii::read(&fixture("bathy.asc"), Some(&b), 1).unwrap();
    let tif = geotiff::read(&fixture("bathy_area.tif"), Some(&b), 1).unwrap();
    // 125.0 .. 124.4 W and 48.0 .. 48.5 N: one node beyond every edge.
    assert_eq!((nc.nx(), nc.ny()), (7, 6), "{:?} {:?}", nc.lon, nc.lat);
    same_nodes(&asc, &nc, "ESRI ASCII");
    same_nodes(&tif, &nc, "GeoTIFF");
    // At 48.051 N, 124.70 W, just inside the south edge: the plane, not phantom land.
    let want = -200.0 + 100.0 * (-124.70 + 125.0) + 50.0 * 0.051;
    for g in [&nc, &asc, &tif] {
        assert!((g.sample(-124.70, 48.051).unwrap() - want).abs() < 1e-3);
    }
}

/// A box smaller than one cell (a 1/12-degree forecast around a small survey) reads the four
/// nodes around it in every format, and in a current forecast.
#[test]
fn a_box_smaller_than_a_cell_reads_the_bracketing_nodes() {
    let b = GeoBox::new(-124.47, 48.52, -124.43, 48.58, "box").unwrap();
    let grids = [
        read_bathymetry(&fixture("bathy_classic.nc"), None, None, Some(&b), 1).unwrap(),
        read_bathymetry(&fixture("bathy_nc4.nc"), None, None, Some(&b), 1).unwrap(),
        esri_ascii::read(&fixture("bathy.asc"), Some(&b), 1).unwrap(),
        geotiff::read(&fixture("bathy_area.tif"), Some(&b), 1).unwrap(),
    ];
    for g in &grids {
        assert_eq!((g.nx(), g.ny()), (2, 2), "{:?} {:?}", g.lon, g.lat);
        assert!((g.lon[0] + 124.5).abs() < 1e-6 && (g.lat[1] - 48.6).abs() < 1e-6, "{:?} {:?}", g.lon, g.lat);
        // The plane at the box's centre.
        let want = -200.0 + 100.0 * 0.55 + 50.0 * 0.55;
        assert!((g.sample(-124.45, 48.55).unwrap() - want).abs() < 0.06);
    }
    // The HYCOM fixture's nodes are 0.1 degree apart too: a 0.02-degree box reads 2 x 2.
    let small = GeoBox::new(-124.79, 48.11, -124.77, 48.13, "box").unwrap();
    let c = read_currents(&fixture("currents_hycom.nc"), None, None, 0.0, Some(&small), 1).unwrap();
    assert_eq!((c.u[0].nx(), c.u[0].ny()), (2, 2), "{:?} {:?}", c.u[0].lon, c.u[0].lat);
    // Outside the data it is still refused, in one line.
    let far = GeoBox::new(10.0, 10.0, 10.01, 10.01, "box").unwrap();
    let e = read_bathymetry(&fixture("bathy_classic.nc"), None, None, Some(&far), 1).unwrap_err().to_string();
    assert!(e.contains("the requested box") && !e.contains('\n'), "{e}");
}

/// `bounds` equal to the file's own extent: the metric domain (the rectangle holding the
/// projected box) pokes past the box's curved edges, beyond the file. The loader warns with
/// the count, the place and the remedy; a box inside the file has no such warning.
#[test]
fn a_box_as_large_as_the_file_warns_naming_the_place_and_the_remedy() {
    let path = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("tests/data/geo/bathy_classic.nc");
    let scenario = |min: &str, max: &str| {
        format!(
            r#"
name = "extent"
[world]
dimensions = 2
frame = "geographic"
bounds = {{ min = [{min}, 0.0], max = [{max}, 0.0] }}
[world.terrain]
kind = "file"
path = "{}"
[mission]
start = [-124.5, 48.5, 0.0]
goal = [-124.3, 48.6, 0.0]
"#,
            path.display()
        )
    };
    let s = tidepath_io::scenario::Scenario::from_toml(&scenario("-125.0, 48.0", "-123.8, 49.0"), "t.toml").unwrap();
    let w = s.warnings.iter().find(|w| w.contains("beyond the file's data")).expect("a warning");
    assert!(w.contains("give world.bounds a box inside the file") && w.contains(" N, "), "{w}");
    let inside =
        tidepath_io::scenario::Scenario::from_toml(&scenario("-124.8, 48.2", "-124.0, 48.8"), "t.toml").unwrap();
    assert!(inside.warnings.is_empty(), "{:?}", inside.warnings);
}

/// An empty file says it is empty, in every format; a domain around a pole is refused in one
/// line (its longitudes go all the way round).
#[test]
fn an_empty_file_and_a_box_around_a_pole_are_refused_saying_so() {
    let dir = tempfile::tempdir().unwrap();
    for name in ["empty.nc", "empty.asc", "empty.tif"] {
        let path = dir.path().join(name);
        std::fs::write(&path, b"").unwrap();
        let file = DataFile::Path(path);
        let e = match name {
            "empty.nc" => read_bathymetry(&file, None, None, None, 1),
            "empty.asc" => esri_ascii::read(&file, None, 1),
            _ => geotiff::read(&file, None, 1),
        }
        .unwrap_err()
        .to_string();
        assert!(e.contains(name) && e.ends_with("the file is empty (0 bytes)"), "{e}");
    }
    let path = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("tests/data/geo/bathy_classic.nc");
    let text = format!(
        "name = \"pole\"\n[world]\ndimensions = 2\nframe = \"geographic\"\nbounds = {{ min = [-180.0, 80.0, 0.0], max = [180.0, 89.0, 0.0] }}\n[world.terrain]\nkind = \"file\"\npath = \"{}\"\n[mission]\nstart = [0.0, 84.0, 0.0]\ngoal = [10.0, 84.0, 0.0]\n",
        path.display()
    );
    let e = tidepath_io::scenario::Scenario::from_toml(&text, "t.toml").map(|_| ()).unwrap_err().to_string();
    assert!(e.starts_with("world.bounds:") && e.contains("North Pole") && !e.contains('\n'), "{e}");
}

/// A global grid holding both -180 and +180 (the same meridian twice): a box across the
/// antimeridian reads it, one column per longitude, and the values across the seam are the
/// file's. The field is periodic in longitude, f = -100 + 10 cos(lon) - lat.
#[test]
fn a_global_grid_with_both_180_columns_reads_across_the_antimeridian() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("global.asc");
    let f = |lon: f64, lat: f64| -100.0 + 10.0 * lon.to_radians().cos() - lat;
    // Cell centres at -180, -179, ..., 180 (361 columns) and 3 N .. 3 S.
    let mut text = String::from("ncols 361\nnrows 7\nxllcorner -180.5\nyllcorner -3.5\ncellsize 1\n");
    for r in 0..7 {
        let lat = 3.0 - r as f64;
        let row: Vec<String> = (0..361).map(|c| format!("{:.6}", f(-180.0 + c as f64, lat))).collect();
        text.push_str(&row.join(" "));
        text.push('\n');
    }
    std::fs::write(&path, text).unwrap();
    let b = GeoBox::new(178.6, -1.2, -178.7, 1.3, "box").unwrap();
    let g = esri_ascii::read(&DataFile::Path(path), Some(&b), 1).unwrap();
    // 178 .. 182 (= 178 W): one node beyond each edge, the seam's meridian once.
    let lons: Vec<f64> = g.lon.iter().map(|l| (l * 1e6).round() / 1e6).collect();
    assert_eq!(lons, vec![178.0, 179.0, 180.0, 181.0, 182.0], "{:?}", g.lon);
    for (lon, lat) in [(179.5, 0.5), (180.25, -1.0), (180.9, 1.2)] {
        let got = g.sample(lon, lat).unwrap();
        // Bilinear on 1-degree cells of a cosine: within 10 (1 - cos 0.5 deg) of f.
        assert!((got - f(lon, lat)).abs() < 0.01, "({lon}, {lat}): {got} vs {}", f(lon, lat));
    }
}
