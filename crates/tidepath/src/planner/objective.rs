//! The bridge from a path problem to the optimizer's view: a bounded vector and a cost. With
//! several missions the vector is the concatenation of each mission's variables and the cost is
//! the sum of the missions' costs (plus the fleet's penalties).
//!
//! A mission's variables are its encoding's, then, when its vehicle has a speed range, one
//! through-water speed per segment of the decoded path, in m/s within the range (ijs2023
//! leaves open how speeds enter the decision vector; this is our reading: plain bounded
//! variables, so every optimizer searches them like coordinates and the bounds repair clamps
//! them). A vehicle without a range adds none, so such problems are unchanged.

use super::Problem;
use crate::encoding::Encoding;
use crate::optim::{Objective, Scratch};
use crate::path::PathModel;

pub struct PathObjective<'a> {
    problem: &'a Problem<'a>,
    models: Vec<PathModel<'a>>,
    encodings: Vec<Box<dyn Encoding>>,
    /// Mission i's variables are x[offsets[i]..offsets[i + 1]]: its encoding's, then
    /// `speed_genes[i]` segment speeds.
    offsets: Vec<usize>,
    speed_genes: Vec<usize>,
    lower: Vec<f64>,
    upper: Vec<f64>,
}

impl<'a> PathObjective<'a> {
    /// `encodings[i]` encodes mission i.
    pub fn new(problem: &'a Problem<'a>, encodings: Vec<Box<dyn Encoding>>) -> Self {
        let models = (0..problem.missions.len()).map(|i| problem.path_model(i)).collect();
        let mut offsets = vec![0];
        let mut speed_genes = Vec::with_capacity(encodings.len());
        let (mut lower, mut upper) = (Vec::new(), Vec::new());
        for (e, m) in encodings.iter().zip(problem.missions) {
            lower.extend_from_slice(e.lower());
            upper.extend_from_slice(e.upper());
            let genes = match m.vehicle.speed_range {
                Some((lo, hi)) => {
                    let n = e.decode(e.lower()).len().saturating_sub(1);
                    lower.extend(std::iter::repeat_n(lo, n));
                    upper.extend(std::iter::repeat_n(hi, n));
                    n
                }
                None => 0,
            };
            speed_genes.push(genes);
            offsets.push(lower.len());
        }
        Self { problem, models, encodings, offsets, speed_genes, lower, upper }
    }

    /// Mission i's encoding variables and its segment speeds (empty without a range).
    fn split<'x>(&self, x: &'x [f64], i: usize) -> (&'x [f64], &'x [f64]) {
        x[self.offsets[i]..self.offsets[i + 1]].split_at(self.encodings[i].dim())
    }

    /// Mission i's model, flying its segments at `speeds` when it has speed variables.
    fn model<'s>(&'s self, i: usize, speeds: &'s [f64]) -> std::borrow::Cow<'s, PathModel<'s>> {
        if speeds.is_empty() {
            std::borrow::Cow::Borrowed(&self.models[i])
        } else {
            std::borrow::Cow::Owned(self.models[i].with_speeds(Some(speeds)))
        }
    }

    /// One path per mission for the vector `x`.
    pub fn decode(&self, x: &[f64]) -> Vec<Vec<crate::geom::Vec3>> {
        self.encodings.iter().enumerate().map(|(i, e)| e.decode(self.split(x, i).0)).collect()
    }

    /// Each mission's segment speeds in `x`; `None` for a vehicle without a speed range.
    pub fn decode_speeds(&self, x: &[f64]) -> Vec<Option<Vec<f64>>> {
        (0..self.encodings.len())
            .map(|i| {
                let s = self.split(x, i).1;
                (self.speed_genes[i] > 0).then(|| s.to_vec())
            })
            .collect()
    }

    /// The vector whose paths follow `paths` (one per mission), for a warm start; segment
    /// speeds start at the cruise speed.
    pub fn encode(&self, paths: &[Vec<crate::geom::Vec3>]) -> Option<Vec<f64>> {
        if paths.len() != self.encodings.len() || paths.iter().any(|p| p.len() < 2) {
            return None;
        }
        let mut out = Vec::with_capacity(self.lower.len());
        for (i, (e, p)) in self.encodings.iter().zip(paths).enumerate() {
            out.extend(e.encode(p));
            let cruise = self.problem.missions[i].vehicle.speed;
            out.extend(std::iter::repeat_n(cruise, self.speed_genes[i]));
        }
        Some(out)
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
        legs.resize_with(self.encodings.len(), Vec::new);
        for (i, e) in self.encodings.iter().enumerate() {
            let (genes, speeds) = self.split(x, i);
            e.decode_into(genes, &mut paths[i]);
            let model = self.model(i, speeds);
            total += self.problem.cost.cost(&model, &paths[i], scratch);
            crate::fleet::timed_legs(&model, &paths[i], &mut legs[i]);
        }
        total += crate::fleet::check_legs(&legs, self.problem.fleet).penalty();
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
            let (genes, speeds) = self.split(x, i);
            e.decode_into(genes, &mut points);
            total += self.problem.cost.cost(&self.model(i, speeds), &points, scratch);
        }
        scratch.points = points;
        total
    }

    /// Every mission's path judged by the path assessment the cost models use (collisions,
    /// domain and depth band, vehicle limits, current); a fleet's separation and arrival rules
    /// are penalties, not constraints, and are not part of it.
    fn feasible(&self, x: &[f64], scratch: &mut Scratch) -> Option<bool> {
        let mut points = std::mem::take(&mut scratch.points);
        let mut times = std::mem::take(&mut scratch.times);
        let mut all = true;
        for (i, e) in self.encodings.iter().enumerate() {
            let (genes, speeds) = self.split(x, i);
            e.decode_into(genes, &mut points);
            if !self.model(i, speeds).assess(&points, &mut times).feasible() {
                all = false;
                break;
            }
        }
        scratch.points = points;
        scratch.times = times;
        Some(all)
    }

    fn repair(&self, x: &mut [f64]) {
        for (i, e) in self.encodings.iter().enumerate() {
            let (genes, speeds) = x[self.offsets[i]..self.offsets[i + 1]].split_at_mut(e.dim());
            e.repair(genes);
            let lo = &self.lower[self.offsets[i] + e.dim()..self.offsets[i + 1]];
            let hi = &self.upper[self.offsets[i] + e.dim()..self.offsets[i + 1]];
            for ((v, l), h) in speeds.iter_mut().zip(lo).zip(hi) {
                *v = v.clamp(*l, *h);
            }
        }
    }

    fn parallel_hint(&self) -> bool {
        true
    }
}
