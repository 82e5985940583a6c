//! `oscsim run --signals FILE.csv`: the traffic signal states of every frame, on the engine's
//! signal-controller fixture (crates/engine/tests/files/signals/controllers.xosc: controller A
//! drives signal S1 through go 8 s / attention 2 s / stop 10 s from t = 0; B drives S2 with a
//! 3 s delay to A, so S2 is red at t = 0 and green from 3 s).

use std::path::Path;

#[test]
fn the_signals_csv_has_one_row_per_signal_per_frame() {
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join("cli_signals");
    std::fs::create_dir_all(&dir).unwrap();
    let csv = dir.join("signals.csv");
    let scenario = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../engine/tests/files/signals/controllers.xosc");
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_oscsim"))
        .args(["run", scenario.to_str().unwrap(), "--quiet", "--signals"])
        .arg(&csv)
        .output()
        .unwrap();
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let text = std::fs::read_to_string(&csv).unwrap();
    let lines: Vec<&str> = text.lines().collect();
    assert_eq!(lines[0], "time,signal,state");
    // 45 s at 0.05 s: frames 0 … 900, two signals each.
    assert_eq!(lines.len(), 1 + 901 * 2);
    let at =
        |t: &str| -> Vec<&str> { lines.iter().filter(|l| l.starts_with(t)).copied().collect() };
    assert_eq!(at("0.000,"), ["0.000,S1,off;off;on", "0.000,S2,on;off;off"]);
    assert_eq!(at("7.950,"), ["7.950,S1,off;off;on", "7.950,S2,off;off;on"]);
    assert_eq!(at("8.000,"), ["8.000,S1,off;on;off", "8.000,S2,off;off;on"]);
    assert_eq!(
        at("10.000,"),
        ["10.000,S1,on;off;off", "10.000,S2,off;off;on"]
    );
}
