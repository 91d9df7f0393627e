"""Writes crates/tidepath-io/data/salish_forecast.nc: a synthetic tidal current forecast over the
Strait of Juan de Fuca in the layout of a Copernicus Marine product (uo, vo as int16 with
scale_factor and _FillValue; dimensions time, depth, latitude, longitude; time in hours since
1950-01-01), so the built-in scenario `salish-forecast` exercises the current reader end to end.

The currents are made up, not a forecast: an M2 tide (period 12.42 h) flowing along the strait
(towards 100 degrees true on the flood), 1.2 m/s at the surface at its strongest, weaker with
depth, with a weak steady outflow of 0.1 m/s; land (elevation >= 0 in salish_topobathy.nc at the
node) is _FillValue, as in the real products.

With --update it writes crates/tidepath-io/data/salish_forecast_update.nc instead: the same
grid and layout, a "newer forecast" issued at 2025-11-12T03:00Z (hourly for 30 hours from
then) whose tide runs about 3 hours later and stronger (1.5 m/s at the surface), so that
routes planned on the first forecast change when it arrives (the built-in scenario
`forecast-update`). Without the option the original file is written, byte for byte as
committed (netCDF4 1.7, netCDF 4.10.1, HDF5 2.2.0).

    python3 -m venv /tmp/venv && /tmp/venv/bin/pip install netCDF4 numpy
    /tmp/venv/bin/python scripts/make_salish_forecast.py [--update]
"""
import math
import os
import sys

import numpy as np
from netCDF4 import Dataset

HERE = os.path.dirname(__file__)
DATA = os.path.join(HERE, "..", "crates", "tidepath-io", "data")


# The two forecasts: file name, title, first time (hours after 2025-11-12T00:00Z), number of
# hourly steps, M2 amplitude at the surface (m/s) and the tide's delay (hours).
ORIGINAL = ("salish_forecast.nc", "Synthetic M2 tidal currents, Strait of Juan de Fuca (tidepath test data, not a forecast)", 0, 49, 1.2, 0.0)
UPDATE = (
    "salish_forecast_update.nc",
    "Synthetic M2 tidal currents, Strait of Juan de Fuca, a later issue: tide 3 h later and stronger (tidepath test data, not a forecast)",
    3,
    31,
    1.5,
    3.0,
)


def main(update=False):
    name, title, first, steps, amplitude, delay = UPDATE if update else ORIGINAL
    with Dataset(os.path.join(DATA, "salish_topobathy.nc")) as topo:
        tlon, tlat, elev = topo["lon"][:], topo["lat"][:], topo["elevation"][:]
    lon = np.round(np.arange(-125.25, -122.6, 1.0 / 12.0), 6)
    lat = np.round(np.arange(48.0, 49.1, 1.0 / 12.0), 6)
    hours = np.arange(first, first + steps)  # hours after 2025-11-12T00:00Z, hourly
    t0 = 665016.0  # hours since 1950-01-01 of 2025-11-12T00:00Z
    depths = np.array([0.494, 10.0, 50.0], dtype="f4")

    def land(lo, la):
        j = int(np.argmin(abs(tlat - la)))
        i = int(np.argmin(abs(tlon - lo)))
        return elev[j, i] >= 0.0

    mask = np.array([[land(lo, la) for lo in lon] for la in lat])
    flood = math.radians(100.0)  # direction towards which the flood flows, from north
    omega = 2.0 * math.pi / 12.42
    out = os.path.join(DATA, name)
    with Dataset(out, "w", format="NETCDF4") as ds:
        ds.title = title
        ds.Conventions = "CF-1.8"
        ds.createDimension("time", len(hours))
        ds.createDimension("depth", len(depths))
        ds.createDimension("latitude", len(lat))
        ds.createDimension("longitude", len(lon))
        t = ds.createVariable("time", "f8", ("time",))
        t.units, t.calendar, t.standard_name, t.axis = "hours since 1950-01-01", "gregorian", "time", "T"
        t[:] = t0 + hours
        d = ds.createVariable("depth", "f4", ("depth",))
        d.units, d.positive, d.standard_name, d.axis = "m", "down", "depth", "Z"
        d[:] = depths
        y = ds.createVariable("latitude", "f4", ("latitude",))
        y.units, y.standard_name, y.axis = "degrees_north", "latitude", "Y"
        y[:] = lat
        x = ds.createVariable("longitude", "f4", ("longitude",))
        x.units, x.standard_name, x.axis = "degrees_east", "longitude", "X"
        x[:] = lon
        for name, std, comp in [("uo", "eastward_sea_water_velocity", math.sin), ("vo", "northward_sea_water_velocity", math.cos)]:
            var = ds.createVariable(
                name, "i2", ("time", "depth", "latitude", "longitude"), zlib=True, fill_value=np.int16(-32767), chunksizes=(1, 1, len(lat), len(lon))
            )
            var.scale_factor, var.add_offset, var.units, var.standard_name = 0.001, 0.0, "m s-1", std
            var.set_auto_maskandscale(True)
            data = np.ma.zeros((len(hours), len(depths), len(lat), len(lon)))
            for k, h in enumerate(hours):
                for l, z in enumerate(depths):
                    speed = amplitude * math.cos(omega * (h - delay)) * math.exp(-z / 60.0) - 0.1
                    data[k, l] = speed * comp(flood)
            data[:, :, mask] = np.ma.masked
            var[:] = data
    print(out, os.path.getsize(out), "bytes")


if __name__ == "__main__":
    main(update="--update" in sys.argv[1:])
