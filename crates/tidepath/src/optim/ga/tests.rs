//! The GA's unit tests: parameters, codings, roulette, ranking, mutation and runs.

use super::*;
use crate::optim::functions::{Function, FunctionObjective};
use crate::optim::run;
use crate::termination::Termination;
use rand::SeedableRng;

#[test]
fn defaults_presets_and_check() {
    let p = GaParams::default();
    assert_eq!(p, GaParams::wpa2017());
    assert_eq!(
        (p.coding, p.population, p.crossover_rate, p.mutation_rate, p.bits, p.elitism, p.sigma_fraction),
        (GaCoding::Real, 50, 0.8, None, 20, 1, 0.1)
    );
    let q = GaParams::amfa2015();
    assert_eq!((q.coding, q.population, q.crossover_rate, q.bits), (GaCoding::Binary, 40, 0.6, 20));
    assert!(p.clone().checked("p").is_ok() && q.clone().checked("p").is_ok());
    for bad in [
        GaParams { population: 1, elitism: 0, ..p.clone() },
        GaParams { crossover_rate: 1.5, ..p.clone() },
        GaParams { crossover_rate: f64::NAN, ..p.clone() },
        GaParams { mutation_rate: Some(-0.1), ..p.clone() },
        GaParams { bits: 0, ..p.clone() },
        GaParams { bits: 53, ..p.clone() },
        GaParams { elitism: 50, ..p.clone() },
        GaParams { sigma_fraction: f64::INFINITY, ..p.clone() },
    ] {
        let e = bad.checked("planner.params.ga").unwrap_err().to_string();
        assert!(e.starts_with("planner.params.ga."), "{e}");
    }
}

/// The chromosome reading flips exactly one bit of a mutated child and none otherwise.
#[test]
fn chromosome_scope_flips_one_bit() {
    let mut rng = Rng::seed_from_u64(5);
    let mut u = vec![0.0; 3 * 20];
    for _ in 0..50 {
        let mut child = vec![0u64; 3];
        Ga::mutate_bits(&mut child, 1.0, MutationScope::Chromosome, 20, &mut u, &mut rng);
        assert_eq!(child.iter().map(|w| w.count_ones()).sum::<u32>(), 1);
        assert!(child.iter().all(|&w| w < 1 << 20));
        let mut still = vec![0u64; 3];
        Ga::mutate_bits(&mut still, 0.0, MutationScope::Chromosome, 20, &mut u, &mut rng);
        assert_eq!(still, vec![0; 3]);
    }
    let t = GaParams::from_table(&toml::from_str("mutation_scope = \"chromosome\"").unwrap(), "p").unwrap();
    assert_eq!(*t.get(), GaParams { mutation_scope: MutationScope::Chromosome, ..GaParams::default() });
    assert_eq!(GaParams::amfa2015_per_chromosome().mutation_scope, MutationScope::Chromosome);
    assert_eq!(GaParams::amfa2015_per_bit_small(30).mutation_rate, Some(1.0 / 600.0));
}

#[test]
fn coding_names() {
    let t = |s: &str| GaParams::from_table(&toml::from_str(s).unwrap(), "p");
    let p = t("coding = \"binary\"\nbits = 12").unwrap();
    assert_eq!(*p.get(), GaParams { coding: GaCoding::Binary, bits: 12, ..GaParams::default() });
    assert!(t("coding = \"gray\"").is_err());
    assert!(t("pc = 0.5").is_err());
}

#[test]
fn roulette_handles_infinities() {
    let mut w = [0.0; 4];
    roulette_fitness(&[3.0, 1.0, f64::INFINITY, 2.0], &mut w);
    assert_eq!(w, [1.0 / 3.0, 1.0, 0.0, 0.5]);
    roulette_fitness(&[f64::INFINITY; 4], &mut w);
    assert_eq!(w, [0.0; 4]);
    roulette_fitness(&[-1e308, 1e308, f64::NAN, -1e308], &mut w);
    assert_eq!(w, [1.0, 0.0, 0.0, 1.0]);
    // All-zero weights pick uniformly; zero-weight individuals are never picked otherwise.
    let mut rng = crate::rng::Rng::seed_from_u64(5);
    let picks: Vec<usize> = (0..200).map(|_| spin(&[0.0, 0.0, 0.0], &mut rng)).collect();
    assert!((0..3).all(|i| picks.contains(&i)));
    assert!((0..200).all(|_| spin(&[0.0, 1.0, 1.0, 2.0], &mut rng) != 0 && spin(&[1.0, 1.0, 2.0], &mut rng) != 1));
}

#[test]
fn rank_is_a_stable_sort_of_the_previous_order() {
    use rand::seq::SliceRandom;
    let mut rng = crate::rng::Rng::seed_from_u64(9);
    let values = [f64::NAN, f64::INFINITY, f64::NEG_INFINITY, -0.0, 0.0, 1.0, -1.0, 2.5, 1e300, -1e-300];
    let mut keys = Vec::new();
    for n in [1usize, 2, 3, 8, 40, 41, 200] {
        let mut order: Vec<usize> = (0..n).collect();
        order.shuffle(&mut rng);
        for _ in 0..20 {
            // Few distinct values, so ties (and NaN, infinities, signed zeros) are common.
            let cost: Vec<f64> = (0..n).map(|_| values[rng.random_range(0..values.len())]).collect();
            let key = |i: usize| if cost[i].is_nan() { f64::INFINITY } else { cost[i] };
            let mut expected = order.clone();
            expected.sort_by(|&a, &b| key(a).total_cmp(&key(b)));
            rank(&mut order, &cost, &mut keys);
            assert_eq!(order, expected, "n = {n}, costs {cost:?}");
        }
    }
}

#[test]
fn binary_decode_and_crossover() {
    assert_eq!(decode(0, 20, -5.0, 5.0), -5.0);
    assert_eq!(decode((1 << 20) - 1, 20, -5.0, 5.0), 5.0);
    assert_eq!(decode(2, 2, 0.0, 3.0), 2.0);
    // 3 variables of 4 bits, cut after 6 bits: variable 0 and the top 2 bits of variable 1
    // come from the first parent.
    let mut a = [0b1111, 0b1111, 0b1111];
    let mut b = [0b0000, 0b0000, 0b0000];
    one_point_bits(&mut a, &mut b, 4, 6);
    assert_eq!(a, [0b1111, 0b1100, 0b0000]);
    assert_eq!(b, [0b0000, 0b0011, 0b1111]);
    let mut a = [0b1010u64];
    let mut b = [0b0101u64];
    one_point_bits(&mut a, &mut b, 4, 4);
    assert_eq!((a, b), ([0b1010], [0b0101]));
}

#[test]
fn both_codings_improve_and_keep_the_elite() {
    for params in [GaParams::wpa2017(), GaParams::amfa2015()] {
        let obj = FunctionObjective::new(Function::Sphere, 4, -5.12, 5.12);
        let mut ga = Ga::new(params.clone().checked("p").unwrap());
        let r =
            run(&mut ga, &obj, &Termination::iterations(100), &mut crate::rng::run_rng(2, 0), false, &[], &mut |_| {});
        assert!(r.best_cost < 0.1, "{:?}: {}", params.coding, r.best_cost);
        // Elitism: the population still holds the best point seen.
        let min = ga.cost.iter().copied().fold(f64::INFINITY, f64::min);
        assert_eq!(min, r.best_cost, "{:?}", params.coding);
        assert!(ga.x.rows().all(|x| x.iter().all(|v| (-5.12..=5.12).contains(v))));
    }
}
