//! OpenSCENARIO 1.3 §9.2.1 functions with the signatures the standard lists (round, floor,
//! ceil: double → int; sqrt and the trigonometric functions: double → double; sign, abs:
//! numeric → numeric; max, min: numeric, numeric → numeric; pow: double, double → double).
//! Expected values are closed forms, worked out in the comments.

use scenario::expr::{evaluate, Value};

const TOL: f64 = 1e-15; // one or two ulps around 1: the libm functions are correctly rounded or close

fn eval(source: &str) -> Value {
    let lookup = |name: &str| match name {
        "acceleration" => Some(Value::Double(2.0)),
        "distance" => Some(Value::Double(25.0)),
        "n" => Some(Value::UnsignedInt(9)),
        _ => None,
    };
    match evaluate(source, &lookup) {
        Ok(v) => v,
        Err(e) => panic!("{source}: {e} at offset {}", e.offset()),
    }
}

fn double(source: &str) -> f64 {
    match eval(source) {
        Value::Double(d) => d,
        other => panic!("{source} = {other:?}, expected a double"),
    }
}

#[test]
fn round_floor_ceil_give_ints() {
    // round halves away from zero: 2.5 → 3, -2.5 → -3, 2.4999 → 2.
    assert_eq!(eval("round(2.5)"), Value::Int(3));
    assert_eq!(eval("round(-2.5)"), Value::Int(-3));
    assert_eq!(eval("round(2.4999)"), Value::Int(2));
    assert_eq!(eval("floor(2.7)"), Value::Int(2));
    assert_eq!(eval("floor(-2.2)"), Value::Int(-3));
    assert_eq!(eval("ceil(2.2)"), Value::Int(3));
    assert_eq!(eval("ceil(-2.7)"), Value::Int(-2));
    // An int argument converts implicitly: ceil(4) = 4.
    assert_eq!(eval("ceil(4)"), Value::Int(4));
    // The results are ints, so int arithmetic follows: round(1.3) % ceil(1.23) = 1 % 2 = 1.
    assert_eq!(eval("round(1.3) % ceil(1.23)"), Value::Int(1));
}

#[test]
fn sqrt_and_pow() {
    assert_eq!(eval("sqrt(9)"), Value::Double(3.0));
    // The standard's example sqrt(2 * $acceleration * $distance) = sqrt(2·2·25) = sqrt(100) = 10.
    assert_eq!(
        eval("sqrt(2* $acceleration * $distance)"),
        Value::Double(10.0)
    );
    assert!((double("sqrt(2)") - std::f64::consts::SQRT_2).abs() <= TOL);
    // pow(3.2, 3) = 3.2³ = 32.768.
    assert!((double("pow(3.2,3)") - 32.768).abs() <= 1e-12);
    // pow(2, -1) = 0.5; pow(4, 0.5) = 2; pow(2, 10) = 1024 is a double, not an int.
    assert_eq!(eval("pow(2, -1)"), Value::Double(0.5));
    assert_eq!(eval("pow(4, 0.5)"), Value::Double(2.0));
    assert_eq!(eval("pow(2, 10)"), Value::Double(1024.0));
}

#[test]
fn trigonometric_functions_in_radians() {
    use std::f64::consts::{FRAC_PI_2, FRAC_PI_4, FRAC_PI_6, PI};
    // sin(π/6) = 1/2, cos(π/3) = 1/2, tan(π/4) = 1, cos(0) = 1, sin(0) = 0.
    let pi = PI;
    let cases = [
        (format!("sin({})", FRAC_PI_6), 0.5),
        (format!("cos({})", pi / 3.0), 0.5),
        (format!("tan({})", FRAC_PI_4), 1.0),
        ("cos(0)".to_owned(), 1.0),
        ("sin(0)".to_owned(), 0.0),
        // asin(1) = π/2, acos(-1) = π, atan(1) = π/4, acos(0.5) = π/3.
        ("asin(1)".to_owned(), FRAC_PI_2),
        ("acos(-1)".to_owned(), pi),
        ("atan(1)".to_owned(), FRAC_PI_4),
        ("acos(0.5)".to_owned(), pi / 3.0),
    ];
    for (source, expected) in cases {
        let got = double(&source);
        assert!(
            (got - expected).abs() <= 4.0 * TOL,
            "{source} = {got}, expected {expected}"
        );
    }
}

#[test]
fn sign_and_abs_keep_the_type() {
    assert_eq!(eval("sign(-4)"), Value::Int(-1));
    assert_eq!(eval("sign(0)"), Value::Int(0));
    assert_eq!(eval("sign(12)"), Value::Int(1));
    assert_eq!(eval("sign(-0.3)"), Value::Double(-1.0));
    // sign(0.0) is 0, not 1 (Rust's f64::signum would say 1).
    assert_eq!(eval("sign(0.0)"), Value::Double(0.0));
    assert_eq!(eval("abs(-4)"), Value::Int(4));
    assert_eq!(eval("abs(-4.25)"), Value::Double(4.25));
    assert_eq!(eval("abs($n)"), Value::UnsignedInt(9));
}

#[test]
fn max_and_min() {
    assert_eq!(eval("max(3, 7)"), Value::Int(7));
    assert_eq!(eval("min(3, 7)"), Value::Int(3));
    assert_eq!(eval("max(-1.5, -2)"), Value::Double(-1.5));
    // Mixed int/double: the result is a double, min(2, 2.5) = 2.0.
    assert_eq!(eval("min(2, 2.5)"), Value::Double(2.0));
    // Nested calls and expressions as arguments: max(min(1, 2) * 10, 5 + 1) = max(10, 6) = 10.
    assert_eq!(eval("max(min(1, 2) * 10, 5 + 1)"), Value::Int(10));
}
