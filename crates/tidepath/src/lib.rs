//! tidepath: safe, fast, energy-aware routes for marine robots.
//!
//! The crate is layered so that each layer knows only the ones below it:
//!
//! * [`world`]: seabed, obstacles, currents and waves, answering questions at a point and time;
//! * [`vehicle`]: what the robot can do (speed, turning, pitch, depth, safety distance);
//! * [`path`]: the one shared evaluation of a path (length, travel time, angles, clearance,
//!   feasibility) that planners, `eval` and experiments all use;
//! * [`cost`]: cost models, one file per paper, each a sum of named terms;
//! * [`encoding`]: decision vectors to paths, owning their bounds and repair;
//! * [`optim`]: box-bounded minimisers that only see a vector and a cost, driven by one runner;
//! * [`planner`]: encoding + cost model + optimizer, selected by id;
//! * [`scenario`]: TOML scenario files and the built-in scenarios;
//! * [`io`]: the plan JSON format;
//! * [`plot`]: SVG figures.

pub mod config;
pub mod cost;
pub mod encoding;
pub mod error;
pub mod experiments;
pub mod geom;
pub mod io;
pub mod mission;
pub mod optim;
pub mod path;
pub mod planner;
pub mod plot;
pub mod registry;
pub mod rng;
pub mod scenario;
pub mod smoothing;
pub mod termination;
pub mod validity;
pub mod vehicle;
pub mod world;

pub use error::{Error, Result};
pub use geom::{Aabb, Vec2, Vec3};
