"""Writes the small geographic data fixtures of tidepath's tests with the reference libraries
(netCDF4-python on the NetCDF C library, rasterio on GDAL), so the Rust readers are tested on
files the tools users have would write. Run once; the outputs are committed (a few KB each).

    python3 -m venv /tmp/venv && /tmp/venv/bin/pip install netCDF4 numpy rasterio
    /tmp/venv/bin/python scripts/make_geo_fixtures.py

Every bathymetry fixture holds the same plane, so tests check values against a formula:
    elevation(lon, lat) = -200 + 100 (lon + 125) + 50 (lat - 48)   [m, up positive]
(bilinear interpolation reproduces a plane exactly; packed files are exact to half a step).
"""
import os

import numpy as np
from netCDF4 import Dataset

OUT = os.path.join(os.path.dirname(__file__), "..", "crates", "tidepath-io", "tests", "data", "geo")


def plane(lon, lat):
    return -200.0 + 100.0 * (lon + 125.0) + 50.0 * (lat - 48.0)


LON = np.round(np.arange(-125.0, -123.75, 0.1), 6)  # 13 columns
LAT = np.round(np.arange(48.0, 49.05, 0.1), 6)  # 11 rows


def coords(ds, lon, lat, lon_name="lon", lat_name="lat", units=True, axis=False):
    ds.createDimension(lat_name, len(lat))
    ds.createDimension(lon_name, len(lon))
    y = ds.createVariable(lat_name, "f8", (lat_name,))
    x = ds.createVariable(lon_name, "f8", (lon_name,))
    if units:
        y.units, x.units = "degrees_north", "degrees_east"
    if axis:
        y.axis, x.axis = "Y", "X"
    y[:], x[:] = lat, lon


def classic():
    """CDF-1, float elevation, one _FillValue cell at the south-west corner."""
    with Dataset(os.path.join(OUT, "bathy_classic.nc"), "w", format="NETCDF3_CLASSIC") as ds:
        coords(ds, LON, LAT)
        z = ds.createVariable("elevation", "f4", ("lat", "lon"), fill_value=np.float32(-9999.0))
        z.units, z.standard_name = "m", "height_above_mean_sea_level"
        data = plane(LON[None, :], LAT[:, None]).astype("f4")
        data[0, 0] = -9999.0
        z[:] = data


def offset64():
    """CDF-2 (64-bit offset), latitude descending, depth positive down, named `depth`."""
    with Dataset(os.path.join(OUT, "bathy_64bit.nc"), "w", format="NETCDF3_64BIT_OFFSET") as ds:
        lat = LAT[::-1]
        coords(ds, LON, lat, "longitude", "latitude")
        d = ds.createVariable("depth", "f8", ("latitude", "longitude"))
        d.units, d.standard_name, d.positive = "m", "sea_floor_depth_below_sea_surface", "down"
        d[:] = -plane(LON[None, :], lat[:, None])


def cdf5():
    """CDF-5, longitudes in 0..360, (lon, lat) dimension order, variable `z` (GMT style)."""
    with Dataset(os.path.join(OUT, "bathy_cdf5.nc"), "w", format="NETCDF3_64BIT_DATA") as ds:
        lon360 = LON + 360.0
        ds.createDimension("x", len(lon360))
        ds.createDimension("y", len(LAT))
        x = ds.createVariable("x", "f8", ("x",))
        y = ds.createVariable("y", "f8", ("y",))
        x.units, y.units = "degrees_east", "degrees_north"
        x[:], y[:] = lon360, LAT
        z = ds.createVariable("z", "f8", ("x", "y"))
        z[:] = plane(LON[:, None], LAT[None, :])


def nc4():
    """NetCDF-4: chunked, deflate + shuffle, int16 packed (0.1 m steps), axis attributes only."""
    with Dataset(os.path.join(OUT, "bathy_nc4.nc"), "w", format="NETCDF4") as ds:
        coords(ds, LON, LAT, "longitude", "latitude", units=False, axis=True)
        z = ds.createVariable(
            "elevation", "i2", ("latitude", "longitude"), zlib=True, shuffle=True, chunksizes=(4, 4), fill_value=np.int16(-32768)
        )
        z.scale_factor, z.add_offset = 0.1, -100.0
        z.units = "m"
        z.set_auto_maskandscale(True)
        data = np.ma.masked_array(plane(LON[None, :], LAT[:, None]))
        data[10, 12] = np.ma.masked
        z[:] = data


def global360():
    """A coarse global grid in 0..360 for boxes across the antimeridian: value = the node's
    longitude in -180..180."""
    lon = np.arange(0.0, 360.0, 2.0)
    lat = np.arange(-88.0, 89.0, 4.0)
    with Dataset(os.path.join(OUT, "global_360.nc"), "w", format="NETCDF4") as ds:
        coords(ds, lon, lat)
        z = ds.createVariable("elevation", "f4", ("lat", "lon"), zlib=True)
        signed = ((lon + 180.0) % 360.0) - 180.0
        z[:] = np.broadcast_to(signed[None, :], (len(lat), len(lon)))


def copernicus():
    """Copernicus Marine layout: uo, vo (time, depth, latitude, longitude), int16 packed,
    land as _FillValue, time in hours since 1950-01-01. u = 0.1 + 0.01 h, v = -0.2 at every
    wet node (h: hours since the first record), land at the north-east corner node."""
    with Dataset(os.path.join(OUT, "currents_copernicus.nc"), "w", format="NETCDF4") as ds:
        ds.createDimension("time", 3)
        ds.createDimension("depth", 2)
        coords(ds, LON, LAT, "longitude", "latitude")
        t = ds.createVariable("time", "f8", ("time",))
        t.units, t.calendar, t.standard_name = "hours since 1950-01-01", "gregorian", "time"
        t0 = 665016.0  # 2025-11-12T00:00:00Z
        t[:] = [t0, t0 + 6.0, t0 + 12.0]
        d = ds.createVariable("depth", "f4", ("depth",))
        d.units, d.positive, d.standard_name = "m", "down", "depth"
        d[:] = [0.5, 50.0]
        for name, std in [("uo", "eastward_sea_water_velocity"), ("vo", "northward_sea_water_velocity")]:
            var = ds.createVariable(name, "i2", ("time", "depth", "latitude", "longitude"), fill_value=np.int16(-32767), zlib=True)
            var.scale_factor, var.add_offset, var.units, var.standard_name = 0.001, 0.0, "m s-1", std
            var.set_auto_maskandscale(True)
            data = np.ma.zeros((3, 2, len(LAT), len(LON)))
            for k, h in enumerate([0.0, 6.0, 12.0]):
                data[k] = (0.1 + 0.01 * h) if name == "uo" else -0.2
            data[:, :, -1, -1] = np.ma.masked
            var[:] = data


def hycom():
    """HYCOM layout: water_u, water_v (time, depth, lat, lon) as short with missing_value,
    time in hours since 2000-01-01 00:00:00, longitudes 0..360. u = 0.3, v = 0.05 h / 10."""
    with Dataset(os.path.join(OUT, "currents_hycom.nc"), "w", format="NETCDF3_64BIT_OFFSET") as ds:
        ds.createDimension("time", 2)
        ds.createDimension("depth", 1)
        coords(ds, LON + 360.0, LAT)
        t = ds.createVariable("time", "f8", ("time",))
        t.units, t.calendar = "hours since 2000-01-01 00:00:00", "standard"
        t[:] = [226392.0, 226402.0]  # 2025-10-29T00:00Z and +10 h
        d = ds.createVariable("depth", "f8", ("depth",))
        d.units, d.positive = "m", "down"
        d[:] = [0.0]
        for name, vals in [("water_u", (0.3, 0.3)), ("water_v", (0.0, 0.05))]:
            var = ds.createVariable(name, "i2", ("time", "depth", "lat", "lon"))
            var.scale_factor, var.add_offset, var.missing_value, var.units = 0.001, 0.0, np.int16(-30000), "m/s"
            var.set_auto_maskandscale(False)
            raw = np.zeros((2, 1, len(LAT), len(LON)), dtype="i2")
            for k, v in enumerate(vals):
                raw[k] = int(round(v / 0.001))
            raw[:, :, 0, 0] = -30000
            var[:] = raw


def geotiffs():
    import rasterio
    from rasterio.transform import from_origin

    # Pixel-is-area: pixel centres on the LON/LAT lattice, so the origin is half a pixel off.
    data = plane(LON[None, :], LAT[::-1][:, None]).astype("f4")
    transform = from_origin(LON[0] - 0.05, LAT[-1] + 0.05, 0.1, 0.1)
    profile = dict(driver="GTiff", width=len(LON), height=len(LAT), count=1, dtype="float32", transform=transform, nodata=-9999.0)
    data_nd = data.copy()
    data_nd[-1, 0] = -9999.0  # south-west corner
    with rasterio.open(os.path.join(OUT, "bathy_area.tif"), "w", crs="EPSG:4326", **profile) as f:
        f.write(data_nd, 1)
    # Pixel-is-point: the tie point is the first pixel's centre.
    with rasterio.open(os.path.join(OUT, "bathy_point.tif"), "w", crs="EPSG:4326", **profile) as f:
        f.update_tags(AREA_OR_POINT="Point")
        f.write(data, 1)
    # A projected CRS, which the reader must refuse by name.
    with rasterio.open(os.path.join(OUT, "bathy_utm.tif"), "w", crs="EPSG:32610", **dict(profile, transform=from_origin(500000, 5400000, 100, 100))) as f:
        f.write(data, 1)
    # ESRI ASCII grid written by GDAL.
    with rasterio.open(os.path.join(OUT, "bathy.asc"), "w", driver="AAIGrid", width=len(LON), height=len(LAT), count=1, dtype="float32",
                       transform=transform, nodata=-9999.0, crs="EPSG:4326") as f:
        f.write(data_nd, 1)
    os.remove(os.path.join(OUT, "bathy.prj"))  # GDAL's side file; the reader takes degrees


def nocoords():
    """CDF-1 with an elevation grid on bare dimensions: no coordinate variables at all."""
    with Dataset(os.path.join(OUT, "bathy_nocoords.nc"), "w", format="NETCDF3_CLASSIC") as ds:
        ds.createDimension("row", len(LAT))
        ds.createDimension("col", len(LON))
        z = ds.createVariable("elevation", "f4", ("row", "col"))
        z.units = "m"
        z[:] = plane(LON[None, :], LAT[:, None]).astype("f4")


# Wave forecasts: a 6 x 5 lon/lat grid of 0.1 degree over the same corner of the sea.
WLON = np.round(np.arange(-125.0, -124.45, 0.1), 6)  # 6 columns
WLAT = np.round(np.arange(48.0, 48.45, 0.1), 6)  # 5 rows


def wave_height(lon, lat, hours):
    """The height every wave fixture holds: 1 m + 2 m per degree east + 0.1 m per hour."""
    return 1.0 + 2.0 * (lon + 125.0) + 0.1 * hours + 0.0 * lat


def waves_copernicus():
    """Copernicus Marine wave layout: VHM0 (time, latitude, longitude) float32 with
    standard_name sea_surface_wave_significant_height, time in hours since 1950-01-01 at 0, 3
    and 6 h after 2025-11-12T00:00Z, land (_FillValue) on the 2 x 2 nodes of the north-east
    corner (longitudes -124.6 and -124.5, latitudes 48.3 and 48.4)."""
    with Dataset(os.path.join(OUT, "waves_copernicus.nc"), "w", format="NETCDF4") as ds:
        ds.createDimension("time", 3)
        coords(ds, WLON, WLAT, "longitude", "latitude")
        t = ds.createVariable("time", "f8", ("time",))
        t.units, t.calendar, t.standard_name = "hours since 1950-01-01", "gregorian", "time"
        t0 = 665016.0  # 2025-11-12T00:00:00Z
        t[:] = [t0, t0 + 3.0, t0 + 6.0]
        var = ds.createVariable("VHM0", "f4", ("time", "latitude", "longitude"), fill_value=np.float32(-999.0), zlib=True)
        var.units, var.standard_name = "m", "sea_surface_wave_significant_height"
        data = np.ma.zeros((3, len(WLAT), len(WLON)))
        for k, h in enumerate([0.0, 3.0, 6.0]):
            data[k] = wave_height(WLON[None, :], WLAT[:, None], h)
        data[:, -2:, -2:] = np.ma.masked
        var[:] = data


def waves_ww3():
    """WAVEWATCH III layout: hs (time, lat, lon) float32 without a standard name, classic
    format, longitudes 0..360, latitudes descending, time in seconds since 1970-01-01 at
    2025-11-12T00:00Z and 6 h later; no land."""
    with Dataset(os.path.join(OUT, "waves_ww3.nc"), "w", format="NETCDF3_CLASSIC") as ds:
        ds.createDimension("time", 2)
        coords(ds, WLON + 360.0, WLAT[::-1])
        t = ds.createVariable("time", "f8", ("time",))
        t.units = "seconds since 1970-01-01 00:00:00"
        t0 = 1762905600.0  # 2025-11-12T00:00:00Z
        t[:] = [t0, t0 + 6 * 3600.0]
        var = ds.createVariable("hs", "f4", ("time", "lat", "lon"))
        var.units = "m"
        for k, h in enumerate([0.0, 6.0]):
            var[k] = wave_height(WLON[None, :], WLAT[::-1][:, None], h).astype("f4")


def waves_malformed():
    """A wave file the readers must refuse: VHM0 on a latitude axis that is not monotonic."""
    with Dataset(os.path.join(OUT, "waves_malformed.nc"), "w", format="NETCDF3_CLASSIC") as ds:
        lat = WLAT.copy()
        lat[2], lat[3] = lat[3], lat[2]
        coords(ds, WLON, lat, "longitude", "latitude")
        var = ds.createVariable("VHM0", "f4", ("latitude", "longitude"))
        var.units, var.standard_name = "m", "sea_surface_wave_significant_height"
        var[:] = np.ones((len(lat), len(WLON)), dtype="f4")


ALL = [classic, offset64, cdf5, nc4, global360, copernicus, hycom, geotiffs, nocoords, waves_copernicus, waves_ww3, waves_malformed]

if __name__ == "__main__":
    # Names of fixtures on the command line (e.g. `waves_ww3`) write only those.
    import sys

    os.makedirs(OUT, exist_ok=True)
    wanted = sys.argv[1:]
    for make in ALL:
        if not wanted or make.__name__ in wanted:
            make()
    for name in sorted(os.listdir(OUT)):
        print(name, os.path.getsize(os.path.join(OUT, name)))
