//! The data readers on fixtures written by the reference libraries (netCDF4-python on the
//! NetCDF C library, rasterio on GDAL; `scripts/make_geo_fixtures.py`). Every bathymetry
//! fixture holds the plane `-200 + 100 (lon + 125) + 50 (lat - 48)`.

use std::path::PathBuf;

use tidepath::io::geodata::netcdf::{read_bathymetry, Positive};
use tidepath::io::geodata::{esri_ascii, GeoBox, GeoGrid};

fn fixture(name: &str) -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("tests/data/geo").join(name)
}

fn plane(lon: f64, lat: f64) -> f64 {
    -200.0 + 100.0 * (lon + 125.0) + 50.0 * (lat - 48.0)
}

/// Every node holds the plane within `tol`, except the `nan` nodes (no data in the file).
fn assert_plane(g: &GeoGrid, tol: f64, nan: &[(f64, f64)]) {
    assert_eq!(g.values.len(), g.nx() * g.ny());
    for j in 0..g.ny() {
        for i in 0..g.nx() {
            let (lon, lat) = (g.lon[i], g.lat[j]);
            let v = g.value(i, j);
            if nan.iter().any(|&(x, y)| (x - lon).abs() < 1e-6 && (y - lat).abs() < 1e-6) {
                assert!(v.is_nan(), "({lon}, {lat}) should be no data, got {v}");
            } else {
                assert!((v - plane(lon, lat)).abs() <= tol, "({lon}, {lat}): {v} vs {}", plane(lon, lat));
            }
        }
    }
}

#[test]
fn classic_cdf1_with_a_fill_value() {
    let g = read_bathymetry(&fixture("bathy_classic.nc"), None, None, None, 1).unwrap();
    assert_eq!((g.nx(), g.ny()), (13, 11));
    assert_plane(&g, 1e-3, &[(-125.0, 48.0)]);
}

#[test]
fn offset64_cdf2_descending_latitude_and_depth_down() {
    let g = read_bathymetry(&fixture("bathy_64bit.nc"), None, None, None, 1).unwrap();
    assert!(g.lat.windows(2).all(|w| w[1] > w[0]));
    assert_plane(&g, 1e-9, &[]);
    // Overriding the convention flips the sign.
    let up = read_bathymetry(&fixture("bathy_64bit.nc"), Some("depth"), Some(Positive::Up), None, 1).unwrap();
    assert!((up.value(0, 0) + g.value(0, 0)).abs() < 1e-9);
}

#[test]
fn cdf5_lon_360_and_lon_lat_order() {
    let g = read_bathymetry(&fixture("bathy_cdf5.nc"), None, None, None, 1).unwrap();
    assert!((g.lon[0] + 125.0).abs() < 1e-9, "{:?}", g.lon);
    assert_plane(&g, 1e-9, &[]);
}

#[test]
fn netcdf4_chunked_deflate_packed_int16() {
    let g = read_bathymetry(&fixture("bathy_nc4.nc"), None, None, None, 1).unwrap();
    // Packed in 0.1 m steps: exact to half a step.
    assert_plane(&g, 0.05 + 1e-9, &[(-123.8, 49.0)]);
}

#[test]
fn a_subset_box_and_decimation_read_only_the_box() {
    let b = GeoBox::new(-124.55, 48.25, -124.15, 48.75, "box").unwrap();
    for f in ["bathy_classic.nc", "bathy_64bit.nc", "bathy_cdf5.nc", "bathy_nc4.nc"] {
        let g = read_bathymetry(&fixture(f), None, None, Some(&b), 1).unwrap();
        assert_eq!((g.nx(), g.ny()), (4, 5), "{f}: {:?} {:?}", g.lon, g.lat);
        assert!((g.lon[0] + 124.5).abs() < 1e-6 && (g.lat[4] - 48.7).abs() < 1e-6, "{f}");
        assert_plane(&g, 0.05 + 1e-9, &[]);
        let d = read_bathymetry(&fixture(f), None, None, Some(&b), 2).unwrap();
        assert_eq!((d.nx(), d.ny()), (2, 3), "{f}");
        assert_plane(&d, 0.05 + 1e-9, &[]);
    }
}

#[test]
fn a_box_across_the_antimeridian_is_continuous() {
    let b = GeoBox::new(170.0, -10.0, -170.0, 10.0, "box").unwrap();
    let g = read_bathymetry(&fixture("global_360.nc"), None, None, Some(&b), 1).unwrap();
    assert_eq!(g.lon, (0..11).map(|k| 170.0 + 2.0 * k as f64).collect::<Vec<_>>());
    // The value is the node's longitude in -180..180: 170 .. 178, then -180 .. -170.
    let row: Vec<f64> = (0..g.nx()).map(|i| g.value(i, 0)).collect();
    assert_eq!(row, vec![170.0, 172.0, 174.0, 176.0, 178.0, -180.0, -178.0, -176.0, -174.0, -172.0, -170.0]);
    // A box across the prime meridian in a 0..360 file.
    let b = GeoBox::new(-5.0, -10.0, 5.0, 10.0, "box").unwrap();
    let g = read_bathymetry(&fixture("global_360.nc"), None, None, Some(&b), 1).unwrap();
    assert_eq!(g.lon, vec![-4.0, -2.0, 0.0, 2.0, 4.0]);
    assert_eq!((0..5).map(|i| g.value(i, 0)).collect::<Vec<_>>(), vec![-4.0, -2.0, 0.0, 2.0, 4.0]);
}

#[test]
fn esri_ascii_written_by_gdal() {
    let g = esri_ascii::read(&fixture("bathy.asc"), None, 1).unwrap();
    assert_eq!((g.nx(), g.ny()), (13, 11));
    assert_plane(&g, 1e-3, &[(-125.0, 48.0)]);
}

#[test]
fn bad_requests_name_the_problem() {
    let e = |r: tidepath::Result<GeoGrid>| r.unwrap_err().to_string();
    assert!(e(read_bathymetry(&fixture("bathy_classic.nc"), Some("nope"), None, None, 1)).contains("`nope` not found"));
    assert!(e(read_bathymetry(&fixture("missing.nc"), None, None, None, 1)).contains("missing.nc"));
    assert!(e(read_bathymetry(&fixture("bathy.asc"), None, None, None, 1)).contains("not a readable NetCDF file"));
    let far = GeoBox::new(10.0, 10.0, 11.0, 11.0, "box").unwrap();
    assert!(e(read_bathymetry(&fixture("bathy_classic.nc"), None, None, Some(&far), 1))
        .contains("inside the requested box"));
    // A variable with more than lat/lon dimensions needs an index.
    assert!(
        e(read_bathymetry(&fixture("currents_copernicus.nc"), Some("uo"), None, None, 1)).contains("say which index")
    );
}
