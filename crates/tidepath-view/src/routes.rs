//! Routes for the page: the drawn line (the flown curve with a turning radius, else the
//! waypoints), its clock, speed over ground and hover text, and the violations to mark.
//!
//! Hover text at each drawn point gives the time (and UTC instant for a scenario with an
//! epoch), the place in longitude and latitude for a geographic scenario, the depth, the
//! clearance above the seabed and to the nearest obstacle where it is at that moment, and the
//! segment the point is on: its length, duration, speed over ground and its additive cost terms
//! (the model's terms that add up segment by segment; path-level terms, such as turn penalties
//! and normalisations, belong to the whole path and are listed in the route's summary).

use serde_json::{json, Value};
use tidepath::cost::CostModel;
use tidepath::geom::Vec3;
use tidepath::scratch::Scratch;
use tidepath::world::{Dims, Obstacle, Terrain, World};
use tidepath_io::scenario::Scenario;

use crate::lattice::{m, round};
use crate::obstacles::EpochObstacles;
use crate::{poll, Stopped, ViewRoute};

/// Points of one route given the full hover text; a longer route (a flown curve, a plan file of
/// 100,000 points) gives it to every k-th point and its clock alone to the rest, so the page
/// grows by about 60 bytes a point, not 300.
pub const FULL_HOVER_POINTS: usize = 2000;

/// Where the page takes each route's data from: the scenario (clock, frame, cost model) and the
/// true world's obstacles over time.
pub struct RouteContext<'a> {
    pub scenario: &'a Scenario,
    pub world: &'a World,
    pub epochs: &'a [EpochObstacles<'a>],
    pub cost: Option<&'a dyn CostModel>,
}

impl RouteContext<'_> {
    fn obstacles_at(&self, t: f64) -> &[Obstacle] {
        self.epochs
            .iter()
            .rev()
            .find(|e| e.from.is_none_or(|f| f <= t))
            .or(self.epochs.first())
            .map_or(&[], |e| e.obstacles)
    }

    /// Distance from `p` to the nearest obstacle present at time `t` (`None` without any).
    fn obstacle_clearance(&self, p: Vec3, t: f64) -> Option<f64> {
        self.obstacles_at(t)
            .iter()
            .filter(|o| o.window.is_none_or(|(a, b)| (a..=b).contains(&t)))
            .map(|o| o.shape_at(t).distance_to_point(p))
            .min_by(f64::total_cmp)
    }

    /// Each waypoint segment's additive terms, evaluated alone on the mission's clock.
    fn segment_terms(&self, r: &ViewRoute) -> Vec<Vec<(&'static str, f64)>> {
        let (Some(cost), Some(_)) = (self.cost, self.scenario.missions.get(r.mission)) else { return Vec::new() };
        let base = self.scenario.mission_model(r.mission);
        let additive = cost.additive_terms();
        let mut scratch = Scratch::default();
        let mut terms = [0.0; tidepath::cost::MAX_TERMS];
        r.points
            .windows(2)
            .enumerate()
            .map(|(k, w)| {
                let speed = r.speeds.as_ref().and_then(|s| s.get(k).map(std::slice::from_ref));
                let mut model = base.with_speeds(speed);
                model.departure_time = r.times.get(k).copied().unwrap_or(base.departure_time);
                cost.evaluate(&model, w, &mut scratch, &mut terms);
                cost.term_names()
                    .iter()
                    .zip(terms)
                    .filter(|(n, _)| additive.contains(n))
                    .map(|(n, v)| (*n, v))
                    .collect()
            })
            .collect()
    }
}

/// The drawn line of a route: the flown curve when there is one, else the waypoints.
fn drawn(r: &ViewRoute) -> (&[Vec3], &[f64]) {
    match &r.flown {
        Some((p, t)) if p.len() == t.len() && p.len() >= 2 => (p, t),
        _ => (&r.points, &r.times),
    }
}

/// Speed over ground leaving each point (the last point repeats the one before).
pub fn ground_speeds(points: &[Vec3], times: &[f64]) -> Vec<f64> {
    let n = points.len().min(times.len());
    let mut out: Vec<f64> = (0..n.saturating_sub(1))
        .map(|k| {
            let dt = times[k + 1] - times[k];
            if dt > 0.0 {
                points[k].distance(points[k + 1]) / dt
            } else {
                0.0
            }
        })
        .collect();
    if let Some(&last) = out.last() {
        out.push(last);
    } else if n == 1 {
        out.push(0.0);
    }
    out
}

/// The waypoint segment a time falls on.
fn segment_at(times: &[f64], t: f64) -> usize {
    let k = times.partition_point(|x| *x <= t);
    k.saturating_sub(1).min(times.len().saturating_sub(2))
}

/// "t = 812.3 s" with the UTC instant when the scenario has an epoch.
pub fn clock_text(s: &Scenario, t: f64) -> String {
    match tidepath_io::export::utc(s.epoch, t) {
        Some(u) => format!("t = {t:.1} s ({u})"),
        None => format!("t = {t:.1} s"),
    }
}

/// One route as the page draws it.
pub fn route_json(cx: &RouteContext<'_>, r: &ViewRoute, stop: &dyn Fn() -> bool) -> Result<Value, Stopped> {
    let (pts, ts) = drawn(r);
    let n = pts.len().min(ts.len());
    let sog = ground_speeds(&pts[..n], &ts[..n]);
    let seg_terms = cx.segment_terms(r);
    let three_d = cx.world.dims == Dims::Three;
    let mut hover = Vec::with_capacity(n);
    let stride = n.div_ceil(FULL_HOVER_POINTS).max(1);
    for k in 0..n {
        if k % 64 == 0 {
            poll(stop)?;
        }
        let (p, t) = (pts[k], ts[k]);
        let mut lines = vec![format!("<b>{}</b>", r.label), clock_text(cx.scenario, t)];
        if k % stride != 0 && k + 1 != n {
            hover.push(lines.join("<br>"));
            continue;
        }
        if let Some(f) = &cx.scenario.frame {
            let (lon, lat) = f.inverse(p.x, p.y);
            lines.push(format!("{} {}", crate::axes::degrees(lat, 'N', 'S'), crate::axes::degrees(lon, 'E', 'W')));
        } else {
            lines.push(format!("x {:.0} m, y {:.0} m", p.x, p.y));
        }
        let mut place = Vec::new();
        if three_d {
            place.push(format!("depth {:.1} m", -p.z));
            if !matches!(cx.world.terrain, Terrain::None) {
                place.push(format!("{:.1} m above the seabed", p.z - cx.world.terrain.elevation(p.x, p.y)));
            }
        }
        if let Some(c) = cx.obstacle_clearance(p, t) {
            place.push(format!("nearest obstacle {c:.1} m"));
        }
        if !place.is_empty() {
            lines.push(place.join(" · "));
        }
        if r.points.len() >= 2 {
            let s = segment_at(&r.times, t);
            let (a, b) = (r.points[s], r.points[s + 1]);
            let dt = r.times.get(s + 1).zip(r.times.get(s)).map_or(f64::NAN, |(b, a)| b - a);
            let len = a.distance(b);
            let sog_seg = if dt > 0.0 { len / dt } else { f64::NAN };
            lines.push(format!(
                "segment {} of {}: {len:.0} m in {dt:.1} s, {sog_seg:.2} m/s over ground",
                s + 1,
                r.points.len() - 1
            ));
            if let Some(terms) = seg_terms.get(s).filter(|t| !t.is_empty()) {
                let parts: Vec<String> = terms.iter().map(|(n, v)| format!("{n} {v:.4}")).collect();
                lines.push(format!("segment terms: {}", parts.join(", ")));
            }
        }
        hover.push(lines.join("<br>"));
    }
    let violations: Vec<Value> = r
        .violations
        .iter()
        .take(200)
        .filter_map(|v| {
            let p = r.points.get(v.index.min(r.points.len().saturating_sub(1)))?;
            Some(json!({ "x": m(p.x), "y": m(p.y), "z": m(p.z), "text": v.message }))
        })
        .collect();
    let terms: Vec<Value> = r.terms.iter().map(|(n, v)| json!([n, v])).collect();
    Ok(json!({
        "label": r.label,
        "group": r.group,
        "status": r.status,
        "feasible": r.feasible,
        "cost": r.cost,
        "terms": terms,
        "length_m": m(pts[..n].windows(2).map(|w| w[0].distance(w[1])).sum::<f64>()),
        "x": pts[..n].iter().map(|p| m(p.x)).collect::<Vec<_>>(),
        "y": pts[..n].iter().map(|p| m(p.y)).collect::<Vec<_>>(),
        "z": pts[..n].iter().map(|p| m(p.z)).collect::<Vec<_>>(),
        "t": ts[..n].iter().map(|t| round(*t, 0.01)).collect::<Vec<_>>(),
        "sog": sog.iter().map(|v| round(*v, 1e-3)).collect::<Vec<_>>(),
        "hover": hover,
        "violations": violations,
    }))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ground_speed_is_distance_over_time() {
        let p = [Vec3::ZERO, Vec3::new(30.0, 40.0, 0.0), Vec3::new(30.0, 40.0, -10.0)];
        assert_eq!(ground_speeds(&p, &[0.0, 25.0, 35.0]), vec![2.0, 1.0, 1.0]);
        assert_eq!(ground_speeds(&p[..1], &[0.0]), vec![0.0]);
    }

    #[test]
    fn a_time_maps_to_its_waypoint_segment() {
        let t = [0.0, 10.0, 30.0, 60.0];
        assert_eq!(segment_at(&t, 0.0), 0);
        assert_eq!(segment_at(&t, 12.0), 1);
        assert_eq!(segment_at(&t, 30.0), 2);
        // The arrival belongs to the last segment.
        assert_eq!(segment_at(&t, 60.0), 2);
        assert_eq!(segment_at(&t, 99.0), 2);
    }
}
