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

    /// [`Population::initial`] with every row repaired by the objective, and its costs: how
    /// most optimizers start. (Repairs end with the run's clock: [`Context::repair`].)
    pub fn initial_evaluated(size: usize, ctx: &mut Context<'_>) -> (Self, Vec<f64>) {
        let mut pop = Self::initial(size, ctx);
        for i in 0..size {
            ctx.repair(pop.row_mut(i));
        }
        let mut cost = vec![f64::INFINITY; size];
        ctx.evaluate_population(&pop, &mut cost);
        (pop, cost)
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

    pub fn as_flat_mut(&mut self) -> &mut [f64] {
        &mut self.data
    }

    /// Rows `i` and `j` (`i < j`), both mutable.
    pub fn two_rows_mut(&mut self, i: usize, j: usize) -> (&mut [f64], &mut [f64]) {
        assert!(i < j, "two_rows_mut({i}, {j})");
        let (head, tail) = self.data.split_at_mut(j * self.dim);
        (&mut head[i * self.dim..(i + 1) * self.dim], &mut tail[..self.dim])
    }

    pub fn rows(&self) -> impl Iterator<Item = &[f64]> {
        self.data.chunks_exact(self.dim.max(1))
    }

    /// Copies row `src` of `other` into row `dst` of `self`.
    pub fn copy_row_from(&mut self, dst: usize, other: &Population, src: usize) {
        self.row_mut(dst).copy_from_slice(other.row(src));
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn two_rows_mut_are_the_rows() {
        let mut p = Population::zeros(4, 3);
        p.as_flat_mut().iter_mut().enumerate().for_each(|(k, v)| *v = k as f64);
        let (a, b) = p.two_rows_mut(1, 3);
        assert_eq!((&a[..], &b[..]), (&[3.0, 4.0, 5.0][..], &[9.0, 10.0, 11.0][..]));
        a[0] = -1.0;
        b[2] = -2.0;
        assert_eq!(p.row(1)[0], -1.0);
        assert_eq!(p.row(3)[2], -2.0);
    }
}
