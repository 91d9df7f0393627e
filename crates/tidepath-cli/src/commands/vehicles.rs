//! `tidepath vehicles`: the vehicle kinds and the speed model of each, so a user can see what
//! sets a plan's clock: a thruster vehicle's chosen through-water speed combined with the
//! current, or a wave glider's regression on the sea state (acopf2016 eqs. 1-2, after Ngo et
//! al.), its keys read from their one declaration ([`GliderSpeed::PARAMS`]).

use tidepath::validity::TravelModel;
use tidepath::vehicle::{GliderSpeed, Vehicle};
use tidepath::Error;

use crate::Outcome;

/// The column the descriptions start at.
const ID_W: usize = 11;

pub fn list() -> Result<Outcome, Error> {
    println!("Vehicles ([vehicle] kind = \"ID\") and the speed over ground each flies at:");
    let auv = Vehicle::default();
    let travel = [TravelModel::Crab, TravelModel::VectorSum].map(|t| format!("\"{}\"", t.id())).join(" or ");
    println!("  {:<ID_W$} thrusters (the default): a through-water speed the plan chooses", "auv");
    println!(
        "  {:<ID_W$} ([vehicle] speed, default {} m/s, or one per segment in [speed_min, speed_max]),",
        "", auv.speed
    );
    println!("  {:<ID_W$} combined with the current by [model] travel = {travel} (default \"crab\")", "");
    println!();
    let g = GliderSpeed::default();
    println!("  {:<ID_W$} driven by the waves, no throttle [acopf2016 eqs. 1-2, after Ngo et al.]", "wave-glider");
    println!("  {:<ID_W$} {}", "", g.formula());
    println!("  {:<ID_W$} needs a 2-D world with [world.waves]; speed, speed_min and speed_max do not apply", "");
    for p in GliderSpeed::PARAMS {
        println!("      {:<22} {}", p.name, p.help());
        println!("      {:<22} {}; default {}; from {}", "", p.range, p.default_text(), p.source);
    }
    println!("  {:<ID_W$} reading of the paper:", "");
    for line in [
        "eq. 2 reprints eq. 1's current coefficient 0.2660 as 0.2260: read as a misprint (0.2660 kept)",
        "x_hfr read as the current against the heading, so its negative coefficient makes a following",
        "  current speed the glider up (+0.2660 c_along), as acopf2016's own heuristic (eq. 10) rewards",
        "the regression has no intercept: min_speed keeps calm water from stopping the clock",
        "a head current that outweighs the waves drives the glider back: that stretch is invalid",
    ] {
        println!("  {:<ID_W$}   {line}", "");
    }
    Ok(Outcome::Success)
}
