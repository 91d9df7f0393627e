//! The core's modules form layers: each may use only the ones listed before it (README, "How
//! the code is laid out"). This test reads the sources and fails on an upward `crate::` path in
//! non-test code, so a new import that breaks the layering is caught when it is written.

const ORDER: &[&str] = &[
    "geom",
    "text",
    "error",
    "geo",
    "config",
    "rng",
    "registry",
    "scratch",
    "world",
    "vehicle",
    "mission",
    "validity",
    "raster",
    "path",
    "cost",
    "encoding",
    "termination",
    "optim",
    "smoothing",
    "planner",
    "io",
    "scenario",
];

fn rank(module: &str) -> Option<usize> {
    ORDER.iter().position(|m| *m == module)
}

fn visit(dir: &std::path::Path, out: &mut Vec<std::path::PathBuf>) {
    for e in std::fs::read_dir(dir).unwrap() {
        let p = e.unwrap().path();
        if p.is_dir() {
            visit(&p, out);
        } else if p.extension().is_some_and(|x| x == "rs") {
            out.push(p);
        }
    }
}

#[test]
fn no_module_uses_a_layer_above_it() {
    let src = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("src");
    let mut files = Vec::new();
    visit(&src, &mut files);
    let mut checked = 0;
    let mut wrong = Vec::new();
    for f in files {
        let rel = f.strip_prefix(&src).unwrap();
        let first = rel.components().next().unwrap().as_os_str().to_string_lossy().trim_end_matches(".rs").to_string();
        if first == "lib"
            || rel.file_name().is_some_and(|n| n == "tests.rs")
            || rel.components().any(|c| c.as_os_str() == "tests")
        {
            continue;
        }
        let own = rank(&first).unwrap_or_else(|| panic!("{first} is not in ORDER: add it where it belongs"));
        let text = std::fs::read_to_string(&f).unwrap();
        // Test modules may use anything.
        let code = text.split("#[cfg(test)]").next().unwrap();
        for (i, line) in code.lines().enumerate() {
            for part in line.split("crate::").skip(1) {
                let used: String = part.chars().take_while(|c| c.is_ascii_alphanumeric() || *c == '_').collect();
                if let Some(r) = rank(&used) {
                    checked += 1;
                    if r > own {
                        wrong.push(format!("{}:{}: {first} uses {used}", rel.display(), i + 1));
                    }
                }
            }
        }
    }
    assert!(checked > 100, "only {checked} imports seen");
    assert!(wrong.is_empty(), "upward imports:\n{}", wrong.join("\n"));
}
