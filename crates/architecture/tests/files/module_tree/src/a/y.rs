// Back to x by the full path: x <-> y is a cycle of folder a.
use crate::a::x::X;
pub struct Why;
