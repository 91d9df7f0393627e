//! A population stored as one flat row-major matrix: cache friendly and cheap to split across
//! rayon workers.

use rand::Rng as _;

use super::Context;

#[derive(Clone, Debug, PartialEq)]
pub struct Population {
    dim: usize,
    data: Vec<f64>,
}

impl Population {
    pub fn zeros(size: usize, dim: usize) -> Self {
        Self { dim, data: vec![0.0; size * dim] }
    }

    /// `size` points drawn uniformly in the box, dimension by dimension, point by point.
    pub fn uniform(size: usize, ctx: &mut Context<'_>) -> Self {
        let dim = ctx.dim();
        let mut pop = Self::zeros(size, dim);
        for i in 0..size {
            for d in 0..dim {
                let (lo, hi) = (ctx.lower()[d], ctx.upper()[d]);
                let u: f64 = ctx.rng().random();
                pop.row_mut(i)[d] = lo + u * (hi - lo);
            }
        }
        pop
    }

    /// The initial population of an optimizer: `size` uniform points, of which the first rows
    /// are replaced by the run's warm-start points (at most half the population, so a warm
    /// start guides the search without collapsing its diversity). The uniform draws happen
    /// either way, so a warm start changes no later random number.
    pub fn initial(size: usize, ctx: &mut Context<'_>) -> Self {
        let mut pop = Self::uniform(size, ctx);
        let k = ctx.seeds().len().min((size / 2).max(1)).min(size);
        for i in 0..k {
            pop.row_mut(i).copy_from_slice(&ctx.seeds()[i]);
        }
        pop
    }

    pub fn dim(&self) -> usize {
        self.dim
    }

    pub fn len(&self) -> usize {
        self.data.len().checked_div(self.dim).unwrap_or(0)
    }

    pub fn is_empty(&self) -> bool {
        self.data.is_empty()
    }

    pub fn row(&self, i: usize) -> &[f64] {
        &self.data[i * self.dim..(i + 1) * self.dim]
    }

    pub fn row_mut(&mut self, i: usize) -> &mut [f64] {
        &mut self.data[i * self.dim..(i + 1) * self.dim]
    }

    pub fn as_flat(&self) -> &[f64] {
        &self.data
    }

    pub fn rows(&self) -> impl Iterator<Item = &[f64]> {
        self.data.chunks_exact(self.dim.max(1))
    }

    /// Copies row `src` of `other` into row `dst` of `self`.
    pub fn copy_row_from(&mut self, dst: usize, other: &Population, src: usize) {
        self.row_mut(dst).copy_from_slice(other.row(src));
    }
}
