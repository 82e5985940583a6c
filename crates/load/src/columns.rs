//! What a batch of seeds tabulates of each run's resolved scenario (docs/batch.md, "Variation
//! by seeds"): the values the constraint solver chose (ASAM OpenSCENARIO DSL 2.1 §7.3.6
//! constraints, resolved with the run's seed) for
//!
//! 1. the top-level parameters of the scenario that runs: its own fields that are not state
//!    variables (`var`), and
//! 2. every field path its `keep(…)` constraints name (`overtaker.bounding_box.length`),
//!
//! each where the resolution holds a scalar there (a number, a quantity in SI units, an enum
//! member, a boolean, a string), in source order, without repeats. Actors and structs as a
//! whole (`ego: vehicle`) have no column; their constrained fields do.

use dsl::semantics::hir::{Expr, ExprKind, Member};
use dsl::semantics::types::CompoundId;
use dsl::{CheckedProgram, Resolution, Value};

/// The dotted path an expression names (`ego.bounding_box.length`, `g.vehicles[0]`).
fn path_of(e: &Expr) -> Option<String> {
    match &e.kind {
        ExprKind::Name(n) => Some(n.clone()),
        ExprKind::Field(inner, n) => Some(format!("{}.{}", path_of(inner)?, n.text)),
        ExprKind::Index(inner, i) => match i.kind {
            ExprKind::Int(i) => Some(format!("{}[{i}]", path_of(inner)?)),
            _ => None,
        },
        _ => None,
    }
}

/// Every maximal path `e` names, in source order.
fn paths(e: &Expr, out: &mut Vec<String>) {
    if let Some(p) = path_of(e) {
        out.push(p);
        return;
    }
    match &e.kind {
        ExprKind::Field(inner, _) | ExprKind::Neg(inner) | ExprKind::Not(inner) => {
            paths(inner, out)
        }
        ExprKind::Cast(inner, _) | ExprKind::TypeTest(inner, _) => paths(inner, out),
        ExprKind::Index(a, b) | ExprKind::Binary(_, a, b) | ExprKind::Range(a, b) => {
            paths(a, out);
            paths(b, out);
        }
        ExprKind::Ternary(a, b, c) => {
            paths(a, out);
            paths(b, out);
            paths(c, out);
        }
        ExprKind::List(items) => items.iter().for_each(|i| paths(i, out)),
        // A method's arguments (`l.size()` names no value of its own).
        ExprKind::Call(_, args) | ExprKind::Temporal(_, args) => {
            args.iter().for_each(|a| paths(&a.value, out))
        }
        _ => {}
    }
}

/// The constrained paths of `members` (module doc), relative to the scenario.
fn member_paths(members: &[Member], out: &mut Vec<String>) {
    for m in members {
        match m {
            Member::Field(f) if !f.is_var => {
                out.extend(f.names.iter().map(|n| n.text.clone()));
            }
            Member::Keep(k) => paths(&k.expr, out),
            Member::For { body, .. } => member_paths(body, out),
            _ => {}
        }
    }
}

/// The scalar at `path` of the scenario `root` in `res`, as the results table writes it:
/// numbers in SI units with the shortest text that reads back to the same double.
pub(crate) fn value_text(res: &Resolution, root: &str, path: &str) -> Option<String> {
    Some(match res.get(&format!("{root}.{path}"))? {
        Value::Bool(b) => b.to_string(),
        Value::Int(i) => i.to_string(),
        Value::Float(x) | Value::Quantity { si: x, .. } => format!("{x}"),
        Value::Enum { member, .. } => member.clone(),
        Value::Str(s) => s.clone(),
        Value::Compound { .. } | Value::List(_) | Value::RunTime(_) => return None,
    })
}

/// The entry scenario's name and its columns (module doc), the scalars checked in `res` (any
/// seed's resolution: the solver gives every field a value of its type whatever the seed).
pub(crate) fn columns(
    program: &CheckedProgram,
    res: &Resolution,
    entry: CompoundId,
) -> (String, Vec<String>) {
    let scenario = program.model.compound(entry);
    let mut found = Vec::new();
    member_paths(&scenario.members, &mut found);
    let mut out: Vec<String> = Vec::new();
    for p in found {
        if !out.contains(&p) && value_text(res, &scenario.name, &p).is_some() {
            out.push(p);
        }
    }
    (scenario.name.clone(), out)
}
