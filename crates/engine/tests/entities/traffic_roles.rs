//! Roles of spawned vehicles (OpenSCENARIO 1.3 XSD `TrafficDefinition/VehicleRoleDistribution`,
//! `VehicleRoleDistributionEntry`): each vehicle a traffic action spawns gets a role drawn by
//! the entries' weights from a stream of its own under the run's seed; the role is on the
//! frames, in the entity snapshot and in the spawn's event-log line, and drawing it leaves the
//! positions, speeds and templates of the traffic unchanged.

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

use engine::output::EventRecord;
use engine::{Engine, EngineConfig, EntityState, Frame, FrameSink, SinkError};
use scenario::Role;

fn file(name: &str) -> PathBuf {
    crate::corpus::fixture("entities").join(name)
}

/// The role each entity shows in the frames, and every (name, t, x, y) of spawned vehicles.
#[derive(Default)]
struct Seen {
    roles: BTreeMap<String, Option<Role>>,
    rows: Vec<(String, f64, f64, f64)>,
}

impl FrameSink for Seen {
    fn frame(&mut self, frame: &Frame<'_>) -> Result<(), SinkError> {
        for e in frame.objects() {
            let role = *self.roles.entry(e.name.to_owned()).or_insert(e.role);
            assert_eq!(role, e.role, "{} keeps its role", e.name);
            if e.name.contains(".entity_") {
                self.rows
                    .push((e.name.to_owned(), frame.time, e.pose.x, e.pose.y));
            }
        }
        Ok(())
    }
}

/// Runs `path` with `seed` for at most `duration` s: what the frames showed, the event log and
/// the entity snapshot at the end.
fn run(
    path: &Path,
    seed: u64,
    duration: Option<f64>,
) -> (Seen, Vec<EventRecord>, Vec<EntityState>) {
    let config = EngineConfig {
        seed,
        duration,
        ..EngineConfig::default()
    };
    let mut engine = Engine::load(path, &[], config)
        .unwrap_or_else(|e| panic!("{} does not load: {e}", path.display()));
    let mut seen = Seen::default();
    let mut events = Vec::new();
    engine.run(&mut seen, &mut events).expect("runs");
    let entities = engine.entities();
    (seen, events, entities)
}

/// The spawned vehicles' roles, by name.
fn spawned(seen: &Seen) -> BTreeMap<&str, Option<Role>> {
    seen.roles
        .iter()
        .filter(|(name, _)| name.starts_with("src.entity_"))
        .map(|(name, role)| (name.as_str(), *role))
        .collect()
}

/// The source owes 0.1 vehicle per step of 0.05 s, so a vehicle appears every 10th step, in
/// the frames of t = 0.5, 1.0, …, 200.0 s (the stop trigger, t > 200 s, fires at the step of
/// 200.05 s): N = 400. Each is civil with probability
/// 3 / (3 + 1 + 0) = 0.75, else police; ambulance has weight 0 and never comes. The number
/// of civil vehicles is binomial: mean 0.75 N (300 for N = 400), standard deviation
/// √(N · 0.75 · 0.25) ≈ 8.7. The seed is fixed, so the count is too (291 with seed 1, −1.0 sd);
/// the test states that it lies within 4 standard deviations of the mean (a correct draw misses that band with
/// probability 6·10⁻⁵), which a draw ignoring the weights (mean 0.5 N = 200, or 0.33 N with
/// ambulances) cannot meet. Every spawn's event-log line names the role the frames show, the
/// snapshot at the end carries the same roles, and the declared Ego keeps its `role`.
#[test]
fn vehicle_roles_are_drawn_by_their_weights() {
    let (seen, events, entities) = run(&file("traffic_roles.xosc"), 1, None);
    let roles = spawned(&seen);
    let n = roles.len();
    assert_eq!(n, 400, "vehicles spawned");
    let count = |r: Role| roles.values().filter(|x| **x == Some(r)).count();
    let (civil, police) = (count(Role::Civil), count(Role::Police));
    assert_eq!(civil + police, n, "every vehicle is civil or police");
    let mean = 0.75 * n as f64;
    let sd = (n as f64 * 0.75 * 0.25).sqrt();
    assert!(
        (civil as f64 - mean).abs() <= 4.0 * sd,
        "{civil} civil of {n}: mean {mean}, sd {sd}"
    );

    let spawns: Vec<(&str, &str)> = events
        .iter()
        .filter_map(|e| match e {
            EventRecord::Entity { entity, change, .. } if change.starts_with("spawned") => {
                Some((entity.as_str(), change.as_str()))
            }
            _ => None,
        })
        .collect();
    assert_eq!(spawns.len(), n);
    for (entity, change) in spawns {
        let role = roles[entity].expect("spawned with a role");
        assert_eq!(change, format!("spawned (role {})", role.as_str()));
    }

    let ego = entities.iter().find(|e| e.name == "Ego").expect("Ego");
    assert_eq!(ego.role, Some(Role::Ambulance));
    let in_scene: Vec<&EntityState> = entities
        .iter()
        .filter(|e| e.name.starts_with("src.entity_"))
        .collect();
    assert!(
        in_scene.len() > 20,
        "{} spawned vehicles in the scene",
        in_scene.len()
    );
    for e in in_scene {
        assert_eq!(e.role, roles[e.name.as_str()], "{}", e.name);
    }
}

/// The same seed gives the same roles; another seed other roles. Drawing roles takes nothing
/// from the source's stream: the same scenario without its VehicleRoleDistribution spawns
/// the same vehicles at the same places, bit for bit, with no role.
#[test]
fn same_seed_same_roles_and_the_traffic_is_that_of_a_run_without_roles() {
    let path = file("traffic_roles.xosc");
    let (a, _, _) = run(&path, 1, Some(30.0));
    let (b, _, _) = run(&path, 1, Some(30.0));
    let (c, _, _) = run(&path, 2, Some(30.0));
    assert!(spawned(&a).len() > 50);
    assert_eq!(spawned(&a), spawned(&b));
    assert_ne!(spawned(&a), spawned(&c));

    let text = std::fs::read_to_string(&path).expect("fixture reads");
    let (from, to) = (
        text.find("<VehicleRoleDistribution>").expect("role block"),
        text.find("</VehicleRoleDistribution>")
            .expect("role block end")
            + "</VehicleRoleDistribution>".len(),
    );
    let road = file("straight_500m.xodr");
    let plain = format!("{}{}", &text[..from], &text[to..]).replace(
        "filepath=\"straight_500m.xodr\"",
        &format!("filepath=\"{}\"", road.display()),
    );
    // Removed when it drops, also if the run fails.
    let copy = tempfile::Builder::new()
        .prefix("oscsim-roles-")
        .suffix(".xosc")
        .tempfile()
        .expect("temp scenario");
    std::fs::write(copy.path(), plain).expect("temp scenario written");
    let (d, _, _) = run(copy.path(), 1, Some(30.0));
    assert!(spawned(&d).values().all(Option::is_none));
    assert_eq!(a.rows, d.rows);
}
