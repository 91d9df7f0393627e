//! The scenario file's `[world.waves]` section: the significant wave height a wave glider
//! (acopf2016) is driven by, given uniform, on a grid, cell by cell or read from a forecast
//! file. Absent: no waves (`Waves::None`), and no wave glider can be planned.

use serde::{Deserialize, Serialize};

use super::spec::P2;

#[derive(Clone, Debug, Serialize, Deserialize)]
#[serde(tag = "kind", rename_all = "kebab-case", deny_unknown_fields)]
pub enum WavesSpec {
    /// The same significant wave height (m) everywhere and always.
    Uniform { height: f64 },
    /// Heights (m) on a regular grid at several times; bilinear in space, linear in time, like
    /// `[world.current] kind = "grid"`.
    Grid {
        origin: P2,
        spacing: P2,
        shape: [usize; 2],
        times: Vec<f64>,
        /// One row-major layer of `shape[0] * shape[1]` heights per time.
        height: Vec<Vec<f64>>,
        /// Nodes (row-major indices) without data: a glider's motion through their cells is
        /// invalid.
        #[serde(default, skip_serializing_if = "Vec::is_empty")]
        no_data: Vec<usize>,
    },
    /// One height per cell of a grid given cell by cell (rows from north to south), nodes at
    /// the cells' centres, like `[world.current] kind = "cells"`.
    Cells {
        /// South-west corner of the grid (m).
        origin: P2,
        /// Side of a (square) cell (m).
        resolution: f64,
        heights: Vec<Vec<f64>>,
    },
    /// A wave forecast file (NetCDF: Copernicus Marine's `VHM0`, WAVEWATCH III's `hs`, any CF
    /// file with `sea_surface_wave_significant_height`), for geographic scenarios: read inside
    /// the box, resampled to metres, on the forecast's clock.
    File {
        /// Relative to the scenario file's folder.
        path: String,
        /// The height variable; found by standard name, then by name, if absent.
        #[serde(default, skip_serializing_if = "Option::is_none")]
        variable: Option<String>,
        /// Spacing (m) of the metric grid; defaults to the file's own.
        #[serde(default, skip_serializing_if = "Option::is_none")]
        resolution: Option<f64>,
    },
}

/// What drives the vehicle: thrusters (`auv`, the default) or the waves (`wave-glider`).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum VehicleKind {
    #[default]
    Auv,
    WaveGlider,
}

impl VehicleKind {
    pub fn is_auv(&self) -> bool {
        *self == VehicleKind::Auv
    }

    pub fn id(&self) -> &'static str {
        match self {
            VehicleKind::Auv => "auv",
            VehicleKind::WaveGlider => "wave-glider",
        }
    }
}
