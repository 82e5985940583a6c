//! A crowded test highway for the controllers' unit tests (mobil, parallel): road "A" and
//! worlds of many cars at pseudo-random places and speeds.

use opendrive::RoadNetwork;

use crate::domain::{BoundingBox, Vector3};
use crate::store::World;
use crate::world::entity::{Entity, EntityId, EntityKind};

/// Road "A": 1 km along +x, right lanes −1 … −4 (3.5 m) towards +s, lane 1 towards −s; a
/// solid mark between lanes −3 and −4 on s 600…1000 (no change across it there).
pub fn network() -> RoadNetwork {
    let lane = |id: i32, mark: &str| {
        format!(
            r#"<lane id="{id}" type="driving"><link/><width sOffset="0" a="3.5" b="0" c="0" d="0"/>{mark}</lane>"#
        )
    };
    let broken = r#"<roadMark sOffset="0" type="broken"/>"#;
    let solid_late =
        r#"<roadMark sOffset="0" type="broken"/><roadMark sOffset="600" type="solid"/>"#;
    let xodr = format!(
        r#"<?xml version="1.0"?><OpenDRIVE><header revMajor="1" revMinor="6"/>
<road id="A" junction="-1" length="1000"><link/><planView><geometry s="0" x="0" y="0" hdg="0" length="1000"><line/></geometry></planView><lanes><laneSection s="0"><left>{l1}</left><center><lane id="0" type="none"/></center><right>{r1}{r2}{r3}{r4}</right></laneSection></lanes></road>
</OpenDRIVE>"#,
        l1 = lane(1, broken),
        r1 = lane(-1, broken),
        r2 = lane(-2, broken),
        r3 = lane(-3, solid_late),
        r4 = lane(-4, broken),
    );
    RoadNetwork::from_str(&xodr, std::path::Path::new("mobil_test.xodr")).expect("road")
}

/// A world of `n` 4.5 m × 2 m cars at pseudo-random s, lanes (some across a lane marking)
/// and speeds (0–35 m/s), from `seed`.
pub fn crowded(n: usize, seed: u64) -> World {
    let mut next = generator(seed);
    let b = BoundingBox::new(Vector3::new(1.4, 0.0, 0.75), 4.5, 2.0, 1.5).expect("box");
    let entities = (0..n as u32)
        .map(|i| Entity::new(EntityId(i), &format!("c{i}"), EntityKind::Vehicle, b))
        .collect();
    let mut w = World::new(std::sync::Arc::new(network()), entities);
    for i in 0..n {
        let s = 20.0 + next() * 900.0;
        let lane = 1.0 + (next() * 4.0).floor();
        // One car in eight straddles the marking towards the next lane.
        let t = -(lane - 0.5) * 3.5 - if next() < 0.125 { 1.75 } else { 0.0 };
        let pose = w.network.road_pose("A", s, t).expect("on road");
        let found = w.network.locate(pose.x, pose.y, Some(pose.h));
        let id = EntityId(i as u32);
        w.place_resolved(id, pose, found);
        w.entity_mut(id).speed = (next() * 35.0).min(34.0);
    }
    w
}

/// Pseudo-random numbers in [0, 1) from `seed` (store/lane_kept.rs's generator): the places
/// and speeds of [`crowded`], and the tests' moves.
pub(crate) use crate::store::generator;
