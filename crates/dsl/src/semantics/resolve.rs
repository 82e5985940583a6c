//! Resolution: concrete values for every field of every instance (ASAM OpenSCENARIO DSL 2.1
//! §7.3.6: unconstrained fields take any value allowed; oscsim samples them from a seed).
//!
//! Stages: build the instance tree with the list sizes decided so far, lower every constraint,
//! propagate; while some list is still unsized, sample the sizes of those lists and start over
//! with them fixed; then sample every remaining variable. The same seed gives the same values.

use std::collections::HashMap;

use super::check::{Invocation, Template};
use super::diagnostic::{Diagnostic, DiagnosticKind as K};
use super::hir::Span;
use super::instance::{Node, NodeId, Tree};
use super::lower::lower;
use super::model::Model;
use super::solver::{
    ConstraintKind, Domain, Linear, Relation, SolveError, Solver, Strength, Value as SolverValue,
};
use super::types::Ty;

/// Most elements of one list (each element is a whole instance with its own variables).
const MAX_LIST_LEN: usize = 1000;

/// Most sizing stages (each expands one level of nested lists).
const MAX_STAGES: usize = 16;

/// Origin tag of a list size the resolver decided (not a user constraint).
const DECIDED: u32 = u32::MAX;

/// A concrete value.
#[derive(Debug, Clone, PartialEq)]
pub enum Value {
    /// `bool`
    Bool(bool),
    /// `int` / `uint`
    Int(i64),
    /// `float`
    Float(f64),
    /// A physical quantity: SI value, type name and the unit it prints in.
    Quantity {
        /// The value in SI units.
        si: f64,
        /// The physical type (`length`).
        ty: String,
        /// The SI unit's name (`m`).
        unit: String,
    },
    /// An enumeration member.
    Enum {
        /// The enum.
        ty: String,
        /// The member.
        member: String,
    },
    /// `string`
    Str(String),
    /// A struct or actor with its fields.
    Compound {
        /// The type.
        ty: String,
        /// Fields in declaration order (ancestors' first).
        fields: Vec<(String, Value)>,
    },
    /// A list.
    List(Vec<Value>),
    /// Resolved at run time (road-network element, state variable): its type.
    RunTime(String),
}

/// Concrete values of all globals, top-level fields and scenarios.
#[derive(Debug, Clone, PartialEq)]
pub struct Resolution {
    /// Roots by name, in declaration order.
    pub roots: Vec<(String, Value)>,
}

impl Resolution {
    /// The value at a dotted path (`my_wide_car.axles[0].number_of_wheels`).
    pub fn get(&self, path: &str) -> Option<&Value> {
        // Root names may contain dots (`dut.driving_alongside_group`): take the longest match.
        let (root, rest) = self
            .roots
            .iter()
            .filter(|(n, _)| {
                path.strip_prefix(n.as_str())
                    .is_some_and(|r| r.is_empty() || r.starts_with('.') || r.starts_with('['))
            })
            .max_by_key(|(n, _)| n.len())
            .map(|(n, v)| (v, &path[n.len()..]))?;
        let mut cur = root;
        for p in split_path(rest).into_iter().filter(|p| !p.is_empty()) {
            cur = match (cur, p.parse::<usize>()) {
                (Value::List(items), Ok(i)) => items.get(i)?,
                (Value::Compound { fields, .. }, _) => &fields.iter().find(|(n, _)| *n == p)?.1,
                _ => return None,
            };
        }
        Some(cur)
    }

    /// One line per scalar: `path = value`, in tree order.
    pub fn lines(&self) -> Vec<String> {
        let mut out = Vec::new();
        for (name, v) in &self.roots {
            flatten(name, v, &mut out);
        }
        out
    }
}

fn split_path(path: &str) -> Vec<String> {
    path.replace('[', ".")
        .replace(']', "")
        .split('.')
        .map(str::to_string)
        .collect()
}

fn flatten(path: &str, v: &Value, out: &mut Vec<String>) {
    match v {
        Value::Compound { fields, .. } => {
            for (n, f) in fields {
                flatten(&format!("{path}.{n}"), f, out);
            }
        }
        Value::List(items) => {
            out.push(format!("{path}.size() = {}", items.len()));
            for (i, item) in items.iter().enumerate() {
                flatten(&format!("{path}[{i}]"), item, out);
            }
        }
        other => out.push(format!("{path} = {}", show(other))),
    }
}

/// A scalar as the CLI prints it (full precision, `1.95 m`).
pub fn show(v: &Value) -> String {
    match v {
        Value::Bool(b) => b.to_string(),
        Value::Int(i) => i.to_string(),
        Value::Float(f) => format!("{f}"),
        Value::Quantity { si, unit, .. } => format!("{si} {unit}"),
        Value::Enum { member, .. } => member.clone(),
        Value::Str(s) => format!("{s:?}"),
        Value::RunTime(ty) => format!("<{ty} at run time>"),
        Value::Compound { ty, .. } => format!("<{ty}>"),
        Value::List(items) => format!("<list of {}>", items.len()),
    }
}

/// Resolves every instance of `model` (with an instance per invocation in `invocations`)
/// under `templates` with `seed`.
pub fn resolve(
    model: &Model,
    templates: &[Template],
    invocations: &[Invocation],
    seed: u64,
) -> Result<Resolution, Vec<Diagnostic>> {
    let mut sizes: HashMap<String, usize> = HashMap::new();
    for stage in 0..MAX_STAGES {
        let mut tree = Tree::build(model, &sizes, invocations);
        let lowered = lower(model, templates, &mut tree);
        if !lowered.diags.is_empty() {
            return Err(lowered.diags);
        }
        for (path, n) in &sizes {
            if let Some(id) = tree.paths.iter().position(|p| p == path) {
                if let Node::List(_, size, _) = &tree.nodes[id] {
                    let expr = Linear::var(*size).add_scaled(&Linear::constant(*n as f64), -1.0);
                    tree.problem.add(
                        ConstraintKind::Linear {
                            expr,
                            rel: Relation::Eq,
                        },
                        Strength::Hard,
                        DECIDED,
                    );
                }
            }
        }
        let stage_seed = seed ^ (stage as u64).wrapping_mul(0x9E37_79B9_7F4A_7C15);
        let unsized_lists = tree.unsized_lists();
        let mut solver = Solver::new(&tree.problem, stage_seed)
            .map_err(|e| unsat(&tree, &lowered.origins, e))?;
        if unsized_lists.is_empty() {
            let sol = solver
                .finish()
                .map_err(|e| unsat(&tree, &lowered.origins, e))?;
            let roots = tree
                .roots
                .iter()
                .map(|(n, id)| (n.clone(), value(model, &tree, *id, &sol.values)))
                .collect();
            return Ok(Resolution { roots });
        }
        let size_vars: Vec<_> = unsized_lists
            .iter()
            .filter_map(|n| match &tree.nodes[*n] {
                Node::List(_, v, _) => Some(*v),
                _ => None,
            })
            .collect();
        solver
            .sample(&size_vars)
            .map_err(|e| unsat(&tree, &lowered.origins, e))?;
        for (list, var) in unsized_lists.iter().zip(&size_vars) {
            if let Domain::Number(i) = solver.domain(*var) {
                let n = i.lo.value.max(0.0);
                if n > MAX_LIST_LEN as f64 {
                    let mut spans: Vec<Span> = Vec::new();
                    for c in i.lo.why.iter().chain(&i.hi.why) {
                        let origin = tree.problem.constraints[c.0 as usize].origin as usize;
                        if let Some(s) = lowered.origins.get(origin).filter(|s| !spans.contains(s))
                        {
                            spans.push(*s);
                        }
                    }
                    let span = spans.first().copied().unwrap_or(Span {
                        file: super::hir::FileId(0),
                        start: 0,
                        end: 0,
                    });
                    let msg = format!("list `{}` would have {n} elements; oscsim resolves lists of at most {MAX_LIST_LEN}", tree.paths[*list]);
                    return Err(vec![Diagnostic::new(K::Unsupported, span, msg)]);
                }
                sizes.insert(tree.paths[*list].clone(), n as usize);
            }
        }
    }
    let span = templates.first().map(|t| t.span).unwrap_or(Span {
        file: super::hir::FileId(0),
        start: 0,
        end: 0,
    });
    Err(vec![Diagnostic::new(
        K::Unsupported,
        span,
        format!("lists nested deeper than {MAX_STAGES} levels"),
    )])
}

fn unsat(tree: &Tree, origins: &[Span], e: SolveError) -> Vec<Diagnostic> {
    let (ids, var) = match e {
        SolveError::Unsat { constraints } => (constraints, None),
        SolveError::NoValue { var, constraints } => (constraints, Some(var)),
    };
    let mut spans: Vec<Span> = Vec::new();
    for id in ids {
        let origin = tree.problem.constraints[id.0 as usize].origin;
        if let Some(s) = origins.get(origin as usize) {
            if !spans.contains(s) {
                spans.push(*s);
            }
        }
    }
    spans.sort();
    let Some((first, rest)) = spans.split_first() else {
        let span = origins.first().copied().unwrap_or(Span {
            file: super::hir::FileId(0),
            start: 0,
            end: 0,
        });
        return vec![Diagnostic::new(
            K::Unsatisfiable,
            span,
            "the constraints have no solution",
        )];
    };
    let msg = match var {
        Some(v) => format!(
            "no value of `{}` satisfies the constraints",
            tree.problem.vars[v.0 as usize].name
        ),
        None if rest.is_empty() => "this constraint cannot hold".to_string(),
        None => format!(
            "the constraints have no solution: this constraint conflicts with {} other(s)",
            rest.len()
        ),
    };
    let mut d = Diagnostic::new(K::Unsatisfiable, *first, msg);
    for s in rest {
        d = d.with(*s, "conflicting constraint");
    }
    vec![d]
}

fn value(model: &Model, tree: &Tree, id: NodeId, values: &[SolverValue]) -> Value {
    match &tree.nodes[id] {
        Node::Scalar(v, ty) => scalar(model, ty, &values[v.0 as usize]),
        Node::Compound(c, fields) => Value::Compound {
            ty: model.compound(*c).name.clone(),
            fields: fields
                .iter()
                .map(|(n, f)| (n.clone(), value(model, tree, *f, values)))
                .collect(),
        },
        Node::List(_, _, items) => Value::List(
            items
                .iter()
                .flatten()
                .map(|i| value(model, tree, *i, values))
                .collect(),
        ),
        Node::Reference(ty) | Node::State(ty) => Value::RunTime(model.type_name(ty)),
    }
}

fn scalar(model: &Model, ty: &Ty, v: &SolverValue) -> Value {
    match (ty, v) {
        (Ty::Bool, SolverValue::Member(m)) => Value::Bool(*m == 1),
        (Ty::Int | Ty::Uint, SolverValue::Number(x)) => Value::Int(*x as i64),
        // `+ 0.0` turns a -0 from propagation into 0.
        (Ty::Float, SolverValue::Number(x)) => Value::Float(*x + 0.0),
        (Ty::Physical(d), SolverValue::Number(x)) => {
            let x = &(*x + 0.0);
            let ty = model.type_name(&Ty::Physical(*d));
            let unit = model
                .units
                .display_unit(&ty)
                .map(|u| u.name.clone())
                .unwrap_or_else(|| d.to_string());
            Value::Quantity { si: *x, ty, unit }
        }
        (Ty::Enum(e), SolverValue::Member(m)) => {
            let def = model.enum_def(*e);
            Value::Enum {
                ty: def.name.clone(),
                member: def.members.get(*m as usize).cloned().unwrap_or_default(),
            }
        }
        (_, SolverValue::Text(s)) => Value::Str(s.clone()),
        (ty, _) => Value::RunTime(model.type_name(ty)),
    }
}
