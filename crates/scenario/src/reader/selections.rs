//! Entity name checks and EntitySelection expansion (OpenSCENARIO 1.3 §7.2.2 "Entities";
//! XSD `EntitySelection`, `SelectedEntities`).
//!
//! Every entity reference read anywhere in the scenario (and its catalogs) must name a
//! ScenarioObject or an EntitySelection. A selection's members expand to scenario objects:
//! nested selections recursively, ByType to every object of that type. A selection that
//! contains itself through other selections is an error naming the cycle.

use crate::error::{Error, ErrorKind, Result};
use crate::model::{Entities, EntityObject, ObjectType, SelectionMember};
use crate::reader::context::EntityUse;

/// Checks unique names and that every used name is declared.
pub(crate) fn check_entity_names(entities: &Entities, uses: &[EntityUse]) -> Result<()> {
    let mut seen = std::collections::HashSet::new();
    let objects = entities.scenario_objects.iter().map(|o| (&o.name, &o.pos));
    let selections = entities.entity_selections.iter().map(|s| (&s.name, &s.pos));
    for (name, pos) in objects.chain(selections) {
        if !seen.insert(name.as_str()) {
            return Err(Error::new(
                ErrorKind::DuplicateEntity { name: name.clone() },
                pos.clone(),
            ));
        }
    }
    for u in uses {
        if !seen.contains(u.name.as_str()) {
            return Err(Error::new(
                ErrorKind::UnknownEntity {
                    name: u.name.clone(),
                    element: u.element.clone(),
                },
                u.pos.clone(),
            ));
        }
    }
    Ok(())
}

/// Fills `EntitySelection::objects` of every selection.
pub(crate) fn expand_selections(entities: &mut Entities) -> Result<()> {
    let mut expanded = Vec::with_capacity(entities.entity_selections.len());
    for i in 0..entities.entity_selections.len() {
        let mut members = vec![false; entities.scenario_objects.len()];
        let mut stack = Vec::new();
        expand(entities, i, &mut stack, &mut members)?;
        let names = entities
            .scenario_objects
            .iter()
            .zip(&members)
            .filter(|(_, &m)| m)
            .map(|(o, _)| o.name.clone())
            .collect();
        expanded.push(names);
    }
    for (s, objects) in entities.entity_selections.iter_mut().zip(expanded) {
        s.objects = objects;
    }
    Ok(())
}

fn expand(
    entities: &Entities,
    i: usize,
    stack: &mut Vec<usize>,
    members: &mut [bool],
) -> Result<()> {
    let selection = &entities.entity_selections[i];
    if let Some(from) = stack.iter().position(|&s| s == i) {
        let mut cycle: Vec<String> = stack[from..]
            .iter()
            .map(|&s| entities.entity_selections[s].name.clone())
            .collect();
        cycle.push(selection.name.clone());
        // The selection that refers back is the last one entered (`stack` holds `i`, so it is
        // not empty).
        let closing = &entities.entity_selections[stack.last().copied().unwrap_or(i)];
        return Err(Error::new(
            ErrorKind::SelectionCycle { cycle },
            closing.pos.clone(),
        ));
    }
    stack.push(i);
    for m in &selection.members {
        match m {
            SelectionMember::EntityRef(name) => {
                if let Some(o) = entities
                    .scenario_objects
                    .iter()
                    .position(|o| &o.name == name)
                {
                    members[o] = true;
                } else if let Some(s) = entities
                    .entity_selections
                    .iter()
                    .position(|s| &s.name == name)
                {
                    expand(entities, s, stack, members)?;
                }
            }
            SelectionMember::ByType(t) => {
                for (o, flag) in entities.scenario_objects.iter().zip(members.iter_mut()) {
                    if object_type(&o.entity_object) == *t {
                        *flag = true;
                    }
                }
            }
        }
    }
    stack.pop();
    Ok(())
}

/// The XSD `ObjectType` of an entity object.
pub(crate) fn object_type(o: &EntityObject) -> ObjectType {
    match o {
        EntityObject::Vehicle(_) => ObjectType::Vehicle,
        EntityObject::Pedestrian(_) => ObjectType::Pedestrian,
        EntityObject::MiscObject(_) => ObjectType::Miscellaneous,
        EntityObject::ExternalObjectReference(_) => ObjectType::External,
    }
}
