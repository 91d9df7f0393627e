//! The wolf pack operators as free functions, so tests check them against hand-computed
//! values: the counts of scouts and renewed wolves, d_near and the distance compared with it,
//! scouting directions (eq. 22) and MWPA's interactive candidate (eq. 23), one raid (eq. 25),
//! one siege move (eq. 28) and the adaptive raid weight (eq. 26 as read in
//! docs/papers/wpa2017.md).

use std::cmp::Ordering;
use std::f64::consts::PI;

/// Number of scouts: a uniform integer in `[ceil(n/(alpha+1)), floor(n/alpha)]`, kept in
/// `[0, n-1]` (the lead is never a scout).
pub fn scout_count(n: usize, alpha: f64, u: f64) -> usize {
    uniform_count(n as f64 / (alpha + 1.0), n as f64 / alpha, n, u)
}

/// A uniform integer in `[ceil(lo), floor(hi)]` from `u` in [0, 1), at most `n - 1` (an empty
/// interval gives `ceil(lo)`).
fn uniform_count(lo: f64, hi: f64, n: usize, u: f64) -> usize {
    let lo = lo.ceil() as usize;
    let hi = (hi.floor() as usize).max(lo);
    let t = lo + ((u * (hi - lo + 1) as f64) as usize).min(hi - lo);
    t.min(n.saturating_sub(1))
}

/// Number of renewed wolves: a uniform integer in `[ceil(n/(2 beta)), floor(n/beta)]`, kept in
/// `[0, n-1]` (the lead is never renewed).
pub fn renewal_count(n: usize, beta: f64, u: f64) -> usize {
    uniform_count(n as f64 / (2.0 * beta), n as f64 / beta, n, u)
}

/// d_near = (1/(D omega)) sum_d |max_d - min_d| (wpa2017 eq. 27; the original WPA's rule).
pub fn d_near(lower: &[f64], upper: &[f64], omega: f64) -> f64 {
    let d = lower.len().max(1) as f64;
    lower.iter().zip(upper).map(|(lo, hi)| (hi - lo).abs()).sum::<f64>() / (d * omega)
}

/// The distance compared with d_near: the mean absolute per-dimension difference.
pub fn distance(a: &[f64], b: &[f64]) -> f64 {
    a.iter().zip(b).map(|(x, y)| (x - y).abs()).sum::<f64>() / a.len().max(1) as f64
}

/// The directions p in 1..=h that move a wolf: sin(2 pi p/h) is 0 exactly when h divides 2p
/// (p = h/2 and p = h), and such a candidate is the wolf itself, which can never be strictly
/// better than it is. The paper's loop evaluates them; tidepath does not, which changes no
/// move a wolf makes (in floating point sin(pi) is 1.2e-16, a shift below the last bit of any
/// coordinate that is not within 1e-16 of 0) and saves h/2 evaluations in every h of
/// scouting's direction candidates when h is even.
pub fn moving_directions(h: usize) -> Vec<usize> {
    (1..=h).filter(|&p| (2 * p) % h != 0).collect()
}

/// Scouting direction p of h (eq. 22 read as sin(2 pi p/h)): `out = x + sin(2 pi p/h) step_a`.
pub fn direction(x: &[f64], step_a: &[f64], p: usize, h: usize, out: &mut [f64]) {
    let s = (2.0 * PI * p as f64 / h as f64).sin();
    for ((o, &x), &a) in out.iter_mut().zip(x).zip(step_a) {
        *o = x + s * a;
    }
}

/// MWPA's interactive candidate (eq. 23): `out = x + phi (lead - x) + varphi (xa - xb)`.
pub fn interactive(x: &[f64], lead: &[f64], xa: &[f64], xb: &[f64], phi: &[f64], varphi: &[f64], out: &mut [f64]) {
    for d in 0..out.len() {
        out[d] = x[d] + phi[d] * (lead[d] - x[d]) + varphi[d] * (xa[d] - xb[d]);
    }
}

/// One raid: `x_d += step_d sign(g_d - x_d)`, with sign(0) = 0 (a coordinate already on the
/// lead's stays).
pub fn raid(x: &mut [f64], g: &[f64], step: &[f64]) {
    for ((x, &g), &s) in x.iter_mut().zip(g).zip(step) {
        let diff = g - *x;
        let sign = if diff > 0.0 {
            1.0
        } else if diff < 0.0 {
            -1.0
        } else {
            0.0
        };
        *x += s * sign;
    }
}

/// One siege move: `out_d = x_d + factor step_c_d |g_d - x_d|`, `factor` = lambda (WPA) or
/// xi lambda (MWPA, eq. 28).
pub fn siege(x: &[f64], g: &[f64], step_c: &[f64], factor: f64, out: &mut [f64]) {
    for d in 0..out.len() {
        out[d] = x[d] + factor * step_c[d] * (g[d] - x[d]).abs();
    }
}

/// The adaptive raid weight (eq. 26 as read in docs/papers/wpa2017.md): from the wolf's own
/// cost f, the pack's best f_min and mean f_avg,
/// `w_min + (w_max - w_min)(f - f_min)/(f_avg - f_min)` when f <= f_avg, else w_max;
/// w_min when f_avg == f_min.
pub fn adaptive_weight(f: f64, f_min: f64, f_avg: f64, w_min: f64, w_max: f64) -> f64 {
    if f > f_avg || f.is_nan() {
        w_max
    } else if f_avg <= f_min {
        w_min
    } else {
        (w_min + (w_max - w_min) * (f - f_min) / (f_avg - f_min)).clamp(w_min, w_max)
    }
}

pub(super) fn cmp_cost(a: f64, b: f64) -> Ordering {
    match (a.is_nan(), b.is_nan()) {
        (true, true) => Ordering::Equal,
        (true, false) => Ordering::Greater,
        (false, true) => Ordering::Less,
        _ => a.partial_cmp(&b).expect("not NaN"),
    }
}

/// True when `a` is strictly better than `b` (NaN is never better).
#[inline]
pub(super) fn better(a: f64, b: f64) -> bool {
    a < b || (b.is_nan() && !a.is_nan())
}
