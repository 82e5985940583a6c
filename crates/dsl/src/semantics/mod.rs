//! Semantics of the OpenSCENARIO DSL 2.1: resolution, types and units, standard library,
//! constraints.
//!
//! | module | implements |
//! | --- | --- |
//! | `units` | physical types, units, dimensions over SI base units (§7.3.4) |
//! | `solver` | constraint solving for `keep` (§7.3.6): interval propagation, defaults, seeded sampling |
//! | `stdlib` | the standard library `osc.standard` as shipped `.osc` source (chapter 8) |
//! | `hir` | the checker's view of a file (declarations, members, behaviors, expressions) |
//! | `namespace` | namespace resolution: top-level names to their qualified form (§7.7.3–§7.7.4) |
//! | `collect` | declarations of all files into a `Model`: names, inheritance, fields, methods (§7.3) |
//! | `declarations` | rules on declarations: events and parameters once, method overrides (§7.3.7.2), behavior and conditional inheritance (§7.3.8), enum members against type names (§7.7.4.2) |
//! | `model` | the declaration tables and lookups (fields and methods through inheritance) |
//! | `types` | static types; physical types identified by dimension (§7.3.1) |
//! | `check` | type checking of members, constraints, behaviors, modifier applicability (§7.3, §7.4, §8.9); invocations of behaviors with a `do` and recursive ones (§7.3.9) |
//! | `instance` | the instance tree of a program: one solver variable per scalar field, one instance per invocation of a behavior with a `do` |
//! | `lower` | checked constraints over instances → solver constraints |
//! | `resolve` | staged list sizing, solving and concrete values |
//! | `diagnostic` | semantic errors with spans and related spans |

pub mod check;
pub mod collect;
mod declarations;
pub mod diagnostic;
pub mod hir;
pub mod instance;
pub mod lower;
pub mod lower_ast;
pub mod model;
pub mod namespace;
pub mod program;
pub mod resolve;
pub mod solver;
pub mod stdlib;
pub mod types;
pub mod units;
