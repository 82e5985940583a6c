//! Errors of position resolution (OpenSCENARIO 1.3 §6.3, §7.4): what was expected, what was
//! found, and where the position was written ("expected X, found Y at file:line:col").

use scenario::SourcePos;

use crate::routing::RoutingError;
use crate::trajectory::TrajectoryError;

/// Why a position could not be resolved.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum PositionErrorKind {
    /// An `entityRef` names no placed entity.
    #[error("expected a placed entity named \"{0}\", found none")]
    UnknownEntity(String),
    /// A road-relative position refers to an entity that stands on no road.
    #[error("expected entity \"{0}\" on a road, found it off every road")]
    EntityOffRoad(String),
    /// A query on the road network failed (unknown road or lane, s beyond the road).
    #[error("{0}")]
    RoadNetwork(opendrive::ErrorKind),
    /// `laneId` is not an integer.
    #[error("expected an integer lane id, found \"{0}\"")]
    InvalidLaneId(String),
    /// A relative lane position lands on a lane the road does not have there.
    #[error("expected lane {lane} (lane {from} + dLane {d_lane}) on road \"{road}\" at s = {s}, found no such lane")]
    NoTargetLane {
        /// Road id.
        road: String,
        /// The reference entity's lane.
        from: i32,
        /// dLane.
        d_lane: i32,
        /// The lane aimed at.
        lane: i32,
        /// s, m.
        s: f64,
    },
    /// A GeoPosition that the road network's georeference cannot map (no geoReference, not a
    /// PROJ string, a point outside the projection).
    #[error("{0}")]
    Geo(opendrive::GeoError),
    /// The route of a RoutePosition cannot be planned (too few waypoints, waypoints not
    /// joined by the road network); it names its own place.
    #[error("{0}")]
    Route(RoutingError),
    /// `pathS` lies beyond the route.
    #[error("expected pathS in [0, {length}] along route \"{route}\", found {path_s}")]
    OutsideRoute {
        /// Route name.
        route: String,
        /// pathS, m.
        path_s: f64,
        /// Route length, m.
        length: f64,
    },
    /// `FromCurrentEntity`: the entity is not on any stretch of the route.
    #[error("expected entity \"{entity}\" on route \"{route}\", found it off the route")]
    EntityOffRoute {
        /// Entity name.
        entity: String,
        /// Route name.
        route: String,
    },
    /// `s` lies beyond the trajectory.
    #[error("expected s in [0, {length}] along trajectory \"{trajectory}\", found {s}")]
    OutsideTrajectory {
        /// Trajectory name.
        trajectory: String,
        /// s, m.
        s: f64,
        /// Trajectory length, m.
        length: f64,
    },
    /// A form oscsim does not support (yet).
    #[error("expected {expected}, found {found} (not supported by oscsim)")]
    Unsupported {
        /// What oscsim supports.
        expected: &'static str,
        /// What was found.
        found: &'static str,
    },
    /// The trajectory of a TrajectoryPosition cannot be built (it names its own place).
    #[error("{0}")]
    Trajectory(TrajectoryError),
    /// A value that must be finite is not.
    #[error("expected a finite {what}, found {value}")]
    NotFinite {
        /// Which value.
        what: &'static str,
        /// The value.
        value: f64,
    },
}

/// A position that could not be resolved: the kind and where the position was written.
/// Boxed, so that `Result<_, PositionError>` stays one pointer wide.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("{}", display(.0))]
pub struct PositionError(Box<Inner>);

/// The contents of a [`PositionError`].
#[derive(Debug, Clone, PartialEq)]
struct Inner {
    kind: PositionErrorKind,
    pos: SourcePos,
}

/// A trajectory or route error already names its own place; every other kind gets the
/// position's.
fn display(inner: &Inner) -> String {
    match &inner.kind {
        PositionErrorKind::Trajectory(e) => e.to_string(),
        PositionErrorKind::Route(e) => e.to_string(),
        kind => format!("{kind} at {}", inner.pos),
    }
}

impl PositionError {
    /// An error of `kind` for the position written at `pos`.
    pub(crate) fn new(kind: PositionErrorKind, pos: &SourcePos) -> Self {
        Self(Box::new(Inner {
            kind,
            pos: pos.clone(),
        }))
    }

    /// What went wrong.
    pub fn kind(&self) -> &PositionErrorKind {
        &self.0.kind
    }

    /// Where the position was written (file, 1-based line and column).
    pub fn pos(&self) -> &SourcePos {
        &self.0.pos
    }
}

/// A route that cannot be planned (too few waypoints, waypoints not joined), at its own place.
impl From<RoutingError> for PositionError {
    fn from(e: RoutingError) -> Self {
        let pos = e.pos().clone();
        Self::new(PositionErrorKind::Route(e), &pos)
    }
}

/// A trajectory that cannot be built, at its own place.
impl From<TrajectoryError> for PositionError {
    fn from(e: TrajectoryError) -> Self {
        let pos = e.pos().clone();
        Self::new(PositionErrorKind::Trajectory(e), &pos)
    }
}

/// Shorthand: an opendrive query error as a position error at `pos`.
pub(crate) fn road_error(e: opendrive::Error, pos: &SourcePos) -> PositionError {
    PositionError::new(PositionErrorKind::RoadNetwork(e.kind().clone()), pos)
}
