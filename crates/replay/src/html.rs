//! The replay page: one self-contained HTML file. Markup, CSS (`web/replay.css`) and the
//! scripts (`web/*.js`, concatenated in one function scope) are inlined with the run's data
//! container (`page_data`); a Content-Security-Policy forbids every network request, so the
//! page works offline and cannot leak what it shows.

use std::path::Path;

use crate::error::{Error, Result};
use crate::measures;
use crate::page_data;
use crate::road::RoadDrawing;
use crate::run::Run;

/// The scripts, in load order.
const SCRIPTS: [&str; 8] = [
    include_str!("web/decode.js"),
    include_str!("web/camera.js"),
    include_str!("web/road_draw.js"),
    include_str!("web/entities.js"),
    include_str!("web/timeline.js"),
    include_str!("web/charts.js"),
    include_str!("web/panel.js"),
    include_str!("web/app.js"),
];
const CSS: &str = include_str!("web/replay.css");
const BODY: &str = include_str!("web/body.html");

/// The policy: inline script and style only; images from data: URLs (none are used yet).
const POLICY: &str = "default-src 'none'; script-src 'unsafe-inline'; \
                      style-src 'unsafe-inline'; img-src data: blob:";

/// `text` with the HTML special characters escaped.
fn escape(text: &str) -> String {
    text.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
        .replace('"', "&quot;")
}

/// The replay page of `run`.
pub fn render(run: &Run) -> String {
    let roads = run
        .network
        .as_ref()
        .map(|n| RoadDrawing::new(n))
        .unwrap_or_default();
    let series = measures::series(run);
    let data = page_data::build(run, &roads, &series);
    let mut page = String::with_capacity(data.len() + 100_000);
    page.push_str("<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n");
    page.push_str(&format!(
        "<meta http-equiv=\"Content-Security-Policy\" content=\"{POLICY}\">\n"
    ));
    page.push_str("<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n");
    page.push_str(&format!(
        "<meta name=\"generator\" content=\"oscsim {}\">\n",
        env!("CARGO_PKG_VERSION")
    ));
    page.push_str(&format!(
        "<title>{} — oscsim replay</title>\n",
        escape(&run.title)
    ));
    page.push_str("<style>\n");
    page.push_str(CSS);
    page.push_str("</style>\n</head>\n<body>\n");
    page.push_str(BODY);
    // Base64 holds no '<', so the data cannot end its element early.
    page.push_str("<script id=\"oscsim-data\" type=\"application/octet-stream\">");
    page.push_str(&data);
    page.push_str("</script>\n<script>\n\"use strict\";\n(function () {\n");
    for script in SCRIPTS {
        page.push_str(script);
        page.push('\n');
    }
    page.push_str("})();\n</script>\n</body>\n</html>\n");
    page
}

/// Writes the replay page of `run` to `path` (creating its folder).
pub fn write(run: &Run, path: &Path) -> Result<()> {
    if let Some(dir) = path.parent().filter(|d| !d.as_os_str().is_empty()) {
        std::fs::create_dir_all(dir)
            .map_err(|e| Error::io("cannot create the folder of", path, e))?;
    }
    std::fs::write(path, render(run)).map_err(|e| Error::io("cannot write", path, e))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn no_script_can_close_its_element_or_reach_the_network() {
        for script in SCRIPTS {
            assert!(!script.to_ascii_lowercase().contains("</script"));
            for word in [
                "http:",
                "https:",
                "fetch(",
                "XMLHttpRequest",
                "import(",
                "WebSocket",
            ] {
                assert!(!script.contains(word), "a script uses {word}");
            }
        }
        assert!(!CSS.contains("url(") && !CSS.contains("@import"));
    }

    #[test]
    fn titles_are_escaped() {
        assert_eq!(escape("a<b>&\"c\""), "a&lt;b&gt;&amp;&quot;c&quot;");
    }
}
