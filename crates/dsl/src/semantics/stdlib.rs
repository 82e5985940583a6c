//! The standard library as `.osc` source shipped inside the crate (ASAM OpenSCENARIO DSL 2.1
//! chapter 8, the domain model; `stdlib/README.md` lists the files and what each declares).
//!
//! `import osc.standard` names all of it; a file without the import sees it as well
//! (2.1 keeps the import only for compatibility with 2.0).

/// One library file: its name (for messages: `osc/standard/objects.osc`) and its text.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct LibraryFile {
    /// Path inside the crate's `stdlib/` folder.
    pub name: &'static str,
    /// The source.
    pub text: &'static str,
}

macro_rules! library {
    ($($path:literal),* $(,)?) => {
        &[$(LibraryFile { name: $path, text: include_str!(concat!("../../stdlib/", $path)) }),*]
    };
}

/// The files of `osc.standard`, in load order, then oscsim's sampling defaults.
pub const STANDARD: &[LibraryFile] = library![
    "osc/standard/physical.osc",
    "osc/standard/structs.osc",
    "osc/standard/objects.osc",
    "osc/standard/map.osc",
    "osc/standard/actions.osc",
    "osc/standard/modifiers.osc",
    "osc/standard/groups.osc",
    "oscsim/defaults.osc",
];

/// Library module names an `import` may name, each with the files it loads.
pub fn module(name: &str) -> Option<&'static [LibraryFile]> {
    match name {
        "osc.standard" | "osc.standard.all" | "osc.standard.base" => Some(STANDARD),
        _ => None,
    }
}
