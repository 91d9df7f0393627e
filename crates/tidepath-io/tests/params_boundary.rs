//! The generic parameter test: every parameter of every component (planners, smoothers, cost
//! models, encodings, repairs; the toys of this crate's tests included) is built at each bound of its
//! one declaration and just beyond it. A bound is accepted; just beyond is refused with one line
//! naming the field (`planner.params.de.f: must be in (0, 2], got 3`). No list of ids here:
//! the registries are read.

use crate::common;

use common::toys;
use tidepath::params::{boundary_values, ParamSpec};
use tidepath::registry::Entry;

/// Checks one component: `build(table)` with each boundary value of each parameter.
fn check<B: Copy>(
    kind: &str,
    entry: &Entry<B>,
    prefix: &str,
    build: &dyn Fn(&toml::Table) -> Result<(), String>,
) -> usize {
    let mut checked = 0;
    for spec in entry.params {
        for (value, accepted) in boundary_values(&spec.range) {
            let mut table = toml::Table::new();
            table.insert(spec.name.to_string(), value.clone());
            let r = build(&table);
            let field = format!("{prefix}.{}", spec.name);
            match (accepted, r) {
                (true, Ok(())) => {}
                // An in-range value may still break a rule between fields (elitism below the
                // population); never the parameter's own range.
                (true, Err(e)) => assert!(
                    !e.contains(&format!("must be {}", spec.range)),
                    "{kind} {}: {} = {value} is in range but refused: {e}",
                    entry.id,
                    spec.name
                ),
                (false, Ok(())) => panic!("{kind} {}: {} = {value} is out of range but accepted", entry.id, spec.name),
                (false, Err(e)) => {
                    assert!(e.starts_with(&format!("{field}: ")), "{kind} {}: {e}", entry.id);
                    assert_eq!(e.lines().count(), 1, "{e}");
                }
            }
            checked += 1;
        }
        assert_declared(kind, entry.id, spec);
    }
    checked
}

/// What `--params` prints comes from the same declaration.
fn assert_declared(kind: &str, id: &str, spec: &ParamSpec) {
    assert!(!spec.help().is_empty(), "{kind} {id}: {} has no help", spec.name);
    assert!(!spec.source.is_empty(), "{kind} {id}: {} has no source", spec.name);
    assert!(spec.optional || (spec.default)().is_some(), "{kind} {id}: {} has no default", spec.name);
}

#[test]
fn every_parameter_of_every_component_holds_its_bounds() {
    let encoding = tidepath::encoding::EncodingSpec::default();
    let mut checked = 0;
    let planners = toys::planners();
    for e in planners.entries() {
        let build =
            |t: &toml::Table| planners.build(e.id, Some(t), None, &encoding).map(|_| ()).map_err(|e| e.to_string());
        checked += check("planner", e, &format!("planner.params.{}", e.id), &build);
    }
    let smoothers = toys::smoothers();
    for e in smoothers.entries() {
        let build = |t: &toml::Table| {
            tidepath::smoothing::build_smoother_with(&smoothers, e.id, Some(t)).map(|_| ()).map_err(|e| e.to_string())
        };
        checked += check("smoother", e, &format!("planner.smoother_params.{}", e.id), &build);
    }
    for e in tidepath::cost::COST_MODELS {
        let build = |t: &toml::Table| (e.build)(t).map(|_| ()).map_err(|e| e.to_string());
        checked += check("cost model", e, "cost.weights", &build);
    }
    for e in tidepath::encoding::ENCODINGS {
        let build = |t: &toml::Table| {
            let n = t.get("waypoints").and_then(|v| v.as_integer());
            let spec = tidepath::encoding::EncodingSpec {
                kind: e.id.into(),
                waypoints: n.map_or(0, |n| n.clamp(0, i64::MAX) as usize),
                ..Default::default()
            };
            match n {
                Some(n) if n < 0 => Err("encoding.waypoints: must be a non-negative integer".to_string()),
                _ => spec.checked().map(|_| ()).map_err(|e| e.to_string()),
            }
        };
        checked += check("encoding", e, "encoding", &build);
    }
    for e in tidepath::repair::REPAIRS {
        let build =
            |t: &toml::Table| tidepath::repair::build_repair(e.id, Some(t)).map(|_| ()).map_err(|e| e.to_string());
        checked += check("repair", e, &format!("encoding.repair_params.{}", e.id), &build);
    }
    assert!(checked > 60, "only {checked} boundary values tried");
    // The toys are in: the generic check covered components registered by a test.
    assert!(planners.find("straight").is_some() && smoothers.find("thin").is_some());
}

/// A planner's `population` flag reaches only planners that have one.
#[test]
fn population_goes_only_where_it_is_declared() {
    let encoding = tidepath::encoding::EncodingSpec::default();
    for e in toys::planners().entries() {
        let r = toys::planners().build(e.id, None, Some(50), &encoding);
        if e.has_param("population") {
            assert!(r.is_ok(), "{}: {:?}", e.id, r.err());
        } else {
            let e2 = r.err().map(|x| x.to_string()).unwrap_or_default();
            assert!(e2.starts_with("--population:"), "{}: {e2}", e.id);
        }
    }
}
