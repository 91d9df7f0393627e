//! The fixed-height histogram of lfhh2019 eqs. 1-2 and its learning transformation (eq. 14),
//! as pure functions, so tests check them against hand-computed values.
//!
//! For one variable with bounds `[lo, hi]` and the ascending values `a[0] <= ... <= a[S-1]` of
//! the elite (0-based):
//!
//! ```text
//! bin 1 starts at lo;
//! bin k, k = 2 .. binNum, starts at (a[q-1] + a[q]) / 2,   q = floor((k - 1) S / binNum)   (eq. 1)
//! bin k ends where bin k + 1 starts; bin binNum ends at hi                                  (eq. 2)
//! ```
//!
//! Eq. 1 is printed without its closing parenthesis; it is read as the midpoint of two
//! neighbours of the sorted elite, with 0-based indices (docs/papers/lfhh2019.md, A1). Every
//! bin holds the same number of elite values, so a value is drawn by picking a bin uniformly
//! and then a point uniformly inside it; a zero-width bin (repeated elite values) returns its
//! one value. `q` is at least 1 for every `k >= 2` exactly when `binNum <= S`, which the
//! parameters guarantee.
//!
//! The learning transformation strategy (eq. 14) pulls each elite value toward the best
//! solution's value of the same variable before the histogram is built:
//! `v' = v + lambda (best_j - v)`.

use crate::optim::clamp;
use crate::rng::unit_f64;

/// Eq. 14: `v + lambda (best - v)`.
#[inline(always)]
pub fn lts(v: f64, best: f64, lambda: f64) -> f64 {
    v + lambda * (best - v)
}

/// Eq. 1's index `q = floor((k - 1) S / binNum)` of the elite value that ends the midpoint
/// starting bin `k` (1-based, `k >= 2`), for an elite of `s` values and `bins` bins.
#[inline]
pub fn boundary_index(k: usize, s: usize, bins: usize) -> usize {
    (k - 1) * s / bins
}

/// The `bins + 1` edges of the histogram of `sorted` (ascending, at least `bins` values) on
/// `[lo, hi]`: bin `b` (0-based) is `[edges[b], edges[b + 1]]`. A midpoint outside the bounds
/// (an elite value the objective's repair left outside the box) is clamped to them, so the
/// edges never decrease.
pub fn bin_edges(sorted: &[f64], bins: usize, lo: f64, hi: f64, edges: &mut [f64]) {
    let s = sorted.len();
    assert!(bins >= 1 && bins <= s, "{bins} bins for {s} elite values");
    assert_eq!(edges.len(), bins + 1);
    edges[0] = lo;
    for k in 2..=bins {
        let q = boundary_index(k, s, bins);
        edges[k - 1] = clamp(0.5 * (sorted[q - 1] + sorted[q]), lo, hi);
    }
    edges[bins] = hi;
}

/// `x`'s place in the order of [`f64::total_cmp`], as an unsigned integer.
#[inline(always)]
pub fn total_order_key(x: f64) -> u64 {
    let b = x.to_bits();
    b ^ ((((b as i64) >> 63) as u64) >> 1) ^ (1 << 63)
}

/// The inverse of [`total_order_key`].
#[inline(always)]
fn from_total_order_key(k: u64) -> f64 {
    let b = k ^ (1 << 63);
    f64::from_bits(b ^ ((((b as i64) >> 63) as u64) >> 1))
}

/// Sorts `values` ascending in the order of [`f64::total_cmp`], through integer keys in
/// `keys` (reused): a sort of integers is about twice as fast as one that compares floats,
/// and the histograms sort every variable's elite every generation.
pub fn sort_values(values: &mut [f64], keys: &mut Vec<u64>) {
    keys.clear();
    keys.extend(values.iter().map(|&v| total_order_key(v)));
    keys.sort_unstable();
    for (v, &k) in values.iter_mut().zip(keys.iter()) {
        *v = from_total_order_key(k);
    }
}

/// The bin a random word picks among `bins`, uniformly, and the place inside it: `w / 2^64`
/// is a uniform U in [0, 1), and `bins U = bin + frac` splits it into a uniform bin (the high
/// part of `w * bins`, Lemire's multiply-shift, bias below `bins / 2^64`) and a uniform
/// fraction independent of it (the low part, to 2^-53 after rounding; `bins <= 2^11` keeps
/// all 53 bits, larger counts lose `log2(bins) - 11` of them). One word therefore draws both,
/// exactly as "a bin uniformly, then a value uniformly inside it" does.
#[inline(always)]
pub fn split_word(w: u64, bins: usize) -> (usize, f64) {
    let p = u128::from(w) * bins as u128;
    ((p >> 64) as usize, unit_f64(p as u64))
}

/// The bin of [`split_word`] alone.
#[inline(always)]
pub fn bin_index(w: u64, bins: usize) -> usize {
    ((u128::from(w) * bins as u128) >> 64) as usize
}

/// The point at fraction `u` in [0, 1) of bin `bin`: `edges[bin] + u (edges[bin + 1] -
/// edges[bin])`, kept inside the bin against rounding; a zero-width bin gives its edge.
#[inline(always)]
pub fn sample_in(edges: &[f64], bin: usize, u: f64) -> f64 {
    let (a, b) = (edges[bin], edges[bin + 1]);
    clamp(a + u * (b - a), a, b)
}
