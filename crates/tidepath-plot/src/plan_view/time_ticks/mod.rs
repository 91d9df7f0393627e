//! Time ticks on a fleet's paths: a short bar across each vehicle's path at every multiple of
//! one round step of the scenario clock, labelled with the time, so a reader sees where every
//! vehicle is at the same moment (what the separation and arrival rules are about).
//!
//! Only a fleet gets them: two or more timed paths that are not one mission's (they differ in
//! start, goal or departure). One vehicle's plan, or several planners' paths of one mission
//! (a comparison), stay as they were: there the timing is the cost's business.

mod place;

use chrono::{DateTime, Duration, Utc};
use plotters::prelude::*;

use super::super::flown::Drawn;
use super::super::style::{self, LegendEntry, Swatch};
use super::super::{time_label, PlanFigure, PlotPath};
use super::overlays::to_px;
use super::Chart;
use place::{draw_marks, heading, plan_keep_out, Mark};
use tidepath::error::Result;
use tidepath::world::Dims;

/// Most ticks along the longest mission: the step is the shortest round step (1, 2, 5, 10,
/// 15, 30 min, 1, 2, 3, 6, 12 h ...) giving at most this many, so, the round steps being at
/// most 2.5 times apart from a minute on, the longest mission gets roughly 4 to 10.
const MOST_TICKS: usize = 10;

/// A tick: its time and where the vehicle is then, as segment `seg` of the drawn line and the
/// fraction `f` along it (positions are linear in time along each segment).
#[derive(Clone, Copy, Debug, PartialEq)]
struct Tick {
    t: f64,
    seg: usize,
    f: f64,
}

/// The step (s) shared by all vehicles and, per path index (its colour), its ticks.
#[derive(Debug)]
struct FleetTicks {
    step: f64,
    paths: Vec<(usize, Vec<Tick>)>,
}

/// The line drawn for `p` (its flown curve when it has one) when every point of it is timed.
fn timed<'a>(p: &PlotPath<'a>) -> Option<Drawn<'a>> {
    let d = Drawn::of(p);
    let (t0, t1) = (*d.times.first()?, *d.times.last()?);
    (d.line.len() >= 2 && d.times.len() == d.line.len() && t0.is_finite() && t1.is_finite() && t1 > t0).then_some(d)
}

impl FleetTicks {
    /// The ticks of `paths` when they are a fleet's, else `None`.
    fn of(paths: &[PlotPath]) -> Option<Self> {
        let lines: Vec<(usize, Drawn)> = paths.iter().enumerate().filter_map(|(i, p)| Some((i, timed(p)?))).collect();
        let key = |d: &Drawn| (d.line[0].truncate(), d.line[d.line.len() - 1].truncate(), d.times[0]);
        let (s0, g0, t0) = key(&lines.first()?.1);
        let apart = |(s, g, t): (tidepath::geom::Vec2, tidepath::geom::Vec2, f64)| {
            s.distance(s0) > 1e-3 || g.distance(g0) > 1e-3 || (t - t0).abs() > 1e-3
        };
        if lines.len() < 2 || !lines.iter().any(|(_, d)| apart(key(d))) {
            return None;
        }
        let span = |d: &Drawn| d.times[d.times.len() - 1] - d.times[0];
        let longest = lines.iter().map(|(_, d)| span(d)).fold(0.0, f64::max);
        let step = time_label::mark_step(longest, MOST_TICKS);
        let paths = lines.iter().map(|(i, d)| (*i, ticks_along(d.times, step))).collect();
        Some(Self { step, paths })
    }
}

/// Ticks at the multiples of `step` strictly between the first and the last of `times`.
fn ticks_along(times: &[f64], step: f64) -> Vec<Tick> {
    let (t0, t1) = (times[0], times[times.len() - 1]);
    let mut out = Vec::new();
    let mut k = (t0 / step).floor() + 1.0;
    while k * step < t1 {
        let t = k * step;
        if let Some(seg) = times.windows(2).position(|w| w[0] <= t && t <= w[1] && w[1] > w[0]) {
            out.push(Tick { t, seg, f: (t - times[seg]) / (times[seg + 1] - times[seg]) });
        }
        k += 1.0;
    }
    out
}

/// A tick's label: the UTC time with an epoch ("13:30"), else the scenario clock in short
/// form ("45m", "1h", "1h30", "90s").
fn tick_text(t: f64, step: f64, epoch: Option<DateTime<Utc>>) -> String {
    if let Some(e) = epoch {
        let at = e + Duration::milliseconds((t * 1000.0).round() as i64);
        return at.format(if step < 60.0 { "%H:%M:%S" } else { "%H:%M" }).to_string();
    }
    let r = t.round() as i64;
    let sign = if r < 0 { "-" } else { "" };
    let (h, m, s) = (r.abs() / 3600, r.abs() % 3600 / 60, r.abs() % 60);
    let text = match (h, m, s) {
        (0, 0, s) => format!("{s}s"),
        (0, m, 0) => format!("{m}m"),
        (0, m, s) => format!("{m}m{s:02}s"),
        (h, 0, 0) => format!("{h}h"),
        (h, m, 0) => format!("{h}h{m:02}"),
        (h, m, s) => format!("{h}h{m:02}m{s:02}s"),
    };
    format!("{sign}{text}")
}

/// The legend's note on the ticks, when `fig` has them.
pub(crate) fn legend(fig: &PlanFigure) -> Option<LegendEntry> {
    let ticks = FleetTicks::of(&fig.paths)?;
    let how = if fig.epoch.is_some() { "labelled in UTC" } else { "labelled with t (scenario clock)" };
    let text = format!("time ticks every {}, {how}", time_label::span(ticks.step));
    Some(LegendEntry::new(text, Swatch::Tick(style::MUTED)))
}

/// The ticks of a fleet on the plan view, over the paths, under the start, goal and focus
/// marks (their labels keep clear of those).
pub(crate) fn draw_on_plan<DB: DrawingBackend>(chart: &Chart<DB>, fig: &PlanFigure, u: f64) -> Result<()> {
    let Some(ticks) = FleetTicks::of(&fig.paths) else { return Ok(()) };
    let px = |q: tidepath::geom::Vec3| to_px(chart, q.x / u, q.y / u);
    let lines: Vec<Vec<(f64, f64)>> = fig
        .paths
        .iter()
        .map(|p| Drawn::of(p).line.iter().map(|&q| px(q)).map(|(x, y)| (f64::from(x), f64::from(y))).collect())
        .collect();
    let (pw, ph) = chart.plotting_area().dim_in_pixel();
    let keep_out = plan_keep_out(fig, px, (pw as i32, ph as i32));
    draw_marks(&chart.plotting_area().strip_coord_spec(), &ticks.marks(&lines, fig.epoch), &lines, keep_out)
}

/// The ticks on the profile (distance along each path against z), of a 3-D fleet only: in
/// 2-D every path is at one depth and the ticks would pile onto one line. `tracks` are the
/// distances along each path's drawn line.
pub(crate) fn draw_on_profile<DB: DrawingBackend>(
    chart: &Chart<DB>,
    fig: &PlanFigure,
    paths: &[PlotPath],
    tracks: &[Vec<f64>],
    u: f64,
    (lo, hi): (f64, f64),
) -> Result<()> {
    let Some(ticks) = FleetTicks::of(paths).filter(|_| fig.world.dims == Dims::Three) else { return Ok(()) };
    let lines: Vec<Vec<(f64, f64)>> = paths
        .iter()
        .zip(tracks)
        .map(|(p, track)| {
            let on = |(q, s): (&tidepath::geom::Vec3, &f64)| to_px(chart, s / u, q.z.clamp(lo, hi));
            Drawn::of(p).line.iter().zip(track).map(on).map(|(x, y)| (f64::from(x), f64::from(y))).collect()
        })
        .collect();
    draw_marks(&chart.plotting_area().strip_coord_spec(), &ticks.marks(&lines, fig.epoch), &lines, Vec::new())
}

impl FleetTicks {
    /// The marks to draw on `lines`, each path's drawn line in pixels.
    fn marks(&self, lines: &[Vec<(f64, f64)>], epoch: Option<DateTime<Utc>>) -> Vec<Mark> {
        let mut out = Vec::new();
        for (i, list) in &self.paths {
            let line = &lines[*i];
            for tk in list.iter().filter(|tk| tk.seg + 1 < line.len()) {
                let (a, b) = (line[tk.seg], line[tk.seg + 1]);
                out.push(Mark {
                    color: style::path_color(*i),
                    at: (a.0 + tk.f * (b.0 - a.0), a.1 + tk.f * (b.1 - a.1)),
                    dir: heading(line, tk.seg),
                    text: tick_text(tk.t, self.step, epoch),
                });
            }
        }
        out
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use tidepath::geom::Vec3;

    #[test]
    fn a_fleet_gets_ticks_on_one_step_and_one_mission_none() {
        let a = [Vec3::new(0.0, 0.0, 0.0), Vec3::new(1000.0, 0.0, 0.0), Vec3::new(1000.0, 1000.0, 0.0)];
        let b = [Vec3::new(0.0, 500.0, 0.0), Vec3::new(600.0, 500.0, 0.0)];
        let (ta, tb) = ([0.0, 1000.0, 3000.0], [0.0, 600.0]);
        let fleet = [PlotPath::new("a", &a).with_times(&ta), PlotPath::new("b", &b).with_times(&tb)];
        let ticks = FleetTicks::of(&fleet).expect("a fleet");
        // 3000 s in at most 10 ticks: every 5 min; a at 300 .. 2700 s, b at 300 s.
        assert_eq!(ticks.step, 300.0);
        let (ia, ka) = &ticks.paths[0];
        assert_eq!((*ia, ka.len(), ticks.paths[1].1.len()), (0, 9, 1));
        assert_eq!(ka[2], Tick { t: 900.0, seg: 0, f: 0.9 });
        assert_eq!(ka[3], Tick { t: 1200.0, seg: 1, f: 0.1 });
        assert_eq!(ticks.paths[1].1[0], Tick { t: 300.0, seg: 0, f: 0.5 });
        // One path, or two planners' paths of one mission: no ticks.
        assert!(FleetTicks::of(&fleet[..1]).is_none());
        assert!(FleetTicks::of(&[fleet[0].clone(), PlotPath::new("a2", &a).with_times(&ta)]).is_none());
        // An untimed path is not counted.
        assert!(FleetTicks::of(&[fleet[0].clone(), PlotPath::new("b", &b)]).is_none());
    }

    #[test]
    fn labels_are_short() {
        let texts: Vec<String> = [30.0, 2700.0, 3600.0, 5400.0, 90.0, 93600.0].map(|t| tick_text(t, 60.0, None)).into();
        assert_eq!(texts, ["30s", "45m", "1h", "1h30", "1m30s", "26h"]);
        let e = DateTime::parse_from_rfc3339("2024-05-01T12:00:00Z").unwrap().with_timezone(&Utc);
        assert_eq!(tick_text(5400.0, 1800.0, Some(e)), "13:30");
    }
}
