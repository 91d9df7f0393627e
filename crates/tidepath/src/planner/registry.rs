//! The planner table: every planner id with its description, citation, parameters (with
//! ranges and defaults) and constructor. `tidepath planners`, `--help`, "known: ..." errors and
//! the generic planner tests all read it; adding a planner is one new file and one line here.

use super::grid_search::{GridParams, GridSearch};
use super::hybrid::{Hybrid, HybridParams};
use super::{OptimizerPlanner, Planner};
use crate::config::from_value;
use crate::encoding::EncodingSpec;
use crate::error::{Error, Result};
use crate::optim::de::{De, DeParams};
use crate::optim::ga::{Ga, GaParams};
use crate::optim::pso::{Pso, PsoParams};
use crate::optim::Optimizer;
use crate::registry::{defaults_of, Entry, Registry};

/// What a planner is built from: its `[planner.params.ID]` table (with `population`
/// overridden when given) and the encoding setting optimization planners use.
#[derive(Clone, Debug, Default)]
pub struct PlannerSettings {
    pub params: toml::Table,
    pub encoding: EncodingSpec,
}

/// How a planner is built.
#[derive(Clone, Copy, Debug)]
pub enum BuildPlanner {
    /// An optimizer over an encoding; the bare optimizer also runs on benchmark functions.
    /// Takes the parameter table and the dotted prefix errors should name.
    Optimizer(fn(toml::Value, &str) -> Result<Box<dyn Optimizer>>),
    /// Any other planner (graph, sampling, composite).
    Direct(fn(&PlannerSettings) -> Result<Box<dyn Planner>>),
}

fn optimizer<P, O>(
    value: toml::Value,
    prefix: &str,
    check: fn(&P) -> Result<()>,
    make: fn(P) -> O,
) -> Result<Box<dyn Optimizer>>
where
    P: serde::de::DeserializeOwned,
    O: Optimizer + 'static,
{
    let p: P = from_value(value, prefix)?;
    check(&p).map_err(|e| scoped(e, prefix))?;
    Ok(Box::new(make(p)))
}

pub const PLANNERS: &[Entry<BuildPlanner>] = &[
    Entry {
        id: "pso",
        description: "particle swarm with inertia weight and velocity clamp",
        citation: "Shi & Eberhart 1998; baseline in wpa2017, amfa2015, ijs2023",
        params: crate::optim::pso::PARAMS,
        defaults: defaults_of::<PsoParams>,
        build: BuildPlanner::Optimizer(|v, p| optimizer(v, p, PsoParams::check, Pso::new)),
    },
    Entry {
        id: "ga",
        description: "genetic algorithm, roulette selection, real-coded or 20-bit binary",
        citation: "Holland 1975, Goldberg 1989; baseline in wpa2017 (real) and amfa2015 (binary)",
        params: crate::optim::ga::PARAMS,
        defaults: defaults_of::<GaParams>,
        build: BuildPlanner::Optimizer(|v, p| optimizer(v, p, GaParams::check, Ga::new)),
    },
    Entry {
        id: "de",
        description: "differential evolution DE/rand/1/bin",
        citation: "Storn & Price 1997; reference baseline",
        params: crate::optim::de::PARAMS,
        defaults: defaults_of::<DeParams>,
        build: BuildPlanner::Optimizer(|v, p| optimizer(v, p, DeParams::check, De::new)),
    },
    Entry {
        id: "astar",
        description: "A* on the world's raster (8-connected 2-D, 26-connected 3-D), shortest or quickest; exact on its graph",
        citation: "Hart, Nilsson & Raphael 1968; reference planner",
        params: super::grid_search::PARAMS,
        defaults: defaults_of::<GridParams>,
        build: BuildPlanner::Direct(|s| {
            Ok(Box::new(GridSearch::new("astar", GridParams::from_settings(s, "astar")?, false)))
        }),
    },
    Entry {
        id: "theta-star",
        description: "any-angle Theta* on the world's raster, shortest or quickest",
        citation: "Nash, Daniel, Koenig & Felner 2007; reference planner",
        params: super::grid_search::PARAMS,
        defaults: defaults_of::<GridParams>,
        build: BuildPlanner::Direct(|s| {
            Ok(Box::new(GridSearch::new("theta-star", GridParams::from_settings(s, "theta-star")?, true)))
        }),
    },
    Entry {
        id: "visibility",
        description: "exact shortest path among discs and boxes in a 2-D world (tangent visibility graph)",
        citation: "Lozano-Perez & Wesley 1979; tangent graphs after Liu & Arimoto 1992",
        params: &[],
        defaults: crate::registry::no_params,
        build: BuildPlanner::Direct(|s| {
            let mut t = s.params.clone();
            t.remove("population");
            if let Some(k) = t.keys().next() {
                return Err(Error::input(format!("planner.params.visibility.{k}"), "visibility has no parameters"));
            }
            Ok(Box::new(super::visibility::Visibility))
        }),
    },
    Entry {
        id: "hybrid",
        description: "a Theta* or visibility reference refined by DE over free waypoints under the scenario's cost; turns back where routes must",
        citation: "tidepath",
        params: super::hybrid::PARAMS,
        defaults: defaults_of::<HybridParams>,
        build: BuildPlanner::Direct(|s| {
            let p: HybridParams = from_value(toml::Value::Table(s.params.clone()), "planner.params.hybrid")?;
            Ok(Box::new(Hybrid::new(p)?))
        }),
    },
];

/// The built-in planners. Extend with [`Registry::with`] to plan with your own.
pub fn registry() -> Registry<BuildPlanner> {
    Registry::new("planner", "planner", "tidepath planners", PLANNERS)
}

/// Parameter checks name `planner.params.FIELD`; the scenario key is `planner.params.ID.FIELD`.
fn scoped(e: Error, prefix: &str) -> Error {
    match e {
        Error::Input { field, message } => {
            let field = match field.strip_prefix("planner.params.") {
                Some(rest) if !format!("planner.params.{rest}").starts_with(&format!("{prefix}.")) => {
                    format!("{prefix}.{rest}")
                }
                _ => field,
            };
            Error::Input { field, message }
        }
        other => other,
    }
}

fn with_population(params: Option<&toml::Table>, population: Option<usize>) -> toml::Value {
    let mut table = params.cloned().unwrap_or_default();
    if let Some(n) = population {
        table.insert("population".into(), toml::Value::Integer(n.min(i64::MAX as usize) as i64));
    }
    toml::Value::Table(table)
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
        match entry.build {
            BuildPlanner::Optimizer(f) => {
                let opt = f(with_population(params, population), &prefix)?;
                Ok(Box::new(OptimizerPlanner::new(opt, encoding.clone())))
            }
            BuildPlanner::Direct(f) => {
                let value = with_population(params, population);
                let toml::Value::Table(params) = value else { unreachable!("built as a table") };
                f(&PlannerSettings { params, encoding: encoding.clone() })
            }
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
        match self.get(id)?.build {
            BuildPlanner::Optimizer(f) => f(with_population(params, population), &format!("planner.params.{id}")),
            BuildPlanner::Direct(_) => Err(Error::input(
                "planner",
                format!("'{id}' is not an optimizer; benchmark functions need one of: {}", optimizer_ids(self)),
            )),
        }
    }
}

fn optimizer_ids(r: &Registry<BuildPlanner>) -> String {
    r.entries()
        .iter()
        .filter(|e| matches!(e.build, BuildPlanner::Optimizer(_)))
        .map(|e| e.id)
        .collect::<Vec<_>>()
        .join(", ")
}

/// The bare optimizer behind a built-in planner id.
pub fn build_optimizer(
    id: &str,
    params: Option<&toml::Table>,
    population: Option<usize>,
) -> Result<Box<dyn Optimizer>> {
    registry().build_optimizer(id, params, population)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_entry_documents_each_default_parameter() {
        for e in PLANNERS {
            let names: Vec<&str> = e.params.iter().map(|p| p.name).collect();
            for key in (e.defaults)().keys() {
                assert!(names.contains(&key.as_str()), "{}: default '{key}' has no Param line", e.id);
            }
        }
    }
}
