//! The page layout shared by the experiment figures: title, shared legend and note, and the
//! grid of panels.

use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

use super::super::style::{self, plot_err, LegendEntry};
use tidepath::error::Result;

const TITLE_H: u32 = 40;
const MARGIN: u32 = 12;
/// Left indent of the shared legend, matching the y label area so it lines up with the plots.
const LEGEND_INDENT: u32 = 64;
/// Size of the one panel of a single-problem figure, and of each panel of a grid.
const SINGLE_PANEL: (u32, u32) = (1000, 560);
const GRID_PANEL: (u32, u32) = (440, 330);

/// Columns and rows of the panel grid: as square as possible, at most four columns so that
/// panels keep readable tick labels. Twelve problems (six functions, small and wide) give 4 x 3,
/// which keeps each function's two variants side by side.
pub(super) fn grid_shape(n: usize) -> (usize, usize) {
    let cols = match n {
        0 | 1 => 1,
        2 | 4 => 2,
        3 | 5 | 6 | 9 => 3,
        _ => 4,
    };
    (cols, n.max(1).div_ceil(cols))
}

/// Figure size for `n` panels of `panel` pixels under a header `header_h` high.
pub(super) fn figure_size(n: usize, header_h: u32) -> (u32, u32, (u32, u32)) {
    let (cols, rows) = grid_shape(n);
    let panel = if n <= 1 { SINGLE_PANEL } else { GRID_PANEL };
    (cols as u32 * panel.0 + 2 * MARGIN, header_h + rows as u32 * panel.1 + MARGIN, panel)
}

const NOTE_LINE_H: u32 = 18;
const TITLE_LINE_H: u32 = 26;
/// Bold text runs wider than the regular-weight estimate of [`style::text_width`].
const BOLD_WIDTH: f64 = 1.12;

/// The title wrapped to the figure width: a long title (many problems joined) would otherwise
/// run off a one-panel figure.
fn title_lines(title: &str, width: u32) -> Vec<String> {
    wrap(title, width.saturating_sub(2 * MARGIN) as f64 / BOLD_WIDTH, style::TITLE_PX)
}

pub(crate) fn title_height(title: &str, width: u32) -> u32 {
    TITLE_H + title_lines(title, width).len().saturating_sub(1) as u32 * TITLE_LINE_H
}

pub(crate) fn draw_title<DB: DrawingBackend>(root: &DrawingArea<DB, Shift>, title: &str) -> Result<()> {
    let (w, _) = root.dim_in_pixel();
    let style = style::bold(style::TITLE_PX).pos(Pos::new(HPos::Center, VPos::Center));
    for (k, line) in title_lines(title, w).into_iter().enumerate() {
        let y = (TITLE_H / 2 + 2 + k as u32 * TITLE_LINE_H) as i32;
        root.draw(&Text::new(line, (w as i32 / 2, y), style.clone())).map_err(plot_err)?;
    }
    Ok(())
}

/// Height of the title, shared legend and explanatory note at figure width `width`.
pub(super) fn header_height(title: &str, legend: &[LegendEntry], note: &str, width: u32) -> u32 {
    let lines = wrap(note, legend_width(width) as f64, style::LEGEND_PX).len() as u32;
    title_height(title, width) + style::legend_height(legend, legend_width(width)) + lines * NOTE_LINE_H + 6
}

fn legend_width(width: u32) -> u32 {
    width.saturating_sub(2 * MARGIN + LEGEND_INDENT)
}

/// Splits `text` into lines no wider than `width` pixels at `px`, at spaces.
pub(crate) fn wrap(text: &str, width: f64, px: f64) -> Vec<String> {
    let mut lines: Vec<String> = Vec::new();
    for word in text.split_whitespace() {
        match lines.last_mut() {
            Some(line) if style::text_width(&format!("{line} {word}"), px) <= width => {
                line.push(' ');
                line.push_str(word);
            }
            _ => lines.push(word.to_string()),
        }
    }
    lines
}

pub(super) fn draw_header<DB: DrawingBackend>(
    root: &DrawingArea<DB, Shift>,
    title: &str,
    legend: &[LegendEntry],
    note: &str,
) -> Result<()> {
    let (w, _) = root.dim_in_pixel();
    draw_title(root, title)?;
    let top = title_height(title, w);
    let legend_h = style::legend_height(legend, legend_width(w));
    let x0 = (MARGIN + LEGEND_INDENT) as i32;
    let legend_area = root.clone().shrink((x0, top as i32), (legend_width(w), legend_h.max(1)));
    style::draw_legend(&legend_area, legend)?;
    let note_style = style::font(style::LEGEND_PX).color(&style::MUTED).pos(Pos::new(HPos::Left, VPos::Center));
    for (k, line) in wrap(note, legend_width(w) as f64, style::LEGEND_PX).into_iter().enumerate() {
        let y = (top + legend_h + k as u32 * NOTE_LINE_H + NOTE_LINE_H / 2) as i32;
        root.draw(&Text::new(line, (x0, y), note_style.clone())).map_err(plot_err)?;
    }
    Ok(())
}

/// The panel areas of the grid below the header, in reading order.
pub(super) fn panels<DB: DrawingBackend>(
    root: &DrawingArea<DB, Shift>,
    n: usize,
    header_h: u32,
    panel: (u32, u32),
) -> Vec<DrawingArea<DB, Shift>> {
    let (cols, _) = grid_shape(n);
    (0..n.max(1))
        .map(|k| {
            let (c, r) = ((k % cols) as u32, (k / cols) as u32);
            let x = MARGIN + c * panel.0;
            let y = header_h + r * panel.1;
            root.clone().shrink((x as i32, y as i32), panel).margin(4, 8, 4, 8)
        })
        .collect()
}

/// A muted message in an empty panel, so a missing result is visible rather than a blank.
pub(super) fn draw_message<DB: DrawingBackend>(area: &DrawingArea<DB, Shift>, msg: &str) -> Result<()> {
    let (w, h) = area.dim_in_pixel();
    let style = style::font(style::AXIS_DESC_PX).color(&style::MUTED).pos(Pos::new(HPos::Center, VPos::Center));
    area.draw(&Text::new(msg.to_string(), (w as i32 / 2, h as i32 / 3), style)).map_err(plot_err)?;
    Ok(())
}

pub(crate) fn render_svg(
    size: (u32, u32),
    draw: impl FnOnce(&DrawingArea<SVGBackend, Shift>) -> Result<()>,
) -> Result<String> {
    let mut svg = String::new();
    {
        let root = SVGBackend::with_string(&mut svg, size).into_drawing_area();
        root.fill(&WHITE).map_err(plot_err)?;
        draw(&root)?;
        root.present().map_err(plot_err)?;
    }
    Ok(svg)
}

/// Explains a zero line in the header, once, when any panel has one.
pub(super) const ZERO_NOTE: &str = " On log axes, runs that reached exactly 0 are drawn on the line labelled 0.";
/// Height of the strip above a plot for per-planner notes ("never feasible", "2 runs = ∞").
pub(super) const NOTE_H: u32 = 18;

/// A whole grid figure: title, legend and note on top, then one panel per problem drawn by
/// `draw_panel(area, index)`, or a "no runs" message when there are no problems. Both grid
/// figures (convergence and box plots) share this frame so their layouts always agree.
pub(super) fn render_panel_grid(
    title: &str,
    legend: &[LegendEntry],
    note: &str,
    n: usize,
    mut draw_panel: impl FnMut(&DrawingArea<SVGBackend, Shift>, usize) -> Result<()>,
) -> Result<String> {
    let (w, _, _) = figure_size(n, 0);
    let header_h = header_height(title, legend, note, w);
    let (w, h, panel) = figure_size(n, header_h);
    render_svg((w, h), |root| {
        draw_header(root, title, legend, note)?;
        let areas = panels(root, n, header_h, panel);
        if n == 0 {
            return draw_message(&areas[0], "no runs");
        }
        for (i, area) in areas.iter().enumerate().take(n) {
            draw_panel(area, i)?;
        }
        Ok(())
    })
}
