//! The standard library against the domain model of ASAM OpenSCENARIO DSL 2.1 (chapter 8):
//! `files/domain_model.txt` lists every physical type, enum, struct, actor, action and modifier
//! of the standard with its section; the library must declare each under its name and kind.
//! The test names every line it misses (issue 30, class 4).

use dsl::semantics::hir::CompoundKind;
use dsl::semantics::model::TypeName;

/// One declaration the standard requires: `(section, kind, name)`.
fn required() -> Vec<(String, String, String)> {
    let path =
        std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/files/domain_model.txt");
    let text = std::fs::read_to_string(&path).expect("domain_model.txt");
    text.lines()
        .map(str::trim)
        .filter(|l| !l.is_empty() && !l.starts_with('#'))
        .map(|l| {
            let parts: Vec<&str> = l.split_whitespace().collect();
            assert_eq!(parts.len(), 3, "not `SECTION KIND NAME`: {l}");
            (
                parts[0].to_string(),
                parts[1].to_string(),
                parts[2].to_string(),
            )
        })
        .collect()
}

#[test]
fn the_library_declares_every_item_of_the_domain_model() {
    let program = dsl::check_source("empty.osc", "").expect("an empty file checks");
    let m = &program.model;
    let compound = |name: &str, kind: CompoundKind| match m.types.get(name) {
        Some((TypeName::Compound(c), _)) => m.compound(*c).kind == kind,
        _ => false,
    };
    let behavior = |name: &str, kind: CompoundKind| {
        m.behaviors
            .get(name)
            .is_some_and(|b| m.compound(*b).kind == kind)
    };
    let list = required();
    let missing: Vec<String> = list
        .iter()
        .filter(|(_, kind, name)| !match kind.as_str() {
            "type" => matches!(m.types.get(name.as_str()), Some((TypeName::Physical(_), _))),
            "enum" => matches!(m.types.get(name.as_str()), Some((TypeName::Enum(_), _))),
            "struct" => compound(name, CompoundKind::Struct),
            "actor" => compound(name, CompoundKind::Actor),
            "action" => behavior(name, CompoundKind::Action),
            "modifier" => behavior(name, CompoundKind::Modifier),
            other => panic!("unknown kind `{other}` for {name}"),
        })
        .map(|(section, kind, name)| format!("§{section} {kind} {name}"))
        .collect();
    assert!(
        missing.is_empty(),
        "the standard library lacks {} of {} declarations:\n{}",
        missing.len(),
        list.len(),
        missing.join("\n")
    );
}

/// The list is the chapter, not a sample: every kind is there in numbers (counted by hand from
/// the file: 16 physical types, 60 enums and structs and actors together at least, 50 actions
/// and modifiers at least), so a truncated file fails here rather than passing quietly.
#[test]
fn the_list_covers_the_chapter() {
    let list = required();
    let count = |k: &str| list.iter().filter(|(_, kind, _)| kind == k).count();
    assert_eq!(count("type"), 16, "§8.13.1 declares 16 physical types");
    assert!(count("enum") + count("struct") + count("actor") >= 60);
    assert!(count("action") + count("modifier") >= 50);
    // Sections are chapter 8 numbers.
    assert!(list.iter().all(|(s, _, _)| s.starts_with("8.")));
}
