//! The one error type of the domain model: the error cases that OpenSCENARIO 2.0 §8.7 names
//! for its methods ("if the physical_object is not on a route the method returns an error",
//! §8.7.2.1.2–8.7.2.1.4, §8.7.4.1.1), plus invalid parameters of the actors themselves.
//!
//! Domain values come from the runtime, not from a file, so an error carries the world
//! position (x, y) it concerns instead of a file position. Display follows the project's
//! "expected X, found Y at …" form.

/// What went wrong in a domain-model method (OpenSCENARIO 2.0 §8.7).
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum DomainErrorKind {
    /// `on_road` (§8.7.16): the point lies on no road of the network.
    #[error("expected a position on a road, found none")]
    NotOnRoad,
    /// `on_lane_section` (§8.7.16): the point lies on no lane section.
    #[error("expected a position on a lane section, found none")]
    NotOnLaneSection,
    /// `on_lane` (§8.7.16): the point lies near a road but in none of its lanes.
    #[error("expected a position in a lane, found none")]
    NotOnLane,
    /// `on_crossing` (§8.7.16): the point lies on a road that is not a junction's
    /// connecting road.
    #[error(
        "expected a position on a junction's connecting road, found {}",
        .road_id.as_deref().map_or("no road".to_string(), |r| format!("road {r}"))
    )]
    NotOnCrossing {
        /// The road the point is on, if any.
        road_id: Option<String>,
    },
    /// `distance_along_route` (§8.7.4.1.1): the object is on none of the route's elements.
    #[error("expected a position on the route, found one off it")]
    NotOnRoute,
    /// The two objects' roads are not joined by road links or junction connections, so no
    /// distance along s exists between them (§8.7.5.1.2, §8.7.5.1.3).
    #[error("expected roads {from} and {to} to be joined by links or junctions, found no route")]
    NoRouteBetween {
        /// Road of the calling object.
        from: String,
        /// Road of the reference object.
        to: String,
    },
    /// A route (§8.7.4.1.1) with no element, or with an element the network does not have.
    #[error("expected a route of roads of the network, found {found}")]
    InvalidRoute {
        /// What was found instead, e.g. `no element` or `unknown road 7`.
        found: String,
    },
    /// A lane position that the network does not have (§8.7.18 vehicle_group placement).
    #[error("expected a position in lane {lane_id} of road {road_id}, found s = {s} outside it")]
    LanePosition {
        /// OpenDRIVE road id.
        road_id: String,
        /// OpenDRIVE lane id.
        lane_id: i32,
        /// The s asked for, m.
        s: f64,
    },
    /// An OpenSCENARIO 1.x entity the domain model does not represent (an
    /// `ExternalObjectReference`, which has no bounding box in the scenario).
    #[error("expected a Vehicle, Pedestrian or MiscObject, found entity {name} of another kind")]
    UnsupportedEntity {
        /// The entity's name.
        name: String,
    },
    /// A parameter of an actor is out of its domain (§8.7.9 bounding_box dimensions are
    /// finite and non-negative; §8.7.18 a vehicle group needs a positive spacing).
    #[error("expected {name} to be {expected}, found {found}")]
    InvalidParameter {
        /// The parameter's name as the seed spells it, e.g. `bounding_box.length`.
        name: &'static str,
        /// What the parameter must be, e.g. `a finite length >= 0`.
        expected: &'static str,
        /// The value given.
        found: f64,
    },
}

/// Error of a domain-model method (OpenSCENARIO 2.0 §8.7): a kind and, when the error is
/// about a place, the world position (x, y) of the point that failed.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("{kind}{}", .at.map(|(x, y)| format!(" at world ({x:.3}, {y:.3})")).unwrap_or_default())]
pub struct DomainError {
    kind: DomainErrorKind,
    at: Option<(f64, f64)>,
}

impl DomainError {
    /// An error of `kind` about the world point (`x`, `y`).
    pub(crate) fn at(kind: DomainErrorKind, x: f64, y: f64) -> Self {
        Self {
            kind,
            at: Some((x, y)),
        }
    }

    /// An error of `kind` that concerns no single place.
    pub(crate) fn new(kind: DomainErrorKind) -> Self {
        Self { kind, at: None }
    }

    /// A parameter error: `name` must be `expected` but is `found`.
    pub(crate) fn parameter(name: &'static str, expected: &'static str, found: f64) -> Self {
        Self::new(DomainErrorKind::InvalidParameter {
            name,
            expected,
            found,
        })
    }

    /// What went wrong (one of the §8.7 error cases).
    pub fn kind(&self) -> &DomainErrorKind {
        &self.kind
    }

    /// The world point (x, y) the error is about, if it is about one.
    pub fn position(&self) -> Option<(f64, f64)> {
        self.at
    }
}
