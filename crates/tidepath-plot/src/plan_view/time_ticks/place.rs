//! Drawing the ticks: a bar across the line, and a label beside it where it reads, keeping
//! clear of the other labels and of what the plan view draws over the ticks.

use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

use super::super::super::style::{self, plot_err};
use super::super::super::{failure, PlanFigure};
use super::super::overlays::{endpoint_box, LabelBox};
use tidepath::error::Result;
use tidepath::planner::Focus;

/// The labels' font size (px): smaller than the legend's, they are many.
const LABEL_PX: f64 = 10.0;
/// Half a tick bar's length (px).
const HALF_BAR: f64 = 6.0;

/// One tick to draw: its colour, pixel position, direction of travel there (pixels) and text.
pub(super) struct Mark {
    pub color: RGBColor,
    pub at: (f64, f64),
    pub dir: (f64, f64),
    pub text: String,
}

/// The unit direction (pixels) of segment `seg` of `line`, or of the nearest segment with a
/// length when it has none (a vehicle holding station); across the screen when none has.
pub(super) fn heading(line: &[(f64, f64)], seg: usize) -> (f64, f64) {
    let len = |k: usize| (line[k + 1].0 - line[k].0).hypot(line[k + 1].1 - line[k].1);
    let n = line.len().saturating_sub(1);
    match (0..n).filter(|&k| len(k) > 1e-6).min_by_key(|&k| k.abs_diff(seg)) {
        Some(k) => ((line[k + 1].0 - line[k].0) / len(k), (line[k + 1].1 - line[k].1) / len(k)),
        None => (1.0, 0.0),
    }
}

/// Bars across the lines at every mark, then their labels beside them, on the side where the
/// label crosses fewer lines and bars; a label that would overlap one drawn before it (an
/// earlier vehicle's at the same time) or a box of `keep_out` is left out.
pub(super) fn draw_marks<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    marks: &[Mark],
    lines: &[Vec<(f64, f64)>],
    mut keep_out: Vec<LabelBox>,
) -> Result<()> {
    let ri = |(x, y): (f64, f64)| (x.round() as i32, y.round() as i32);
    let bar =
        |m: &Mark, h: f64| [(m.at.0 + h * m.dir.1, m.at.1 - h * m.dir.0), (m.at.0 - h * m.dir.1, m.at.1 + h * m.dir.0)];
    for m in marks {
        let [a, b] = bar(m, HALF_BAR + 1.5);
        area.draw(&PathElement::new(vec![ri(a), ri(b)], style::line(WHITE.mix(0.85), 5))).map_err(plot_err)?;
        let [a, b] = bar(m, HALF_BAR);
        area.draw(&PathElement::new(vec![ri(a), ri(b)], style::line(m.color, 2))).map_err(plot_err)?;
    }
    let segments: Vec<[(f64, f64); 2]> = lines
        .iter()
        .flat_map(|l| l.windows(2).map(|s| [s[0], s[1]]))
        .chain(marks.iter().map(|m| bar(m, HALF_BAR)))
        .collect();
    let (w, h) = area.dim_in_pixel();
    for m in marks {
        let (tw, th) = (style::text_width(&m.text, LABEL_PX).round() + 6.0, 13.0);
        let (nx, ny) = (-m.dir.1, m.dir.0);
        // Beyond the bar's end, as far again as the box's half extent along the normal.
        let reach = HALF_BAR + 4.0 + 0.5 * (nx.abs() * tw + ny.abs() * th);
        let boxes = [1.0, -1.0].map(|side| {
            let (cx, cy) = (m.at.0 + side * reach * nx, m.at.1 + side * reach * ny);
            [ri((cx - tw / 2.0, cy - th / 2.0)), ri((cx + tw / 2.0, cy + th / 2.0))]
        });
        let inside = |b: &LabelBox| b[0].0 >= 1 && b[0].1 >= 1 && b[1].0 < w as i32 && b[1].1 < h as i32;
        // A gap between labels, so neighbours read as two.
        let pad = |b: &LabelBox| [(b[0].0 - 3, b[0].1 - 1), (b[1].0 + 3, b[1].1 + 1)];
        let fits = |b: &&LabelBox| inside(b) && !keep_out.iter().any(|k| overlap(&pad(b), k));
        let crossings = |b: &&LabelBox| segments.iter().filter(|s| crosses(b, s[0], s[1])).count();
        let Some(&b) = boxes.iter().filter(fits).min_by_key(crossings) else { continue };
        area.draw(&Rectangle::new(b, style::fill(WHITE.mix(0.85)))).map_err(plot_err)?;
        area.draw(&Rectangle::new(b, style::line(m.color, 1))).map_err(plot_err)?;
        let centre = ((b[0].0 + b[1].0) / 2, (b[0].1 + b[1].1) / 2);
        let font = style::font(LABEL_PX).pos(Pos::new(HPos::Center, VPos::Center));
        area.draw(&Text::new(m.text.clone(), centre, font)).map_err(plot_err)?;
        keep_out.push(b);
    }
    Ok(())
}

/// What the plan view draws over the ticks' labels, in pixels of its plotting area `(pw, ph)`
/// given where the start, goal and focuses are (`px`): the start and goal markers with their
/// labels, and the focuses' rings with their labels, placed as `draw_endpoints` and
/// `draw_focus` place them.
pub(super) fn plan_keep_out(
    fig: &PlanFigure,
    px: impl Fn(tidepath::geom::Vec3) -> (i32, i32),
    (pw, ph): (i32, i32),
) -> Vec<LabelBox> {
    let mut out = Vec::new();
    let ring = |c: (i32, i32), r: i32| [(c.0 - r, c.1 - r), (c.0 + r, c.1 + r)];
    let first = fig.paths.iter().find(|p| p.points.len() >= 2).map(|p| p.points);
    let n = first.map_or(0, |p| p.len());
    let away_start = first.map(|p| p[0].truncate() - p[1].truncate());
    let away_goal = first.map(|p| p[n - 1].truncate() - p[n - 2].truncate());
    for (q, away, label) in [(fig.start, away_start, "start"), (fig.goal, away_goal, "goal")] {
        if q.x.is_finite() && q.y.is_finite() {
            out.push(ring(px(q), 12));
            out.push(endpoint_box(px(q), away, label, (pw, ph)));
        }
    }
    for f in fig.focus.iter().filter(|f| f.at.x.is_finite() && f.at.y.is_finite()) {
        out.push(ring(px(f.at), 24));
        out.push(focus_box(fig, f, px(f.at), (pw, ph)));
    }
    out
}

/// Where `draw_focus` puts the label of focus `f`, its ring at `c`.
fn focus_box(fig: &PlanFigure, f: &Focus, c: (i32, i32), (pw, ph): (i32, i32)) -> LabelBox {
    let lines: Vec<String> = std::iter::once(f.label.clone()).chain(failure::what_is_there(fig, f)).collect();
    let tw = lines.iter().map(|l| style::text_width(l, style::LEGEND_PX)).fold(0.0, f64::max).round() as i32 + 12;
    let th = 18 * lines.len() as i32 + 4;
    let bx = if c.0 + 26 + tw <= pw - 2 { c.0 + 26 } else { (c.0 - 26 - tw).max(2) };
    let by = (c.1 - 26 - th).clamp(2, (ph - th - 2).max(2));
    [(bx, by), (bx + tw, by + th)]
}

fn overlap(a: &LabelBox, b: &LabelBox) -> bool {
    a[0].0 < b[1].0 && b[0].0 < a[1].0 && a[0].1 < b[1].1 && b[0].1 < a[1].1
}

/// Whether the segment `p`-`q` passes through the box (Liang-Barsky clipping).
fn crosses(b: &LabelBox, p: (f64, f64), q: (f64, f64)) -> bool {
    let (dx, dy) = (q.0 - p.0, q.1 - p.1);
    let (mut t0, mut t1) = (0.0_f64, 1.0_f64);
    let (x0, y0, x1, y1) = (f64::from(b[0].0), f64::from(b[0].1), f64::from(b[1].0), f64::from(b[1].1));
    for (pk, qk) in [(-dx, p.0 - x0), (dx, x1 - p.0), (-dy, p.1 - y0), (dy, y1 - p.1)] {
        if pk == 0.0 {
            if qk < 0.0 {
                return false;
            }
        } else if pk < 0.0 {
            t0 = t0.max(qk / pk);
        } else {
            t1 = t1.min(qk / pk);
        }
    }
    t0 <= t1
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_label_box_knows_the_lines_through_it() {
        let b: LabelBox = [(10, 10), (20, 20)];
        assert!(crosses(&b, (0.0, 15.0), (30.0, 15.0)));
        assert!(crosses(&b, (12.0, 12.0), (13.0, 13.0)));
        assert!(!crosses(&b, (0.0, 0.0), (30.0, 5.0)));
        assert!(!crosses(&b, (0.0, 25.0), (25.0, 40.0)));
        assert!(overlap(&b, &[(19, 19), (30, 30)]) && !overlap(&b, &[(20, 10), (30, 20)]));
    }

    #[test]
    fn a_heading_skips_segments_without_length() {
        let line = [(0.0, 0.0), (3.0, 4.0), (3.0, 4.0)];
        assert_eq!(heading(&line, 1), (0.6, 0.8));
        assert_eq!(heading(&line[1..], 0), (1.0, 0.0));
    }
}
