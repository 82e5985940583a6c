//! `call` of external methods (ASAM OpenSCENARIO DSL 2.1 §7.3.9 `call` directive, §7.3.6
//! methods `is external`): a method the host program implements, run for its side effects at
//! the moment the `call` is reached in a `do` or its `on` handler's event occurs.
//!
//! The runtime does not run methods itself: a `call` becomes a command to the host, logged in
//! the event log as a `customCommand` of type `call` whose content is the method's name and
//! its arguments evaluated when the scenario is resolved, as JSON values
//! (`log_speed(20.0, "ego")`: numbers in SI units, strings, booleans, enumeration members and
//! instance paths as strings). The host runs the function it bound to that name (the Python
//! package's `Simulation.bind`); a host without bindings (`oscsim run`) refuses the scenario.
//! A method defined by an expression (`is expression e`) can be called too (§7.3.9: `call`
//! calls a method): it has no side effect, so its call evaluates its arguments when the
//! scenario is resolved (an error there at its place) and does nothing else: an instant phase
//! with no command, no binding asked of the host. A method `is undefined` has nothing to run:
//! an error at its name. Arguments are bound to the method's declared parameters as the language
//! binds any argument list (§7.3.9, §7.4: positional ones first, in declaration order, then
//! named ones by name; a parameter given neither takes its declaration's default), and the
//! host receives them in declaration order.
//!
//! The result of an external method is read in conditions (`until m(…) > 3`, `wait`, events):
//! the condition becomes a 1.x UserDefinedValueCondition on the value named by the call's
//! content (`m(args)`), which the host sets to its function's result before each step
//! (`load::Bindings`). Anywhere the plan needs a value before the run (a parameter, a
//! modifier's argument) it has none: the constraint solver leaves it undefined there.

use dsl::semantics::hir::{Arg as HirArg, Expr, ExprKind, MethodBody, Param, Span};

use super::eval::Eval;
use super::value::Val;
use crate::error::{Error, ErrorKind as K};

/// A `call` of an external method, read.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Call {
    /// The method's name.
    pub method: String,
    /// The command's content: `name(args as JSON values)`.
    pub content: String,
    /// Whether the method is external (the host runs it). A method defined by an expression
    /// has no side effect: its call evaluates the arguments and does nothing else, no command.
    pub external: bool,
}

/// Reads the call expression `e` of a `call` directive.
pub(crate) fn read(ev: &Eval<'_>, e: &Expr) -> Result<Call, Error> {
    let ExprKind::Call(callee, args) = &e.kind else {
        return Err(ev.files.err(
            K::Call,
            e.span,
            "expected a method call after `call`, found another expression",
        ));
    };
    let name = match &callee.kind {
        ExprKind::Name(n) => n,
        ExprKind::Field(_, n) => &n.text,
        _ => {
            return Err(ev.files.err(
                K::Call,
                callee.span,
                "expected a method name in `call`, found another expression",
            ))
        }
    };
    let decl = match ev.method_decl(name) {
        Some(d) if matches!(d.body, MethodBody::External | MethodBody::Expression(_)) => d,
        Some(_) => {
            return Err(ev.files.err(
                K::Call,
                callee.span,
                format!("expected a method with an implementation in `call` (def {name}(…) is external … or is expression …), found `{name}` undefined"),
            ))
        }
        None => {
            return Err(ev.files.err(
                K::Call,
                callee.span,
                format!("expected a method declared in the program in `call`, found `{name}`"),
            ))
        }
    };
    let mut values = Vec::with_capacity(decl.params.len());
    for e in bind_params(ev, name, &decl.params, args, e.span)? {
        values.push(json(ev, e)?);
    }
    Ok(Call {
        method: name.clone(),
        content: format!("{name}({})", values.join(", ")),
        external: decl.body == MethodBody::External,
    })
}

/// The arguments of a call of `name` in the order of its declared parameters `params` (§7.3.9:
/// positional arguments first, in declaration order, then named ones by name; a parameter
/// given neither takes its declaration's default). The checker reports the same faults at the
/// same places before the runtime runs; these errors keep a program it let through from
/// calling the host with arguments out of place.
fn bind_params<'e>(
    ev: &Eval<'_>,
    name: &str,
    params: &'e [Param],
    args: &'e [HirArg],
    call: Span,
) -> Result<Vec<&'e Expr>, Error> {
    let mut slots: Vec<Option<&Expr>> = vec![None; params.len()];
    let mut named = false;
    for (i, a) in args.iter().enumerate() {
        let k = match &a.name {
            Some(n) => {
                named = true;
                params
                    .iter()
                    .position(|p| p.name.text == n.text)
                    .ok_or_else(|| {
                        ev.files.err(
                            K::Argument,
                            n.span,
                            format!("expected a parameter of `{name}` in `call`, found `{}:`", n.text),
                        )
                    })?
            }
            None if named => {
                return Err(ev.files.err(
                    K::Argument,
                    a.value.span,
                    format!("expected named arguments after a named one in `call` of `{name}`, found a positional argument"),
                ))
            }
            None if i >= params.len() => {
                return Err(ev.files.err(
                    K::Argument,
                    a.value.span,
                    format!("expected at most {} arguments in `call` of `{name}`, found {}", params.len(), args.len()),
                ))
            }
            None => i,
        };
        if slots[k].replace(&a.value).is_some() {
            return Err(ev.files.err(
                K::Argument,
                a.name.as_ref().map_or(a.value.span, |n| n.span),
                format!(
                    "expected `{}` once in `call` of `{name}`, found it again",
                    params[k].name.text
                ),
            ));
        }
    }
    slots
        .into_iter()
        .zip(params)
        .map(|(s, p)| {
            s.or(p.default.as_ref()).ok_or_else(|| {
                ev.files.err(
                    K::Argument,
                    call,
                    format!("expected an argument for parameter `{}` of `{name}` in `call`, found none (it has no default)", p.name.text),
                )
            })
        })
        .collect()
}

/// When `e` calls a method declared `is external`: the call, read (its result is a value the
/// host provides at run time, `Cond::Measured`).
pub(crate) fn external(ev: &Eval<'_>, e: &Expr) -> Result<Option<Call>, Error> {
    let ExprKind::Call(callee, _) = &e.kind else {
        return Ok(None);
    };
    let name = match &callee.kind {
        ExprKind::Name(n) => n,
        ExprKind::Field(_, n) => &n.text,
        _ => return Ok(None),
    };
    match ev.method_decl(name).map(|d| &d.body) {
        Some(MethodBody::External) => read(ev, e).map(Some),
        _ => Ok(None),
    }
}

/// An argument as a JSON value.
fn json(ev: &Eval<'_>, e: &Expr) -> Result<String, Error> {
    if let ExprKind::Str(s) = &e.kind {
        return Ok(string(s));
    }
    Ok(match ev.eval(e)? {
        Val::Num(x) if x.is_finite() => format!("{x:?}"),
        Val::Num(x) => {
            return Err(ev.files.err(
                K::Value,
                e.span,
                format!("expected a finite number as an argument of `call`, found {x}"),
            ))
        }
        Val::Bool(b) => b.to_string(),
        Val::Enum(s) | Val::Instance(s) => string(&s),
    })
}

/// `s` as a JSON string.
fn string(s: &str) -> String {
    serde_json::Value::from(s).to_string()
}
