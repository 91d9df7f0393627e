//! What a planning run found, separate from why it stopped ([`crate::termination::StopReason`]).

/// Every planner's result carries one. Set from direct checks, never inferred from counters:
/// start and goal are checked before the search, `unreachable` comes only from a search that
/// can prove it, `exact` only from a planner that is optimal for its model.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum Status {
    /// Feasible and optimal for the planner's model (e.g. A* on its grid).
    Exact,
    /// Feasible: no constraint violated.
    Feasible,
    /// The best path found violates constraints.
    Infeasible,
    /// The wall-time limit stopped the run before a feasible path was found.
    Timeout,
    /// The start state is invalid (outside the domain or depth band, in the seabed or an
    /// obstacle); nothing was planned.
    InvalidStart,
    /// The goal state is invalid; nothing was planned.
    InvalidGoal,
    /// Proved: no path connects start and goal for this vehicle.
    Unreachable,
    /// The caller stopped the run (Ctrl-C, a stop flag) before a feasible path was found.
    Cancelled,
}

impl Status {
    pub fn id(self) -> &'static str {
        match self {
            Status::Exact => "exact",
            Status::Feasible => "feasible",
            Status::Infeasible => "infeasible",
            Status::Timeout => "timeout",
            Status::InvalidStart => "invalid-start",
            Status::InvalidGoal => "invalid-goal",
            Status::Unreachable => "unreachable",
            Status::Cancelled => "cancelled",
        }
    }

    /// How bad the status is, for the worst of a fleet's missions: flyable first, then a
    /// search that ran out (time, a stop), a path that breaks constraints, a proof that none
    /// exists, and bad input last.
    pub fn severity(self) -> u8 {
        match self {
            Status::Exact => 0,
            Status::Feasible => 1,
            Status::Cancelled => 2,
            Status::Timeout => 3,
            Status::Infeasible => 4,
            Status::Unreachable => 5,
            Status::InvalidGoal => 6,
            Status::InvalidStart => 7,
        }
    }

    /// Every status, in order of severity.
    pub const ALL: [Status; 8] = [
        Status::Exact,
        Status::Feasible,
        Status::Cancelled,
        Status::Timeout,
        Status::Infeasible,
        Status::Unreachable,
        Status::InvalidGoal,
        Status::InvalidStart,
    ];

    /// Exact and feasible plans can be flown; everything else cannot.
    pub fn is_success(self) -> bool {
        matches!(self, Status::Exact | Status::Feasible)
    }

    /// The process exit code the CLI uses: 0 for a plan that can be flown, 130 for a run the
    /// user interrupted, 1 otherwise.
    pub fn exit_code(self) -> i32 {
        match self {
            s if s.is_success() => 0,
            Status::Cancelled => 130,
            _ => 1,
        }
    }
}

impl std::fmt::Display for Status {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.id())
    }
}
