//! An independent re-checker for vehicles with a turning radius, written apart from
//! `tidepath::kinematics` and `tidepath::path`: it derives the flown curve from the documented
//! fillet model (docs/kinematics.md) with its own formulas, checks that every turn is flown at
//! the vehicle's radius or more, samples the exact arcs and straights densely at the vehicle's
//! own clock (each turn timed on the documented chords, each chord by the documented crab
//! rule, its time scaled by the arc's length over the chord's) and checks clearance there, and
//! measures the curvature of the sampled curve itself: the circle through every three
//! consecutive samples must have a radius of at least the vehicle's (or of the tightest turn
//! the documented slack lets pass); the smallest such radius is returned, for tests that
//! require the vehicle's radius exactly.

use super::distance;
use tidepath::geom::Vec3;
use tidepath::path::ModelSettings;
use tidepath::vehicle::Vehicle;
use tidepath::world::World;

/// Spacing of the curvature and clearance samples (m) along the flown curve.
const SPACING: f64 = 0.5;
/// Samples closer than this (m) are skipped for the curvature check: a circle through points
/// micrometres apart far from the origin measures rounding, not the curve.
const MIN_CURVATURE_SPACING: f64 = 0.1;
/// Rounding allowance (m) on clearances.
const TOL: f64 = 1e-6;

/// A turn of the fillet model: where it starts and ends, its centre, radius and signed sweep.
#[derive(Clone, Copy, Debug)]
struct Turn {
    a: Vec3,
    b: Vec3,
    cx: f64,
    cy: f64,
    radius: f64,
    start: f64,
    sweep: f64,
}

impl Turn {
    fn at(&self, f: f64) -> Vec3 {
        let ang = self.start + self.sweep * f;
        Vec3::new(
            self.cx + self.radius * ang.cos(),
            self.cy + self.radius * ang.sin(),
            self.a.z + (self.b.z - self.a.z) * f,
        )
    }
}

fn hlen(a: Vec3, b: Vec3) -> f64 {
    ((b.x - a.x).powi(2) + (b.y - a.y).powi(2)).sqrt()
}

/// Heading change at interior waypoint i (rad) and its sign (+1 left), or none when a leg has
/// no horizontal extent.
fn turn_at(p: &[Vec3], i: usize, r: f64) -> Option<(f64, f64)> {
    let (ux, uy) = (p[i].x - p[i - 1].x, p[i].y - p[i - 1].y);
    let (vx, vy) = (p[i + 1].x - p[i].x, p[i + 1].y - p[i].y);
    let (lu, lv) = ((ux * ux + uy * uy).sqrt(), (vx * vx + vy * vy).sqrt());
    if lu <= 1e-9 * r || lv <= 1e-9 * r {
        return None;
    }
    let cross = ux * vy - uy * vx;
    let dot = ux * vx + uy * vy;
    let theta = cross.abs().atan2(dot);
    Some((if theta <= 1e-9 { 0.0 } else { theta }, cross.signum()))
}

fn demand(p: &[Vec3], i: usize, r: f64) -> f64 {
    if i == 0 || i + 1 >= p.len() {
        return 0.0;
    }
    turn_at(p, i, r).map_or(0.0, |(th, _)| r * (th / 2.0).tan())
}

/// The turns of the fillet model, one per interior waypoint (`None`: no turn flown there).
fn turns(p: &[Vec3], r: f64, tolerance: f64) -> Result<Vec<Option<Turn>>, String> {
    let mut out = vec![None; p.len()];
    for i in 1..p.len().saturating_sub(1) {
        let Some((theta, side)) = turn_at(p, i, r) else {
            // A leg without heading: the headings either side must agree (checked by the
            // curvature samples below, where a kink shows).
            continue;
        };
        if theta == 0.0 {
            continue;
        }
        let d = demand(p, i, r);
        // A leg is shared in proportion to the two demands when they do not both fit.
        let share = |len: f64, other: f64| if d + other <= len { d } else { len * d / (d + other) };
        let (l_in, l_out) = (hlen(p[i - 1], p[i]), hlen(p[i], p[i + 1]));
        let t = d.min(share(l_in, demand(p, i - 1, r))).min(share(l_out, demand(p, i + 1, r)));
        let radius = t / (theta / 2.0).tan();
        // Documented slack: a turn under the radius passes when the vehicle's own fillet would
        // lie within the arc tolerance of it (the two arcs' midpoints are (r - radius)
        // (sec(theta/2) - 1) apart).
        let stray = (r - radius) * (1.0 / (theta / 2.0).cos() - 1.0);
        if radius < r * (1.0 - 1e-9) && stray > tolerance {
            return Err(format!(
                "the turn at waypoint {i} is flown at radius {radius:.3} m, under the vehicle's {r} m"
            ));
        }
        let a = p[i] + (p[i - 1] - p[i]) * (t / l_in);
        let b = p[i] + (p[i + 1] - p[i]) * (t / l_out);
        let (ux, uy) = ((p[i].x - p[i - 1].x) / l_in, (p[i].y - p[i - 1].y) / l_in);
        let (cx, cy) = (a.x - side * uy * radius, a.y + side * ux * radius);
        out[i] = Some(Turn { a, b, cx, cy, radius, start: (a.y - cy).atan2(a.x - cx), sweep: side * theta });
    }
    Ok(out)
}

/// Re-checks a path flown with turning radius `r`; `times` are the plan's times at the
/// waypoints (halfway round each turn). Returns the number of samples and the curvature
/// measured.
pub fn recheck_flown(
    world: &World,
    vehicle: &Vehicle,
    settings: &ModelSettings,
    path: &[Vec3],
    times: &[f64],
    speeds: &[f64],
    r: f64,
) -> Result<Rechecked, String> {
    if path.len() != times.len() {
        return Err(format!("{} points but {} times", path.len(), times.len()));
    }
    let turns = turns(path, r, settings.arc_tolerance)?;
    // The tightest radius any turn flies: the curvature samples may not be tighter.
    let tightest = turns.iter().flatten().map(|t| t.radius).fold(r, f64::min);
    let safety = vehicle.safety_distance;
    // Samples of the flown curve in order: (point, time, on a turn).
    let mut samples: Vec<(Vec3, f64, bool)> = Vec::new();
    let mut t = times[0];
    let mut from = path[0];
    let fly = |a: Vec3,
               b: Vec3,
               t: &mut f64,
               scale: f64,
               at: &dyn Fn(f64) -> Vec3,
               turn: bool,
               out: &mut Vec<(Vec3, f64, bool)>|
     -> Result<(), String> {
        let v = super::speed_at(vehicle, speeds, times, *t);
        let pieces =
            super::vehicle_clock(world, settings, vehicle, v, a, b, *t).ok_or("the current blocks the vehicle")?;
        let len = a.distance(b).max(f64::MIN_POSITIVE);
        let t_start = *t;
        let mut done = 0.0;
        for &(p0, p1, ta, tb) in &pieces {
            let piece = p0.distance(p1);
            let n = ((piece * scale / SPACING).ceil() as usize).max(2);
            for k in 0..=n {
                let s = k as f64 / n as f64;
                let f = (done + piece * s) / len;
                out.push((at(f), t_start + (ta - t_start + (tb - ta) * s) * scale, turn));
            }
            done += piece;
        }
        *t = t_start + (pieces.last().map_or(t_start, |p| p.3) - t_start) * scale;
        Ok(())
    };
    for j in 0..path.len() - 1 {
        let end_turn = turns.get(j + 1).copied().flatten().filter(|_| j + 2 < path.len());
        let to = end_turn.map_or(path[j + 1], |tn| tn.a);
        fly(from, to, &mut t, 1.0, &|f| from + (to - from) * f, false, &mut samples)?;
        if let Some(tn) = end_turn {
            // The documented chords: an even count keeping the sagitta within the tolerance.
            let half = if settings.arc_tolerance >= tn.radius {
                std::f64::consts::FRAC_PI_2
            } else {
                (1.0 - settings.arc_tolerance / tn.radius).acos()
            };
            let k = (tn.sweep.abs() / (2.0 * half.max(1e-6))).ceil().clamp(1.0, 1e5) as usize;
            let k = (k + k % 2).max(2);
            let arc_len = (tn.radius * tn.sweep.abs()).hypot(tn.b.z - tn.a.z) / k as f64;
            for c in 0..k {
                let (f0, f1) = (c as f64 / k as f64, (c + 1) as f64 / k as f64);
                let (ca, cb) = (tn.at(f0), tn.at(f1));
                let scale = arc_len / ca.distance(cb);
                fly(ca, cb, &mut t, scale, &|f| tn.at(f0 + (f1 - f0) * f), true, &mut samples)?;
                if 2 * (c + 1) == k && (t - times[j + 1]).abs() > 1e-9 * t.abs().max(1.0) {
                    return Err(format!(
                        "waypoint {}: halfway round its turn at {t} by the re-checker, {} reported",
                        j + 1,
                        times[j + 1]
                    ));
                }
            }
            from = tn.b;
        } else {
            if (t - times[j + 1]).abs() > 1e-9 * t.abs().max(1.0) {
                return Err(format!("waypoint {}: reached at {t} by the re-checker, {} reported", j + 1, times[j + 1]));
            }
            from = path[j + 1];
        }
    }
    // Clearance: on a turn the evaluation checks chords within `arc_tolerance` of the arc, so
    // the arc itself may be that much closer (twice, for the seabed's slope).
    for &(p, time, turn) in &samples {
        let slack = if turn { 2.0 * settings.arc_tolerance } else { 0.0 } + TOL;
        let clearance = p.z - world.terrain.elevation(p.x, p.y);
        if clearance < safety - slack {
            return Err(format!("{p:?} is {clearance:.3} m above the seabed (safety {safety})"));
        }
        for (j, o) in world.obstacles.iter().enumerate() {
            let d = distance(o, p, time);
            if d < safety - slack {
                return Err(format!("{p:?} at t = {time:.3} s is {d:.3} m from obstacle {j} (safety {safety})"));
            }
        }
    }
    // Curvature of the curve itself: the circle through three consecutive distinct samples.
    let pts: Vec<Vec3> = samples.iter().map(|s| s.0).fold(Vec::new(), |mut v, p| {
        if v.last().is_none_or(|q: &Vec3| hlen(*q, p) > MIN_CURVATURE_SPACING) {
            v.push(p);
        }
        v
    });
    let mut min_circumradius = f64::INFINITY;
    for w in pts.windows(3) {
        let (a, b, c) = (w[0], w[1], w[2]);
        let (ab, bc, ca) = (hlen(a, b), hlen(b, c), hlen(c, a));
        let cross = ((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x)).abs();
        if cross <= 1e-12 * ab * bc {
            continue;
        }
        let circumradius = ab * bc * ca / (2.0 * cross);
        min_circumradius = min_circumradius.min(circumradius);
        if circumradius < tightest * (1.0 - 1e-6) {
            return Err(format!("curvature 1/{circumradius:.3} m at {b:?}, over the turns' 1/{tightest} m"));
        }
    }
    Ok(Rechecked { samples: samples.len(), min_circumradius })
}

/// What the re-checker measured.
#[derive(Clone, Copy, Debug)]
pub struct Rechecked {
    pub samples: usize,
    /// The smallest radius of a circle through three consecutive samples (+inf when straight):
    /// the flown curve's largest curvature is its inverse.
    pub min_circumradius: f64,
}
