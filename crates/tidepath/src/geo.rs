//! The geographic frame: latitude/longitude projected into tidepath's local metric frame (x
//! east, y north, metres) by the **azimuthal equidistant projection on the WGS84 ellipsoid**
//! about an origin (the centre of a scenario's box).
//!
//! Why this projection: distance and direction from the origin are exact (x = s sin α,
//! y = s cos α with s and α the geodesic distance and azimuth from the origin, computed by
//! `geographiclib-rs`), and between any two points within r of the origin the distance error
//! grows like r²/(6 R²): about 0.01% at 150 km, the half-width of a 300 km box. The test
//! `geo_projection_error` measures it against geodesic distances (under 0.1% over a 300 km box,
//! as promised in docs/data-formats.md).
//!
//! Depth is not projected: z stays metres, up positive, sea surface 0.

use geographiclib_rs::{DirectGeodesic, Geodesic, InverseGeodesic};

use crate::error::{Error, Result};

/// Largest distance from the origin a projected point may have: 2000 km. Beyond that the
/// local frame's distortion (about 1.6% at 2000 km) makes metric planning misleading.
pub const MAX_RADIUS_M: f64 = 2.0e6;

/// A local metric frame about (`lon0`, `lat0`).
#[derive(Clone, Debug)]
pub struct GeoFrame {
    pub lon0: f64,
    pub lat0: f64,
    geodesic: Geodesic,
}

impl PartialEq for GeoFrame {
    fn eq(&self, o: &Self) -> bool {
        self.lon0 == o.lon0 && self.lat0 == o.lat0
    }
}

impl GeoFrame {
    /// A frame about (`lon0`, `lat0`) in degrees; `field` names the input in errors.
    pub fn new(lon0: f64, lat0: f64, field: &str) -> Result<Self> {
        check_lon_lat(lon0, lat0, field)?;
        if lat0.abs() > 89.0 {
            return Err(Error::input(
                field,
                format!("origin latitude {lat0} is too close to a pole (limit 89 degrees)"),
            ));
        }
        Ok(Self { lon0, lat0, geodesic: Geodesic::wgs84() })
    }

    /// (x, y) in metres of (`lon`, `lat`); `field` names the input in errors (a point too far
    /// from the origin, or not a longitude/latitude).
    pub fn forward(&self, lon: f64, lat: f64, field: &str) -> Result<(f64, f64)> {
        check_lon_lat(lon, lat, field)?;
        let (s, azi, _, _): (f64, f64, f64, f64) = self.geodesic.inverse(self.lat0, self.lon0, lat, lon);
        if s.is_nan() || s > MAX_RADIUS_M {
            return Err(Error::input(
                field,
                format!(
                    "({lon}, {lat}) is {:.0} km from the frame's origin ({}, {}); the local frame reaches {:.0} km",
                    s / 1e3,
                    self.lon0,
                    self.lat0,
                    MAX_RADIUS_M / 1e3
                ),
            ));
        }
        let a = azi.to_radians();
        Ok((s * a.sin(), s * a.cos()))
    }

    /// (lon, lat) in degrees of the point (`x`, `y`) metres from the origin; longitudes in
    /// (-180, 180].
    pub fn inverse(&self, x: f64, y: f64) -> (f64, f64) {
        let s = x.hypot(y);
        if s == 0.0 {
            return (self.lon0, self.lat0);
        }
        let azi = x.atan2(y).to_degrees();
        let (lat, lon): (f64, f64) = self.geodesic.direct(self.lat0, self.lon0, azi, s);
        (normalise_lon(lon), lat)
    }

    /// The point (`x`, `y`) in degrees for messages: "48.3812 N, 123.2101 W".
    pub fn place(&self, x: f64, y: f64) -> String {
        let (lon, lat) = self.inverse(x, y);
        let ns = if lat >= 0.0 { "N" } else { "S" };
        let ew = if lon >= 0.0 { "E" } else { "W" };
        format!("{:.4} {ns}, {:.4} {ew}", lat.abs(), lon.abs())
    }

    /// A horizontal vector given east and north at the point (`lon`, `lat`), which the frame
    /// puts at (`x`, `y`), in the frame's x and y: they differ by the meridian convergence, the
    /// angle of local north on the map, 0 at the origin and growing away from it.
    pub fn east_north_to_xy(&self, (lon, lat): (f64, f64), (x, y): (f64, f64), east: f64, north: f64) -> (f64, f64) {
        let up = self.forward(lon, (lat + 1e-3).min(90.0), "vector").map(|(x2, y2)| (x2 - x, y2 - y));
        let angle = up.map(|(dx, dy)| dx.atan2(dy)).unwrap_or(0.0);
        let (s, c) = angle.sin_cos();
        (east * c + north * s, -east * s + north * c)
    }

    /// The geodesic distance in metres between two points given in degrees.
    pub fn geodesic_distance(&self, (lon1, lat1): (f64, f64), (lon2, lat2): (f64, f64)) -> f64 {
        self.geodesic.inverse(lat1, lon1, lat2, lon2)
    }
}

/// Longitude in (-180, 180].
pub fn normalise_lon(lon: f64) -> f64 {
    let l = (lon + 180.0).rem_euclid(360.0) - 180.0;
    if l == -180.0 {
        180.0
    } else {
        l
    }
}

fn check_lon_lat(lon: f64, lat: f64, field: &str) -> Result<()> {
    if !lon.is_finite() || lon.abs() > 360.0 {
        return Err(Error::input(field, format!("longitude must be within [-360, 360] degrees, got {lon}")));
    }
    if !lat.is_finite() || lat.abs() > 90.0 {
        return Err(Error::input(field, format!("latitude must be within [-90, 90] degrees, got {lat}")));
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn distance_and_direction_from_the_origin_are_exact() {
        let f = GeoFrame::new(-124.0, 48.5, "o").unwrap();
        // One degree of latitude north: the meridian arc at 48.5 N, about 111.2 km.
        let (x, y) = f.forward(-124.0, 49.5, "p").unwrap();
        assert!(x.abs() < 1e-6);
        assert!((y - f.geodesic_distance((-124.0, 48.5), (-124.0, 49.5))).abs() < 1e-6);
        assert!((y - 111_226.0).abs() < 50.0, "{y}");
        let (lon, lat) = f.inverse(x, y);
        assert!((lon + 124.0).abs() < 1e-9 && (lat - 49.5).abs() < 1e-9);
        assert_eq!(f.inverse(0.0, 0.0), (-124.0, 48.5));
    }

    #[test]
    fn forward_and_inverse_round_trip_across_the_antimeridian() {
        let f = GeoFrame::new(179.5, -17.0, "o").unwrap();
        for (lon, lat) in [(-179.5, -17.2), (179.9, -16.5), (178.8, -18.0)] {
            let (x, y) = f.forward(lon, lat, "p").unwrap();
            let (l2, b2) = f.inverse(x, y);
            assert!((normalise_lon(l2 - lon)).abs() < 1e-9 && (b2 - lat).abs() < 1e-9, "{lon} {lat}: {l2} {b2}");
        }
        assert!(f.forward(-179.5, -17.0, "p").unwrap().0 > 0.0, "east of the antimeridian is east");
    }

    #[test]
    fn bad_points_name_the_field() {
        let f = GeoFrame::new(0.0, 0.0, "o").unwrap();
        assert!(f
            .forward(f64::NAN, 0.0, "mission.start")
            .unwrap_err()
            .to_string()
            .starts_with("mission.start: longitude"));
        assert!(f.forward(0.0, 91.0, "p").unwrap_err().to_string().contains("latitude"));
        assert!(f.forward(40.0, 0.0, "p").unwrap_err().to_string().contains("km from the frame's origin"));
        assert!(GeoFrame::new(0.0, 89.5, "o").is_err());
        assert_eq!(normalise_lon(-180.0), 180.0);
        assert_eq!(normalise_lon(190.0), -170.0);
    }
}
