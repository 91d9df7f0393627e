//! The repair operators of [`crate::repair`] (amfa2015's excluding and contracting) as
//! smoothers applied after a planner: the repair runs on a copy of the path, and the copy is
//! kept only if it honours the [`Smoother`] contract: no costlier under the scenario's cost
//! model and not infeasible when the input was feasible. An infeasible input the repair makes
//! feasible is always kept.

use super::Smoother;
use crate::cost::CostModel;
use crate::error::Result;
use crate::geom::Vec3;
use crate::path::PathModel;
use crate::repair::Repair;
use crate::scratch::Scratch;
use crate::termination::Termination;

/// A repair applied once to a plan, kept when it helps.
pub struct RepairSmoother {
    repair: Box<dyn Repair>,
}

impl RepairSmoother {
    pub fn new(repair: Box<dyn Repair>) -> Self {
        Self { repair }
    }

    /// Repair `id` with its `[planner.smoother_params.ID]` table (errors name `prefix`).
    pub fn build(id: &str, table: &toml::Table, prefix: &str) -> Result<Box<dyn Smoother>> {
        Ok(Box::new(Self::new(crate::repair::build_repair_prefixed(id, Some(table), prefix)?)))
    }
}

impl Smoother for RepairSmoother {
    fn id(&self) -> &'static str {
        self.repair.id()
    }

    fn smooth(
        &self,
        model: &PathModel<'_>,
        cost: &dyn CostModel,
        points: &[Vec3],
        termination: &Termination,
    ) -> Vec<Vec3> {
        // One repair is a handful of point queries: poll once, before it.
        if termination.interrupted().is_some() || points.len() < 3 {
            return points.to_vec();
        }
        let mut repaired = points.to_vec();
        self.repair.apply(model, &mut repaired);
        if repaired == points {
            return repaired;
        }
        let mut scratch = Scratch::default();
        let was_feasible = model.assess(points, &mut scratch.times).feasible();
        let feasible = model.assess(&repaired, &mut scratch.times).feasible();
        let keep = if was_feasible {
            feasible && cost.cost(model, &repaired, &mut scratch) <= cost.cost(model, points, &mut scratch)
        } else {
            feasible || cost.cost(model, &repaired, &mut scratch) <= cost.cost(model, points, &mut scratch)
        };
        if keep {
            repaired
        } else {
            points.to_vec()
        }
    }
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
    use rand::Rng as _;

    /// Random paths through a box with spheres, each smoothed by every repair smoother: never
    /// costlier, never infeasible from a feasible input, endpoints kept.
    #[test]
    fn repair_smoothers_honour_the_smoother_contract() {
        let mut w = World::open(Aabb::new(Vec3::new(0.0, 0.0, -100.0), Vec3::new(100.0, 100.0, 0.0)));
        for (c, r) in [((30.0, 40.0, -50.0), 12.0), ((65.0, 60.0, -40.0), 15.0), ((50.0, 20.0, -70.0), 8.0)] {
            w.obstacles.push(Obstacle::fixed(Shape::Sphere { center: Vec3::new(c.0, c.1, c.2), radius: r }));
        }
        let v = Vehicle {
            max_turn: std::f64::consts::PI,
            max_pitch: 1.5,
            safety_distance: 1.0,
            depth_max: 100.0,
            ..Vehicle::default()
        };
        let (s, g) = (Vec3::new(5.0, 5.0, -50.0), Vec3::new(95.0, 95.0, -50.0));
        let mission = Mission::new("m", v, s, g, 0.0);
        let settings = ModelSettings::default();
        let model = PathModel::new(&w, &mission, &settings);
        let cost = GeneralCost::new(GeneralWeights::default().checked("cost.weights").unwrap());
        let smoothers: Vec<Box<dyn Smoother>> = ["exclude", "contract", "exclude-contract"]
            .iter()
            .map(|id| super::super::build_smoother(id, None).unwrap())
            .collect();
        let mut rng = crate::rng::run_rng(7, 0);
        let mut scratch = Scratch::default();
        let (mut kept, mut feasible_inputs) = (0, 0);
        for trial in 0..200 {
            let n = 2 + trial % 8;
            let mut p = vec![s];
            for k in 0..n {
                let f = (k + 1) as f64 / (n + 1) as f64;
                let base = s.lerp(g, f);
                let jitter = if trial % 2 == 0 { 10.0 } else { 40.0 };
                let d = Vec3::new(rng.random::<f64>() - 0.5, rng.random::<f64>() - 0.5, rng.random::<f64>() - 0.5);
                p.push((base + d * jitter).clamp(Vec3::new(0.0, 0.0, -100.0), Vec3::new(100.0, 100.0, 0.0)));
            }
            p.push(g);
            let before = cost.cost(&model, &p, &mut scratch);
            let was_feasible = model.assess(&p, &mut scratch.times).feasible();
            feasible_inputs += was_feasible as usize;
            for sm in &smoothers {
                let out = sm.smooth(&model, &cost, &p, &Termination::default());
                assert_eq!((out[0], *out.last().unwrap()), (s, g));
                let feasible = model.assess(&out, &mut scratch.times).feasible();
                let after = cost.cost(&model, &out, &mut scratch);
                assert!(after <= before || (feasible && !was_feasible), "{}: {after} > {before}", sm.id());
                assert!(feasible || !was_feasible, "{} broke feasibility", sm.id());
                kept += (out != p) as usize;
            }
        }
        assert!(kept > 0 && feasible_inputs > 0, "kept {kept}, feasible inputs {feasible_inputs}");
    }
}
