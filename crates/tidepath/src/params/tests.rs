use super::*;

#[derive(Clone, Copy, Debug, PartialEq)]
enum Coding {
    Real,
    Binary,
}

impl Word for Coding {
    const WORDS: &'static [(&'static str, Self)] = &[("real", Coding::Real), ("binary", Coding::Binary)];
}

crate::params::word_param!(Coding);

fn together(t: &Toy, prefix: &str) -> Result<()> {
    if t.elite >= t.population {
        return Err(field_error(
            prefix,
            "elite",
            format!("must be below population ({}), got {}", t.population, t.elite),
        ));
    }
    Ok(())
}

crate::params! {
    /// A toy component.
    struct Toy {
        /// Individuals.
        population: usize = 40, Range::integer(2, 100), "tidepath";
        /// Step, as a fraction.
        f: f64 = 0.5, Range::Number { lo: Bound::Open(0.0), hi: Bound::Closed(2.0) }, "Storn & Price 1997";
        /// Best kept.
        elite: usize = 1, Range::integer(0, 100), "tidepath";
        /// Coding.
        coding: Coding = Coding::Real, Range::Choice(&["real", "binary"]), "amfa2015";
        /// A schedule length, or none.
        schedule: Option<u64> = None, Range::integer(1, 1000), "ijs2023";
    }
    check = together;
}

fn table(pairs: &[(&str, toml::Value)]) -> toml::Table {
    pairs.iter().map(|(k, v)| (k.to_string(), v.clone())).collect()
}

#[test]
fn errors_name_the_field_and_the_value() {
    let e =
        |pairs: &[(&str, toml::Value)]| Toy::from_table(&table(pairs), "planner.params.toy").unwrap_err().to_string();
    assert_eq!(e(&[("f", toml::Value::Float(3.0))]), "planner.params.toy.f: must be in (0, 2], got 3");
    assert_eq!(e(&[("f", toml::Value::Float(1e-300 * 0.0))]), "planner.params.toy.f: must be in (0, 2], got 0");
    assert_eq!(
        e(&[("population", toml::Value::Integer(1))]),
        "planner.params.toy.population: must be an integer in [2, 100], got 1"
    );
    assert_eq!(
        e(&[("coding", toml::Value::String("gray".into()))]),
        "planner.params.toy.coding: must be one of \"real\", \"binary\", got \"gray\""
    );
    assert!(e(&[("pc", toml::Value::Float(0.5))])
        .starts_with("planner.params.toy.pc: unknown parameter (known: population, f"));
    assert_eq!(
        e(&[("elite", toml::Value::Integer(40))]),
        "planner.params.toy.elite: must be below population (40), got 40"
    );
    assert!(e(&[("f", toml::Value::String("x".into()))]).contains("must be a number"));
}

#[test]
fn defaults_and_tables_round_trip() {
    let t = Toy::from_table(&toml::Table::new(), "p").unwrap();
    assert_eq!(*t.get(), Toy::default());
    let back = Toy::from_table(&t.to_table(), "p").unwrap();
    assert_eq!(back, t);
    assert!(!t.to_table().contains_key("schedule"), "an absent optional stays absent");
    let spec = Toy::SPECS.iter().find(|s| s.name == "schedule").unwrap();
    assert!(spec.optional && spec.default_text() == "absent");
    let f = Toy::SPECS.iter().find(|s| s.name == "f").unwrap();
    assert_eq!(
        (f.default_text().as_str(), f.range.to_string().as_str(), f.help(), f.source),
        ("0.5", "in (0, 2]", "Step, as a fraction.", "Storn & Price 1997")
    );
}

/// The boundary values of each declaration are accepted or refused exactly as declared:
/// changing a range in its one declaration moves the check, the text `--params` prints and
/// these values together.
#[test]
fn boundary_values_follow_the_declaration() {
    for spec in Toy::SPECS {
        for (value, accepted) in boundary_values(&spec.range) {
            let r = Toy::from_table(&table(&[(spec.name, value.clone())]), "planner.params.toy");
            // Only the cross-field rule may refuse an in-range value (elite at the top).
            let cross = spec.name == "elite" && value.as_integer().is_some_and(|v| v >= 40);
            if accepted && !cross {
                assert!(r.is_ok(), "{} = {value} refused: {:?}", spec.name, r.err());
            } else if !accepted {
                let e = r.unwrap_err().to_string();
                assert!(e.starts_with(&format!("planner.params.toy.{}:", spec.name)), "{e}");
            }
        }
    }
    // A declaration with another range: the same generators give other values.
    let narrow = Range::integer(5, 6);
    let vals: Vec<(i64, bool)> = boundary_values(&narrow).iter().map(|(v, a)| (v.as_integer().unwrap(), *a)).collect();
    assert_eq!(vals, [(5, true), (4, false), (6, true), (7, false)]);
    assert_eq!(narrow.to_string(), "an integer in [5, 6]");
}

#[test]
fn checked_values_come_only_from_checks() {
    let bad = Toy { f: 5.0, ..Toy::default() };
    assert!(bad.clone().checked("p").is_err());
    let good = Toy { f: 1.5, ..Toy::default() }.checked("p").unwrap();
    assert_eq!(good.f, 1.5);
}
