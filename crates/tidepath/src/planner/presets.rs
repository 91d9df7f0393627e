//! Named parameter sets of the papers: `bench functions --preset wpa2017` runs each optimizer
//! with the values a paper used for its benchmark tables (where the paper gives a planner's
//! values; other planners keep their defaults). The values themselves are declared once, as
//! the parameter structs' constructors (`MwpaParams::wpa2017()`, ...); this table only names
//! them. Adding a preset is one entry.

use crate::error::Result;
use crate::optim::ade::AdeParams;
use crate::optim::amfa::AmfaParams;
use crate::optim::eda_g::EdaGParams;
use crate::optim::fa::FaParams;
use crate::optim::ga::GaParams;
use crate::optim::histogram::{FhhLtsParams, FhhParams, LfhhParams};
use crate::optim::mwpa::MwpaParams;
use crate::optim::pso::PsoParams;
use crate::optim::wpa::WpaParams;
use crate::registry::{Entry, Registry};

/// A preset's parameters for a planner id, as the TOML table a scenario would write; `None`
/// when the preset has none for that planner.
pub type PresetFor = fn(&str) -> Option<toml::Table>;

pub const PRESETS: &[Entry<PresetFor>] = &[
    Entry {
        id: "wpa2017",
        description: "wpa2017's benchmark setting (Table 3): mwpa, wpa, pso, ga",
        citation: "Zhang et al. 2017 (wpa2017), Table 3 (readings in docs/papers/wpa2017.md A12, A13)",
        params: &[],
        build: wpa2017,
    },
    Entry {
        id: "amfa2015",
        description:
            "amfa2015's setting (section 5, Tables 1-4): amfa, fa, pso (V_max = X_max: half the box width), ga",
        citation: "Liu et al. 2015 (amfa2015), section 5 (readings in docs/papers/amfa2015.md A8, A13)",
        params: &[],
        build: amfa2015,
    },
    Entry {
        id: "amfa2015-vmax-range",
        description: "amfa2015's setting with PSO's V_max read as the whole box width: amfa, fa, pso, ga",
        citation: "Liu et al. 2015 (amfa2015), section 5 (the other reading of V_max, docs/papers/amfa2015.md A13)",
        params: &[],
        build: amfa2015_vmax_range,
    },
    Entry {
        id: "ijs2023",
        description: "ijs2023's baseline setting (section IV): pso (w 0.9 -> 0.4 over 500 iterations, c = 2, v_max = 0.2 x the box width); js, ijs, qpso, hho, mpa keep their published defaults",
        citation: "Guo, Chen & Pang 2023 (ijs2023), section IV (readings in docs/papers/ijs2023.md A13)",
        params: &[],
        build: ijs2023,
    },
    Entry {
        id: "lfhh2019",
        description: "lfhh2019's setting (Table 1): lfhh, fhh, fhh-lts, eda-g, ade",
        citation: "Liu et al. 2019 (lfhh2019), Table 1 (readings in docs/papers/lfhh2019.md A7, A9, A14)",
        params: &[],
        build: lfhh2019,
    },
];

fn wpa2017(planner: &str) -> Option<toml::Table> {
    Some(match planner {
        "mwpa" => MwpaParams::wpa2017().to_table(),
        "wpa" => WpaParams::wpa2017().to_table(),
        "pso" => PsoParams::wpa2017().to_table(),
        "ga" => GaParams::wpa2017().to_table(),
        _ => return None,
    })
}

fn amfa2015(planner: &str) -> Option<toml::Table> {
    Some(match planner {
        "amfa" => AmfaParams::amfa2015().to_table(),
        "fa" => FaParams::amfa2015().to_table(),
        "pso" => PsoParams::amfa2015().to_table(),
        "ga" => GaParams::amfa2015().to_table(),
        _ => return None,
    })
}

fn amfa2015_vmax_range(planner: &str) -> Option<toml::Table> {
    match planner {
        "pso" => Some(PsoParams::amfa2015_vmax_range().to_table()),
        other => amfa2015(other),
    }
}

/// ijs2023 prints no baseline parameters (A13): PSO's standard linearly falling inertia over
/// the paper's T = 500 iterations.
fn ijs2023(planner: &str) -> Option<toml::Table> {
    (planner == "pso").then(|| PsoParams::ijs2023(500).to_table())
}

/// lfhh2019's Table 1: NP = 200 for all, binNum = S = 100, lambda = 0.08, T = 5, and the
/// adaptive DE's alpha = 0, beta = 0.4, F0 = 0.6 (the parameter structs' defaults).
fn lfhh2019(planner: &str) -> Option<toml::Table> {
    Some(match planner {
        "lfhh" => LfhhParams::lfhh2019().to_table(),
        "fhh" => FhhParams::lfhh2019().to_table(),
        "fhh-lts" => FhhLtsParams::lfhh2019().to_table(),
        "eda-g" => EdaGParams::lfhh2019().to_table(),
        "ade" => AdeParams::lfhh2019().to_table(),
        _ => return None,
    })
}

/// The presets as a registry: lists and "known: ..." errors.
pub fn presets() -> Registry<PresetFor> {
    Registry::new("preset", "--preset", "tidepath bench functions --help", PRESETS)
}

/// The parameters preset `id` gives `planner`, if any.
pub fn preset_params(id: &str, planner: &str) -> Result<Option<toml::Table>> {
    Ok((presets().get(id)?.build)(planner))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_preset_builds_its_planners_from_the_declared_values() {
        for e in PRESETS {
            let mut any = false;
            for p in crate::planner::registry().entries() {
                if let Some(t) = (e.build)(p.id) {
                    any = true;
                    crate::planner::build_optimizer(p.id, Some(&t), None)
                        .unwrap_or_else(|err| panic!("{} for {}: {err}", e.id, p.id));
                }
            }
            assert!(any, "{} names no planner", e.id);
        }
        let t = preset_params("wpa2017", "mwpa").unwrap().unwrap();
        assert_eq!(t["population"].as_integer(), Some(100));
        assert_eq!(t["omega"].as_float(), Some(500.0));
        assert_eq!(preset_params("wpa2017", "de").unwrap(), None);
        let e = preset_params("nope", "pso").unwrap_err().to_string();
        assert!(e.starts_with("--preset: unknown preset 'nope' (known: wpa2017, amfa2015"), "{e}");
        // amfa2015's two readings of V_max = X_max differ in PSO's clamp only.
        let half = preset_params("amfa2015", "pso").unwrap().unwrap();
        let whole = preset_params("amfa2015-vmax-range", "pso").unwrap().unwrap();
        assert_eq!((half["vmax_fraction"].as_float(), whole["vmax_fraction"].as_float()), (Some(0.5), Some(1.0)));
        for p in ["amfa", "fa", "ga", "de"] {
            assert_eq!(preset_params("amfa2015", p).unwrap(), preset_params("amfa2015-vmax-range", p).unwrap());
        }
    }
}
