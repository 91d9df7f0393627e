//! Analytic seabed: a base level plus Gaussian peaks (wpa2017 and 001).

use crate::error::{Error, Result};

/// One Gaussian peak: height `h` above the base at (x, y), widths `sigma_x`, `sigma_y`:
/// h exp(-((x - x_j)/sigma_x)^2 - ((y - y_j)/sigma_y)^2)  (wpa2017 eq. 1 with sigma = x_j / k).
#[derive(Clone, Debug, PartialEq)]
pub struct Peak {
    pub x: f64,
    pub y: f64,
    pub height: f64,
    pub sigma_x: f64,
    pub sigma_y: f64,
}

/// Analytic seabed: base level plus a sum of Gaussian peaks, optionally capped at a ceiling
/// (wpa2017 eq. 1 caps the terrain at h_max).
#[derive(Clone, Debug, PartialEq)]
pub struct GaussianPeaks {
    pub base: f64,
    pub peaks: Vec<Peak>,
    pub ceiling: Option<f64>,
}

impl Peak {
    /// wpa2017 eq. 1 writes the exponent as (k_x (x - x_j) / x_j)^2: the peak's own centre
    /// coordinate sets its width, sigma_x = x_j / k_x (docs/papers/wpa2017.md). That only makes
    /// sense for centres at positive coordinates and positive k, so anything else is rejected.
    pub fn from_paper_k(x: f64, y: f64, height: f64, k_x: f64, k_y: f64, field: &str) -> Result<Self> {
        if !(x > 0.0 && y > 0.0 && x.is_finite() && y.is_finite()) {
            return Err(Error::input(
                format!("{field}.center"),
                format!("wpa2017 peak widths are x_j / k, so the centre must be positive and finite, got [{x}, {y}]"),
            ));
        }
        if !(k_x > 0.0 && k_y > 0.0 && k_x.is_finite() && k_y.is_finite()) {
            return Err(Error::input(format!("{field}.k"), format!("must be positive and finite, got [{k_x}, {k_y}]")));
        }
        if !height.is_finite() {
            return Err(Error::input(format!("{field}.height"), format!("must be finite, got {height}")));
        }
        Ok(Self { x, y, height, sigma_x: x / k_x, sigma_y: y / k_y })
    }

    /// lfhh2019 eq. 11, Z = h exp(-((Y - y0)^2 a^2 + (X - x0)^2 b^2) / (2 sigma^2)), is the
    /// same Gaussian with sigma_x = sqrt(2) sigma / b and sigma_y = sqrt(2) sigma / a.
    pub fn from_seabed_eq11(x0: f64, y0: f64, h: f64, a: f64, b: f64, sigma: f64, field: &str) -> Result<Self> {
        if !(x0.is_finite() && y0.is_finite() && h.is_finite()) {
            return Err(Error::input(
                field.to_string(),
                format!("centre and height must be finite, got [{x0}, {y0}], {h}"),
            ));
        }
        if !(a > 0.0 && b > 0.0 && sigma > 0.0 && a.is_finite() && b.is_finite() && sigma.is_finite()) {
            return Err(Error::input(
                field.to_string(),
                format!("a, b and sigma must be positive and finite, got a = {a}, b = {b}, sigma = {sigma}"),
            ));
        }
        let s = std::f64::consts::SQRT_2 * sigma;
        Ok(Self { x: x0, y: y0, height: h, sigma_x: s / b, sigma_y: s / a })
    }

    /// h exp(-(dx/sx)^2 - (dy/sy)^2). Both the point elevation and the rectangle bound go through
    /// this one expression so that, at a point, the bound rounds exactly like the value.
    ///
    /// Beyond FAR_EXPONENT the term is below 1e-26 of the peak's height and is taken as 0
    /// without calling exp, which is a third of a path evaluation's time on a peak seabed
    /// (wpa-threats); for any seabed deeper than a micrometre the sum is unchanged to the bit.
    #[inline]
    fn term(&self, dx: f64, dy: f64) -> f64 {
        let u = dx / self.sigma_x;
        let v = dy / self.sigma_y;
        let e = u * u + v * v;
        if e > FAR_EXPONENT {
            return 0.0;
        }
        self.height * (-e).exp()
    }
}

/// Exponent beyond which a peak's term is taken as 0 (exp(-60) = 8.8e-27).
const FAR_EXPONENT: f64 = 60.0;

impl GaussianPeaks {
    /// The terrain of wpa2017 eq. 1 from its own parameters: base h0, peaks given as
    /// `[x_j, y_j, h_j, k_x, k_y]`, and the cap h_max (see [`Peak::from_paper_k`]).
    pub fn from_paper_k(h0: f64, peaks: &[[f64; 5]], h_max: Option<f64>, field: &str) -> Result<Self> {
        if !h0.is_finite() {
            return Err(Error::input(format!("{field}.base"), format!("must be finite, got {h0}")));
        }
        if let Some(c) = h_max {
            if c.is_nan() {
                return Err(Error::input(format!("{field}.ceiling"), "must be a number, got NaN"));
            }
        }
        let peaks = peaks
            .iter()
            .enumerate()
            .map(|(j, &[x, y, h, kx, ky])| Peak::from_paper_k(x, y, h, kx, ky, &format!("{field}.peaks[{j}]")))
            .collect::<Result<Vec<_>>>()?;
        Ok(Self { base: h0, peaks, ceiling: h_max })
    }

    #[inline]
    pub(super) fn elevation(&self, x: f64, y: f64) -> f64 {
        let z = self.uncapped(x, y);
        match self.ceiling {
            Some(c) => z.min(c),
            None => z,
        }
    }

    #[inline]
    pub(super) fn uncapped(&self, x: f64, y: f64) -> f64 {
        let mut z = self.base;
        for p in &self.peaks {
            z += p.term(x - p.x, y - p.y);
        }
        z
    }

    /// How sharply the uncapped sum can curve downward: an upper bound of minus its second
    /// derivative along any horizontal unit direction. For one peak, with alpha = w_x / sigma_x
    /// and beta = w_y / sigma_y, the second derivative of exp(-u^2 - v^2) is
    /// [4 (u alpha + v beta)^2 - 2 (alpha^2 + beta^2)] exp(-u^2 - v^2), which lies in
    /// [-2, 4/e] (alpha^2 + beta^2). So a bump (h > 0) curves down by at most 2 h m (over its
    /// summit) and a dip by at most 4/e |h| m (on its flanks), with m = max(1/sigma_x^2,
    /// 1/sigma_y^2).
    pub(super) fn max_concavity(&self) -> f64 {
        self.peaks
            .iter()
            .map(|p| {
                let m = (1.0 / (p.sigma_x * p.sigma_x)).max(1.0 / (p.sigma_y * p.sigma_y));
                let k = if p.height >= 0.0 { 2.0 } else { 4.0 / std::f64::consts::E };
                k * p.height.abs() * m
            })
            .sum()
    }

    /// Each term is bounded on its own: a bump is highest at the rectangle point nearest its
    /// centre, a dip (h < 0) is shallowest at the farthest corner. Summing per-term bounds loses
    /// a little where peaks overlap but needs one exp per peak, and collapses to the exact value
    /// (bit for bit) when the rectangle is a point.
    #[inline]
    pub(super) fn max_in(&self, x0: f64, y0: f64, x1: f64, y1: f64) -> f64 {
        let mut z = self.base;
        for p in &self.peaks {
            let (dx, dy) = if p.height >= 0.0 {
                ((x0 - p.x).max(p.x - x1).max(0.0), (y0 - p.y).max(p.y - y1).max(0.0))
            } else {
                ((x0 - p.x).abs().max((x1 - p.x).abs()), (y0 - p.y).abs().max((y1 - p.y).abs()))
            };
            z += p.term(dx, dy);
        }
        match self.ceiling {
            Some(c) => z.min(c),
            None => z,
        }
    }

    /// An upper bound of [`GaussianPeaks::max_in`]'s value as it computes it, without exp, to
    /// reject far segments before it. Each bump's exp(-e) (the same e, bit for bit) is bounded
    /// by 1 / (1 + e + e^2/2 + e^3/6 + e^4/24), the Taylor polynomial of exp(e) being below it,
    /// times 1 + 1e-9 (the roundings of the polynomial and of exp are about 1e-15); each dip's
    /// term by 0, as it is never positive. Rounding is monotone, so the sum of these larger
    /// terms is never below the sum `max_in` makes. NaN (no bound) where `max_in` could meet a
    /// NaN or an infinite dip. Above it by at most 1.15 % of each bump's height (near e = 3.3;
    /// 0.14 % at e = 1, 1e-5 at e = 40).
    #[inline]
    pub(super) fn max_in_upper(&self, x0: f64, y0: f64, x1: f64, y1: f64) -> f64 {
        let mut z = self.base;
        for p in &self.peaks {
            if p.height >= 0.0 {
                let dx = (x0 - p.x).max(p.x - x1).max(0.0);
                let dy = (y0 - p.y).max(p.y - y1).max(0.0);
                let u = dx / p.sigma_x;
                let v = dy / p.sigma_y;
                let e = u * u + v * v;
                // As `Peak::term`: beyond FAR_EXPONENT the term is 0 (skipped); a NaN e stays NaN.
                if e <= FAR_EXPONENT || e.is_nan() {
                    // 1 + e + e^2/2 + e^3/6 + e^4/24 in two short chains (all terms positive:
                    // the roundings stay relative, about 1e-15).
                    let e2 = e * e;
                    let d = (1.0 + e) + e2 * ((0.5 + e * (1.0 / 6.0)) + e2 * (1.0 / 24.0));
                    z += p.height * ((1.0 + 1e-9) / d);
                }
            } else {
                let dx = (x0 - p.x).abs().max((x1 - p.x).abs());
                let dy = (y0 - p.y).abs().max((y1 - p.y).abs());
                let u = dx / p.sigma_x;
                let v = dy / p.sigma_y;
                if (u * u + v * v).is_nan() || !p.height.is_finite() {
                    return f64::NAN;
                }
            }
        }
        match self.ceiling {
            Some(c) => z.min(c),
            None => z,
        }
    }

    /// Lower bound over a rectangle: each peak at the point of the rectangle where it is
    /// lowest (the farthest for a positive peak, the nearest for a negative one); the ceiling
    /// only caps, so min(bound, ceiling) stays a lower bound.
    pub(super) fn min_in(&self, x0: f64, y0: f64, x1: f64, y1: f64) -> f64 {
        let mut z = self.base;
        for p in &self.peaks {
            let (dx, dy) = if p.height >= 0.0 {
                ((x0 - p.x).abs().max((x1 - p.x).abs()), (y0 - p.y).abs().max((y1 - p.y).abs()))
            } else {
                ((x0 - p.x).max(p.x - x1).max(0.0), (y0 - p.y).max(p.y - y1).max(0.0))
            };
            z += p.term(dx, dy);
        }
        match self.ceiling {
            Some(c) => z.min(c),
            None => z,
        }
    }

    pub(super) fn min_sigma(&self) -> Option<f64> {
        self.peaks.iter().map(|p| p.sigma_x.min(p.sigma_y)).filter(|s| *s > 0.0).reduce(f64::min)
    }
}
