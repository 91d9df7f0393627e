//! max |v_c| of eq. 18, computed once per world rather than per evaluation.
//!
//! A cost model is built from its parameters alone and meets the world only through the
//! [`PathModel`] of each evaluation, so the peak cannot be computed at build time. It is
//! [`Current::max_speed_hint`] over the domain at the mission's departure time: exact for a
//! uniform current (and still water), a scan of the nodes for a gridded forecast, 4096 samples
//! for a jet or vortices. The cheap cases are computed each time; the others are cached per
//! thread (no lock, so parallel evaluations do not contend), at most [`SLOTS`] worlds, keyed
//! by what the value depends on:
//!
//! - a jet or vortices: the field itself, compared by value (a few dozen numbers), with the
//!   domain box and the time;
//! - a gridded forecast: its geometry and layer times by value, the addresses of its layers,
//!   and [`GRID_SAMPLES`] node values spread over all its layers. Comparing a whole forecast
//!   by value would cost as much as the scan; the samples make a forecast rebuilt in the same
//!   memory with other values (a newer forecast in `simulate`) a miss. Two forecasts that
//!   share addresses, geometry, times and every sampled value but differ elsewhere would share
//!   a peak: not a case tidepath's scenarios can build.
//!
//! The value is a pure function of the current, the box and the time, so every thread finds
//! the same number and plans stay reproducible on any number of threads.

use crate::geom::Aabb;
use crate::path::PathModel;
use crate::world::current::{CurrentGrid, LambOseen, MeanderingJet};
use crate::world::{Current, RegularGrid2};
use std::cell::RefCell;

/// Worlds remembered per thread.
const SLOTS: usize = 8;
/// Node values compared, in all, to tell gridded forecasts apart (half from u, half from v).
pub const GRID_SAMPLES: usize = 64;

#[derive(Debug, PartialEq)]
enum Field {
    Jet(MeanderingJet),
    Vortices(Vec<LambOseen>),
    Grid(Box<GridKey>),
}

#[derive(Debug, PartialEq)]
struct GridKey {
    grid: RegularGrid2,
    times: Vec<f64>,
    layers: [usize; 2],
    samples: [f64; GRID_SAMPLES],
}

#[derive(Debug)]
struct Slot {
    field: Field,
    bounds: Aabb,
    time_bits: u64,
    peak: f64,
}

thread_local! {
    static CACHE: RefCell<(Vec<Slot>, usize)> = const { RefCell::new((Vec::new(), 0)) };
}

/// The flat index `k` of `GRID_SAMPLES / 2` nodes spread over `layers` layers of `n` nodes.
#[inline]
fn sample_index(k: usize, layers: usize, n: usize) -> (usize, usize) {
    let total = layers * n;
    let flat = (k * total) / (GRID_SAMPLES / 2) + (total / GRID_SAMPLES);
    let flat = flat.min(total - 1);
    (flat / n, flat % n)
}

fn grid_samples(g: &CurrentGrid) -> [f64; GRID_SAMPLES] {
    let mut out = [0.0; GRID_SAMPLES];
    let layers = g.u.len().min(g.v.len());
    let n = g.u.first().map_or(0, Vec::len);
    if layers == 0 || n == 0 {
        return out;
    }
    for k in 0..GRID_SAMPLES / 2 {
        let (l, i) = sample_index(k, layers, n);
        out[2 * k] = g.u[l].get(i).copied().unwrap_or(0.0);
        out[2 * k + 1] = g.v[l].get(i).copied().unwrap_or(0.0);
    }
    out
}

/// Does `field` describe `current`? Allocation-free.
fn same(field: &Field, current: &Current) -> bool {
    match (field, current) {
        (Field::Jet(a), Current::Jet(b)) => a == b,
        (Field::Vortices(a), Current::Vortices(b)) => a == b,
        (Field::Grid(k), Current::Grid(g)) => {
            k.grid == g.grid
                && k.times == g.times
                && k.layers == [g.u.as_ptr() as usize, g.v.as_ptr() as usize]
                && k.samples == grid_samples(g)
        }
        _ => false,
    }
}

fn key(current: &Current) -> Option<Field> {
    Some(match current {
        Current::Jet(j) => Field::Jet(j.clone()),
        Current::Vortices(v) => Field::Vortices(v.clone()),
        Current::Grid(g) => Field::Grid(Box::new(GridKey {
            grid: g.grid.clone(),
            times: g.times.clone(),
            layers: [g.u.as_ptr() as usize, g.v.as_ptr() as usize],
            samples: grid_samples(g),
        })),
        Current::None | Current::Uniform(_) => return None,
    })
}

/// max |v_c| (m/s, horizontal) over the domain of `model`'s world at its departure time.
pub fn peak_current(model: &PathModel<'_>) -> f64 {
    let world = model.world;
    let t = model.departure_time;
    let current = &world.current;
    match current {
        Current::None => return 0.0,
        Current::Uniform(v) => return v.x.hypot(v.y),
        Current::Jet(_) | Current::Vortices(_) | Current::Grid(_) => {}
    }
    CACHE.with(|cell| {
        let mut cache = cell.borrow_mut();
        let (slots, next) = &mut *cache;
        let bits = t.to_bits();
        if let Some(s) =
            slots.iter().find(|s| s.time_bits == bits && s.bounds == world.bounds && same(&s.field, current))
        {
            return s.peak;
        }
        let peak = current.max_speed_hint(&world.bounds, t);
        let field = key(current).expect("a field worth caching");
        let slot = Slot { field, bounds: world.bounds, time_bits: bits, peak };
        if slots.len() < SLOTS {
            slots.push(slot);
        } else {
            slots[*next] = slot;
            *next = (*next + 1) % SLOTS;
        }
        peak
    })
}

/// Worlds cached on this thread (for tests).
#[cfg(test)]
pub fn cached() -> usize {
    CACHE.with(|c| c.borrow().0.len())
}
