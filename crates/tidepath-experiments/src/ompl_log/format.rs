//! Text fields of the log: numbers, booleans, words, setup blocks and UTC dates.

pub(super) fn boolean(b: bool) -> String {
    // The `bestPlannerConfigs` views average `solved`, which needs numbers, not words.
    if b { "1" } else { "0" }.to_string()
}

/// Shortest round-trip text; exponent form only where plain digits would run long. Empty (NULL)
/// for non-finite values, see the module docs.
pub(super) fn real(x: f64) -> String {
    if !x.is_finite() {
        return String::new();
    }
    let a = x.abs();
    if a != 0.0 && !(1e-5..1e16).contains(&a) {
        format!("{x:e}")
    } else {
        format!("{x}")
    }
}

/// Header numbers go through Python's `float()` and cannot be empty.
pub(super) fn header_real(x: f64) -> String {
    if x.is_finite() {
        real(x)
    } else {
        "0".to_string()
    }
}

pub(super) fn token(s: &str, fallback: &str) -> String {
    let t = s.split_whitespace().collect::<Vec<_>>().join("_");
    if t.is_empty() {
        fallback.to_string()
    } else {
        t
    }
}

pub(super) fn block(text: &str) -> String {
    // Python reads with universal newlines, so a lone '\r' also ends a line.
    let text = text.replace("\r\n", "\n").replace('\r', "\n");
    let mut out = String::new();
    for line in text.lines() {
        if line.starts_with("|>>>") {
            out.push(' ');
        }
        out.push_str(line);
        out.push('\n');
    }
    out
}

pub(super) fn utc_date_time(unix_s: u64) -> String {
    let secs = unix_s % 86_400;
    let (y, m, d) = civil_from_days((unix_s / 86_400) as i64);
    format!("{y:04}-{m:02}-{d:02} {:02}:{:02}:{:02}", secs / 3600, secs / 60 % 60, secs % 60)
}

/// Days since 1970-01-01 to a proleptic Gregorian date (H. Hinnant's `civil_from_days`); the
/// crate has no date dependency and needs only this.
fn civil_from_days(days: i64) -> (i64, u32, u32) {
    let z = days + 719_468;
    let era = z.div_euclid(146_097);
    let doe = z.rem_euclid(146_097);
    let yoe = (doe - doe / 1460 + doe / 36_524 - doe / 146_096) / 365;
    let doy = doe - (365 * yoe + yoe / 4 - yoe / 100);
    let mp = (5 * doy + 2) / 153;
    let d = (doy - (153 * mp + 2) / 5 + 1) as u32;
    let m = (if mp < 10 { mp + 3 } else { mp - 9 }) as u32;
    let y = yoe + era * 400 + i64::from(m <= 2);
    (y, m, d)
}
