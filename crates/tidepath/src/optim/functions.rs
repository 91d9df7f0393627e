//! Benchmark functions used by wpa2017 (Zhang et al. 2017, MWPA, Table 2) and 002 (Liu et al.
//! 2015, AMFA, Tables 1 and 3), with the standard definitions of docs/papers/shared.md#benchmark-functions.
//!
//! The papers' printed formulas are not copied where they are wrong: amfa2015 prints Griewank
//! with Rosenbrock's formula (we use the standard Griewank), and prints Rosenbrock as
//! `100(x_i^2 - x_{i+1})^2 + (x_i - 1)^2`, which is the same function. wpa2017's "Easorm" and
//! "Rastrigrn" are Easom and Rastrigin.
//!
//! Ranges: [`Function::default_range`] is the usual domain; [`Function::small_range`] and
//! [`Function::wide_range`] are amfa2015's Table 1 and Table 3 (for reproduction);
//! [`Function::wpa2017_setting`] is wpa2017's Table 2 (dimension and range).

use super::{Objective, Scratch};

use std::f64::consts::{E, PI};

/// One benchmark function. Every function is defined for any dimension `D >= 1` except Easom,
/// which is a two-dimensional function (see [`Function::value`] for what other `D` give).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, serde::Serialize, serde::Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Function {
    /// `sum x_i^2`; 0 at 0.
    Sphere,
    /// `sum_{i<D} [100 (x_{i+1} - x_i^2)^2 + (x_i - 1)^2]`; 0 at (1, ..., 1).
    Rosenbrock,
    /// `sum [x_i^2 - 10 cos(2 pi x_i) + 10]`; 0 at 0.
    Rastrigin,
    /// `1 + sum x_i^2 / 4000 - prod cos(x_i / sqrt(i))` (i from 1); 0 at 0.
    Griewank,
    /// `-20 exp(-0.2 sqrt(mean x_i^2)) - exp(mean cos(2 pi x_i)) + 20 + e`; 0 at 0.
    Ackley,
    /// `sum x_i^2 + (sum 0.5 i x_i)^2 + (sum 0.5 i x_i)^4` (i from 1); 0 at 0.
    Zakharov,
    /// `-cos x1 cos x2 exp(-(x1 - pi)^2 - (x2 - pi)^2)` (D = 2); -1 at (pi, pi).
    Easom,
    /// `sum (x_i - 1)^2 - sum_{i>=2} x_i x_{i-1}`; `-D(D+4)(D-1)/6` at `x_i = i (D + 1 - i)`.
    Trid,
    /// Schwefel 1.2: `sum_i (sum_{k<=i} x_k)^2`; 0 at 0.
    Quadric,
}

impl Function {
    /// Every function, in a fixed order.
    pub const ALL: [Function; 9] = [
        Function::Sphere,
        Function::Rosenbrock,
        Function::Rastrigin,
        Function::Griewank,
        Function::Ackley,
        Function::Zakharov,
        Function::Easom,
        Function::Trid,
        Function::Quadric,
    ];

    /// Lower-case id (`sphere`, `rosenbrock`, ..., `quadric`).
    pub fn id(&self) -> &'static str {
        match self {
            Function::Sphere => "sphere",
            Function::Rosenbrock => "rosenbrock",
            Function::Rastrigin => "rastrigin",
            Function::Griewank => "griewank",
            Function::Ackley => "ackley",
            Function::Zakharov => "zakharov",
            Function::Easom => "easom",
            Function::Trid => "trid",
            Function::Quadric => "quadric",
        }
    }

    /// The function with this id (exact, lower-case), if any.
    pub fn from_id(id: &str) -> Option<Function> {
        Function::ALL.into_iter().find(|f| f.id() == id)
    }

    /// The dimension the function is defined for, if it has a fixed one (Easom: 2).
    pub fn fixed_dim(&self) -> Option<usize> {
        match self {
            Function::Easom => Some(2),
            _ => None,
        }
    }

    /// `f(x)`. Never allocates.
    ///
    /// Easom is defined for `D = 2`. For other `D` this evaluates
    /// `-(-1)^D prod cos x_i exp(-sum (x_i - pi)^2)`, which is the standard form at `D = 2` and
    /// keeps the global minimum -1 at (pi, ..., pi) for any `D`.
    pub fn value(&self, x: &[f64]) -> f64 {
        match self {
            Function::Sphere => x.iter().map(|v| v * v).sum(),
            Function::Rosenbrock => x
                .windows(2)
                .map(|w| {
                    let a = w[1] - w[0] * w[0];
                    let b = w[0] - 1.0;
                    100.0 * a * a + b * b
                })
                .sum(),
            Function::Rastrigin if turns_in_range(x) => lanes_sum(x, |v| v * v - 10.0 * cos_2pi_near(v) + 10.0),
            Function::Rastrigin => x.iter().map(|v| v * v - 10.0 * cos_2pi(*v) + 10.0).sum(),
            Function::Griewank => {
                let mut sum = 0.0;
                let mut prod = 1.0;
                for (i, v) in x.iter().enumerate() {
                    sum += v * v;
                    prod *= (v / ((i + 1) as f64).sqrt()).cos();
                }
                1.0 + sum / 4000.0 - prod
            }
            Function::Ackley => {
                let n = x.len() as f64;
                let sq = x.iter().map(|v| v * v).sum::<f64>() / n;
                let cs =
                    if turns_in_range(x) { lanes_sum(x, cos_2pi_near) } else { x.iter().map(|v| cos_2pi(*v)).sum() }
                        / n;
                // Grouped so that the value at the optimum is exactly 0.
                20.0 * (1.0 - (-0.2 * sq.sqrt()).exp()) + (E - cs.exp())
            }
            Function::Zakharov => {
                let mut sq = 0.0;
                let mut s = 0.0;
                for (i, v) in x.iter().enumerate() {
                    sq += v * v;
                    s += 0.5 * (i + 1) as f64 * v;
                }
                let s2 = s * s;
                sq + s2 + s2 * s2
            }
            Function::Easom => {
                let mut prod = if x.len() % 2 == 0 { -1.0 } else { 1.0 };
                let mut sq = 0.0;
                for v in x {
                    prod *= v.cos();
                    sq += (v - PI) * (v - PI);
                }
                prod * (-sq).exp()
            }
            Function::Trid => {
                let a: f64 = x.iter().map(|v| (v - 1.0) * (v - 1.0)).sum();
                let b: f64 = x.windows(2).map(|w| w[1] * w[0]).sum();
                a - b
            }
            Function::Quadric => {
                let mut run = 0.0;
                let mut total = 0.0;
                for v in x {
                    run += v;
                    total += run * run;
                }
                total
            }
        }
    }

    /// The global minimum value in dimension `dim`.
    pub fn optimum(&self, dim: usize) -> f64 {
        match self {
            Function::Easom => -1.0,
            Function::Trid => {
                let d = dim as f64;
                -d * (d + 4.0) * (d - 1.0) / 6.0
            }
            _ => 0.0,
        }
    }

    /// A point where the global minimum is attained in dimension `dim`.
    pub fn optimum_point(&self, dim: usize) -> Vec<f64> {
        match self {
            Function::Rosenbrock => vec![1.0; dim],
            Function::Easom => vec![PI; dim],
            Function::Trid => (1..=dim).map(|i| (i * (dim + 1 - i)) as f64).collect(),
            _ => vec![0.0; dim],
        }
    }

    /// The usual search domain (the same for every coordinate): Sphere and Rastrigin
    /// [-5.12, 5.12], Rosenbrock [-2.048, 2.048], Griewank [-600, 600], Ackley
    /// [-32.768, 32.768], Zakharov [-5, 10], Easom [-100, 100], Trid [-D^2, D^2],
    /// Quadric [-100, 100].
    pub fn default_range(&self, dim: usize) -> (f64, f64) {
        match self {
            Function::Sphere | Function::Rastrigin => (-5.12, 5.12),
            Function::Rosenbrock => (-2.048, 2.048),
            Function::Griewank => (-600.0, 600.0),
            Function::Ackley => (-32.768, 32.768),
            Function::Zakharov => (-5.0, 10.0),
            Function::Easom => (-100.0, 100.0),
            Function::Trid => {
                let d2 = (dim * dim) as f64;
                (-d2, d2)
            }
            Function::Quadric => (-100.0, 100.0),
        }
    }

    /// amfa2015, Table 1 ("small range"), for the six functions it uses; `None` otherwise.
    ///
    /// Note: the printed Ackley range [-2.768, 2.768] (and Griewank's [-8, 8]) are not the usual
    /// ones; they are kept for reproduction. See [`Function::amfa2015_range_note`].
    pub fn small_range(&self) -> Option<(f64, f64)> {
        match self {
            Function::Sphere | Function::Rastrigin => Some((-5.12, 5.12)),
            Function::Rosenbrock => Some((-2.048, 2.048)),
            Function::Griewank => Some((-8.0, 8.0)),
            Function::Ackley => Some((-2.768, 2.768)),
            Function::Zakharov => Some((-5.0, 10.0)),
            _ => None,
        }
    }

    /// amfa2015, Table 3 ("wide range"), for the six functions it uses; `None` otherwise.
    ///
    /// Note: the printed Ackley range [-23.768, 23.768] is not the usual [-32.768, 32.768]; it
    /// is kept for reproduction. See [`Function::amfa2015_range_note`].
    pub fn wide_range(&self) -> Option<(f64, f64)> {
        match self {
            Function::Sphere | Function::Rosenbrock | Function::Rastrigin => Some((-100.0, 100.0)),
            Function::Griewank => Some((-600.0, 600.0)),
            Function::Ackley => Some((-23.768, 23.768)),
            Function::Zakharov => Some((-50.0, 100.0)),
            _ => None,
        }
    }

    /// A warning to print next to results obtained on amfa2015's ranges when those ranges are
    /// not the usual ones (Ackley, and Griewank's small range).
    pub fn amfa2015_range_note(&self) -> Option<&'static str> {
        match self {
            Function::Ackley => Some(
                "amfa2015 prints Ackley ranges [-2.768, 2.768] and [-23.768, 23.768]; the usual domain is \
                 [-32.768, 32.768]. The printed ranges are used for reproduction.",
            ),
            Function::Griewank => {
                Some("amfa2015's small Griewank range [-8, 8] is unusual (the usual domain is [-600, 600]).")
            }
            _ => None,
        }
    }

    /// wpa2017, Table 2: `(dimension, lower, upper)` for Easom (2, [-100, 100]), Trid6
    /// (6, [-36, 36]), Sphere (30, [-1.5, 1.5]), Rastrigin (60, [-10, 10]) and Quadric
    /// (120, [-30, 30]); `None` for the functions wpa2017 does not use.
    pub fn wpa2017_setting(&self) -> Option<(usize, f64, f64)> {
        match self {
            Function::Easom => Some((2, -100.0, 100.0)),
            Function::Trid => Some((6, -36.0, 36.0)),
            Function::Sphere => Some((30, -1.5, 1.5)),
            Function::Rastrigin => Some((60, -10.0, 10.0)),
            Function::Quadric => Some((120, -30.0, 30.0)),
            _ => None,
        }
    }
}

impl std::fmt::Display for Function {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.id())
    }
}

/// A benchmark function on a box, as an [`Objective`]. Cheap to evaluate, so
/// `parallel_hint` is false; `evaluate` never allocates.
#[derive(Clone, Debug, PartialEq)]
pub struct FunctionObjective {
    pub function: Function,
    pub lower: Vec<f64>,
    pub upper: Vec<f64>,
}

impl FunctionObjective {
    /// `function` on the cube `[lo, hi]^dim`.
    pub fn new(function: Function, dim: usize, lo: f64, hi: f64) -> Self {
        Self { function, lower: vec![lo; dim], upper: vec![hi; dim] }
    }

    /// `function` on its [`Function::default_range`] in dimension `dim`.
    pub fn with_default_range(function: Function, dim: usize) -> Self {
        let (lo, hi) = function.default_range(dim);
        Self::new(function, dim, lo, hi)
    }
}

impl Objective for FunctionObjective {
    fn dim(&self) -> usize {
        self.lower.len()
    }

    fn lower(&self) -> &[f64] {
        &self.lower
    }

    fn upper(&self) -> &[f64] {
        &self.upper
    }

    fn evaluate(&self, x: &[f64], _scratch: &mut Scratch) -> f64 {
        self.function.value(x)
    }
}

/// The sum of `term` over `x`, four coordinates at a time into four partial sums (then added
/// in a fixed order, so the value is deterministic): independent lanes let the compiler
/// evaluate `term` for several coordinates at once.
#[inline]
fn lanes_sum(x: &[f64], term: impl Fn(f64) -> f64) -> f64 {
    let mut acc = [0.0f64; 4];
    let chunks = x.chunks_exact(4);
    let tail = chunks.remainder();
    for c in chunks {
        for k in 0..4 {
            acc[k] += term(c[k]);
        }
    }
    let mut rest = 0.0;
    for &v in tail {
        rest += term(v);
    }
    (acc[0] + acc[1]) + (acc[2] + acc[3]) + rest
}

/// cos(2π v), with the turn count taken out exactly: v = n/4 + r with n an integer and
/// |r| ≤ 1/8 (both exact in floating point), then cos or sin of 2π r (|2π r| ≤ π/4) by
/// minimax polynomials and the quadrant n mod 4. Where
/// `(2.0 * PI * v).cos()` first rounds 2π v (an error of 1e-13 at v = 100), this reduces v
/// exactly: integers give exactly 1, half-integers exactly −1. About four times faster than
/// libm's `cos` (no data-dependent branches), which makes Rastrigin and Ackley, the benchmark
/// tables' most common functions, as cheap as they should be. Falls back to libm for |v| ≥ 2^49.
#[inline]
pub fn cos_2pi(v: f64) -> f64 {
    if v.is_nan() || v.abs() >= MAX_TURNS {
        return (std::f64::consts::TAU * v).cos();
    }
    cos_2pi_near(v)
}

/// |v| below which [`cos_2pi_near`] holds (2^49: 4v + 1.5 · 2^52 is exact).
const MAX_TURNS: f64 = 562_949_953_421_312.0;

/// Whether every coordinate is within [`MAX_TURNS`] (NaN is not), so a whole vector can take
/// [`cos_2pi_near`] without a branch per coordinate, which would keep the compiler from
/// evaluating several coordinates at once.
#[inline]
fn turns_in_range(x: &[f64]) -> bool {
    x.iter().fold(true, |ok, v| ok & (v.abs() < MAX_TURNS))
}

/// [`cos_2pi`] for |v| < [`MAX_TURNS`], without the check.
#[inline(always)]
fn cos_2pi_near(v: f64) -> f64 {
    // 1.5 · 2^52: adding it rounds to an integer (ties to even) for |4v| < 2^51.
    const ROUND: f64 = 6_755_399_441_055_744.0;
    let shifted = 4.0 * v + ROUND;
    let n = shifted - ROUND;
    // ROUND is a multiple of 4, so the low bits of the shifted value are n mod 4.
    let q = shifted.to_bits() & 3;
    let x = std::f64::consts::TAU * (v - 0.25 * n);
    let x2 = x * x;
    // Minimax polynomials on [−π/4, π/4] (the coefficients of fdlibm's __kernel_cos and
    // __kernel_sin, errors below 2^−58): degree 14 and 13.
    const C: [f64; 6] = [
        0.0416666666666666,
        -0.001388888888887411,
        2.480158728947673e-05,
        -2.7557314351390663e-07,
        2.087572321298175e-09,
        -1.1359647557788195e-11,
    ];
    const S: [f64; 6] = [
        -0.16666666666666632,
        0.00833333333332249,
        -0.0001984126982985795,
        2.7557313707070068e-06,
        -2.5050760253406863e-08,
        1.58969099521155e-10,
    ];
    let x4 = x2 * x2;
    let c = 1.0 - 0.5 * x2 + x4 * (C[0] + x2 * (C[1] + x2 * (C[2] + x2 * (C[3] + x2 * (C[4] + x2 * C[5])))));
    let s = x + x * x2 * (S[0] + x2 * (S[1] + x2 * (S[2] + x2 * (S[3] + x2 * (S[4] + x2 * S[5])))));
    // Quadrant without branches (a mispredicted branch per coordinate costs more than both
    // series): odd quadrants take the sine, quadrants 1 and 2 flip the sign.
    let odd = 0u64.wrapping_sub(q & 1);
    let sign = (((q + 1) >> 1) & 1) << 63;
    f64::from_bits(((c.to_bits() & !odd) | (s.to_bits() & odd)) ^ sign)
}

#[cfg(test)]
mod tests {
    /// cos(2π v) agrees with libm to 1e-15 where libm's argument is exact enough (|v| < 1),
    /// to the rounding of 2π v beyond, and is exact at integers and half-integers.
    #[test]
    fn cos_2pi_matches_libm_and_is_exact_at_whole_turns() {
        let mut state = 0x9e37_79b9_7f4a_7c15u64;
        let mut worst_small = 0.0f64;
        for k in 0..200_000 {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            let u = (state >> 11) as f64 / (1u64 << 53) as f64;
            let v = if k % 2 == 0 { 2.0 * u - 1.0 } else { 2000.0 * u - 1000.0 };
            let libm = (std::f64::consts::TAU * v).cos();
            let ours = cos_2pi(v);
            // libm's argument 2π v carries an error of about |2π v| 1.1e-16.
            let allowed = 1e-15 + std::f64::consts::TAU * v.abs() * 2.3e-16;
            assert!((ours - libm).abs() <= allowed, "v = {v}: {ours} vs {libm}");
            if v.abs() < 1.0 {
                worst_small = worst_small.max((ours - libm).abs());
            }
        }
        assert!(worst_small < 1e-15, "{worst_small}");
        for k in [-1000.0, -3.0, -1.0, 0.0, 1.0, 2.0, 7.0, 599.0] {
            assert_eq!(cos_2pi(k), 1.0, "{k}");
            assert_eq!(cos_2pi(k + 0.5), -1.0, "{k}");
            assert!(cos_2pi(k + 0.25).abs() < 1e-16, "{k}");
        }
        assert_eq!(cos_2pi(1e300), (std::f64::consts::TAU * 1e300).cos());
        assert!(cos_2pi(f64::NAN).is_nan() && cos_2pi(f64::INFINITY).is_nan());
        assert_eq!(Function::Rastrigin.value(&[0.0; 30]), 0.0);
        assert_eq!(Function::Rastrigin.value(&[1.0, -2.0, 3.0]), 14.0);
    }

    use super::*;

    fn close(a: f64, b: f64, tol: f64) -> bool {
        (a - b).abs() <= tol * (1.0 + b.abs())
    }

    #[test]
    fn ids_round_trip() {
        for f in Function::ALL {
            assert_eq!(Function::from_id(f.id()), Some(f));
            assert_eq!(serde_json::to_string(&f).unwrap(), format!("\"{}\"", f.id()));
        }
        assert_eq!(Function::from_id("Sphere"), None);
        assert_eq!(Function::from_id("schwefel"), None);
    }

    #[test]
    fn optimum_point_gives_optimum() {
        for f in Function::ALL {
            for dim in [2usize, 6, 10, 30] {
                if f.fixed_dim().is_some_and(|d| d != dim) {
                    continue;
                }
                let x = f.optimum_point(dim);
                assert_eq!(x.len(), dim);
                let v = f.value(&x);
                assert!(close(v, f.optimum(dim), 1e-12), "{f} D={dim}: f(x*) = {v}, expected {}", f.optimum(dim));
            }
        }
    }

    #[test]
    fn trid6_and_easom_known_optima() {
        let x: Vec<f64> = (1..=6).map(|i| (i * (7 - i)) as f64).collect();
        assert_eq!(x, vec![6.0, 10.0, 12.0, 12.0, 10.0, 6.0]);
        assert_eq!(Function::Trid.value(&x), -50.0);
        assert_eq!(Function::Trid.optimum(6), -50.0);
        assert!(close(Function::Easom.value(&[PI, PI]), -1.0, 1e-15));
        // Easom generalisation keeps -1 at (pi, ..., pi) in odd dimensions too.
        assert!(close(Function::Easom.value(&[PI, PI, PI]), -1.0, 1e-15));
    }

    #[test]
    fn hand_computed_values() {
        let x = [1.0, 2.0];
        // Sphere: 1 + 4.
        assert_eq!(Function::Sphere.value(&x), 5.0);
        // Rosenbrock: 100 (2 - 1)^2 + 0^2.
        assert_eq!(Function::Rosenbrock.value(&x), 100.0);
        assert_eq!(Function::Rosenbrock.value(&[0.0, 0.0, 0.0]), 2.0);
        // Rastrigin at integers: cos(2 pi k) = 1, so sum x_i^2.
        assert!(close(Function::Rastrigin.value(&x), 5.0, 1e-12));
        assert!(close(Function::Rastrigin.value(&[0.5]), 20.25, 1e-12));
        // Griewank: 1 + 5/4000 - cos(1) cos(2/sqrt 2).
        let g = 1.0 + 5.0 / 4000.0 - 1f64.cos() * (2.0 / 2f64.sqrt()).cos();
        assert!(close(Function::Griewank.value(&x), g, 1e-14));
        // Ackley at (1, 1): mean x^2 = 1, mean cos = 1: -20 e^-0.2 - e + 20 + e.
        assert!(close(Function::Ackley.value(&[1.0, 1.0]), 20.0 - 20.0 * (-0.2f64).exp(), 1e-13));
        // Zakharov: 5 + s^2 + s^4 with s = 0.5 * 1 + 0.5 * 2 * 2 = 2.5.
        assert!(close(Function::Zakharov.value(&x), 5.0 + 6.25 + 39.0625, 1e-14));
        // Easom at (0, 0): -exp(-2 pi^2).
        assert!(close(Function::Easom.value(&[0.0, 0.0]), -(-2.0 * PI * PI).exp(), 1e-14));
        // Trid at (1, 2): 0 + 1 - 2.
        assert_eq!(Function::Trid.value(&x), -1.0);
        // Quadric at (1, 2, 3): 1 + 9 + 36.
        assert_eq!(Function::Quadric.value(&[1.0, 2.0, 3.0]), 46.0);
    }

    #[test]
    fn ranges_match_the_papers() {
        assert_eq!(Function::Ackley.small_range(), Some((-2.768, 2.768)));
        assert_eq!(Function::Ackley.wide_range(), Some((-23.768, 23.768)));
        assert_eq!(Function::Ackley.default_range(30), (-32.768, 32.768));
        assert!(Function::Ackley.amfa2015_range_note().is_some());
        assert_eq!(Function::Zakharov.wide_range(), Some((-50.0, 100.0)));
        assert_eq!(Function::Griewank.small_range(), Some((-8.0, 8.0)));
        assert_eq!(Function::Trid.default_range(6), (-36.0, 36.0));
        assert_eq!(Function::Trid.wpa2017_setting(), Some((6, -36.0, 36.0)));
        assert_eq!(Function::Quadric.wpa2017_setting(), Some((120, -30.0, 30.0)));
        assert_eq!(Function::Zakharov.wpa2017_setting(), None);
        assert_eq!(Function::Easom.small_range(), None);
        for f in Function::ALL {
            if let Some((d, lo, hi)) = f.wpa2017_setting() {
                let x = f.optimum_point(d);
                assert!(x.iter().all(|v| (lo..=hi).contains(v)), "{f}: optimum outside wpa2017 box");
            }
        }
    }

    #[test]
    fn objective_wraps_function() {
        let obj = FunctionObjective::with_default_range(Function::Trid, 6);
        assert_eq!(obj.dim(), 6);
        assert_eq!(obj.lower(), &[-36.0; 6]);
        assert!(!obj.parallel_hint());
        let mut s = Scratch::default();
        assert_eq!(obj.evaluate(&Function::Trid.optimum_point(6), &mut s), -50.0);
        let mut x = vec![100.0, -100.0, 0.0, 0.0, 0.0, 0.0];
        obj.repair(&mut x);
        assert_eq!(&x[..2], &[36.0, -36.0]);
    }
}
