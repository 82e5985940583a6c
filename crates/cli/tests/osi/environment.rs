//! `oscsim run --osi` and EnvironmentAction (OpenSCENARIO 1.3 XSD `Environment`): the
//! environment in force in `GroundTruth.environmental_conditions` (OSI 3.8
//! osi_environment.proto), mapped by `osi::environment` (docs/osi.md "Environment").
//!
//! `tests/files/osi_environment.xosc`: no environment until the step at 0.5 s, "morning" from
//! there, "storm" (weather only) from 1 s. An action of the step at T shapes the frames after T.
//! Expected, by hand from the scenario text and OSI's band tables (osi_environment.proto,
//! intervals [lower, upper[):
//! - t ≤ 0.5 s: no environmental_conditions.
//! - 0.5 < t ≤ 1 s ("morning"): dateTime 2026-11-26T08:00:00+01:00 = 07:00:00Z = 20 783 days ·
//!   86 400 s + 7 · 3600 s = 1 795 676 400 s since the epoch (Python
//!   `datetime(2026, 11, 26, 8, tzinfo=timezone(timedelta(hours=1))).timestamp()` agrees),
//!   running from 0.5 s: unix_timestamp = 1 795 676 400 + floor(t − 0.5), seconds since local
//!   midnight = 8 · 3600 + floor(t − 0.5) = 28 800 + …; 101325 Pa, 283.15 K; three oktas;
//!   sun azimuth π/2 clockwise (east) → OSI counterclockwise 2π − π/2 = 3π/2 (OSI: "3/2 pi:
//!   east"), elevation 0.2, 5000 lx → ambient LEVEL8 ([1000, 10000[ lx); fog 150 m → THICK
//!   ([50, 200[ m); rain 1 mm/h → LIGHT ([0.5, 1.9[ mm/h); wind blowing to heading 0 (+x,
//!   east), so from the west: OSI origin_direction π/2 ("+pi/2: west"), 5 m/s.
//! - t > 1 s ("storm"): the clock runs on (at 2 s: 1 795 676 401, 28 801); 99000 Pa, 270 K;
//!   nineOktas → SKY_OBSCURED; sun azimuth 4 → 2π − 4 = 2.283185307179586, elevation −0.1,
//!   0.5 lx → LEVEL2 ([0.01, 1[ lx); fog 40 m → DENSE ([0, 50[ m); snow 10 mm/h → HEAVY
//!   ([8.1, 34[ mm/h); wind blowing to heading π (−x), from the east: 3π/2, 20 m/s.

use crate::osi_common;

use std::f64::consts::PI;
use std::path::Path;

use osi::osi3::environmental_conditions::cloud_layer::FractionalCloudCover as Okta;
use osi::osi3::environmental_conditions::{
    AmbientIllumination, CloudLayer, Fog, Precipitation, Sun, TimeOfDay, Wind,
};
use osi::osi3::{EnvironmentalConditions, GroundTruth};
use osi_common::traced_run;

/// Angles and copied values: closed forms evaluated in f64.
const ANGLE: f64 = 1e-12;
/// 1 795 676 400 s: 2026-11-26T07:00:00Z (module doc).
const MORNING_UTC: i64 = 1_795_676_400;

fn seconds(gt: &GroundTruth) -> f64 {
    let ts = gt.timestamp.expect("every frame has a timestamp");
    ts.seconds.unwrap_or(0) as f64 + f64::from(ts.nanos.unwrap_or(0)) * 1e-9
}

/// Asserts the sun's azimuth and elevation and the wind's origin direction of `found` at `ANGLE`.
fn assert_angles(found: &EnvironmentalConditions, azimuth: f64, elevation: f64, wind: f64, t: f64) {
    let sun = found.sun.expect("sun set");
    let w = found.wind.expect("wind set");
    for (what, f, e) in [
        ("sun azimuth", sun.azimuth, azimuth),
        ("sun elevation", sun.elevation, elevation),
        ("wind origin_direction", w.origin_direction, wind),
    ] {
        let f = f.unwrap_or(f64::NAN);
        assert!(
            (f - e).abs() < ANGLE,
            "{what} at t = {t}: {f}, expected {e}"
        );
    }
}

#[test]
fn environment_actions_reach_the_environmental_conditions() {
    let scenario = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/files/osi_environment.xosc");
    let (trace, _) = traced_run("osi_environment", &scenario, 2.0);
    assert_eq!(trace.len(), 41, "frames 0 to 2 s");
    let slack = 1e-6;
    let mut seen = [0; 3];
    for gt in &trace {
        let t = seconds(gt);
        let found = gt.environmental_conditions.as_ref();
        if t <= 0.5 + slack {
            assert_eq!(found, None, "no environment yet at t = {t}");
            seen[0] += 1;
            continue;
        }
        let found = found.unwrap_or_else(|| panic!("environment at t = {t}"));
        let elapsed = (t - 0.5 + slack).floor();
        let clock = (
            Some(MORNING_UTC + elapsed as i64),
            Some(TimeOfDay {
                seconds_since_midnight: Some(28_800 + elapsed as u32),
            }),
        );
        assert_eq!(
            (found.unix_timestamp, found.time_of_day),
            clock,
            "clock at t = {t}"
        );
        // Everything but the angles, compared whole (angles below at ANGLE).
        let angle_free = |c: &EnvironmentalConditions| EnvironmentalConditions {
            sun: c.sun.map(|s| Sun {
                azimuth: None,
                elevation: None,
                ..s
            }),
            wind: c.wind.map(|w| Wind {
                origin_direction: None,
                ..w
            }),
            ..c.clone()
        };
        let expected = if t <= 1.0 + slack {
            seen[1] += 1;
            assert_angles(found, 1.5 * PI, 0.2, 0.5 * PI, t);
            EnvironmentalConditions {
                ambient_illumination: Some(AmbientIllumination::Level8 as i32),
                atmospheric_pressure: Some(101_325.0),
                temperature: Some(283.15),
                precipitation: Some(Precipitation::Light as i32),
                fog: Some(Fog::Thick as i32),
                clouds: Some(CloudLayer {
                    fractional_cloud_cover: Some(Okta::ThreeOktas as i32),
                }),
                wind: Some(Wind {
                    origin_direction: None,
                    speed: Some(5.0),
                }),
                sun: Some(Sun {
                    azimuth: None,
                    elevation: None,
                    intensity: Some(5000.0),
                }),
                ..Default::default()
            }
        } else {
            seen[2] += 1;
            assert_angles(found, 2.0 * PI - 4.0, -0.1, 1.5 * PI, t);
            EnvironmentalConditions {
                ambient_illumination: Some(AmbientIllumination::Level2 as i32),
                atmospheric_pressure: Some(99_000.0),
                temperature: Some(270.0),
                precipitation: Some(Precipitation::Heavy as i32),
                fog: Some(Fog::Dense as i32),
                clouds: Some(CloudLayer {
                    fractional_cloud_cover: Some(Okta::SkyObscured as i32),
                }),
                wind: Some(Wind {
                    origin_direction: None,
                    speed: Some(20.0),
                }),
                sun: Some(Sun {
                    azimuth: None,
                    elevation: None,
                    intensity: Some(0.5),
                }),
                ..Default::default()
            }
        };
        let expected = EnvironmentalConditions {
            unix_timestamp: clock.0,
            time_of_day: clock.1,
            ..expected
        };
        assert_eq!(angle_free(found), expected, "conditions at t = {t}");
    }
    // 0 … 0.5 s, 0.55 … 1 s, 1.05 … 2 s at 0.05 s.
    assert_eq!(seen, [11, 10, 20]);
    // The last frame: 1.5 s after 0.5 s.
    let last = trace[40].environmental_conditions.as_ref().expect("set");
    assert_eq!(last.unix_timestamp, Some(MORNING_UTC + 1));
}
