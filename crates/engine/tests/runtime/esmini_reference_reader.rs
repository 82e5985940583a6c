//! The readers of esmini's reference runs (`runtime_support::esmini_reference`), checked
//! against lines of the corpus files themselves (`shared/corpus/reference/esmini/`) and against
//! small texts written here: columns found by header name, element names with spaces, and the
//! place named when a line cannot be read.

use crate::runtime_support;

use engine::storyboard::Transition;
use runtime_support::{
    esmini_reference, esmini_reference_events, first_transition, parse_reference,
    parse_reference_events,
};

/// Parsed values of 3-decimal text: a few ulps from the decimal.
const PARSED: f64 = 1e-12;

/// cut-in.csv, line 3: `0.000,1,OverTaker,4.510,24.985,-0.011,1.567,0.001,0.000,0,-2,0.000,
/// -4.425,25.000,0.000`; the run lasts 0 … 22 s at 0.1 s rows for Ego and OverTaker.
#[test]
fn cut_in_rows_have_every_column_of_the_header() {
    let rows = esmini_reference("cut-in");
    assert_eq!(rows.len(), 2 * 221);
    let r = &rows[1];
    assert_eq!((r.id, r.name.as_str()), (1, "OverTaker"));
    assert_eq!((r.road_id.as_str(), r.lane_id), ("0", -2));
    let numbers = [
        (r.time, 0.0),
        (r.x, 4.510),
        (r.y, 24.985),
        (r.z, -0.011),
        (r.h, 1.567),
        (r.p, 0.001),
        (r.r, 0.0),
        (r.offset, 0.0),
        (r.t, -4.425),
        (r.s, 25.0),
        (r.speed, 0.0),
    ];
    for (i, (got, want)) in numbers.into_iter().enumerate() {
        assert!((got - want).abs() < PARSED, "value {i}: {got} vs {want}");
    }
    let last = rows.last().map(|r| (r.time, r.name.as_str()));
    assert!(last.is_some_and(|(t, name)| (t - 22.0).abs() < PARSED && name == "OverTaker"));
}

/// Columns are taken by name: a header in another order reads the same values.
#[test]
fn columns_are_found_by_their_header_names() {
    let text = "speed,name,time,id,x,y,z,h,p,r,roadId,laneId,offset,t,s\n\
                36.000,Car,0.100,3,1.5,2.5,0.0,0.1,0.0,0.0,17,1,0.2,1.8,26.8\n";
    let rows = parse_reference("swapped.csv", text);
    assert_eq!(rows.len(), 1);
    let r = &rows[0];
    assert_eq!(
        (r.name.as_str(), r.id, r.road_id.as_str(), r.lane_id),
        ("Car", 3, "17", 1)
    );
    assert!((r.speed - 36.0).abs() < PARSED && (r.time - 0.1).abs() < PARSED);
    assert!((r.x - 1.5).abs() < PARSED && (r.s - 26.8).abs() < PARSED);
}

#[test]
#[should_panic(expected = "short.csv:1: expected a column `laneId` in the header")]
fn a_missing_column_names_the_file_and_the_column() {
    parse_reference(
        "short.csv",
        "time,id,name,x,y,z,h,p,r,roadId,offset,t,s,speed\n",
    );
}

#[test]
#[should_panic(expected = "bad.csv:3: expected f64 in column `x`, found `abc`")]
fn a_bad_number_names_the_file_line_and_column() {
    parse_reference(
        "bad.csv",
        "time,id,name,x,y,z,h,p,r,roadId,laneId,offset,t,s,speed\n\
         0.0,0,Ego,1,2,0,0,0,0,0,-1,0,-1.5,1,0\n\
         0.1,0,Ego,abc,2,0,0,0,0,0,-1,0,-1.5,1,0\n",
    );
}

/// lane_change_simple.events.txt, line 4: `0.000 Lane change story initState ->
/// startTransition -> runningState`; line 79: `175.400 Lane change story runningState ->
/// endTransition -> completeState`.
#[test]
fn element_names_with_spaces_are_read_whole() {
    let log = esmini_reference_events("lane_change_simple");
    let e = &log[3];
    assert_eq!(e.element, "Lane change story");
    assert_eq!(
        (e.from.as_str(), e.to.as_str()),
        ("initState", "runningState")
    );
    assert_eq!(e.transition, Transition::Start);
    assert!(e.time.abs() < PARSED);
    let end = first_transition(&log, "Lane change story", Transition::End);
    assert!(end.is_some_and(|t| (t - 175.4).abs() < PARSED), "{end:?}");
    // Names match whole: the log has "Lane change act", "Lane change event", … but no
    // "Lane change".
    assert_eq!(first_transition(&log, "Lane change", Transition::End), None);
}

#[test]
#[should_panic(expected = "x.events.txt:2: expected `TIME ELEMENT FROM -> TRANSITION -> TO`")]
fn an_unknown_transition_names_the_file_and_line() {
    parse_reference_events(
        "x.events.txt",
        "0.000 storyBoard initState -> startTransition -> runningState\n\
         0.050 storyBoard runningState -> pauseTransition -> completeState\n",
    );
}
