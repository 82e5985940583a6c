//! [`Trajectory`]: a shape of OpenSCENARIO 1.3 §6.9 ("Trajectories", XSD `Shape`) as pieces
//! laid end to end, evaluated by horizontal arc length s from its start, with its times where
//! the shape has them (§6.9).
//!
//! s is measured in the horizontal plane, as road s is along an OpenDRIVE reference line and
//! as `position::resolve` measures TrajectoryPosition s; z follows the shape.

use opendrive::Real;

use super::clothoid::Clothoid;
use super::line::Line;
use super::nurbs::Nurbs;
use super::orientation::Orientations;
use super::time_table::TimeTable;
use super::{TrajectoryClock, TrajectoryPoint};

/// Which XSD `Shape` a trajectory was built from.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[non_exhaustive]
pub enum ShapeKind {
    /// `Polyline`.
    Polyline,
    /// `Clothoid`.
    Clothoid,
    /// `ClothoidSpline` (1.3).
    ClothoidSpline,
    /// `Nurbs`.
    Nurbs,
}

/// One piece of a trajectory.
#[derive(Debug, Clone, PartialEq)]
pub(crate) enum Piece {
    Line(Line),
    Clothoid(Clothoid),
    Nurbs(Box<Nurbs>),
}

impl Piece {
    fn length(&self) -> Real {
        match self {
            Piece::Line(l) => l.length(),
            Piece::Clothoid(c) => c.length(),
            Piece::Nurbs(n) => n.length(),
        }
    }

    fn eval(&self, ds: Real) -> TrajectoryPoint {
        match self {
            Piece::Line(l) => l.eval(ds),
            Piece::Clothoid(c) => c.eval(ds),
            Piece::Nurbs(n) => n.eval(ds).0,
        }
    }
}

/// A trajectory ready for the runtime: evaluation by s, length, times.
#[derive(Debug, Clone, PartialEq)]
pub struct Trajectory {
    name: String,
    kind: ShapeKind,
    closed: bool,
    pieces: Vec<Piece>,
    /// s at which each piece starts.
    starts: Vec<Real>,
    length: Real,
    times: Option<TimeTable>,
    /// The headings of a six-dimensional Polyline (every vertex states one).
    orientations: Option<Orientations>,
}

impl Trajectory {
    /// A trajectory of `pieces` (at least one, positive total length: checked by `build`).
    pub(crate) fn new(
        name: &str,
        kind: ShapeKind,
        closed: bool,
        pieces: Vec<Piece>,
        times: Option<TimeTable>,
    ) -> Self {
        let mut starts = Vec::with_capacity(pieces.len());
        let mut length = 0.0;
        for p in &pieces {
            starts.push(length);
            length += p.length();
        }
        Self {
            name: name.to_string(),
            kind,
            closed,
            pieces,
            starts,
            length,
            times,
            orientations: None,
        }
    }

    /// This trajectory with the vertex headings of a six-dimensional Polyline.
    pub(crate) fn with_orientations(self, orientations: Orientations) -> Self {
        Self {
            orientations: Some(orientations),
            ..self
        }
    }

    /// `Trajectory/@name`.
    pub fn name(&self) -> &str {
        &self.name
    }

    /// The shape it was built from.
    pub fn kind(&self) -> ShapeKind {
        self.kind
    }

    /// `Trajectory/@closed` (a closed Polyline also runs from its last vertex to its first).
    pub fn closed(&self) -> bool {
        self.closed
    }

    /// Total horizontal length (m).
    pub fn length(&self) -> Real {
        self.length
    }

    /// The point at arc length `s`, clamped to [0, length]. At a joint between two pieces
    /// (polyline vertex, spline segment start) the later piece answers, so the heading there
    /// is the next piece's (they differ at a polyline corner or a segment's `hOffset`).
    pub fn eval(&self, s: Real) -> TrajectoryPoint {
        let s = if s.is_nan() {
            0.0
        } else {
            s.clamp(0.0, self.length)
        };
        let i = self
            .starts
            .partition_point(|&x| x <= s)
            .clamp(1, self.pieces.len())
            - 1;
        let p = self.pieces[i].eval(s - self.starts[i]);
        TrajectoryPoint { s, ..p }
    }

    /// The point at arc length `s` moved `t` metres to the left of the trajectory's heading
    /// (TrajectoryPosition's `s` and `t`, OpenSCENARIO 1.3 XSD `TrajectoryPosition`), with
    /// the curvature of that offset curve, κ/(1 − κt) (0 where 1 − κt vanishes, the centre
    /// of curvature).
    pub fn point_at(&self, s: Real, t: Real) -> TrajectoryPoint {
        let p = self.eval(s);
        let (sin_h, cos_h) = p.heading.sin_cos();
        let scale = 1.0 - p.curvature * t;
        TrajectoryPoint {
            x: p.x - t * sin_h,
            y: p.y + t * cos_h,
            curvature: if scale != 0.0 {
                p.curvature / scale
            } else {
                0.0
            },
            ..p
        }
    }

    /// The heading an entity on the trajectory has at arc length `s` when the shape states
    /// one (a Polyline whose every vertex has an orientation, OpenSCENARIO 1.3 §6.9); `None`
    /// where the entity faces along the tangent ([`TrajectoryPoint::heading`]).
    pub fn orientation_at(&self, s: Real) -> Option<Real> {
        self.orientations.as_ref().map(|o| o.at(s))
    }

    /// The arc lengths where pieces meet (polyline vertices, spline segment starts).
    pub(crate) fn joints(&self) -> &[Real] {
        &self.starts
    }

    /// Whether the shape carries times (every vertex, control point or segment has one).
    pub fn has_times(&self) -> bool {
        self.times.is_some()
    }

    /// The trajectory time at which s is reached, if the shape has times.
    pub fn time_at(&self, s: Real) -> Option<Real> {
        self.times.as_ref().map(|tt| tt.t_at(s))
    }

    /// The arc length reached at trajectory time `t`, if the shape has times (clamped to the
    /// first and last time).
    pub fn s_at_time(&self, t: Real) -> Option<Real> {
        self.times.as_ref().map(|tt| tt.s_at(t))
    }

    /// The trajectory's first and last time, if it has times.
    pub fn time_range(&self) -> Option<(Real, Real)> {
        self.times.as_ref().map(|tt| (tt.start(), tt.end()))
    }

    /// Arc length at simulation time `sim_time` under `clock` (FollowTrajectoryAction with
    /// Timing), if the shape has times.
    pub fn s_at_simulation_time(&self, clock: &TrajectoryClock, sim_time: Real) -> Option<Real> {
        self.s_at_time(clock.trajectory_time(sim_time))
    }

    /// The speed-continuous reading of the times for `follow` mode (see
    /// `TimeTable::continuous_speeds`), starting at `v_start` m/s of simulation time; `None`
    /// without times.
    pub(crate) fn continuous_speeds(
        &self,
        clock: &TrajectoryClock,
        v_start: Real,
    ) -> Option<Vec<(Real, Real)>> {
        self.times
            .as_ref()
            .map(|tt| tt.continuous_speeds(v_start / clock.rate()))
    }

    /// Arc length at simulation time `sim_time` under `clock` on the reading `speeds` of
    /// [`continuous_speeds`](Self::continuous_speeds); `None` without times.
    pub(crate) fn s_at_simulation_time_continuous(
        &self,
        clock: &TrajectoryClock,
        speeds: &[(Real, Real)],
        sim_time: Real,
    ) -> Option<Real> {
        self.times
            .as_ref()
            .map(|tt| tt.s_at_continuous(speeds, clock.trajectory_time(sim_time)))
    }

    /// Speed along the trajectory (m/s of simulation time) at `sim_time` under `clock`: the
    /// slope of s over the vertex interval, divided by the timing's scale; 0 before the first
    /// and after the last time. `None` without times.
    pub fn speed_at_simulation_time(
        &self,
        clock: &TrajectoryClock,
        sim_time: Real,
    ) -> Option<Real> {
        self.times
            .as_ref()
            .map(|tt| tt.speed_at(clock.trajectory_time(sim_time)) * clock.rate())
    }

    /// Speed (m/s of simulation time) on arrival at the trajectory's end under `clock`: the
    /// slope of s over the last timed interval, divided by the timing's scale. `None` without
    /// times.
    pub fn arrival_speed(&self, clock: &TrajectoryClock) -> Option<Real> {
        self.times
            .as_ref()
            .map(|tt| tt.arrival_speed() * clock.rate())
    }

    /// Simulation time at which s is reached under `clock`, if the shape has times.
    pub fn simulation_time_at(&self, clock: &TrajectoryClock, s: Real) -> Option<Real> {
        self.time_at(s).map(|t| clock.simulation_time(t))
    }
}
