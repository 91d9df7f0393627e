//! The bridge from a path problem to the optimizer's view: a bounded vector and a cost. With
//! several missions the vector is the concatenation of each mission's encoding and the cost is
//! the sum of the missions' costs.

use super::Problem;
use crate::encoding::Encoding;
use crate::optim::{Objective, Scratch};
use crate::path::PathModel;

pub struct PathObjective<'a> {
    problem: &'a Problem<'a>,
    models: Vec<PathModel<'a>>,
    encodings: Vec<Box<dyn Encoding>>,
    /// Mission i's variables are x[offsets[i]..offsets[i + 1]].
    offsets: Vec<usize>,
    lower: Vec<f64>,
    upper: Vec<f64>,
}

impl<'a> PathObjective<'a> {
    /// `encodings[i]` encodes mission i.
    pub fn new(problem: &'a Problem<'a>, encodings: Vec<Box<dyn Encoding>>) -> Self {
        let models = (0..problem.missions.len()).map(|i| problem.path_model(i)).collect();
        let mut offsets = vec![0];
        let (mut lower, mut upper) = (Vec::new(), Vec::new());
        for e in &encodings {
            lower.extend_from_slice(e.lower());
            upper.extend_from_slice(e.upper());
            offsets.push(lower.len());
        }
        Self { problem, models, encodings, offsets, lower, upper }
    }

    /// One path per mission for the vector `x`.
    pub fn decode(&self, x: &[f64]) -> Vec<Vec<crate::geom::Vec3>> {
        self.encodings.iter().enumerate().map(|(i, e)| e.decode(&x[self.offsets[i]..self.offsets[i + 1]])).collect()
    }

    /// The vector whose paths follow `paths` (one per mission), for a warm start.
    pub fn encode(&self, paths: &[Vec<crate::geom::Vec3>]) -> Option<Vec<f64>> {
        if paths.len() != self.encodings.len() || paths.iter().any(|p| p.len() < 2) {
            return None;
        }
        Some(self.encodings.iter().zip(paths).flat_map(|(e, p)| e.encode(p)).collect())
    }
}

impl PathObjective<'_> {
    /// The missions' costs plus the fleet's separation penalty ([`crate::fleet::FleetCheck::penalty`]),
    /// every path decoded into its own reused buffer so all are at hand for the pairwise check.
    fn evaluate_fleet(&self, x: &[f64], scratch: &mut Scratch) -> f64 {
        let mut paths = std::mem::take(&mut scratch.paths);
        let mut legs = std::mem::take(&mut scratch.legs);
        paths.resize_with(self.encodings.len(), Vec::new);
        let mut total = 0.0;
        for (i, e) in self.encodings.iter().enumerate() {
            e.decode_into(&x[self.offsets[i]..self.offsets[i + 1]], &mut paths[i]);
            total += self.problem.cost.cost(&self.models[i], &paths[i], scratch);
        }
        total += crate::fleet::check(&self.models, &paths, self.problem.fleet, &mut legs).penalty();
        scratch.paths = paths;
        scratch.legs = legs;
        total
    }
}

impl Objective for PathObjective<'_> {
    fn dim(&self) -> usize {
        self.lower.len()
    }

    fn lower(&self) -> &[f64] {
        &self.lower
    }

    fn upper(&self) -> &[f64] {
        &self.upper
    }

    fn evaluate(&self, x: &[f64], scratch: &mut Scratch) -> f64 {
        if self.problem.fleet.active(self.encodings.len()) {
            return self.evaluate_fleet(x, scratch);
        }
        // Move the point buffer out so the cost model can borrow the rest of the scratch;
        // moving a Vec does not allocate.
        let mut points = std::mem::take(&mut scratch.points);
        let mut total = 0.0;
        for (i, e) in self.encodings.iter().enumerate() {
            e.decode_into(&x[self.offsets[i]..self.offsets[i + 1]], &mut points);
            total += self.problem.cost.cost(&self.models[i], &points, scratch);
        }
        scratch.points = points;
        total
    }

    fn repair(&self, x: &mut [f64]) {
        for (i, e) in self.encodings.iter().enumerate() {
            e.repair(&mut x[self.offsets[i]..self.offsets[i + 1]]);
        }
    }

    fn parallel_hint(&self) -> bool {
        true
    }
}
