//! Errors of route planning (OpenSCENARIO 1.3 §7.5 "Routes", XSD `Route`, `Waypoint`):
//! "expected X, found Y at file:line:col", the place being the waypoint's Position (or the
//! action's, for a route as a whole).

use scenario::SourcePos;

/// Why a route could not be planned.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum RoutingErrorKind {
    /// A route with fewer than two waypoints.
    #[error("expected at least 2 waypoints in route \"{route}\", found {found}")]
    TooFewWaypoints {
        /// Route name.
        route: String,
        /// Waypoints found.
        found: usize,
    },
    /// A waypoint that lies on no road.
    #[error(
        "expected waypoint {waypoint} of route \"{route}\" on a road, found it off every road"
    )]
    OffRoad {
        /// Route name.
        route: String,
        /// 1-based waypoint index.
        waypoint: usize,
    },
    /// Two waypoints not joined by the lane graph in the driving direction.
    #[error("expected a path through the road network from waypoint {from} ({from_at}) to waypoint {to} ({to_at}) of route \"{route}\", found none")]
    NotConnected {
        /// Route name.
        route: String,
        /// 1-based index of the waypoint the leg starts at.
        from: usize,
        /// Where it is: road, lane, s.
        from_at: String,
        /// 1-based index of the waypoint the leg ends at.
        to: usize,
        /// Where it is: road, lane, s.
        to_at: String,
    },
}

/// A route that could not be planned: the kind and where it was written.
/// Boxed, so that `Result<_, RoutingError>` stays one pointer wide.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("{}", display(.0))]
pub struct RoutingError(Box<Inner>);

#[derive(Debug, Clone, PartialEq)]
struct Inner {
    kind: RoutingErrorKind,
    pos: SourcePos,
}

/// Every kind gets " at file:line:col".
fn display(inner: &Inner) -> String {
    format!("{} at {}", inner.kind, inner.pos)
}

impl RoutingError {
    /// An error of `kind` for the element written at `pos`.
    pub(crate) fn new(kind: RoutingErrorKind, pos: &SourcePos) -> Self {
        Self(Box::new(Inner {
            kind,
            pos: pos.clone(),
        }))
    }

    /// What went wrong.
    pub fn kind(&self) -> &RoutingErrorKind {
        &self.0.kind
    }

    /// Where (file, 1-based line and column).
    pub fn pos(&self) -> &SourcePos {
        &self.0.pos
    }
}
