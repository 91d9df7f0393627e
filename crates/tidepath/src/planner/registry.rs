//! Planner ids, their one-line descriptions and papers, and construction from scenario params.

use super::{OptimizerPlanner, Planner};
use crate::error::{Error, Result};
use crate::optim::de::{De, DeParams};
use crate::optim::ga::{Ga, GaParams};
use crate::optim::pso::{Pso, PsoParams};
use crate::optim::Optimizer;

#[derive(Clone, Copy, Debug)]
pub struct PlannerInfo {
    pub id: &'static str,
    pub description: &'static str,
    /// Where the method comes from and which seed paper uses it.
    pub paper: &'static str,
}

pub const PLANNERS: &[PlannerInfo] = &[
    PlannerInfo {
        id: "pso",
        description: "particle swarm with inertia weight and velocity clamp",
        paper: "Shi & Eberhart 1998; baseline in seeds 000, 002, 003",
    },
    PlannerInfo {
        id: "ga",
        description: "genetic algorithm, roulette selection, real-coded or 20-bit binary",
        paper: "Holland/Goldberg; baseline in seeds 000 (real) and 002 (binary)",
    },
    PlannerInfo {
        id: "de",
        description: "differential evolution DE/rand/1/bin",
        paper: "Storn & Price 1997; reference baseline",
    },
];

pub fn planner_info(id: &str) -> Option<&'static PlannerInfo> {
    PLANNERS.iter().find(|p| p.id == id)
}

/// Parameter checks name `planner.params.FIELD`; the scenario key is `planner.params.ID.FIELD`.
fn scoped(e: Error, id: &str) -> Error {
    match e {
        Error::Input { field, message } => {
            let field = match field.strip_prefix("planner.params.") {
                Some(rest) if !rest.starts_with(&format!("{id}.")) => format!("planner.params.{id}.{rest}"),
                _ => field,
            };
            Error::Input { field, message }
        }
        other => other,
    }
}

fn unknown(id: &str) -> Error {
    Error::input(
        "planner",
        format!(
            "unknown planner '{id}' (known: {}; run `tidepath planners`)",
            PLANNERS.iter().map(|p| p.id).collect::<Vec<_>>().join(", ")
        ),
    )
}

/// Builds planner `id` from its `[planner.params.ID]` table, with `population` overriding the
/// table's population when given.
pub fn build_planner(id: &str, params: Option<&toml::Table>, population: Option<usize>) -> Result<Box<dyn Planner>> {
    Ok(Box::new(OptimizerPlanner::new(build_optimizer(id, params, population)?)))
}

/// The bare optimizer behind planner `id`, for problems that are not paths (benchmark
/// functions).
pub fn build_optimizer(
    id: &str,
    params: Option<&toml::Table>,
    population: Option<usize>,
) -> Result<Box<dyn Optimizer>> {
    let mut table = params.cloned().unwrap_or_default();
    if let Some(n) = population {
        table.insert("population".into(), toml::Value::Integer(n as i64));
    }
    let prefix = format!("planner.params.{id}");
    let value = toml::Value::Table(table);
    Ok(match id {
        "pso" => {
            let p: PsoParams = crate::scenario::from_value(value, &prefix)?;
            p.check().map_err(|e| scoped(e, id))?;
            Box::new(Pso::new(p))
        }
        "ga" => {
            let p: GaParams = crate::scenario::from_value(value, &prefix)?;
            p.check().map_err(|e| scoped(e, id))?;
            Box::new(Ga::new(p))
        }
        "de" => {
            let p: DeParams = crate::scenario::from_value(value, &prefix)?;
            p.check().map_err(|e| scoped(e, id))?;
            Box::new(De::new(p))
        }
        other => return Err(unknown(other)),
    })
}
