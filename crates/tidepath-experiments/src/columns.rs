//! How numbers are written in a table column: one format per column, chosen from all its
//! values, so that a reader can compare rows digit by digit (a column never mixes `0.5430` with
//! `4.702`, or `1.2e-7` with `3.400`).

/// The format of one column: fixed decimals, or scientific notation when the values span more
/// than fixed decimals can show with the wanted precision.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ColumnFormat {
    /// This many decimals for every value.
    Fixed(usize),
    /// Scientific notation with this many decimals in the mantissa.
    Scientific(usize),
}

/// Largest ratio between a column's largest and smallest non-zero magnitude still written with
/// fixed decimals: beyond it the large values would carry too many digits.
const FIXED_SPAN: f64 = 1e4;

impl ColumnFormat {
    /// The format that gives the column's smallest non-zero magnitude `digits` significant
    /// digits (at least 1). Fixed decimals when every magnitude lies in [1e-3, 1e5) and the
    /// largest is at most 1e4 times the smallest; scientific otherwise. Zeros, infinities and
    /// NaN do not choose the format.
    pub fn of(values: impl IntoIterator<Item = f64>, digits: usize) -> Self {
        let digits = digits.max(1);
        let (lo, hi) = values
            .into_iter()
            .filter(|v| v.is_finite() && *v != 0.0)
            .map(f64::abs)
            .fold((f64::INFINITY, 0.0f64), |(lo, hi), a| (lo.min(a), hi.max(a)));
        if hi == 0.0 {
            return ColumnFormat::Fixed(0);
        }
        if lo < 1e-3 || hi >= 1e5 || hi > lo * FIXED_SPAN {
            return ColumnFormat::Scientific(digits - 1);
        }
        let decimals = digits as i32 - 1 - lo.log10().floor() as i32;
        ColumnFormat::Fixed(decimals.max(0) as usize)
    }

    /// `x` in this format; exact zero is `0` in scientific columns (it has no exponent), NaN is
    /// `—`.
    pub fn show(self, x: f64) -> String {
        if x.is_nan() {
            return "—".into();
        }
        if x.is_infinite() {
            return if x > 0.0 { "inf".into() } else { "-inf".into() };
        }
        match self {
            ColumnFormat::Fixed(d) => format!("{x:.d$}"),
            ColumnFormat::Scientific(_) if x == 0.0 => "0".into(),
            ColumnFormat::Scientific(d) => format!("{x:.d$e}"),
        }
    }
}

/// A header and the cells of one column of a Markdown table, in row order.
pub struct Column {
    pub header: String,
    pub cells: Vec<String>,
}

impl Column {
    pub fn new(header: impl Into<String>, cells: Vec<String>) -> Self {
        Self { header: header.into(), cells }
    }

    /// A numeric column written in one format chosen from all its values (`digits` significant
    /// digits for the smallest).
    pub fn numbers(header: impl Into<String>, values: Vec<f64>, digits: usize) -> Self {
        let f = ColumnFormat::of(values.iter().copied(), digits);
        Self::new(header, values.into_iter().map(|v| f.show(v)).collect())
    }
}

/// The Markdown table of `columns` (all of the same length).
pub fn render(columns: &[Column]) -> String {
    let line = |cells: Vec<&str>| format!("| {} |\n", cells.join(" | "));
    let mut out = line(columns.iter().map(|c| c.header.as_str()).collect());
    out.push_str(&format!("|{}\n", "---|".repeat(columns.len())));
    let rows = columns.first().map_or(0, |c| c.cells.len());
    for i in 0..rows {
        out.push_str(&line(columns.iter().map(|c| c.cells[i].as_str()).collect()));
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_column_shares_one_format() {
        // Smallest non-zero 0.5430 gets 4 significant digits: 4 decimals for all.
        let f = ColumnFormat::of([4.7016, 0.543, 0.0], 4);
        assert_eq!(f, ColumnFormat::Fixed(4));
        assert_eq!([f.show(4.7016), f.show(0.543), f.show(0.0)], ["4.7016", "0.5430", "0.0000"]);
        // Lengths: 4 significant digits of 9632 need no decimals.
        let f = ColumnFormat::of([12929.47, 9632.2], 4);
        assert_eq!([f.show(12929.47), f.show(9632.2)], ["12929", "9632"]);
        // Benchmark costs from 1.75e-36 to 58: scientific for every value, zero stays 0.
        let f = ColumnFormat::of([1.75e-36, 58.04, 0.0], 4);
        assert_eq!(f, ColumnFormat::Scientific(3));
        assert_eq!([f.show(1.75e-36), f.show(58.04), f.show(0.0)], ["1.750e-36", "5.804e1", "0"]);
        // A span over 1e4 is scientific even inside [1e-3, 1e5).
        assert_eq!(ColumnFormat::of([0.002, 50.0], 4), ColumnFormat::Scientific(3));
        // p-values with 2 significant digits.
        let f = ColumnFormat::of([0.007495, 0.4], 2);
        assert_eq!([f.show(0.007495), f.show(0.4)], ["0.0075", "0.4000"]);
        // Nothing but zeros and infinities: whole numbers.
        let f = ColumnFormat::of([0.0, f64::INFINITY], 4);
        assert_eq!([f.show(0.0), f.show(f64::INFINITY), f.show(f64::NAN)], ["0", "inf", "—"]);
    }
}
