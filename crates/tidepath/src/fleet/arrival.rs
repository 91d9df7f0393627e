//! When a fleet's vehicles reach their goals: together within a tolerance, or in a given
//! order. A vehicle arrives when its timed path reaches its goal; a vehicle that gets there
//! early and waits has still arrived early (waiting is not arriving together).

/// What the fleet's arrival times must satisfy.
#[derive(Clone, Debug, Default, PartialEq)]
pub enum Arrival {
    /// No constraint.
    #[default]
    Free,
    /// All arrivals within `tolerance_s` of each other (the spread, last minus first).
    Together { tolerance_s: f64 },
    /// Arrivals in this order of mission indices (each no earlier than the one before).
    Order(Vec<usize>),
}

/// The fleet's arrivals: the spread and, when the rule is broken, why.
#[derive(Clone, Debug, PartialEq)]
pub struct ArrivalCheck {
    /// Last arrival minus first (s).
    pub spread_s: f64,
    /// (mission, arrival time) of the first and the last to arrive.
    pub first: (usize, f64),
    pub last: (usize, f64),
    /// How far past the rule the arrivals are (s): the spread beyond the tolerance, or the
    /// total of the out-of-order gaps; 0 when the rule holds.
    pub excess_s: f64,
    /// One line when the rule is broken (mission indices in `{i}` placeholders are not used:
    /// the caller names them).
    pub broken: Option<Broken>,
}

/// How the arrival rule was broken.
#[derive(Clone, Debug, PartialEq)]
pub enum Broken {
    /// The spread exceeds the tolerance.
    Spread { tolerance_s: f64 },
    /// Mission `later` (in the order) arrived `by_s` seconds before mission `earlier`.
    Order { earlier: usize, later: usize, by_s: f64 },
}

/// Checks `arrivals` (mission index, arrival time) against `rule`; `None` with fewer than
/// two arrivals.
pub fn check_arrivals(rule: &Arrival, arrivals: &[(usize, f64)]) -> Option<ArrivalCheck> {
    if arrivals.len() < 2 {
        return None;
    }
    let first = *arrivals.iter().min_by(|a, b| a.1.total_cmp(&b.1).then(a.0.cmp(&b.0)))?;
    let last = *arrivals.iter().max_by(|a, b| a.1.total_cmp(&b.1).then(b.0.cmp(&a.0)))?;
    let spread_s = last.1 - first.1;
    let (excess_s, broken) = match rule {
        Arrival::Free => (0.0, None),
        Arrival::Together { tolerance_s } => {
            let excess = (spread_s - tolerance_s).max(0.0);
            (excess, (excess > 0.0).then_some(Broken::Spread { tolerance_s: *tolerance_s }))
        }
        Arrival::Order(order) => {
            let at = |i: usize| arrivals.iter().find(|a| a.0 == i).map(|a| a.1);
            let mut excess = 0.0;
            let mut broken = None;
            for w in order.windows(2) {
                if let (Some(a), Some(b)) = (at(w[0]), at(w[1])) {
                    if b < a {
                        excess += a - b;
                        broken.get_or_insert(Broken::Order { earlier: w[0], later: w[1], by_s: a - b });
                    }
                }
            }
            (excess, broken)
        }
    };
    Some(ArrivalCheck { spread_s, first, last, excess_s, broken })
}

/// The joint objective's penalty for broken arrivals: the separation penalty's 10, plus as
/// much again for every [`ARRIVAL_PENALTY_SCALE_S`] of excess. Unbounded and linear, so an
/// optimizer is led toward the rule from any spread: an hour apart costs more than half an
/// hour, and shortening the spread by a second is worth more than the time term's loss when a
/// vehicle slows down by that second (its weight per second is 1 / the straight time, hours).
pub fn arrival_penalty(check: &ArrivalCheck) -> f64 {
    if check.broken.is_none() {
        return 0.0;
    }
    super::SEPARATION_PENALTY * (1.0 + check.excess_s / ARRIVAL_PENALTY_SCALE_S)
}

/// Excess arrival time (s) that costs as much as one violation: ten minutes.
pub const ARRIVAL_PENALTY_SCALE_S: f64 = 600.0;
