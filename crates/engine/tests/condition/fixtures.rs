//! Conditions read from a scenario file by the `scenario` crate and evaluated here: the path
//! a running scenario takes (XML → typed model → `condition::evaluate`), with parameter
//! expressions. `files/condition/NAME.xosc` holds one condition per ConditionGroup of its Act's
//! start trigger; `NAME.expected` gives each condition's expected raw value and why.

use crate::condition_support;

use std::path::Path;

use condition_support::{eval, FakeWorld};
use engine::position::resolve;
use scenario::{ActionKind, PrivateAction, Scenario};

fn fixture(name: &str) -> String {
    crate::corpus::fixture("condition")
        .join(name)
        .display()
        .to_string()
}

/// Loads NAME.xosc, places its Init teleports, sets `speeds`, and checks every condition of
/// the Act's start trigger against NAME.expected.
fn check(name: &str, speeds: &[(&str, f64)]) {
    let scenario = Scenario::load(Path::new(&fixture(&format!("{name}.xosc")))).unwrap();
    let xodr = scenario.road_network.logic_file.as_ref().unwrap();
    let mut w = FakeWorld::new(opendrive::RoadNetwork::from_file(xodr).unwrap());
    for p in &scenario.parameter_declarations {
        w.parameters.insert(p.name.clone(), p.value.clone());
    }
    for private in &scenario.storyboard.init.privates {
        for action in &private.actions {
            if let ActionKind::Private(PrivateAction::Teleport(position)) = &action.kind {
                let pose = resolve(position, &w).unwrap().pose;
                w.place(&private.entity_ref, pose);
            }
        }
    }
    for &(entity, speed) in speeds {
        w.set_speed(entity, speed);
    }
    let expected = std::fs::read_to_string(fixture(&format!("{name}.expected"))).unwrap();
    let trigger = scenario.storyboard.stories[0].acts[0]
        .start_trigger
        .as_ref()
        .unwrap();
    let conditions: Vec<_> = trigger
        .condition_groups
        .iter()
        .flat_map(|g| &g.conditions)
        .collect();
    let mut checked = 0;
    for line in expected
        .lines()
        .filter(|l| !l.starts_with('#') && !l.trim().is_empty())
    {
        let mut fields = line.split_whitespace();
        let (cond, value) = (fields.next().unwrap(), fields.next().unwrap() == "true");
        let c = conditions
            .iter()
            .find(|c| c.name == cond)
            .unwrap_or_else(|| panic!("{name}: no condition {cond}"));
        assert_eq!(eval(&w, c), value, "{name}: {line}");
        checked += 1;
    }
    assert_eq!(
        checked,
        conditions.len(),
        "{name}: every condition has an expectation"
    );
}

#[test]
fn spacing() {
    check("spacing", &[("Ego", 20.0), ("Lead", 10.0)]);
}
