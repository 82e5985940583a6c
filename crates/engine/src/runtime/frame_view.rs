//! What the OpenSCENARIO DSL 2.1 §8.7 domain methods see of an entity in a frame or a kept
//! state (`EntityView`: pose, box, road position, speed, and velocity and acceleration in its
//! own axes; frames give them in world axes): the view the batch's measurements and the
//! coverage sampler measure one entity against another with.

use opendrive::Real;

use crate::domain::{Acceleration6d, Vector3, Velocity6d};
use crate::output::EntityFrame;
use crate::position::EntityView;
use crate::snapshot::EntityState;

impl<'a> EntityFrame<'a> {
    /// The entity as the §8.7 domain methods see it (`EntityView`: pose, box, road position,
    /// speed, and velocity and acceleration in its own axes; the frame gives them in world
    /// axes), e.g. to measure it against another with `traffic_participant()`.
    pub fn view(&self) -> EntityView<'a> {
        let base = EntityView {
            speed: self.speed,
            odometer: self.odometer,
            road_position: self.road_position,
            ..EntityView::new(
                self.name,
                self.kind.object_type(),
                self.pose,
                self.bounding_box,
            )
        };
        with_motion(base, self.velocity, self.acceleration, self.yaw_rate)
    }
}

impl EntityState {
    /// The entity as the §8.7 domain methods see it ([`EntityFrame::view`] of a kept state).
    pub fn view(&self) -> EntityView<'_> {
        let base = EntityView {
            speed: self.speed,
            odometer: self.odometer,
            road_position: self.road_position.as_ref(),
            ..EntityView::new(
                &self.name,
                self.kind.object_type(),
                self.pose,
                self.bounding_box,
            )
        };
        with_motion(base, self.velocity, self.acceleration, self.yaw_rate)
    }
}

/// `view` with the world-axes `velocity`, `acceleration` and `yaw_rate` turned into its own
/// axes (heading only: the frame's motion is planar).
fn with_motion(
    view: EntityView<'_>,
    velocity: Vector3,
    acceleration: Vector3,
    yaw_rate: Real,
) -> EntityView<'_> {
    let (s, c) = view.pose.h.sin_cos();
    let local = |v: Vector3| Vector3::new(c * v.x + s * v.y, -s * v.x + c * v.y, v.z);
    EntityView {
        velocity: Velocity6d {
            translational: local(velocity),
            rotational: Vector3::new(0.0, 0.0, yaw_rate),
        },
        acceleration: Acceleration6d {
            translational: local(acceleration),
            ..Acceleration6d::ZERO
        },
        ..view
    }
}
