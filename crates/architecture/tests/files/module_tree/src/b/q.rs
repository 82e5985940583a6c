// Out of folder b: b -> a at the root.
use crate::a::Why;
pub struct Q;
// A comment naming super::p and a string "super::p" are no use.
const S: &str = "super::p";
