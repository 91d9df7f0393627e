use super::*;

/// Every file under `dir` with its contents (folders as `name/`), sorted.
fn tree(dir: &Path) -> Vec<(String, String)> {
    let mut out = Vec::new();
    fn walk(base: &Path, dir: &Path, out: &mut Vec<(String, String)>) {
        for e in std::fs::read_dir(dir).unwrap() {
            let p = e.unwrap().path();
            let rel = p.strip_prefix(base).unwrap().display().to_string();
            let meta = std::fs::symlink_metadata(&p).unwrap();
            if meta.is_dir() {
                out.push((format!("{rel}/"), String::new()));
                walk(base, &p, out);
            } else if meta.file_type().is_symlink() {
                out.push((rel, format!("-> {}", std::fs::read_link(&p).unwrap().display())));
            } else {
                out.push((rel, std::fs::read_to_string(&p).unwrap_or_default()));
            }
        }
    }
    walk(dir, dir, &mut out);
    out.sort();
    out
}

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
    let e = out.stage("--plot", &dir.path().join("missing/d.svg"), b"2").unwrap_err().to_string();
    assert!(e.contains("folder") && e.contains("does not exist"), "{e}");
    assert!(out.stage_in("--plot", &dir.path().join("missing.txt"), "d.svg", b"2").is_ok());
    std::fs::write(dir.path().join("missing.txt"), "a file, not a folder").unwrap();
    assert!(out.commit().is_err());
    let names: Vec<_> = tree(dir.path()).into_iter().map(|(n, _)| n).collect();
    assert_eq!(names, ["a.json", "b.svg", "missing.txt"]);
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

/// The cases that once deleted a user's folder: a refusal after `..` through a folder that did
/// not exist yet. The user's file must survive every one, and nothing new may be left.
#[test]
fn parent_steps_through_missing_folders_never_remove_user_files() {
    for shape in ["new/../keep", "a/b/../../keep", "new/..", "./new/../keep/.", "keep/../keep"] {
        let dir = tempfile::tempdir().unwrap();
        let keep = dir.path().join("keep");
        std::fs::create_dir(&keep).unwrap();
        std::fs::write(keep.join("thesis.tex"), "text").unwrap();
        std::fs::write(dir.path().join("data.csv"), "1,2").unwrap();
        // A directory where an output must go: refused when declared.
        let target_dir = dir.path().join(shape);
        std::fs::create_dir_all(dir.path().join("keep/results.json")).unwrap();
        std::fs::create_dir_all(dir.path().join("results.json")).unwrap();
        let before = tree(dir.path());
        let mut out = Outputs::new();
        let e = out.declare_in("--out", &target_dir, "results.json").unwrap_err().to_string();
        assert!(e.contains("is a directory"), "{shape}: {e}");
        drop(out);
        assert_eq!(tree(dir.path()), before, "{shape}");
        // A failure inside the commit, after the first rename.
        std::fs::remove_dir(dir.path().join("keep/results.json")).unwrap();
        std::fs::remove_dir(dir.path().join("results.json")).unwrap();
        let before = tree(dir.path());
        let mut out = Outputs::new();
        out.stage_in("--out", &target_dir, "results.json", b"{}").unwrap();
        out.stage_in("--out", &target_dir, "table.md", b"|").unwrap();
        out.fail_after = Some(1);
        assert!(out.commit().is_err(), "{shape}");
        assert_eq!(tree(dir.path()), before, "{shape}");
        // And a successful one writes exactly where the path resolves.
        let mut out = Outputs::new();
        out.stage_in("--out", &target_dir, "results.json", b"{}").unwrap();
        out.commit().unwrap();
        let expect = if shape == "new/.." { dir.path().join("results.json") } else { keep.join("results.json") };
        assert!(expect.is_file(), "{shape}");
        assert!(!dir.path().join("new").exists() && !dir.path().join("a").exists(), "{shape}");
    }
}

#[test]
fn a_failed_commit_puts_replaced_files_back_and_removes_only_the_folders_it_made() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("old.json"), "old plan").unwrap();
    std::fs::create_dir(dir.path().join("made")).unwrap();
    std::fs::write(dir.path().join("made/user.txt"), "mine").unwrap();
    let before = tree(dir.path());
    for fail_after in 0..4 {
        let mut out = Outputs::new();
        out.stage("--out", &dir.path().join("old.json"), b"new plan").unwrap();
        out.stage_in("--out", &dir.path().join("x/y/z"), "results.json", b"{}").unwrap();
        out.stage_in("--out", &dir.path().join("made"), "table.md", b"|").unwrap();
        out.fail_after = Some(fail_after);
        let r = out.commit();
        if fail_after < 3 {
            assert!(r.is_err());
            assert_eq!(tree(dir.path()), before, "failing after {fail_after} renames");
        } else {
            r.unwrap();
        }
    }
    assert_eq!(std::fs::read_to_string(dir.path().join("old.json")).unwrap(), "new plan");
    assert!(dir.path().join("x/y/z/results.json").is_file());
    // No backups or temporaries left behind.
    assert!(tree(dir.path()).iter().all(|(n, _)| !n.contains(".tidepath-")), "{:?}", tree(dir.path()));
}

#[test]
fn one_file_named_by_two_flags_is_refused() {
    let dir = tempfile::tempdir().unwrap();
    let a = dir.path().join("x.json");
    let b = dir.path().join("sub/../x.json");
    let mut out = Outputs::new();
    out.declare("--out", &a).unwrap();
    let e = out.declare("--plot", &b).unwrap_err().to_string();
    assert!(e.starts_with("--plot:") && e.contains("is also the --out file"), "{e}");
    let e = out.declare_in("--out", dir.path(), "x.json").unwrap_err().to_string();
    assert!(e.contains("is named twice"), "{e}");
    assert!(out.declare_in("--out", dir.path(), "../x").is_err());
    assert!(out.declare("--out", &dir.path().join("..")).is_err());
}

#[cfg(unix)]
#[test]
fn folders_through_symlinks_resolve_to_their_targets() {
    let dir = tempfile::tempdir().unwrap();
    let real = dir.path().join("real");
    std::fs::create_dir(&real).unwrap();
    std::os::unix::fs::symlink(&real, dir.path().join("link")).unwrap();
    std::os::unix::fs::symlink(dir.path().join("nowhere"), dir.path().join("dangling")).unwrap();
    // `link/../x` is `dir/x` to the kernel (`..` of the link's target), whatever the text says.
    let mut out = Outputs::new();
    std::fs::create_dir(real.join("sub")).unwrap();
    out.stage("--out", &dir.path().join("link/sub/../a.json"), b"1").unwrap();
    let e = out.declare("--plot", &real.join("a.json")).unwrap_err().to_string();
    assert!(e.contains("is also the --out file"), "{e}");
    out.commit().unwrap();
    assert!(real.join("a.json").is_file());
    let mut out = Outputs::new();
    let e = out.declare_in("--out", &dir.path().join("dangling/new"), "a.json").unwrap_err().to_string();
    assert!(e.contains("symbolic link to nothing"), "{e}");
    assert!(!dir.path().join("nowhere").exists());
}
