//! Bad input never panics: random damage to a valid scenario (bytes replaced, spans cut out,
//! the text truncated) either loads or fails with an error whose position lies inside the text.

use std::path::Path;

use proptest::prelude::*;
use scenario::Scenario;

const VALID: &str = include_str!("../files/errors/valid.xosc");

fn fixture_path() -> &'static Path {
    Path::new(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/tests/files/errors/valid.xosc"
    ))
}

/// Loads `text` and checks that an error, if any, points inside it.
fn load_and_check(text: &str) {
    match Scenario::load_from_str(text, fixture_path(), &[]) {
        Ok(_) => {}
        Err(e) => {
            let lines = u32::try_from(text.lines().count()).unwrap() + 1;
            assert!(e.pos().line >= 1 && e.pos().line <= lines, "{e}");
            assert!(e.pos().col >= 1, "{e}");
            assert!(!e.to_string().is_empty());
        }
    }
}

#[test]
fn the_undamaged_text_loads() {
    let s = Scenario::load_from_str(VALID, fixture_path(), &[]).unwrap();
    assert_eq!(s.entities.scenario_objects[0].name, "Ego");
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 256, ..ProptestConfig::default() })]

    #[test]
    fn replaced_bytes_never_panic(at in 0usize..VALID.len(), with in proptest::char::range(' ', '~')) {
        let mut text = VALID.to_owned();
        if text.is_char_boundary(at) && text.is_char_boundary(at + 1) {
            text.replace_range(at..at + 1, &with.to_string());
        }
        load_and_check(&text);
    }

    #[test]
    fn cut_spans_never_panic(from in 0usize..VALID.len(), len in 0usize..200) {
        let to = (from + len).min(VALID.len());
        let mut text = VALID.to_owned();
        if text.is_char_boundary(from) && text.is_char_boundary(to) {
            text.replace_range(from..to, "");
        }
        load_and_check(&text);
    }

    #[test]
    fn truncated_text_never_panics(at in 0usize..VALID.len()) {
        if VALID.is_char_boundary(at) {
            load_and_check(&VALID[..at]);
        }
    }
}
