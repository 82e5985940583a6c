// Module b::r::imp (by its path attribute): r -> q in folder b.
use super::super::q::Q;
