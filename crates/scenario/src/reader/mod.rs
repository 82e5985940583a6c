//! Readers from XML to the model, one per XSD element group; each function names the XSD
//! element it reads (`read_speed_action` reads `SpeedAction`).

pub(crate) mod appearance;
pub(crate) mod catalog;
pub(crate) mod compat;
pub(crate) mod conditions;
pub(crate) mod context;
pub(crate) mod entities;
pub(crate) mod environment;
pub(crate) mod files;
pub(crate) mod global_actions;
pub(crate) mod params;
pub(crate) mod positions;
pub(crate) mod private_actions;
pub(crate) mod references;
pub(crate) mod resolve;
pub(crate) mod road_network;
pub(crate) mod routing;
pub(crate) mod scenario;
pub(crate) mod selections;
pub(crate) mod storyboard;
pub(crate) mod traffic;
