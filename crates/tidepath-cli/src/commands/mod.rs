pub mod eval;
pub mod plan;
pub mod planners;
pub mod scenarios;
