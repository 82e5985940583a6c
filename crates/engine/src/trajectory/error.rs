//! Errors of building a trajectory (OpenSCENARIO 1.3 §6.9 "Trajectories", XSD `Polyline`,
//! `Clothoid`, `ClothoidSpline`, `Nurbs`, `Timing`): what was expected, what was found, and
//! where ("expected X, found Y at file:line:col"). The place is the vertex or control point's
//! own Position where the fault is in one point, else the position the caller names (the
//! FollowTrajectoryAction or TrajectoryPosition).

use scenario::SourcePos;

/// Why a trajectory could not be built or timed.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum TrajectoryErrorKind {
    /// A polyline with fewer than two vertices.
    #[error(
        "expected at least 2 vertices in Polyline of trajectory \"{trajectory}\", found {found}"
    )]
    TooFewVertices {
        /// Trajectory name.
        trajectory: String,
        /// Vertices found.
        found: usize,
    },
    /// A NURBS with fewer than two control points.
    #[error(
        "expected at least 2 ControlPoints in Nurbs of trajectory \"{trajectory}\", found {found}"
    )]
    TooFewControlPoints {
        /// Trajectory name.
        trajectory: String,
        /// Control points found.
        found: usize,
    },
    /// `Nurbs/@order` outside 2 ..= number of control points.
    #[error(
        "expected Nurbs order in 2..={points} (2 to the number of control points), found {order}"
    )]
    Order {
        /// The order.
        order: u32,
        /// Number of control points.
        points: usize,
    },
    /// The knot vector's length is not control points + order.
    #[error("expected {expected} Knots (control points + order), found {found}")]
    KnotCount {
        /// control points + order.
        expected: usize,
        /// Knots found.
        found: usize,
    },
    /// A knot smaller than the one before it.
    #[error("expected Knot {index} >= {previous} (knots in non-decreasing order), found {found}")]
    KnotsOutOfOrder {
        /// 1-based index of the knot.
        index: usize,
        /// The knot before it.
        previous: f64,
        /// Its value.
        found: f64,
    },
    /// The knot vector spans no parameter range (u_order−1 = u_points).
    #[error("expected Knots spanning a parameter range (knot {first} < knot {last}), found both {value}")]
    EmptyKnotRange {
        /// 1-based index of the first knot of the range.
        first: usize,
        /// 1-based index of the last knot of the range.
        last: usize,
        /// Their common value.
        value: f64,
    },
    /// A control point weight that is not a finite number > 0.
    #[error("expected ControlPoint {index} weight > 0, found {found}")]
    Weight {
        /// 1-based index of the control point.
        index: usize,
        /// The weight.
        found: f64,
    },
    /// A length that must be positive is not (Clothoid/@length, ClothoidSplineSegment/@length).
    #[error("expected {what} > 0, found {found}")]
    NonPositiveLength {
        /// Which attribute.
        what: &'static str,
        /// The value.
        found: f64,
    },
    /// A value that must be finite is not.
    #[error("expected a finite {what}, found {found}")]
    NotFinite {
        /// Which value.
        what: &'static str,
        /// The value.
        found: f64,
    },
    /// Some points carry a time and others do not.
    #[error(
        "expected a time on every {element} once one has a time, found none on {element} {index}"
    )]
    PartialTimes {
        /// "Vertex", "ControlPoint" or "ClothoidSplineSegment".
        element: &'static str,
        /// 1-based index of the point without a time.
        index: usize,
    },
    /// A time earlier than the one before it.
    #[error("expected the time of {element} {index} >= {previous} s, found {found} s")]
    TimesOutOfOrder {
        /// "Vertex", "ControlPoint", "ClothoidSplineSegment" or "Clothoid".
        element: &'static str,
        /// 1-based index.
        index: usize,
        /// The previous time, s.
        previous: f64,
        /// This time, s.
        found: f64,
    },
    /// A ClothoidSpline whose `timeEnd` comes before its last segment's `timeStart`.
    #[error(
        "expected ClothoidSpline timeEnd >= {previous} s (the last timeStart), found {found} s"
    )]
    TimeEndTooEarly {
        /// The last timeStart, s.
        previous: f64,
        /// timeEnd, s.
        found: f64,
    },
    /// A ClothoidSpline whose segments have times but which has no `timeEnd`.
    #[error("expected ClothoidSpline timeEnd when its segments have timeStart, found none")]
    MissingTimeEnd,
    /// The first ClothoidSplineSegment has no PositionStart.
    #[error("expected a PositionStart on the first ClothoidSplineSegment, found none")]
    MissingPositionStart,
    /// oscsim's smooth curve from the actor where no actor follows the trajectory (a
    /// TrajectoryPosition, not a FollowTrajectoryAction).
    #[error("expected an actor following oscsim's smooth curve from the actor (it starts where the actor stands), found a trajectory outside a FollowTrajectoryAction")]
    NoActor,
    /// A ClothoidSpline without segments.
    #[error("expected at least 1 ClothoidSplineSegment, found 0")]
    NoSegments,
    /// `FollowTrajectoryAction/@initialDistanceOffset` outside [0, arc length] (its range in
    /// OpenSCENARIO 1.3) or not a number.
    #[error("expected initialDistanceOffset in [0, {length}] m (the trajectory's length), found {found} m")]
    InitialDistanceOffset {
        /// The offset given, m.
        found: f64,
        /// The trajectory's length, m.
        length: f64,
    },
    /// `Timing/@scale` is not a finite number > 0.
    #[error("expected Timing scale > 0, found {0}")]
    Scale(f64),
    /// The shape has no length (all points at one place).
    #[error("expected a trajectory of positive length, found length {0} m")]
    ZeroLength(f64),
    /// A shape oscsim does not know.
    #[error("expected Polyline, Clothoid, ClothoidSpline or Nurbs, found {0}")]
    UnknownShape(&'static str),
}

/// A trajectory that could not be built: the kind and where it was written.
/// Boxed, so that `Result<_, TrajectoryError>` stays one pointer wide.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("{}", display(.0))]
pub struct TrajectoryError(Box<Inner>);

#[derive(Debug, Clone, PartialEq)]
struct Inner {
    kind: TrajectoryErrorKind,
    pos: SourcePos,
}

/// Every kind gets " at file:line:col".
fn display(inner: &Inner) -> String {
    format!("{} at {}", inner.kind, inner.pos)
}

impl TrajectoryError {
    /// An error of `kind` for the element written at `pos`.
    pub(crate) fn new(kind: TrajectoryErrorKind, pos: &SourcePos) -> Self {
        Self(Box::new(Inner {
            kind,
            pos: pos.clone(),
        }))
    }

    /// What went wrong.
    pub fn kind(&self) -> &TrajectoryErrorKind {
        &self.0.kind
    }

    /// Where (file, 1-based line and column).
    pub fn pos(&self) -> &SourcePos {
        &self.0.pos
    }
}

/// `Err` unless every value is finite; `what` names the attribute.
pub(crate) fn check_finite(
    values: &[(&'static str, f64)],
    pos: &SourcePos,
) -> Result<(), TrajectoryError> {
    match values.iter().find(|(_, v)| !v.is_finite()) {
        Some(&(what, found)) => Err(TrajectoryError::new(
            TrajectoryErrorKind::NotFinite { what, found },
            pos,
        )),
        None => Ok(()),
    }
}
