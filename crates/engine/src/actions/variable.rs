//! VariableSetAction and VariableModifyAction (OpenSCENARIO 1.3 §7.7.1 "GlobalAction",
//! XSD `VariableAction`, 1.2+): change a variable's value at runtime.

use scenario::{ModifyRule, SourcePos};

use super::parameter::modify_value;
use crate::error::Error;
use crate::store::World;

/// Applies `rule` to variable `name`.
pub(crate) fn apply(
    world: &mut World,
    name: &str,
    rule: &ModifyRule,
    pos: &SourcePos,
) -> Result<(), Error> {
    modify_value(
        &mut world.variables,
        "variable",
        name,
        rule,
        pos,
        |_| Ok(()),
    )
}
