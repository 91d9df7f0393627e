//! Agreement of tidepath's Dubins lengths with OMPL's (issue #27). Ignored by default: it
//! needs the pairs `scripts/ompl_dubins_check.py` writes with the `ompl` wheel, named by
//! `TIDEPATH_DUBINS_PAIRS` (CI runs it where the wheel installs):
//!
//! ```text
//! python3 scripts/ompl_dubins_check.py --out pairs.csv
//! TIDEPATH_DUBINS_PAIRS=pairs.csv cargo test -p tidepath --test dubins_ompl -- --ignored --nocapture
//! ```
//!
//! * 2-D: every pair's length agrees with OMPL's `DubinsStateSpace` distance to 1e-9
//!   relative (of the length, or of the radius for lengths below it).
//! * 3-D, OMPL's `OwenStateSpace`: where OMPL's path is low altitude, ours is the same planar
//!   curve with the climb spread and the lengths agree to 1e-9. Where it is medium or high
//!   altitude, both constructions fly exactly the pitch limit, so the length is
//!   |dz| / sin(pitch): ours equals that to 1e-9, OMPL's to its root finder's tolerance (1e-6
//!   is asserted; the figure is printed), and a high-altitude path has as many whole turns in
//!   both. Where ours is a helix of whole turns (no partial turn found), it is longer than
//!   |dz| / sin(pitch), and where OMPL finds no path (it then reports its maximum extent) ours
//!   still exists; both are counted.

use tidepath::kinematics::dubins::Dubins;
use tidepath::kinematics::dubins3::{Altitude, Dubins3};
use tidepath::kinematics::Pose;
use tidepath::Vec3;

struct Row {
    dims: u8,
    r: f64,
    pitch: f64,
    a: Pose,
    b: Pose,
    length: f64,
    category: String,
    turns: u32,
}

fn read(path: &str) -> Vec<Row> {
    let text = std::fs::read_to_string(path).unwrap_or_else(|e| panic!("{path}: {e}"));
    let mut lines = text.lines();
    let header = lines.next().expect("a header");
    assert_eq!(header, "dims,r,pitch,x0,y0,z0,th0,x1,y1,z1,th1,length,category,phi,turns,radius");
    lines
        .map(|line| {
            let f: Vec<&str> = line.split(',').collect();
            assert_eq!(f.len(), 16, "{line}");
            let x = |i: usize| -> f64 { f[i].parse().unwrap_or_else(|e| panic!("{line}: column {i}: {e}")) };
            Row {
                dims: f[0].parse().unwrap(),
                r: x(1),
                pitch: x(2),
                a: Pose::new(Vec3::new(x(3), x(4), x(5)), x(6)),
                b: Pose::new(Vec3::new(x(7), x(8), x(9)), x(10)),
                length: x(11),
                category: f[12].to_string(),
                turns: f[14].parse().unwrap(),
            }
        })
        .collect()
}

fn rel(ours: f64, theirs: f64, scale: f64) -> f64 {
    (ours - theirs).abs() / theirs.abs().max(scale)
}

#[test]
#[ignore = "needs TIDEPATH_DUBINS_PAIRS from scripts/ompl_dubins_check.py (the ompl wheel)"]
fn dubins_lengths_agree_with_ompl() {
    let path = std::env::var("TIDEPATH_DUBINS_PAIRS").expect("TIDEPATH_DUBINS_PAIRS names the pairs file");
    let rows = read(&path);
    let (planar, spatial): (Vec<&Row>, Vec<&Row>) = rows.iter().partition(|r| r.dims == 2);
    assert!(planar.len() >= 1000 && spatial.len() >= 1000, "{} planar, {} 3-D pairs", planar.len(), spatial.len());

    // 2-D against DubinsStateSpace.
    let (mut max_err, mut ccc, mut ccc_err) = (0.0f64, 0, 0.0f64);
    let mut words = std::collections::BTreeMap::new();
    for row in &planar {
        let d = Dubins::shortest(row.a, row.b, row.r).expect("a Dubins curve");
        let e = rel(d.length(), row.length, row.r);
        assert!(
            e <= 1e-9,
            "2-D pair {:?} -> {:?} r {}: ours {} ({}), OMPL {}",
            row.a,
            row.b,
            row.r,
            d.length(),
            d.word.name(),
            row.length
        );
        max_err = max_err.max(e);
        *words.entry(d.word.name()).or_insert(0) += 1;
        if d.word.turns()[1] != 0 {
            ccc += 1;
            ccc_err = ccc_err.max(e);
        }
    }
    println!(
        "2-D: {} pairs agree with OMPL's DubinsStateSpace, max relative error {max_err:.2e}; {ccc} CCC (max {ccc_err:.2e}); words {words:?}",
        planar.len()
    );
    assert!(ccc >= 50, "too few CCC pairs ({ccc}) to test the LRL/RLR words");

    // 3-D against OwenStateSpace.
    let (mut low, mut low_err) = (0, 0.0f64);
    let (mut climb, mut climb_ideal_err, mut climb_ompl_err) = (0, 0.0f64, 0.0f64);
    let (mut helix, mut none, mut turns_checked) = (0, 0, 0);
    for row in &spatial {
        let d = Dubins3::shortest(row.a, row.b, row.r, row.pitch).expect("a 3-D curve");
        let dz = row.b.p.z - row.a.p.z;
        let ideal = dz.abs() / row.pitch.sin();
        let flat = Dubins::shortest(row.a, row.b, row.r).unwrap().length();
        // Never shorter than what the pitch limit or the planar curve allow.
        assert!(d.length() >= ideal * (1.0 - 1e-12) && d.length() >= flat.hypot(dz) * (1.0 - 1e-12));
        match row.category.as_str() {
            "LOW_ALTITUDE" => {
                assert_eq!(d.altitude, Altitude::Low, "{:?} -> {:?}", row.a, row.b);
                let e = rel(d.length(), row.length, row.r);
                assert!(e <= 1e-9, "3-D low {:?} -> {:?}: ours {} OMPL {}", row.a, row.b, d.length(), row.length);
                low += 1;
                low_err = low_err.max(e);
            }
            "MEDIUM_ALTITUDE" | "HIGH_ALTITUDE" => match d.altitude {
                Altitude::Medium | Altitude::High => {
                    climb += 1;
                    climb_ideal_err = climb_ideal_err.max(rel(d.length(), ideal, row.r));
                    let e = rel(d.length(), row.length, row.r);
                    climb_ompl_err = climb_ompl_err.max(e);
                    assert!(e <= 1e-6, "3-D climb {:?} -> {:?}: ours {} OMPL {}", row.a, row.b, d.length(), row.length);
                    if row.category == "HIGH_ALTITUDE" {
                        assert_eq!((d.pre_turn.abs() / std::f64::consts::TAU).floor() as u32, row.turns, "{d:?}");
                        turns_checked += 1;
                    }
                }
                Altitude::Helix => helix += 1,
                Altitude::Low => panic!("OMPL {} but ours low: {:?} -> {:?}", row.category, row.a, row.b),
            },
            "NONE" => none += 1,
            other => panic!("unknown category {other}"),
        }
    }
    assert!(climb_ideal_err <= 1e-9, "{climb_ideal_err}");
    println!(
        "3-D: {low} low-altitude pairs agree with OMPL's OwenStateSpace, max relative error {low_err:.2e}; \
         {climb} medium/high pairs: ours |dz|/sin(pitch) to {climb_ideal_err:.2e}, OMPL within {climb_ompl_err:.2e} of ours, \
         whole turns equal in {turns_checked} high-altitude pairs; {helix} where ours is a helix of whole turns (longer); \
         {none} where OMPL finds no path"
    );
    assert!(low >= 300 && climb >= 100, "too few pairs of a case: {low} low, {climb} medium/high");
}
