//! OpenDRIVE: any bytes as an `.xodr` file. A network that loads is then queried the way the
//! engine queries it: every road sampled along s (reference line and every lane centre), lane
//! graph successors and predecessors, points near and far located, one route planned. The
//! queries must not panic or hang, and what they return must be finite.
#![no_main]

use std::path::Path;

use libfuzzer_sys::fuzz_target;
use opendrive::{LanePosition, RoadNetwork};

mod support;
use support::Draws;

/// Roads sampled per input, and s samples per road (ends included).
const MAX_ROADS: usize = 64;
const SAMPLES: usize = 12;

fn finite(values: &[f64]) -> bool {
    values.iter().all(|v| v.is_finite())
}

fuzz_target!(|data: &[u8]| {
    support::watchdog::start(data);
    support::on_this_thread(|| road_network(data));
});

/// One input, checked as the module doc says.
fn road_network(data: &[u8]) {
    let Ok(text) = std::str::from_utf8(data) else {
        return;
    };
    let Ok(net) = RoadNetwork::from_str(text, Path::new("fuzz.xodr")) else {
        return;
    };
    let mut draws = Draws::new(data);
    let mut driving = Vec::new();
    for road in net.roads().iter().take(MAX_ROADS) {
        assert!(
            road.length.is_finite() && road.length >= 0.0,
            "{}",
            road.length
        );
        for i in 0..SAMPLES {
            let s = road.length * i as f64 / (SAMPLES - 1) as f64;
            if let Ok(p) = road.pose(s, 0.0) {
                assert!(
                    finite(&[p.x, p.y, p.z, p.h, p.p, p.r]),
                    "road {} s {s}: {p:?}",
                    road.id
                );
            }
            let section = road.lane_section_at(s);
            for lane in section.lanes() {
                if let Ok(p) = road.lane_pose(lane.id, s, 0.0) {
                    assert!(
                        finite(&[p.x, p.y, p.z, p.h, p.p, p.r]),
                        "lane {} {s}: {p:?}",
                        lane.id
                    );
                    if lane.id != 0 && driving.len() < 8 && opendrive::is_drivable(&lane.lane_type)
                    {
                        driving.push(LanePosition {
                            road_id: road.id.clone(),
                            lane_id: lane.id,
                            s,
                            offset: 0.0,
                        });
                    }
                }
                if let Ok(span) = road.lane_span(lane.id, s) {
                    assert!(finite(&[span.inner, span.outer]), "{span:?}");
                }
                if let Some(h) = net.lane_handle(&road.id, lane.id, s) {
                    let _ = net.driving_direction(h);
                    for &next in net.successors(h).iter().chain(net.predecessors(h)) {
                        let _ = net.handle_road(next);
                    }
                }
            }
        }
    }
    if let Some([x0, y0, x1, y1]) = net.bounding_box() {
        for _ in 0..8 {
            let x = x0 + (x1 - x0) * draws.unit() + draws.signed() * 50.0;
            let y = y0 + (y1 - y0) * draws.unit() + draws.signed() * 50.0;
            let heading = draws.bool().then(|| draws.signed() * 4.0);
            if let Some(rp) = net.locate(x, y, heading) {
                assert!(
                    finite(&[rp.s, rp.t, rp.offset, rp.relative_heading, rp.distance]),
                    "{rp:?}"
                );
                let road = net
                    .road(&rp.road_id)
                    .expect("located on a road of the network");
                assert!(
                    rp.s >= 0.0 && rp.s <= road.length,
                    "{rp:?} on length {}",
                    road.length
                );
            }
        }
    }
    if let (Some(a), Some(b)) = (driving.first(), driving.last()) {
        if let Some(route) = net.route(a, b) {
            assert!(route.length.is_finite(), "{route:?}");
        }
    }
}
