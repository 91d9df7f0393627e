//! One registry type for every kind of component (planners, cost models, encodings, smoothers,
//! built-in scenarios, reproductions), after ruff's rule table: each entry is written once,
//! with its id, a one-line description, its citation, its parameter declarations and a
//! constructor, and the CLI's lists, `--help`, "known: ..." errors and the generic tests all
//! read the table. Adding a component is a new file plus one table line.

use crate::error::{Error, Result};
use crate::params::ParamSpec;

/// One registered component of kind `B` (its constructor's type).
#[derive(Clone, Copy, Debug)]
pub struct Entry<B: Copy + 'static> {
    pub id: &'static str,
    pub description: &'static str,
    /// Where the method comes from (paper citation and reproduction id, or "tidepath").
    pub citation: &'static str,
    /// Its parameters, each declared once ([`crate::params!`]): ranges, defaults, help.
    pub params: &'static [ParamSpec],
    pub build: B,
}

impl<B: Copy + 'static> Entry<B> {
    /// The parameters' defaults, as the TOML table a scenario would write.
    pub fn defaults(&self) -> toml::Table {
        self.params.iter().filter_map(|p| (p.default)().map(|v| (p.name.to_string(), v))).collect()
    }

    /// Whether the component has a parameter named `name`.
    pub fn has_param(&self, name: &str) -> bool {
        self.params.iter().any(|p| p.name == name)
    }
}

/// A table of entries of one kind. Built-in tables are `const` slices; a program (or a test)
/// extends one with [`Registry::with`].
#[derive(Clone, Debug)]
pub struct Registry<B: Copy + 'static> {
    /// "planner", "cost model", ...: used in messages.
    pub kind: &'static str,
    /// The scenario field or flag that names an entry of this kind, for error messages.
    pub field: &'static str,
    /// The command that lists this kind, for error messages.
    pub list_command: &'static str,
    entries: Vec<Entry<B>>,
}

impl<B: Copy + 'static> Registry<B> {
    pub fn new(kind: &'static str, field: &'static str, list_command: &'static str, entries: &[Entry<B>]) -> Self {
        Self { kind, field, list_command, entries: entries.to_vec() }
    }

    /// The registry with `entry` added (replacing an entry with the same id).
    pub fn with(mut self, entry: Entry<B>) -> Self {
        self.entries.retain(|e| e.id != entry.id);
        self.entries.push(entry);
        self
    }

    pub fn entries(&self) -> &[Entry<B>] {
        &self.entries
    }

    pub fn ids(&self) -> impl Iterator<Item = &'static str> + '_ {
        self.entries.iter().map(|e| e.id)
    }

    pub fn find(&self, id: &str) -> Option<&Entry<B>> {
        self.entries.iter().find(|e| e.id == id)
    }

    /// The entry `id`, or an input error naming the field and listing the known ids.
    pub fn get(&self, id: &str) -> Result<&Entry<B>> {
        self.find(id).ok_or_else(|| {
            let known = self.ids().collect::<Vec<_>>().join(", ");
            let hint =
                if self.list_command.is_empty() { String::new() } else { format!("; run `{}`", self.list_command) };
            Error::input(self.field, format!("unknown {} '{id}' (known: {known}{hint})", self.kind))
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const E: &[Entry<u8>] = &[
        Entry { id: "a", description: "", citation: "", params: &[], build: 1 },
        Entry { id: "b", description: "", citation: "", params: &[], build: 2 },
    ];

    #[test]
    fn lookup_extension_and_unknown_ids() {
        let r = Registry::new("thing", "thing.id", "tidepath things", E);
        assert_eq!(r.get("b").unwrap().build, 2);
        let e = r.get("zz").unwrap_err().to_string();
        assert_eq!(e, "thing.id: unknown thing 'zz' (known: a, b; run `tidepath things`)");
        let r = r.with(Entry { id: "c", description: "", citation: "", params: &[], build: 3 });
        assert_eq!(r.ids().collect::<Vec<_>>(), ["a", "b", "c"]);
    }
}
