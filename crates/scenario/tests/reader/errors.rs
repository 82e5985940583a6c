//! Bad input never panics or hangs: each fixture `tests/files/errors/NAME.xosc` fails with
//! the exact message and 1-based line:column in `NAME.expected` ("line:col: message", the
//! file path left out and other paths written from `tests/files` as `$FILES/` so the text does not depend on
//! the checkout). The positions were counted by hand in the fixtures; `tests/files/errors/
//! README.md` says what each position points at.

use std::path::{Path, PathBuf};

use scenario::{ErrorKind, Scenario};

fn fixture(name: &str) -> PathBuf {
    Path::new(concat!(env!("CARGO_MANIFEST_DIR"), "/tests/files/errors")).join(name)
}

fn check(name: &str) {
    let path = fixture(&format!("{name}.xosc"));
    let expected = std::fs::read_to_string(fixture(&format!("{name}.expected"))).unwrap();
    let err = Scenario::load(&path).expect_err("the fixture is broken on purpose");
    assert!(err.pos().file.ends_with(format!("{name}.xosc")), "{err}");
    // Paths in messages are shown relative to `tests/files`, as `$FILES/…`.
    let files = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/files/")
        .display()
        .to_string();
    let actual =
        format!("{}:{}: {}", err.pos().line, err.pos().col, err.kind()).replace(&files, "$FILES/");
    assert_eq!(actual, expected.trim_end(), "{name}");
    // Display appends "at file:line:col".
    let shown = err.to_string();
    assert!(
        shown.ends_with(&format!("{name}.xosc:{}:{}", err.pos().line, err.pos().col)),
        "{shown}"
    );
}

macro_rules! error_cases {
    ($($name:ident),+ $(,)?) => {
        $(#[test]
        fn $name() {
            check(stringify!($name));
        })+
    };
}

error_cases!(
    malformed_xml,
    unknown_element,
    wrong_enum_literal,
    unknown_parameter,
    unknown_entity,
    selection_cycle,
    self_referencing_parameter,
    parameter_cycle,
    division_by_zero,
    wrong_parameter_type,
    missing_attribute,
    missing_road_network_file,
    missing_catalog_entry,
    constraint_violated,
    misspelt_child,
    unknown_storyboard_element,
    unknown_variable,
    duplicate_entity,
    unknown_monitor,
    dtd_entities,
    unclosed_expression,
    negative_performance,
);

#[test]
fn the_valid_twin_of_the_fixtures_loads() {
    // Every error fixture is this file with one fault added, so the faults alone fail.
    let s = Scenario::load(&fixture("valid.xosc")).unwrap();
    assert_eq!(s.entities.scenario_objects.len(), 1);
    assert!(s.warnings.is_empty(), "{:?}", s.warnings);
}

/// A folder of its own below the system's temporary folder, removed with what it holds when
/// the returned value drops (at the test's end, also when it fails).
fn scratch(what: &str) -> tempfile::TempDir {
    tempfile::Builder::new()
        .prefix(&format!("oscsim-{what}-"))
        .tempdir()
        .unwrap()
}

#[test]
fn a_100_mb_file_is_refused_before_reading() {
    let dir = scratch("scenario");
    let path = dir.path().join("huge.xosc");
    let file = std::fs::File::create(&path).unwrap();
    // A sparse file: 100 MB long without writing 100 MB.
    file.set_len(100 * 1000 * 1000).unwrap();
    let err = Scenario::load(&path).unwrap_err();
    let ErrorKind::FileTooLarge { size, limit, .. } = err.kind() else {
        panic!("{err}")
    };
    assert_eq!(*size, 100_000_000);
    assert_eq!(*limit, 64 * 1024 * 1024);
    assert_eq!((err.pos().line, err.pos().col), (1, 1));
    // 100 000 000 B / 1 048 576 B/MiB = 95.37 MiB.
    assert!(
        err.to_string()
            .starts_with("expected a file of at most 64 MiB, found "),
        "{err}"
    );
    assert!(err.to_string().contains("with 95.4 MiB at "), "{err}");
}

#[test]
fn an_8_mb_blank_file_is_malformed_xml_not_a_hang() {
    let dir = scratch("scenario-ws");
    let path = dir.path().join("blank.xosc");
    // 8 MB of spaces and newlines: no root element. 100 000 lines of 80 spaces + '\n'.
    let line = format!("{}\n", " ".repeat(80));
    std::fs::write(&path, line.repeat(100_000)).unwrap();
    let err = Scenario::load(&path).unwrap_err();
    assert!(matches!(err.kind(), ErrorKind::Xml { .. }), "{err}");
    // roxmltree reports a missing root element at the start of the document.
    assert_eq!((err.pos().line, err.pos().col), (1, 1), "{err}");
}

#[test]
fn deeply_nested_elements_do_not_overflow_the_stack() {
    let dir = scratch("scenario-deep");
    let path = dir.path().join("deep.xosc");
    // valid.xosc with 200 000 nested <Deep> elements in the Storyboard.
    let valid = std::fs::read_to_string(fixture("valid.xosc")).unwrap();
    let depth = 200_000;
    let nest = format!("{}{}", "<Deep>".repeat(depth), "</Deep>".repeat(depth));
    let text = valid.replacen("  <Storyboard>\n", &format!("  <Storyboard>{nest}\n"), 1);
    std::fs::write(&path, text).unwrap();
    let err = Scenario::load(&path).unwrap_err();
    // The Storyboard's child check stops at the first <Deep>: line 18 of valid.xosc, after the
    // 2 spaces and 12 characters of `  <Storyboard>`, column 15.
    assert_eq!((err.pos().line, err.pos().col), (18, 15), "{err}");
    assert!(err
        .to_string()
        .starts_with("expected one of Init, Story, StopTrigger in Storyboard, found element Deep"));
}

#[test]
fn a_catalog_entry_that_contains_itself_is_a_cycle_not_a_stack_overflow() {
    // catalog_cycle.xosc references Cyclic/truck, whose Trailer references Cyclic/truck again.
    let err = Scenario::load(&fixture("catalog_cycle.xosc")).unwrap_err();
    assert_eq!(
        err.kind().to_string(),
        "expected catalog references without cycles, found Cyclic/truck → Cyclic/truck"
    );
    // The inner reference, line 12 of catalogs_cyclic/Cyclic.xosc, indented by 10.
    assert!(
        err.pos().file.ends_with("catalogs_cyclic/Cyclic.xosc"),
        "{err}"
    );
    assert_eq!((err.pos().line, err.pos().col), (12, 11));
}

#[test]
fn recursively_nested_positions_stop_at_the_nesting_limit() {
    // valid.xosc with its TeleportAction position replaced by RoutePositions nested 2000 deep
    // (Position → RoutePosition → RouteRef → Route → Waypoint → Position …), which the
    // readers would otherwise follow recursively.
    let valid = std::fs::read_to_string(fixture("valid.xosc")).unwrap();
    let levels = 2000;
    let open = r#"<Position><RoutePosition><RouteRef><Route name="r" closed="false"><Waypoint routeStrategy="shortest">"#;
    let close = r#"</Waypoint></Route></RouteRef><InRoutePosition><FromRoadCoordinates pathS="0" t="0"/></InRoutePosition></RoutePosition></Position>"#;
    let inner = r#"<Position><WorldPosition x="0" y="0"/></Position>"#;
    let nested = format!("{}{inner}{}", open.repeat(levels), close.repeat(levels));
    let teleport = r#"<Position><LanePosition roadId="1" laneId="-1" s="10"/></Position>"#;
    assert!(valid.contains(teleport));
    let text = valid.replacen(teleport, &nested, 1);
    let path = fixture("valid.xosc");
    let err = Scenario::load_from_str(&text, &path, &[]).unwrap_err();
    let ErrorKind::TooDeep { limit, .. } = err.kind() else {
        panic!("{err}")
    };
    assert_eq!(*limit, 256);
    // All of it is on line 23 of valid.xosc.
    assert_eq!(err.pos().line, 23, "{err}");
}

#[test]
fn a_long_chain_of_parameter_references_is_refused_not_overflowed() {
    // 10 000 declarations p0 = $p1, p1 = $p2, …, p9999 = 1 in one block.
    let valid = std::fs::read_to_string(fixture("valid.xosc")).unwrap();
    let n = 10_000;
    let mut decls = String::new();
    for i in 0..n - 1 {
        decls.push_str(&format!(
            "<ParameterDeclaration name=\"p{i}\" parameterType=\"double\" value=\"$p{}\"/>\n",
            i + 1
        ));
    }
    decls.push_str(&format!(
        "<ParameterDeclaration name=\"p{}\" parameterType=\"double\" value=\"1\"/>\n",
        n - 1
    ));
    let text = valid.replacen(
        "  <ParameterDeclarations>\n",
        &format!("  <ParameterDeclarations>\n{decls}"),
        1,
    );
    let err = Scenario::load_from_str(&text, &fixture("valid.xosc"), &[]).unwrap_err();
    assert!(
        matches!(err.kind(), ErrorKind::ParameterChainTooLong { limit: 256 }),
        "{err}"
    );
    // The declarations start on line 5; the 257th link, p256, is on line 5 + 256 = 261, its
    // value after `<ParameterDeclaration name="p256" parameterType="double" value="` (64
    // characters).
    assert_eq!((err.pos().line, err.pos().col), (261, 65), "{err}");
}

#[test]
fn a_file_of_millions_of_elements_is_refused_at_the_node_limit() {
    // 5 000 000 empty elements (35 MB) inside the root: more nodes than the 4 000 000 the
    // loader parses, so memory stays bounded.
    let text = format!("<OpenSCENARIO>{}</OpenSCENARIO>", "<a/>".repeat(5_000_000));
    let err = Scenario::load_from_str(&text, &fixture("huge.xosc"), &[]).unwrap_err();
    assert!(matches!(err.kind(), ErrorKind::Xml { .. }), "{err}");
    assert!(err.to_string().contains("nodes limit reached"), "{err}");
}
