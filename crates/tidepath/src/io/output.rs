//! Output files, written safely: all of a command's files or none of them, each through an
//! unpredictable, exclusively created temporary file in the target's folder and a rename, and
//! never over something that is not a regular file.
//!
//! Why: a plan written half-way, or a results folder where some files are new and some are
//! from the last run, is worse than none; a temporary with a predictable name lets another
//! local user plant a symlink there; and `--out /dev/sda` or a FIFO must be refused, not
//! replaced or blocked on.

use std::io::Write as _;
use std::path::{Path, PathBuf};

use crate::error::{Error, Result};

/// Refuses `path` as an output unless it is absent or a regular file and its folder exists.
/// `flag` names where the path came from (`--out`, `--plot`, ...).
pub fn check_target(flag: &str, path: &Path) -> Result<()> {
    if path.file_name().is_none() {
        return Err(Error::input(flag, format!("'{}' is not a file path", path.display())));
    }
    match std::fs::symlink_metadata(path) {
        Ok(meta) if !meta.file_type().is_file() => {
            let what = if meta.file_type().is_symlink() {
                "a symbolic link"
            } else if meta.is_dir() {
                "a directory"
            } else {
                "not a regular file (a FIFO, socket or device)"
            };
            return Err(Error::input(flag, format!("'{}' is {what}; refusing to replace it", path.display())));
        }
        _ => {}
    }
    let dir = folder(path);
    if !dir.is_dir() {
        return Err(Error::input(flag, format!("folder '{}' does not exist", dir.display())));
    }
    Ok(())
}

fn folder(path: &Path) -> &Path {
    path.parent().filter(|d| !d.as_os_str().is_empty()).unwrap_or(Path::new("."))
}

/// Files staged for one command: nothing appears at a target until [`Outputs::commit`].
#[derive(Default)]
pub struct Outputs {
    staged: Vec<(String, PathBuf, tempfile::NamedTempFile)>,
}

impl Outputs {
    pub fn new() -> Self {
        Self::default()
    }

    /// Writes `bytes` to a fresh temporary next to `path`. Dropping the set without committing
    /// removes every temporary.
    pub fn stage(&mut self, flag: &str, path: &Path, bytes: &[u8]) -> Result<()> {
        check_target(flag, path)?;
        if self.staged.iter().any(|(_, p, _)| p == path) {
            return Err(Error::input(flag, format!("'{}' is named twice as an output", path.display())));
        }
        let mut tmp = tempfile::Builder::new()
            .prefix(".tidepath-")
            .suffix(".tmp")
            .tempfile_in(folder(path))
            .map_err(|e| Error::io(path, e))?;
        tmp.write_all(bytes).and_then(|_| tmp.flush()).map_err(|e| Error::io(path, e))?;
        set_readable(&tmp, path)?;
        self.staged.push((flag.to_string(), path.to_path_buf(), tmp));
        Ok(())
    }

    /// Moves every staged file to its target. Targets are checked again first, so a target
    /// that became a symlink or a FIFO meanwhile is refused before any file is moved.
    pub fn commit(self) -> Result<()> {
        for (flag, path, _) in &self.staged {
            check_target(flag, path)?;
        }
        for (_, path, tmp) in self.staged {
            tmp.persist(&path).map_err(|e| Error::io(&path, e.error))?;
        }
        Ok(())
    }
}

/// Temporary files are created private (0600); a finished output gets the permissions of the
/// file it replaces, or the usual 0644.
fn set_readable(tmp: &tempfile::NamedTempFile, target: &Path) -> Result<()> {
    #[cfg(unix)]
    {
        use std::os::unix::fs::PermissionsExt;
        let mode = std::fs::metadata(target).map(|m| m.permissions().mode() & 0o777).unwrap_or(0o644);
        std::fs::set_permissions(tmp.path(), std::fs::Permissions::from_mode(mode))
            .map_err(|e| Error::io(target, e))?;
    }
    #[cfg(not(unix))]
    let _ = (tmp, target);
    Ok(())
}

/// Writes one file safely (see the module documentation).
pub fn write_atomic(path: &Path, bytes: &[u8]) -> Result<()> {
    let mut out = Outputs::new();
    out.stage("output", path, bytes)?;
    out.commit()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn staged_files_appear_together_or_not_at_all() {
        let dir = tempfile::tempdir().unwrap();
        let (a, b) = (dir.path().join("a.json"), dir.path().join("b.svg"));
        let mut out = Outputs::new();
        out.stage("--out", &a, b"{}").unwrap();
        out.stage("--plot", &b, b"<svg/>").unwrap();
        assert!(!a.exists() && !b.exists());
        out.commit().unwrap();
        assert_eq!(std::fs::read(&a).unwrap(), b"{}");
        // A failed second stage leaves nothing new behind.
        let mut out = Outputs::new();
        out.stage("--out", &dir.path().join("c.json"), b"1").unwrap();
        assert!(out.stage("--plot", &dir.path().join("missing/d.svg"), b"2").is_err());
        drop(out);
        let names: Vec<_> = std::fs::read_dir(dir.path()).unwrap().map(|e| e.unwrap().file_name()).collect();
        assert_eq!(names.len(), 2, "{names:?}");
    }

    #[cfg(unix)]
    #[test]
    fn symlinks_fifos_devices_and_directories_are_refused_and_left_alone() {
        let dir = tempfile::tempdir().unwrap();
        let target = dir.path().join("real.txt");
        std::fs::write(&target, b"keep").unwrap();
        let link = dir.path().join("link.json");
        std::os::unix::fs::symlink(&target, &link).unwrap();
        let e = write_atomic(&link, b"x").unwrap_err().to_string();
        assert!(e.contains("symbolic link"), "{e}");
        assert_eq!(std::fs::read(&target).unwrap(), b"keep");
        assert!(std::fs::symlink_metadata(&link).unwrap().file_type().is_symlink());
        let fifo = dir.path().join("fifo");
        let made = std::process::Command::new("mkfifo").arg(&fifo).status().map(|s| s.success()).unwrap_or(false);
        if made {
            assert!(write_atomic(&fifo, b"x").unwrap_err().to_string().contains("FIFO"));
        }
        assert!(write_atomic(Path::new("/dev/null"), b"x").unwrap_err().to_string().contains("device"));
        assert!(write_atomic(dir.path(), b"x").is_err());
    }
}
