//! `<signal>` and its `<validity>` lanes (OpenDRIVE 1.8 §14.2 "Lane validity for signals"); `<object>` outlines (§13.3).

use std::path::Path;

use opendrive::RoadNetwork;

const ROAD: &str = r#"<OpenDRIVE><header revMajor="1" revMinor="8"/>
<road id="1" length="100" junction="-1"><planView>
<geometry s="0" x="0" y="0" hdg="0" length="100"><line/></geometry></planView>
<lanes><laneSection s="0">
<left><lane id="1" type="driving"><width sOffset="0" a="3.5" b="0" c="0" d="0"/></lane></left>
<center><lane id="0" type="none"/></center>
<right><lane id="-1" type="driving"><width sOffset="0" a="3.5" b="0" c="0" d="0"/></lane>
<lane id="-2" type="driving"><width sOffset="0" a="3.5" b="0" c="0" d="0"/></lane>
<lane id="-3" type="sidewalk"><width sOffset="0" a="2" b="0" c="0" d="0"/></lane></right>
</laneSection></lanes>
<signals>SIGNALS</signals></road></OpenDRIVE>"#;

fn load(signals: &str) -> Result<RoadNetwork, opendrive::Error> {
    RoadNetwork::from_str(&ROAD.replace("SIGNALS", signals), Path::new("signals.xodr"))
}

/// Without `<validity>` a signal is valid for every lane (of its orientation's direction); with
/// `<validity fromLane="-3" toLane="-2"/>` and `<validity fromLane="-1" toLane="-1"/>`… only
/// for the lanes in the ranges, bounds included.
#[test]
fn validity_ranges_restrict_a_signal_to_their_lanes() {
    let net = load(
        r#"<signal s="50" t="-8" id="A" orientation="+" type="1000001"/>
           <signal s="60" t="-8" id="B" orientation="+" type="1000001">
             <validity fromLane="-3" toLane="-2"/></signal>"#,
    )
    .unwrap_or_else(|e| panic!("{e}"));
    let signals = &net.road("1").expect("road 1").signals;
    assert!(signals[0].validity.is_empty());
    assert!((-3..=1).all(|l| signals[0].valid_for_lane(l)));
    assert_eq!(signals[1].validity, vec![(-3, -2)]);
    assert!(!signals[1].valid_for_lane(-1));
    assert!(signals[1].valid_for_lane(-2) && signals[1].valid_for_lane(-3));
    assert!(!signals[1].valid_for_lane(-4));
}

/// A `<validity>` without `toLane` is an error at the element.
#[test]
fn a_validity_without_to_lane_is_an_error() {
    let err = load(
        r#"<signal s="50" t="-8" id="A" orientation="+" type="1000001">
             <validity fromLane="-1"/></signal>"#,
    )
    .expect_err("toLane is required");
    assert!(err.to_string().contains("toLane"), "{err}");
}

/// The lanes a signal is for (`Road::signal_lanes`, left to right), on a right-hand-traffic
/// road with lane 1 (driving, −s), lanes −1 and −2 (driving, +s) and −3 (sidewalk): without
/// validity, "+" gives the drivable +s lanes −1, −2; "-" gives 1; "none" gives 1, −1, −2; with
/// `<validity fromLane="-3" toLane="-2"/>` exactly −2 and −3 (the sidewalk too: the file
/// says so).
#[test]
fn signal_lanes_follow_orientation_and_validity() {
    let net = load(
        r#"<signal s="50" t="-8" id="P" orientation="+" type="1000001"/>
           <signal s="50" t="5" id="M" orientation="-" type="1000001"/>
           <signal s="50" t="5" id="N" orientation="none" type="274"/>
           <signal s="60" t="-8" id="V" orientation="+" type="1000001">
             <validity fromLane="-3" toLane="-2"/></signal>"#,
    )
    .unwrap_or_else(|e| panic!("{e}"));
    let road = net.road("1").expect("road 1");
    let lanes: Vec<Vec<i32>> = road.signals.iter().map(|s| road.signal_lanes(s)).collect();
    assert_eq!(
        lanes,
        vec![vec![-1, -2], vec![1], vec![1, -1, -2], vec![-2, -3]]
    );
}

/// `<controller>` (OpenDRIVE 1.8 §14, "Controllers"): the signals it switches are its
/// `<control signalId>` children, in file order; a `<control>` without `signalId` is an error at
/// its position.
#[test]
fn controllers_list_the_signals_they_switch() {
    let text = ROAD.replace("SIGNALS", "").replace(
        "</road></OpenDRIVE>",
        r#"</road><controller id="7" name="crossing"><control signalId="B" type="0"/><control signalId="A"/></controller>
<controller id="8"/></OpenDRIVE>"#,
    );
    let net =
        RoadNetwork::from_str(&text, Path::new("signals.xodr")).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(net.controllers().len(), 2);
    let c = net.controller("7").expect("controller 7");
    assert_eq!(c.name, "crossing");
    assert_eq!(c.signal_ids, vec!["B".to_string(), "A".to_string()]);
    assert!(net
        .controller("8")
        .expect("controller 8")
        .signal_ids
        .is_empty());
    assert!(net.controller("9").is_none());

    let bad = text.replace(r#"<control signalId="A"/>"#, r#"<control type="0"/>"#);
    let e = RoadNetwork::from_str(&bad, Path::new("signals.xodr")).expect_err("no signalId");
    // Line 11 of the text; column 94 after `<signals></signals></road>`, the `<controller …>`
    // start tag and the first `<control …/>` (19 + 7 + 35 + 32 = 93 characters).
    assert_eq!(
        e.to_string(),
        "expected attribute `signalId` on <control>, found none at signals.xodr:11:94"
    );
}

/// An object's outline (OpenDRIVE 1.8 §13.3): the corners of `<outlines><outline>` in order,
/// in road (`cornerRoad`) or local (`cornerLocal`) coordinates, and the OpenDRIVE 1.4
/// `<outline>` child too; a crosswalk is known by its type.
#[test]
fn object_outlines_are_read_in_order() {
    let xodr = ROAD.replace("<signals>SIGNALS</signals>", r#"<objects>
        <object id="cw" type="crosswalk" s="50" t="0"><outlines><outline id="0">
          <cornerRoad s="48" t="-3.5" dz="0" height="0"/><cornerRoad s="52" t="-3.5" dz="0" height="0"/>
          <cornerRoad s="52" t="3.5" dz="0" height="0"/></outline></outlines></object>
        <object id="box" type="obstacle" s="70" t="-2"><outline>
          <cornerLocal u="-1" v="0.5" z="0" height="1"/><cornerLocal u="1" v="0.5" z="0" height="1"/></outline></object>
        </objects>"#);
    let net =
        RoadNetwork::from_str(&xodr, Path::new("objects.xodr")).unwrap_or_else(|e| panic!("{e}"));
    let objects = &net.road("1").expect("road 1").objects;
    use opendrive::Corner::{Local, Road};
    assert!(objects[0].is_crosswalk() && !objects[1].is_crosswalk());
    assert_eq!(
        objects[0].outlines,
        vec![vec![
            Road { s: 48.0, t: -3.5 },
            Road { s: 52.0, t: -3.5 },
            Road { s: 52.0, t: 3.5 }
        ]]
    );
    assert_eq!(
        objects[1].outlines,
        vec![vec![Local { u: -1.0, v: 0.5 }, Local { u: 1.0, v: 0.5 }]]
    );
}
