//! tidepath: safe, fast, energy-aware routes for marine robots. This is the core library; it
//! has no plotting or statistics dependency (those are `tidepath-plot` and
//! `tidepath-experiments`, above it).
//!
//! Each top-level module is a layer that uses only the layers below it: shared basics (vectors,
//! errors, TOML decoding, seeded streams) at the bottom, the world model and what is valid in
//! it above them, then path evaluation, costs and encodings, then optimizers and planners, and
//! files and scenarios (the `plan` and `eval` entry points) at the top. The exact order is
//! written once, as `ORDER` in `tests/layers.rs`, which checks every crate path in the
//! non-test code against it.

pub mod config;
pub mod cost;
pub mod encoding;
pub mod error;
pub mod fleet;
pub mod geo;
pub mod geom;
pub mod kinematics;
pub mod mission;
pub mod optim;
pub mod params;
pub mod path;
pub mod planner;
pub mod raster;
pub mod registry;
pub mod repair;
pub mod rng;
pub mod scratch;
pub mod simulate;
pub mod smoothing;
pub mod termination;
pub mod text;
pub mod validity;
pub mod vehicle;
pub mod world;

pub use error::{Error, Result};
pub use geom::{Aabb, Vec2, Vec3};
