//! The time-varying meandering jet of ijs2023 and the configuration that maps it onto the world.

use crate::error::{Error, Result};
use crate::geom::{Aabb, Vec3};
use std::f64::consts::FRAC_PI_2;

/// How the meandering jet's speed is turned into metres per second.
///
/// The jet is non-dimensional, so its own speed says nothing about a real ocean; ijs2023 only
/// borrows its direction and states the magnitude relative to the AUV's speed.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Magnitude {
    /// Every point where the jet flows (jet-unit speed > 1e-12) gets exactly this speed (m/s):
    /// ijs2023's literal "|v_c| = ratio x |v_rc|" (docs/papers/ijs2023.md).
    Fixed(f64),
    /// The fastest point of the domain at t = 0 gets this speed (m/s) and the rest keep their
    /// relative strength: docs/papers/ijs2023.md's option "scale so that the maximum equals the
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
    /// Seconds of world time per jet time unit. Chosen 2000 (t_jet = t / 2000): ijs2023's
    /// missions last about 26 000 s, so the jet changes visibly but not wildly along a path.
    pub seconds_per_unit: f64,
    pub magnitude: Magnitude,
}

impl JetConfig {
    /// The constants chosen in docs/papers/shared.md#meandering-jet stretched over the given world rectangle.
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

/// The time-varying meandering jet of ijs2023 (Guo, Chen & Pang, IEEE Access; eqs. 27-28,
/// docs/papers/shared.md#meandering-jet), mapped from jet units onto a rectangle of the world.
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

    /// World velocity (m/s) at `p` and time `t` (s); horizontal only, as in ijs2023.
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
