//! Property tests: the world → road → world round trip on random single-geometry roads, and
//! random attribute corruption of a valid file never panicking.

use std::path::Path;

use opendrive::RoadNetwork;
use proptest::prelude::*;

/// A 100 m road of one geometry with a right and a left lane, and a gentle bank and slope.
fn road(curve: &str, bank: f64) -> Option<RoadNetwork> {
    let text = format!(
        r#"<OpenDRIVE><header/><road id="1" length="100" junction="-1"><planView>
<geometry s="0" x="10" y="-5" hdg="0.7" length="100">{curve}</geometry></planView>
<elevationProfile><elevation s="0" a="0" b="0.02" c="0" d="0"/></elevationProfile>
<lateralProfile><superelevation s="0" a="{bank}" b="0" c="0" d="0"/></lateralProfile>
<lanes><laneSection s="0"><left><lane id="1" type="driving"><width sOffset="0" a="3.5" b="0" c="0" d="0"/></lane></left>
<center><lane id="0" type="none"/></center><right>
<lane id="-1" type="driving"><width sOffset="0" a="3" b="0.01" c="0" d="0"/></lane></right>
</laneSection></lanes></road></OpenDRIVE>"#
    );
    RoadNetwork::from_str(&text, Path::new("prop.xodr")).ok()
}

fn curve() -> impl Strategy<Value = String> {
    prop_oneof![
        Just("<line/>".to_string()),
        (-0.02f64..0.02).prop_map(|k| format!(r#"<arc curvature="{k}"/>"#)),
        (-0.02f64..0.02, -0.02f64..0.02).prop_map(|(a, b)| format!(r#"<spiral curvStart="{a}" curvEnd="{b}"/>"#)),
        (-0.002f64..0.002, -2e-5f64..2e-5).prop_map(|(c, d)| format!(r#"<poly3 a="0" b="0" c="{c}" d="{d}"/>"#)),
        (-0.002f64..0.002, -2e-5f64..2e-5).prop_map(|(c, d)| format!(
            r#"<paramPoly3 aU="0" bU="1" cU="0" dU="0" aV="0" bV="0" cV="{c}" dV="{d}" pRange="arcLength"/>"#
        )),
    ]
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 200, ..ProptestConfig::default() })]

    #[test]
    fn road_world_road_round_trip(curve in curve(), bank in -0.1f64..0.1, s in 0.0f64..100.0, t in -3.0f64..3.5) {
        let net = road(&curve, bank).expect("the generated road is valid");
        let p = net.road_pose("1", s, t).expect("s is on the road");
        let found = net.locate_on_road("1", p.x, p.y).expect("the road exists");
        let back = net.road_pose("1", found.s, found.t).expect("located s is on the road");
        // The curvature radius stays above 50 m and |t| ≤ 3.5 m: the inverse is unique.
        prop_assert!((back.x - p.x).hypot(back.y - p.y) < 1e-6, "{:?} → {:?}", (s, t), found);
        prop_assert!((found.s - s).abs() < 1e-6 && (found.t - t).abs() < 1e-6, "{:?} → {:?}", (s, t), found);
        let global = net.locate(p.x, p.y, Some(p.h)).expect("network is not empty");
        prop_assert_eq!(global.road_id.as_str(), "1");
        // t ∈ [−3, 3.5) lies on the surface (lane −1 is at least 3 m wide, lane 1 3.5 m).
        prop_assert!(global.distance < 1e-9, "{:?}", global);
    }

    #[test]
    fn corrupted_attributes_never_panic(index in 0usize..200, junk in prop_oneof![
        Just(String::new()), Just("NaN".to_string()), Just("-1".to_string()), Just("1e999".to_string()),
        Just("0".to_string()), "[a-z0-9.-]{1,6}"
    ]) {
        let text = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/tests/files/three_lanes.xodr"))
            .expect("fixture present");
        // Replace the value of the index-th attribute (modulo the count) with junk.
        let quotes: Vec<usize> = text.match_indices('"').map(|(i, _)| i).collect();
        let pairs = quotes.len() / 2;
        let k = index % pairs;
        let (a, b) = (quotes[2 * k], quotes[2 * k + 1]);
        let corrupted = format!("{}\"{}\"{}", &text[..a], junk, &text[b + 1..]);
        match RoadNetwork::from_str(&corrupted, Path::new("junk.xodr")) {
            Ok(net) => {
                // Whatever loads must answer queries without panicking.
                for r in net.roads() {
                    let _ = r.pose(r.length / 2.0, 0.0);
                    let _ = r.lane_pose(-1, 1.0, 0.0);
                }
                let _ = net.locate(50.0, -2.0, Some(0.0));
            }
            Err(e) => prop_assert!(e.pos().is_some(), "{}", e),
        }
    }
}
