//! The OpenSCENARIO 1.3 §9.2 expression language: any text as the inside of `${…}`, parsed and
//! evaluated with parameters of every type in scope. Must not panic or hang; an error's byte
//! offsets lie inside the text; evaluation is deterministic.
#![no_main]

use libfuzzer_sys::fuzz_target;

mod support;
use scenario::expr::{Expression, Value};

fn lookup(name: &str) -> Option<Value> {
    Some(match name {
        "$i" | "i" => Value::Int(7),
        "$n" | "n" => Value::Int(i64::MIN),
        "$d" | "d" => Value::Double(2.5),
        "$z" | "z" => Value::Double(0.0),
        "$b" | "b" => Value::Bool(true),
        "$s" | "s" => Value::String("text".into()),
        _ => return None,
    })
}

fuzz_target!(|data: &[u8]| {
    support::watchdog::start(data);
    let Ok(text) = std::str::from_utf8(data) else {
        return;
    };
    match Expression::parse(text) {
        Ok(e) => {
            let a = e.evaluate(&lookup);
            let b = scenario::expr::evaluate(text, &lookup);
            assert_eq!(format!("{a:?}"), format!("{b:?}"));
            let _ = e.parameters();
        }
        Err(e) => {
            assert!(
                e.offset() <= text.len(),
                "{e} at byte {} of {}",
                e.offset(),
                text.len()
            );
            let _ = e.to_string();
        }
    }
});
