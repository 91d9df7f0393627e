//! Experiment figures (convergence bands, final-cost boxes, best paths) render from synthetic
//! runs, including the awkward ones: costs over ten decades, exact zeros, a single run, ragged
//! and initially infinite histories, and identical costs.
//!
//! Set `TIDEPATH_PLOT_DIR` to also write the SVGs there, to look at them.

// The other figure suites, as modules of this one test binary (one link instead of five).
#[path = "plot/plot_failures.rs"]
mod plot_failures;
#[path = "plot/plot_flown.rs"]
mod plot_flown;
#[path = "plot/plot_smoke.rs"]
mod plot_smoke;
#[path = "plot/plot_speed.rs"]
mod plot_speed;
#[path = "plot/plot_time_ticks.rs"]
mod plot_time_ticks;
#[path = "plot/plot_waves.rs"]
mod plot_waves;

use tidepath::geom::{Aabb, Vec2, Vec3};
use tidepath::world::terrain::{GaussianPeaks, Peak};
use tidepath::world::{Current, Obstacle, Shape, Terrain, World};
use tidepath_plot::experiment::{
    best_path_label, render_boxplot_figure, render_convergence_figure, render_paths_figure, write_boxplot_figure,
    write_convergence_figure, write_paths_figure, PlannerRuns, ProblemRuns,
};
use tidepath_plot::{PlanFigure, PlotPath};

const PLANNERS: [&str; 3] = ["pso", "de", "random search"];

/// splitmix64, so the synthetic runs are the same on every machine without a dependency.
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> f64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        ((z ^ (z >> 31)) >> 11) as f64 / (1u64 << 53) as f64
    }

    /// Log-normal factor exp(sigma * u), u roughly standard normal.
    fn spread(&mut self, sigma: f64) -> f64 {
        let u = (0..4).map(|_| self.next()).sum::<f64>() - 2.0;
        (sigma * u * 1.7).exp()
    }
}

/// One planner's 30 runs with its own convergence shape:
/// * pso: fast exponential drop to a noisy plateau;
/// * de: power-law fall over ten decades, ragged lengths, and (with `zeros`) exact optima;
/// * random search: slow, with no feasible solution for its first iterations.
fn runs(planner: &'static str, seed: u64, scale: f64, zeros: bool) -> PlannerRuns<'static> {
    let mut rng = Rng(seed);
    let mut histories = Vec::new();
    for r in 0..30 {
        let a = rng.spread(0.4);
        let h: Vec<f64> = match planner {
            "pso" => (0..200).map(|i| scale * (0.05 * a + 50.0 * (-(i as f64) / (12.0 * a)).exp())).collect(),
            "de" => {
                let len = 120 + (rng.next() * 80.0) as usize;
                let reach_zero = zeros && r % 2 == 0;
                (0..len)
                    .map(|i| {
                        let v = scale * 1e4 * a * (1.0 + i as f64).powf(-4.0 - a);
                        if reach_zero && i > 100 {
                            0.0
                        } else {
                            v.max(scale * 1e-6 * a)
                        }
                    })
                    .collect()
            }
            _ => {
                let lead = (rng.next() * 12.0) as usize;
                (0..200)
                    .map(|i| if i < lead { f64::INFINITY } else { scale * 80.0 * a / (1.0 + (i as f64) / 20.0).sqrt() })
                    .collect()
            }
        };
        // Best so far, as the runner records it.
        let mut best = f64::INFINITY;
        let h: Vec<f64> = h
            .into_iter()
            .map(|v| {
                best = if v.is_finite() { best.min(v) } else { best };
                if best.is_finite() {
                    best
                } else {
                    v
                }
            })
            .collect();
        histories.push(h);
    }
    let costs = histories.iter().map(|h| *h.last().unwrap()).collect();
    PlannerRuns { planner, costs, histories, search_before_iterations: false }
}

fn problem(name: &'static str, seed: u64, scale: f64, zeros: bool) -> ProblemRuns<'static> {
    ProblemRuns {
        problem: name,
        planners: PLANNERS.iter().enumerate().map(|(k, p)| runs(p, seed * 10 + k as u64, scale, zeros)).collect(),
    }
}

fn twelve_problems() -> Vec<ProblemRuns<'static>> {
    const NAMES: [&str; 12] = [
        "sphere-d30-small",
        "sphere-d30-wide",
        "rastrigin-d30-small",
        "rastrigin-d30-wide",
        "rosenbrock-d30-small",
        "rosenbrock-d30-wide",
        "ackley-d30-small",
        "ackley-d30-wide",
        "griewank-d30-small",
        "griewank-d30-wide",
        "schwefel-d30-small",
        "schwefel-d30-wide",
    ];
    NAMES.iter().enumerate().map(|(k, n)| problem(n, k as u64 + 1, 10f64.powi(k as i32 % 4 - 1), k % 3 == 0)).collect()
}

fn out_dir() -> Option<std::path::PathBuf> {
    std::env::var_os("TIDEPATH_PLOT_DIR").map(std::path::PathBuf::from)
}

fn save(name: &str, svg: &str) {
    if let Some(dir) = out_dir() {
        std::fs::create_dir_all(&dir).unwrap();
        std::fs::write(dir.join(name), svg).unwrap();
    }
}

fn assert_well_formed(svg: &str, title: &str, labels: &[&str]) {
    assert!(svg.starts_with("<svg"), "not an SVG: {}", &svg[..svg.len().min(80)]);
    assert!(svg.trim_end().ends_with("</svg>"));
    assert!(svg.contains(title), "title {title:?} missing");
    for label in labels {
        assert!(svg.contains(label), "label {label:?} missing");
    }
    assert!(!svg.contains("NaN"), "NaN in the SVG");
    // Coordinates and numbers only: a non-finite value would print as "inf".
    assert!(!svg.contains("=\"inf") && !svg.contains("=\"-inf") && !svg.contains(",inf"), "inf in the SVG");
}

#[test]
fn one_problem_with_ten_decades_and_zeros() {
    let problems = vec![problem("sphere-d30-small", 7, 1.0, true)];
    let title =
        "Convergence — sphere-d30-small, a long list of problems: 30 runs per planner (median and interquartile band)";
    let svg = render_convergence_figure(title, &problems).unwrap();
    // Too long for one line of a one-panel figure: wrapped, not cut off.
    assert_well_formed(
        &svg,
        "Convergence — sphere-d30-small,",
        &[
            "(median and interquartile band)",
            "sphere-d30-small",
            "iteration",
            "best cost (log scale, 0 below break)",
            "interquartile range",
            "random search",
        ],
    );
    // One band per planner behind one median each.
    assert!(svg.matches("<polygon").count() >= 3);
    save("convergence_one.svg", &svg);

    let svg = render_boxplot_figure("Final costs on sphere", &problems).unwrap();
    assert_well_formed(
        &svg,
        "Final costs on sphere",
        &["final cost (log scale, 0 below break)", "labelled 0", "pso", "de", "random search"],
    );
    save("boxplot_one.svg", &svg);
}

#[test]
fn twelve_problems_in_a_grid() {
    let problems = twelve_problems();
    let svg = render_convergence_figure("Function benchmarks: convergence over 30 runs", &problems).unwrap();
    let names: Vec<&str> = problems.iter().map(|p| p.problem).collect();
    assert_well_formed(&svg, "Function benchmarks", &names);
    assert_eq!(svg.matches("\niteration\n").count(), 12, "every panel labels its x axis");
    save("convergence_grid.svg", &svg);

    let svg = render_boxplot_figure("Function benchmarks: final cost over 30 runs", &problems).unwrap();
    assert_well_formed(&svg, "Function benchmarks", &names);
    assert!(svg.matches("final cost").count() >= 12);
    save("boxplot_grid.svg", &svg);
}

#[test]
fn awkward_runs_still_render() {
    let inf = f64::INFINITY;
    let problems = vec![
        ProblemRuns {
            problem: "ragged",
            planners: vec![
                // One run only: a line, no band, a box that is a bar.
                PlannerRuns {
                    planner: "lonely",
                    costs: vec![3.0],
                    histories: vec![vec![inf, inf, 9.0, 5.0, 3.0]],
                    search_before_iterations: false,
                },
                // Histories of different lengths, with NaN gaps and infinite starts.
                PlannerRuns {
                    planner: "ragged runs",
                    costs: vec![2.0, 4.0, inf],
                    histories: vec![
                        vec![inf, 8.0, f64::NAN, 2.0],
                        vec![inf, inf, inf, inf, inf, inf, 6.0, 4.0],
                        vec![inf, inf],
                    ],
                    search_before_iterations: true,
                },
                // Every run starts infeasible and no history is finite at all.
                PlannerRuns {
                    planner: "never feasible",
                    costs: vec![inf, inf],
                    histories: vec![vec![inf; 6]; 2],
                    search_before_iterations: false,
                },
            ],
        },
        ProblemRuns {
            problem: "all equal",
            planners: vec![PlannerRuns {
                planner: "flat",
                costs: vec![7.0; 30],
                histories: vec![vec![7.0; 10]; 30],
                search_before_iterations: false,
            }],
        },
        ProblemRuns { problem: "nothing ran", planners: vec![] },
    ];
    let svg = render_convergence_figure("edge cases", &problems).unwrap();
    assert_well_formed(&svg, "edge cases", &["ragged", "all equal", "lonely", "never feasible", "no runs"]);
    // A planner whose iterations follow a search gets its iteration 0 marked and explained.
    assert!(svg.contains("iteration 0 of ragged runs: refinement starts from the reference search"));
    save("convergence_edge.svg", &svg);
    let svg = render_boxplot_figure("edge cases", &problems).unwrap();
    assert_well_formed(&svg, "edge cases", &["ragged runs", "flat", "no finite cost", "1 run = ∞", "no runs"]);
    save("boxplot_edge.svg", &svg);

    let svg = render_convergence_figure("empty", &[]).unwrap();
    assert_well_formed(&svg, "empty", &["no runs"]);
}

#[test]
fn many_planners_with_long_names_keep_their_colours() {
    let names = ["pso", "de", "random search", "ga", "abc with restarts", "straight line baseline", "cmaes", "gwo"];
    let problems: Vec<ProblemRuns> = (0..4)
        .map(|k| ProblemRuns {
            problem: ["a", "b", "c", "d"][k],
            planners: names
                .iter()
                .enumerate()
                .map(|(i, n)| PlannerRuns {
                    planner: n,
                    ..runs(PLANNERS[i % 3], 100 + i as u64, 1.0 + k as f64, false)
                })
                .collect(),
        })
        .collect();
    let svg = render_boxplot_figure("eight planners", &problems).unwrap();
    assert_well_formed(&svg, "eight planners", &names);
    save("boxplot_many.svg", &svg);
    let svg = render_convergence_figure("eight planners", &problems).unwrap();
    assert_well_formed(&svg, "eight planners", &names);
    save("convergence_many.svg", &svg);
}

fn small_world() -> World {
    let mut w = World::open(Aabb::new(Vec3::new(0.0, 0.0, -400.0), Vec3::new(4_000.0, 3_000.0, 0.0)));
    w.terrain = Terrain::Peaks(GaussianPeaks {
        base: -380.0,
        peaks: vec![
            Peak { x: 1_800.0, y: 1_500.0, height: 300.0, sigma_x: 500.0, sigma_y: 400.0 },
            Peak { x: 3_000.0, y: 700.0, height: 200.0, sigma_x: 400.0, sigma_y: 400.0 },
        ],
        ceiling: None,
    });
    w.obstacles = vec![Obstacle::fixed(Shape::Circle { center: Vec2::new(2_600.0, 2_100.0), radius: 250.0 })];
    w.current = Current::Uniform(Vec3::new(0.2, 0.05, 0.0));
    w
}

#[test]
fn best_paths_with_costs_in_the_legend() {
    let world = small_world();
    let (start, goal) = (Vec3::new(200.0, 300.0, -100.0), Vec3::new(3_800.0, 2_700.0, -150.0));
    let via = |x: f64, y: f64, z: f64| vec![start, Vec3::new(x, y, z), goal];
    let paths = [via(1_800.0, 400.0, -250.0), via(1_000.0, 2_400.0, -200.0), via(2_000.0, 1_500.0, -60.0)];
    let costs = [1.234, 0.98765, 3.2e6];
    let labelled: Vec<PlotPath> =
        PLANNERS.iter().zip(&paths).zip(costs).map(|((p, pts), c)| PlotPath::new(best_path_label(p, c), pts)).collect();
    let reference = via(1_500.0, 1_000.0, -300.0);
    let mut fig = PlanFigure::new("Best path per planner", &world, start, goal, 0.0);
    fig.paths = labelled;
    fig.reference = Some(PlotPath::new("reference: theta-star (cost 0.9)", &reference));
    let svg = render_paths_figure(&fig).unwrap();
    assert_well_formed(
        &svg,
        "Best path per planner",
        &[
            "pso (best 1.23)",
            "de (best 0.988)",
            "random search (best 3.2e6)",
            "Plan view",
            "Vertical profile",
            "reference: theta-star (cost 0.9)",
        ],
    );
    // The reference is drawn: dashed pieces in its colour.
    assert!(svg.matches(r##"stroke="#005A32" stroke-width="2""##).count() >= 3, "no reference path");
    save("paths.svg", &svg);
}

#[test]
fn writers_replace_files_whole() {
    let dir = tempfile::tempdir().unwrap();
    let problems = vec![problem("p", 3, 1.0, false)];
    let conv = dir.path().join("convergence.svg");
    write_convergence_figure("t", &problems, &conv).unwrap();
    assert_eq!(std::fs::read_to_string(&conv).unwrap(), render_convergence_figure("t", &problems).unwrap());
    let boxes = dir.path().join("boxplot.svg");
    write_boxplot_figure("t", &problems, &boxes).unwrap();
    assert_eq!(std::fs::read_to_string(&boxes).unwrap(), render_boxplot_figure("t", &problems).unwrap());
    let world = small_world();
    let pts = [Vec3::new(100.0, 100.0, -50.0), Vec3::new(3_900.0, 2_900.0, -50.0)];
    let out = dir.path().join("paths.svg");
    let mut fig = PlanFigure::new("t", &world, pts[0], pts[1], 0.0);
    fig.paths = vec![PlotPath::new("x", &pts)];
    write_paths_figure(&fig, &out).unwrap();
    assert!(std::fs::read_to_string(&out).unwrap().starts_with("<svg"));
    assert_eq!(std::fs::read_dir(dir.path()).unwrap().count(), 3, "no temporary file left behind");
}
