//! paths.svg: the plan view and vertical profile of each planner's best path.

use super::super::{draw_plan_view, draw_profile, PlanFigure};
use super::layout::{draw_title, render_svg, title_height};
use tidepath::error::Result;

/// paths.svg: the plan view of `fig` (each planner's best path, and the reference path when
/// there is one) beside their vertical profile. Give each path a [`best_path_label`] so the
/// legend carries the cost.
///
/// [`best_path_label`]: super::best_path_label
pub fn render_paths_figure(fig: &PlanFigure) -> Result<String> {
    const SIZE: (u32, u32) = (1400, 760);
    render_svg(SIZE, |root| {
        let (w, h) = SIZE;
        draw_title(root, &fig.title)?;
        let title_h = title_height(&fig.title, w);
        let body = root.split_vertically(title_h).1.margin(0, 8, 8, 8);
        // A wide domain gets a wider plan view, as in the plan figure; the profile keeps
        // enough width to read the climbs.
        let b = fig.world.bounds;
        let aspect = ((b.max.x - b.min.x) / (b.max.y - b.min.y)).clamp(0.3, 3.0);
        let avail_h = h.saturating_sub(title_h) as f64 - 200.0;
        let left_w = (aspect * avail_h + 200.0).clamp(560.0, 880.0) as u32;
        let (left, right) = body.split_horizontally(left_w);
        draw_plan_view(&left, fig)?;
        draw_profile(&right.margin(0, 0, 16, 0), fig)
    })
}
