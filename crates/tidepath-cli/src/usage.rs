//! Usage errors in one line: clap's message, its tips ("a similar argument exists: ..."), and
//! the `--help` of the command that was mistyped, so the fix is on the same line as the error.

/// One line from clap's rendered error `text`: the first paragraph, every `tip:` line, and a
/// pointer to the `--help` of the command named in its `Usage:` line.
pub fn one_line(text: &str) -> String {
    // The first paragraph (clap may wrap it over several lines), on one line.
    let first: Vec<&str> =
        text.lines().skip_while(|l| l.trim().is_empty()).take_while(|l| !l.trim().is_empty()).map(str::trim).collect();
    let tips: Vec<&str> = text.lines().map(str::trim).filter(|l| l.starts_with("tip:")).collect();
    let mut line = first.join(" ");
    for tip in tips {
        line.push_str("; ");
        line.push_str(tip);
    }
    format!("{line} (see `{} --help`)", command(text))
}

/// The command path of clap's `Usage:` line (`tidepath compare`), up to its first argument;
/// `tidepath` when there is none.
fn command(text: &str) -> String {
    let usage = text.lines().find_map(|l| l.trim().strip_prefix("Usage:"));
    let words: Vec<&str> = usage
        .map(|u| u.split_whitespace().take_while(|w| !w.starts_with(['<', '[', '-'])).collect())
        .unwrap_or_default();
    if words.is_empty() {
        "tidepath".into()
    } else {
        words.join(" ")
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_tip_and_the_subcommand_help_stay_on_the_line() {
        let clap = "error: unexpected argument '--planner' found\n\n  tip: a similar argument exists: '--planners'\n\n\
                    Usage: tidepath compare <SCENARIO> --planners <PLANNERS>\n\nFor more information, try '--help'.\n";
        assert_eq!(
            one_line(clap),
            "error: unexpected argument '--planner' found; tip: a similar argument exists: '--planners' \
             (see `tidepath compare --help`)"
        );
        let nested = "error: the following required arguments were not provided:\n  --algos <ALGOS>\n\n\
                      Usage: tidepath bench functions [OPTIONS] --algos <ALGOS>\n";
        assert_eq!(
            one_line(nested),
            "error: the following required arguments were not provided: --algos <ALGOS> \
             (see `tidepath bench functions --help`)"
        );
        assert_eq!(
            one_line("error: unrecognized subcommand 'x'\n"),
            "error: unrecognized subcommand 'x' (see `tidepath --help`)"
        );
    }
}
