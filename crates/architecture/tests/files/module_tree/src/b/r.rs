#[path = "r_impl.rs"]
mod imp;
pub struct R;
