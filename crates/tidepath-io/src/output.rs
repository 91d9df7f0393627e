//! Output files, written safely: all of a command's files or none of them.
//!
//! A command declares every output before it starts working ([`Outputs::declare`],
//! [`Outputs::declare_in`]), so a bad target is refused before any time is spent, fills them
//! in when its work is done, and [`Outputs::commit`]s them together:
//!
//! * each path is resolved once: the longest part that exists is canonicalised, the rest (the
//!   folders still to create) is taken lexically, so `new/../keep` means `./keep` whether or
//!   not `new` exists, and two flags naming one file (`x.json` and `./x.json`) are caught;
//! * a target must be absent or a regular file; a symlink, folder, FIFO or device is refused
//!   and left as it was;
//! * each file is written to an unpredictable, exclusively created temporary in the target's
//!   folder and renamed into place only once every file is written;
//! * if anything fails, exactly what this command did is undone: files it replaced are put
//!   back (from a hard link made before the rename), files it created are removed, and the
//!   folders it created are removed again, each only if still empty. Nothing that existed
//!   before is ever removed.
//!
//! Why: a plan written half-way, or a results folder where some files are new and some are
//! from the last run, is worse than none; a clean-up that removes what a path *names* rather
//! than what the run *made* can delete a user's folder; a temporary with a predictable name
//! lets another local user plant a symlink there.

use std::ffi::OsString;
use std::io::Write as _;
use std::path::{Component, Path, PathBuf};

use tidepath::error::{Error, Result};

/// A path resolved once: `existing` is canonical (no symlinks, no `..`), `missing` are the
/// folders or file below it that do not exist yet, with `.` and `..` already applied.
#[derive(Clone, Debug, PartialEq, Eq)]
struct Resolved {
    existing: PathBuf,
    missing: Vec<OsString>,
}

impl Resolved {
    fn full(&self) -> PathBuf {
        let mut p = self.existing.clone();
        p.extend(&self.missing);
        p
    }
}

/// Resolves `path` (following symlinks in the parts that exist) without creating anything.
fn resolve(path: &Path) -> std::io::Result<Resolved> {
    let abs = if path.is_absolute() { path.to_path_buf() } else { std::env::current_dir()?.join(path) };
    let mut existing = PathBuf::new();
    let mut missing: Vec<OsString> = Vec::new();
    for comp in abs.components() {
        match comp {
            Component::Prefix(_) | Component::RootDir => existing.push(comp.as_os_str()),
            Component::CurDir => {}
            Component::ParentDir => {
                // `existing` is canonical, so its parent is the real parent.
                if missing.pop().is_none() {
                    existing.pop();
                }
            }
            Component::Normal(name) => {
                if !missing.is_empty() {
                    missing.push(name.to_os_string());
                    continue;
                }
                let next = existing.join(name);
                match std::fs::symlink_metadata(&next) {
                    Ok(m) if m.file_type().is_symlink() => match std::fs::canonicalize(&next) {
                        Ok(real) => existing = real,
                        // A dangling link: creating through it would create its target.
                        Err(_) => {
                            return Err(std::io::Error::other(format!(
                                "'{}' is a symbolic link to nothing",
                                next.display()
                            )))
                        }
                    },
                    Ok(_) => existing = next,
                    // Below a file (ENOTDIR) nothing exists either; the check says the file
                    // is not a folder.
                    Err(e) if matches!(e.kind(), std::io::ErrorKind::NotFound | std::io::ErrorKind::NotADirectory) => {
                        missing.push(name.to_os_string())
                    }
                    Err(e) => return Err(e),
                }
            }
        }
    }
    Ok(Resolved { existing, missing })
}

/// What is at `path` if it is not acceptable as an output file, in words.
fn refusal(path: &Path) -> Option<&'static str> {
    let meta = std::fs::symlink_metadata(path).ok()?;
    let t = meta.file_type();
    if t.is_file() {
        None
    } else if t.is_symlink() {
        Some("a symbolic link")
    } else if t.is_dir() {
        Some("a directory")
    } else {
        Some("not a regular file (a FIFO, socket or device)")
    }
}

/// One declared output file.
struct Planned {
    flag: String,
    /// The path as the user gave it, for messages.
    shown: PathBuf,
    folder: Resolved,
    name: OsString,
    bytes: Option<Vec<u8>>,
}

impl Planned {
    fn target(&self) -> PathBuf {
        self.folder.full().join(&self.name)
    }

    /// Refuses the target unless it is absent or a regular file and its folder exists or can
    /// be created.
    fn check(&self) -> Result<()> {
        let err = |m: String| Error::input(&self.flag, m);
        let shown = self.shown.display().to_string();
        if !self.folder.existing.is_dir() {
            return Err(err(format!("'{shown}': '{}' is not a folder", self.folder.existing.display())));
        }
        if self.folder.missing.is_empty() {
            if let Some(what) = refusal(&self.target()) {
                return Err(err(format!("'{shown}' is {what}; refusing to replace it")));
            }
        }
        Ok(())
    }
}

/// Index of a declared output, to fill in later.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct OutputId(usize);

/// The output files of one command: nothing appears at a target until [`Outputs::commit`],
/// and a failed commit leaves everything as it was.
#[derive(Default)]
pub struct Outputs {
    files: Vec<Planned>,
    /// Tests make the commit fail after this many renames, to check the undo.
    #[cfg(test)]
    fail_after: Option<usize>,
}

impl Outputs {
    pub fn new() -> Self {
        Self::default()
    }

    /// Declares the output file `path` (named by `flag` in errors) and checks it now: absent
    /// or a regular file, in a folder that exists (a file's folder is not created: a typo in
    /// it should not grow a tree of folders), not named twice.
    pub fn declare(&mut self, flag: &str, path: &Path) -> Result<OutputId> {
        let shown = path.display().to_string();
        let name = match path.components().next_back() {
            Some(Component::Normal(n)) => n.to_os_string(),
            _ => return Err(Error::input(flag, format!("'{shown}' is not a file path"))),
        };
        let parent = path.parent().filter(|d| !d.as_os_str().is_empty()).unwrap_or(Path::new("."));
        let id = self.push(flag, path.to_path_buf(), parent, name)?;
        if !self.files[id.0].folder.missing.is_empty() {
            self.files.pop();
            return Err(Error::input(flag, format!("folder '{}' does not exist", parent.display())));
        }
        Ok(id)
    }

    /// Declares the file `name` in the folder `dir` (created at commit if missing; a symlink
    /// to a folder is followed).
    pub fn declare_in(&mut self, flag: &str, dir: &Path, name: &str) -> Result<OutputId> {
        if Path::new(name).components().count() != 1 || name == ".." || name == "." {
            return Err(Error::input(flag, format!("'{}' is not a file name", name)));
        }
        self.push(flag, dir.join(name), dir, OsString::from(name))
    }

    fn push(&mut self, flag: &str, shown: PathBuf, folder: &Path, name: OsString) -> Result<OutputId> {
        let folder = resolve(folder).map_err(|e| Error::input(flag, format!("'{}': {e}", shown.display())))?;
        let planned = Planned { flag: flag.to_string(), shown, folder, name, bytes: None };
        planned.check()?;
        let target = planned.target();
        if let Some(other) = self.files.iter().find(|p| p.target() == target) {
            let same = if other.flag == planned.flag { "is named twice as an output" } else { "is also" };
            let tail = if other.flag == planned.flag { String::new() } else { format!(" the {} file", other.flag) };
            return Err(Error::input(flag, format!("'{}' {same}{tail}", planned.shown.display())));
        }
        self.files.push(planned);
        Ok(OutputId(self.files.len() - 1))
    }

    /// Sets the contents of a declared file.
    pub fn fill(&mut self, id: OutputId, bytes: impl Into<Vec<u8>>) {
        self.files[id.0].bytes = Some(bytes.into());
    }

    /// Declares and fills `path` at once.
    pub fn stage(&mut self, flag: &str, path: &Path, bytes: &[u8]) -> Result<()> {
        let id = self.declare(flag, path)?;
        self.fill(id, bytes);
        Ok(())
    }

    /// Declares and fills `dir/name` at once, or fills it if it was declared already.
    pub fn stage_in(&mut self, flag: &str, dir: &Path, name: &str, bytes: &[u8]) -> Result<()> {
        let folder = resolve(dir).ok();
        let known = self.files.iter().position(|p| Some(&p.folder) == folder.as_ref() && p.name == name);
        let id = match known {
            Some(k) => OutputId(k),
            None => self.declare_in(flag, dir, name)?,
        };
        self.fill(id, bytes);
        Ok(())
    }

    /// Writes every filled file (declared files left empty are skipped): all of them, or, on
    /// any failure, none, with every folder and file as it was before. Holds
    /// [`commit_lock`] throughout, so a process that exits at once (a second Ctrl-C) waits for
    /// a commit in progress instead of leaving half of it.
    pub fn commit(self) -> Result<()> {
        let _guard = commit_lock();
        let files: Vec<Planned> = self.files.into_iter().filter(|p| p.bytes.is_some()).collect();
        for p in &files {
            p.check()?;
        }
        let mut undo = Undo::default();
        #[cfg(test)]
        let result = write_all(&files, &mut undo, self.fail_after);
        #[cfg(not(test))]
        let result = write_all(&files, &mut undo, None);
        match result {
            Ok(()) => {
                undo.forget();
                Ok(())
            }
            Err(e) => {
                undo.roll_back();
                Err(e)
            }
        }
    }
}

/// The lock every commit holds. Code that ends the process abruptly (the second Ctrl-C)
/// takes it first, so it never exits between the renames of one commit.
pub fn commit_lock() -> std::sync::MutexGuard<'static, ()> {
    static LOCK: std::sync::Mutex<()> = std::sync::Mutex::new(());
    LOCK.lock().unwrap_or_else(|e| e.into_inner())
}

/// What a commit has done so far, to undo it.
#[derive(Default)]
struct Undo {
    /// Folders this commit created, in creation order.
    created_dirs: Vec<PathBuf>,
    /// Targets moved into place: (target, hard-link backup of the file it replaced).
    placed: Vec<(PathBuf, Option<PathBuf>)>,
}

impl Undo {
    fn roll_back(self) {
        for (target, backup) in self.placed.iter().rev() {
            match backup {
                // Should the rename fail, the backup stays: the user's bytes are never lost.
                Some(b) => {
                    let _ = std::fs::rename(b, target);
                }
                None => {
                    let _ = std::fs::remove_file(target);
                }
            }
        }
        // Only empty folders go, and only those this commit made.
        for d in self.created_dirs.iter().rev() {
            let _ = std::fs::remove_dir(d);
        }
    }

    fn forget(self) {
        for b in self.placed.iter().filter_map(|(_, b)| b.as_ref()) {
            let _ = std::fs::remove_file(b);
        }
    }
}

fn write_all(files: &[Planned], undo: &mut Undo, fail_after: Option<usize>) -> Result<()> {
    // Folders first, one level at a time, remembering each one made here.
    for p in files {
        let mut dir = p.folder.existing.clone();
        for part in &p.folder.missing {
            dir.push(part);
            match std::fs::create_dir(&dir) {
                Ok(()) => undo.created_dirs.push(dir.clone()),
                Err(e) if e.kind() == std::io::ErrorKind::AlreadyExists && dir.is_dir() => {}
                Err(e) => return Err(Error::io(&p.shown, e)),
            }
        }
    }
    // Every file into a temporary beside its target.
    let mut temps = Vec::with_capacity(files.len());
    for p in files {
        let folder = p.folder.full();
        let mut tmp = tempfile::Builder::new()
            .prefix(".tidepath-")
            .suffix(".tmp")
            .tempfile_in(&folder)
            .map_err(|e| Error::io(&p.shown, e))?;
        let bytes = p.bytes.as_deref().unwrap_or_default();
        tmp.write_all(bytes).and_then(|_| tmp.flush()).map_err(|e| Error::io(&p.shown, e))?;
        set_readable(&tmp, &p.target(), &p.shown)?;
        temps.push(tmp);
    }
    // Targets checked again just before the renames: one that became a symlink or a FIFO
    // meanwhile is refused before any file is moved.
    for p in files {
        if let Some(what) = refusal(&p.target()) {
            return Err(Error::input(&p.flag, format!("'{}' is {what}; refusing to replace it", p.shown.display())));
        }
    }
    for (k, (p, tmp)) in files.iter().zip(temps).enumerate() {
        if fail_after == Some(k) {
            return Err(Error::io(&p.shown, std::io::Error::other("injected failure")));
        }
        let target = p.target();
        let backup = if target.exists() { Some(backup_of(&target, &p.folder.full(), &p.shown)?) } else { None };
        if let Err(e) = tmp.persist(&target) {
            if let Some(b) = backup {
                let _ = std::fs::remove_file(b);
            }
            return Err(Error::io(&p.shown, e.error));
        }
        undo.placed.push((target, backup));
    }
    Ok(())
}

/// A second name for the file at `target` (a hard link, or a copy where links are not
/// supported), so that it can be put back if a later step of the commit fails.
fn backup_of(target: &Path, folder: &Path, shown: &Path) -> Result<PathBuf> {
    let b = tempfile::Builder::new()
        .prefix(".tidepath-")
        .suffix(".bak")
        .make_in(folder, |b| match std::fs::hard_link(target, b) {
            Err(e) if e.kind() != std::io::ErrorKind::AlreadyExists => copy_new(target, b),
            other => other,
        })
        .map_err(|e| Error::io(shown, e))?;
    // Kept on disk: the undo log owns it from here.
    b.into_temp_path().keep().map_err(|e| Error::io(shown, e.error))
}

/// Copies `from` to `to`, which must not exist yet.
fn copy_new(from: &Path, to: &Path) -> std::io::Result<()> {
    let mut src = std::fs::File::open(from)?;
    let mut dst = std::fs::OpenOptions::new().write(true).create_new(true).open(to)?;
    std::io::copy(&mut src, &mut dst)?;
    dst.sync_all()
}

/// Temporary files are created private (0600); a finished output gets the permissions of the
/// file it replaces, or the usual 0644.
fn set_readable(tmp: &tempfile::NamedTempFile, target: &Path, shown: &Path) -> Result<()> {
    #[cfg(unix)]
    {
        use std::os::unix::fs::PermissionsExt;
        let mode = std::fs::metadata(target).map(|m| m.permissions().mode() & 0o777).unwrap_or(0o644);
        std::fs::set_permissions(tmp.path(), std::fs::Permissions::from_mode(mode)).map_err(|e| Error::io(shown, e))?;
    }
    #[cfg(not(unix))]
    let _ = (tmp, target, shown);
    Ok(())
}

/// Writes one file safely (see the module documentation).
pub fn write_atomic(path: &Path, bytes: &[u8]) -> Result<()> {
    let mut out = Outputs::new();
    out.stage("output", path, bytes)?;
    out.commit()
}

#[cfg(test)]
mod tests;
