//! ParameterDeclarations (OpenSCENARIO 1.3 §9.1 "Parameters", XSD `ParameterDeclaration`,
//! `ValueConstraintGroup`): typed values, overrides, constraint checks and cycle detection.
//!
//! The values of one ParameterDeclarations block may refer to each other (`$a`, `${$a * 2}`)
//! in any order: each declaration is resolved after the declarations of the same block it
//! names, by a depth-first walk that reports a self-reference or a cycle ("a → b → a") at the
//! value attribute that closes it, instead of looping. A declaration that names itself refers
//! to the enclosing scope's parameter of that name if there is one (shadowing).

use std::collections::HashMap;

use crate::error::{Error, ErrorKind, Result};
use crate::expr::{Value, ValueType};
use crate::model::{ParameterDeclaration, ValueConstraint, ValueConstraintGroup};
use crate::reader::context::{Ctx, Node, Scope};
use crate::warning::Warning;

/// Longest chain of declarations of one block that refer to each other (a → b → c …).
const MAX_CHAIN: usize = 256;

/// One declaration before resolution.
struct Pending<'a> {
    node: Node<'a>,
    name: String,
    ty: ValueType,
    /// The override's text (already resolved by the caller), if any.
    given: Option<String>,
    deps: Vec<usize>,
}

/// Reads a ParameterDeclarations element into a scope. `overrides` are (name, value) pairs
/// from ParameterAssignments or `--param`, whose values are used as written.
pub(crate) fn read_parameter_declarations<'a>(
    ctx: &mut Ctx<'a>,
    decls: Node<'a>,
    overrides: &[(String, String)],
) -> Result<Scope> {
    Ok(declare(ctx, decls, overrides)?.0)
}

/// As [`read_parameter_declarations`], also giving the model's declaration records.
pub(crate) fn declare<'a>(
    ctx: &mut Ctx<'a>,
    decls: Node<'a>,
    overrides: &[(String, String)],
) -> Result<(Scope, Vec<ParameterDeclaration>)> {
    let mut pending = Vec::new();
    for d in ctx.children(decls, "ParameterDeclaration") {
        let name = ctx.param_name(d, "name")?;
        let ty = read_parameter_type(ctx, d, "parameterType")?;
        if ctx.raw_attr(d, "value").is_none() {
            return Err(ctx.err(
                d,
                ErrorKind::MissingAttribute {
                    element: "ParameterDeclaration".into(),
                    attribute: "value",
                },
            ));
        }
        let given = overrides
            .iter()
            .rev()
            .find(|(n, _)| *n == name)
            .map(|(_, v)| v.clone());
        pending.push(Pending {
            node: d,
            name,
            ty,
            given,
            deps: Vec::new(),
        });
    }
    // Name → index of its last declaration. Names should be unique in one block, but
    // esmini's corpus repeats some; the last declaration wins (as in esmini), with a warning.
    let mut last: HashMap<String, usize> = HashMap::with_capacity(pending.len());
    for (i, p) in pending.iter().enumerate() {
        if last.insert(p.name.clone(), i).is_some() {
            let pos = ctx
                .raw_attr(p.node, "name")
                .map_or_else(|| ctx.pos(p.node), |a| ctx.attr_pos(&a));
            let message = format!(
                "parameter '{}' is declared twice in one ParameterDeclarations; the last declaration wins",
                p.name
            );
            ctx.warnings.push(Warning { message, pos });
        }
    }
    for (i, p) in pending.iter_mut().enumerate() {
        if p.given.is_none() {
            let raw = ctx
                .raw_attr(p.node, "value")
                .map(|a| a.value())
                .unwrap_or_default();
            // A declaration naming itself means the enclosing scope's parameter when there
            // is one (`Speed = ${$Speed * 2}` in a Story); otherwise it is a self-reference.
            let outer = ctx.lookup(&p.name).is_some();
            p.deps = referenced_names(raw)
                .filter_map(|r| last.get(r).copied())
                .filter(|&j| !(j == i && outer))
                .collect();
        }
    }
    ctx.scopes.push(Scope::default());
    let mut state = vec![State::Pending; pending.len()];
    let mut records = Vec::new();
    let mut result = Ok(());
    for i in 0..pending.len() {
        let mut stack = Vec::new();
        result = visit(ctx, &pending, &mut state, &mut stack, i, &mut records);
        if result.is_err() {
            break;
        }
    }
    // The scope pushed above is still on top: `visit` only adds to it.
    let scope = ctx.scopes.pop().unwrap_or_default();
    result.map(|()| (scope, records))
}

#[derive(Clone, Copy, PartialEq)]
enum State {
    Pending,
    InProgress,
    Done,
}

fn visit<'a>(
    ctx: &mut Ctx<'a>,
    pending: &[Pending<'a>],
    state: &mut [State],
    stack: &mut Vec<usize>,
    i: usize,
    records: &mut Vec<ParameterDeclaration>,
) -> Result<()> {
    match state[i] {
        State::Done => return Ok(()),
        State::InProgress => {
            let from = stack.iter().position(|&s| s == i).unwrap_or(0);
            let mut cycle: Vec<String> = stack[from..]
                .iter()
                .map(|&s| pending[s].name.clone())
                .collect();
            cycle.push(pending[i].name.clone());
            // The declaration whose value closes the cycle is the last one on the stack.
            let closing = pending[stack.last().copied().unwrap_or(i)].node;
            let pos = ctx
                .raw_attr(closing, "value")
                .map_or_else(|| ctx.pos(closing), |a| ctx.attr_pos(&a));
            return Err(Error::new(ErrorKind::ParameterCycle { cycle }, pos));
        }
        State::Pending => {}
    }
    if stack.len() >= MAX_CHAIN {
        // Each link is a recursive call; a chain this long is not a real scenario.
        let node = pending[i].node;
        let pos = ctx
            .raw_attr(node, "value")
            .map_or_else(|| ctx.pos(node), |a| ctx.attr_pos(&a));
        return Err(Error::new(
            ErrorKind::ParameterChainTooLong { limit: MAX_CHAIN },
            pos,
        ));
    }
    state[i] = State::InProgress;
    stack.push(i);
    for &d in &pending[i].deps {
        visit(ctx, pending, state, stack, d, records)?;
    }
    stack.pop();
    let p = &pending[i];
    let value_attr = ctx.raw_attr(p.node, "value");
    let text = match (&p.given, &value_attr) {
        (Some(given), _) => given.clone(),
        (None, Some(a)) => ctx.resolve(p.node, a)?,
        (None, None) => String::new(),
    };
    let pos = value_attr
        .as_ref()
        .map_or_else(|| ctx.pos(p.node), |a| ctx.attr_pos(a));
    // A value that does not fit the declared type (esmini's controller catalog declares
    // `FollowMode` a double with value "time") is kept as a string with a warning; an
    // attribute that needs the declared type then fails at the attribute that uses it.
    let value = match Value::parse(p.ty, &text) {
        Ok(v) => v,
        Err(_) => {
            let message = format!(
                "parameter {} is declared {} but its value '{text}' is not one; kept as a string",
                p.name,
                p.ty.xsd_name()
            );
            ctx.warnings.push(Warning {
                message,
                pos: pos.clone(),
            });
            Value::String(text.clone())
        }
    };
    let constraint_groups = check_constraints(ctx, p.node, &p.name, &value)?;
    if let Some(top) = ctx.scopes.last_mut() {
        top.params.push((p.name.clone(), value.clone()));
    }
    records.push(ParameterDeclaration {
        name: p.name.clone(),
        parameter_type: p.ty,
        value,
        pos,
        constraint_groups,
    });
    state[i] = State::Done;
    Ok(())
}

/// Reads a `ParameterType` attribute (`integer` is the deprecated spelling of `int`).
pub(crate) fn read_parameter_type<'a>(
    ctx: &mut Ctx<'a>,
    n: Node<'a>,
    attr: &'static str,
) -> Result<ValueType> {
    let text: String = ctx.req(n, attr)?;
    let ty = ValueType::from_xsd_name(text.trim()).ok_or_else(|| {
        let pos = ctx
            .raw_attr(n, attr)
            .map_or_else(|| ctx.pos(n), |a| ctx.attr_pos(&a));
        Error::new(
            ErrorKind::InvalidValue {
                element: n.tag_name().name().into(),
                attribute: attr.into(),
                expected:
                    "one of int, double, string, unsignedInt, unsignedShort, boolean, dateTime"
                        .into(),
                found: text.clone(),
            },
            pos,
        )
    })?;
    if text.trim() == "integer" {
        ctx.warn(
            n,
            format!(
                "{}@{attr}: 'integer' is deprecated, read as 'int'",
                n.tag_name().name()
            ),
        );
    }
    Ok(ty)
}

/// The names of `$name` references in raw attribute text.
pub(crate) fn referenced_names(raw: &str) -> impl Iterator<Item = &str> {
    raw.match_indices('$').filter_map(move |(i, _)| {
        let rest = &raw[i + 1..];
        let end = rest
            .find(|c: char| !(c.is_alphanumeric() || c == '_'))
            .unwrap_or(rest.len());
        (end > 0).then(|| &rest[..end])
    })
}

/// The ConstraintGroups (1.2+) of declaration `decl` of parameter `name`, checked on `value`
/// (the value must meet every constraint of at least one group).
fn check_constraints<'a>(
    ctx: &mut Ctx<'a>,
    decl: Node<'a>,
    name: &str,
    value: &Value,
) -> Result<Vec<ValueConstraintGroup>> {
    let nodes: Vec<Node<'a>> = ctx.children(decl, "ConstraintGroup").collect();
    if let Some(first) = nodes.first() {
        ctx.since(*first, 2);
    }
    let mut groups = Vec::new();
    for g in nodes {
        let mut constraints = Vec::new();
        for c in ctx.children(g, "ValueConstraint") {
            constraints.push(ValueConstraint {
                rule: ctx.req(c, "rule")?,
                value: ctx.req(c, "value")?,
            });
        }
        groups.push(ValueConstraintGroup { constraints });
    }
    if let Err(expected) = ValueConstraintGroup::check(&groups, value) {
        return Err(ctx.err(
            decl,
            ErrorKind::ConstraintViolated {
                name: name.to_owned(),
                value: value.to_string(),
                expected,
            },
        ));
    }
    Ok(groups)
}

/// Reading inside a scope: the ParameterDeclarations of an element in force while its
/// content is read (beside the declarations' reader).
impl<'a> Ctx<'a> {
    /// Reads `n` with the ParameterDeclarations of `n` (if any) in scope.
    pub fn scoped<T>(
        &mut self,
        n: Node<'a>,
        read: impl FnOnce(&mut Self) -> Result<T>,
    ) -> Result<T> {
        if self.entry_scoped == Some((self.cur, n.id())) {
            return read(self);
        }
        let Some(decls) = self.opt_child(n, "ParameterDeclarations") else {
            return read(self);
        };
        let scope = read_parameter_declarations(self, decls, &[])?;
        self.scopes.push(scope);
        let result = read(self);
        self.scopes.pop();
        result
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn references_are_found_inside_expressions() {
        let names: Vec<&str> = referenced_names("${$a * 2 + $b_1}").collect();
        assert_eq!(names, ["a", "b_1"]);
        assert_eq!(referenced_names("$x").collect::<Vec<_>>(), ["x"]);
        assert_eq!(referenced_names("plain").count(), 0);
    }

    use crate::model::Rule;

    /// Whether `value` `rule` `bound` holds, through a one-constraint group.
    fn meets(value: &Value, rule: Rule, bound: &str) -> bool {
        let group = ValueConstraintGroup {
            constraints: vec![ValueConstraint {
                rule,
                value: bound.to_owned(),
            }],
        };
        ValueConstraintGroup::check(&[group], value).is_ok()
    }

    #[test]
    fn constraint_rules_compare_numbers_numerically() {
        // 10 > 9 numerically although "10" < "9" as text.
        assert!(meets(&Value::Double(10.0), Rule::GreaterThan, "9"));
        assert!(!meets(&Value::Int(3), Rule::LessThan, "3"));
        assert!(meets(&Value::String("car".into()), Rule::EqualTo, "car"));
    }
}
