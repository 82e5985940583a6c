// Through the folder's re-export: names y.
use super::Why;
pub struct X;
