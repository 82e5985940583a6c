//! `docs/coverage.md` lists every element of the OpenSCENARIO 1.3.0 XSD with its parsed and
//! executed state and a note; this test keeps the table and the readers in step.

use std::collections::BTreeSet;
use std::path::Path;

const XSD: &str = concat!(
    env!("CARGO_MANIFEST_DIR"),
    "/../../../shared/corpus/schema/openscenario/1.3.0/OpenSCENARIO.xsd"
);
const TABLE: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/../../docs/coverage.md");

/// The `name` of every `<xsd:element name="…">` of the schema.
fn xsd_elements() -> BTreeSet<String> {
    let text = std::fs::read_to_string(XSD).unwrap();
    text.split("<xsd:element name=\"")
        .skip(1)
        .map(|rest| rest[..rest.find('"').unwrap()].to_owned())
        .collect()
}

/// One row of the table.
struct Row {
    element: String,
    parsed: String,
    executed: String,
    notes: String,
}

/// The rows of the table (element, parsed, executed, notes).
fn table_rows() -> Vec<Row> {
    let text = std::fs::read_to_string(TABLE).unwrap();
    text.lines()
        .filter(|l| l.starts_with("| ") && !l.starts_with("| element") && !l.starts_with("| ---"))
        .map(|l| {
            let cells: Vec<&str> = l.trim_matches('|').split('|').map(str::trim).collect();
            assert_eq!(cells.len(), 4, "row {l}");
            Row {
                element: cells[0].to_owned(),
                parsed: cells[1].to_owned(),
                executed: cells[2].to_owned(),
                notes: cells[3].to_owned(),
            }
        })
        .collect()
}

/// All Rust sources under `dir`, concatenated.
fn sources(dir: &str) -> String {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join(dir);
    let mut text = String::new();
    for entry in std::fs::read_dir(dir).unwrap() {
        let path = entry.unwrap().path();
        if path.extension().is_some_and(|x| x == "rs") {
            text.push_str(&std::fs::read_to_string(path).unwrap());
        }
    }
    text
}

#[test]
fn every_xsd_element_has_exactly_one_row() {
    let elements = xsd_elements();
    // The 1.3.0 schema declares 295 distinct element names.
    assert_eq!(elements.len(), 295);
    let rows = table_rows();
    let named: BTreeSet<String> = rows.iter().map(|r| r.element.clone()).collect();
    assert_eq!(named.len(), rows.len(), "an element has two rows");
    let missing: Vec<&String> = elements.difference(&named).collect();
    let extra: Vec<&String> = named.difference(&elements).collect();
    assert!(missing.is_empty(), "elements without a row: {missing:?}");
    assert!(extra.is_empty(), "rows naming no XSD element: {extra:?}");
}

#[test]
fn the_parsed_column_matches_the_readers() {
    let readers = sources("src/reader");
    let distribution = sources("src/distribution");
    for Row {
        element, parsed, ..
    } in table_rows()
    {
        let literal = format!("\"{element}\"");
        let by_reader = readers.contains(&literal);
        let by_distribution = distribution.contains(&literal);
        match parsed.as_str() {
            "yes" => assert!(
                by_reader,
                "{element} is marked parsed but no reader names it"
            ),
            "yes (distribution)" => {
                assert!(
                    by_distribution,
                    "{element} is marked parsed by the distribution module, which does not name it"
                )
            }
            "no" => assert!(
                !by_reader && !by_distribution,
                "{element} is read but marked not parsed"
            ),
            other => {
                panic!("{element}: parsed must be yes, yes (distribution) or no, found {other}")
            }
        }
    }
}

#[test]
fn the_executed_column_has_its_values_and_gaps_have_notes() {
    for Row {
        element,
        executed,
        notes,
        ..
    } in table_rows()
    {
        assert!(
            matches!(executed.as_str(), "yes" | "no" | "partly"),
            "{element}: executed must be yes, partly or no, found {executed}"
        );
        assert!(
            executed == "yes" || !notes.is_empty(),
            "{element}: a {executed} row needs a note saying what is missing"
        );
    }
}
