//! Input files, read defensively: only regular files (a FIFO with no writer would block
//! forever, `/dev/zero` never ends), and never more bytes than a documented limit, checked
//! from the file's size before reading and enforced while reading (a file may grow).

use std::io::Read as _;
use std::path::Path;

use tidepath::error::{Error, Result};

/// Most bytes of a scenario file. The largest scenario one would write by hand or generate
/// (a 4,000 x 4,000 cell map) is a few tens of MB; TOML parsing needs several times the
/// file's size in memory.
pub const MAX_SCENARIO_BYTES: u64 = 64 << 20;

/// Most bytes of a plan file: a plan of [`crate::plan_json::MAX_PLAN_POINTS`] points per
/// path is a few MB of JSON.
pub const MAX_PLAN_BYTES: u64 = 64 << 20;

/// The size of the regular file at `path` (symlinks followed); anything else is refused,
/// naming `field` and the path.
pub fn regular_file(path: &Path, field: &str) -> Result<u64> {
    let meta = std::fs::metadata(path).map_err(|e| Error::io(path, e))?;
    if !meta.is_file() {
        let what = if meta.is_dir() { "a folder" } else { "not a regular file (a FIFO, socket or device)" };
        return Err(Error::input(field, format!("'{}' is {what}", path.display())));
    }
    Ok(meta.len())
}

/// The text of the regular file at `path`, refused (naming `field`) if it holds more than
/// `max` bytes or is not UTF-8.
pub fn read_text(path: &Path, field: &str, max: u64) -> Result<String> {
    let len = regular_file(path, field)?;
    let too_big = |n: u64| {
        Error::input(
            field,
            format!("'{}' holds {n} bytes, more than the limit of {max} bytes for this kind of file", path.display()),
        )
    };
    if len > max {
        return Err(too_big(len));
    }
    let file = std::fs::File::open(path).map_err(|e| Error::io(path, e))?;
    let mut bytes = Vec::with_capacity(len as usize);
    file.take(max + 1).read_to_end(&mut bytes).map_err(|e| Error::io(path, e))?;
    if bytes.len() as u64 > max {
        return Err(too_big(bytes.len() as u64));
    }
    String::from_utf8(bytes).map_err(|e| {
        Error::input(field, format!("'{}' is not UTF-8 text (byte {})", path.display(), e.utf8_error().valid_up_to()))
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn only_regular_files_within_the_limit_are_read() {
        let dir = tempfile::tempdir().unwrap();
        let f = dir.path().join("s.toml");
        std::fs::write(&f, "name = \"x\"\n").unwrap();
        assert_eq!(read_text(&f, "SCENARIO", 100).unwrap(), "name = \"x\"\n");
        let e = read_text(&f, "SCENARIO", 4).unwrap_err().to_string();
        assert!(e.starts_with("SCENARIO:") && e.contains("11 bytes") && e.contains("limit of 4"), "{e}");
        assert!(read_text(dir.path(), "SCENARIO", 100).unwrap_err().to_string().contains("a folder"));
        let e = read_text(Path::new("/dev/zero"), "SCENARIO", 100).unwrap_err().to_string();
        assert!(e.contains("not a regular file"), "{e}");
        std::fs::write(&f, [0xff, 0xfe, b'a']).unwrap();
        assert!(read_text(&f, "SCENARIO", 100).unwrap_err().to_string().contains("not UTF-8"));
        #[cfg(unix)]
        {
            let fifo = dir.path().join("fifo");
            if std::process::Command::new("mkfifo").arg(&fifo).status().is_ok_and(|s| s.success()) {
                // Refused from its type: opening it would block with no writer.
                assert!(read_text(&fifo, "SCENARIO", 100).unwrap_err().to_string().contains("FIFO"));
            }
        }
    }
}
