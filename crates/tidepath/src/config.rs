//! TOML configuration helpers shared by every layer that reads settings (scenarios, planner
//! parameters, cost weights): typed decoding whose errors name the dotted field, and a walk that
//! rejects NaN and infinities anywhere (TOML allows `nan` and `inf`).

use serde::de::DeserializeOwned;

use crate::error::{Error, Result};

/// Parses TOML into a typed value, rejecting non-finite numbers; errors name `source`.
pub fn parse_toml<T: DeserializeOwned>(text: &str, source: &str) -> Result<T> {
    let table: toml::Table = text.parse().map_err(|e: toml::de::Error| {
        let at = e
            .span()
            .map(|s| line_col(text, s.start))
            .map(|(l, c)| format!(" at line {l}, column {c}"))
            .unwrap_or_default();
        Error::input(source, format!("malformed TOML{at}: {}", e.message().trim()))
    })?;
    reject_non_finite(&toml::Value::Table(table.clone()), &mut String::new())?;
    from_value(toml::Value::Table(table), "")
}

/// Typed decoding of a TOML value; the error names the dotted path under `prefix`.
pub fn from_value<T: DeserializeOwned>(value: toml::Value, prefix: &str) -> Result<T> {
    serde_path_to_error::deserialize(value).map_err(|e| {
        let path = e.path().to_string();
        let field = match (prefix.is_empty(), path == ".") {
            (true, _) => path,
            (false, true) => prefix.to_string(),
            (false, false) => format!("{prefix}.{path}"),
        };
        Error::input(field, e.into_inner().message().trim().replace('\n', " "))
    })
}

fn line_col(text: &str, offset: usize) -> (usize, usize) {
    let before = &text[..offset.min(text.len())];
    let line = before.matches('\n').count() + 1;
    let col = before.rfind('\n').map_or(before.len(), |i| before.len() - i - 1) + 1;
    (line, col)
}

fn reject_non_finite(value: &toml::Value, path: &mut String) -> Result<()> {
    match value {
        toml::Value::Float(f) if !f.is_finite() => {
            Err(Error::input(path.clone(), format!("= {f}: numbers must be finite")))
        }
        toml::Value::Table(t) => {
            for (k, v) in t {
                let len = path.len();
                if !path.is_empty() {
                    path.push('.');
                }
                path.push_str(k);
                reject_non_finite(v, path)?;
                path.truncate(len);
            }
            Ok(())
        }
        toml::Value::Array(items) => {
            for (i, v) in items.iter().enumerate() {
                let len = path.len();
                path.push_str(&format!("[{i}]"));
                reject_non_finite(v, path)?;
                path.truncate(len);
            }
            Ok(())
        }
        _ => Ok(()),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[derive(serde::Deserialize, Debug)]
    #[allow(dead_code)]
    struct T {
        a: f64,
        b: Inner,
    }
    #[derive(serde::Deserialize, Debug)]
    #[allow(dead_code)]
    struct Inner {
        c: Vec<f64>,
    }

    #[test]
    fn nan_and_inf_are_named_with_their_path() {
        let e = parse_toml::<T>("a = 1.0\n[b]\nc = [1.0, nan]\n", "f.toml").unwrap_err().to_string();
        assert_eq!(e, "b.c[1]: = NaN: numbers must be finite");
        let e = parse_toml::<T>("a = -inf\n[b]\nc = []\n", "f.toml").unwrap_err().to_string();
        assert_eq!(e, "a: = -inf: numbers must be finite");
    }

    #[test]
    fn syntax_errors_are_one_line_with_position() {
        let e = parse_toml::<T>("a = 1.0\nb = [\n", "f.toml").unwrap_err().to_string();
        assert!(e.starts_with("f.toml: malformed TOML at line 2"), "{e}");
        assert!(!e.contains('\n'));
    }

    #[test]
    fn type_errors_name_the_field() {
        let e = parse_toml::<T>("a = 1.0\n[b]\nc = [1.0, \"x\"]\n", "f.toml").unwrap_err().to_string();
        assert!(e.starts_with("b.c[1]: invalid type: string \"x\""), "{e}");
    }
}
