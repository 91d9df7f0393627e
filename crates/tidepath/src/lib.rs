//! tidepath: safe, fast, energy-aware routes for marine robots. This is the core library; it
//! has no plotting or statistics dependency (those are `tidepath-plot` and
//! `tidepath-experiments`, above it).
//!
//! Each module knows only the ones listed before it:
//!
//! * [`geom`], [`text`], [`error`], [`geo`], [`config`], [`rng`], [`registry`]: shared basics
//!   (vectors, one-line text, errors that name the field, the latitude/longitude frame, TOML decoding, seeded streams,
//!   the one registry-table type);
//! * [`world`]: seabed, obstacles and currents, answering questions at a point and time;
//! * [`vehicle`], [`mission`]: what the robot can do; where it goes and when it leaves;
//! * [`validity`]: is a state valid at t, is a motion valid leaving at t (on the travel clock);
//! * [`path`]: the one shared evaluation of a path (length, travel time, angles, clearance,
//!   feasibility) that planners, `eval` and experiments all use;
//! * [`cost`]: cost models, one file per paper, each a sum of named terms;
//! * [`encoding`]: decision vectors to paths, owning their bounds and repair;
//! * [`termination`], [`optim`]: when to stop; box-bounded minimisers driven by one runner;
//! * [`planner`], [`smoothing`]: the planner trait, statuses, the planner table, `solve`;
//!   smoothers any plan can go through;
//! * [`io`], [`scenario`]: plan files and safe output files; scenario files and the built-in
//!   scenarios, with `plan` and `eval` entry points.

pub mod config;
pub mod cost;
pub mod encoding;
pub mod error;
pub mod geo;
pub mod geom;
pub mod io;
pub mod mission;
pub mod optim;
pub mod path;
pub mod planner;
pub mod raster;
pub mod registry;
pub mod rng;
pub mod scenario;
pub mod scratch;
pub mod smoothing;
pub mod termination;
pub mod text;
pub mod validity;
pub mod vehicle;
pub mod world;

pub use error::{Error, Result};
pub use geom::{Aabb, Vec2, Vec3};
