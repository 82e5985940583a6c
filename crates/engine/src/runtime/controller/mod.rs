//! Controllers (OpenSCENARIO 1.3 §7.5 "Controllers"): what moves an entity each step. Only the
//! default controller exists; other controllers are rejected by the controller actions.

mod default;

pub(crate) use default::{move_entity, place_on_track};
