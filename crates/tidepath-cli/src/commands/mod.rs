pub mod bench;
pub mod budget;
pub mod compare;
pub mod eval;
pub mod plan;
pub mod planners;
pub mod reproduce;
pub mod scenarios;
