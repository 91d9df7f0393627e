//! Parameters declared once. Each parameter of every component (optimizer, planner, smoother,
//! cost model, encoding) is written once, in a [`params!`](crate::params!) block: its name,
//! type, default, typed range, help and the paper it comes from. Everything else is derived
//! from that one declaration: the struct and its `Default`, reading a `[planner.params.ID]`
//! table (unknown keys, wrong types and values outside the range are input errors naming the
//! field: `planner.params.de.f: must be in (0, 2], got 3`), `tidepath planners --params`, and
//! the generic boundary test (each bound accepted, just beyond it refused).
//!
//! A component is built only from a [`Checked`] value, which only reading a table or checking
//! a preset can make, so unchecked parameters never reach an algorithm.

use std::fmt;

use crate::error::{Error, Result};

/// One end of a numeric range.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Bound {
    /// The value itself is allowed.
    Closed(f64),
    /// Only values strictly beyond it are allowed.
    Open(f64),
    /// No bound (the value must still be finite).
    Unbounded,
}

/// The values a parameter accepts.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Range {
    /// A finite number between two bounds.
    Number { lo: Bound, hi: Bound },
    /// An integer in `[min, max]`.
    Integer { min: u64, max: u64 },
    /// One of these words.
    Choice(&'static [&'static str]),
    /// Either value.
    Flag,
    /// A word naming another component (a smoother id, say), checked against its own table
    /// when the component is built.
    Id(&'static str),
}

impl Range {
    /// A finite number in `[lo, hi]`.
    pub const fn closed(lo: f64, hi: f64) -> Self {
        Range::Number { lo: Bound::Closed(lo), hi: Bound::Closed(hi) }
    }

    /// Any finite number.
    pub const fn finite() -> Self {
        Range::Number { lo: Bound::Unbounded, hi: Bound::Unbounded }
    }

    /// An integer in `[min, max]`.
    pub const fn integer(min: u64, max: u64) -> Self {
        Range::Integer { min, max }
    }

    /// Whether `v` (a number, for numeric ranges) is in the range; `Err` says why not.
    pub fn check_number(&self, v: f64) -> std::result::Result<(), String> {
        let ok = match *self {
            Range::Number { lo, hi } => {
                v.is_finite()
                    && match lo {
                        Bound::Closed(a) => v >= a,
                        Bound::Open(a) => v > a,
                        Bound::Unbounded => true,
                    }
                    && match hi {
                        Bound::Closed(b) => v <= b,
                        Bound::Open(b) => v < b,
                        Bound::Unbounded => true,
                    }
            }
            Range::Integer { min, max } => v.fract() == 0.0 && v >= min as f64 && v <= max as f64,
            Range::Choice(_) | Range::Flag | Range::Id(_) => false,
        };
        if ok {
            Ok(())
        } else {
            Err(format!("must be {self}, got {}", show(v)))
        }
    }

    /// Whether the word `w` is one of the choices.
    pub fn check_word(&self, w: &str) -> std::result::Result<(), String> {
        match self {
            Range::Choice(words) if words.contains(&w) => Ok(()),
            _ => Err(format!("must be {self}, got \"{w}\"")),
        }
    }
}

/// A number as a user wrote it: `3`, `0.5`, `1e-300` (never 300 zeros).
fn show(v: f64) -> String {
    if v.fract() == 0.0 && v.abs() < 1e15 {
        format!("{v:.0}")
    } else {
        format!("{v:?}")
    }
}

impl fmt::Display for Range {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match *self {
            Range::Number { lo: Bound::Unbounded, hi: Bound::Unbounded } => f.write_str("finite"),
            Range::Number { lo, hi } => {
                let (open, a) = match lo {
                    Bound::Closed(a) => ('[', show(a)),
                    Bound::Open(a) => ('(', show(a)),
                    Bound::Unbounded => ('(', "-inf".into()),
                };
                let (b, close) = match hi {
                    Bound::Closed(b) => (show(b), ']'),
                    Bound::Open(b) => (show(b), ')'),
                    Bound::Unbounded => ("inf".into(), ')'),
                };
                write!(f, "in {open}{a}, {b}{close}")
            }
            Range::Integer { min, max } => write!(f, "an integer in [{min}, {max}]"),
            Range::Choice(words) => {
                let quoted: Vec<String> = words.iter().map(|w| format!("\"{w}\"")).collect();
                write!(f, "one of {}", quoted.join(", "))
            }
            Range::Flag => f.write_str("true or false"),
            Range::Id(kind) => write!(f, "a {kind} id"),
        }
    }
}

/// One parameter, as declared: everything the CLI, the checks and the tests need.
#[derive(Clone, Copy, Debug)]
pub struct ParamSpec {
    pub name: &'static str,
    pub range: Range,
    /// `true` when the parameter may be left out (then it is absent, not defaulted).
    pub optional: bool,
    /// The default as TOML would write it; `None` for optional parameters without one.
    pub default: fn() -> Option<toml::Value>,
    /// The field's doc comment, as written (see [`ParamSpec::help`]).
    pub doc: &'static str,
    /// Where the parameter and its default come from (a reproduction id and section, or
    /// "tidepath").
    pub source: &'static str,
}

impl ParamSpec {
    /// The help line: the field's doc comment.
    pub fn help(&self) -> &'static str {
        self.doc.trim()
    }

    /// The default, as shown by `tidepath planners --params`.
    pub fn default_text(&self) -> String {
        match (self.default)() {
            Some(toml::Value::String(s)) => format!("\"{s}\""),
            Some(v) => v.to_string(),
            None => "absent".into(),
        }
    }
}

/// A value that passed its declaration's checks. Only [`Params::from_table`] and
/// [`Params::checked`] make one.
#[derive(Clone, Debug, PartialEq)]
pub struct Checked<T>(T);

impl<T> Checked<T> {
    pub fn get(&self) -> &T {
        &self.0
    }

    pub fn into_inner(self) -> T {
        self.0
    }
}

impl<T> std::ops::Deref for Checked<T> {
    type Target = T;

    fn deref(&self) -> &T {
        &self.0
    }
}

/// A Rust type a parameter can have.
pub trait ParamValue: Sized + Clone {
    /// Reads a TOML value; `Err` names what was expected.
    fn from_toml(v: &toml::Value) -> std::result::Result<Self, String>;
    fn to_toml(&self) -> Option<toml::Value>;
    /// Checks the value against its range.
    fn check(&self, range: &Range) -> std::result::Result<(), String>;
}

macro_rules! integer_param {
    ($($t:ty),*) => {$(
        impl ParamValue for $t {
            fn from_toml(v: &toml::Value) -> std::result::Result<Self, String> {
                match v {
                    toml::Value::Integer(i) if *i >= 0 => <$t>::try_from(*i).map_err(|_| format!("must be an integer we can hold, got {i}")),
                    toml::Value::Integer(i) => Err(format!("must be a non-negative integer, got {i}")),
                    other => Err(format!("must be an integer, got {other}")),
                }
            }
            fn to_toml(&self) -> Option<toml::Value> {
                Some(toml::Value::Integer(i64::try_from(*self).unwrap_or(i64::MAX)))
            }
            fn check(&self, range: &Range) -> std::result::Result<(), String> {
                match *range {
                    Range::Integer { min, max } if (*self as u64) < min || (*self as u64) > max => {
                        Err(format!("must be {range}, got {self}"))
                    }
                    _ => Ok(()),
                }
            }
        }
    )*};
}

integer_param!(usize, u64, u32);

impl ParamValue for f64 {
    fn from_toml(v: &toml::Value) -> std::result::Result<Self, String> {
        match v {
            toml::Value::Float(x) => Ok(*x),
            toml::Value::Integer(i) => Ok(*i as f64),
            other => Err(format!("must be a number, got {other}")),
        }
    }
    fn to_toml(&self) -> Option<toml::Value> {
        Some(toml::Value::Float(*self))
    }
    fn check(&self, range: &Range) -> std::result::Result<(), String> {
        range.check_number(*self)
    }
}

impl ParamValue for bool {
    fn from_toml(v: &toml::Value) -> std::result::Result<Self, String> {
        v.as_bool().ok_or_else(|| format!("must be true or false, got {v}"))
    }
    fn to_toml(&self) -> Option<toml::Value> {
        Some(toml::Value::Boolean(*self))
    }
    fn check(&self, _: &Range) -> std::result::Result<(), String> {
        Ok(())
    }
}

impl ParamValue for String {
    fn from_toml(v: &toml::Value) -> std::result::Result<Self, String> {
        v.as_str().map(str::to_string).ok_or_else(|| format!("must be a word, got {v}"))
    }
    fn to_toml(&self) -> Option<toml::Value> {
        Some(toml::Value::String(self.clone()))
    }
    fn check(&self, range: &Range) -> std::result::Result<(), String> {
        match range {
            Range::Choice(_) => range.check_word(self),
            _ => Ok(()),
        }
    }
}

impl<T: ParamValue> ParamValue for Option<T> {
    fn from_toml(v: &toml::Value) -> std::result::Result<Self, String> {
        T::from_toml(v).map(Some)
    }
    fn to_toml(&self) -> Option<toml::Value> {
        self.as_ref().and_then(T::to_toml)
    }
    fn check(&self, range: &Range) -> std::result::Result<(), String> {
        self.as_ref().map_or(Ok(()), |v| v.check(range))
    }
}

/// A word-valued parameter: an enum whose variants are the words of a [`Range::Choice`].
pub trait Word: Sized + Clone + Copy + PartialEq + 'static {
    /// Every variant with its word.
    const WORDS: &'static [(&'static str, Self)];
}

/// Implements [`ParamValue`] for a [`Word`] enum.
macro_rules! word_param {
    ($t:ty) => {
        impl $crate::params::ParamValue for $t {
            fn from_toml(v: &toml::Value) -> std::result::Result<Self, String> {
                let s = v.as_str().ok_or_else(|| format!("must be a word, got {v}"))?;
                <$t as $crate::params::Word>::WORDS.iter().find(|(w, _)| *w == s).map(|(_, x)| *x).ok_or_else(|| {
                    let known: Vec<String> =
                        <$t as $crate::params::Word>::WORDS.iter().map(|(w, _)| format!("\"{w}\"")).collect();
                    format!("must be one of {}, got \"{s}\"", known.join(", "))
                })
            }
            fn to_toml(&self) -> Option<toml::Value> {
                <$t as $crate::params::Word>::WORDS
                    .iter()
                    .find(|(_, x)| x == self)
                    .map(|(w, _)| toml::Value::String(w.to_string()))
            }
            fn check(&self, _: &$crate::params::Range) -> std::result::Result<(), String> {
                Ok(())
            }
        }
    };
}

/// A parameter struct declared with [`params!`](crate::params!).
pub trait Params: Sized + Clone + Default {
    /// The declarations, in order.
    const SPECS: &'static [ParamSpec];

    /// Reads the struct from a TOML table under `prefix` (e.g. `planner.params.de`): unknown
    /// keys, wrong types and values out of range are input errors naming `prefix.FIELD`;
    /// missing keys take their defaults.
    fn from_table(table: &toml::Table, prefix: &str) -> Result<Checked<Self>>;

    /// The struct as a table, every parameter that has a value.
    fn to_table(&self) -> toml::Table;

    /// Checks every field against its range (`prefix.FIELD` in errors), then the struct's
    /// own rules between fields (the `check = FN;` line of its declaration, e.g. elitism
    /// below the population).
    fn checked(self, prefix: &str) -> Result<Checked<Self>>;
}

/// Makes a [`Checked`] value; only the code [`params!`](crate::params!) generates calls it,
/// after checking.
#[doc(hidden)]
pub fn checked_unchecked<T>(t: T) -> Checked<T> {
    Checked(t)
}

/// The error for field `name` under `prefix`.
pub fn field_error(prefix: &str, name: &str, message: impl Into<String>) -> Error {
    Error::input(format!("{prefix}.{name}"), message)
}

/// Declares a parameter struct: each field once, with its default, range, help and source.
///
/// ```
/// use tidepath::params::{Params, Range};
/// tidepath::params! {
///     /// A toy.
///     pub struct Toy {
///         /// Step size.
///         step: f64 = 0.5, Range::closed(0.0, 1.0), "tidepath";
///     }
/// }
/// let mut t = toml::Table::new();
/// t.insert("step".into(), toml::Value::Float(2.0));
/// let e = Toy::from_table(&t, "planner.params.toy").unwrap_err().to_string();
/// assert_eq!(e, "planner.params.toy.step: must be in [0, 1], got 2");
/// ```
#[macro_export]
macro_rules! params {
    (
        $(#[$meta:meta])*
        $vis:vis struct $name:ident {
            $(
                $(#[doc = $doc:literal])*
                $field:ident : $ty:ty = $default:expr, $range:expr, $source:literal;
            )*
        }
        $(check = $check:path;)?
    ) => {
        $(#[$meta])*
        #[derive(Clone, Debug, PartialEq)]
        $vis struct $name {
            $( $(#[doc = $doc])* pub $field: $ty, )*
        }

        impl Default for $name {
            fn default() -> Self {
                Self { $( $field: $default, )* }
            }
        }

        impl $name {
            /// The declarations ([`Params::SPECS`](crate::params::Params::SPECS)).
            pub const SPECS: &'static [$crate::params::ParamSpec] = <Self as $crate::params::Params>::SPECS;

            /// Reads a table under `prefix` ([`Params::from_table`](crate::params::Params::from_table)).
            pub fn from_table(table: &toml::Table, prefix: &str) -> $crate::error::Result<$crate::params::Checked<Self>> {
                <Self as $crate::params::Params>::from_table(table, prefix)
            }

            /// Checks the values ([`Params::checked`](crate::params::Params::checked)).
            pub fn checked(self, prefix: &str) -> $crate::error::Result<$crate::params::Checked<Self>> {
                <Self as $crate::params::Params>::checked(self, prefix)
            }

            /// The values as a table ([`Params::to_table`](crate::params::Params::to_table)).
            pub fn to_table(&self) -> toml::Table {
                <Self as $crate::params::Params>::to_table(self)
            }
        }

        impl $crate::params::Params for $name {
            const SPECS: &'static [$crate::params::ParamSpec] = &[
                $( $crate::params::ParamSpec {
                    name: stringify!($field),
                    range: $range,
                    optional: $crate::params::is_option(stringify!($ty)),
                    default: || { let d: $ty = $default; $crate::params::ParamValue::to_toml(&d) },
                    doc: concat!($( $doc, )* ""),
                    source: $source,
                }, )*
            ];

            #[allow(unused_mut)]
            fn from_table(table: &toml::Table, prefix: &str) -> $crate::error::Result<$crate::params::Checked<Self>> {
                let known: &[&str] = &[$( stringify!($field) ),*];
                for key in table.keys() {
                    if !known.contains(&key.as_str()) {
                        return Err($crate::params::field_error(
                            prefix,
                            key,
                            if known.is_empty() {
                                "this component has no parameters".to_string()
                            } else {
                                format!("unknown parameter (known: {})", known.join(", "))
                            },
                        ));
                    }
                }
                let mut out = Self::default();
                $(
                    if let Some(v) = table.get(stringify!($field)) {
                        out.$field = <$ty as $crate::params::ParamValue>::from_toml(v)
                            .map_err(|m| $crate::params::field_error(prefix, stringify!($field), m))?;
                    }
                )*
                $crate::params::Params::checked(out, prefix)
            }

            #[allow(unused_mut)]
            fn to_table(&self) -> toml::Table {
                let mut t = toml::Table::new();
                $(
                    if let Some(v) = $crate::params::ParamValue::to_toml(&self.$field) {
                        t.insert(stringify!($field).to_string(), v);
                    }
                )*
                t
            }

            #[allow(unused_variables)]
            fn checked(self, prefix: &str) -> $crate::error::Result<$crate::params::Checked<Self>> {
                let specs = <Self as $crate::params::Params>::SPECS;
                $(
                    let spec = specs.iter().find(|s| s.name == stringify!($field)).expect("declared");
                    $crate::params::ParamValue::check(&self.$field, &spec.range)
                        .map_err(|m| $crate::params::field_error(prefix, stringify!($field), m))?;
                )*
                $( $check(&self, prefix)?; )?
                Ok($crate::params::checked_unchecked(self))
            }
        }
    };
}

/// Whether a field's type, as written, is an `Option` (an optional parameter).
pub const fn is_option(ty: &str) -> bool {
    let b = ty.as_bytes();
    b.len() >= 7 && b[0] == b'O' && b[1] == b'p' && b[2] == b't' && b[3] == b'i' && b[4] == b'o' && b[5] == b'n'
}

/// The defaults of a parameter struct, as a TOML table.
pub fn defaults_table<P: Params>() -> toml::Table {
    P::default().to_table()
}

/// Values just inside and just outside a range, for the generic boundary test: (value,
/// whether it must be accepted).
pub fn boundary_values(range: &Range) -> Vec<(toml::Value, bool)> {
    use toml::Value::{Float, Integer, String as Text};
    let mut out = Vec::new();
    match *range {
        Range::Number { lo, hi } => {
            for (b, below) in [(lo, true), (hi, false)] {
                let step = |x: f64| if below { next_down(x) } else { next_up(x) };
                match b {
                    Bound::Closed(x) => {
                        out.push((Float(x), true));
                        out.push((Float(step(x)), false));
                    }
                    Bound::Open(x) => {
                        out.push((Float(x), false));
                        let inside = if below { next_up(x) } else { next_down(x) };
                        out.push((Float(inside), true));
                    }
                    Bound::Unbounded => out.push((Float(if below { f64::NEG_INFINITY } else { f64::INFINITY }), false)),
                }
            }
            out.push((Float(f64::NAN), false));
        }
        Range::Integer { min, max } => {
            out.push((Integer(min as i64), true));
            out.push((Integer(min as i64 - 1), false));
            if max < i64::MAX as u64 {
                out.push((Integer(max as i64), true));
                out.push((Integer(max as i64 + 1), false));
            }
        }
        Range::Choice(words) => {
            for w in words {
                out.push((Text(w.to_string()), true));
            }
            out.push((Text("bogus".into()), false));
        }
        Range::Flag => {
            out.push((toml::Value::Boolean(true), true));
            out.push((toml::Value::Boolean(false), true));
        }
        Range::Id(_) => out.push((toml::Value::Integer(1), false)),
    }
    out
}

fn next_up(x: f64) -> f64 {
    if x == 0.0 {
        f64::from_bits(1)
    } else if x > 0.0 {
        f64::from_bits(x.to_bits() + 1)
    } else {
        f64::from_bits(x.to_bits() - 1)
    }
}

fn next_down(x: f64) -> f64 {
    -next_up(-x)
}

#[cfg(test)]
mod tests;

/// The word-parameter macro, at the path of the module it belongs to.
pub(crate) use word_param;
