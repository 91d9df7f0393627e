//! The one statement of tidepath's layering, and its check.
//!
//! [`ORDER`] lists the core's layers (its top-level modules) lowest first; a module may use
//! only its own layer and those listed before it. [`CRATES`] lists the workspace's crates
//! lowest first; a crate may depend only on crates listed before it. README and `lib.rs` point
//! here instead of repeating either list.
//!
//! The check parses every source file reachable from `src/lib.rs` with `syn`, following `mod`
//! declarations, and resolves every path that names a crate module: `use` trees (grouped and
//! nested), `crate::`, `self::` and `super::` (any number of them) paths in types and
//! expressions, and the same inside macro calls. Only items under `#[cfg(test)]` (or
//! `#[cfg(all(test, ...))]`) and `#[test]` functions are skipped, wherever they are in a file.

use std::collections::{BTreeMap, BTreeSet};
use std::path::Path;

#[path = "layers/checker.rs"]
mod checker;

use checker::{crate_violations, read_tree, scan, upward};

/// The core's layers, lowest first: each top-level module of `crates/tidepath/src` may use
/// only its own layer and the ones before it.
const ORDER: &[&str] = &[
    "geom",
    "text",
    "error",
    "params",
    "geo",
    "config",
    "rng",
    "registry",
    "scratch",
    "world",
    "vehicle",
    "kinematics",
    "mission",
    "validity",
    "raster",
    "path",
    "fleet",
    "cost",
    "repair",
    "encoding",
    "termination",
    "optim",
    "smoothing",
    "planner",
    "simulate",
];

/// The workspace's crates, lowest first: each may depend only on the ones before it.
const CRATES: &[&str] = &[
    "tidepath-search",
    "tidepath",
    "tidepath-io",
    "tidepath-experiments",
    "tidepath-plot",
    "tidepath-view",
    "tidepath-cli",
    "tidepath-py",
];

#[test]
fn no_module_uses_a_layer_above_it() {
    let src = Path::new(env!("CARGO_MANIFEST_DIR")).join("src");
    let mut files = BTreeMap::new();
    read_tree(&src, &src, &mut files);
    let s = scan(&files);
    assert!(s.problems.is_empty(), "cannot check:\n{}", s.problems.join("\n"));

    let order: BTreeSet<String> = ORDER.iter().map(|m| m.to_string()).collect();
    assert_eq!(s.top, order, "ORDER must list exactly lib.rs's modules, each where it belongs");
    assert_eq!(ORDER.len(), order.len(), "a layer is listed twice");
    let unread: Vec<_> = files.keys().filter(|f| !s.checked.contains(*f) && !s.test_files.contains(*f)).collect();
    assert!(unread.is_empty(), "files no `mod` reaches: {unread:?}");

    // The checker must be seeing the code: counts well below today's (381 crate paths, 261
    // of them across layers, 60 files, once scenarios and files moved to tidepath-io) would
    // mean it stopped resolving something.
    let across = s.uses.iter().filter(|u| u.from != u.to).count();
    assert!(s.uses.len() > 300, "only {} crate paths seen", s.uses.len());
    assert!(across > 200, "only {across} paths across layers seen");
    assert!(s.checked.len() > 48, "only {} files read", s.checked.len());

    let wrong = upward(&s.uses, ORDER);
    assert!(wrong.is_empty(), "upward uses (see ORDER in this file):\n{}", wrong.join("\n"));
}

#[test]
fn no_crate_depends_on_one_above_it() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../..");
    let workspace: toml::Table = std::fs::read_to_string(root.join("Cargo.toml")).unwrap().parse().unwrap();
    let members = workspace["workspace"]["members"].as_array().unwrap();
    let mut manifests = Vec::new();
    for m in members {
        let path = root.join(m.as_str().unwrap()).join("Cargo.toml");
        manifests.push((path.display().to_string(), std::fs::read_to_string(&path).unwrap()));
    }
    let mut names: Vec<String> = manifests
        .iter()
        .map(|(_, t)| t.parse::<toml::Table>().unwrap()["package"]["name"].as_str().unwrap().to_string())
        .collect();
    names.sort();
    let mut listed: Vec<String> = CRATES.iter().map(|c| c.to_string()).collect();
    listed.sort();
    assert_eq!(names, listed, "CRATES must list exactly the workspace members");
    let wrong = crate_violations(&manifests, CRATES);
    assert!(wrong.is_empty(), "upward crate dependencies (see CRATES in this file):\n{}", wrong.join("\n"));
}
