//! A generated town-grid road network for the load and look-up benchmarks: `n × n` four-way
//! junctions (OpenDRIVE 1.8 §12 default junctions) joined by arterial roads, each junction
//! holding twelve one-lane connecting roads (right turn, straight on, left turn from each arm).
//!
//! The arterial roads are written the way survey-grade exports are: the reference line as a
//! run of short geometries (straight `paramPoly3` and `line` pieces), an elevation record per
//! piece, a lane section every 100 m with three driving lanes and a sidewalk each side,
//! road marks, objects and signals. Every geometry starts exactly where the previous one ends
//! and every link and lane link resolves, so the file loads without warnings (the benchmark
//! asserts it). Deterministic: the same `n` gives the same bytes.

use std::f64::consts::FRAC_PI_2;
use std::fmt::Write as _;

/// Length of an arterial road between two junctions (m).
const ROAD_LENGTH: f64 = 300.0;
/// Half the side of a junction's square (m): connecting roads run from one arm's mouth to
/// another's; turns are quarter arcs of this radius.
const HALF: f64 = 20.0;
/// Length of each plan-view geometry of an arterial road (m).
const PIECE: f64 = 2.5;
/// Distance between lane sections of an arterial road (m).
const SECTION: f64 = 100.0;
/// Distance between junction centres (m).
const PITCH: f64 = ROAD_LENGTH + 2.0 * HALF;

/// The id of junction (i, j).
fn junction_id(n: usize, i: usize, j: usize) -> usize {
    i * n + j
}

/// An arterial road: from the junction at `from` towards +x (`east`) or +y, of id `id`.
struct Arterial {
    id: usize,
    /// Start of the reference line.
    x0: f64,
    y0: f64,
    hdg: f64,
    /// Junction at s = 0 and at s = length.
    start_junction: usize,
    end_junction: usize,
}

/// How many bytes [`grid_network`] writes for `n` (within a few per cent): for picking `n`.
pub fn approx_bytes(n: usize) -> usize {
    let arterials = 2 * n * (n - 1);
    // Connecting roads: 12 per inner junction, 6 per edge junction, 2 per corner.
    let inner = n.saturating_sub(2);
    let connecting = inner * inner * 12 + 4 * inner * 6 + 4 * 2;
    arterials * 80_000 + connecting * 1_500
}

/// The smallest grid whose file is at least `bytes` long.
pub fn grid_for_bytes(bytes: usize) -> String {
    let mut n = 2;
    while approx_bytes(n) < bytes {
        n += 1;
    }
    grid_network(n)
}

/// The `.xodr` text of an `n × n` grid of junctions (n ≥ 2).
pub fn grid_network(n: usize) -> String {
    let mut out = String::with_capacity(approx_bytes(n) + 4096);
    out.push_str("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<OpenDRIVE>\n");
    out.push_str("  <header revMajor=\"1\" revMinor=\"8\" name=\"grid\" version=\"1\"/>\n");
    // Arterials: ids from 1; horizontal ones (towards +x) then vertical ones (towards +y).
    let mut arterials = Vec::new();
    for i in 0..n {
        for j in 0..n {
            let (cx, cy) = (i as f64 * PITCH, j as f64 * PITCH);
            if i + 1 < n {
                arterials.push(Arterial {
                    id: arterials.len() + 1,
                    x0: cx + HALF,
                    y0: cy,
                    hdg: 0.0,
                    start_junction: junction_id(n, i, j),
                    end_junction: junction_id(n, i + 1, j),
                });
            }
            if j + 1 < n {
                arterials.push(Arterial {
                    id: arterials.len() + 1,
                    x0: cx,
                    y0: cy + HALF,
                    hdg: FRAC_PI_2,
                    start_junction: junction_id(n, i, j),
                    end_junction: junction_id(n, i, j + 1),
                });
            }
        }
    }
    for a in &arterials {
        arterial(&mut out, a);
    }
    // Connecting roads and junctions.
    let mut next_id = arterials.len() + 1;
    let mut junctions = String::new();
    for i in 0..n {
        for j in 0..n {
            let jid = junction_id(n, i, j);
            // The arms of this junction: (road id, heading pointing out of the junction,
            // whether the road starts here).
            let arms: Vec<(usize, f64, bool)> = arterials
                .iter()
                .filter_map(|a| {
                    if a.start_junction == jid {
                        Some((a.id, a.hdg, true))
                    } else if a.end_junction == jid {
                        Some((a.id, a.hdg + std::f64::consts::PI, false))
                    } else {
                        None
                    }
                })
                .collect();
            let (cx, cy) = (i as f64 * PITCH, j as f64 * PITCH);
            let _ = writeln!(
                junctions,
                r#"  <junction id="{jid}" name="junction {i} {j}" type="default">"#
            );
            let mut conn = 0;
            for &(in_road, in_out_hdg, in_starts) in &arms {
                for &(out_road, out_hdg, out_starts) in &arms {
                    if out_road == in_road {
                        continue;
                    }
                    let id = next_id;
                    next_id += 1;
                    // Entering at the arm's mouth, heading into the junction.
                    let h0 = in_out_hdg + std::f64::consts::PI;
                    let (x0, y0) = (cx - HALF * h0.cos(), cy - HALF * h0.sin());
                    connecting_road(
                        &mut out,
                        id,
                        jid,
                        (x0, y0, h0),
                        out_hdg,
                        (in_road, in_starts),
                        (out_road, out_starts),
                    );
                    // Forward lanes (negative) leave the start of a road, backward lanes
                    // (positive) arrive at it (right-hand traffic).
                    let from = if in_starts { 1 } else { -1 };
                    let _ = writeln!(
                        junctions,
                        r#"    <connection id="{conn}" incomingRoad="{in_road}" connectingRoad="{id}" contactPoint="start"><laneLink from="{from}" to="-1"/></connection>"#
                    );
                    conn += 1;
                }
            }
            junctions.push_str("  </junction>\n");
        }
    }
    out.push_str(&junctions);
    out.push_str("</OpenDRIVE>\n");
    out
}

/// Writes one arterial road.
fn arterial(out: &mut String, a: &Arterial) {
    let (c, s) = (a.hdg.cos(), a.hdg.sin());
    let _ = writeln!(
        out,
        r#"  <road name="arterial {id}" length="{ROAD_LENGTH}" id="{id}" junction="-1" rule="RHT">
    <link>
      <predecessor elementType="junction" elementId="{sj}"/>
      <successor elementType="junction" elementId="{ej}"/>
    </link>
    <type s="0" type="town"><speed max="50" unit="km/h"/></type>
    <planView>"#,
        id = a.id,
        sj = a.start_junction,
        ej = a.end_junction
    );
    let pieces = (ROAD_LENGTH / PIECE) as usize;
    for k in 0..pieces {
        let s0 = k as f64 * PIECE;
        let (x, y) = (a.x0 + s0 * c, a.y0 + s0 * s);
        let curve = if k % 2 == 0 {
            r#"<paramPoly3 aU="0.0000000000000000e+00" bU="1.0000000000000000e+00" cU="0.0000000000000000e+00" dU="0.0000000000000000e+00" aV="0.0000000000000000e+00" bV="0.0000000000000000e+00" cV="0.0000000000000000e+00" dV="0.0000000000000000e+00" pRange="arcLength"/>"#
        } else {
            "<line/>"
        };
        let _ = writeln!(
            out,
            r#"      <geometry s="{s0:.16e}" x="{x:.16e}" y="{y:.16e}" hdg="{hdg:.16e}" length="{PIECE:.16e}">{curve}</geometry>"#,
            hdg = a.hdg
        );
    }
    out.push_str("    </planView>\n    <elevationProfile>\n");
    for k in 0..pieces {
        let s0 = k as f64 * PIECE;
        // A gentle wave: z = 2·sin(2π·s / length), written as cubics per piece.
        let w = std::f64::consts::TAU / ROAD_LENGTH;
        let (z, dz) = (2.0 * (w * s0).sin(), 2.0 * w * (w * s0).cos());
        let _ = writeln!(
            out,
            r#"      <elevation s="{s0:.16e}" a="{z:.16e}" b="{dz:.16e}" c="0.0000000000000000e+00" d="0.0000000000000000e+00"/>"#
        );
    }
    out.push_str("    </elevationProfile>\n    <lateralProfile>\n");
    out.push_str(r#"      <superelevation s="0.0000000000000000e+00" a="0.0000000000000000e+00" b="0.0000000000000000e+00" c="0.0000000000000000e+00" d="0.0000000000000000e+00"/>"#);
    out.push_str("\n    </lateralProfile>\n    <lanes>\n");
    out.push_str(r#"      <laneOffset s="0.0000000000000000e+00" a="0.0000000000000000e+00" b="0.0000000000000000e+00" c="0.0000000000000000e+00" d="0.0000000000000000e+00"/>"#);
    out.push('\n');
    let sections = (ROAD_LENGTH / SECTION) as usize;
    for k in 0..sections {
        let s0 = k as f64 * SECTION;
        let _ = writeln!(out, r#"      <laneSection s="{s0:.16e}">"#);
        out.push_str("        <left>\n");
        for id in (1..=4).rev() {
            lane(out, id, k, sections);
        }
        out.push_str("        </left>\n        <center>\n");
        out.push_str(r#"          <lane id="0" type="none" level="false"><roadMark sOffset="0.0000000000000000e+00" type="solid solid" weight="standard" color="yellow" material="standard" width="1.2000000000000000e-01" laneChange="none"/></lane>"#);
        out.push_str("\n        </center>\n        <right>\n");
        for id in 1..=4 {
            lane(out, -id, k, sections);
        }
        out.push_str("        </right>\n      </laneSection>\n");
    }
    out.push_str("    </lanes>\n    <objects>\n");
    for k in 0..10 {
        let _ = writeln!(
            out,
            r#"      <object id="{id}{k:02}" name="pole" type="pole" s="{s:.16e}" t="-1.2500000000000000e+01" zOffset="0.0000000000000000e+00" hdg="0.0000000000000000e+00" pitch="0.0000000000000000e+00" roll="0.0000000000000000e+00" orientation="none" height="4.0000000000000000e+00" radius="1.0000000000000001e-01"/>"#,
            id = a.id,
            s = 15.0 + 30.0 * k as f64
        );
    }
    out.push_str("    </objects>\n    <signals>\n");
    for (k, s) in [(0, 10.0), (1, ROAD_LENGTH - 10.0)] {
        let (t, orientation) = if k == 0 { (-12.0, "+") } else { (12.0, "-") };
        let _ = writeln!(
            out,
            r#"      <signal id="{id}9{k}" name="speed limit" s="{s:.16e}" t="{t:.16e}" zOffset="2.0000000000000000e+00" hOffset="0.0000000000000000e+00" orientation="{orientation}" dynamic="no" country="DE" type="274" subtype="120" value="50" unit="km/h" width="0.6" height="0.6"/>"#,
            id = a.id
        );
    }
    out.push_str("    </signals>\n  </road>\n");
}

/// Writes lane `id` of lane section `k` of `sections` (±1…±3 driving, ±4 sidewalk).
fn lane(out: &mut String, id: i32, k: usize, sections: usize) {
    let sidewalk = id.abs() == 4;
    let (kind, width) = if sidewalk {
        ("sidewalk", 2.0)
    } else {
        ("driving", 3.25)
    };
    let _ = write!(
        out,
        r#"          <lane id="{id}" type="{kind}" level="false"><link>"#
    );
    if k > 0 {
        let _ = write!(out, r#"<predecessor id="{id}"/>"#);
    }
    if k + 1 < sections {
        let _ = write!(out, r#"<successor id="{id}"/>"#);
    }
    let _ = write!(
        out,
        r#"</link><width sOffset="0.0000000000000000e+00" a="{width:.16e}" b="0.0000000000000000e+00" c="0.0000000000000000e+00" d="0.0000000000000000e+00"/>"#
    );
    let mark = if sidewalk || id.abs() == 3 {
        "solid"
    } else {
        "broken"
    };
    for m in 0..4 {
        let _ = write!(
            out,
            r#"<roadMark sOffset="{:.16e}" type="{mark}" weight="standard" color="standard" material="standard" width="1.2000000000000000e-01" laneChange="both"/>"#,
            25.0 * m as f64
        );
    }
    if sidewalk {
        out.push_str(r#"<height sOffset="0.0000000000000000e+00" inner="1.2000000000000000e-01" outer="1.2000000000000000e-01"/>"#);
    }
    out.push_str(r#"<speed sOffset="0.0000000000000000e+00" max="50" unit="km/h"/>"#);
    out.push_str("</lane>\n");
}

/// Writes a one-lane connecting road from `(x0, y0, h0)` into the junction, leaving towards
/// `out_hdg`: straight on (a line of 2·HALF), or a quarter arc of radius HALF left or right.
fn connecting_road(
    out: &mut String,
    id: usize,
    junction: usize,
    (x0, y0, h0): (f64, f64, f64),
    out_hdg: f64,
    (in_road, in_starts): (usize, bool),
    (out_road, out_starts): (usize, bool),
) {
    let turn = opendrive::normalize_angle(out_hdg - h0);
    let (length, curve) = if turn.abs() < 1e-9 {
        (2.0 * HALF, "<line/>".to_string())
    } else {
        let k = turn.signum() / HALF;
        (HALF * FRAC_PI_2, format!(r#"<arc curvature="{k:.16e}"/>"#))
    };
    let in_contact = if in_starts { "start" } else { "end" };
    let out_contact = if out_starts { "start" } else { "end" };
    // The lane of the incoming road that drives into the junction, and of the outgoing one
    // that drives away from it.
    let in_lane = if in_starts { 1 } else { -1 };
    let out_lane = if out_starts { -1 } else { 1 };
    let _ = writeln!(
        out,
        r#"  <road name="connection {id}" length="{length:.16e}" id="{id}" junction="{junction}" rule="RHT">
    <link>
      <predecessor elementType="road" elementId="{in_road}" contactPoint="{in_contact}"/>
      <successor elementType="road" elementId="{out_road}" contactPoint="{out_contact}"/>
    </link>
    <type s="0" type="town"><speed max="30" unit="km/h"/></type>
    <planView>
      <geometry s="0.0000000000000000e+00" x="{x0:.16e}" y="{y0:.16e}" hdg="{h0:.16e}" length="{length:.16e}">{curve}</geometry>
    </planView>
    <elevationProfile><elevation s="0" a="0" b="0" c="0" d="0"/></elevationProfile>
    <lanes>
      <laneSection s="0.0000000000000000e+00">
        <center><lane id="0" type="none" level="false"/></center>
        <right>
          <lane id="-1" type="driving" level="false"><link><predecessor id="{in_lane}"/><successor id="{out_lane}"/></link><width sOffset="0.0000000000000000e+00" a="3.25" b="0" c="0" d="0"/><roadMark sOffset="0" type="none"/></lane>
        </right>
      </laneSection>
    </lanes>
  </road>"#
    );
}
