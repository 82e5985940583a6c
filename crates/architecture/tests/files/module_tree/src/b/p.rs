use self::inner::I;
use super::q::Q;
mod inner {
    // From an inline module: still p's use of r.
    use super::super::r::R;
    pub struct I;
}
