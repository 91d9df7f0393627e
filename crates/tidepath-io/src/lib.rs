//! Scenarios and files for tidepath, above the planning core and below the command line:
//!
//! * [`scenario`]: scenario TOML files and the built-in scenarios, geographic scenarios with
//!   their data files, and the `plan` and `eval` entry points every front end shares;
//! * [`geodata`]: bathymetry (NetCDF, GeoTIFF, ESRI ASCII) and current forecasts (NetCDF),
//!   read only inside the box a scenario needs;
//! * [`plan_json`]: the plan file `plan --out` writes and `eval` and `plan --init` read, with
//!   [`fleet_report`] for a fleet's separation and arrivals;
//! * [`graph_file`]: a planner's search graphs as `plan --graph` writes them (GraphML, JSON);
//! * [`export`]: GIS exports (GeoJSON, CSV, KML, GPX), written with `geojson`, `csv` and
//!   `quick-xml` ([`csv_table`] is the one CSV writer);
//! * [`simulation`]: `simulate` on a scenario and the simulation file it writes;
//! * [`input`], [`output`]: input files read defensively, output files written all or none.
//!
//! The core (`tidepath`) carries no file-format dependency: every reader and writer of a file
//! format lives here.

pub mod csv_table;
pub mod export;
pub mod fleet_report;
pub mod geodata;
pub mod graph_file;
pub mod input;
pub mod output;
pub mod plan_json;
pub mod routes;
pub mod scenario;
pub mod simulation;

pub use fleet_report::{ApproachReport, ArrivalReport, FleetReport};
pub use output::{write_atomic, OutputId, Outputs};
pub use plan_json::{GraphReport, MissionReport, PlanAbout, PlanFile, PlanReport, RouteFrame, PLAN_FORMAT_VERSION};
