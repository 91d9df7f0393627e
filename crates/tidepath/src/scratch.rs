//! Buffers reused across evaluations so the hot path never allocates. Shared by the cost
//! models (which fill them) and the optimizers (which hand one to each worker).

/// Reusable buffers for one evaluation, so the hot path never allocates.
/// Each rayon worker gets its own; objectives that need none ignore it.
#[derive(Default, Debug)]
pub struct Scratch {
    pub points: Vec<crate::geom::Vec3>,
    pub times: Vec<f64>,
    pub values: Vec<f64>,
    /// One decoded path per mission of a fleet, and each one's timed legs (from, to, time
    /// in, time out), for the separation check of a joint objective.
    pub paths: Vec<Vec<crate::geom::Vec3>>,
    pub legs: Vec<Vec<(crate::geom::Vec3, crate::geom::Vec3, f64, f64)>>,
}
