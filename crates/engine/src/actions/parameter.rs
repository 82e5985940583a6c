//! ParameterSetAction and ParameterModifyAction (OpenSCENARIO 1.3 §7.7.1 "GlobalAction",
//! XSD `ParameterAction`, deprecated since 1.2 in favour of variables): change a parameter's
//! value at runtime. Shares the rule with VariableAction (`modify_value`).
//!
//! The new value must meet the parameter's ConstraintGroups (OpenSCENARIO 1.2+
//! `ValueConstraintGroup`: every constraint of at least one group), as its declared and
//! `--param` values must when the scenario loads; a value that does not is a run error at the
//! action, naming the parameter and the constraints, and the parameter keeps its old value.
//! (Variables have no constraints in 1.3: XSD `VariableDeclaration`.)

use std::collections::BTreeMap;

use scenario::expr::Value;
use scenario::{ModifyRule, SourcePos, ValueConstraintGroup};

use crate::error::Error;
use crate::store::World;

/// Applies `rule` to parameter `name`.
pub(crate) fn apply(
    world: &mut World,
    name: &str,
    rule: &ModifyRule,
    pos: &SourcePos,
) -> Result<(), Error> {
    modify_value(&mut world.parameters, "parameter", name, rule, pos, |new| {
        meets_constraints(&world.parameter_constraints, name, new)
            .map_err(|expected| Error::at(expected, new.to_string(), pos))
    })
}

/// Whether `value` meets parameter `name`'s ConstraintGroups in `constraints` (a parameter
/// without any meets them); `Err` says what they allow ("parameter Limit greaterOrEqual 0 and
/// lessOrEqual 40 or equalTo 100"). Serves the actions here and `Engine::set_parameter`.
pub(crate) fn meets_constraints(
    constraints: &BTreeMap<String, Vec<ValueConstraintGroup>>,
    name: &str,
    value: &Value,
) -> Result<(), String> {
    let groups = constraints.get(name).map_or(&[][..], Vec::as_slice);
    ValueConstraintGroup::check(groups, value)
        .map_err(|allowed| format!("parameter {name} {allowed}"))
}

/// Applies `rule` to entry `name` of `store` (parameters or variables): Set parses the text as
/// the declared type; Add and Multiply need a numeric value and keep its type. The new value
/// is stored once `accept` has accepted it.
pub(crate) fn modify_value(
    store: &mut BTreeMap<String, Value>,
    what: &str,
    name: &str,
    rule: &ModifyRule,
    pos: &SourcePos,
    accept: impl FnOnce(&Value) -> Result<(), Error>,
) -> Result<(), Error> {
    let Some(old) = store.get(name) else {
        return Err(Error::at(
            format!("a declared {what}"),
            format!("'{name}'"),
            pos,
        ));
    };
    let ty = old.value_type();
    let new = match rule {
        ModifyRule::Set(text) => Value::parse(ty, text).map_err(|e| {
            Error::at(
                format!("a value of type {}", ty.xsd_name()),
                format!("'{text}' ({e})"),
                pos,
            )
        })?,
        ModifyRule::AddValue(v) | ModifyRule::MultiplyByValue(v) => {
            let Some(x) = old.as_f64() else {
                return Err(Error::at(
                    format!("a numeric {what}"),
                    format!("'{name}' of type {}", ty.xsd_name()),
                    pos,
                ));
            };
            let (y, op) = if matches!(rule, ModifyRule::AddValue(_)) {
                (x + v, "+")
            } else {
                (x * v, "*")
            };
            // A double overflows to ±inf (then NaN): refused as a declared value or an
            // expression result that is not finite is (scenario crate, Value::parse).
            if !y.is_finite() {
                return Err(Error::at(
                    format!("a finite value of {what} '{name}'"),
                    format!("{x:e} {op} {v:e} = {y}"),
                    pos,
                ));
            }
            Value::Double(y).convert_to(ty).map_err(|e| {
                Error::at(
                    format!("a value of type {}", ty.xsd_name()),
                    format!("{y} ({e})"),
                    pos,
                )
            })?
        }
        _ => return Err(Error::unsupported("this modify rule", pos)),
    };
    accept(&new)?;
    store.insert(name.to_owned(), new);
    Ok(())
}
