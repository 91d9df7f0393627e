//! The planner table: every planner id with its description, citation, parameter declarations,
//! capabilities and constructor. `tidepath planners`, `--help`, "known: ..." errors, request
//! checks and the generic planner tests all read it; adding a planner is one new file and one
//! entry here.

use super::capabilities::{Capabilities, Dimensions, Fleets, Unit};
use super::grid_search::{GridParams, GridSearch};
use super::hybrid::{Hybrid, HybridParams};
use super::{OptimizerPlanner, Planner};
use crate::encoding::EncodingSpec;
use crate::error::{Error, Result};
use crate::optim::ade::{Ade, AdeParams};
use crate::optim::amfa::{Amfa, AmfaParams};
use crate::optim::de::{De, DeParams};
use crate::optim::eda_g::{EdaG, EdaGParams};
use crate::optim::fa::{Fa, FaParams};
use crate::optim::ga::{Ga, GaParams};
use crate::optim::hho::{Hho, HhoParams};
use crate::optim::histogram::{FhhLtsParams, FhhParams, Histogram, LfhhParams};
use crate::optim::ijs::{Ijs, IjsParams};
use crate::optim::js::{Js, JsParams};
use crate::optim::mpa::{Mpa, MpaParams};
use crate::optim::mwpa::{Mwpa, MwpaParams};
use crate::optim::pso::{Pso, PsoParams};
use crate::optim::qpso::{Qpso, QpsoParams};
use crate::optim::wpa::{Wpa, WpaParams};
use crate::optim::Optimizer;
use crate::registry::{Entry, Registry};

/// What a planner is built from: its `[planner.params.ID]` table (with `population`
/// overridden when given, for planners that have one) and the encoding setting optimization
/// planners use.
#[derive(Clone, Debug, Default)]
pub struct PlannerSettings {
    pub params: toml::Table,
    pub encoding: EncodingSpec,
    /// The dotted prefix errors name: `planner.params.ID`.
    pub prefix: String,
}

/// How a planner is built.
#[derive(Clone, Copy, Debug)]
pub enum Make {
    /// An optimizer over an encoding; the bare optimizer also runs on benchmark functions.
    /// Takes the parameter table and the dotted prefix errors should name.
    Optimizer(fn(&toml::Table, &str) -> Result<Box<dyn Optimizer>>),
    /// Any other planner (graph, sampling, composite).
    Direct(fn(&PlannerSettings) -> Result<Box<dyn Planner>>),
}

/// A planner's entry: what it can do, and how to build it.
#[derive(Clone, Copy, Debug)]
pub struct BuildPlanner {
    pub caps: Capabilities,
    pub make: Make,
}

impl BuildPlanner {
    /// An optimizer over an encoding: plans fleets jointly, takes warm starts into its first
    /// population, counts iterations and evaluations, randomised.
    pub const fn optimizer(make: fn(&toml::Table, &str) -> Result<Box<dyn Optimizer>>) -> Self {
        Self { caps: Capabilities::OPTIMIZER, make: Make::Optimizer(make) }
    }

    /// Any other planner, with its capabilities.
    pub const fn direct(caps: Capabilities, make: fn(&PlannerSettings) -> Result<Box<dyn Planner>>) -> Self {
        Self { caps, make: Make::Direct(make) }
    }

    pub fn is_optimizer(&self) -> bool {
        matches!(self.make, Make::Optimizer(_))
    }
}

/// The grid planners' capabilities.
const GRID: Capabilities = Capabilities {
    dimensions: Dimensions::Both,
    fleets: Fleets::OneAfterAnother,
    warm_start: false,
    counts: &[Unit::Expansions],
    optimal: Some("the scenario's cost model on its raster, in worlds that do not change in time (astar only)"),
    randomised: false,
    graph: false,
};

/// The sampling planners' capabilities.
const SAMPLING: Capabilities = Capabilities {
    dimensions: Dimensions::Both,
    fleets: Fleets::OneAfterAnother,
    warm_start: true,
    counts: &[Unit::Samples],
    optimal: None,
    randomised: true,
    graph: true,
};

/// The ant colonies' capabilities: 2-D rasters, counted in iterations (their ant steps are
/// reported as expansions), pheromone seeded by a warm start, randomised, never exact.
const ANTS: Capabilities = Capabilities {
    dimensions: Dimensions::TwoOnly,
    fleets: Fleets::OneAfterAnother,
    warm_start: true,
    counts: &[Unit::Iterations],
    optimal: None,
    randomised: true,
    graph: false,
};

pub const PLANNERS: &[Entry<BuildPlanner>] = &[
    Entry {
        id: "pso",
        description: "particle swarm with inertia weight and velocity clamp",
        citation: "Shi & Eberhart 1998; baseline in wpa2017, amfa2015, ijs2023",
        params: PsoParams::SPECS,
        build: BuildPlanner::optimizer(|t, p| Ok(Box::new(Pso::new(PsoParams::from_table(t, p)?)))),
    },
    Entry {
        id: "ga",
        description: "genetic algorithm, roulette selection, real-coded or 20-bit binary",
        citation: "Holland 1975, Goldberg 1989; baseline in wpa2017 (real) and amfa2015 (binary)",
        params: GaParams::SPECS,
        build: BuildPlanner::optimizer(|t, p| Ok(Box::new(Ga::new(GaParams::from_table(t, p)?)))),
    },
    Entry {
        id: "de",
        description: "differential evolution DE/rand/1/bin",
        citation: "Storn & Price 1997; reference baseline",
        params: DeParams::SPECS,
        build: BuildPlanner::optimizer(|t, p| Ok(Box::new(De::new(DeParams::from_table(t, p)?)))),
    },
    Entry {
        id: "wpa",
        description: "original wolf pack algorithm: scouting, calling, besieging, renewal",
        citation: "Wu, Zhang & Wu 2013; baseline in wpa2017",
        params: WpaParams::SPECS,
        build: BuildPlanner::optimizer(|t, p| Ok(Box::new(Wpa::new(WpaParams::from_table(t, p)?)))),
    },
    Entry {
        id: "mwpa",
        description: "modified wolf pack algorithm: interactive scouting, adaptive raid step, shrinking siege",
        citation: "wpa2017 (Zhang et al. 2017)",
        params: MwpaParams::SPECS,
        build: BuildPlanner::optimizer(|t, p| Ok(Box::new(Mwpa::new(MwpaParams::from_table(t, p)?)))),
    },
    Entry {
        id: "fa",
        description: "firefly algorithm: each firefly moves toward every brighter one, attraction decaying with distance, a uniform random step",
        citation: "Yang 2009; baseline in amfa2015",
        params: FaParams::SPECS,
        build: BuildPlanner::optimizer(|t, p| Ok(Box::new(Fa::new(FaParams::from_table(t, p)?)))),
    },
    Entry {
        id: "amfa",
        description: "modified firefly algorithm: random step scaled by the distance, absorption and randomness scheduled over the run, moves kept only when they help (AFS); excludes and contracts paths",
        citation: "amfa2015 (Liu et al. 2015)",
        params: AmfaParams::SPECS,
        build: BuildPlanner::optimizer(|t, p| Ok(Box::new(Amfa::new(AmfaParams::from_table(t, p)?)))),
    },
    Entry {
        id: "js",
        description: "artificial jellyfish search: logistic-map start, time control between following the ocean current and passive or active swarm motion, wrap-around bounds, moves kept only when they improve",
        citation: "Chou & Truong 2021; baseline in ijs2023",
        params: JsParams::SPECS,
        build: BuildPlanner::optimizer(|t, p| Ok(Box::new(Js::new(JsParams::from_table(t, p)?)))),
    },
    Entry {
        id: "ijs",
        description: "improved jellyfish search: personal-best memory, by rank an elite third with a hybrid shrinking-random or best-following move, a learning third with jellyfish search's active move, followers in a memory current",
        citation: "ijs2023 (Guo, Chen & Pang 2023)",
        params: IjsParams::SPECS,
        build: BuildPlanner::optimizer(|t, p| Ok(Box::new(Ijs::new(IjsParams::from_table(t, p)?)))),
    },
    Entry {
        id: "hho",
        description: "Harris hawks optimization: perching, soft and hard besieges around the best, rapid dives with Levy flights kept only when they improve",
        citation: "Heidari et al. 2019; baseline in ijs2023",
        params: HhoParams::SPECS,
        build: BuildPlanner::optimizer(|t, p| Ok(Box::new(Hho::new(HhoParams::from_table(t, p)?)))),
    },
    Entry {
        id: "mpa",
        description: "marine predators algorithm: Brownian then Levy moves toward the elite by thirds of the run, fish aggregating devices, greedy marine memory",
        citation: "Faramarzi et al. 2020; baseline in ijs2023",
        params: MpaParams::SPECS,
        build: BuildPlanner::optimizer(|t, p| Ok(Box::new(Mpa::new(MpaParams::from_table(t, p)?)))),
    },
    Entry {
        id: "qpso",
        description: "quantum-behaved particle swarm: each coordinate sampled around a random mix of the personal and global best, spread by its distance to the mean personal best; contraction-expansion 1.0 -> 0.5",
        citation: "Sun, Feng & Xu 2004; baseline in ijs2023",
        params: QpsoParams::SPECS,
        build: BuildPlanner::optimizer(|t, p| Ok(Box::new(Qpso::new(QpsoParams::from_table(t, p)?)))),
    },
    Entry {
        id: "lfhh",
        description: "learning fixed-height histogram EDA: histograms of the elite pulled toward the best, path smoothing every T-th generation, safe-cell sampling of 3-D waypoints",
        citation: "lfhh2019 (Liu et al. 2019)",
        params: LfhhParams::SPECS,
        build: BuildPlanner::optimizer(|t, p| Ok(Box::new(Histogram::lfhh(LfhhParams::from_table(t, p)?)))),
    },
    Entry {
        id: "fhh",
        description: "fixed-height histogram EDA: per-variable histograms of equal mass from the elite, (mu + lambda) selection",
        citation: "Tsutsui et al.; baseline in lfhh2019",
        params: FhhParams::SPECS,
        build: BuildPlanner::optimizer(|t, p| Ok(Box::new(Histogram::fhh(FhhParams::from_table(t, p)?)))),
    },
    Entry {
        id: "fhh-lts",
        description: "fixed-height histogram EDA with lfhh2019's learning transformation (elite pulled toward the best)",
        citation: "Tsutsui et al. with lfhh2019 eq. 14; baseline in lfhh2019",
        params: FhhLtsParams::SPECS,
        build: BuildPlanner::optimizer(|t, p| Ok(Box::new(Histogram::fhh_lts(FhhLtsParams::from_table(t, p)?)))),
    },
    Entry {
        id: "eda-g",
        description: "Gaussian EDA (UMDA_c): independent normals fitted to the elite, std floored at 1e-3 of the range, (mu + lambda) selection",
        citation: "Sebag & Ducoulombier 1998 (PBIL_C family), UMDA_c form; baseline in lfhh2019",
        params: EdaGParams::SPECS,
        build: BuildPlanner::optimizer(|t, p| Ok(Box::new(EdaG::new(EdaGParams::from_table(t, p)?)))),
    },
    Entry {
        id: "ade",
        description: "adaptive DE (a labelled reading: the cited rules could not be checked): DE/rand/1/bin, F decaying from 2 F0 to F0, CR ~ U[alpha, alpha + beta]",
        citation: "Zhang, Gong, Li & Lin 2014 as cited; baseline in lfhh2019 (rules: docs/papers/lfhh2019.md A7)",
        params: AdeParams::SPECS,
        build: BuildPlanner::optimizer(|t, p| Ok(Box::new(Ade::new(AdeParams::from_table(t, p)?)))),
    },
    Entry {
        id: "astar",
        description: "A* on the world's raster (8-connected 2-D, 26-connected 3-D), moves priced by the scenario's cost; exact on its graph",
        citation: "Hart, Nilsson & Raphael 1968; reference planner",
        params: GridParams::SPECS,
        build: BuildPlanner::direct(GRID, |s| {
            Ok(Box::new(GridSearch::new("astar", GridParams::from_table(&s.params, &s.prefix)?, false)))
        }),
    },
    Entry {
        id: "theta-star",
        description: "any-angle Theta* on the world's raster, moves priced by the scenario's cost",
        citation: "Nash, Daniel, Koenig & Felner 2007; reference planner",
        params: GridParams::SPECS,
        build: BuildPlanner::direct(Capabilities { optimal: None, ..GRID }, |s| {
            Ok(Box::new(GridSearch::new("theta-star", GridParams::from_table(&s.params, &s.prefix)?, true)))
        }),
    },
    Entry {
        id: "aco",
        description: "basic ant colony on the world's raster (8-connected 2-D): roulette on pheromone and 1/distance to the goal, every ant that reaches the goal deposits Q/L; moves priced by the scenario's cost",
        citation: "Dorigo 1991; grid form as acopf2016 eqs. 4-6",
        params: super::aco::AcoParams::SPECS,
        build: BuildPlanner::direct(ANTS, |s| {
            Ok(Box::new(super::aco::AntColony::aco(super::aco::AcoParams::from_table(&s.params, &s.prefix)?)))
        }),
    },
    Entry {
        id: "acopf",
        description: "improved ant colony with a potential field: heuristic of attraction to the goal, repulsion from obstacles, waves and current; best tour rewarded, worst punished",
        citation: "Gao et al. 2016 (acopf2016)",
        params: super::aco::AcopfParams::SPECS,
        build: BuildPlanner::direct(ANTS, |s| {
            Ok(Box::new(super::aco::AntColony::acopf(super::aco::AcopfParams::from_table(&s.params, &s.prefix)?)))
        }),
    },
    Entry {
        id: "visibility",
        description: "exact shortest path among discs and boxes in a 2-D world (tangent visibility graph)",
        citation: "Lozano-Perez & Wesley 1979; tangent graphs after Liu & Arimoto 1992",
        params: super::visibility::VisibilityParams::SPECS,
        build: BuildPlanner::direct(
            Capabilities {
                dimensions: Dimensions::TwoOnly,
                fleets: Fleets::OneAfterAnother,
                warm_start: false,
                counts: &[],
                optimal: Some("the scenario's cost model over all paths in the plane, in still water (a cost per metre)"),
                randomised: false,
                graph: false,
            },
            |s| {
                super::visibility::VisibilityParams::from_table(&s.params, &s.prefix)?;
                Ok(Box::new(super::visibility::Visibility))
            },
        ),
    },
    Entry {
        id: "hybrid",
        description: "a Theta* or visibility reference refined by DE over free waypoints under the scenario's cost; turns back where routes must",
        citation: "tidepath",
        params: HybridParams::SPECS,
        // Built directly (it owns its reference search), but it takes what an optimizer takes.
        build: BuildPlanner::direct(Capabilities::OPTIMIZER, |s| {
            Ok(Box::new(Hybrid::new(HybridParams::from_table(&s.params, &s.prefix)?)?))
        }),
    },
    Entry {
        id: "hybrid-astar",
        description: "Hybrid-A* over arcs of the vehicle's turning radius and straights, with analytic Dubins shots to the goal; flyable paths priced by the scenario's cost",
        citation: "Dolgov, Thrun, Montemerlo & Diebel 2010; Nav2 Smac Hybrid-A*",
        params: super::hybrid_astar::HybridAstarParams::SPECS,
        build: BuildPlanner::direct(
            Capabilities {
                dimensions: Dimensions::Both,
                fleets: Fleets::OneAfterAnother,
                warm_start: false,
                counts: &[Unit::Expansions],
                optimal: None,
                randomised: false,
                graph: false,
            },
            |s| {
                let p = super::hybrid_astar::HybridAstarParams::from_table(&s.params, &s.prefix)?;
                Ok(Box::new(super::hybrid_astar::HybridAstar::new(p)))
            },
        ),
    },
    Entry {
        id: "rrt-star",
        description: "RRT*: a tree of samples rewired towards the cheapest path, edges priced by the scenario's cost at the vehicle's clock",
        citation: "Karaman & Frazzoli 2011; baseline in lfhh2019",
        params: super::sampling::RrtStarParams::SPECS,
        build: BuildPlanner::direct(SAMPLING, |s| {
            Ok(Box::new(super::sampling::RrtStar::new(super::sampling::RrtStarParams::from_table(&s.params, &s.prefix)?, false)))
        }),
    },
    Entry {
        id: "informed-rrt-star",
        description: "Informed RRT*: RRT* that samples only where a shorter path can pass once it has one (costs proportional to length; whole space otherwise)",
        citation: "Gammell, Srinivasa & Barfoot 2014",
        params: super::sampling::RrtStarParams::SPECS,
        build: BuildPlanner::direct(SAMPLING, |s| {
            Ok(Box::new(super::sampling::RrtStar::new(super::sampling::RrtStarParams::from_table(&s.params, &s.prefix)?, true)))
        }),
    },
    Entry {
        id: "prm-star",
        description: "PRM*: a roadmap of samples joined within the shrinking radius, searched by A* under the scenario's cost at the vehicle's clock",
        citation: "Karaman & Frazzoli 2011; baseline in lfhh2019",
        params: super::sampling::PrmStarParams::SPECS,
        build: BuildPlanner::direct(SAMPLING, |s| {
            Ok(Box::new(super::sampling::PrmStar::new(super::sampling::PrmStarParams::from_table(&s.params, &s.prefix)?)))
        }),
    },
];

/// The built-in planners. Extend with [`Registry::with`] to plan with your own.
pub fn registry() -> Registry<BuildPlanner> {
    Registry::new("planner", "planner", "tidepath planners", PLANNERS)
}

/// The parameter table with `population` set, for planners that have one; `population` given
/// to a planner without one is an input error naming `--population`.
fn with_population(
    entry: &Entry<BuildPlanner>,
    params: Option<&toml::Table>,
    population: Option<usize>,
) -> Result<toml::Table> {
    let mut table = params.cloned().unwrap_or_default();
    if let Some(n) = population {
        if !entry.has_param("population") {
            return Err(Error::input("--population", format!("{} has no population", entry.id)));
        }
        table.insert("population".into(), toml::Value::Integer(n.min(i64::MAX as usize) as i64));
    }
    Ok(table)
}

impl Registry<BuildPlanner> {
    /// Builds planner `id` from its parameters, with `population` overriding the table's.
    pub fn build(
        &self,
        id: &str,
        params: Option<&toml::Table>,
        population: Option<usize>,
        encoding: &EncodingSpec,
    ) -> Result<Box<dyn Planner>> {
        let entry = self.get(id)?;
        let prefix = format!("planner.params.{id}");
        let table = with_population(entry, params, population)?;
        match entry.build.make {
            Make::Optimizer(f) => {
                let opt = f(&table, &prefix)?;
                Ok(Box::new(OptimizerPlanner::new(opt, encoding.clone())))
            }
            Make::Direct(f) => f(&PlannerSettings { params: table, encoding: encoding.clone(), prefix }),
        }
    }

    /// The bare optimizer behind planner `id`, for problems that are not paths (benchmark
    /// functions); an input error for planners that are not optimizers.
    pub fn build_optimizer(
        &self,
        id: &str,
        params: Option<&toml::Table>,
        population: Option<usize>,
    ) -> Result<Box<dyn Optimizer>> {
        let entry = self.get(id)?;
        match entry.build.make {
            Make::Optimizer(f) => f(&with_population(entry, params, population)?, &format!("planner.params.{id}")),
            Make::Direct(_) => Err(Error::input(
                "planner",
                format!("'{id}' is not an optimizer; benchmark functions need one of: {}", optimizer_ids(self)),
            )),
        }
    }
}

fn optimizer_ids(r: &Registry<BuildPlanner>) -> String {
    r.entries().iter().filter(|e| e.build.is_optimizer()).map(|e| e.id).collect::<Vec<_>>().join(", ")
}

/// The bare optimizer behind a built-in planner id.
pub fn build_optimizer(
    id: &str,
    params: Option<&toml::Table>,
    population: Option<usize>,
) -> Result<Box<dyn Optimizer>> {
    registry().build_optimizer(id, params, population)
}
