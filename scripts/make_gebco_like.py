#!/usr/bin/env python3
"""Writes a large synthetic bathymetry file with GEBCO 2024's NetCDF layout (not committed).

GEBCO_2024.nc holds `elevation` as int16 on a 15-arc-second grid: 43200 latitudes by 86400
longitudes, NetCDF-4, chunked and deflated, with `lat`/`lon` coordinate variables. This script
writes the same shapes, types and attributes with a smooth synthetic seabed (so it compresses
to a few hundred MB instead of 7.4 GB), to measure how fast tidepath reads a small box out of a
file of that size:

    python3 scripts/make_gebco_like.py /tmp/gebco_like.nc
    TIDEPATH_GEBCO_LIKE=/tmp/gebco_like.nc cargo test --release -p tidepath-io --test io \
        geodata::gebco_layout_subset -- --ignored --nocapture

Needs numpy and netCDF4 (pip install numpy netCDF4).
"""
import sys

import numpy as np
from netCDF4 import Dataset

N_LAT, N_LON = 43200, 86400
STEP = 1.0 / 240.0  # 15 arc seconds
CHUNK = (540, 540)  # rows x columns per chunk
BAND = 540  # rows written at a time (93 MB of int16)


def elevation(lat, lon):
    """A smooth synthetic seabed in metres, known in closed form so tests can check values."""
    la = np.radians(lat)[:, None]
    lo = np.radians(lon)[None, :]
    return np.round(-2500.0 + 2000.0 * np.sin(3.0 * lo) * np.cos(2.0 * la) + 500.0 * np.cos(40.0 * lo)).astype(np.int16)


def main(path):
    ds = Dataset(path, "w", format="NETCDF4")
    ds.Conventions = "CF-1.6"
    ds.title = "Synthetic seabed in GEBCO 2024's layout (tidepath benchmark, not real data)"
    ds.createDimension("lat", N_LAT)
    ds.createDimension("lon", N_LON)
    lat = ds.createVariable("lat", "f8", ("lat",))
    lat.standard_name = "latitude"
    lat.units = "degrees_north"
    lat.axis = "Y"
    lon = ds.createVariable("lon", "f8", ("lon",))
    lon.standard_name = "longitude"
    lon.units = "degrees_east"
    lon.axis = "X"
    lats = -90.0 + STEP / 2 + STEP * np.arange(N_LAT)
    lons = -180.0 + STEP / 2 + STEP * np.arange(N_LON)
    lat[:] = lats
    lon[:] = lons
    z = ds.createVariable("elevation", "i2", ("lat", "lon"), zlib=True, complevel=1, shuffle=True, chunksizes=CHUNK)
    z.standard_name = "height_above_mean_sea_level"
    z.units = "m"
    z.positive = "up"
    for r in range(0, N_LAT, BAND):
        z[r:r + BAND, :] = elevation(lats[r:r + BAND], lons)
        print(f"\r{r + BAND}/{N_LAT} rows", end="", file=sys.stderr, flush=True)
    print(file=sys.stderr)
    ds.close()


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else "gebco_like.nc")
