//! Catalogs (OpenSCENARIO 1.3 §9.4 "Catalogs", XSD `CatalogLocations`, `Catalog`,
//! `CatalogReference`, `ParameterAssignment`).
//!
//! Every `.xosc` file in a CatalogLocations directory (resolved relative to the scenario
//! file) is parsed once; its `Catalog@name` names the catalog a CatalogReference looks in.
//! An entry is read with the scope chain [scenario globals, entry declarations overridden
//! by the reference's ParameterAssignments]; the assignments' values are resolved in the
//! referencing scope first.

use crate::error::{Error, ErrorKind, Result};
use crate::model::CatalogOrigin;
use crate::reader::context::{CatalogFile, Ctx, Node, Scope};
use crate::reader::params::read_parameter_declarations;
use crate::warning::Warning;

/// Reads the CatalogReference `reference` and then its entry with `read`, returning what
/// `read` built and where it came from.
pub(crate) fn read_catalog_reference<'a, T>(
    ctx: &mut Ctx<'a>,
    reference: Node<'a>,
    read: impl FnOnce(&mut Ctx<'a>, Node<'a>) -> Result<T>,
) -> Result<(T, CatalogOrigin)> {
    let catalog_name: String = ctx.req(reference, "catalogName")?;
    let entry_name: String = ctx.req(reference, "entryName")?;
    let mut assignments = Vec::new();
    if let Some(list) = ctx.opt_child(reference, "ParameterAssignments") {
        for a in ctx.children(list, "ParameterAssignment") {
            let name = ctx.param_name(a, "parameterRef")?;
            let value: String = ctx.req(a, "value")?;
            assignments.push((name, value));
        }
    }
    let pos = ctx.pos(reference);
    let named: Vec<&CatalogFile<'a>> = ctx
        .catalogs
        .files
        .iter()
        .filter(|f| f.name == catalog_name)
        .collect();
    // esmini finds entries whatever the Catalog@name (its corpus has an Environment catalog
    // named "VehicleCatalog"); when no catalog has the name, any catalog's entry of that name
    // is taken, with a warning.
    let by_name = !named.is_empty();
    let candidates: Vec<&CatalogFile<'a>> = if by_name {
        named
    } else {
        ctx.catalogs.files.iter().collect()
    };
    let found = candidates.iter().find_map(|f| {
        f.node
            .children()
            .find(|e| e.is_element() && e.attribute("name") == Some(entry_name.as_str()))
            .map(|e| (f.doc, e, f.name.clone()))
    });
    let Some((doc, entry, found_in)) = found else {
        if !by_name {
            let searched = ctx.catalogs.dirs.clone();
            let missing = ctx.catalogs.missing_dirs.clone();
            return Err(Error::new(
                ErrorKind::CatalogNotFound {
                    catalog: catalog_name,
                    searched,
                    missing,
                },
                pos,
            ));
        }
        let searched = candidates
            .iter()
            .map(|f| ctx.docs[f.doc].path.to_path_buf())
            .collect();
        return Err(Error::new(
            ErrorKind::CatalogEntryNotFound {
                catalog: catalog_name,
                entry: entry_name,
                searched,
            },
            pos,
        ));
    };
    if !by_name {
        let file = ctx.docs[doc].path.display().to_string();
        ctx.warnings.push(Warning {
            message: format!(
                "no catalog is named '{catalog_name}'; entry '{entry_name}' taken from catalog '{found_in}' in {file}"
            ),
            pos: pos.clone(),
        });
    }
    let origin = CatalogOrigin {
        catalog_name,
        entry_name,
        parameter_assignments: assignments.clone(),
        file: ctx.docs[doc].path.to_path_buf(),
        pos,
    };
    // An entry that (through a Trailer, say) refers to itself would recurse for ever.
    let label = format!("{}/{}", origin.catalog_name, origin.entry_name);
    if ctx
        .entry_stack
        .iter()
        .any(|(d, id, _)| *d == doc && *id == entry.id())
    {
        let from = ctx
            .entry_stack
            .iter()
            .position(|(d, id, _)| *d == doc && *id == entry.id())
            .unwrap_or(0);
        let mut cycle: Vec<String> = ctx.entry_stack[from..]
            .iter()
            .map(|(_, _, l)| l.clone())
            .collect();
        cycle.push(label);
        return Err(Error::new(ErrorKind::CatalogCycle { cycle }, origin.pos));
    }
    ctx.entry_stack.push((doc, entry.id(), label));
    let saved_cur = std::mem::replace(&mut ctx.cur, doc);
    let globals = ctx.scopes.first().cloned().unwrap_or_default();
    let saved_scopes = std::mem::replace(&mut ctx.scopes, vec![globals]);
    let result = read_entry(ctx, entry, &assignments, read);
    ctx.scopes = saved_scopes;
    ctx.cur = saved_cur;
    ctx.entry_stack.pop();
    result.map(|value| (value, origin))
}

fn read_entry<'a, T>(
    ctx: &mut Ctx<'a>,
    entry: Node<'a>,
    assignments: &[(String, String)],
    read: impl FnOnce(&mut Ctx<'a>, Node<'a>) -> Result<T>,
) -> Result<T> {
    let scope = match ctx.opt_child(entry, "ParameterDeclarations") {
        Some(decls) => read_parameter_declarations(ctx, decls, assignments)?,
        None => Scope::default(),
    };
    for (name, _) in assignments {
        if !scope.params.iter().any(|(n, _)| n == name) {
            let entry_name = entry.attribute("name").unwrap_or_default().to_owned();
            ctx.warn(entry, format!("ParameterAssignment of '{name}' matches no parameter of catalog entry '{entry_name}'"));
        }
    }
    ctx.scopes.push(scope);
    // The entry's own ParameterDeclarations are in scope now; `Ctx::scoped` must skip them.
    let saved = ctx.entry_scoped.replace((ctx.cur, entry.id()));
    let result = read(ctx, entry);
    ctx.entry_scoped = saved;
    result
}
