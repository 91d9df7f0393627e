//! Greedy shortcutting (the deterministic form of OMPL's `PathSimplifier::reduceVertices`):
//! from each waypoint, jump to the farthest later waypoint such that the shortened path is no
//! costlier under the scenario's own cost model and no less feasible. Judging by the full cost
//! model (not only by length) keeps detours that pay off, such as riding a favourable current.

use super::Smoother;
use crate::cost::CostModel;
use crate::geom::Vec3;
use crate::params::{Checked, Range};
use crate::path::PathModel;
use crate::scratch::Scratch;
use crate::termination::Termination;

crate::params! {
    /// Shortcut parameters.
    pub struct ShortcutParams {
        /// Greedy passes over the path; a later pass may drop points an earlier one kept,
        /// since the path it judges has changed.
        passes: usize = 1, Range::integer(1, 100), "tidepath";
    }
}

#[derive(Clone, Debug, Default)]
pub struct Shortcut {
    params: ShortcutParams,
}

impl Shortcut {
    pub fn new(params: Checked<ShortcutParams>) -> Self {
        Self { params: params.into_inner() }
    }
}

impl Smoother for Shortcut {
    fn id(&self) -> &'static str {
        "shortcut"
    }

    fn smooth(
        &self,
        model: &PathModel<'_>,
        cost: &dyn CostModel,
        points: &[Vec3],
        termination: &Termination,
    ) -> Vec<Vec3> {
        let mut path = points.to_vec();
        for _ in 0..self.params.passes {
            let before = path.len();
            path = one_pass(model, cost, &path, termination);
            if path.len() == before || termination.interrupted().is_some() {
                break;
            }
        }
        path
    }
}

/// One greedy pass: from each waypoint, jump to the farthest later one whose bypass is no
/// costlier and no less feasible.
fn one_pass(model: &PathModel<'_>, cost: &dyn CostModel, points: &[Vec3], termination: &Termination) -> Vec<Vec3> {
    let mut scratch = Scratch::default();
    let mut path = points.to_vec();
    let mut best = cost.cost(model, &path, &mut scratch);
    let mut best_feasible = model.assess(&path, &mut scratch.times).feasible();
    let mut candidate = Vec::with_capacity(path.len());
    let mut i = 0;
    while i + 2 < path.len() {
        for j in (i + 2..path.len()).rev() {
            // Every candidate is a whole path evaluation: poll before each.
            if termination.interrupted().is_some() {
                return path;
            }
            candidate.clear();
            candidate.extend_from_slice(&path[..=i]);
            candidate.extend_from_slice(&path[j..]);
            let feasible = model.assess(&candidate, &mut scratch.times).feasible();
            if best_feasible && !feasible {
                continue;
            }
            let c = cost.cost(model, &candidate, &mut scratch);
            if c <= best || (feasible && !best_feasible) {
                std::mem::swap(&mut path, &mut candidate);
                best = c;
                best_feasible = feasible;
                break;
            }
        }
        i += 1;
    }
    path
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::cost::{GeneralCost, GeneralWeights};
    use crate::geom::Aabb;
    use crate::mission::Mission;
    use crate::path::ModelSettings;
    use crate::vehicle::Vehicle;
    use crate::world::{Obstacle, Shape, World};

    fn setup() -> (World, Vehicle, ModelSettings) {
        let w = World::open(Aabb::new(Vec3::new(0.0, 0.0, -100.0), Vec3::new(100.0, 100.0, 0.0)));
        let v = Vehicle { max_turn: std::f64::consts::PI, safety_distance: 1.0, ..Vehicle::default() };
        (w, v, ModelSettings::default())
    }

    #[test]
    fn zigzag_in_open_water_becomes_straight() {
        let (w, v, s) = setup();
        let p: Vec<Vec3> =
            (0..=10).map(|i| Vec3::new(i as f64 * 9.0, 50.0 + if i % 2 == 1 { 5.0 } else { 0.0 }, -50.0)).collect();
        let mission = Mission::new("m", v, p[0], p[10], 0.0);
        let m = PathModel::new(&w, &mission, &s);
        let cost = GeneralCost::new(GeneralWeights::default().checked("cost.weights").unwrap());
        let out = Shortcut::default().smooth(&m, &cost, &p, &Termination::default());
        assert_eq!(out, vec![p[0], p[10]]);
    }

    #[test]
    fn keeps_the_detour_around_an_obstacle() {
        let (mut w, v, s) = setup();
        w.obstacles.push(Obstacle::fixed(Shape::Sphere { center: Vec3::new(50.0, 50.0, -50.0), radius: 10.0 }));
        let p = vec![
            Vec3::new(10.0, 50.0, -50.0),
            Vec3::new(30.0, 70.0, -50.0),
            Vec3::new(50.0, 70.0, -50.0),
            Vec3::new(70.0, 70.0, -50.0),
            Vec3::new(90.0, 50.0, -50.0),
        ];
        let mission = Mission::new("m", v, p[0], p[4], 0.0);
        let m = PathModel::new(&w, &mission, &s);
        let cost = GeneralCost::new(GeneralWeights::default().checked("cost.weights").unwrap());
        let before = cost.cost(&m, &p, &mut Scratch::default());
        let out = Shortcut::default().smooth(&m, &cost, &p, &Termination::default());
        let mut times = Vec::new();
        assert!(m.assess(&out, &mut times).feasible(), "smoothing broke feasibility: {out:?}");
        assert!(out.len() < p.len() && out.len() > 2, "{out:?}");
        assert!(cost.cost(&m, &out, &mut Scratch::default()) <= before);
        assert_eq!((out[0], *out.last().unwrap()), (p[0], p[4]));
    }
}
