//! Routes read from files (plan JSON, GeoJSON, GPX, KML, CSV) put into a scenario's frame.
//!
//! The file says its frame (see [`crate::routes`]); nothing is guessed. Longitude/latitude
//! routes need a geographic scenario and are projected by its frame; a hand-written plan JSON
//! that does not say its frame is metres for a local scenario and refused for a geographic
//! one, since its numbers could be either.

use tidepath::error::{Error, Result};
use tidepath::geom::Vec3;
use tidepath::world::Dims;

use super::Scenario;
use crate::plan_json::{PlanFile, RouteFrame};

impl Scenario {
    /// Each route of `file` in this scenario's metres; `source` names the file in errors.
    pub fn route_paths(&self, file: &PlanFile, source: &str) -> Result<Vec<Vec<Vec3>>> {
        let frame = match (file.frame, &self.frame) {
            (Some(f), _) => f,
            (None, None) => RouteFrame::Metres,
            (None, Some(_)) => {
                return Err(Error::input(
                    format!("{source}: frame"),
                    format!(
                        "scenario '{}' is geographic: say whether the waypoints are longitude, latitude and depth (\"frame\": \"lonlat\") or the scenario's metres (\"frame\": \"metres\")",
                        self.name
                    ),
                ))
            }
        };
        let mut out = Vec::with_capacity(file.paths.len());
        for (i, (name, points)) in file.paths.iter().enumerate() {
            let what = name.clone().map_or(format!("route {}", i + 1), |n| format!("route {} ('{n}')", i + 1));
            // The 2-D plane of this route's mission, for points without a depth.
            let plane = self.missions.get(i).map_or(self.start.z, |m| m.start.z);
            let mut path = Vec::with_capacity(points.len());
            for (k, p) in points.iter().enumerate() {
                let z = if p.z.is_nan() {
                    match self.world.dims {
                        Dims::Two => plane,
                        Dims::Three => {
                            return Err(Error::input(
                                source,
                                format!(
                                    "{what}, point {}: no depth or elevation, and scenario '{}' is 3-D",
                                    k + 1,
                                    self.name
                                ),
                            ))
                        }
                    }
                } else {
                    p.z
                };
                let q = match (frame, &self.frame) {
                    (RouteFrame::Metres, _) => Vec3::new(p.x, p.y, z),
                    (RouteFrame::LonLat, Some(f)) => {
                        let (x, y) = f.forward(p.x, p.y, &format!("{source}: {what}, point {}", k + 1))?;
                        Vec3::new(x, y, z)
                    }
                    (RouteFrame::LonLat, None) => {
                        return Err(Error::input(
                            source,
                            format!(
                                "this {} file is in longitude/latitude, but scenario '{}' is local (metres): use a geographic scenario or a file in metres",
                                file.format, self.name
                            ),
                        ))
                    }
                };
                path.push(q);
            }
            out.push(path);
        }
        Ok(out)
    }
}
