//! Ocean currents behind one interface: velocity (m/s, ENU) at a point and time.
//!
//! `Current::velocity` sits in the innermost loop of every cost evaluation (tens of calls per
//! path, about 5 microseconds per path), so no variant allocates and each avoids work it can
//! prove is wasted: vortices skip `exp` where it cannot change the result, the grid locates
//! the cell once for all four interpolations.

use super::grid::RegularGrid2;
use crate::error::{Error, Result};
use crate::geom::{Aabb, Vec2, Vec3};
use std::f64::consts::{FRAC_PI_2, TAU};

/// One Lamb-Oseen vortex (seed 001 eqs. 3-5, ALGORITHMS.md section 0.2).
#[derive(Clone, Debug, PartialEq)]
pub struct LambOseen {
    pub x: f64,
    pub y: f64,
    /// eta: circulation strength (m^2/s); positive is counter-clockwise.
    pub strength: f64,
    /// zeta: core radius (m).
    pub core_radius: f64,
}

/// Beyond this r^2/zeta^2, exp(-r^2/zeta^2) < 2e-22 and 1 - exp(..) rounds to exactly 1.
const VORTEX_FAR_FIELD: f64 = 50.0;

/// Radius of peak speed of a Lamb-Oseen vortex in core radii (root of 2 r^2 = e^{r^2} - 1);
/// used so that speed hints do not miss a small core between sample points.
const VORTEX_PEAK_RADIUS: f64 = 1.120_906_423_2;

impl LambOseen {
    /// Horizontal velocity of this vortex alone at (x, y).
    ///
    /// The paper's "(R - R0)^2" is the squared distance. The centre returns zero because the
    /// limit there is zero and the formula would divide 0 by 0.
    #[inline]
    pub fn velocity(&self, x: f64, y: f64) -> Vec2 {
        let (dx, dy) = (x - self.x, y - self.y);
        let r2 = dx * dx + dy * dy;
        if r2 < 1e-12 {
            return Vec2::ZERO;
        }
        let q = r2 / (self.core_radius * self.core_radius);
        // -expm1(-q) rather than 1 - exp(-q): near the core the subtraction would cancel.
        let shape = if q > VORTEX_FAR_FIELD { 1.0 } else { -(-q).exp_m1() };
        let k = self.strength * shape / (TAU * r2);
        Vec2::new(-k * dy, k * dx)
    }
}

/// How the meandering jet's speed is turned into metres per second.
///
/// The jet is non-dimensional, so its own speed says nothing about a real ocean; seed 003 only
/// borrows its direction and states the magnitude relative to the AUV's speed.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Magnitude {
    /// Every point where the jet flows (jet-unit speed > 1e-12) gets exactly this speed (m/s):
    /// seed 003's literal "|v_c| = ratio x |v_rc|" (ALGORITHMS.md 4.2).
    Fixed(f64),
    /// The fastest point of the domain at t = 0 gets this speed (m/s) and the rest keep their
    /// relative strength: ALGORITHMS.md 4.2's option "scale so that the maximum equals the
    /// ratio". The maximum is sampled once on a 200 x 120 grid at t = 0, so between the sample
    /// points (by about 0.1 %) and as the jet breathes at later times the speed can exceed this.
    Scaled(f64),
}

/// The jet's constants and how its non-dimensional units map onto the world.
///
/// Plain data with public fields so scenarios can override any value; `MeanderingJet::new`
/// checks it once and precomputes what `velocity` needs.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct JetConfig {
    /// Wavenumber of the meander (paper: 1).
    pub kappa: f64,
    /// Phase speed of the meander (paper: 0.12).
    pub eps: f64,
    /// Width modulation of the jet across the meander (paper: 0.84).
    pub eta: f64,
    /// Mean meander amplitude. Paper prints 0.12; Chosen 1.2 (see `MeanderingJet`).
    pub alpha0: f64,
    /// Amplitude of the meander's breathing (paper: 0.3).
    pub beta: f64,
    /// Phase of the breathing (paper: pi/2).
    pub gamma: f64,
    /// Frequency of the breathing. Not given in the paper; Chosen 0.4 (the Bower-type value).
    pub omega0: f64,
    /// World rectangle (m) the jet is stretched over; positions outside are clamped onto it.
    pub x_min: f64,
    pub x_max: f64,
    pub y_min: f64,
    pub y_max: f64,
    /// Jet-unit interval that [x_min, x_max] maps onto. Chosen [0, 10]: about 1.6 meanders.
    pub jet_x: [f64; 2],
    /// Jet-unit interval that [y_min, y_max] maps onto. Chosen [-3, 3]: the jet core and both
    /// recirculation flanks.
    pub jet_y: [f64; 2],
    /// Seconds of world time per jet time unit. Chosen 2000 (t_jet = t / 2000): seed 003's
    /// missions last about 26 000 s, so the jet changes visibly but not wildly along a path.
    pub seconds_per_unit: f64,
    pub magnitude: Magnitude,
}

impl JetConfig {
    /// The Chosen constants of ALGORITHMS.md 0.3 stretched over the given world rectangle.
    pub fn new(x_min: f64, x_max: f64, y_min: f64, y_max: f64, magnitude: Magnitude) -> Self {
        Self {
            kappa: 1.0,
            eps: 0.12,
            eta: 0.84,
            alpha0: 1.2,
            beta: 0.3,
            gamma: FRAC_PI_2,
            omega0: 0.4,
            x_min,
            x_max,
            y_min,
            y_max,
            jet_x: [0.0, 10.0],
            jet_y: [-3.0, 3.0],
            seconds_per_unit: 2000.0,
            magnitude,
        }
    }

    /// As `new`, over the horizontal extent of a domain box (usually `World::bounds`).
    pub fn over(bounds: &Aabb, magnitude: Magnitude) -> Self {
        Self::new(bounds.min.x, bounds.max.x, bounds.min.y, bounds.max.y, magnitude)
    }
}

/// The time-varying meandering jet of seed 003 (Guo, Chen & Pang, IEEE Access; eqs. 27-28,
/// ALGORITHMS.md section 0.3), mapped from jet units onto a rectangle of the world.
///
/// Stream function (eq. 27) xi = 1 - tanh((y - a cos(kappa (x - eps t))) /
/// sqrt(1 + (eta a sin(kappa (x - eps t)))^2)), with a(t) = alpha0 - beta cos(omega0 t + gamma)
/// (eq. 28), and velocity (-d xi/dy, d xi/dx). Derivatives are analytic: they are exact, cost
/// one `cosh`, and keep the field exactly divergence-free, which finite differences would not.
///
/// Values: kappa = 1, eps = 0.12, eta = 0.84, beta = 0.3, gamma = pi/2 as printed. The paper's
/// alpha0 = 0.12 is read as a slip for 1.2 (the usual Bower-type jet has B0 = 1.2, and 0.12
/// would make the meander almost straight); omega0 is not given and is Chosen 0.4. The world
/// rectangle maps onto x_j in [0, 10], y_j in [-3, 3]; t_jet = t / 2000 s.
///
/// The x and y map scales differ, so a jet-unit velocity is converted to the world by the chain
/// rule (each component times metres per jet unit on its axis) before its magnitude is set;
/// converting the direction naively would rotate the flow off its streamlines.
#[derive(Clone, Debug, PartialEq)]
pub struct MeanderingJet {
    config: JetConfig,
    /// Jet units per metre on each axis.
    jx_per_m: f64,
    jy_per_m: f64,
    /// Metres per jet unit on each axis (the chain-rule factors).
    m_per_jx: f64,
    m_per_jy: f64,
    inv_seconds_per_unit: f64,
    /// For `Scaled`: metres-per-unit factors times the scale that maps the sampled maximum
    /// onto the requested speed, so `velocity` is two multiplications.
    gain_x: f64,
    gain_y: f64,
}

impl MeanderingJet {
    /// Checks `config` (`field` names it in errors) and, for `Magnitude::Scaled`, samples the
    /// jet's maximum speed over the rectangle at t = 0 on a 200 x 120 grid.
    pub fn new(config: JetConfig, field: &str) -> Result<Self> {
        let c = &config;
        let constants = [
            ("kappa", c.kappa),
            ("eps", c.eps),
            ("eta", c.eta),
            ("alpha0", c.alpha0),
            ("beta", c.beta),
            ("gamma", c.gamma),
            ("omega0", c.omega0),
        ];
        for (name, value) in constants {
            if !value.is_finite() {
                return Err(Error::input(format!("{field}.{name}"), format!("must be finite, got {value}")));
            }
        }
        let intervals =
            [("x_range", [c.x_min, c.x_max]), ("y_range", [c.y_min, c.y_max]), ("jet_x", c.jet_x), ("jet_y", c.jet_y)];
        for (name, [lo, hi]) in intervals {
            if !(lo.is_finite() && hi.is_finite() && hi > lo) {
                return Err(Error::input(
                    format!("{field}.{name}"),
                    format!("must be finite and increasing, got [{lo}, {hi}]"),
                ));
            }
        }
        if !(c.seconds_per_unit > 0.0 && c.seconds_per_unit.is_finite()) {
            return Err(Error::input(
                format!("{field}.seconds_per_unit"),
                format!("must be positive and finite, got {}", c.seconds_per_unit),
            ));
        }
        let speed = match c.magnitude {
            Magnitude::Fixed(s) | Magnitude::Scaled(s) => s,
        };
        if !(speed >= 0.0 && speed.is_finite()) {
            return Err(Error::input(
                format!("{field}.magnitude"),
                format!("speed must be non-negative and finite, got {speed}"),
            ));
        }

        let m_per_jx = (c.x_max - c.x_min) / (c.jet_x[1] - c.jet_x[0]);
        let m_per_jy = (c.y_max - c.y_min) / (c.jet_y[1] - c.jet_y[0]);
        let mut jet = Self {
            config,
            jx_per_m: 1.0 / m_per_jx,
            jy_per_m: 1.0 / m_per_jy,
            m_per_jx,
            m_per_jy,
            inv_seconds_per_unit: 1.0 / c.seconds_per_unit,
            gain_x: 0.0,
            gain_y: 0.0,
        };
        if let Magnitude::Scaled(max_speed) = config.magnitude {
            let (nx, ny) = (200, 120);
            let [x0, x1] = config.jet_x;
            let [y0, y1] = config.jet_y;
            let mut peak: f64 = 0.0;
            for j in 0..ny {
                let yj = y0 + (y1 - y0) * j as f64 / (ny - 1) as f64;
                for i in 0..nx {
                    let xj = x0 + (x1 - x0) * i as f64 / (nx - 1) as f64;
                    let (u, v) = jet.jet_velocity(xj, yj, 0.0);
                    peak = peak.max((u * m_per_jx).hypot(v * m_per_jy));
                }
            }
            let scale = if peak > 1e-12 { max_speed / peak } else { 0.0 };
            jet.gain_x = m_per_jx * scale;
            jet.gain_y = m_per_jy * scale;
        }
        Ok(jet)
    }

    pub fn config(&self) -> &JetConfig {
        &self.config
    }

    /// World position and time to jet units, clamping the position onto the rectangle so the
    /// field outside is the nearest edge's rather than an extrapolated meander.
    #[inline]
    pub fn to_jet(&self, x: f64, y: f64, t: f64) -> (f64, f64, f64) {
        let c = &self.config;
        let xj = c.jet_x[0] + (x.clamp(c.x_min, c.x_max) - c.x_min) * self.jx_per_m;
        let yj = c.jet_y[0] + (y.clamp(c.y_min, c.y_max) - c.y_min) * self.jy_per_m;
        (xj, yj, t * self.inv_seconds_per_unit)
    }

    /// a(t) of eq. 28 (jet time).
    #[inline]
    fn amplitude(&self, tj: f64) -> f64 {
        let c = &self.config;
        c.alpha0 - c.beta * (c.omega0 * tj + c.gamma).cos()
    }

    /// The stream function xi of eq. 27 in jet units; exposed for tests and streamline plots.
    pub fn stream_function(&self, xj: f64, yj: f64, tj: f64) -> f64 {
        let c = &self.config;
        let a = self.amplitude(tj);
        let (sin_th, cos_th) = (c.kappa * (xj - c.eps * tj)).sin_cos();
        let ea = c.eta * a * sin_th;
        1.0 - ((yj - a * cos_th) / (1.0 + ea * ea).sqrt()).tanh()
    }

    /// (-d xi/dy, d xi/dx) in jet units, before any mapping or magnitude option.
    ///
    /// With s = N / D, N = y - a cos(theta), D = sqrt(1 + (eta a sin(theta))^2),
    /// theta = kappa (x - eps t): d xi/dy = -sech^2(s) / D and
    /// d xi/dx = -sech^2(s) (dN/dx - s dD/dx) / D, dN/dx = a kappa sin(theta),
    /// dD/dx = (eta a)^2 kappa sin(theta) cos(theta) / D.
    #[inline]
    pub fn jet_velocity(&self, xj: f64, yj: f64, tj: f64) -> (f64, f64) {
        let c = &self.config;
        let a = self.amplitude(tj);
        let (sin_th, cos_th) = (c.kappa * (xj - c.eps * tj)).sin_cos();
        let ea2 = (c.eta * a) * (c.eta * a);
        let inv_d = 1.0 / (1.0 + ea2 * sin_th * sin_th).sqrt();
        let s = (yj - a * cos_th) * inv_d;
        // sech^2(s) = 4 e / (1 + e)^2 with e = exp(-2|s|): one exp, and it underflows to the
        // correct 0 far from the jet instead of overflowing.
        let e = (-2.0 * s.abs()).exp();
        let sech2 = 4.0 * e / ((1.0 + e) * (1.0 + e));
        let dn_dx = a * c.kappa * sin_th;
        let dd_dx = ea2 * c.kappa * sin_th * cos_th * inv_d;
        let ds_dx = (dn_dx - s * dd_dx) * inv_d;
        (sech2 * inv_d, -sech2 * ds_dx)
    }

    /// World velocity (m/s) at `p` and time `t` (s); horizontal only, as in seed 003.
    #[inline]
    pub fn velocity(&self, p: Vec3, t: f64) -> Vec3 {
        let (xj, yj, tj) = self.to_jet(p.x, p.y, t);
        let (u, v) = self.jet_velocity(xj, yj, tj);
        match self.config.magnitude {
            Magnitude::Fixed(speed) => {
                if u * u + v * v <= 1e-24 {
                    return Vec3::ZERO;
                }
                let (wx, wy) = (u * self.m_per_jx, v * self.m_per_jy);
                let k = speed / (wx * wx + wy * wy).sqrt();
                Vec3::new(wx * k, wy * k, 0.0)
            }
            Magnitude::Scaled(_) => Vec3::new(u * self.gain_x, v * self.gain_y, 0.0),
        }
    }
}

/// u, v components on a regular grid at a list of times; bilinear in space, linear in time.
///
/// Build it with `CurrentGrid::new`: `velocity` relies on its checks (at least one layer,
/// every layer full) and does not repeat them.
#[derive(Clone, Debug, PartialEq)]
pub struct CurrentGrid {
    pub grid: RegularGrid2,
    /// Strictly increasing times (s) of the layers.
    pub times: Vec<f64>,
    /// One row-major layer per time.
    pub u: Vec<Vec<f64>>,
    pub v: Vec<Vec<f64>>,
}

impl CurrentGrid {
    /// Checks the layers; `field` names the scenario field for error messages, which give the
    /// offending layer, node and value so a broken data file can be found.
    pub fn new(grid: RegularGrid2, times: Vec<f64>, u: Vec<Vec<f64>>, v: Vec<Vec<f64>>, field: &str) -> Result<Self> {
        if times.is_empty() {
            return Err(Error::input(format!("{field}.times"), "needs at least one layer, got none"));
        }
        for (k, &t) in times.iter().enumerate() {
            if !t.is_finite() {
                return Err(Error::input(format!("{field}.times"), format!("times[{k}] is {t}; must be finite")));
            }
            if k > 0 && t <= times[k - 1] {
                return Err(Error::input(
                    format!("{field}.times"),
                    format!(
                        "must be strictly increasing, but times[{k}] = {t} follows times[{}] = {}",
                        k - 1,
                        times[k - 1]
                    ),
                ));
            }
        }
        for (name, layers) in [("u", &u), ("v", &v)] {
            let name = format!("{field}.{name}");
            if layers.len() != times.len() {
                return Err(Error::input(name, format!("has {} layers but times has {}", layers.len(), times.len())));
            }
            for (l, layer) in layers.iter().enumerate() {
                if layer.len() != grid.len() {
                    return Err(Error::input(
                        name,
                        format!(
                            "layer {l} has {} values; the grid has {} x {} = {} nodes",
                            layer.len(),
                            grid.nx,
                            grid.ny,
                            grid.len()
                        ),
                    ));
                }
                if let Some(k) = layer.iter().position(|x| !x.is_finite()) {
                    return Err(Error::input(
                        name,
                        format!(
                            "layer {l}, value {k} (node i = {}, j = {}) is {}; must be finite",
                            k % grid.nx,
                            k / grid.nx,
                            layer[k]
                        ),
                    ));
                }
            }
        }
        Ok(Self { grid, times, u, v })
    }

    /// The two layers around `t` and the weight of the second; outside the time range the
    /// nearest layer holds, since extrapolating a forecast in time is worse than freezing it.
    #[inline]
    fn bracket(&self, t: f64) -> (usize, usize, f64) {
        let n = self.times.len();
        // NaN goes to the first layer rather than to an out-of-range index.
        if n == 1 || t.is_nan() || t <= self.times[0] {
            return (0, 0, 0.0);
        }
        if t >= self.times[n - 1] {
            return (n - 1, n - 1, 0.0);
        }
        let k = self.times.partition_point(|&s| s <= t);
        (k - 1, k, (t - self.times[k - 1]) / (self.times[k] - self.times[k - 1]))
    }

    /// Velocity at (x, y) and time t (s); w = 0. Outside the grid the edge values hold.
    #[inline]
    pub fn velocity(&self, x: f64, y: f64, t: f64) -> Vec3 {
        let g = &self.grid;
        let (i, j, fu, fv) = g.locate(x, y);
        let k = j * g.nx + i;
        let (l0, l1, w) = self.bracket(t);
        let mut u = lerp2(&self.u[l0], k, g.nx, fu, fv);
        let mut v = lerp2(&self.v[l0], k, g.nx, fu, fv);
        if w > 0.0 {
            u += (lerp2(&self.u[l1], k, g.nx, fu, fv) - u) * w;
            v += (lerp2(&self.v[l1], k, g.nx, fu, fv) - v) * w;
        }
        Vec3::new(u, v, 0.0)
    }

    /// Largest horizontal speed at time t over the nodes of the cells that touch `bounds`.
    /// Exact: an interpolated vector is a convex combination of node vectors, so its length
    /// never exceeds the longest of them.
    fn max_speed(&self, bounds: &Aabb, t: f64) -> f64 {
        let g = &self.grid;
        let (i0, j0, _, _) = g.locate(bounds.min.x, bounds.min.y);
        let (i1, j1, _, _) = g.locate(bounds.max.x, bounds.max.y);
        let (l0, l1, w) = self.bracket(t);
        let mut peak: f64 = 0.0;
        for j in j0..=(j1 + 1) {
            for i in i0..=(i1 + 1) {
                let k = j * g.nx + i;
                let u = self.u[l0][k] + (self.u[l1][k] - self.u[l0][k]) * w;
                let v = self.v[l0][k] + (self.v[l1][k] - self.v[l0][k]) * w;
                peak = peak.max(u.hypot(v));
            }
        }
        peak
    }
}

/// `RegularGrid2::bilinear` for an already located cell, in the same operation order so the
/// results are bit-identical; locating once serves all four interpolations.
#[inline]
fn lerp2(values: &[f64], k: usize, nx: usize, fu: f64, fv: f64) -> f64 {
    let (a, b) = (values[k], values[k + 1]);
    let (c, d) = (values[k + nx], values[k + nx + 1]);
    let lo = a + (b - a) * fu;
    let hi = c + (d - c) * fu;
    lo + (hi - lo) * fv
}

#[derive(Clone, Debug, PartialEq)]
pub enum Current {
    None,
    Uniform(Vec3),
    Vortices(Vec<LambOseen>),
    Jet(MeanderingJet),
    Grid(CurrentGrid),
}

impl Current {
    /// Current velocity at `p` and time `t` (s).
    #[inline]
    pub fn velocity(&self, p: Vec3, t: f64) -> Vec3 {
        match self {
            Current::None => Vec3::ZERO,
            Current::Uniform(v) => *v,
            Current::Vortices(vortices) => {
                let mut sum = Vec2::ZERO;
                for vortex in vortices {
                    sum += vortex.velocity(p.x, p.y);
                }
                sum.extend(0.0)
            }
            Current::Jet(jet) => jet.velocity(p, t),
            Current::Grid(grid) => grid.velocity(p.x, p.y, t),
        }
    }

    /// An estimate of the largest horizontal current speed (m/s) over the horizontal extent of
    /// `bounds` at time `t`, for scaling arrows and speed bounds in plots.
    ///
    /// Exact for `None`, `Uniform` and `Grid`. Vortices and the jet are sampled on a 64 x 64
    /// grid; for vortices the ring of peak speed around each centre inside `bounds` is sampled
    /// too, since a core smaller than the grid spacing would otherwise be missed.
    pub fn max_speed_hint(&self, bounds: &Aabb, t: f64) -> f64 {
        match self {
            Current::None => 0.0,
            Current::Uniform(v) => v.x.hypot(v.y),
            Current::Grid(grid) => grid.max_speed(bounds, t),
            Current::Jet(_) => sample_max_speed(self, bounds, t),
            Current::Vortices(vortices) => {
                let mut peak = sample_max_speed(self, bounds, t);
                for vortex in vortices {
                    let r = VORTEX_PEAK_RADIUS * vortex.core_radius.abs();
                    for k in 0..16 {
                        let (s, c) = (TAU * k as f64 / 16.0).sin_cos();
                        let p = Vec3::new(vortex.x + r * c, vortex.y + r * s, bounds.min.z);
                        if p.x >= bounds.min.x && p.x <= bounds.max.x && p.y >= bounds.min.y && p.y <= bounds.max.y {
                            peak = peak.max(self.velocity(p, t).truncate().length());
                        }
                    }
                }
                peak
            }
        }
    }
}

/// Largest horizontal speed on a 64 x 64 grid of points spanning `bounds` (edges included).
fn sample_max_speed(current: &Current, bounds: &Aabb, t: f64) -> f64 {
    const N: usize = 64;
    let mut peak: f64 = 0.0;
    for j in 0..N {
        let y = bounds.min.y + (bounds.max.y - bounds.min.y) * j as f64 / (N - 1) as f64;
        for i in 0..N {
            let x = bounds.min.x + (bounds.max.x - bounds.min.x) * i as f64 / (N - 1) as f64;
            let v = current.velocity(Vec3::new(x, y, bounds.min.z), t);
            peak = peak.max(v.truncate().length());
        }
    }
    peak
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::f64::consts::PI;

    fn close(a: f64, b: f64, tol: f64) -> bool {
        (a - b).abs() <= tol
    }

    // ---- Lamb-Oseen -------------------------------------------------------------------------

    fn vortex() -> LambOseen {
        LambOseen { x: 3.0, y: 4.0, strength: 2.0, core_radius: 1.2 }
    }

    #[test]
    fn lamb_oseen_speed_at_core_radius() {
        let w = vortex();
        let expected = 2.0 * (1.0 - (-1.0f64).exp()) / (2.0 * PI * 1.2);
        let current = Current::Vortices(vec![w.clone()]);
        // Several directions around the centre: east, north-east-ish, south-west.
        for (dx, dy) in [(1.0, 0.0), (0.6, 0.8), (-0.28, -0.96)] {
            let r = Vec3::new(dx * 1.2, dy * 1.2, 0.0);
            let v = current.velocity(Vec3::new(3.0, 4.0, -7.0) + r, 0.0);
            assert!(close(v.length(), expected, 1e-12), "{v}");
            assert!(close(v.dot(r), 0.0, 1e-12), "not perpendicular: {v}");
            // Counter-clockwise for positive strength: z of (R - R0) x V is positive.
            assert!(r.cross(v).z > 0.0);
            assert_eq!(v.z, 0.0);
        }
        // East of the centre the flow goes due north.
        let v = current.velocity(Vec3::new(4.2, 4.0, 0.0), 0.0);
        assert!(close(v.x, 0.0, 1e-15) && close(v.y, expected, 1e-12));
    }

    #[test]
    fn lamb_oseen_negative_strength_turns_clockwise() {
        let w = LambOseen { strength: -2.0, ..vortex() };
        let v = w.velocity(4.2, 4.0);
        assert!(v.y < 0.0 && close(v.x, 0.0, 1e-15));
    }

    #[test]
    fn lamb_oseen_is_zero_at_centre() {
        let current = Current::Vortices(vec![vortex()]);
        assert_eq!(current.velocity(Vec3::new(3.0, 4.0, 0.0), 0.0), Vec3::ZERO);
        assert_eq!(current.velocity(Vec3::new(3.0 + 1e-7, 4.0, 0.0), 0.0), Vec3::ZERO);
    }

    #[test]
    fn lamb_oseen_far_field_shortcut_is_seamless() {
        // Just inside and just outside r^2/zeta^2 = 50 the speed is eta / (2 pi r) to 1e-15.
        let w = vortex();
        for q in [49.999_999, 50.000_001] {
            let r = 1.2 * f64::sqrt(q);
            let v = w.velocity(3.0 + r, 4.0);
            assert!(close(v.y, 2.0 / (TAU * r), 1e-15), "q = {q}: {}", v.y);
        }
    }

    #[test]
    fn vortices_superpose() {
        let a = vortex();
        let b = LambOseen { x: -1.0, y: 2.5, strength: -0.7, core_radius: 0.5 };
        let both = Current::Vortices(vec![a.clone(), b.clone()]);
        for p in [Vec3::new(0.0, 0.0, 0.0), Vec3::new(2.0, 3.0, -1.0), Vec3::new(-1.3, 2.9, 0.0)] {
            let sum = a.velocity(p.x, p.y) + b.velocity(p.x, p.y);
            let v = both.velocity(p, 5.0);
            assert!(close(v.x, sum.x, 1e-15) && close(v.y, sum.y, 1e-15) && v.z == 0.0);
        }
        // At a's centre only b contributes.
        let v = both.velocity(Vec3::new(3.0, 4.0, 0.0), 0.0);
        assert_eq!(v.truncate(), b.velocity(3.0, 4.0));
    }

    #[test]
    fn vortex_speed_hint_finds_peak_ring() {
        // Core much smaller than the 64 x 64 spacing: the ring samples must catch the peak.
        let w = LambOseen { x: 10.3, y: 20.7, strength: 2.0, core_radius: 0.05 };
        let current = Current::Vortices(vec![w]);
        let bounds = Aabb::new(Vec3::ZERO, Vec3::new(100.0, 100.0, 0.0));
        // Peak of (1 - e^{-q}) / sqrt(q) at q = VORTEX_PEAK_RADIUS^2.
        let q = VORTEX_PEAK_RADIUS * VORTEX_PEAK_RADIUS;
        let exact = 2.0 / (TAU * 0.05) * (1.0 - (-q).exp()) / q.sqrt();
        let hint = current.max_speed_hint(&bounds, 0.0);
        assert!(close(hint, exact, 1e-9 * exact), "{hint} vs {exact}");
    }

    // ---- None and Uniform -------------------------------------------------------------------

    #[test]
    fn none_and_uniform() {
        let p = Vec3::new(1.0, 2.0, 3.0);
        let b = Aabb::new(Vec3::ZERO, Vec3::ONE);
        assert_eq!(Current::None.velocity(p, 9.0), Vec3::ZERO);
        assert_eq!(Current::None.max_speed_hint(&b, 0.0), 0.0);
        let u = Current::Uniform(Vec3::new(0.3, -0.4, 0.1));
        assert_eq!(u.velocity(p, 9.0), Vec3::new(0.3, -0.4, 0.1));
        assert!(close(u.max_speed_hint(&b, 0.0), 0.5, 1e-15));
    }

    // ---- Meandering jet ---------------------------------------------------------------------

    fn jet(magnitude: Magnitude) -> MeanderingJet {
        // 10 km x 3 km: 1000 m per jet unit in x, 500 m per jet unit in y.
        MeanderingJet::new(JetConfig::new(0.0, 10_000.0, -1_500.0, 1_500.0, magnitude), "current.jet").unwrap()
    }

    const JET_POINTS: [(f64, f64, f64); 5] =
        [(0.3, -1.1, 0.0), (2.0, 0.4, 1.7), (4.9, 1.3, 12.5), (7.7, -2.4, 3.3), (9.1, 0.05, 40.0)];

    #[test]
    fn jet_matches_hand_computed_values() {
        let j = jet(Magnitude::Fixed(1.0));
        // t = 0: a = 1.2 - 0.3 cos(pi/2) = 1.2.
        // x = pi: sin = 0, cos = -1, D = 1; at y = -1.2, s = 0, so (u, v) = (1, 0).
        let (u, v) = j.jet_velocity(PI, -1.2, 0.0);
        assert!(close(u, 1.0, 1e-12) && close(v, 0.0, 1e-12), "{u} {v}");
        // x = pi/2: sin = 1, cos = 0, D = sqrt(1 + (0.84 * 1.2)^2); at y = 0, s = 0:
        // u = 1/D, v = -a kappa / D = -1.2 / D.
        let d = (1.0 + (0.84f64 * 1.2).powi(2)).sqrt();
        let (u, v) = j.jet_velocity(FRAC_PI_2, 0.0, 0.0);
        assert!(close(u, 1.0 / d, 1e-12) && close(v, -1.2 / d, 1e-12), "{u} {v}");
        // World: x = 1000 pi/2 m, y = -1500 + 500 * 3 = 0 m; the chain rule makes the world
        // direction (1000, -600) / |.|, not (1, -1.2) / |.|.
        let w = j.velocity(Vec3::new(1000.0 * FRAC_PI_2, 0.0, -50.0), 0.0);
        let n = 1000.0f64.hypot(600.0);
        assert!(close(w.x, 1000.0 / n, 1e-12) && close(w.y, -600.0 / n, 1e-12) && w.z == 0.0, "{w}");
    }

    #[test]
    fn jet_velocity_matches_stream_function_differences() {
        let j = jet(Magnitude::Fixed(1.0));
        let h = 1e-6;
        for (x, y, t) in JET_POINTS {
            let (u, v) = j.jet_velocity(x, y, t);
            let dxi_dy = (j.stream_function(x, y + h, t) - j.stream_function(x, y - h, t)) / (2.0 * h);
            let dxi_dx = (j.stream_function(x + h, y, t) - j.stream_function(x - h, y, t)) / (2.0 * h);
            assert!(close(u, -dxi_dy, 1e-8), "u at {x} {y} {t}: {u} vs {}", -dxi_dy);
            assert!(close(v, dxi_dx, 1e-8), "v at {x} {y} {t}: {v} vs {dxi_dx}");
        }
    }

    #[test]
    fn jet_is_divergence_free() {
        let j = jet(Magnitude::Fixed(1.0));
        let h = 1e-4;
        for (x, y, t) in JET_POINTS {
            let du_dx = (j.jet_velocity(x + h, y, t).0 - j.jet_velocity(x - h, y, t).0) / (2.0 * h);
            let dv_dy = (j.jet_velocity(x, y + h, t).1 - j.jet_velocity(x, y - h, t).1) / (2.0 * h);
            assert!(close(du_dx + dv_dy, 0.0, 1e-6), "div at {x} {y} {t}: {}", du_dx + dv_dy);
        }
    }

    #[test]
    fn jet_fixed_magnitude_has_that_speed_everywhere() {
        let j = jet(Magnitude::Fixed(0.257));
        for (x, y, t) in JET_POINTS {
            // Jet units to metres, and jet time to seconds.
            let p = Vec3::new(x * 1000.0, -1500.0 + (y + 3.0) * 500.0, 0.0);
            let v = j.velocity(p, t * 2000.0);
            assert!(close(v.length(), 0.257, 1e-12), "{v}");
        }
        // Outside the rectangle the position clamps onto its edge.
        let inside = j.velocity(Vec3::new(10_000.0, 1_500.0, 0.0), 10.0);
        assert_eq!(j.velocity(Vec3::new(25_000.0, 9_000.0, 0.0), 10.0), inside);
    }

    #[test]
    fn jet_scaled_magnitude_peaks_at_requested_speed() {
        let j = jet(Magnitude::Scaled(0.8));
        // The same 200 x 120 grid, in world units, at t = 0.
        let mut peak: f64 = 0.0;
        for jj in 0..120 {
            for ii in 0..200 {
                let p = Vec3::new(10_000.0 * ii as f64 / 199.0, -1500.0 + 3000.0 * jj as f64 / 119.0, 0.0);
                peak = peak.max(j.velocity(p, 0.0).length());
            }
        }
        assert!(close(peak, 0.8, 1e-9), "{peak}");
        // The hint samples other points (some between the 200 x 120 nodes, a little faster),
        // so it only agrees to within sampling error.
        let bounds = Aabb::new(Vec3::new(0.0, -1500.0, -100.0), Vec3::new(10_000.0, 1500.0, 0.0));
        let hint = Current::Jet(j).max_speed_hint(&bounds, 0.0);
        assert!(close(hint, 0.8, 0.01), "{hint}");
    }

    #[test]
    fn jet_time_mapping_uses_seconds_per_unit() {
        let j = jet(Magnitude::Scaled(1.0));
        let p = Vec3::new(3_000.0, 200.0, 0.0);
        let (xj, yj, tj) = j.to_jet(p.x, p.y, 5_000.0);
        assert!(close(xj, 3.0, 1e-12) && close(yj, 0.4, 1e-12) && close(tj, 2.5, 1e-15));
        let (u, v) = j.jet_velocity(xj, yj, tj);
        let w = j.velocity(p, 5_000.0);
        assert!(close(w.x / w.y, (u * 1000.0) / (v * 500.0), 1e-9));
    }

    #[test]
    fn jet_rejects_bad_config() {
        let ok = JetConfig::new(0.0, 1.0, 0.0, 1.0, Magnitude::Fixed(1.0));
        let bad = [
            JetConfig { x_max: 0.0, ..ok },
            JetConfig { jet_y: [3.0, -3.0], ..ok },
            JetConfig { alpha0: f64::NAN, ..ok },
            JetConfig { seconds_per_unit: 0.0, ..ok },
            JetConfig { magnitude: Magnitude::Scaled(-1.0), ..ok },
        ];
        for cfg in bad {
            assert!(MeanderingJet::new(cfg, "j").is_err(), "{cfg:?}");
        }
        let e = MeanderingJet::new(JetConfig { omega0: f64::INFINITY, ..ok }, "current.jet").unwrap_err();
        assert!(e.to_string().starts_with("current.jet.omega0"), "{e}");
    }

    // ---- Grid -------------------------------------------------------------------------------

    fn grid() -> RegularGrid2 {
        // Nodes x = 10, 12, 14; y = 20, 24.
        RegularGrid2::new(10.0, 20.0, 2.0, 4.0, 3, 2, "g").unwrap()
    }

    fn grid_current() -> CurrentGrid {
        let u0 = vec![1.0, 3.0, 5.0, 2.0, 6.0, 4.0];
        let v0 = vec![0.0, -1.0, -2.0, 1.0, 2.0, 3.0];
        let u1 = u0.iter().map(|x| 3.0 * x).collect();
        let v1 = v0.iter().map(|x| x - 1.0).collect();
        CurrentGrid::new(grid(), vec![100.0, 200.0], vec![u0, u1], vec![v0, v1], "current.grid").unwrap()
    }

    #[test]
    fn grid_reproduces_nodes() {
        let c = Current::Grid(grid_current());
        assert_eq!(c.velocity(Vec3::new(12.0, 24.0, -3.0), 100.0), Vec3::new(6.0, 2.0, 0.0));
        assert_eq!(c.velocity(Vec3::new(14.0, 20.0, 0.0), 200.0), Vec3::new(15.0, -3.0, 0.0));
    }

    #[test]
    fn grid_is_bilinear_at_cell_centre() {
        let c = grid_current();
        // Centre of the first cell: u = mean(1, 3, 2, 6) = 3, v = mean(0, -1, 0 + 1, 2) = 0.5.
        let v = c.velocity(11.0, 22.0, 100.0);
        assert!(close(v.x, 3.0, 1e-12) && close(v.y, 0.5, 1e-12), "{v}");
        // (13, 21), u = 0.5, v = 0.25 in cell (1, 0): u: lo 4, hi 5 -> 4.25;
        // v: lo -1.5, hi 2.5 -> -0.5. Bit-identical to the shared grid interpolation.
        let v = c.velocity(13.0, 21.0, 100.0);
        assert!(close(v.x, 4.25, 1e-12) && close(v.y, -0.5, 1e-12), "{v}");
        assert_eq!(v.x, c.grid.bilinear(&c.u[0], 13.0, 21.0));
    }

    #[test]
    fn grid_is_linear_in_time() {
        let c = grid_current();
        // Halfway: u = (3 + 9) / 2 = 6, v = (0.5 + -0.5) / 2 = 0 at the first cell's centre.
        let v = c.velocity(11.0, 22.0, 150.0);
        assert!(close(v.x, 6.0, 1e-12) && close(v.y, 0.0, 1e-12), "{v}");
        // A quarter of the way at a node: u = 6 + 0.25 (18 - 6) = 9, v = 2 - 0.25 = 1.75.
        let v = c.velocity(12.0, 24.0, 125.0);
        assert!(close(v.x, 9.0, 1e-12) && close(v.y, 1.75, 1e-12), "{v}");
    }

    #[test]
    fn grid_clamps_outside_time_range() {
        let c = grid_current();
        assert_eq!(c.velocity(12.0, 24.0, -1e9), Vec3::new(6.0, 2.0, 0.0));
        assert_eq!(c.velocity(12.0, 24.0, 1e9), Vec3::new(18.0, 1.0, 0.0));
        assert_eq!(c.velocity(12.0, 24.0, f64::NAN), Vec3::new(6.0, 2.0, 0.0));
    }

    #[test]
    fn grid_single_layer_is_steady() {
        let g = grid();
        let c = CurrentGrid::new(g, vec![0.0], vec![vec![1.0; 6]], vec![vec![-2.0; 6]], "c").unwrap();
        for t in [-5.0, 0.0, 7.0] {
            assert_eq!(c.velocity(11.0, 22.0, t), Vec3::new(1.0, -2.0, 0.0));
        }
    }

    #[test]
    fn grid_speed_hint_is_node_maximum() {
        let c = Current::Grid(grid_current());
        let all = Aabb::new(Vec3::new(0.0, 0.0, -1.0), Vec3::new(100.0, 100.0, 0.0));
        // At t = 100 the fastest node is (12, 24): (6, 2).
        assert!(close(c.max_speed_hint(&all, 100.0), 40f64.sqrt(), 1e-12));
        // Halfway, node (12, 24) is (12, 1.5).
        assert!(close(c.max_speed_hint(&all, 150.0), 12f64.hypot(1.5), 1e-12));
        // Only the first cell (nodes x = 10, 12) touches this box: (12, 24) still leads.
        let left = Aabb::new(Vec3::new(10.0, 20.0, 0.0), Vec3::new(11.0, 21.0, 0.0));
        assert!(close(c.max_speed_hint(&left, 100.0), 40f64.sqrt(), 1e-12));
    }

    #[test]
    fn grid_rejects_non_increasing_times() {
        let l = || vec![vec![0.0; 6], vec![0.0; 6]];
        let e = CurrentGrid::new(grid(), vec![1.0, 1.0], l(), l(), "cur").unwrap_err();
        assert!(e.to_string().starts_with("cur.times") && e.to_string().contains("times[1]"), "{e}");
        assert!(CurrentGrid::new(grid(), vec![2.0, 1.0], l(), l(), "cur").is_err());
        assert!(CurrentGrid::new(grid(), vec![0.0, f64::INFINITY], l(), l(), "cur").is_err());
        assert!(CurrentGrid::new(grid(), vec![], vec![], vec![], "cur").is_err());
    }

    #[test]
    fn grid_rejects_wrong_layer_length() {
        let e = CurrentGrid::new(grid(), vec![0.0], vec![vec![0.0; 6]], vec![vec![0.0; 5]], "cur").unwrap_err();
        assert!(e.to_string().starts_with("cur.v") && e.to_string().contains("layer 0 has 5"), "{e}");
        // Layer count must match the times.
        assert!(CurrentGrid::new(grid(), vec![0.0, 1.0], vec![vec![0.0; 6]; 2], vec![vec![0.0; 6]], "cur").is_err());
    }

    #[test]
    fn grid_rejects_nan_values() {
        let mut u = vec![vec![0.0; 6], vec![0.0; 6]];
        u[1][4] = f64::NAN;
        let e = CurrentGrid::new(grid(), vec![0.0, 1.0], u, vec![vec![0.0; 6]; 2], "cur").unwrap_err();
        let msg = e.to_string();
        assert!(msg.starts_with("cur.u") && msg.contains("layer 1, value 4") && msg.contains("NaN"), "{msg}");
    }
}
