//! Semantics of the OpenSCENARIO DSL 2.1: resolution, types and units, standard library,
//! constraints.
