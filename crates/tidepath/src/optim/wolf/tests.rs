use super::*;
use crate::optim::functions::{Function, FunctionObjective};
use crate::optim::mwpa::{Mwpa, MwpaParams};
use crate::optim::wpa::{Wpa, WpaParams};
use crate::optim::{run, Objective, Optimizer, RunResult, Scratch, StopReason};
use crate::termination::Termination;
use std::sync::atomic::{AtomicBool, AtomicU64, Ordering};
use std::sync::Arc;

/// (x - 0.2)^2 + (y - 0.2)^2 on [0, 1]^2, feasible only where x >= 0.5: the unconstrained
/// optimum is infeasible.
struct HalfPlane;

impl Objective for HalfPlane {
    fn dim(&self) -> usize {
        2
    }
    fn lower(&self) -> &[f64] {
        &[0.0, 0.0]
    }
    fn upper(&self) -> &[f64] {
        &[1.0, 1.0]
    }
    fn evaluate(&self, x: &[f64], _: &mut Scratch) -> f64 {
        (x[0] - 0.2).powi(2) + (x[1] - 0.2).powi(2)
    }
    fn feasible(&self, x: &[f64], _: &mut Scratch) -> Option<bool> {
        Some(x[0] >= 0.5)
    }
}

fn pack(replace_infeasible: bool) -> Pack {
    let settings = Settings {
        population: 4,
        t_max: 1,
        omega: 50.0,
        step_a: 0.01,
        step_b: 0.02,
        step_c: 0.005,
        alpha: 4.0,
        beta: 5.0,
        h: 4,
    };
    Pack::new(settings, Variant { interactive: true, adaptive: None, decay: Some(0.99), replace_infeasible })
}

/// Puts wolves at `rows` and evaluates them, as `init` would have.
fn place(p: &mut Pack, ctx: &mut Context<'_>, rows: &[[f64; 2]]) {
    p.init(ctx);
    for (i, r) in rows.iter().enumerate() {
        p.x.row_mut(i).copy_from_slice(r);
    }
    ctx.evaluate_population(&p.x, &mut p.cost);
    p.rank();
}

/// x^2 + y^2 on [-10, 10]^2, steps of 1 (step_a, step_b) and 0.5 (step_c) per dimension,
/// d_near = 20 / 20 = 1; wolves: the lead at (0.1, 0), then (2, 2), (5, 5), (-6, 6).
fn sphere_pack(ctx: &mut Context<'_>, variant: Variant) -> Pack {
    let settings = Settings {
        population: 4,
        t_max: 10,
        omega: 20.0,
        step_a: 0.05,
        step_b: 0.05,
        step_c: 0.025,
        alpha: 3.0,
        beta: 2.0,
        h: 4,
    };
    let mut p = Pack::new(settings, variant);
    place(&mut p, ctx, &[[0.1, 0.0], [2.0, 2.0], [5.0, 5.0], [-6.0, 6.0]]);
    p
}

const WPA: Variant = Variant { interactive: false, adaptive: None, decay: None, replace_infeasible: false };

#[test]
fn scouting_moves_a_scout_to_its_best_direction_until_it_beats_the_lead() {
    let f = FunctionObjective::new(Function::Sphere, 2, -10.0, 10.0);
    let mut rng = crate::rng::run_rng(1, 0);
    let mut ctx = Context::new(&f, &mut rng, None, false, &[]);
    let mut p = sphere_pack(&mut ctx, WPA);
    assert_eq!((scout_count(4, 3.0, 0.5), p.lead, p.order[1]), (1, 0, 1));
    let before = ctx.evaluations();
    assert!(p.scout(&mut ctx, 1));
    // Round 1 from (2, 2): x + sin(2 pi p/4) for p = 1, 3 (p = 2, 4 leave it where it is and
    // are not evaluated) = (3, 3) 18, (1, 1) 2: to (1, 1). Round 2: (2, 2) 8, (0, 0) 0:
    // (0, 0) beats the lead (0.01) and scouting ends: 4 evaluations.
    assert_eq!(ctx.evaluations() - before, 4);
    assert_eq!(p.x.row(1), &[0.0, 0.0]);
    assert_eq!((p.cost[1], p.lead), (0.0, 1));
    // The others did not move.
    assert_eq!([p.x.row(2), p.x.row(3)], [&[5.0, 5.0][..], &[-6.0, 6.0][..]]);
}

#[test]
fn only_directions_that_move_a_wolf_are_tried() {
    assert_eq!(moving_directions(4), [1, 3]);
    assert_eq!(moving_directions(6), [1, 2, 4, 5]);
    assert_eq!(moving_directions(3), [1, 2]);
    assert!(moving_directions(1).is_empty() && moving_directions(2).is_empty());
    // With no moving direction and no interactive candidate, scouting costs nothing.
    let f = FunctionObjective::new(Function::Sphere, 2, -10.0, 10.0);
    let mut rng = crate::rng::run_rng(1, 0);
    let mut ctx = Context::new(&f, &mut rng, None, false, &[]);
    let mut p = sphere_pack(&mut ctx, WPA);
    p.settings.h = 2;
    p.init(&mut ctx);
    let before = ctx.evaluations();
    assert!(p.scout(&mut ctx, 1));
    assert_eq!(ctx.evaluations(), before);
}

#[test]
fn calling_raids_each_ferocious_wolf_to_d_near_or_past_the_lead() {
    let f = FunctionObjective::new(Function::Sphere, 2, -10.0, 10.0);
    let mut rng = crate::rng::run_rng(1, 0);
    let mut ctx = Context::new(&f, &mut rng, None, false, &[]);
    let mut p = sphere_pack(&mut ctx, WPA);
    let before = ctx.evaluations();
    assert!(p.call(&mut ctx, 1));
    // (5, 5) raids by 1 per dimension to (1, 1): mean distance to (0.1, 0) 0.95 <= d_near.
    assert_eq!(p.x.row(2), &[1.0, 1.0]);
    // (-6, 6) raids to (-1, 1) (distance 1.05) and on to (0, 0), which beats the lead.
    assert_eq!(p.x.row(3), &[0.0, 0.0]);
    assert_eq!((p.lead, p.cost[3]), (3, 0.0));
    assert_eq!(ctx.evaluations() - before, 4 + 6);
    // T_max caps the raids of a phase: one raid each.
    let mut rng = crate::rng::run_rng(1, 0);
    let mut ctx = Context::new(&f, &mut rng, None, false, &[]);
    let mut p = sphere_pack(&mut ctx, WPA);
    p.settings.t_max = 1;
    p.call(&mut ctx, 1);
    assert_eq!([p.x.row(2), p.x.row(3)], [&[4.0, 4.0][..], &[-5.0, 5.0][..]]);
}

#[test]
fn the_siege_moves_each_wolf_along_one_scaled_step_and_keeps_only_improvements() {
    let f = FunctionObjective::new(Function::Sphere, 2, -10.0, 10.0);
    let mut rng = crate::rng::run_rng(3, 0);
    let mut ctx = Context::new(&f, &mut rng, None, false, &[]);
    let mwpa = Variant { decay: Some(0.9), ..WPA };
    let mut p = sphere_pack(&mut ctx, mwpa);
    let (x0, c0) = (p.x.clone(), p.cost.clone());
    p.besiege(&mut ctx);
    assert_eq!(p.xi, 0.9);
    assert_eq!(p.x.row(0), x0.row(0), "the lead does not move");
    let mut moved = 0;
    for (i, &c) in c0.iter().enumerate().skip(1) {
        let (old, new) = (x0.row(i), p.x.row(i));
        if old == new {
            continue;
        }
        moved += 1;
        assert!(p.cost[i] < c);
        // x' = x + xi lambda step_c |G - x| with one lambda in [-1, 1] for both dimensions.
        let lambdas: Vec<f64> =
            (0..2).map(|d| (new[d] - old[d]) / (0.9 * 0.5 * (x0.row(0)[d] - old[d]).abs())).collect();
        assert!((lambdas[0] - lambdas[1]).abs() < 1e-12 && lambdas[0].abs() <= 1.0, "{lambdas:?}");
    }
    assert!(moved > 0, "with these draws some wolf improves");
}

#[test]
fn renewal_replaces_only_the_worst_wolves() {
    let f = FunctionObjective::new(Function::Sphere, 2, -10.0, 10.0);
    for seed in 0..20 {
        let mut rng = crate::rng::run_rng(seed, 0);
        let mut ctx = Context::new(&f, &mut rng, None, false, &[]);
        let mut p = sphere_pack(&mut ctx, WPA);
        let x0 = p.x.clone();
        let before = ctx.evaluations();
        p.renew(&mut ctx);
        let renewed: Vec<usize> = (0..4).filter(|&i| p.x.row(i) != x0.row(i)).collect();
        // N = 4, beta = 2: R in [1, 2]; the two worst are (-6, 6) and (5, 5).
        assert!(matches!(renewed.as_slice(), [3] | [2, 3]), "seed {seed}: {renewed:?}");
        assert_eq!(ctx.evaluations() - before, renewed.len() as u64);
        for &i in &renewed {
            assert_eq!(p.cost[i], p.x.row(i).iter().map(|v| v * v).sum::<f64>());
        }
    }
}

#[test]
fn step_7_copies_the_best_feasible_wolf_over_infeasible_ones() {
    let mut rng = crate::rng::run_rng(1, 0);
    let mut ctx = Context::new(&HalfPlane, &mut rng, None, false, &[]);
    let mut p = pack(true);
    // Costs 0.0 (infeasible, the lead), 0.41 (feasible: 0.09 + 0.32), 0.25 (feasible:
    // 0.25 + 0), 0.68 (infeasible: 0.04 + 0.64).
    let rows = [[0.2, 0.2], [0.5, 0.2 + 0.32f64.sqrt()], [0.7, 0.2], [0.0, 1.0]];
    place(&mut p, &mut ctx, &rows);
    let before = ctx.evaluations();
    p.replace_infeasible(&mut ctx);
    // Four checks, each counted.
    assert_eq!(ctx.evaluations(), before + 4);
    let x: Vec<Vec<f64>> = p.x.rows().map(|r| r.to_vec()).collect();
    assert_eq!(x, vec![vec![0.7, 0.2], rows[1].to_vec(), vec![0.7, 0.2], vec![0.7, 0.2]]);
    assert!((p.cost[0] - 0.25).abs() < 1e-15 && p.cost[3] == p.cost[2], "{:?}", p.cost);
    assert_eq!(p.lead, 0, "ties go to the lower index");
    // Nothing moved: no wolf is checked again.
    p.replace_infeasible(&mut ctx);
    assert_eq!(ctx.evaluations(), before + 4);
    // One wolf moves: only it is checked.
    p.x.row_mut(1)[0] = 0.1;
    p.replace_infeasible(&mut ctx);
    assert_eq!(ctx.evaluations(), before + 5);
    assert_eq!(p.x.row(1), &[0.7, 0.2]);
}

#[test]
fn step_7_leaves_the_pack_alone_without_a_feasible_wolf_or_constraints() {
    let mut rng = crate::rng::run_rng(1, 0);
    let mut ctx = Context::new(&HalfPlane, &mut rng, None, false, &[]);
    let mut p = pack(true);
    let rows = [[0.2, 0.2], [0.1, 0.9], [0.3, 0.3], [0.0, 1.0]];
    place(&mut p, &mut ctx, &rows);
    p.replace_infeasible(&mut ctx);
    let x: Vec<Vec<f64>> = p.x.rows().map(|r| r.to_vec()).collect();
    assert_eq!(x, rows.iter().map(|r| r.to_vec()).collect::<Vec<_>>());
    // A benchmark function reports no feasibility: no check is made or counted.
    let f = FunctionObjective::new(Function::Sphere, 2, 0.0, 1.0);
    let mut rng = crate::rng::run_rng(1, 0);
    let mut ctx = Context::new(&f, &mut rng, None, false, &[]);
    let mut p = pack(true);
    place(&mut p, &mut ctx, &rows);
    let before = ctx.evaluations();
    p.replace_infeasible(&mut ctx);
    assert_eq!(ctx.evaluations(), before);
}

#[test]
fn step_7_runs_in_mwpa_only_and_keeps_the_run_feasible() {
    // A whole run: with Step 7 every wolf ends feasible once one is; without it (WPA's
    // skeleton) the pack keeps infeasible wolves that beat every feasible one.
    for (replace, all_feasible) in [(true, true), (false, false)] {
        let mut rng = crate::rng::run_rng(7, 0);
        let mut ctx = Context::new(&HalfPlane, &mut rng, Some(5_000), false, &[]);
        let mut p = pack(replace);
        p.settings.population = 20;
        p.init(&mut ctx);
        for _ in 0..10 {
            p.step(&mut ctx);
        }
        let feasible = p.x.rows().all(|r| r[0] >= 0.5);
        assert_eq!(feasible, all_feasible, "replace_infeasible = {replace}");
    }
}

fn close(a: &[f64], b: &[f64]) {
    assert_eq!(a.len(), b.len());
    for (x, y) in a.iter().zip(b) {
        assert!((x - y).abs() < 1e-12, "{a:?} != {b:?}");
    }
}

#[test]
fn operators_match_hand_computed_values() {
    // A 2-D box [0, 10] x [-5, 5]; a wolf at (2, 1), the lead at (4, -1).
    let (x, g) = ([2.0, 1.0], [4.0, -1.0]);
    let step_a = [0.5, 0.25];
    let mut out = [0.0; 2];
    // h = 4: sin(pi/2) = 1, sin(pi) = 0, sin(3 pi/2) = -1, sin(2 pi) = 0.
    direction(&x, &step_a, 1, 4, &mut out);
    close(&out, &[2.5, 1.25]);
    direction(&x, &step_a, 2, 4, &mut out);
    close(&out, &[2.0, 1.0]);
    direction(&x, &step_a, 3, 4, &mut out);
    close(&out, &[1.5, 0.75]);
    // h = 6, p = 1: sin(pi/3) = 0.8660...
    direction(&x, &step_a, 1, 6, &mut out);
    close(&out, &[2.0 + 0.5 * 3f64.sqrt() / 2.0, 1.0 + 0.25 * 3f64.sqrt() / 2.0]);
    // Eq. 23 with phi = (0.5, 0.25), varphi = (-1, 0.5), partners (3, 3) and (1, 5).
    interactive(&x, &g, &[3.0, 3.0], &[1.0, 5.0], &[0.5, 0.25], &[-1.0, 0.5], &mut out);
    close(&out, &[2.0 + 1.0 - 2.0, 1.0 - 0.5 - 1.0]);
    // One raid with step (0.4, 0.2): towards the lead in each dimension; 0 difference stays.
    let mut y = x;
    raid(&mut y, &g, &[0.4, 0.2]);
    close(&y, &[2.4, 0.8]);
    let mut z = [4.0, 0.0];
    raid(&mut z, &g, &[0.4, 0.2]);
    close(&z, &[4.0, -0.2]);
    // One siege move with lambda = -0.5, step_c = (0.1, 0.2): |G - x| = (2, 2).
    siege(&x, &g, &[0.1, 0.2], -0.5, &mut out);
    close(&out, &[1.9, 0.8]);
    // MWPA with xi = 0.99^2 and the same lambda.
    siege(&x, &g, &[0.1, 0.2], 0.99 * 0.99 * -0.5, &mut out);
    close(&out, &[2.0 - 0.09801, 1.0 - 0.19602]);
    // d_near = (10 + 10) / (2 * 50) = 0.2; the distance is the mean absolute difference.
    assert!((d_near(&[0.0, -5.0], &[10.0, 5.0], 50.0) - 0.2).abs() < 1e-15);
    assert_eq!(distance(&x, &g), 2.0);
    // Adaptive weight: F_min = 1, F_avg = 5, w in [0.4, 1].
    assert!((adaptive_weight(3.0, 1.0, 5.0, 0.4, 1.0) - 0.7).abs() < 1e-15);
    assert_eq!(adaptive_weight(1.0, 1.0, 5.0, 0.4, 1.0), 0.4);
    assert_eq!(adaptive_weight(5.0, 1.0, 5.0, 0.4, 1.0), 1.0);
    assert_eq!(adaptive_weight(9.0, 1.0, 5.0, 0.4, 1.0), 1.0);
    assert_eq!(adaptive_weight(2.0, 2.0, 2.0, 0.4, 1.0), 0.4);
    // Counts: N = 300, alpha = 4: T in [60, 75]; beta = 5: R in [30, 60].
    assert_eq!((scout_count(300, 4.0, 0.0), scout_count(300, 4.0, 0.999_999)), (60, 75));
    assert_eq!((renewal_count(300, 5.0, 0.0), renewal_count(300, 5.0, 0.999_999)), (30, 60));
    assert_eq!(scout_count(4, 1.0, 0.999), 3);
}

/// Sphere that raises a stop flag once it has been evaluated `after` times.
pub(crate) struct StopAfter {
    pub inner: FunctionObjective,
    pub count: AtomicU64,
    pub after: u64,
    pub flag: Arc<AtomicBool>,
}

impl Objective for StopAfter {
    fn dim(&self) -> usize {
        self.inner.dim()
    }
    fn lower(&self) -> &[f64] {
        self.inner.lower()
    }
    fn upper(&self) -> &[f64] {
        self.inner.upper()
    }
    fn evaluate(&self, x: &[f64], s: &mut Scratch) -> f64 {
        if self.count.fetch_add(1, Ordering::Relaxed) + 1 >= self.after {
            self.flag.store(true, Ordering::Relaxed);
        }
        self.inner.evaluate(x, s)
    }
}

/// A wolf pack built from the registry's parameters: `mwpa` (with `compound`), else `wpa`,
/// with the benchmark preset's settings and `population` wolves.
fn pack_optimizer(mwpa: bool, compound: bool, population: Option<usize>) -> Box<dyn Optimizer> {
    if mwpa {
        let p = MwpaParams { compound_raid_step: compound, ..MwpaParams::wpa2017() };
        let p = MwpaParams { population: population.unwrap_or(p.population), ..p };
        Box::new(Mwpa::new(p.checked("t").unwrap()))
    } else {
        let p = WpaParams::wpa2017();
        let p = WpaParams { population: population.unwrap_or(p.population), ..p };
        Box::new(Wpa::new(p.checked("t").unwrap()))
    }
}

fn sphere_run(
    o: &mut dyn Optimizer,
    obj: &FunctionObjective,
    evaluations: u64,
    seed: u64,
    parallel: bool,
) -> RunResult {
    run(o, obj, &Termination::evaluations(evaluations), &mut crate::rng::run_rng(seed, 0), parallel, &[], &mut |_| {})
}

#[test]
fn both_packs_reduce_sphere_and_repeat_bit_for_bit_on_any_thread_count() {
    let obj = FunctionObjective::new(Function::Sphere, 5, -5.12, 5.12);
    for mwpa in [false, true] {
        let r = sphere_run(&mut *pack_optimizer(mwpa, false, Some(40)), &obj, 30_000, 1, false);
        assert!(r.best_cost < r.history[0] * 1e-3, "mwpa {mwpa}: {} from {}", r.best_cost, r.history[0]);
        assert!(r.best_x.iter().all(|v| (-5.12..=5.12).contains(v)));
        let again = sphere_run(&mut *pack_optimizer(mwpa, false, Some(40)), &obj, 30_000, 1, false);
        assert_eq!((&r.best_x, &r.history), (&again.best_x, &again.history));
        // 1 and 4 rayon threads, parallel evaluation.
        let runs: Vec<_> = [1, 4]
            .iter()
            .map(|&t| {
                let pool = rayon::ThreadPoolBuilder::new().num_threads(t).build().unwrap();
                pool.install(|| sphere_run(&mut *pack_optimizer(mwpa, false, Some(40)), &obj, 5_001, 3, true))
            })
            .collect();
        assert_eq!((&runs[0].best_x, &runs[0].history), (&runs[1].best_x, &runs[1].history));
    }
}

#[test]
fn evaluation_limit_and_stop_flag_are_honoured_inside_a_generation() {
    let obj = FunctionObjective::new(Function::Sphere, 4, -5.0, 5.0);
    // The path defaults: 300 wolves, T_max = 30.
    let path = |mwpa: bool, compound: bool| -> Box<dyn Optimizer> {
        if mwpa {
            Box::new(Mwpa::new(
                MwpaParams { compound_raid_step: compound, ..MwpaParams::default() }.checked("t").unwrap(),
            ))
        } else {
            Box::new(Wpa::new(WpaParams::default().checked("t").unwrap()))
        }
    };
    for (mwpa, compound) in [(false, false), (true, false), (true, true)] {
        for limit in [1u64, 37, 301, 2_345] {
            let r = sphere_run(&mut *path(mwpa, compound), &obj, limit, 2, false);
            assert_eq!(r.evaluations, limit, "mwpa {mwpa}, compound {compound}");
        }
        // Stop raised during the first iteration's scouting (300 initial evaluations), and
        // during its calling phase: the run ends within one scouting candidate set / one raid.
        for after in [320u64, 2_000] {
            let flag = Arc::new(AtomicBool::new(false));
            let obj = StopAfter { inner: obj.clone(), count: AtomicU64::new(0), after, flag: flag.clone() };
            let term = Termination::iterations(1_000).with_stop_flag(flag);
            let r =
                run(&mut *path(mwpa, compound), &obj, &term, &mut crate::rng::run_rng(2, 0), false, &[], &mut |_| {});
            assert_eq!(r.stop_reason, StopReason::Cancelled);
            assert!(r.iterations <= 1, "{}", r.iterations);
            assert!(r.evaluations <= after + 3, "{} evaluations after a stop at {after}", r.evaluations);
        }
    }
}
