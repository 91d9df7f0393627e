//! The page: plotly.js, the viewer's script and style, and the scene, all inline.
//!
//! Nothing is linked: no `<script src>`, no stylesheet, no font or image from the network, so
//! the file opens offline from a disk or an e-mail attachment and makes no request (the
//! browser test checks). The scene goes in a `<script type="application/json">` element with
//! every `<` escaped, so no string in it (a scenario's description, a violation message) can
//! close the element or inject markup.

use crate::{scene::scene_json, Stopped, ViewInput};

/// The vendored plotly.js bundle and its version (see `vendor/plotly.js-gl3d-dist-min/README.md`).
pub const PLOTLY_VERSION: &str = "4.1.1";
const PLOTLY: &str = include_str!("../vendor/plotly.js-gl3d-dist-min/plotly-gl3d.min.js");
const VIEWER_JS: &str = include_str!("../assets/viewer.js");
const VIEWER_CSS: &str = include_str!("../assets/viewer.css");
const PAGE: &str = include_str!("../assets/page.html");

/// The HTML of the view (`Err(Stopped)` when `stop` said so while it was being built).
pub fn render_view(input: &ViewInput<'_>, stop: &dyn Fn() -> bool) -> Result<String, Stopped> {
    let scene = scene_json(input, stop)?;
    let data = serde_json::to_string(&scene).expect("a scene of numbers and strings");
    Ok(page(&input.title, &data))
}

/// The page around a scene given as JSON text.
pub fn page(title: &str, scene_json: &str) -> String {
    // `<` never appears raw inside the data element: JSON allows \u003c for it.
    let data = scene_json.replace('<', "\\u003c");
    let plotly = PLOTLY.replace("</script", "<\\/script");
    fill(
        PAGE,
        &[
            ("TITLE", &escape_html(title)),
            ("CSS", VIEWER_CSS),
            ("PLOTLY_VERSION", PLOTLY_VERSION),
            ("SCENE", &data),
            ("VIEWER", VIEWER_JS),
            ("PLOTLY", &plotly),
        ],
    )
}

/// The template with each `{{KEY}}` replaced, in one pass: text put in is never searched again
/// (a scene string that reads "{{VIEWER}}" stays as it is).
fn fill(template: &str, values: &[(&str, &str)]) -> String {
    let mut out = String::with_capacity(template.len() + values.iter().map(|v| v.1.len()).sum::<usize>());
    let mut rest = template;
    while let Some(open) = rest.find("{{") {
        out.push_str(&rest[..open]);
        let after = &rest[open + 2..];
        match after.find("}}").map(|close| (&after[..close], close)) {
            Some((key, close)) if values.iter().any(|v| v.0 == key) => {
                out.push_str(values.iter().find(|v| v.0 == key).map_or("", |v| v.1));
                rest = &after[close + 2..];
            }
            _ => {
                out.push_str("{{");
                rest = after;
            }
        }
    }
    out.push_str(rest);
    out
}

fn escape_html(s: &str) -> String {
    s.replace('&', "&amp;").replace('<', "&lt;").replace('>', "&gt;").replace('"', "&quot;")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_vendored_bundle_is_the_version_named() {
        assert!(PLOTLY[..200].contains(&format!("plotly.js (gl3d - minified) v{PLOTLY_VERSION}")));
    }

    #[test]
    fn the_page_links_nothing_and_escapes_the_data() {
        let html = page("a <b> & c", r#"{"subtitle":"</script><script>alert(1)</script>"}"#);
        let lower = html.to_lowercase();
        assert!(!lower.contains("<script src"), "a script is linked");
        assert!(!lower.contains("<link"), "a stylesheet is linked");
        assert!(!lower.contains("@import"), "a stylesheet is imported");
        assert!(lower.contains("<title>a &lt;b&gt; &amp; c</title>"));
        // The data cannot close its element.
        assert!(!html.contains("</script><script>alert(1)"));
        assert!(html.contains("\\u003c/script>\\u003cscript>alert(1)"));
        // Three inline scripts and the data: plotly, the viewer, the scene.
        assert_eq!(lower.matches("<script").count(), 3);
    }

    #[test]
    fn placeholders_are_filled_once() {
        assert_eq!(fill("a{{X}}b{{Y}}c{{Z}}", &[("X", "{{Y}}"), ("Y", "2")]), "a{{Y}}b2c{{Z}}");
    }
}
