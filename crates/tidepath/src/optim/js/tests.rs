//! JS's unit tests: parameters, each motion by hand, one iteration replayed from the same
//! random numbers, runs.

use super::*;
use crate::optim::functions::{Function, FunctionObjective};
use crate::optim::{run, test_support};
use crate::rng::run_rng;
use crate::termination::Termination;

fn js(p: JsParams) -> Js {
    Js::new(p.checked("t").unwrap())
}

/// Equal to 1e-12, coordinate by coordinate.
fn close(a: &[f64], b: &[f64]) -> bool {
    a.len() == b.len() && a.iter().zip(b).all(|(x, y)| (x - y).abs() < 1e-12)
}

#[test]
fn defaults_are_the_papers() {
    let p = JsParams::default();
    assert_eq!((p.population, p.beta, p.gamma, p.c0), (50, 3.0, 0.1, 0.5));
    assert!(p.clone().checked("p").is_ok());
    let q = JsParams::from_table(&toml::from_str("population = 45\nbeta = 2.5").unwrap(), "p").unwrap();
    assert_eq!(*q.get(), JsParams { population: 45, beta: 2.5, ..JsParams::default() });
    assert_eq!(*JsParams::from_table(&p.to_table(), "p").unwrap().get(), p);
    for bad in [
        JsParams { population: 1, ..p.clone() },
        JsParams { beta: -1.0, ..p.clone() },
        JsParams { beta: f64::NAN, ..p.clone() },
        JsParams { gamma: f64::INFINITY, ..p.clone() },
        JsParams { c0: 1.5, ..p.clone() },
    ] {
        let e = bad.checked("planner.params.js").unwrap_err().to_string();
        assert!(e.starts_with("planner.params.js."), "{e}");
    }
    assert!(JsParams::from_table(&toml::from_str("delta = 0.1").unwrap(), "p").is_err());
}

#[test]
fn logistic_map_by_hand() {
    assert_eq!(logistic(0.5), 1.0);
    assert_eq!(logistic(0.25), 0.75);
    assert_eq!(logistic(0.75), 0.75); // the fixed point
    assert!((logistic(0.3) - 0.84).abs() < 1e-15);
    // Box [0, 10] x [−1, 1]; x0 = (0.3, 0.9).
    let mut pop = Population::zeros(3, 2);
    logistic_population(&[0.3, 0.9], &[0.0, -1.0], &[10.0, 1.0], &mut pop);
    let want = [[3.0, 0.8], [8.4, -1.0 + 2.0 * 0.36], [10.0 * 0.5376, -1.0 + 2.0 * 0.9216]];
    for (i, w) in want.iter().enumerate() {
        assert!(close(pop.row(i), w), "row {i}: {:?}", pop.row(i));
    }
}

#[test]
fn time_control_and_move_choice_by_hand() {
    // c = |(1 − t/T)(2 rand − 1)|.
    assert!((time_control(0.5, 0.1) - 0.4).abs() < 1e-15);
    assert_eq!(time_control(0.0, 1.0), 1.0);
    assert_eq!(time_control(1.0, 0.9), 0.0);
    assert_eq!(time_control(0.0, 0.5), 0.0);
    // c ≥ C₀: ocean current, whatever r.
    assert_eq!(choose_move(0.5, 0.5, 0.99), JsMove::OceanCurrent);
    assert_eq!(choose_move(0.8, 0.5, 0.0), JsMove::OceanCurrent);
    // c < C₀: passive when r > 1 − c (the original's test, A3), else active.
    assert_eq!(choose_move(0.3, 0.5, 0.71), JsMove::Passive);
    assert_eq!(choose_move(0.3, 0.5, 0.7), JsMove::Active);
    assert_eq!(choose_move(0.3, 0.5, 0.2), JsMove::Active);
    assert_eq!(choose_move(0.0, 0.5, 0.999), JsMove::Active);
}

#[test]
fn motions_by_hand() {
    // Ocean current: x + u ⊙ (x* − βr μ), βr = 3 · 0.5.
    let mut out = [0.0; 2];
    ocean_current(&[1.0, -2.0], &[0.5, 0.5], &[2.0, -1.0], 1.5, &[0.5, 0.25], &mut out);
    assert_eq!(out, [1.0 + 0.5 * (0.5 - 3.0), -2.0 + 0.25 * (0.5 + 1.5)]);
    // Passive: x + γr (ub − lb), γr = 0.1 · 0.5, widths 10 and 2.
    passive(&[1.0, -2.0], 0.05, &[-5.0, -1.0], &[5.0, 1.0], &mut out);
    assert_eq!(out, [1.5, -1.9]);
    // Active: toward a better x_j, away from a worse one.
    active(&[1.0, 1.0], &[3.0, 0.0], true, &[0.5, 0.25], &mut out);
    assert_eq!(out, [2.0, 0.75]);
    active(&[1.0, 1.0], &[3.0, 0.0], false, &[0.5, 0.25], &mut out);
    assert_eq!(out, [0.0, 1.25]);
}

#[test]
fn wrap_around_by_hand() {
    // Box [−1, 3] (width 4).
    assert_eq!(wrap(2.0, -1.0, 3.0), 2.0);
    assert_eq!(wrap(3.0, -1.0, 3.0), 3.0); // on a bound: stays
    assert_eq!(wrap(-1.0, -1.0, 3.0), -1.0);
    assert_eq!(wrap(3.5, -1.0, 3.0), -0.5); // lb + (x − ub)
    assert_eq!(wrap(-2.0, -1.0, 3.0), 2.0); // ub + (x − lb)
    assert_eq!(wrap(7.0, -1.0, 3.0), 3.0); // re-entered once at 3: inside
    assert_eq!(wrap(8.0, -1.0, 3.0), 0.0); // twice: 4, then 0
    assert_eq!(wrap(-9.5, -1.0, 3.0), 2.5); // −9.5 → −5.5 → −1.5 → 2.5
    assert_eq!(wrap(5.0, 2.0, 2.0), 2.0); // degenerate box
    assert_eq!(wrap(f64::INFINITY, -1.0, 3.0), 3.0);
    assert_eq!(wrap(f64::NEG_INFINITY, -1.0, 3.0), -1.0);
    for k in 0..2000 {
        let v = -50.0 + 0.05 * k as f64;
        let w = wrap(v, -1.0, 3.0);
        assert!((-1.0..=3.0).contains(&w), "{v} -> {w}");
        // The same point modulo the width.
        let turns = (w - v) / 4.0;
        assert!((turns - turns.round()).abs() < 1e-9, "{v} -> {w}");
    }
}

#[test]
fn best_index_and_greedy_test() {
    assert_eq!(best_index(&[3.0, f64::NAN, 1.0, 1.0]), 2);
    assert_eq!(best_index(&[f64::NAN, f64::INFINITY]), 0);
    assert!(improves(1.0, 2.0) && !improves(2.0, 2.0) && !improves(3.0, 2.0));
    assert!(improves(5.0, f64::NAN) && !improves(f64::NAN, 5.0) && !improves(f64::NAN, f64::NAN));
}

/// One iteration on three jellyfish, replayed from the same random numbers: every candidate is
/// computed by hand from the start-of-iteration x*, μ and costs, wrapped, evaluated, and kept
/// only if better.
#[test]
fn an_iteration_matches_a_hand_computation() {
    for seed in 0..20 {
        let obj = FunctionObjective::new(Function::Sphere, 2, -1.0, 3.0);
        let mut opt = js(JsParams { population: 3, ..JsParams::default() });
        let mut rng = run_rng(seed, 0);
        let mut ctx = Context::new(&obj, &mut rng, Some(30), false, &[]);
        opt.init(&mut ctx);
        let (x0, cost0) = (opt.x.clone(), opt.cost.clone());
        let mut twin = ctx.rng().clone();
        opt.step(&mut ctx);
        assert_eq!(ctx.evaluations(), 6);
        let frac = 3.0 / 30.0;
        let b = best_index(&cost0);
        let mean: Vec<f64> = (0..2).map(|d| (x0.row(0)[d] + x0.row(1)[d] + x0.row(2)[d]) / 3.0).collect();
        for i in 0..3 {
            let xi = x0.row(i);
            let c = ((1.0 - frac) * (2.0 * twin.random::<f64>() - 1.0)).abs();
            let mut cand = [0.0; 2];
            let mut u = [0.0; 2];
            if c >= 0.5 {
                let r = twin.random::<f64>();
                fill_unit_f64_32(&mut twin, &mut u);
                for d in 0..2 {
                    cand[d] = xi[d] + u[d] * (x0.row(b)[d] - 3.0 * r * mean[d]);
                }
            } else if twin.random::<f64>() > 1.0 - c {
                let r = twin.random::<f64>();
                for d in 0..2 {
                    cand[d] = xi[d] + 0.1 * r * 4.0;
                }
            } else {
                let j = twin.random_range(0..2usize);
                let j = if j >= i { j + 1 } else { j };
                fill_unit_f64_32(&mut twin, &mut u);
                let xj = x0.row(j);
                for d in 0..2 {
                    let step = if cost0[j] < cost0[i] { xj[d] - xi[d] } else { xi[d] - xj[d] };
                    cand[d] = xi[d] + u[d] * step;
                }
            }
            for v in cand.iter_mut() {
                // Wrap into [−1, 3] by hand.
                while *v > 3.0 {
                    *v = -1.0 + (*v - 3.0);
                }
                while *v < -1.0 {
                    *v = 3.0 + (*v + 1.0);
                }
            }
            let f = Function::Sphere.value(&cand);
            let (want_x, want_f) = if f < cost0[i] { (&cand[..], f) } else { (xi, cost0[i]) };
            assert!(close(opt.x.row(i), want_x), "seed {seed} jellyfish {i}");
            assert!((opt.cost[i] - want_f).abs() < 1e-12, "seed {seed} jellyfish {i}");
        }
    }
}

/// The share of passive moves follows c(t): about E[c; c < C₀] of the jellyfish early in a run,
/// none at its end (c = 0 there, so every jellyfish moves actively).
#[test]
fn passive_share_tracks_the_time_control() {
    let mut rng = run_rng(1, 0);
    let share = |frac: f64, rng: &mut crate::rng::Rng| {
        let mut passive = 0;
        for _ in 0..200_000 {
            let c = time_control(frac, rng.random::<f64>());
            let r = if c >= 0.5 { 0.0 } else { rng.random::<f64>() };
            passive += usize::from(choose_move(c, 0.5, r) == JsMove::Passive);
        }
        passive as f64 / 200_000.0
    };
    // At t = 0, c = |2 rand − 1| is uniform on [0, 1]: P(passive) = ∫₀^½ c dc = 1/8.
    assert!((share(0.0, &mut rng) - 0.125).abs() < 0.003);
    // At t/T = 0.9, c is uniform on [0, 0.1]: P(passive) = E[c] = 0.05.
    assert!((share(0.9, &mut rng) - 0.05).abs() < 0.003);
    assert_eq!(share(1.0, &mut rng), 0.0);
}

#[test]
fn warm_starts_go_first() {
    let obj = FunctionObjective::new(Function::Sphere, 3, -5.0, 5.0);
    let seeds = vec![vec![0.1, 0.2, 0.3], vec![9.0, 0.0, 0.0]];
    let mut opt = js(JsParams { population: 6, ..JsParams::default() });
    let mut rng = run_rng(2, 0);
    let mut ctx = Context::new(&obj, &mut rng, None, false, &seeds);
    opt.init(&mut ctx);
    assert_eq!(opt.x.row(0), &[0.1, 0.2, 0.3]);
    // Repaired into the box by the context.
    assert_eq!(opt.x.row(1), &[5.0, 0.0, 0.0]);
    // The rest is the logistic map continued from the same x0 as without warm starts.
    let mut cold = js(JsParams { population: 6, ..JsParams::default() });
    let mut rng = run_rng(2, 0);
    let mut ctx = Context::new(&obj, &mut rng, None, false, &[]);
    cold.init(&mut ctx);
    for i in 2..6 {
        assert_eq!(opt.x.row(i), cold.x.row(i));
    }
    for i in 0..5 {
        let (a, b) = (cold.x.row(i), cold.x.row(i + 1));
        for d in 0..3 {
            let (ua, ub) = ((a[d] + 5.0) / 10.0, (b[d] + 5.0) / 10.0);
            assert!((ub - logistic(ua)).abs() < 1e-9);
        }
    }
}

#[test]
fn greedy_never_increases_a_jellyfishs_cost() {
    let obj = FunctionObjective::new(Function::Rastrigin, 6, -5.12, 5.12);
    let mut rng = run_rng(2, 0);
    let mut ctx = Context::new(&obj, &mut rng, Some(6_000), false, &[]);
    let mut opt = js(JsParams { population: 12, ..JsParams::default() });
    opt.init(&mut ctx);
    let mut before = opt.cost.clone();
    let mut iterations = 0;
    while !ctx.exhausted() {
        opt.step(&mut ctx);
        iterations += 1;
        for (k, (&now, &was)) in opt.cost.iter().zip(&before).enumerate() {
            assert!(now <= was, "jellyfish {k}: {was} -> {now} in iteration {iterations}");
            assert_eq!(Function::Rastrigin.value(opt.x.row(k)), now);
            assert!(opt.x.row(k).iter().all(|v| (-5.12..=5.12).contains(v)));
        }
        before.clone_from(&opt.cost);
    }
    assert_eq!(iterations, 499);
}

#[test]
fn converges_on_sphere_and_stays_in_the_box() {
    let obj = FunctionObjective::new(Function::Sphere, 10, -5.12, 5.12);
    let mut opt = js(JsParams::default());
    let r = run(&mut opt, &obj, &Termination::evaluations(20_000), &mut run_rng(3, 0), false, &[], &mut |_| {});
    eprintln!("js sphere-10: {}", r.best_cost);
    assert!(r.best_cost < 1e-12, "{}", r.best_cost);
    assert!(opt.x.rows().all(|x| x.iter().all(|v| (-5.12..=5.12).contains(v))));
    // A multimodal function, in an iteration-limited run (t/T from iterations).
    let obj = FunctionObjective::new(Function::Rastrigin, 5, -5.12, 5.12);
    let mut opt = js(JsParams::default());
    let r = run(&mut opt, &obj, &Termination::iterations(400), &mut run_rng(3, 0), false, &[], &mut |_| {});
    eprintln!("js rastrigin-5: {}", r.best_cost);
    assert!(r.best_cost < 2.0, "{}", r.best_cost);
}

#[test]
fn stops_exactly_at_the_evaluation_budget() {
    let obj = FunctionObjective::new(Function::Rastrigin, 7, -5.12, 5.12);
    test_support::assert_exact_budgets(&obj, &[1u64, 49, 50, 51, 1000, 3001], || Box::new(js(JsParams::default())));
}

#[test]
fn same_seed_same_bits() {
    let obj = FunctionObjective::new(Function::Ackley, 10, -32.0, 32.0);
    test_support::assert_same_bits(&obj, || Box::new(js(JsParams::default())));
}
