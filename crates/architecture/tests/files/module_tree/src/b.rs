// A folder in the `b.rs` + `b/` layout.
mod p;
mod q;
mod r;
