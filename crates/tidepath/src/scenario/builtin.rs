//! Scenarios embedded in the binary, so a newcomer can plan without writing a file.

/// (name, TOML text).
pub const BUILTIN: &[(&str, &str)] = &[("demo", include_str!("../../scenarios/demo.toml"))];

pub fn builtin(name: &str) -> Option<&'static str> {
    BUILTIN.iter().find(|(n, _)| *n == name).map(|(_, t)| *t)
}

pub fn builtin_names() -> impl Iterator<Item = &'static str> {
    BUILTIN.iter().map(|(n, _)| *n)
}
