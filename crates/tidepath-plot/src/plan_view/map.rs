//! The map under every plan view: the layout that keeps the domain's aspect ratio, the axes
//! (metres or, for a geographic world, degrees with the graticule), the seabed's shading and
//! contours (in a world with waves, the significant wave height's shading in their place),
//! the currents, the frame, the colour bar and the legend. What goes on the map (the plan
//! figure's paths and obstacles, a simulation's track and routes) is drawn by the caller
//! between the currents and the frame.

use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::text_anchor;

use super::super::style::{self, plot_err, LegendEntry, LengthUnit, Swatch};
use super::colorbar::{self, ColourBar};
use super::graticule::Graticule;
use super::overlays::{draw_quiver, quiver_px_per_speed, scale_speed, Quiver, ARROW_CELLS};
use super::seabed::{draw_seabed, Seabed};
use super::waves::{draw_waves, WaveMap};
use super::{Chart, MAX_SCALE_ARROW_PX};
use tidepath::error::Result;
use tidepath::world::World;

const Y_LABEL_W: u32 = 74;
const X_LABEL_H: u32 = 46;
const TOP_PAD: u32 = 8;
const RIGHT_PAD: u32 = 16;
const COLORBAR_W: u32 = 104;
const COLORBAR_H: u32 = 48;
/// Pixels between colour bars stacked beside the map.
const COLORBAR_GAP: u32 = 28;

/// Where the colour bar goes: beside suits tall maps, below suits wide ones.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum BarPlace {
    Beside,
    Below,
}

/// What the map shows and what goes around it.
pub(crate) struct MapSpec<'a> {
    pub(super) world: &'a World,
    /// The region shown (metres): x0, y0, x1, y1.
    pub(super) view: (f64, f64, f64, f64),
    pub(super) seabed: Option<Seabed>,
    /// The significant wave height, shown in place of the seabed in a world with waves.
    pub(super) waves: Option<WaveMap>,
    pub(super) quiver: Option<Quiver>,
    /// The caption above the map; `None` leaves no room for one.
    pub(crate) caption: Option<String>,
    /// Entries of the legend under the map; a current's scale arrow gets its length here.
    pub(crate) legend: Vec<LegendEntry>,
    /// Whether the colour bars are drawn (a grid of small maps leaves them to one map).
    pub(crate) colorbar: bool,
    /// A second colour bar after the seabed's or the waves' (a path coloured by its speed over
    /// ground).
    pub(crate) extra_bar: Option<ColourBar>,
}

impl<'a> MapSpec<'a> {
    /// The map of `world` over `view`, its currents drawn at `time` and depth `current_z`.
    pub(crate) fn new(world: &'a World, view: (f64, f64, f64, f64), time: f64, current_z: f64) -> Self {
        Self::with_arrows(world, view, time, current_z, ARROW_CELLS)
    }

    /// [`MapSpec::new`] with `cells` current arrows each way (a small map wants fewer).
    pub(crate) fn with_arrows(
        world: &'a World,
        view: (f64, f64, f64, f64),
        time: f64,
        current_z: f64,
        cells: usize,
    ) -> Self {
        let (x0, y0, x1, y1) = view;
        let waves = WaveMap::sample(world, view, time);
        Self {
            world,
            view,
            seabed: if waves.is_some() { None } else { Seabed::sample(&world.terrain, x0, y0, x1, y1) },
            waves,
            quiver: Quiver::sample(world, time, current_z, view, cells),
            caption: None,
            legend: Vec::new(),
            colorbar: true,
            extra_bar: None,
        }
    }

    /// The map's length unit (metres or kilometres, by the view's extent).
    pub(crate) fn unit(&self) -> LengthUnit {
        let (x0, y0, x1, y1) = self.view;
        LengthUnit::for_extent((x1 - x0).max(y1 - y0))
    }

    /// The colour bars to draw: the seabed's or the waves', then the extra one (taken).
    fn take_bars(&mut self) -> Vec<ColourBar> {
        if !self.colorbar {
            return Vec::new();
        }
        let background =
            self.seabed.as_ref().map(Seabed::colour_bar).or_else(|| self.waves.as_ref().map(WaveMap::colour_bar));
        background.into_iter().chain(self.extra_bar.take()).collect()
    }

    fn bar_count(&self) -> u32 {
        if self.colorbar {
            u32::from(self.seabed.is_some() || self.waves.is_some()) + u32::from(self.extra_bar.is_some())
        } else {
            0
        }
    }
}

/// The pixels a map of `spec` in an area `w` wide takes beside and above/below the plot
/// itself (axis labels, caption, colour bar, legend), for callers sizing the area: a plot
/// `pw` x `ph` needs an area of at least `pw + extra_w` x `ph + extra_h`.
pub(crate) fn map_frame(spec: &MapSpec, w: u32) -> (u32, u32) {
    let legend_h = style::legend_height(&spec.legend, w.saturating_sub(20).max(100));
    let caption_h = if spec.caption.is_some() { style::CAPTION_H } else { 0 };
    let bar_h = COLORBAR_H * spec.bar_count();
    (Y_LABEL_W + RIGHT_PAD + 4, caption_h + TOP_PAD + X_LABEL_H + 8 + legend_h + bar_h)
}

/// Lays out and draws the map of `spec` in `area`, calling `overlay` with the chart and the
/// length unit (metres per axis unit) to draw what goes on it, above the currents and under
/// the frame.
pub(crate) fn draw_map<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    mut spec: MapSpec,
    overlay: impl FnOnce(&Chart<DB>, f64) -> Result<()>,
) -> Result<()> {
    let world = spec.world;
    let view = spec.view;
    let (x0, y0, x1, y1) = view;
    let unit = spec.unit();

    let (w, h) = area.dim_in_pixel();
    let legend_w = w.saturating_sub(20).max(100);
    let legend_h = style::legend_height(&spec.legend, legend_w);

    // Largest plot that keeps the aspect ratio and leaves room for labels and legend, with the
    // colour bar beside the map or under it, whichever leaves the bigger map.
    let (lx, ly) = ((x1 - x0) / unit.metres, (y1 - y0) / unit.metres);
    let caption_h = if spec.caption.is_some() { style::CAPTION_H } else { 0 };
    let base_w = w.saturating_sub(Y_LABEL_W + RIGHT_PAD + 4);
    let base_h = h.saturating_sub(caption_h + TOP_PAD + X_LABEL_H + 8 + legend_h);
    let fit = |aw: u32, ah: u32| (aw.max(40) as f64 / lx).min(ah.max(40) as f64 / ly);
    let n_bars = spec.bar_count();
    let (bar, scale) = match n_bars {
        0 => (None, fit(base_w, base_h)),
        _ => {
            let beside = fit(base_w.saturating_sub(COLORBAR_W), base_h);
            let below = fit(base_w, base_h.saturating_sub(COLORBAR_H * n_bars));
            if beside >= below {
                (Some(BarPlace::Beside), beside)
            } else {
                (Some(BarPlace::Below), below)
            }
        }
    };
    let (plot_w, plot_h) = ((lx * scale).floor() as u32, (ly * scale).floor() as u32);
    let chart_w = Y_LABEL_W + plot_w + RIGHT_PAD;
    let chart_h = TOP_PAD + plot_h + X_LABEL_H;
    let block_w = chart_w + if bar == Some(BarPlace::Beside) { COLORBAR_W } else { 0 };
    let left = (w.saturating_sub(block_w) / 2) as i32;
    let legend_top = chart_h + 6 + if bar == Some(BarPlace::Below) { COLORBAR_H * n_bars } else { 0 };

    let body = match &spec.caption {
        Some(c) => style::caption(area, c)?,
        None => area.clone(),
    };
    let chart_area = body.clone().shrink((left, 0), (chart_w, chart_h));
    let (nx_labels, ny_labels) = ((plot_w / 70).clamp(2, 10) as usize, (plot_h / 45).clamp(2, 10) as usize);
    let u = unit.metres;
    let (rx, ry) = (x0 / u..x1 / u, y0 / u..y1 / u);
    // Geographic worlds: ticks where meridians and parallels meet the edges, in degrees.
    let graticule = world.frame.as_ref().map(|f| Graticule::new(f, view, nx_labels.min(7), ny_labels.min(6)));
    let mut chart = ChartBuilder::on(&chart_area)
        .margin_top(TOP_PAD)
        .margin_right(RIGHT_PAD)
        .x_label_area_size(X_LABEL_H)
        .y_label_area_size(Y_LABEL_W)
        .build_cartesian_2d(rx.clone(), ry.clone())
        .map_err(plot_err)?;
    let ticks_x = style::tick_formatter(rx, nx_labels);
    let ticks_y = style::tick_formatter(ry, ny_labels);
    // Geographic worlds label their own ticks (where meridians and parallels meet the edges).
    let geographic = graticule.is_some();
    chart
        .configure_mesh()
        .disable_mesh()
        .x_labels(if geographic { 0 } else { nx_labels })
        .y_labels(if geographic { 0 } else { ny_labels })
        .x_desc(if geographic { "longitude".to_string() } else { format!("x east ({})", unit.name) })
        .y_desc(if geographic { "latitude".to_string() } else { format!("y north ({})", unit.name) })
        .x_label_formatter(&ticks_x)
        .y_label_formatter(&ticks_y)
        .label_style(style::font(style::TICK_PX))
        .axis_desc_style(style::font(style::AXIS_DESC_PX))
        .draw()
        .map_err(plot_err)?;
    if let Some(g) = &graticule {
        draw_degree_ticks(&chart_area, &chart, g, view, u)?;
    }

    match (&spec.seabed, &spec.waves) {
        (Some(s), _) => draw_seabed(&chart, s, u)?,
        (None, Some(m)) => draw_waves(&chart, m, u)?,
        (None, None) => {
            chart
                .draw_series(std::iter::once(Rectangle::new(
                    [(x0 / u, y0 / u), (x1 / u, y1 / u)],
                    style::fill(style::NO_TERRAIN_BG),
                )))
                .map_err(plot_err)?;
        }
    }
    if let Some(g) = &graticule {
        for line in &g.lines {
            chart
                .draw_series(std::iter::once(PathElement::new(
                    line.iter().map(|&(x, y)| (x / u, y / u)).collect::<Vec<_>>(),
                    style::line(style::MUTED.mix(0.45), 1),
                )))
                .map_err(plot_err)?;
        }
    }
    if let Some(q) = &spec.quiver {
        // Over the wave colours, whose dark end would swallow a dark arrow, each gets a halo.
        draw_quiver(&chart, q, u, spec.waves.is_some())?;
        let len_px = (scale_speed(q.max_speed) * quiver_px_per_speed(&chart, q, u)).round() as i32;
        for e in spec.legend.iter_mut() {
            if let Swatch::ScaledArrow { len_px: l, .. } = &mut e.swatch {
                *l = len_px.clamp(4, MAX_SCALE_ARROW_PX);
            }
        }
    }
    overlay(&chart, u)?;
    // Frame on top of the shading, which otherwise covers the axis line's inner half.
    chart
        .draw_series(std::iter::once(Rectangle::new([(x0 / u, y0 / u), (x1 / u, y1 / u)], style::line(BLACK, 1))))
        .map_err(plot_err)?;

    // Beside the map the bars share its height; below it, each takes a row.
    let bars = spec.take_bars();
    let n = bars.len() as u32;
    for (k, b) in (0u32..).zip(&bars) {
        match bar {
            Some(BarPlace::Beside) => {
                let bar_h = plot_h.saturating_sub(COLORBAR_GAP * (n - 1)) / n;
                let top = TOP_PAD + k * (bar_h + COLORBAR_GAP);
                let area = body.clone().shrink((left + chart_w as i32 + 6, top as i32), (COLORBAR_W - 6, bar_h));
                colorbar::draw_vertical(&area, b)?;
            }
            Some(BarPlace::Below) => {
                let bar_w = plot_w.saturating_sub(190).clamp(120, 480);
                let top = chart_h + k * COLORBAR_H;
                let area = body.clone().shrink((left + Y_LABEL_W as i32, top as i32), (bar_w + 200, COLORBAR_H));
                colorbar::draw_horizontal(&area, b, bar_w)?;
            }
            None => {}
        }
    }
    let legend_area = body.shrink((10, legend_top as i32), (legend_w, legend_h.max(1)));
    style::draw_legend(&legend_area, &spec.legend)
}

/// Tick marks and degree labels on the bottom and left edges, in pixels of `area`.
fn draw_degree_ticks<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    chart: &Chart<DB>,
    g: &Graticule,
    (x0, y0, _, _): (f64, f64, f64, f64),
    u: f64,
) -> Result<()> {
    let base = area.get_base_pixel();
    let font = style::font(style::TICK_PX);
    for (x, label) in &g.x_ticks {
        let (px, py) = chart.backend_coord(&(x / u, y0 / u));
        let (px, py) = (px - base.0, py - base.1);
        area.draw(&PathElement::new(vec![(px, py), (px, py + 5)], style::line(BLACK, 1))).map_err(plot_err)?;
        let t = font.clone().pos(text_anchor::Pos::new(text_anchor::HPos::Center, text_anchor::VPos::Top));
        area.draw(&Text::new(label.clone(), (px, py + 8), t)).map_err(plot_err)?;
    }
    for (y, label) in &g.y_ticks {
        let (px, py) = chart.backend_coord(&(x0 / u, y / u));
        let (px, py) = (px - base.0, py - base.1);
        area.draw(&PathElement::new(vec![(px - 5, py), (px, py)], style::line(BLACK, 1))).map_err(plot_err)?;
        let t = font.clone().pos(text_anchor::Pos::new(text_anchor::HPos::Right, text_anchor::VPos::Center));
        area.draw(&Text::new(label.clone(), (px - 8, py), t)).map_err(plot_err)?;
    }
    Ok(())
}
