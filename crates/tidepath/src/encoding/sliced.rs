//! The sliced encoding of seeds 000 (section 3.1, the planes x = x_i), 001 (eqs. 12-13, the
//! lines Y = j) and 003 (section 3.1, planes parallel to YOZ), generalised so the main axis is
//! the horizontal start-to-goal direction instead of the x axis.
//!
//! Interior waypoint i (1..=n) lies on the vertical plane perpendicular to the main axis at
//! distance s_i = i D / (n + 1) from the start, D the horizontal start-goal distance. Its
//! decision variables are the lateral offset l_i from the start-goal line (positive to the left
//! of travel) and, in 3-D, its absolute height z_i. The papers' x-axis case is the special case
//! where the main axis is x and l_i = y_i - y_start.
//!
//! Bounds are derived from the world: each plane's lateral range is where it crosses the domain
//! rectangle (so every decoded waypoint lies inside the domain) and z spans the domain box
//! intersected with the vehicle's depth band.
//!
//! Posture limits (ijs2023 eq. 14, [`super::posture`]): at most UB sideways and UR vertically
//! between consecutive planes, enforced by `repair` and again when decoding.

use crate::error::{Error, Result};
use crate::geom::{Aabb, Vec2, Vec3};

use super::posture::{Posture, StepChain};
use super::{Encoding, SliceAxis};

#[derive(Clone, Debug)]
pub struct Sliced {
    start: Vec3,
    goal: Vec3,
    /// Unit main axis (horizontal) and its left normal.
    axis: Vec2,
    normal: Vec2,
    /// Plane positions along the main axis (m from the start) and the horizontal start-goal
    /// distance.
    stations: Vec<f64>,
    span: f64,
    three_d: bool,
    lower: Vec<f64>,
    upper: Vec<f64>,
    /// eq. 14's lateral and vertical chains, when limited.
    lateral: Option<StepChain>,
    vertical: Option<StepChain>,
}

impl Sliced {
    /// `waypoints` interior planes; `z_range` is the allowed height band (3-D) or `None` for a
    /// 2-D plane, where z is interpolated between start and goal.
    pub fn new(start: Vec3, goal: Vec3, waypoints: usize, domain: &Aabb, z_range: Option<(f64, f64)>) -> Result<Self> {
        Self::along(start, goal, waypoints, domain, z_range, SliceAxis::Path)
    }

    /// Planes across `axis`: the start-goal direction, or a world axis (planes x = const or
    /// y = const between the start's and the goal's coordinate). The lateral variable is then
    /// the other horizontal coordinate, measured from the start's.
    pub fn along(
        start: Vec3,
        goal: Vec3,
        waypoints: usize,
        domain: &Aabb,
        z_range: Option<(f64, f64)>,
        axis: SliceAxis,
    ) -> Result<Self> {
        if waypoints == 0 {
            return Err(Error::input("encoding.waypoints", "must be at least 1, got 0"));
        }
        let tiny = 1e-9 * domain.size().max_element().max(1.0);
        let span = (goal - start).truncate();
        let (axis, dist) = match axis {
            SliceAxis::Path => {
                let dist = span.length();
                if dist <= tiny {
                    return Err(Error::input(
                        "encoding.kind",
                        "the sliced encoding needs start and goal apart horizontally; use kind = \"free\"",
                    ));
                }
                (span / dist, dist)
            }
            SliceAxis::X | SliceAxis::Y => {
                let k = if axis == SliceAxis::X { 0 } else { 1 };
                let dist = span[k].abs();
                if dist <= tiny {
                    let name = if k == 0 { "x" } else { "y" };
                    return Err(Error::input(
                        "encoding.axis",
                        format!("planes across {name} need start and goal apart in {name}; use axis = \"path\""),
                    ));
                }
                let mut unit = Vec2::ZERO;
                unit[k] = span[k].signum();
                (unit, dist)
            }
        };
        let normal = axis.perp();
        let stations: Vec<f64> = (1..=waypoints).map(|i| dist * i as f64 / (waypoints + 1) as f64).collect();
        let per = if z_range.is_some() { 2 } else { 1 };
        let (mut lower, mut upper) = (Vec::with_capacity(per * waypoints), Vec::with_capacity(per * waypoints));
        for (i, &s) in stations.iter().enumerate() {
            let base = start.truncate() + axis * s;
            let (lo, hi) = lateral_range(base, normal, domain).ok_or_else(|| {
                Error::input("encoding", format!("plane {} of the sliced encoding lies outside the domain", i + 1))
            })?;
            lower.push(lo);
            upper.push(hi);
            if let Some((zlo, zhi)) = z_range {
                lower.push(zlo);
                upper.push(zhi);
            }
        }
        if let Some((zlo, zhi)) = z_range {
            if zlo > zhi {
                return Err(Error::input(
                    "vehicle.depth_min",
                    format!("the depth band and the domain leave no room: z range [{zlo}, {zhi}]"),
                ));
            }
        }
        Ok(Self {
            start,
            goal,
            axis,
            normal,
            stations,
            span: dist,
            three_d: z_range.is_some(),
            lower,
            upper,
            lateral: None,
            vertical: None,
        })
    }

    /// The encoding with ijs2023's posture limits (eq. 14): steps converted to metres with the
    /// plane spacing, chains checked to fit the box.
    pub fn with_posture(mut self, posture: Posture) -> Result<Self> {
        let spacing = self.span / (self.stations.len() + 1) as f64;
        let per = self.waypoint_dim();
        let column = |v: &[f64], j: usize| v.iter().skip(j).step_by(per).copied().collect::<Vec<_>>();
        if let Some(limit) = posture.lateral {
            let (lo, hi) = (column(&self.lower, 0), column(&self.upper, 0));
            self.lateral = Some(StepChain::new(0.0, limit.metres(spacing), &lo, &hi, "lateral_step")?);
        }
        if let Some(limit) = posture.vertical {
            if !self.three_d {
                return Err(Error::input(
                    "encoding.vertical_step",
                    "a 2-D world has no vertical move between planes (heights are interpolated)",
                ));
            }
            let (lo, hi) = (column(&self.lower, 1), column(&self.upper, 1));
            self.vertical = Some(StepChain::new(self.start.z, limit.metres(spacing), &lo, &hi, "vertical_step")?);
        }
        Ok(self)
    }

    /// eq. 14's largest lateral and vertical steps (m), when limited.
    pub fn posture_steps(&self) -> (Option<f64>, Option<f64>) {
        (self.lateral.as_ref().map(StepChain::step), self.vertical.as_ref().map(StepChain::step))
    }

    /// Applies the posture chains to `x` in place (each variable into its predecessor's
    /// window); the box too, since each chain's intervals lie inside it.
    fn apply_posture(&self, x: &mut [f64]) {
        let per = self.waypoint_dim();
        for (j, chain) in [&self.lateral, &self.vertical].into_iter().enumerate() {
            let Some(chain) = chain else { continue };
            let mut prev = chain.start();
            for k in 0..self.stations.len() {
                let v = &mut x[per * k + j];
                *v = chain.clamp(k, prev, *v);
                prev = *v;
            }
        }
    }

    pub fn waypoints(&self) -> usize {
        self.stations.len()
    }
}

/// The interval of l for which base + l * normal stays inside the domain rectangle, shrunk by
/// a hair so decoded points never round outside.
fn lateral_range(base: Vec2, normal: Vec2, domain: &Aabb) -> Option<(f64, f64)> {
    let (mut lo, mut hi) = (f64::NEG_INFINITY, f64::INFINITY);
    for k in 0..2 {
        let (p, n, min, max) = (base[k], normal[k], domain.min[k], domain.max[k]);
        if n.abs() < 1e-15 {
            if p < min || p > max {
                return None;
            }
            continue;
        }
        let (a, b) = ((min - p) / n, (max - p) / n);
        lo = lo.max(a.min(b));
        hi = hi.min(a.max(b));
    }
    let eps = 1e-9 * (domain.size().x + domain.size().y);
    (lo + eps <= hi - eps).then_some((lo + eps, hi - eps))
}

impl Encoding for Sliced {
    fn id(&self) -> &'static str {
        "sliced"
    }

    fn dim(&self) -> usize {
        self.lower.len()
    }

    fn lower(&self) -> &[f64] {
        &self.lower
    }

    fn upper(&self) -> &[f64] {
        &self.upper
    }

    /// The path of `x`, with the posture limits applied on the way (so a vector no repair saw
    /// decodes to the path its repair would give).
    fn decode_into(&self, x: &[f64], out: &mut Vec<Vec3>) {
        out.clear();
        out.push(self.start);
        let per = self.waypoint_dim();
        let holds = |chain: &Option<StepChain>, j: usize| chain.as_ref().is_none_or(|c| c.holds(|k| x[per * k + j]));
        if holds(&self.lateral, 0) && holds(&self.vertical, 1) {
            for k in 0..self.stations.len() {
                out.push(self.waypoint_at(k, &x[per * k..per * k + per]));
            }
            out.push(self.goal);
            return;
        }
        let (mut lat, mut z) =
            (self.lateral.as_ref().map(StepChain::start), self.vertical.as_ref().map(StepChain::start));
        let mut v = [0.0; 2];
        for k in 0..self.stations.len() {
            v[..per].copy_from_slice(&x[per * k..per * k + per]);
            if let (Some(c), Some(p)) = (&self.lateral, lat.as_mut()) {
                v[0] = c.clamp(k, *p, v[0]);
                *p = v[0];
            }
            if let (Some(c), Some(p)) = (&self.vertical, z.as_mut()) {
                v[1] = c.clamp(k, *p, v[1]);
                *p = v[1];
            }
            out.push(self.waypoint_at(k, &v[..per]));
        }
        out.push(self.goal);
    }

    /// Clamps to the box, then applies the posture limits from the start onward.
    fn repair(&self, x: &mut [f64]) {
        for ((v, lo), hi) in x.iter_mut().zip(&self.lower).zip(&self.upper) {
            *v = v.clamp(*lo, *hi);
        }
        self.apply_posture(x);
    }

    fn waypoint_dim(&self) -> usize {
        if self.three_d {
            2
        } else {
            1
        }
    }

    fn waypoint_at(&self, k: usize, v: &[f64]) -> Vec3 {
        let s = self.stations[k];
        let xy = self.start.truncate() + self.axis * s + self.normal * v[0];
        let z = if self.three_d { v[1] } else { self.start.z + (self.goal.z - self.start.z) * s / self.span };
        xy.extend(z)
    }

    /// The lateral offset of `p` from plane k's base point, and its height in 3-D: `p` moved
    /// along the main axis onto the plane.
    fn set_waypoint(&self, x: &mut [f64], k: usize, p: Vec3) {
        let per = self.waypoint_dim();
        x[per * k] = (p.truncate() - self.start.truncate()).dot(self.normal);
        if self.three_d {
            x[per * k + 1] = p.z;
        }
    }

    /// Each plane takes the point where `path` first reaches its station along the main axis
    /// (the path's last point when it never does).
    fn encode(&self, path: &[Vec3]) -> Vec<f64> {
        let origin = self.start.truncate();
        let along = |p: Vec3| (p.truncate() - origin).dot(self.axis);
        let mut x = Vec::with_capacity(self.lower.len());
        for &s in &self.stations {
            let mut hit = path.last().copied().unwrap_or(self.goal);
            for w in path.windows(2) {
                let (u0, u1) = (along(w[0]), along(w[1]));
                if (u0 - s) * (u1 - s) <= 0.0 && u0 != u1 {
                    hit = w[0] + (w[1] - w[0]) * ((s - u0) / (u1 - u0));
                    break;
                }
            }
            x.push((hit.truncate() - origin).dot(self.normal));
            if self.three_d {
                x.push(hit.z);
            }
        }
        for ((v, lo), hi) in x.iter_mut().zip(&self.lower).zip(&self.upper) {
            *v = if v.is_finite() { v.clamp(*lo, *hi) } else { 0.5 * (lo + hi) };
        }
        self.apply_posture(&mut x);
        x
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn domain() -> Aabb {
        Aabb::new(Vec3::new(0.0, 0.0, -100.0), Vec3::new(100.0, 50.0, 0.0))
    }

    #[test]
    fn x_axis_case_matches_the_papers_planes() {
        let (s, g) = (Vec3::new(0.0, 10.0, -50.0), Vec3::new(100.0, 10.0, -20.0));
        let enc = Sliced::new(s, g, 4, &domain(), Some((-90.0, -10.0))).unwrap();
        assert_eq!(enc.dim(), 8);
        // Planes at x = 20, 40, 60, 80; lateral range is y in [0, 50] minus y_start = 10.
        assert!((enc.lower()[0] + 10.0).abs() < 1e-6 && (enc.upper()[0] - 40.0).abs() < 1e-6);
        assert_eq!((enc.lower()[1], enc.upper()[1]), (-90.0, -10.0));
        let path = enc.decode(&[5.0, -30.0, 0.0, -40.0, -5.0, -50.0, 1.0, -60.0]);
        assert_eq!(path.len(), 6);
        assert_eq!(path[0], s);
        assert!((path[1] - Vec3::new(20.0, 15.0, -30.0)).length() < 1e-12);
        assert!((path[3] - Vec3::new(60.0, 5.0, -50.0)).length() < 1e-12);
        assert_eq!(path[5], g);
    }

    #[test]
    fn diagonal_axis_keeps_waypoints_in_the_domain() {
        let (s, g) = (Vec3::new(5.0, 5.0, -50.0), Vec3::new(95.0, 45.0, -50.0));
        let enc = Sliced::new(s, g, 7, &domain(), Some((-100.0, 0.0))).unwrap();
        let d = domain();
        for corner in [enc.lower().to_vec(), enc.upper().to_vec()] {
            for p in enc.decode(&corner) {
                assert!(d.contains(p), "{p:?} left the domain");
            }
        }
        // Zero offsets give the straight line.
        let mid = enc.decode(
            &vec![0.0; enc.dim()]
                .iter()
                .enumerate()
                .map(|(i, _)| if i % 2 == 1 { -50.0 } else { 0.0 })
                .collect::<Vec<_>>(),
        );
        for p in &mid {
            let t = (p.x - 5.0) / 90.0;
            assert!((p.y - (5.0 + 40.0 * t)).abs() < 1e-9);
        }
    }

    #[test]
    fn two_d_variant_interpolates_height() {
        let (s, g) = (Vec3::new(0.0, 25.0, 0.0), Vec3::new(100.0, 25.0, 0.0));
        let enc = Sliced::new(s, g, 3, &domain(), None).unwrap();
        assert_eq!(enc.dim(), 3);
        let p = enc.decode(&[1.0, 2.0, 3.0]);
        assert!((p[2] - Vec3::new(50.0, 27.0, 0.0)).length() < 1e-12);
    }

    /// Planes x = const between the start's and the goal's x, whatever the goal's y: the
    /// lateral variable is y - y_start, the same offset on every plane.
    #[test]
    fn x_axis_planes_sit_at_even_x_whatever_the_goal() {
        let (s, g) = (Vec3::new(0.0, 10.0, -50.0), Vec3::new(100.0, 40.0, -20.0));
        let enc = Sliced::along(s, g, 4, &domain(), Some((-90.0, -10.0)), SliceAxis::X).unwrap();
        for k in 0..4 {
            assert!((enc.lower()[2 * k] + 10.0).abs() < 1e-6 && (enc.upper()[2 * k] - 40.0).abs() < 1e-6);
        }
        let path = enc.decode(&[5.0, -30.0, 0.0, -40.0, -5.0, -50.0, 1.0, -60.0]);
        let xs: Vec<f64> = path.iter().map(|p| p.x).collect();
        for (x, want) in xs.iter().zip([0.0, 20.0, 40.0, 60.0, 80.0, 100.0]) {
            assert!((x - want).abs() < 1e-9, "{xs:?}");
        }
        assert!((path[1] - Vec3::new(20.0, 15.0, -30.0)).length() < 1e-12);
        assert_eq!(enc.encode(&path), vec![5.0, -30.0, 0.0, -40.0, -5.0, -50.0, 1.0, -60.0]);
        // Travel towards -y along y planes.
        let enc =
            Sliced::along(Vec3::new(30.0, 45.0, 0.0), Vec3::new(80.0, 5.0, 0.0), 3, &domain(), None, SliceAxis::Y)
                .unwrap();
        let p = enc.decode(&[0.0, 0.0, 0.0]);
        assert!((p[1] - Vec3::new(30.0, 35.0, 0.0)).length() < 1e-9, "{p:?}");
        let err = Sliced::along(s, Vec3::new(0.0, 40.0, -20.0), 3, &domain(), None, SliceAxis::X).unwrap_err();
        assert!(err.to_string().starts_with("encoding.axis"), "{err}");
    }

    #[test]
    fn rejects_vertical_travel() {
        let s = Vec3::new(50.0, 25.0, -90.0);
        let err = Sliced::new(s, Vec3::new(50.0, 25.0, -10.0), 3, &domain(), Some((-100.0, 0.0))).unwrap_err();
        assert!(err.to_string().contains("encoding.kind"));
    }
}
