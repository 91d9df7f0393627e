//! What each planner can do, declared in its table entry (OMPL's `PlannerSpecs` is the model),
//! so a request it cannot honour is refused before any planning, naming the flag, and
//! `tidepath planners` can say what to expect of it.

use std::fmt;

use crate::world::Dims;

/// A unit a planner counts its work in; each has a limit (`--iterations`, ...).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Unit {
    Iterations,
    Evaluations,
    Expansions,
    Samples,
}

impl Unit {
    pub const ALL: [Unit; 4] = [Unit::Iterations, Unit::Evaluations, Unit::Expansions, Unit::Samples];

    /// "iterations", ...
    pub fn name(self) -> &'static str {
        match self {
            Unit::Iterations => "iterations",
            Unit::Evaluations => "evaluations",
            Unit::Expansions => "expansions",
            Unit::Samples => "samples",
        }
    }
}

/// Which worlds a planner plans in.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Dimensions {
    Both,
    TwoOnly,
}

impl Dimensions {
    pub fn covers(self, dims: Dims) -> bool {
        matches!((self, dims), (Dimensions::Both, _) | (Dimensions::TwoOnly, Dims::Two))
    }
}

/// How a planner plans several missions.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Fleets {
    /// All missions in one search (one decision vector, one cost).
    Jointly,
    /// Each mission on its own, in order.
    OneAfterAnother,
}

/// A planner's capabilities.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Capabilities {
    pub dimensions: Dimensions,
    pub fleets: Fleets,
    /// Uses a warm start (`--init`): optimizers seed their first population with it, a
    /// composite planner takes it as its reference.
    pub warm_start: bool,
    /// The units it counts; a limit in another unit cannot stop it.
    pub counts: &'static [Unit],
    /// What it can claim to be optimal for, and where; `None`: never `exact`.
    pub optimal: Option<&'static str>,
    /// Its result depends on the seed.
    pub randomised: bool,
    /// Builds a search graph (a tree or a roadmap) it can give back when a run asks for it
    /// ([`super::RunOptions::record_graph`], `plan --graph`); a request for the graph of a
    /// planner without one is refused before planning.
    pub graph: bool,
}

impl Capabilities {
    /// An optimizer over an encoding.
    pub const OPTIMIZER: Capabilities = Capabilities {
        dimensions: Dimensions::Both,
        fleets: Fleets::Jointly,
        warm_start: true,
        counts: &[Unit::Iterations, Unit::Evaluations],
        optimal: None,
        randomised: true,
        graph: false,
    };

    pub fn counts_unit(&self, unit: Unit) -> bool {
        self.counts.contains(&unit)
    }

    /// The units it counts, as words: "iterations and evaluations", "no unit".
    pub fn counts_text(&self) -> String {
        match self.counts {
            [] => "nothing (it runs to completion)".into(),
            [one] => one.name().into(),
            units => {
                let names: Vec<&str> = units.iter().map(|u| u.name()).collect();
                format!("{} and {}", names[..names.len() - 1].join(", "), names[names.len() - 1])
            }
        }
    }
}

impl fmt::Display for Capabilities {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let dims = match self.dimensions {
            Dimensions::Both => "2-D and 3-D",
            Dimensions::TwoOnly => "2-D only",
        };
        let fleets = match self.fleets {
            Fleets::Jointly => "fleets jointly",
            Fleets::OneAfterAnother => "fleets one mission after another",
        };
        let warm = if self.warm_start { "takes a warm start" } else { "no warm start" };
        let seed = if self.randomised { "randomised" } else { "deterministic" };
        write!(f, "{dims}; {fleets}; {warm}; counts {}; {seed}", self.counts_text())?;
        match self.optimal {
            Some(o) => write!(f, "; exact for {o}")?,
            None => f.write_str("; never exact")?,
        }
        if self.graph {
            f.write_str("; draws its search graph (--graph)")?;
        }
        Ok(())
    }
}
