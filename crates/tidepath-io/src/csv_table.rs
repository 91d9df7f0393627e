//! The one CSV writer every CSV output of tidepath goes through (plan exports, experiment run
//! tables): the `csv` crate, quoting a field only when it holds a comma, a quote, a carriage
//! return or a newline, with `\n` line ends.

use tidepath::error::{Error, Result};

/// A writer into memory.
pub fn writer() -> csv::Writer<Vec<u8>> {
    csv::WriterBuilder::new().terminator(csv::Terminator::Any(b'\n')).from_writer(Vec::new())
}

/// Writes one row; `what` names the output in errors.
pub fn row<I, T>(w: &mut csv::Writer<Vec<u8>>, what: &str, fields: I) -> Result<()>
where
    I: IntoIterator<Item = T>,
    T: AsRef<[u8]>,
{
    w.write_record(fields).map_err(|e| Error::input(what, format!("writing CSV: {e}")))
}

/// The text written.
pub fn text(w: csv::Writer<Vec<u8>>, what: &str) -> Result<String> {
    let bytes = w.into_inner().map_err(|e| Error::input(what, format!("writing CSV: {}", e.error())))?;
    String::from_utf8(bytes).map_err(|e| Error::input(what, format!("writing CSV: {e}")))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn fields_are_quoted_only_when_needed_and_lines_end_in_newline() {
        let mut w = writer();
        row(&mut w, "t", ["plain", "a,b", "say \"hi\"", "two\nlines", "cr\rhere"]).unwrap();
        assert_eq!(text(w, "t").unwrap(), "plain,\"a,b\",\"say \"\"hi\"\"\",\"two\nlines\",\"cr\rhere\"\n");
    }
}
