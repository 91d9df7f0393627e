//! The ants' heuristic information η_ij for the move s_i -> s_j (acopf2016 eqs. 7-10), and the
//! classic 1/L(s_j, goal) of the basic ant colony.
//!
//! acopf (eq. 10):
//!
//! ```text
//! η_ij = (e^{cos θ_art(s_j)})^ς · (1/L(s_j, goal))^σ · (e^{a sin X_wht(s_j) + b X_hfr(s_j) cos θ_hfr(s_j)})^ω
//! ```
//!
//! with θ_art the angle between the move and the potential-field force at s_j (eqs. 7-8):
//! F = F_att + F_rep, F_att of magnitude ξ (L_g + 1/L_g) (printed; Khatib's ξ L_g as an option)
//! toward the goal, F_rep = Σ over blocked cells within L_0 of μ/L_n² (1/L_n − 1/L_0) away from
//! each. Distances are in cells (the paper's grid has edge 1). The roulette uses η^β, so the
//! tables below hold exp(β ln η).

use super::colony::Graph;
use crate::geom::{Vec2, Vec3};
use crate::params::Word;
use crate::world::World;

/// The attraction's magnitude (eq. 8): as printed, or Khatib's usual one.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Attraction {
    /// ξ (L_g + 1/L_g), as acopf2016 prints it.
    Printed,
    /// ξ L_g (Khatib 1986).
    Khatib,
}

impl Word for Attraction {
    const WORDS: &'static [(&'static str, Self)] = &[("printed", Attraction::Printed), ("khatib", Attraction::Khatib)];
}

crate::params::word_param!(Attraction);

/// acopf's potential field and environment settings (eqs. 8 and 10).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Field {
    pub xi: f64,
    pub mu: f64,
    /// L_0, in cells.
    pub l0: f64,
    pub varsigma: f64,
    pub sigma: f64,
    pub omega: f64,
    /// The wave and current coefficients a and b of eq. 10.
    pub a: f64,
    pub b: f64,
    pub attraction: Attraction,
}

/// |F_att| at `lg` cells from the goal (eq. 8).
pub fn attraction(xi: f64, lg: f64, form: Attraction) -> f64 {
    match form {
        Attraction::Printed => xi * (lg + 1.0 / lg),
        Attraction::Khatib => xi * lg,
    }
}

/// |F_rep| of one blocked cell `ln` cells away (eq. 8): zero beyond `l0`.
pub fn repulsion(mu: f64, ln: f64, l0: f64) -> f64 {
    if ln > 0.0 && ln <= l0 {
        mu / (ln * ln) * (1.0 / ln - 1.0 / l0)
    } else {
        0.0
    }
}

/// cos of the angle between `u` and `v`; 0 (a right angle, e^0 = 1 in eq. 10) when either is
/// zero.
pub fn cos_between(u: Vec2, v: Vec2) -> f64 {
    let l = u.length() * v.length();
    if l > 0.0 && l.is_finite() {
        (u.dot(v) / l).clamp(-1.0, 1.0)
    } else {
        0.0
    }
}

/// The environment exponent of eq. 10: a sin(X_wht) + b X_hfr cos θ_hfr.
pub fn environment(a: f64, b: f64, x_wht: f64, x_hfr: f64, cos_hfr: f64) -> f64 {
    a * x_wht.sin() + b * x_hfr * cos_hfr
}

/// ln η_ij of eq. 10 from cos θ_art, L (cells) and the environment exponent.
pub fn ln_eta(f: &Field, cos_art: f64, l: f64, env: f64) -> f64 {
    f.varsigma * cos_art - f.sigma * l.ln() + f.omega * env
}

/// The distance L(s_j, goal) in cells used by 1/L: half a cell at the goal (acopf2016 A13),
/// never less elsewhere.
pub fn goal_distance(at: Vec2, goal: Vec2, unit: f64, is_goal: bool) -> f64 {
    if is_goal {
        0.5
    } else {
        (at.distance(goal) / unit).max(0.5)
    }
}

/// The wave and current at a point, normalised by their maxima (acopf2016 A6): X_wht in
/// [0, 1], X_hfr in [0, 1] and the current's direction.
#[derive(Clone, Copy, Debug)]
pub struct Environment<'w> {
    pub world: &'w World,
    /// Largest wave height and current speed (0: the factor is 0).
    pub wave_max: f64,
    pub current_max: f64,
    pub a: f64,
    pub b: f64,
}

impl Environment<'_> {
    /// X_wht and the current (normalised so that |X| = X_hfr) at `p`, time `t`.
    #[inline]
    pub fn sample(&self, p: Vec3, t: f64) -> (f64, Vec2) {
        let h = self.world.waves.height(p, t);
        let x_wht = if self.wave_max > 0.0 && h.is_finite() { (h / self.wave_max).clamp(0.0, 1.0) } else { 0.0 };
        let c = self.world.current.velocity(p, t).truncate();
        let s = c.length();
        let x_hfr = if self.current_max > 0.0 && s.is_finite() && s > 0.0 {
            c * ((s / self.current_max).min(1.0) / s)
        } else {
            Vec2::ZERO
        };
        (x_wht, x_hfr)
    }

    /// The exponent of eq. 10 for a sample and the move `mv`.
    #[inline]
    pub fn exponent(&self, (x_wht, x_hfr): (f64, Vec2), mv: Vec2) -> f64 {
        environment(self.a, self.b, x_wht, x_hfr.length(), cos_between(x_hfr, mv))
    }
}

/// The potential-field force at a point `at` (in cells) toward `goal` (in cells), with the
/// repulsion `rep` already summed; `toward` is the attraction's direction where `at` is the
/// goal itself (the move into it).
pub fn force(f: &Field, at: Vec2, goal: Vec2, is_goal: bool, toward: Vec2, rep: Vec2) -> Vec2 {
    let (lg, dir) = if is_goal { (0.5, toward) } else { (at.distance(goal).max(0.5), goal - at) };
    let n = dir.length();
    let unit = if n > 0.0 { dir / n } else { Vec2::ZERO };
    unit * attraction(f.xi, lg, f.attraction) + rep
}

/// The summed repulsion at `at` (cells) from the blocked cells whose centres are `obstacles`
/// (cells): each pushes away from itself with [`repulsion`].
pub fn repulsion_at(f: &Field, at: Vec2, obstacles: impl Iterator<Item = Vec2>) -> Vec2 {
    let mut sum = Vec2::ZERO;
    for o in obstacles {
        let d = at - o;
        let ln = d.length();
        let m = repulsion(f.mu, ln, f.l0);
        if m > 0.0 {
            sum += d / ln * m;
        }
    }
    sum
}

/// η_e^β for every directed edge e = `8 i + d` of `g` (0 off the graph): the basic colony's
/// (1/L)^β when `field` is `None`, else eq. 10's, with its environment factor sampled at time
/// `t` when `env` is given (a world that does not change in time) and left out otherwise (the
/// caller multiplies it in at the ant's clock). `None` when `stop` (polled once per row of
/// cells) asked to stop.
pub fn weights(
    g: &Graph,
    beta: f64,
    field: Option<&Field>,
    env: Option<(&Environment<'_>, f64)>,
    stop: &dyn Fn() -> bool,
) -> Option<Vec<f64>> {
    let unit = g.unit();
    let cells = |p: Vec3| p.truncate() / unit;
    let free = |c: usize| g.masks[c] != 0 || c == g.goal;
    // Per cell: the summed repulsion (in cells) and the environment sample.
    let rep = match field {
        Some(f) => {
            let r = (f.l0 * unit / g.dx.min(g.dy)).ceil() as isize;
            let mut rep = vec![Vec2::ZERO; g.len()];
            for (c, out) in rep.iter_mut().enumerate() {
                if c % g.nx == 0 && stop() {
                    return None;
                }
                if !free(c) {
                    continue;
                }
                let (i, j) = ((c % g.nx) as isize, (c / g.nx) as isize);
                let window = (-r..=r).flat_map(|dj| (-r..=r).map(move |di| (i + di, j + dj)));
                let blocked = window
                    .filter(|&(a, b)| a >= 0 && b >= 0 && (a as usize) < g.nx && (b as usize) < g.ny)
                    .map(|(a, b)| a as usize + g.nx * b as usize)
                    .filter(|&o| g.blocked[o])
                    .map(|o| cells(g.centre(o)));
                *out = repulsion_at(f, cells(g.point(c)), blocked);
            }
            rep
        }
        None => Vec::new(),
    };
    let samples = match env {
        Some((e, t)) => {
            let mut s = vec![(0.0, Vec2::ZERO); g.len()];
            for (c, out) in s.iter_mut().enumerate() {
                if c % g.nx == 0 && stop() {
                    return None;
                }
                if free(c) {
                    *out = e.sample(g.point(c), t);
                }
            }
            s
        }
        None => Vec::new(),
    };
    let goal = cells(g.goal_point);
    let mut w = vec![0.0; 8 * g.len()];
    for i in 0..g.len() {
        if i % g.nx == 0 && stop() {
            return None;
        }
        for d in 0..8 {
            if g.masks[i] & (1 << d) == 0 {
                continue;
            }
            let j = g.neighbour(i, d);
            let (pi, pj) = (cells(g.point(i)), cells(g.point(j)));
            let mv = pj - pi;
            let at_goal = j == g.goal;
            let l = goal_distance(pj, goal, 1.0, at_goal);
            let ln = match field {
                None => -l.ln(),
                Some(f) => {
                    let cos_art = cos_between(force(f, pj, goal, at_goal, mv, rep[j]), mv);
                    let x = match env {
                        Some((e, _)) => e.exponent(samples[j], mv),
                        None => 0.0,
                    };
                    ln_eta(f, cos_art, l, x)
                }
            };
            w[8 * i + d] = (beta * ln).exp();
        }
    }
    Some(w)
}
