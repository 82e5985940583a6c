//! What one road answers on its own, before any network exists (OpenDRIVE 1.8 §8.3 reference
//! line coordinates, §10.5 superelevation, §11.4–§11.6 lane offsets and widths): the road frame
//! at s, lane spans, stretches where the lanes stay constant and where the frame runs along one
//! piece (a straight line: its pose without a look-up), the horizontal placement for the
//! projection, and the spatial index of road pieces a [`RoadNetwork`](crate::RoadNetwork)
//! keeps. Module `query` asks these of a network's roads.

mod constant_lanes;
pub(crate) mod frame;
mod frame_stretch;
pub(crate) mod lane_span;
pub(crate) mod pieces_by_distance;
pub(crate) mod plan_frame;
mod point_grid;
pub(crate) mod spatial;

pub use constant_lanes::CONSTANT_MARGIN;
pub use frame_stretch::FrameStretch;
pub use lane_span::LaneSpan;
pub(crate) use spatial::SpatialIndex;
