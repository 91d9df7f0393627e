//! The data readers on fixtures written by the reference libraries (netCDF4-python on the
//! NetCDF C library, rasterio on GDAL; `scripts/make_geo_fixtures.py`). Every bathymetry
//! fixture holds the plane `-200 + 100 (lon + 125) + 50 (lat - 48)`.

use std::path::PathBuf;

use tidepath_io::geodata::netcdf::{read_bathymetry, Positive};
use tidepath_io::geodata::{esri_ascii, DataFile, GeoBox, GeoGrid};

fn fixture(name: &str) -> DataFile {
    DataFile::Path(PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("tests/data/geo").join(name))
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
        // The nodes inside, and one beyond each edge (for interpolation up to the edge).
        assert_eq!((g.nx(), g.ny()), (6, 7), "{f}: {:?} {:?}", g.lon, g.lat);
        assert!((g.lon[0] + 124.6).abs() < 1e-6 && (g.lat[6] - 48.8).abs() < 1e-6, "{f}");
        assert_plane(&g, 0.05 + 1e-9, &[]);
        let d = read_bathymetry(&fixture(f), None, None, Some(&b), 2).unwrap();
        // Every 2nd node from the south-west one, and one more east so the kept nodes still
        // bracket the box (-124.6 .. -124.0).
        assert_eq!((d.nx(), d.ny()), (4, 4), "{f}: {:?}", d.lon);
        assert!((d.lon[3] + 124.0).abs() < 1e-6, "{f}");
        assert_plane(&d, 0.05 + 1e-9, &[]);
    }
}

#[test]
fn a_box_across_the_antimeridian_is_continuous() {
    let b = GeoBox::new(170.0, -10.0, -170.0, 10.0, "box").unwrap();
    let g = read_bathymetry(&fixture("global_360.nc"), None, None, Some(&b), 1).unwrap();
    assert_eq!(g.lon, (0..13).map(|k| 168.0 + 2.0 * k as f64).collect::<Vec<_>>());
    // The value is the node's longitude in -180..180: 168 .. 178, then -180 .. -168.
    let row: Vec<f64> = (0..g.nx()).map(|i| g.value(i, 0)).collect();
    assert_eq!(
        row,
        vec![168.0, 170.0, 172.0, 174.0, 176.0, 178.0, -180.0, -178.0, -176.0, -174.0, -172.0, -170.0, -168.0]
    );
    // A box across the prime meridian in a 0..360 file.
    let b = GeoBox::new(-5.0, -10.0, 5.0, 10.0, "box").unwrap();
    let g = read_bathymetry(&fixture("global_360.nc"), None, None, Some(&b), 1).unwrap();
    assert_eq!(g.lon, vec![-6.0, -4.0, -2.0, 0.0, 2.0, 4.0, 6.0]);
    assert_eq!((0..7).map(|i| g.value(i, 0)).collect::<Vec<_>>(), vec![-6.0, -4.0, -2.0, 0.0, 2.0, 4.0, 6.0]);
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
    assert!(e(read_bathymetry(&fixture("bathy_classic.nc"), None, None, Some(&far), 1)).contains("the requested box"));
    // A variable with more than lat/lon dimensions needs an index.
    assert!(
        e(read_bathymetry(&fixture("currents_copernicus.nc"), Some("uo"), None, None, 1)).contains("say which index")
    );
    // No coordinate variables: the dimensions alone say nothing about where the grid is.
    let msg = e(read_bathymetry(&fixture("bathy_nocoords.nc"), None, None, None, 1));
    assert!(msg.contains("bathy_nocoords.nc") && msg.contains("longitude"), "{msg}");
    // Truncated files (a download cut short), at several lengths, in every format: one line
    // naming the file, or (where only unused trailing bytes went, as HDF5 files can have) the
    // same grid as the whole file.
    let dir = tempfile::tempdir().unwrap();
    let read = |name: &str, file: &DataFile| match name.rsplit('.').next().unwrap() {
        "nc" => read_bathymetry(file, None, None, None, 1),
        "tif" => tidepath_io::geodata::geotiff::read(file, None, 1),
        _ => esri_ascii::read(file, None, 1),
    };
    let same = |a: &GeoGrid, b: &GeoGrid| {
        a.lon == b.lon
            && a.lat == b.lat
            && a.values.iter().zip(&b.values).all(|(x, y)| x == y || (x.is_nan() && y.is_nan()))
    };
    let mut errors = 0;
    for name in ["bathy_classic.nc", "bathy_nc4.nc", "bathy_area.tif", "bathy.asc"] {
        let whole = read(name, &fixture(name)).unwrap();
        let bytes = std::fs::read(PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("tests/data/geo").join(name)).unwrap();
        for keep in [0, 7, bytes.len() / 3, bytes.len() - 40] {
            let path = dir.path().join(name);
            std::fs::write(&path, &bytes[..keep]).unwrap();
            match read(name, &DataFile::Path(path)) {
                Ok(g) => assert!(keep > bytes.len() / 2 && same(&g, &whole), "{name} cut at {keep} read as {g:?}"),
                Err(err) => {
                    let msg = err.to_string();
                    assert!(msg.contains(name) && !msg.contains('\n'), "{name} cut at {keep}: {msg}");
                    errors += 1;
                }
            }
        }
    }
    assert!(errors >= 14, "{errors}");
}

/// The projection's distance error against geodesic distances (WGS84, geographiclib) over a
/// 300 km box: every pair of a 7 x 7 lattice of points, at mid and high latitude.
#[test]
fn geo_projection_error() {
    use tidepath::geo::GeoFrame;
    for (lon0, lat0) in [(-124.0, 48.5), (10.0, 70.0), (179.5, -17.0), (0.0, 0.0)] {
        let f = GeoFrame::new(lon0, lat0, "o").unwrap();
        // 300 km box: +-150 km about the origin, as lon/lat via the inverse projection.
        let pts: Vec<(f64, f64)> = (0..7)
            .flat_map(|i| (0..7).map(move |j| (-150e3 + 50e3 * i as f64, -150e3 + 50e3 * j as f64)))
            .map(|(x, y)| f.inverse(x, y))
            .collect();
        let mut worst: f64 = 0.0;
        for a in &pts {
            for b in &pts {
                let g = f.geodesic_distance(*a, *b);
                if g < 1.0 {
                    continue;
                }
                let (pa, pb) = (f.forward(a.0, a.1, "a").unwrap(), f.forward(b.0, b.1, "b").unwrap());
                let e = (pa.0 - pb.0).hypot(pa.1 - pb.1);
                worst = worst.max((e - g).abs() / g);
            }
        }
        assert!(worst < 1e-3, "({lon0}, {lat0}): worst relative distance error {worst}");
        eprintln!("({lon0}, {lat0}): worst relative distance error over a 300 km box {:.4}%", worst * 100.0);
    }
}

#[test]
fn copernicus_currents_packed_with_cf_time_and_land() {
    use tidepath_io::geodata::currents::read_currents;
    let c = read_currents(&fixture("currents_copernicus.nc"), None, None, 40.0, None, 1).unwrap();
    let iso: Vec<String> = c.times.iter().map(|t| t.to_rfc3339()).collect();
    assert_eq!(iso, ["2025-11-12T00:00:00+00:00", "2025-11-12T06:00:00+00:00", "2025-11-12T12:00:00+00:00"]);
    assert_eq!(c.depth, Some(50.0), "the level nearest 40 m");
    for (k, h) in [0.0, 6.0, 12.0].iter().enumerate() {
        let (u, v) = (&c.u[k], &c.v[k]);
        assert!((u.value(3, 4) - (0.1 + 0.01 * h)).abs() < 5e-4, "{}", u.value(3, 4));
        assert!((v.value(3, 4) + 0.2).abs() < 5e-4);
        // Land (the fill value) is no data.
        assert!(u.value(u.nx() - 1, u.ny() - 1).is_nan() && v.value(v.nx() - 1, v.ny() - 1).is_nan());
    }
}

#[test]
fn hycom_currents_with_missing_value_and_lon_360() {
    use tidepath_io::geodata::currents::read_currents;
    let b = GeoBox::new(-125.05, 47.95, -124.45, 48.55, "box").unwrap();
    let c = read_currents(&fixture("currents_hycom.nc"), None, None, 0.0, Some(&b), 1).unwrap();
    assert_eq!(c.times[0].to_rfc3339(), "2025-10-29T00:00:00+00:00");
    assert_eq!(c.times[1].to_rfc3339(), "2025-10-29T10:00:00+00:00");
    assert!((c.u[0].lon[0] + 125.0).abs() < 1e-9, "{:?}", c.u[0].lon);
    assert!(c.u[0].value(0, 0).is_nan(), "missing_value is no data");
    assert!((c.u[1].value(2, 2) - 0.3).abs() < 1e-9 && (c.v[1].value(2, 2) - 0.05).abs() < 1e-9);
    let e = read_currents(&fixture("currents_hycom.nc"), Some("nope"), None, 0.0, None, 1).unwrap_err().to_string();
    assert!(e.starts_with("world.current.u: `nope` not found"), "{e}");
    let e = read_currents(&fixture("bathy_classic.nc"), None, None, 0.0, None, 1).unwrap_err().to_string();
    assert!(e.contains("no velocity variable found"), "{e}");
}

#[test]
fn geotiff_pixel_is_area_and_pixel_is_point_written_by_gdal() {
    use tidepath_io::geodata::geotiff;
    let area = geotiff::read(&fixture("bathy_area.tif"), None, 1).unwrap();
    assert_eq!((area.nx(), area.ny()), (13, 11));
    assert!((area.lon[0] + 125.0).abs() < 1e-9 && (area.lat[0] - 48.0).abs() < 1e-9, "{:?} {:?}", area.lon, area.lat);
    assert_plane(&area, 1e-3, &[(-125.0, 48.0)]);
    // Pixel-is-point: GDAL stores the first pixel's centre; the same lattice comes back.
    let point = geotiff::read(&fixture("bathy_point.tif"), None, 1).unwrap();
    assert!((point.lon[0] + 125.0).abs() < 1e-9 && (point.lat[10] - 49.0).abs() < 1e-9, "{:?}", point.lon);
    assert_plane(&point, 1e-3, &[]);
    let b = GeoBox::new(-124.55, 48.25, -124.15, 48.75, "box").unwrap();
    let g = geotiff::read(&fixture("bathy_area.tif"), Some(&b), 1).unwrap();
    assert_eq!((g.nx(), g.ny()), (6, 7));
    assert_plane(&g, 1e-3, &[]);
}

#[test]
fn a_projected_geotiff_is_refused_with_its_epsg_code() {
    use tidepath_io::geodata::geotiff;
    let e = geotiff::read(&fixture("bathy_utm.tif"), None, 1).unwrap_err().to_string();
    assert!(e.contains("EPSG:32610 is a projected CRS"), "{e}");
    let e = geotiff::read(&fixture("bathy_classic.nc"), None, 1).unwrap_err().to_string();
    assert!(e.contains("not a readable GeoTIFF"), "{e}");
}

/// A 1 x 1 degree box out of a file with GEBCO 2024's layout (43200 x 86400 int16, NetCDF-4,
/// chunked and deflated). The file is 600 MB even compressed, so it is not committed: make it
/// with `scripts/make_gebco_like.py` and point `TIDEPATH_GEBCO_LIKE` at it. Checks the values
/// against the script's closed form and prints the read time (the issue asks for under 1 s).
#[test]
#[ignore]
fn gebco_layout_subset() {
    let Ok(path) = std::env::var("TIDEPATH_GEBCO_LIKE") else {
        eprintln!("TIDEPATH_GEBCO_LIKE not set; skipped");
        return;
    };
    let file = DataFile::Path(PathBuf::from(path));
    let bbox = GeoBox::new(-124.5, 48.0, -123.5, 49.0, "box").unwrap();
    let started = std::time::Instant::now();
    let g = read_bathymetry(&file, None, None, Some(&bbox), 1).unwrap();
    let elapsed = started.elapsed();
    let closed = |lat: f64, lon: f64| {
        let (la, lo) = (lat.to_radians(), lon.to_radians());
        (-2500.0 + 2000.0 * (3.0 * lo).sin() * (2.0 * la).cos() + 500.0 * (40.0 * lo).cos()).round()
    };
    for (i, j) in [(0, 0), (g.lon.len() / 2, g.lat.len() / 3), (g.lon.len() - 1, g.lat.len() - 1)] {
        let (lon, lat) = (g.lon[i], g.lat[j]);
        assert_eq!(g.values[j * g.lon.len() + i], closed(lat, lon), "at {lon}, {lat}");
    }
    eprintln!("GEBCO-layout subset: {} x {} nodes in {:.3} s", g.lon.len(), g.lat.len(), elapsed.as_secs_f64());
    assert!(g.lon.len() >= 240 && g.lat.len() >= 240);
}
