//! Text shown to users: every error is one line, whatever the values in it hold.

use std::fmt::Write as _;

/// `s` with line breaks, tabs and other control characters written as escapes (`\n`, `\r`,
/// `\t`, `\u{1b}`), so a value with a newline in it (a departure, a path, an id) cannot split
/// an error message over several lines or move the terminal's cursor.
pub fn one_line(s: &str) -> std::borrow::Cow<'_, str> {
    if !s.chars().any(char::is_control) {
        return std::borrow::Cow::Borrowed(s);
    }
    let mut out = String::with_capacity(s.len() + 8);
    for c in s.chars() {
        match c {
            '\n' => out.push_str("\\n"),
            '\r' => out.push_str("\\r"),
            '\t' => out.push_str("\\t"),
            c if c.is_control() => {
                let _ = write!(out, "\\u{{{:x}}}", c as u32);
            }
            c => out.push(c),
        }
    }
    std::borrow::Cow::Owned(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn control_characters_are_escaped() {
        assert_eq!(one_line("plain, with ü"), "plain, with ü");
        assert_eq!(one_line("a\nb\r\tc\u{1b}[2J\u{7f}"), "a\\nb\\r\\tc\\u{1b}[2J\\u{7f}");
    }
}
