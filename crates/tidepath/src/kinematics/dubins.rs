//! Dubins curves in the plane: the shortest paths of bounded curvature between two poses
//! (Dubins 1957), of six words LSL, LSR, RSL, RSR, RLR, LRL. The geometry is the
//! `dubins_paths` crate's (a port of Walker's C library, whose words agree with OMPL's
//! `DubinsStateSpace`); this module adds what tidepath needs around it: lengths in metres,
//! poses at a distance, and the curve written as a tangent polygon so the fillet model flies
//! it exactly.

use super::{Pose, TangentPolygon};
use crate::geom::Vec3;
use dubins_paths::f64::{DubinsPath, PosRot};
use dubins_paths::{PathType, SegmentType};

/// The six Dubins words.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Word {
    Lsl,
    Lsr,
    Rsl,
    Rsr,
    Rlr,
    Lrl,
}

impl Word {
    pub const ALL: [Word; 6] = [Word::Lsl, Word::Lsr, Word::Rsl, Word::Rsr, Word::Rlr, Word::Lrl];

    fn path_type(self) -> PathType {
        match self {
            Word::Lsl => PathType::LSL,
            Word::Lsr => PathType::LSR,
            Word::Rsl => PathType::RSL,
            Word::Rsr => PathType::RSR,
            Word::Rlr => PathType::RLR,
            Word::Lrl => PathType::LRL,
        }
    }

    fn from_path_type(t: PathType) -> Self {
        match t {
            PathType::LSL => Word::Lsl,
            PathType::LSR => Word::Lsr,
            PathType::RSL => Word::Rsl,
            PathType::RSR => Word::Rsr,
            PathType::RLR => Word::Rlr,
            PathType::LRL => Word::Lrl,
        }
    }

    /// The word's three letters: +1 left, -1 right, 0 straight.
    pub fn turns(self) -> [i8; 3] {
        self.path_type().to_segment_types().map(|s| match s {
            SegmentType::L => 1,
            SegmentType::R => -1,
            SegmentType::S => 0,
        })
    }

    pub fn name(self) -> &'static str {
        match self {
            Word::Lsl => "LSL",
            Word::Lsr => "LSR",
            Word::Rsl => "RSL",
            Word::Rsr => "RSR",
            Word::Rlr => "RLR",
            Word::Lrl => "LRL",
        }
    }
}

/// A planar Dubins curve from a start pose (z ignored).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Dubins {
    pub from: Pose,
    pub word: Word,
    pub radius: f64,
    /// The three segments' lengths (m): arc, straight or arc, arc.
    pub lengths: [f64; 3],
}

fn pos_rot(p: Pose) -> PosRot {
    PosRot::from_floats(p.p.x, p.p.y, p.heading)
}

impl Dubins {
    /// The shortest of the six words from `from` to `to` with turning radius `radius`, or
    /// `None` when no word exists (a non-finite input or a radius that is not positive).
    pub fn shortest(from: Pose, to: Pose, radius: f64) -> Option<Self> {
        Self::shortest_in(from, to, radius, &Word::ALL)
    }

    /// The shortest among `words`.
    pub fn shortest_in(from: Pose, to: Pose, radius: f64, words: &[Word]) -> Option<Self> {
        if !(radius > 0.0 && radius.is_finite()) {
            return None;
        }
        let types: Vec<PathType> = words.iter().map(|w| w.path_type()).collect();
        let path = DubinsPath::shortest_in(pos_rot(from), pos_rot(to), radius, &types).ok()?;
        let lengths = path.param.map(|t| t * radius);
        lengths.iter().all(|l| l.is_finite()).then_some(Self {
            from,
            word: Word::from_path_type(path.path_type),
            radius,
            lengths,
        })
    }

    /// Word `word` from `from` to `to`, when it exists.
    pub fn with_word(from: Pose, to: Pose, radius: f64, word: Word) -> Option<Self> {
        Self::shortest_in(from, to, radius, &[word])
    }

    /// Horizontal length (m).
    pub fn length(&self) -> f64 {
        self.lengths.iter().sum()
    }

    /// The pose `s` metres along the curve (clamped to its length); z is the start's.
    pub fn pose_at(&self, s: f64) -> Pose {
        let mut pose = self.from;
        let mut left = s.clamp(0.0, self.length());
        for (turn, len) in self.word.turns().into_iter().zip(self.lengths) {
            let d = left.min(len);
            pose = advance(pose, turn, d, self.radius);
            left -= d;
        }
        pose
    }

    /// Writes the curve into `tp` (whose pen must be at the curve's start), changing the height
    /// by `dz` spread evenly over the curve's length.
    pub fn write(&self, tp: &mut TangentPolygon, dz: f64) {
        let total = self.length();
        for (turn, len) in self.word.turns().into_iter().zip(self.lengths) {
            let dzi = if total > 0.0 { dz * len / total } else { 0.0 };
            if turn == 0 {
                tp.straight(len, dzi);
            } else {
                tp.arc(f64::from(turn) * len / self.radius, dzi);
            }
        }
    }
}

/// The pose after `d` metres of a turn (`turn` +1 left, -1 right) or a straight (0).
pub fn advance(pose: Pose, turn: i8, d: f64, radius: f64) -> Pose {
    let (h, p) = (pose.heading, pose.p);
    if turn == 0 {
        return Pose::new(p + Vec3::new(h.cos() * d, h.sin() * d, 0.0), h);
    }
    let s = f64::from(turn);
    let dh = s * d / radius;
    // Centre of the turning circle, to the left (s = +1) or the right of the heading.
    let (cx, cy) = (p.x - s * radius * h.sin(), p.y + s * radius * h.cos());
    let h1 = h + dh;
    Pose::new(Vec3::new(cx + s * radius * h1.sin(), cy - s * radius * h1.cos(), p.z), h1)
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::f64::consts::{FRAC_PI_2, PI};

    #[test]
    fn straight_ahead_is_a_straight_line() {
        let a = Pose::new(Vec3::ZERO, 0.0);
        let b = Pose::new(Vec3::new(100.0, 0.0, 0.0), 0.0);
        let d = Dubins::shortest(a, b, 10.0).unwrap();
        assert!((d.length() - 100.0).abs() < 1e-9, "{d:?}");
    }

    #[test]
    fn a_u_turn_onto_the_neighbouring_circle_point_is_half_a_circle() {
        // Heading east at the origin, arrive heading west at (0, 2r): a left half circle.
        let r = 5.0;
        let d = Dubins::shortest(Pose::new(Vec3::ZERO, 0.0), Pose::new(Vec3::new(0.0, 2.0 * r, 0.0), PI), r).unwrap();
        assert!((d.length() - PI * r).abs() < 1e-9, "{d:?}");
        let end = d.pose_at(d.length());
        assert!((end.p - Vec3::new(0.0, 2.0 * r, 0.0)).length() < 1e-9);
    }

    #[test]
    fn quarter_turn_then_straight_by_hand() {
        // East at the origin to north at (r, r + 20): a left quarter circle (pi r / 2) and 20 m.
        let r = 8.0;
        let d =
            Dubins::shortest(Pose::new(Vec3::ZERO, 0.0), Pose::new(Vec3::new(r, r + 20.0, 0.0), FRAC_PI_2), r).unwrap();
        assert!((d.length() - (FRAC_PI_2 * r + 20.0)).abs() < 1e-9, "{d:?}");
        assert_eq!(d.word.turns()[0], 1);
    }

    #[test]
    fn the_crates_documented_case() {
        // dubins_paths' README: (0, 0, pi/4) to (100, -100, 3 pi/4) with radius 11.6 is "just
        // over 185" long; OMPL 2.0.1's DubinsStateSpace(11.6) gives 185.0022887156118.
        let d = Dubins::shortest(
            Pose::new(Vec3::ZERO, PI / 4.0),
            Pose::new(Vec3::new(100.0, -100.0, 0.0), 3.0 * PI / 4.0),
            11.6,
        )
        .unwrap();
        assert!((d.length() - 185.0022887156118).abs() < 1e-9 * 185.0, "{}", d.length());
    }

    #[test]
    fn advance_matches_the_crate_sampler() {
        let a = Pose::new(Vec3::new(3.0, -2.0, 0.0), 0.7);
        let b = Pose::new(Vec3::new(-40.0, 25.0, 0.0), -2.1);
        for w in Word::ALL {
            let Some(d) = Dubins::with_word(a, b, 12.0, w) else { continue };
            let path = DubinsPath::new(pos_rot(a), pos_rot(b), 12.0, w.path_type()).unwrap();
            for k in 0..=10 {
                let s = d.length() * k as f64 / 10.0;
                let (ours, theirs) = (d.pose_at(s), path.sample(s));
                assert!((ours.p.x - theirs.x()).abs() < 1e-9 && (ours.p.y - theirs.y()).abs() < 1e-9, "{w:?} at {s}");
            }
        }
    }
}
