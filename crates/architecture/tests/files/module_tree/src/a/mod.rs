mod x;
mod y;
pub use y::Why;
