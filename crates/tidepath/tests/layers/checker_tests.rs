//! The checker itself, on small crates written inline.

use std::collections::BTreeMap;

use super::*;

fn crate_of(files: &[(&str, &str)]) -> Scan {
    let files: BTreeMap<String, String> = files.iter().map(|(p, t)| (p.to_string(), t.to_string())).collect();
    scan(&files)
}

fn paths(s: &Scan) -> Vec<String> {
    s.uses.iter().map(|u| format!("{}:{} {}->{} {}", u.file, u.line, u.from, u.to, u.path)).collect()
}

const LOW_HIGH: &[&str] = &["low", "mid", "high"];

#[test]
fn grouped_and_nested_imports_are_each_resolved() {
    let s = crate_of(&[
        ("lib.rs", "pub mod low;\npub mod mid;\npub mod high;\n"),
        ("low.rs", "use crate::{mid::A, high::{self, x::{B, C as D}}, low::*};\n"),
        ("mid.rs", ""),
        ("high.rs", ""),
    ]);
    assert!(s.problems.is_empty(), "{:?}", s.problems);
    assert_eq!(
        paths(&s),
        [
            "low.rs:1 low->mid crate::mid::A",
            "low.rs:1 low->high crate::high",
            "low.rs:1 low->high crate::high::x::B",
            "low.rs:1 low->high crate::high::x::C",
            "low.rs:1 low->low crate::low",
        ]
    );
    assert_eq!(upward(&s.uses, LOW_HIGH).len(), 4);
}

#[test]
fn super_is_resolved_against_the_module_path_of_mod_rs_and_flat_files() {
    let s = crate_of(&[
        ("lib.rs", "mod low;\nmod high;\npub use high::Top;\n"),
        // low/mod.rs is `low`; low/a.rs is `low::a`; low/a/b.rs is `low::a::b`.
        ("low/mod.rs", "mod a;\nuse super::high::X;\n"),
        ("low/a.rs", "mod b;\nuse super::super::high::Y;\nuse super::Z;\n"),
        ("low/a/b.rs", "fn f() { super::super::super::Top::new(); super::super::W::g(); }\n"),
        ("high.rs", ""),
    ]);
    assert!(s.problems.is_empty(), "{:?}", s.problems);
    let mut got = paths(&s);
    got.sort();
    assert_eq!(
        got,
        [
            "low/a.rs:2 low->high super::super::high::Y",
            "low/a.rs:3 low->low super::Z",
            "low/a/b.rs:1 low->high super::super::super::Top::new",
            "low/a/b.rs:1 low->low super::super::W::g",
            "low/mod.rs:2 low->high super::high::X",
        ]
    );
    assert_eq!(upward(&s.uses, LOW_HIGH).len(), 3);

    let s = crate_of(&[("lib.rs", "mod low;\n"), ("low.rs", "use super::super::x;\n")]);
    assert_eq!(s.problems.len(), 1, "a path above the root is reported: {:?}", s.problems);
}

#[test]
fn test_code_anywhere_in_a_file_is_skipped_and_code_after_it_is_not() {
    let s = crate_of(&[
        ("lib.rs", "mod low;\nmod high;\n#[cfg(test)]\nmod helpers;\n"),
        (
            "low.rs",
            "\
struct S {
    #[cfg(test)]
    t: crate::high::A,
}
#[cfg(test)]
mod tests { use crate::high::B; }
#[test]
fn t() { crate::high::C::f(); }
#[cfg(all(unix, test))]
fn u() { crate::high::D::f(); }
impl S {
    #[cfg(test)]
    fn only_in_tests() -> crate::high::E { todo!() }
    fn real() -> crate::high::F { todo!() }
}
#[cfg(not(test))]
use crate::high::G;
fn after() { let _ = format!(\"{}\", crate::high::H::x()); }
",
        ),
        ("high.rs", ""),
        ("helpers.rs", "use crate::low::nonsense;\n"),
    ]);
    assert!(s.problems.is_empty(), "{:?}", s.problems);
    assert_eq!(
        paths(&s),
        [
            "low.rs:14 low->high crate::high::F",
            "low.rs:17 low->high crate::high::G",
            "low.rs:18 low->high crate::high::H::x"
        ]
    );
    assert!(s.test_files.contains("helpers.rs") && !s.checked.contains("helpers.rs"));
}

#[test]
fn an_upward_import_is_caught_and_a_downward_one_is_not() {
    let s = crate_of(&[
        ("lib.rs", "pub mod low;\npub mod high;\npub use low::Thing;\n"),
        ("low.rs", "pub struct Thing;\npub fn f() -> crate::high::Other { todo!() }\n"),
        ("high.rs", "pub struct Other(crate::Thing);\nuse crate::low::f;\n"),
    ]);
    assert!(s.problems.is_empty(), "{:?}", s.problems);
    assert_eq!(upward(&s.uses, LOW_HIGH), ["low.rs:2: low uses high (crate::high::Other)"]);
    assert_eq!(s.uses.len(), 3);

    let s = crate_of(&[("lib.rs", "mod low;\n"), ("low.rs", "use crate::Unknown;\n")]);
    assert_eq!(s.problems.len(), 1, "an unplaceable crate path is reported: {:?}", s.problems);
    let s = crate_of(&[("lib.rs", "mod low;\nmod side;\n"), ("low.rs", "use crate::side::X;\n"), ("side.rs", "")]);
    assert_eq!(upward(&s.uses, LOW_HIGH).len(), 1, "a layer missing from the order is reported");
}

#[test]
fn an_upward_crate_dependency_is_caught() {
    let m = |name: &str, deps: &str| (format!("{name}/Cargo.toml"), format!("[package]\nname = \"{name}\"\n{deps}"));
    let crates = &["a", "b", "c"];
    let ok = [
        m("a", ""),
        m("b", "[dependencies]\na = { path = \"../a\" }\nserde = \"1\"\n"),
        m("c", "[dependencies]\nb.workspace = true\n"),
    ];
    assert!(crate_violations(&ok, crates).is_empty());
    let bad = [
        m("a", "[dev-dependencies]\nrenamed = { package = \"c\", path = \"../c\" }\n"),
        m("b", "[target.'cfg(unix)'.dependencies]\nb = { path = \".\" }\n"),
        m("c", ""),
        m("d", ""),
    ];
    assert_eq!(crate_violations(&bad, crates).len(), 3, "{:?}", crate_violations(&bad, crates));
}
