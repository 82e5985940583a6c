//! The standard library as `.osc` source shipped inside the crate (ASAM OpenSCENARIO DSL 2.1
//! chapter 8, the domain model; `stdlib/README.md` lists the files and what each declares).
//!
//! `import osc.standard` names all of it; a file without the import sees it as well, behind its
//! own declarations: each file's declarations reside in `stdtypes` or `std` (§7.7.5.2, §8.1.3;
//! `namespace.rs` resolves them).

/// One library file: its name (for messages: `osc/standard/objects.osc`), its namespace and
/// its text.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct LibraryFile {
    /// Path inside the crate's `stdlib/` folder.
    pub name: &'static str,
    /// The namespace its declarations reside in (§8.1.3): `stdtypes` for the sub-module
    /// `types` (physical types, units and the basic structs), `std` for the rest.
    pub namespace: &'static str,
    /// The source.
    pub text: &'static str,
}

macro_rules! library {
    ($($path:literal in $ns:literal),* $(,)?) => {
        &[$(LibraryFile {
            name: $path,
            namespace: $ns,
            text: include_str!(concat!("../../stdlib/", $path)),
        }),*]
    };
}

/// The files of `osc.standard`, in load order, then oscsim's sampling defaults.
pub const STANDARD: &[LibraryFile] = library![
    "osc/standard/physical.osc" in "stdtypes",
    "osc/standard/structs.osc" in "stdtypes",
    "osc/standard/behavioral_model.osc" in "std",
    "osc/standard/objects.osc" in "std",
    "osc/standard/map.osc" in "std",
    "osc/standard/actions.osc" in "std",
    "osc/standard/modifiers.osc" in "std",
    "osc/standard/environment.osc" in "std",
    "osc/standard/traffic_lights.osc" in "std",
    "osc/standard/groups.osc" in "std",
    "oscsim/defaults.osc" in "std",
];

/// Library module names an `import` may name, each with the files it loads.
pub fn module(name: &str) -> Option<&'static [LibraryFile]> {
    match name {
        "osc.standard"
        | "osc.standard.all"
        | "osc.standard.types"
        | "osc.standard.domain"
        | "osc.standard.base" => Some(STANDARD),
        _ => None,
    }
}
