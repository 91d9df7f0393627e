//! Corrupted data files: every byte of a bathymetry or current file may be wrong (a truncated
//! download, a disk error, a hostile file). The readers must answer with an input error or a
//! grid, never panic, abort or hang. Mutations of the committed fixtures (NetCDF classic,
//! 64-bit offset, CDF-5 and NetCDF-4, GeoTIFF, ESRI ASCII): flipped bytes, truncation, size
//! fields overwritten with extreme integers, spliced ranges. One case in eight is a hostile
//! source instead: a special file (FIFO, `/dev/zero`, a folder, a sparse file of up to 20 GB)
//! under a data file's name, an ESRI header declaring extreme sizes over little data, or a
//! NetCDF forecast whose header declares up to billions of values it does not hold.
//!
//! Same knobs as the scenario fuzzer: `TIDEPATH_FUZZ_CASES` (default 300),
//! `TIDEPATH_FUZZ_SEED`, `TIDEPATH_FUZZ_FROM`. A failing case prints its seed and number.

use std::panic::{catch_unwind, AssertUnwindSafe};
use std::path::PathBuf;
use std::time::{Duration, Instant};

use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use tidepath_io::geodata::currents::read_currents;
use tidepath_io::geodata::netcdf::read_bathymetry;
use tidepath_io::geodata::{esri_ascii, geotiff, DataFile, GeoBox};

use crate::common;

const FIXTURES: &[&str] = &[
    "bathy_classic.nc",
    "bathy_64bit.nc",
    "bathy_cdf5.nc",
    "bathy_nc4.nc",
    "global_360.nc",
    "currents_copernicus.nc",
    "currents_hycom.nc",
    "bathy_area.tif",
    "bathy_point.tif",
    "bathy_utm.tif",
    "bathy.asc",
];

/// One case may take this long before it counts as a hang.
const SLOW: Duration = Duration::from_secs(10);

fn env_u64(name: &str, default: u64) -> u64 {
    std::env::var(name).ok().and_then(|v| v.parse().ok()).unwrap_or(default)
}

/// Integers that size fields break on.
const EXTREMES: &[u64] = &[0, 1, 0x7f, 0xff, 0x7fff, 0xffff, 0x7fff_ffff, 0xffff_ffff, 0x8000_0000, u64::MAX, 1 << 40];

fn mutate(bytes: &[u8], rng: &mut ChaCha8Rng) -> Vec<u8> {
    let mut b = bytes.to_vec();
    let rounds = rng.random_range(1..=4);
    for _ in 0..rounds {
        if b.is_empty() {
            break;
        }
        let n = b.len();
        match rng.random_range(0..6) {
            // A few random bytes.
            0 | 1 => {
                for _ in 0..rng.random_range(1..=8) {
                    let i = rng.random_range(0..n);
                    b[i] = rng.random();
                }
            }
            // One bit.
            2 => {
                let i = rng.random_range(0..n);
                b[i] ^= 1 << rng.random_range(0..8);
            }
            // Truncated.
            3 => b.truncate(rng.random_range(0..n)),
            // An extreme integer over 2, 4 or 8 bytes, either byte order (sizes, offsets,
            // counts, dimension lengths).
            4 => {
                let width = [2usize, 4, 8][rng.random_range(0..3)];
                if n >= width {
                    let i = rng.random_range(0..=n - width);
                    let v = EXTREMES[rng.random_range(0..EXTREMES.len())];
                    let bytes = if rng.random() { v.to_be_bytes() } else { v.to_le_bytes() };
                    let src = if rng.random() { &bytes[8 - width..] } else { &bytes[..width] };
                    b[i..i + width].copy_from_slice(src);
                }
            }
            // A range copied over another.
            _ => {
                let len = rng.random_range(1..=n.min(64));
                let (from, to) = (rng.random_range(0..=n - len), rng.random_range(0..=n - len));
                let chunk = b[from..from + len].to_vec();
                b[to..to + len].copy_from_slice(&chunk);
            }
        }
    }
    b
}

/// Runs every reader that applies to `name` on the file at `path`; an error is a fine answer.
/// Returns how many reads gave a grid (the rest gave errors).
fn read_all(name: &str, path: &std::path::Path) -> usize {
    let file = DataFile::Path(path.to_path_buf());
    let boxes = [None, Some(GeoBox::new(-124.5, 48.0, -123.0, 48.8, "box").unwrap())];
    let mut ok = 0;
    for b in &boxes {
        let b = b.as_ref();
        if name.ends_with(".nc") {
            if name.starts_with("currents") {
                ok += usize::from(read_currents(&file, None, None, 0.0, b, 1).is_ok());
            } else {
                ok += usize::from(read_bathymetry(&file, None, None, b, 1).is_ok());
                ok += usize::from(read_bathymetry(&file, None, None, b, 3).is_ok());
            }
        } else if name.ends_with(".tif") {
            ok += usize::from(geotiff::read(&file, b, 1).is_ok());
        } else {
            ok += usize::from(esri_ascii::read(&file, b, 2).is_ok());
        }
    }
    ok
}

/// Writes a hostile source for a file named `name` at `path`: a special file, a sparse file, or
/// a header declaring sizes the file does not hold.
fn hostile_source(name: &str, path: &std::path::Path, rng: &mut ChaCha8Rng) {
    let _ = std::fs::remove_file(path);
    let _ = std::fs::remove_dir(path);
    match rng.random_range(0..6) {
        0 => {
            let made = std::process::Command::new("mkfifo").arg(path).status().is_ok_and(|s| s.success());
            assert!(made, "mkfifo");
        }
        1 => std::os::unix::fs::symlink("/dev/zero", path).unwrap(),
        2 => std::fs::create_dir(path).unwrap(),
        3 => {
            let len = [0u64, 1, 4096, 1 << 30, 20_000_000_000][rng.random_range(0..5)];
            std::fs::File::create(path).unwrap().set_len(len).unwrap();
        }
        4 if name.ends_with(".asc") => {
            let side = |rng: &mut ChaCha8Rng| EXTREMES[rng.random_range(0..EXTREMES.len())].min(u64::MAX / 2);
            let (nx, ny) = (side(rng), side(rng));
            let mut text = format!("ncols {nx}\nnrows {ny}\nxllcorner -124.5\nyllcorner 48\ncellsize 0.001\n");
            for _ in 0..rng.random_range(0..4) {
                text += "1 2 3 4 5 6 7 8\n";
            }
            std::fs::write(path, text).unwrap();
        }
        _ => std::fs::write(path, forecast(rng)).unwrap(),
    }
}

/// A forecast header declaring random, often enormous, sizes.
fn forecast(rng: &mut ChaCha8Rng) -> Vec<u8> {
    let pick = |rng: &mut ChaCha8Rng, list: &[u32]| list[rng.random_range(0..list.len())];
    common::cdf1::forecast_bomb(
        pick(rng, &[1, 2, 24, 9000, 9001, 20_000]),
        pick(rng, &[2, 3, 201, 1001, 5000]),
        pick(rng, &[2, 3, 201, 1001, 5000]),
    )
}

#[test]
fn corrupted_data_files_give_errors_not_panics() {
    let cases = env_u64("TIDEPATH_FUZZ_CASES", 300);
    let seed = env_u64("TIDEPATH_FUZZ_SEED", 1);
    let from = env_u64("TIDEPATH_FUZZ_FROM", 0);
    let dir = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("tests/data/geo");
    let originals: Vec<(&str, Vec<u8>)> = FIXTURES.iter().map(|n| (*n, std::fs::read(dir.join(n)).unwrap())).collect();
    let tmp = tempfile::tempdir().unwrap();
    let started = Instant::now();
    let mut failures = Vec::new();
    // Cases where some read still gave a grid: the mutation left the file readable, so the
    // readers' inner paths (not only the header checks) were exercised.
    let mut readable = 0u64;
    for case in from..from + cases {
        let mut rng = ChaCha8Rng::seed_from_u64(seed.wrapping_mul(0x9e37_79b9_7f4a_7c15) ^ case);
        let (name, bytes) = &originals[rng.random_range(0..originals.len())];
        let path = tmp.path().join(name);
        if rng.random_range(0..8) == 0 {
            hostile_source(name, &path, &mut rng);
        } else {
            let _ = std::fs::remove_dir(&path);
            let _ = std::fs::remove_file(&path);
            std::fs::write(&path, mutate(bytes, &mut rng)).unwrap();
        }
        let t0 = Instant::now();
        let outcome = catch_unwind(AssertUnwindSafe(|| read_all(name, &path)));
        let took = t0.elapsed();
        readable += u64::from(matches!(outcome, Ok(n) if n > 0));
        if outcome.is_err() || took > SLOW {
            let what = if outcome.is_err() { "panicked" } else { "took too long" };
            let keep = tmp.path().join(format!("case-{case}-{name}"));
            if path.is_file() {
                let _ = std::fs::copy(&path, &keep);
            }
            failures.push(format!("seed {seed} case {case} ({name}): {what} after {took:?}"));
            if failures.len() >= 10 {
                break;
            }
        }
    }
    eprintln!(
        "reader fuzz: {cases} cases (seed {seed}) in {:.1} s, {readable} still readable, {} failures",
        started.elapsed().as_secs_f64(),
        failures.len()
    );
    if !failures.is_empty() {
        // Keep the offending files for a look.
        let kept = tmp.keep();
        panic!("{}\ncorrupted files kept in {}", failures.join("\n"), kept.display());
    }
}
