//! Times as figures state them: on the scenario clock (seconds from its zero) or, when the
//! scenario has an epoch, as a UTC date, so a reader knows which instant a time-varying field
//! or a moving obstacle is drawn at.

use chrono::{DateTime, Duration, Utc};

/// "t = 0 s" or, with an epoch, "2024-05-01 12:30 UTC".
pub fn instant(t: f64, epoch: Option<DateTime<Utc>>) -> String {
    let utc = epoch.filter(|_| t.is_finite()).and_then(|e| {
        let ms = (t * 1000.0).round();
        (ms.abs() < 1e15).then(|| e + Duration::milliseconds(ms as i64))
    });
    match utc {
        Some(d) => d.format("%Y-%m-%d %H:%M UTC").to_string(),
        None => format!("t = {} s", super::style::fmt_sig(t)),
    }
}

/// A time span for time marks: "90 s", "30 min", "1 h 30 min", "26 h".
pub fn span(s: f64) -> String {
    if !s.is_finite() {
        return String::new();
    }
    let r = s.round() as i64;
    if r.abs() < 120 {
        format!("{r} s")
    } else if r % 3600 == 0 {
        format!("{} h", r / 3600)
    } else if r.abs() < 2 * 3600 && r % 60 == 0 || r.abs() < 3600 {
        format!("{} min", (s / 60.0).round() as i64)
    } else if r.abs() < 24 * 3600 {
        format!("{} h {} min", r / 3600, (r % 3600).abs() / 60)
    } else {
        format!("{} h", (s / 3600.0).round() as i64)
    }
}

/// A round step (s) giving at most `most` marks over `span_s` seconds.
pub fn mark_step(span_s: f64, most: usize) -> f64 {
    const STEPS: [f64; 14] =
        [10.0, 30.0, 60.0, 120.0, 300.0, 600.0, 900.0, 1800.0, 3600.0, 7200.0, 10800.0, 21600.0, 43200.0, 86400.0];
    let raw = span_s / most.max(1) as f64;
    STEPS.iter().copied().find(|&s| s >= raw).unwrap_or_else(|| (raw / 86400.0).ceil() * 86400.0)
}

#[cfg(test)]
mod tests {
    use super::*;
    use chrono::TimeZone;

    #[test]
    fn times_read_as_clock_or_date() {
        assert_eq!(instant(0.0, None), "t = 0 s");
        assert_eq!(instant(1800.0, None), "t = 1800 s");
        let e = Utc.with_ymd_and_hms(2024, 5, 1, 12, 0, 0).unwrap();
        assert_eq!(instant(5400.0, Some(e)), "2024-05-01 13:30 UTC");
        assert_eq!(
            (span(90.0), span(1800.0), span(5400.0), span(7200.0)),
            ("90 s".into(), "30 min".into(), "90 min".into(), "2 h".into())
        );
        assert_eq!(span(3600.0), "1 h");
        assert_eq!(span(9000.0), "2 h 30 min");
        // 13,725 s (the demo's crossing) in at most 5 marks: every hour.
        assert_eq!(mark_step(13725.0, 5), 3600.0);
        assert_eq!(mark_step(100.0, 4), 30.0);
    }
}
