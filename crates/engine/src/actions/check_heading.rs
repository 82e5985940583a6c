//! The heading oscsim's state check requires (`scenario::StateCheck::heading`, no XML form):
//! the OpenSCENARIO DSL runtime's `yaw`/`orientation` measured in the world or from another
//! object (ASAM OpenSCENARIO DSL 2.1 §8.9: `measure_by: relative_to_north` and the measures
//! between two objects' axes, `measured_by: absolute`, `relative_to_reference`) where its plan
//! does not know the actor's place: a phase that starts on a run-time condition, an end the
//! plan does not know, or every step of a phase whose end it does not know.
//!
//! Headings are those of the road network's inertial frame (OpenDRIVE's x, y), counted
//! counter-clockwise about z from +x as OpenSCENARIO 1.x counts a heading: the one asked is
//! `from`'s heading plus the check's angle, `from` being 0 (the world), another entity's
//! heading at the moment, or the heading of the road's s-axis where the actor is (its
//! heading less its `relative_heading` on the road). The actor's heading is its pose's; within
//! the tolerance of the one asked (on the circle) it holds, otherwise the check fails naming
//! the heading asked, the actor's and its lane's (the s-axis's, turned by π for a lane track
//! driven in −s).

use opendrive::{angle_difference, Direction};
use scenario::{HeadingCheck, HeadingFrom, StateCheck};

use crate::error::Error;
use crate::store::World;
use crate::world::entity::Entity;
use crate::EntityId;

/// The heading `check` requires of entity `e`, if it requires one (`from`: the entity it is
/// measured from, resolved when the storyboard was built, `CheckRefs`; `fail`: the check's
/// error from what it expected and what it found).
pub(super) fn require(
    world: &World,
    e: &Entity,
    (check, from): (&StateCheck, Option<EntityId>),
    fail: &dyn Fn(String, String) -> Error,
) -> Result<(), Error> {
    let Some(heading) = &check.heading else {
        return Ok(());
    };
    // The road's s-axis where the actor is (its heading less its heading on the road).
    let axis = e
        .road_position
        .as_ref()
        .map(|p| angle_difference(e.pose.h, p.relative_heading));
    let base = match &heading.from {
        HeadingFrom::World => 0.0,
        HeadingFrom::Entity(x) => match from {
            Some(o) => world.entity(o).pose.h,
            None => {
                return Err(fail(
                    format!("'{x}' in the scenario"),
                    "no such entity".into(),
                ))
            }
        },
        HeadingFrom::Road => match axis {
            Some(a) => a,
            None => {
                return Err(fail(
                    format!("'{}' on a road", e.name),
                    "it off every road".into(),
                ))
            }
        },
    };
    let want = opendrive::normalize_angle(base + heading.angle);
    let got = e.pose.h;
    if angle_difference(got, want).abs() <= heading.tolerance {
        return Ok(());
    }
    Err(fail(
        format!(
            "'{}' at heading {want:.4} rad ({}, within {} rad)",
            e.name,
            described(heading, base),
            heading.tolerance
        ),
        format!("it at {got:.4} rad{}", lane_heading(e, axis)),
    ))
}

/// The measure and the angle of `heading`, with the heading `base` it is measured from.
fn described(heading: &HeadingCheck, base: f64) -> String {
    let of = match &heading.from {
        HeadingFrom::World => String::new(),
        HeadingFrom::Entity(x) => format!(", '{x}' at heading {base:.4} rad"),
        HeadingFrom::Road => format!(", the road's s-axis at {base:.4} rad"),
    };
    format!("{}{of}", heading.measure)
}

/// ", its lane's heading h rad" of entity `e` on a lane (the road's s-axis `axis` in the lane
/// track's direction of travel), else nothing.
fn lane_heading(e: &Entity, axis: Option<f64>) -> String {
    let (Some(axis), Some(track)) = (axis, e.track.as_ref()) else {
        return String::new();
    };
    let turn = match track.direction {
        Direction::Forward => 0.0,
        Direction::Backward => std::f64::consts::PI,
    };
    format!(
        ", its lane's heading {:.4} rad",
        opendrive::normalize_angle(axis + turn)
    )
}
