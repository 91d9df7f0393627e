//! The layering checker: reads a crate's sources with `syn` and lists every path from one
//! layer to another (see `layers.rs` for what it checks and why).

use std::collections::{BTreeMap, BTreeSet};
use std::path::Path;

use proc_macro2::{Delimiter, TokenStream, TokenTree};
use syn::punctuated::Punctuated;
use syn::visit::{self, Visit};
use syn::{Attribute, Ident, Item, Meta, UseTree};

/// One reference from a layer's non-test code to a crate module.
#[derive(Debug, Clone)]
pub(crate) struct Use {
    pub(crate) file: String,
    pub(crate) line: usize,
    /// The layer the referring code is in.
    pub(crate) from: String,
    /// The layer it refers to.
    pub(crate) to: String,
    /// The path as written (a `use` tree's leaf spelled out in full).
    pub(crate) path: String,
}

/// What [`scan`] found.
#[derive(Debug, Default)]
pub(crate) struct Scan {
    pub(crate) uses: Vec<Use>,
    /// Paths that name something under the crate root that is neither a module nor a
    /// re-export of `lib.rs`, and other things the checker cannot place.
    pub(crate) problems: Vec<String>,
    /// Top-level modules declared in `lib.rs` (outside test code).
    pub(crate) top: BTreeSet<String>,
    /// Files read as non-test code.
    pub(crate) checked: BTreeSet<String>,
    /// Files of modules declared under `#[cfg(test)]`, not read.
    pub(crate) test_files: BTreeSet<String>,
}

/// A `mod name;` without a body, to be read from its file.
pub(crate) struct PendingMod {
    pub(crate) module: Vec<String>,
    pub(crate) child_dir: String,
    pub(crate) test: bool,
    pub(crate) line: usize,
}

/// Reads the crate whose sources are `files` (paths relative to `src`, `/`-separated),
/// starting at `lib.rs` and following `mod` declarations.
pub(crate) fn scan(files: &BTreeMap<String, String>) -> Scan {
    let mut out = Scan::default();
    let root = parse(files, "lib.rs");
    // `crate::Name` for a name `lib.rs` re-exports means the module it comes from
    // (`pub use error::Error` -> `error`).
    let mut exports = BTreeMap::new();
    for item in &root.items {
        if test_only(item_attrs(item)) {
            continue;
        }
        match item {
            Item::Mod(m) => {
                out.top.insert(m.ident.to_string());
            }
            Item::Use(u) => root_exports(&u.tree, None, &mut exports, &mut out.problems),
            _ => {}
        }
    }
    let mut queue = vec![("lib.rs".to_string(), Vec::<String>::new(), String::new())];
    while let Some((file, module, child_dir)) = queue.pop() {
        let ast = parse(files, &file);
        out.checked.insert(file.clone());
        let mut w = Walker {
            file: &file,
            module,
            child_dir,
            top: &out.top,
            exports: &exports,
            uses: Vec::new(),
            problems: Vec::new(),
            mods: Vec::new(),
        };
        w.visit_file(&ast);
        out.uses.append(&mut w.uses);
        out.problems.append(&mut w.problems);
        for m in w.mods {
            let name = m.module.last().unwrap();
            let flat = format!("{}{name}.rs", m.child_dir);
            let nested = format!("{}{name}/mod.rs", m.child_dir);
            let found = match (files.contains_key(&flat), files.contains_key(&nested)) {
                (true, false) => flat,
                (false, true) => nested,
                (a, _) => {
                    let why = if a { "both" } else { "neither" };
                    out.problems.push(format!("{file}:{}: mod {name}: {why} of {flat} and {nested} exist", m.line));
                    continue;
                }
            };
            if m.test {
                out.test_files.insert(found);
            } else {
                let child_dir = format!("{}{name}/", m.child_dir);
                queue.push((found, m.module, child_dir));
            }
        }
    }
    out
}

pub(crate) fn parse(files: &BTreeMap<String, String>, file: &str) -> syn::File {
    let text = files.get(file).unwrap_or_else(|| panic!("{file} is missing"));
    syn::parse_file(text).unwrap_or_else(|e| panic!("{file}: {e}"))
}

/// Records what each name re-exported by `lib.rs` comes from: its first module.
pub(crate) fn root_exports(
    tree: &UseTree,
    first: Option<&str>,
    out: &mut BTreeMap<String, String>,
    problems: &mut Vec<String>,
) {
    match tree {
        UseTree::Path(p) => {
            let id = p.ident.to_string();
            let first = match first {
                Some(f) => Some(f),
                None if id == "crate" || id == "self" => None,
                None => Some(id.as_str()),
            };
            root_exports(&p.tree, first, out, problems);
        }
        UseTree::Name(n) => {
            if let Some(f) = first {
                out.insert(n.ident.to_string(), f.to_string());
            }
        }
        UseTree::Rename(r) => {
            if let Some(f) = first {
                out.insert(r.rename.to_string(), f.to_string());
            }
        }
        UseTree::Group(g) => {
            for t in &g.items {
                root_exports(t, first, out, problems);
            }
        }
        UseTree::Glob(_) => problems.push("lib.rs: a glob re-export hides which module a name comes from".into()),
    }
}

/// Whether these attributes make an item exist only in test builds.
pub(crate) fn test_only(attrs: &[Attribute]) -> bool {
    attrs.iter().any(|a| {
        a.path().is_ident("test")
            || (a.path().is_ident("cfg") && a.parse_args::<Meta>().is_ok_and(|m| requires_test(&m)))
    })
}

/// `test`, or `all(..)` with a part that requires `test`.
pub(crate) fn requires_test(m: &Meta) -> bool {
    match m {
        Meta::Path(p) => p.is_ident("test"),
        Meta::List(l) if l.path.is_ident("all") => l
            .parse_args_with(Punctuated::<Meta, syn::Token![,]>::parse_terminated)
            .is_ok_and(|parts| parts.iter().any(requires_test)),
        _ => false,
    }
}

pub(crate) fn item_attrs(item: &Item) -> &[Attribute] {
    match item {
        Item::Const(i) => &i.attrs,
        Item::Enum(i) => &i.attrs,
        Item::ExternCrate(i) => &i.attrs,
        Item::Fn(i) => &i.attrs,
        Item::ForeignMod(i) => &i.attrs,
        Item::Impl(i) => &i.attrs,
        Item::Macro(i) => &i.attrs,
        Item::Mod(i) => &i.attrs,
        Item::Static(i) => &i.attrs,
        Item::Struct(i) => &i.attrs,
        Item::Trait(i) => &i.attrs,
        Item::TraitAlias(i) => &i.attrs,
        Item::Type(i) => &i.attrs,
        Item::Union(i) => &i.attrs,
        Item::Use(i) => &i.attrs,
        _ => &[],
    }
}

/// Walks one file, in the module `module` whose child modules' files live in `child_dir`.
pub(crate) struct Walker<'a> {
    file: &'a str,
    module: Vec<String>,
    child_dir: String,
    top: &'a BTreeSet<String>,
    exports: &'a BTreeMap<String, String>,
    uses: Vec<Use>,
    problems: Vec<String>,
    mods: Vec<PendingMod>,
}

impl Walker<'_> {
    /// Resolves a path spelled as `segs` in the current module and records the layer it
    /// names. Paths not starting with `crate`, `self` or `super` name a child item or another
    /// crate and stay in the layer. The crate root itself (`lib.rs`) may use anything.
    fn record(&mut self, segs: &[Ident]) {
        let Some(first) = segs.first() else { return };
        let line = first.span().start().line;
        let names: Vec<String> = segs.iter().map(|s| s.to_string()).collect();
        let shown = names.join("::");
        let Some(from) = self.module.first().cloned() else { return };
        if names == ["self"] {
            return; // a method's receiver, not a module
        }
        let (mut base, mut i) = match names[0].as_str() {
            "crate" => (Vec::new(), 1),
            "self" | "super" => (self.module.clone(), 0),
            _ => return,
        };
        while i < names.len() && (names[i] == "self" || names[i] == "super") {
            if names[i] == "super" && base.pop().is_none() {
                self.problems.push(format!("{}:{line}: {shown} goes above the crate root", self.file));
                return;
            }
            i += 1;
        }
        let to = match (base.first(), names.get(i)) {
            (Some(m), _) => m.clone(),
            (None, None) => return, // the root itself, as in `pub(crate)`
            (None, Some(n)) if self.top.contains(n) => n.clone(),
            (None, Some(n)) => match self.exports.get(n) {
                Some(m) => m.clone(),
                None => {
                    self.problems.push(format!(
                        "{}:{line}: {shown}: {n} is neither a module nor a re-export of lib.rs",
                        self.file
                    ));
                    return;
                }
            },
        };
        self.uses.push(Use { file: self.file.to_string(), line, from, to, path: shown });
    }

    /// Records every leaf of a `use` tree, with the prefix it sits under.
    fn use_tree(&mut self, prefix: &mut Vec<Ident>, tree: &UseTree) {
        match tree {
            UseTree::Path(p) => {
                prefix.push(p.ident.clone());
                self.use_tree(prefix, &p.tree);
                prefix.pop();
            }
            UseTree::Name(n) if n.ident == "self" => self.record(prefix),
            UseTree::Name(n) => self.leaf(prefix, &n.ident),
            UseTree::Rename(r) if r.ident == "self" => self.record(prefix),
            UseTree::Rename(r) => self.leaf(prefix, &r.ident),
            UseTree::Glob(_) => self.record(prefix),
            UseTree::Group(g) => {
                for t in &g.items {
                    self.use_tree(prefix, t);
                }
            }
        }
    }

    fn leaf(&mut self, prefix: &mut Vec<Ident>, ident: &Ident) {
        prefix.push(ident.clone());
        self.record(prefix);
        prefix.pop();
    }

    /// Finds `crate::…`, `$crate::…` and `super::…` paths (grouped ones too) among a macro
    /// call's tokens, which `syn` leaves unparsed.
    fn tokens(&mut self, ts: TokenStream) {
        let tts: Vec<TokenTree> = ts.into_iter().collect();
        let colon = |t: Option<&TokenTree>| matches!(t, Some(TokenTree::Punct(p)) if p.as_char() == ':');
        let mut i = 0;
        while i < tts.len() {
            match &tts[i] {
                TokenTree::Group(g) => self.tokens(g.stream()),
                TokenTree::Ident(id) if id == "crate" || id == "super" => {
                    let mut j = i + 1;
                    while colon(tts.get(j)) && colon(tts.get(j + 1)) {
                        match tts.get(j + 2) {
                            Some(TokenTree::Ident(_)) => j += 3,
                            Some(TokenTree::Group(g)) if g.delimiter() == Delimiter::Brace => {
                                j += 3;
                                break;
                            }
                            Some(TokenTree::Punct(p)) if p.as_char() == '*' => {
                                j += 3;
                                break;
                            }
                            _ => break,
                        }
                    }
                    if j > i + 1 {
                        let stream: TokenStream = tts[i..j].iter().cloned().collect();
                        match syn::parse2::<UseTree>(stream) {
                            Ok(tree) => self.use_tree(&mut Vec::new(), &tree),
                            Err(e) => self.problems.push(format!(
                                "{}:{}: cannot read a path in a macro: {e}",
                                self.file,
                                id.span().start().line
                            )),
                        }
                        i = j;
                        continue;
                    }
                }
                _ => {}
            }
            i += 1;
        }
    }
}

impl<'ast> Visit<'ast> for Walker<'_> {
    fn visit_item(&mut self, i: &'ast Item) {
        if test_only(item_attrs(i)) {
            if let Item::Mod(m) = i {
                if m.content.is_none() {
                    let mut module = self.module.clone();
                    module.push(m.ident.to_string());
                    let line = m.ident.span().start().line;
                    self.mods.push(PendingMod { module, child_dir: self.child_dir.clone(), test: true, line });
                }
            }
            return;
        }
        visit::visit_item(self, i);
    }

    fn visit_item_mod(&mut self, m: &'ast syn::ItemMod) {
        if let Some(a) = m.attrs.iter().find(|a| a.path().is_ident("path")) {
            let line = a.pound_token.spans[0].start().line;
            self.problems.push(format!("{}:{line}: #[path] is not followed by this check", self.file));
        }
        let name = m.ident.to_string();
        let mut module = self.module.clone();
        module.push(name.clone());
        if m.content.is_none() {
            let line = m.ident.span().start().line;
            self.mods.push(PendingMod { module, child_dir: self.child_dir.clone(), test: false, line });
            return;
        }
        let dir = format!("{}{name}/", self.child_dir);
        let saved_dir = std::mem::replace(&mut self.child_dir, dir);
        let saved_module = std::mem::replace(&mut self.module, module);
        visit::visit_item_mod(self, m);
        self.module = saved_module;
        self.child_dir = saved_dir;
    }

    fn visit_item_use(&mut self, u: &'ast syn::ItemUse) {
        if u.leading_colon.is_none() {
            self.use_tree(&mut Vec::new(), &u.tree);
        }
    }

    fn visit_path(&mut self, p: &'ast syn::Path) {
        if p.leading_colon.is_none() {
            let segs: Vec<Ident> = p.segments.iter().map(|s| s.ident.clone()).collect();
            self.record(&segs);
        }
        visit::visit_path(self, p);
    }

    fn visit_macro(&mut self, m: &'ast syn::Macro) {
        self.tokens(m.tokens.clone());
        visit::visit_macro(self, m);
    }

    fn visit_impl_item(&mut self, i: &'ast syn::ImplItem) {
        let attrs: &[Attribute] = match i {
            syn::ImplItem::Const(c) => &c.attrs,
            syn::ImplItem::Fn(f) => &f.attrs,
            syn::ImplItem::Type(t) => &t.attrs,
            syn::ImplItem::Macro(m) => &m.attrs,
            _ => &[],
        };
        if !test_only(attrs) {
            visit::visit_impl_item(self, i);
        }
    }

    fn visit_trait_item(&mut self, i: &'ast syn::TraitItem) {
        let attrs: &[Attribute] = match i {
            syn::TraitItem::Const(c) => &c.attrs,
            syn::TraitItem::Fn(f) => &f.attrs,
            syn::TraitItem::Type(t) => &t.attrs,
            syn::TraitItem::Macro(m) => &m.attrs,
            _ => &[],
        };
        if !test_only(attrs) {
            visit::visit_trait_item(self, i);
        }
    }

    fn visit_field(&mut self, f: &'ast syn::Field) {
        if !test_only(&f.attrs) {
            visit::visit_field(self, f);
        }
    }

    fn visit_field_value(&mut self, f: &'ast syn::FieldValue) {
        if !test_only(&f.attrs) {
            visit::visit_field_value(self, f);
        }
    }

    fn visit_variant(&mut self, v: &'ast syn::Variant) {
        if !test_only(&v.attrs) {
            visit::visit_variant(self, v);
        }
    }

    fn visit_arm(&mut self, a: &'ast syn::Arm) {
        if !test_only(&a.attrs) {
            visit::visit_arm(self, a);
        }
    }

    fn visit_local(&mut self, l: &'ast syn::Local) {
        if !test_only(&l.attrs) {
            visit::visit_local(self, l);
        }
    }

    fn visit_stmt_macro(&mut self, m: &'ast syn::StmtMacro) {
        if !test_only(&m.attrs) {
            visit::visit_stmt_macro(self, m);
        }
    }
}

pub(crate) fn rank(order: &[&str], name: &str) -> Option<usize> {
    order.iter().position(|m| *m == name)
}

/// Every use of a layer above the user's, and every layer missing from `order`.
pub(crate) fn upward(uses: &[Use], order: &[&str]) -> Vec<String> {
    let mut wrong = Vec::new();
    for u in uses {
        match (rank(order, &u.from), rank(order, &u.to)) {
            (Some(f), Some(t)) if t > f => {
                wrong.push(format!("{}:{}: {} uses {} ({})", u.file, u.line, u.from, u.to, u.path))
            }
            (Some(_), Some(_)) => {}
            _ => wrong.push(format!("{}:{}: {} or {} is not in ORDER", u.file, u.line, u.from, u.to)),
        }
    }
    wrong
}

/// Every dependency of a workspace crate on a crate not before it in `crates`. `manifests`
/// are the crates' `Cargo.toml` texts.
pub(crate) fn crate_violations(manifests: &[(String, String)], crates: &[&str]) -> Vec<String> {
    let mut wrong = Vec::new();
    for (where_, text) in manifests {
        let doc: toml::Table = text.parse().unwrap_or_else(|e| panic!("{where_}: {e}"));
        let name = doc["package"]["name"].as_str().unwrap().to_string();
        let Some(own) = rank(crates, &name) else {
            wrong.push(format!("{where_}: crate {name} is not in CRATES"));
            continue;
        };
        let mut tables = Vec::new();
        for kind in ["dependencies", "dev-dependencies", "build-dependencies"] {
            tables.extend(doc.get(kind).and_then(|t| t.as_table()).map(|t| (kind.to_string(), t)));
            if let Some(targets) = doc.get("target").and_then(|t| t.as_table()) {
                for (cfg, t) in targets {
                    let t = t.get(kind).and_then(|t| t.as_table());
                    tables.extend(t.map(|t| (format!("target.{cfg}.{kind}"), t)));
                }
            }
        }
        for (kind, table) in tables {
            for (key, spec) in table {
                let dep = spec.get("package").and_then(|p| p.as_str()).unwrap_or(key);
                if rank(crates, dep).is_some_and(|r| r >= own) {
                    wrong.push(format!("{where_}: {name} ({kind}) depends on {dep}, not below it"));
                }
            }
        }
    }
    wrong
}

pub(crate) fn read_tree(dir: &Path, root: &Path, out: &mut BTreeMap<String, String>) {
    for e in std::fs::read_dir(dir).unwrap() {
        let p = e.unwrap().path();
        if p.is_dir() {
            read_tree(&p, root, out);
        } else if p.extension().is_some_and(|x| x == "rs") {
            let rel = p.strip_prefix(root).unwrap().components().map(|c| c.as_os_str().to_string_lossy().into_owned());
            out.insert(rel.collect::<Vec<_>>().join("/"), std::fs::read_to_string(&p).unwrap());
        }
    }
}

#[cfg(test)]
#[path = "checker_tests.rs"]
mod tests;
