//! The replay page of the bundled cut-in (`oscsim run --csv --events`, then `oscsim view`)
//! opened in headless Chromium with the network refused: it loads without a console error or a
//! blocked request, the slider set to t = 5 s draws Ego where the CSV row puts it, the road is
//! drawn where OpenDRIVE puts it (a centre-line point of highway.xodr worked out by hand), the
//! arrow key steps a frame, `]` speeds up, a click on the timeline jumps to the event under it,
//! and a screenshot is written to `target/tmp/replay/cut_in_t5.png`.
//!
//! Needs Debian's `chromium` (`.ci/run` installs it); without a browser the test says so and
//! passes without checking, unless `OSCSIM_REQUIRE_BROWSER` is set (as `.ci/run` does).
//! `OSCSIM_CHROMIUM` names another binary.

use std::path::{Path, PathBuf};
use std::process::Command;

use serde_json::Value;

/// The browser, if one is installed.
fn chromium() -> Option<PathBuf> {
    if let Some(p) = std::env::var_os("OSCSIM_CHROMIUM") {
        return Some(PathBuf::from(p));
    }
    [
        "/usr/bin/chromium",
        "/usr/bin/chromium-browser",
        "/usr/bin/google-chrome",
    ]
    .into_iter()
    .map(PathBuf::from)
    .find(|p| p.exists())
}

/// A fresh folder for this test's files.
fn scratch() -> PathBuf {
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join("replay");
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap_or_else(|e| panic!("{}: {e}", dir.display()));
    dir
}

/// Runs `oscsim` with `args`; panics unless it succeeds.
fn oscsim(args: &[&str]) {
    let out = Command::new(env!("CARGO_BIN_EXE_oscsim"))
        .args(args)
        .output()
        .unwrap_or_else(|e| panic!("cannot start oscsim: {e}"));
    assert!(
        out.status.success(),
        "oscsim {args:?}: {}",
        String::from_utf8_lossy(&out.stderr)
    );
}

fn repo(path: &str) -> String {
    format!("{}/../../{path}", env!("CARGO_MANIFEST_DIR"))
}

/// Scripts put into a copy of the page: the first (in `<head>`) collects errors, console
/// errors and Content-Security-Policy violations (a blocked request); the second checks the
/// road, sets the slider to 5 s like a user, waits until the page's own loop has drawn that
/// time (polling on timers: headless Chromium's virtual clock does not promise animation
/// frames to a waiting script), reads the state and the pixels, presses keys, clicks the
/// timeline, and writes it all as JSON into `<pre id="test-result">`.
const CATCH: &str = r#"<script>window.__errors=[];addEventListener('error',e=>__errors.push('error: '+e.message));addEventListener('unhandledrejection',e=>__errors.push('rejection: '+e.reason));document.addEventListener('securitypolicyviolation',e=>__errors.push('blocked: '+e.violatedDirective+' '+e.blockedURI));const __ce=console.error;console.error=(...a)=>{__errors.push('console: '+a.join(' '));__ce.apply(console,a);};</script>"#;
const DRIVE: &str = r#"<script>(async function(){const out=document.createElement('pre');out.id='test-result';
const sleep=(ms)=>new Promise(r=>setTimeout(r,ms));
try{const R=window.oscsimReplay;await R.ready;
const drawn=async(t)=>{for(let i=0;i<100&&R.state().drawnTime!==t;i++)await sleep(20);if(R.state().drawnTime!==t)throw new Error('time '+t+' was not drawn');};
const road={};for(const [name,x,y] of ROAD_POINTS){R.setView(x,y,40);const p=R.worldToScreen(x,y);road[name]=R.pixel(p[0],p[1]);}
R.fit();
const s=document.getElementById('slider');s.value='5';s.dispatchEvent(new Event('input',{bubbles:true}));
await drawn(5);
const st=R.state();const px={};for(const e of st.entities){if(e.present)px[e.name]=R.pixel(e.center[0],e.center[1]);}
const key=(k)=>document.dispatchEvent(new KeyboardEvent('keydown',{key:k,bubbles:true}));
key('ArrowRight');const afterRight=R.state().time;key(']');const rate=R.state().rate;
const tl=document.getElementById('timeline');const box=tl.getBoundingClientRect();
const x=64+(5.65/10)*(tl.clientWidth-68);
tl.dispatchEvent(new MouseEvent('click',{clientX:box.left+x+2,clientY:box.top+20,bubbles:true}));
const afterClick=R.state().time;
s.value='5';s.dispatchEvent(new Event('input',{bubbles:true}));await drawn(5);
out.textContent=JSON.stringify({state:st,pixels:px,road,afterRight,rate,afterClick,errors:__errors});
}catch(e){out.textContent=JSON.stringify({failure:String(e),errors:__errors});}
document.body.appendChild(out);})();</script>"#;

/// Hand-computed points of highway.xodr road 0 at s = 150, the start of its arc geometry
/// (`<geometry s="150.0" x="148.28439010333318" y="-21.101602806253027"
/// hdg="-0.07424999999999998">`), lane section s = 50 (lanes ±1, ±2 of width 3, laneOffset 0).
/// A point at t lies at (x − t·sin hdg, y + t·cos hdg), with sin hdg = −0.0741818,
/// cos hdg = 0.9972448:
/// - centre line (t = 0, solid mark 0.2 m): (148.284390, −21.101603);
/// - centre of lane −1 (t = −1.5, driving): (148.284390 − 0.111273, −21.101603 − 1.495867)
///   = (148.173117, −22.597470);
/// - outside the road (t = 7, past lane 2's outer border at t = 6): (148.284390 + 0.519273,
///   −21.101603 + 6.980714) = (148.803663, −14.120889).
const ROAD_POINTS: &str = "[['centre',148.284390,-21.101603],['lane',148.173117,-22.597470],['outside',148.803663,-14.120889]]";

/// Runs the browser on `page` with the network refused; `extra` picks the output.
fn browse(browser: &Path, dir: &Path, page: &Path, extra: &[&str]) -> std::process::Output {
    let profile = tempdir(dir, extra.first().copied().unwrap_or("run"));
    Command::new(browser)
        .args([
            "--headless",
            "--no-sandbox",
            "--disable-gpu",
            "--disable-quic",
            "--no-first-run",
            "--disable-background-networking",
            "--disable-component-update",
            "--disable-sync",
            "--hide-scrollbars",
            "--window-size=1400,900",
            "--virtual-time-budget=10000",
            // No network: every host resolves to nothing and every proxy connection is refused.
            "--host-resolver-rules=MAP * ~NOTFOUND",
            "--proxy-server=127.0.0.1:9",
        ])
        .arg(format!("--user-data-dir={}", profile.display()))
        .args(extra)
        .arg(format!("file://{}", page.display()))
        .output()
        .unwrap_or_else(|e| panic!("cannot start {}: {e}", browser.display()))
}

/// A fresh browser profile folder under `dir`.
fn tempdir(dir: &Path, name: &str) -> PathBuf {
    let p = dir.join(format!(
        "profile-{}",
        name.trim_start_matches('-').replace(['=', '/'], "_")
    ));
    let _ = std::fs::remove_dir_all(&p);
    p
}

/// The CSV row of `name` at `time` (x, y).
fn csv_xy(csv: &str, time: &str, name: &str) -> (f64, f64) {
    let row = csv
        .lines()
        .find(|l| l.starts_with(&format!("{time},")) && l.split(',').nth(2) == Some(name))
        .unwrap_or_else(|| panic!("no CSV row for {name} at {time}"));
    let f: Vec<&str> = row.split(',').collect();
    (f[3].parse().expect("x"), f[4].parse().expect("y"))
}

#[test]
fn cut_in_replay_draws_ego_where_the_csv_puts_it() {
    let dir = scratch();
    let (csv, events, html) = (
        dir.join("cut_in.csv"),
        dir.join("cut_in.jsonl"),
        dir.join("cut_in.html"),
    );
    let p = |p: &Path| p.to_string_lossy().into_owned();
    oscsim(&[
        "run",
        &repo("examples/scenarios/cut_in_highway.xosc"),
        "--quiet",
        "--csv",
        &p(&csv),
        "--events",
        &p(&events),
    ]);
    oscsim(&["view", &p(&csv), "-o", &p(&html)]);
    let page = std::fs::read_to_string(&html).expect("the page was written");
    // The bundled scenario's page stays small and names no network resource.
    assert!(page.len() < 2_000_000, "{} bytes", page.len());
    assert!(
        !page.contains("http:") && !page.contains("https:"),
        "the page names a URL"
    );
    assert!(page.contains("Content-Security-Policy\" content=\"default-src 'none'"));

    let Some(browser) = chromium() else {
        assert!(
            std::env::var_os("OSCSIM_REQUIRE_BROWSER").is_none(),
            "OSCSIM_REQUIRE_BROWSER is set but no Chromium was found"
        );
        eprintln!("skipped: no Chromium (/usr/bin/chromium; `apt-get install -y chromium`, or set OSCSIM_CHROMIUM)");
        return;
    };
    let driven = page
        .replacen(
            "<meta name=\"viewport\"",
            &format!("{CATCH}<meta name=\"viewport\""),
            1,
        )
        .replacen(
            "</body>",
            &format!("{}</body>", DRIVE.replace("ROAD_POINTS", ROAD_POINTS)),
            1,
        );
    let test_page = dir.join("cut_in_driven.html");
    std::fs::write(&test_page, driven).expect("write the driven page");

    let out = browse(&browser, &dir, &test_page, &["--dump-dom"]);
    let dom = String::from_utf8_lossy(&out.stdout);
    let json = dom
        .split("<pre id=\"test-result\">")
        .nth(1)
        .and_then(|r| r.split("</pre>").next())
        .unwrap_or_else(|| {
            panic!(
                "no test result in the page; browser said: {}",
                String::from_utf8_lossy(&out.stderr)
            )
        });
    let json = json
        .replace("&quot;", "\"")
        .replace("&lt;", "<")
        .replace("&gt;", ">")
        .replace("&amp;", "&");
    let r: Value = serde_json::from_str(&json).unwrap_or_else(|e| panic!("{e}: {json}"));
    assert_eq!(r.get("failure"), None, "{json}");
    assert_eq!(
        r["errors"],
        Value::Array(vec![]),
        "console errors or blocked requests"
    );

    // Ego at t = 5 s: the CSV row, to the page's quantisation (1 mm, rounded: 0.5 mm).
    let state = &r["state"];
    assert_eq!(state["time"].as_f64(), Some(5.0));
    let csv_text = std::fs::read_to_string(&csv).expect("the CSV");
    let (x, y) = csv_xy(&csv_text, "5.000", "Ego");
    let ego = state["entities"]
        .as_array()
        .and_then(|a| a.iter().find(|e| e["name"] == "Ego"))
        .expect("Ego is in the state");
    let num = |v: &Value| v.as_f64().expect("a number");
    const POSITION_TOLERANCE: f64 = 0.5e-3 + 1e-9;
    assert!(
        (num(&ego["x"]) - x).abs() <= POSITION_TOLERANCE,
        "x {} vs CSV {x}",
        ego["x"]
    );
    assert!(
        (num(&ego["y"]) - y).abs() <= POSITION_TOLERANCE,
        "y {} vs CSV {y}",
        ego["y"]
    );
    // Where it is drawn: the camera's closed form, screen = ((x − cx)·scale + w/2,
    // h/2 − (y − cy)·scale), from the CSV values (0.01 px: the 0.5 mm above at ~2 px/m).
    let cam = &state["camera"];
    let (cx, cy, scale) = (num(&cam["cx"]), num(&cam["cy"]), num(&cam["scale"]));
    let (w, h) = (num(&cam["width"]), num(&cam["height"]));
    let sx = (x - cx) * scale + w / 2.0;
    let sy = h / 2.0 - (y - cy) * scale;
    assert!(
        (num(&ego["screen"][0]) - sx).abs() < 0.01 && (num(&ego["screen"][1]) - sy).abs() < 0.01,
        "{ego}"
    );
    // And the canvas holds Ego's colour (white, Properties color) at its box centre, the
    // OverTaker's (red) at its own.
    assert_eq!(r["pixels"]["Ego"], serde_json::json!([255, 255, 255, 255]));
    assert_eq!(
        r["pixels"]["OverTaker"],
        serde_json::json!([255, 0, 0, 255])
    );
    // The road as OpenDRIVE puts it: mark colour on the centre line, the driving-lane colour
    // in lane −1, the ground outside (colours of web/road_draw.js and app.js).
    assert_eq!(
        r["road"]["centre"],
        serde_json::json!([244, 244, 244, 255]),
        "{}",
        r["road"]
    );
    assert_eq!(
        r["road"]["lane"],
        serde_json::json!([107, 111, 117, 255]),
        "{}",
        r["road"]
    );
    assert_eq!(
        r["road"]["outside"],
        serde_json::json!([93, 122, 79, 255]),
        "{}",
        r["road"]
    );

    // Keys: → steps one frame (0.05 s), ] doubles the playback speed (1× → 2×).
    assert_eq!(r["afterRight"].as_f64(), Some(5.05));
    assert_eq!(r["rate"].as_f64(), Some(2.0));
    // A click 2 px right of the timeline's mark of CutInEvent's start (5.650 s, the event log)
    // jumps to that record's time (the x of t is 64 + t/10 · (width − 68), timeline.js).
    assert_eq!(r["afterClick"].as_f64(), Some(5.65));

    // The screenshot artifact: the same page at t = 5 s.
    let shot = dir.join("cut_in_t5.png");
    let out = browse(
        &browser,
        &dir,
        &test_page,
        &[&format!("--screenshot={}", shot.display())],
    );
    let png = std::fs::read(&shot).unwrap_or_else(|e| {
        panic!(
            "no screenshot ({e}); browser said: {}",
            String::from_utf8_lossy(&out.stderr)
        )
    });
    assert!(
        png.starts_with(b"\x89PNG") && png.len() > 20_000,
        "{} bytes",
        png.len()
    );
    eprintln!("screenshot: {}", shot.display());
}
