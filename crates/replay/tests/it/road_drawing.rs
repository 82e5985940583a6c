//! The road drawing against OpenDRIVE by hand: highway.xodr road 0 at s = 150, the start of
//! its arc (`<geometry s="150.0" x="148.28439010333318" y="-21.101602806253027"
//! hdg="-0.07424999999999998">`), lane section s = 50 (lanes 2 … −4).

use std::path::Path;

use opendrive::{RoadMarkType, RoadNetwork};
use replay::road::{RoadDrawing, SAG_TOLERANCE};

/// Agreement with the hand computation (m): the geometry is evaluated exactly.
const TOLERANCE: f64 = 1e-6;

fn highway() -> RoadDrawing {
    let path = Path::new(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../../examples/roads/highway.xodr"
    ));
    RoadDrawing::new(&RoadNetwork::from_file(path).unwrap_or_else(|e| panic!("{e}")))
}

#[test]
fn lane_borders_lie_where_the_geometry_puts_them() {
    let d = highway();
    let road = d.roads.iter().find(|r| r.id == "0").expect("road 0");
    // Sections of road 0 start at s = 0, 50, 175: the second holds s = 150.
    let sec = &road.sections[1];
    let k = sec
        .s
        .iter()
        .position(|&s| (s - 150.0).abs() < 1e-9)
        .expect("s = 150 is a breakpoint (a geometry start)");
    // Borders: the outer borders of lanes 2, 1, the centre line, lanes −1, −2, −3 (all 3 m
    // wide) and −4, whose width is the cubic 0.000576·ds² − 3.072e-6·ds³: at ds = 100 (s = 150)
    // 5.76 − 3.072 = 2.688 m, so t = 6, 3, 0, −3, −6, −9, −11.688.
    assert_eq!(sec.borders.len(), 7);
    // A point at t: (x − t·sin hdg, y + t·cos hdg) with sin hdg = −0.0741817947 and
    // cos hdg = 0.9972447349 (hdg = −0.07425).
    let expect = [
        (6.0, 148.729480871, -15.118134397),
        (3.0, 148.506935487, -18.109868601),
        (0.0, 148.284390103, -21.101602806),
        (-3.0, 148.061844719, -24.093337011),
        (-6.0, 147.839299335, -27.085071216),
        (-9.0, 147.616753951, -30.076805421),
        (-11.688, 147.417353287, -32.757399268),
    ];
    for (b, (t, x, y)) in expect.into_iter().enumerate() {
        let p = sec.borders[b][k];
        assert!(
            (p[0] - x).abs() < TOLERANCE && (p[1] - y).abs() < TOLERANCE,
            "t = {t}: {p:?} vs ({x}, {y})"
        );
    }
    // Lane −1 lies between the centre line and its outer border, lane 2 outside lane 1.
    let lane = |id| sec.lanes.iter().find(|l| l.id == id).expect("lane");
    assert_eq!((lane(-1).inner, lane(-1).outer), (2, 3));
    assert_eq!((lane(2).inner, lane(2).outer), (1, 0));
    // The marks: the centre line solid, lane −1's outer border broken (3 m dash, 9 m gap).
    let mark = |b| sec.marks.iter().find(|m| m.border == b).expect("a mark");
    assert_eq!(mark(2).mark.mark_type, RoadMarkType::Solid);
    assert_eq!(mark(3).mark.mark_type, RoadMarkType::Broken);
    assert_eq!(
        (mark(3).mark.lines[0].length, mark(3).mark.lines[0].space),
        (3.0, 9.0)
    );
    assert_eq!((mark(3).from, mark(3).to), (0, sec.s.len() - 1));
}

#[test]
fn curved_borders_stay_within_the_sag_tolerance() {
    // Between two samples of the arc (κ = 0.005, R = 200 m) the outermost border (R ± 6 m)
    // deviates from its chord by at most c²/(8R'); the sampler keeps that under SAG_TOLERANCE,
    // so chords are at most sqrt(8 · 194 · 0.02) = 5.57 m long on the inner border.
    let d = highway();
    let road = d.roads.iter().find(|r| r.id == "0").expect("road 0");
    let sec = &road.sections[1];
    for b in &sec.borders {
        for (k, pair) in b.windows(2).enumerate() {
            if sec.s[k] < 150.0 {
                continue;
            }
            let chord = (pair[1][0] - pair[0][0]).hypot(pair[1][1] - pair[0][1]);
            let sag = chord * chord / (8.0 * 194.0);
            assert!(
                sag <= SAG_TOLERANCE * 1.01,
                "chord {chord} m at s = {}",
                sec.s[k]
            );
        }
    }
}
