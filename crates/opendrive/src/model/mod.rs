//! The typed OpenDRIVE data model, one file per part of the standard.

mod controller;
mod header;
mod junction;
mod lanes;
mod objects;
mod road;
mod road_mark;

pub use controller::Controller;
pub use header::{GeoReference, Header, Offset};
pub use junction::{Connection, ContactPoint, Junction, JunctionKind, LaneLink};
pub use lanes::{is_drivable, Lane, LaneHeight, LaneSection, LaneType, MarkStretch};
pub use objects::{Corner, Object, Signal};
pub use road::{
    ElementType, Road, RoadLink, RoadLinks, RoadType, SectionStretch, Speed, TrafficRule,
};
pub use road_mark::{RoadMark, RoadMarkColor, RoadMarkLaneChange, RoadMarkLine, RoadMarkType};
