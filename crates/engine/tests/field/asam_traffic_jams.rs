//! Issue 34 — equivalents of ASAM's OpenSCENARIO 1.2/1.3 traffic-jam examples (EndOfTrafficJam,
//! EndofTrafficJamNeighboringLaneOccupied, TrafficJam), written for this project on stand-in
//! roads along +x (x = s, y = t): `rq31_straight.xodr` (lane −2 at t = −4.55, −3 at −8.45) and
//! `rq36_straight.xodr` (three driving lanes per side: −2 at −2.375, −3 at −6.125, −4 at
//! −9.875). The ASAM files are not copied (no licence statement for redistribution); each
//! fixture's comment says what it keeps of its example.
//!
//! Readings these examples rest on (OpenSCENARIO 1.3):
//! - A DistanceCondition measures to a Position, a point: with `freespace="true"` from the
//!   triggering entity's bounding box to that point (XSD DistanceCondition: freespace "True:
//!   distance is measured between closest bounding box points"; a position has no box), even
//!   when the position is a RelativeObjectPosition of another entity with dx = dy = 0.
//! - A LaneChangeAction and a SpeedAction in one Event run together; the actions of a step
//!   act in document order, so a lane change written first moves at the speed the step
//!   started with (engine runtime::action_order), and once it has ended the car moves at the
//!   speed each step ends with.
//! - `dynamicsDimension="distance"` counts the distance along the road (engine
//!   actions/lane_change.rs, as esmini), not the longer path.
//! - Scripted lane changes check no lane for occupants: the standard asks for none.

use engine::storyboard::Transition;

use crate::support::{assert_at, run, transitions};

/// Closed forms along a straight road, up to round-off.
const POS_TOL: f64 = 1e-6;
/// Step times are sums of dt = 0.05 s.
const TIME_TOL: f64 = 1e-9;

#[test]
fn end_of_traffic_jam_equivalent_brakes_each_car_after_its_travelled_distance() {
    let (_, rows, events) = run("asam_end_of_traffic_jam.xosc", &[]);
    let at = |name: &str, t: Transition| transitions(&events, name, t);
    // The road file comes from the parameter Road_Logics; A1 200 m ahead of Ego in its lane,
    // A2 200 m ahead one lane to its left.
    let placed = [
        ("Ego", 1000.0, -8.45),
        ("A1", 1200.0, -8.45),
        ("A2", 1200.0, -4.55),
    ];
    assert_at(&rows, 0.0, &placed, POS_TOL);
    // A1 has travelled 22.222·4.50 = 99.999 m < 100 at 4.50 s and 101.11 m at 4.55 s: Event1
    // at 4.55 s. 22.222 → 19.444 at 5 m/s² (0.25 m/s a step) takes 11.1 steps: the target is
    // reached in the step that starts at 5.10 s. A2: 199.998 m at 9.00 s, Event2 at 9.05 s,
    // the end at 9.60 s.
    for (event, action, start, end) in [
        ("Event1", "Action1", 4.55, 5.10),
        ("Event2", "Action2", 9.05, 9.60),
    ] {
        assert!(
            (at(event, Transition::Start)[0] - start).abs() < TIME_TOL,
            "{event}"
        );
        assert!(
            (at(action, Transition::End)[0] - end).abs() < TIME_TOL,
            "{action}"
        );
    }
    assert!((rows.at("A1", 4.60).speed - 21.972).abs() < POS_TOL);
    assert!((rows.at("A1", 5.15).speed - 19.444).abs() < POS_TOL);
    // A1 at 40 s: 1200 + 22.222·4.55 + 0.05·(Σ_{k=1..11}(22.222 − 0.25k) + 19.444)
    // + 19.444·(40 − 5.15) = 1301.1101 + 12.3693 + 677.6234 = 1991.1028 m.
    assert!((rows.at("A1", 40.0).x - 1991.1028).abs() < POS_TOL);
    // Ego's ObjectController (ExternalController, no oscsim model) is activated in the Init
    // and kept off: the default controller drives it at 27.778 m/s, x(40) = 2111.12 m.
    let ego = rows.at("Ego", 40.0);
    assert!((ego.x - 2111.12).abs() < POS_TOL && (ego.speed - 27.778).abs() < POS_TOL);
    // SimulationTime > 40 first holds at 40.05 s.
    assert!((at("storyBoard", Transition::Stop)[0] - 40.05).abs() < TIME_TOL);
}

#[test]
fn end_of_jam_lane_occupied_equivalent_changes_lane_and_stops_beside_the_jam() {
    let (_, rows, events) = run("asam_end_of_jam_lane_occupied.xosc", &[]);
    let at = |name: &str, t: Transition| transitions(&events, name, t);
    // RelativeLanePosition with offset 0.5 from Ego (lane −4, t = −9.875): A1 and A2 at
    // t = −9.375; A3 two lanes to the left (lane −2) at −2.375 + 0.5 = −1.875.
    let placed = [
        ("A1", 1300.0, -9.375),
        ("A2", 2000.0, -9.375),
        ("A3", 2000.0, -1.875),
    ];
    assert_at(&rows, 0.0, &placed, POS_TOL);
    // From A1's box front (x + 1.4 + 2.25) to A2's reference point (2000): 1996.35 − x < 55
    // once x > 1941.35, x = 1300 + 19.444·t: x(32.95) = 1940.680, x(33.00) = 1941.652, so the
    // Event starts at 33.00 s. (To A2's box, 1999.15, it would be 32.95 s: the condition
    // names a position, not the entity.)
    assert!((at("Event1", Transition::Start)[0] - 33.00).abs() < TIME_TOL);
    let x0 = 1300.0 + 19.444 * 33.0;
    assert!((rows.at("A1", 33.0).x - x0).abs() < POS_TOL);
    // Braking at 10 m/s² (0.5 m/s a step): 19.444 − 0.5k after k steps, 0.444 m/s after 38,
    // rest in the step that starts at 34.90 s.
    assert!((rows.at("A1", 34.30).speed - 6.444).abs() < POS_TOL);
    assert!((at("Action2", Transition::End)[0] - 34.90).abs() < TIME_TOL);
    assert!(rows.at("A1", 34.95).speed.abs() < POS_TOL);
    // The 18 m of the change are counted along the road (x here): it ends logged at the first
    // frame in which A1 has covered them; by then it is on lane −3 at offset 0.5
    // (y = −6.125 + 0.5), before the car stands.
    let end = at("Action1", Transition::End);
    assert_eq!(end.len(), 1, "{end:?}");
    let first_18 = (0..60)
        .map(|k| 33.0 + 0.05 * f64::from(k))
        .find(|&t| rows.at("A1", t).x - x0 >= 18.0)
        .expect("A1 covers 18 m");
    assert!(
        (end[0] - first_18).abs() < TIME_TOL,
        "{end:?} vs {first_18}"
    );
    assert!(end[0] < 34.90);
    let rest = rows.at("A1", 35.0);
    assert!((rest.y + 5.625).abs() < POS_TOL, "{}", rest.y);
    assert_eq!(rest.road.as_ref().map(|r| r.1), Some(-3));
    // Standing: the path is at most 0.05·Σ_{k=0..38}(19.444 − 0.5k) = 19.391 m (every step at
    // its start speed), and at least the 18 m the change covered along the road.
    let stood = rest.x - x0;
    assert!((18.0..=19.391).contains(&stood), "{stood}");
    // The lane it changed into was free at its place; it stays standing there, short of the
    // jam, so the lane next to Ego's is now occupied too.
    assert!((rows.at("A1", 55.0).x - rest.x).abs() < POS_TOL);
}

#[test]
fn traffic_jam_equivalent_places_a_chain_of_standing_cars_and_nothing_else() {
    let (_, rows, events) = run("asam_traffic_jam.xosc", &[]);
    // Ego at (1000, −2.375) on lane −2. A1: dLane −2 → lane −4 (−9.875), ds 145, offset −0.6:
    // (1145, −10.475); A2 8 m ahead of A1 in its frame (heading 0): (1153, −10.475); A3: A1's
    // lane + 1 → lane −3 (−6.125), ds 3, offset −1.6 from that lane's centre: (1148, −7.725);
    // A4: (1156, −7.725); A5: Ego's s + 151, t + 0.9: (1151, −1.475); A6: (1159, −1.475).
    let placed = [
        ("A1", 1145.0, -10.475),
        ("A2", 1153.0, -10.475),
        ("A3", 1148.0, -7.725),
        ("A4", 1156.0, -7.725),
        ("A5", 1151.0, -1.475),
        ("A6", 1159.0, -1.475),
    ];
    for t in [0.0, 10.0] {
        assert_at(&rows, t, &placed, POS_TOL);
        for (name, _, _) in placed {
            assert!(rows.at(name, t).h.abs() < POS_TOL, "{name} at {t}");
        }
    }
    assert!((rows.at("Ego", 10.0).x - 1361.0).abs() < POS_TOL);
    // No Story: the storyboard's only transitions are its start and its stop at 10.05 s
    // (SimulationTime > 10).
    let stop = transitions(&events, "storyBoard", Transition::Stop);
    assert_eq!(stop.len(), 1);
    assert!((stop[0] - 10.05).abs() < TIME_TOL, "{stop:?}");
}
