//! OpenSCENARIO 1.3 §9.2.1 operators: arithmetic, unary minus, comparisons, `not`/`and`/`or`,
//! precedence and the result types. Expected values are worked out by hand in the comments.

use scenario::expr::{evaluate, Value};

/// Parameters used below: speed = 20.0 (double), lanes = 3 (int), count = 7 (unsignedInt),
/// flag = true (boolean), name = "ego" (string).
fn lookup(name: &str) -> Option<Value> {
    match name {
        "speed" => Some(Value::Double(20.0)),
        "lanes" => Some(Value::Int(3)),
        "count" => Some(Value::UnsignedInt(7)),
        "flag" => Some(Value::Bool(true)),
        "name" => Some(Value::String("ego".into())),
        _ => None,
    }
}

fn eval(source: &str) -> Value {
    match evaluate(source, &lookup) {
        Ok(v) => v,
        Err(e) => panic!("{source}: {e} at offset {}", e.offset()),
    }
}

/// Asserts a double result within `tol` (the tolerance is stated at each call).
fn assert_double(source: &str, expected: f64, tol: f64) {
    match eval(source) {
        Value::Double(d) => assert!(
            (d - expected).abs() <= tol,
            "{source} = {d}, expected {expected}"
        ),
        other => panic!("{source} = {other:?}, expected a double"),
    }
}

#[test]
fn division_is_in_double_precision() {
    // §9.2: "numeric, numeric → double" for "/": 5/2 = 2.5, not the integer 2.
    assert_eq!(eval("5/2"), Value::Double(2.5));
    // 1/3 is the double nearest to 0.333…; exact equality with Rust's own 1.0/3.0.
    assert_eq!(eval("1/3"), Value::Double(1.0 / 3.0));
    // 250 km/h in m/s: 250/3.6 = 69.444…
    assert_double("250/3.6", 69.444_444_444_444_44, 1e-12);
}

#[test]
fn addition_subtraction_multiplication_keep_integers() {
    assert_eq!(eval("2+3"), Value::Int(5));
    assert_eq!(eval("2-3"), Value::Int(-1));
    assert_eq!(eval("4*3"), Value::Int(12));
    // An int parameter: 4*3 - lanes = 12 - 3 = 9.
    assert_eq!(eval("4*3 -$lanes"), Value::Int(9));
    // Two unsigned operands stay unsigned while ≥ 0: 7 + 7 = 14.
    assert_eq!(eval("$count + $count"), Value::UnsignedInt(14));
    // ...and become int below 0: 7 - 10 = -3 (10 is an int literal).
    assert_eq!(eval("$count - 10"), Value::Int(-3));
}

#[test]
fn a_double_operand_makes_a_double() {
    // 2 + 0.5 = 2.5; 20.0 * 2 = 40.0; 3 * 1.5 = 4.5.
    assert_eq!(eval("2 + 0.5"), Value::Double(2.5));
    assert_eq!(eval("$speed * 2"), Value::Double(40.0));
    assert_eq!(eval("$lanes * 1.5"), Value::Double(4.5));
    // The example of the standard's expression proposal: -15 + 3.14 + 23 + 2.1E-7
    // = 11.14 + 0.00000021 = 11.14000021.
    assert_double("-15 + 3.14 + 23 + 2.1E-7", 11.140_000_21, 1e-12);
}

#[test]
fn modulo_follows_the_dividend_sign() {
    // Truncated division remainder: 7 % 3 = 1, -7 % 3 = -1 (−7 = −2·3 − 1), 7 % -3 = 1.
    assert_eq!(eval("7 % 3"), Value::Int(1));
    assert_eq!(eval("-7 % 3"), Value::Int(-1));
    assert_eq!(eval("7 % -3"), Value::Int(1));
    // count % 5 = 7 % 5 = 2; an int, since the literal 5 is an int.
    assert_eq!(eval("$count%5"), Value::Int(2));
    // Both operands unsigned: 7 % 7 = 0, unsigned.
    assert_eq!(eval("$count % $count"), Value::UnsignedInt(0));
    // 5.5 % 2 = 5.5 − 2·2 = 1.5 (exact in binary).
    assert_eq!(eval("5.5 % 2"), Value::Double(1.5));
}

#[test]
fn unary_minus() {
    assert_eq!(eval("-$speed"), Value::Double(-20.0));
    assert_eq!(eval("-$lanes"), Value::Int(-3));
    // Negating an unsigned gives a signed int.
    assert_eq!(eval("-$count"), Value::Int(-7));
    assert_eq!(eval("--4"), Value::Int(4));
    // The smallest i64 is reachable: 9223372036854775808 is read unsigned, then negated.
    assert_eq!(eval("-9223372036854775808"), Value::Int(i64::MIN));
}

#[test]
fn precedence_follows_the_standard() {
    // * before +: 2 + 3*4 = 14; parentheses first: (2+3)*4 = 20.
    assert_eq!(eval("2 + 3*4"), Value::Int(14));
    assert_eq!(eval("(2+3)*4"), Value::Int(20));
    // Left associativity: 10 - 4 - 3 = 3, not 9; 8 / 4 / 2 = 1.0, not 4.
    assert_eq!(eval("10 - 4 - 3"), Value::Int(3));
    assert_eq!(eval("8 / 4 / 2"), Value::Double(1.0));
    // Unary minus binds tighter than %: -7 % 3 = (-7) % 3 = -1 (checked above); and than *.
    assert_eq!(eval("-2 * -3"), Value::Int(6));
    // Functions bind tightest: sqrt(9) + pow(2, 3) * 2 = 3 + 16 = 19.
    assert_eq!(eval("sqrt(9) + pow(2,3) * 2"), Value::Double(19.0));
    // The standard's example (defaultWidth = speed here): (20 + 3)/2 = 11.5.
    assert_eq!(eval("($speed + 3)/2"), Value::Double(11.5));
    // Comparison below +: 1 + 1 == 2 is (1+1) == 2.
    assert_eq!(eval("1 + 1 == 2"), Value::Bool(true));
    // not below comparison: not 1 < 2 is not (1 < 2) = false.
    assert_eq!(eval("not 1 < 2"), Value::Bool(false));
    // and before or: true or false and false = true or (false and false) = true.
    assert_eq!(eval("true or false and false"), Value::Bool(true));
    // (true or false) and false = false.
    assert_eq!(eval("(true or false) and false"), Value::Bool(false));
    // not before and: not false and false = (not false) and false = false.
    assert_eq!(eval("not false and false"), Value::Bool(false));
}

#[test]
fn comparisons() {
    let cases = [
        ("3 == 3", true),
        ("3 == 3.0", true),
        ("3 != 3", false),
        ("2 < 3", true),
        ("3 < 3", false),
        ("3 <= 3", true),
        ("4 > 3.5", true),
        ("3 >= 3.5", false),
        ("$speed >= 20", true),
        ("$count > $lanes", true),
        ("true == true", true),
        ("true != $flag", false),
        // 0.1 + 0.2 is 0.30000000000000004 in doubles: exact comparison says not equal.
        ("0.1 + 0.2 == 0.3", false),
    ];
    for (source, expected) in cases {
        assert_eq!(eval(source), Value::Bool(expected), "{source}");
    }
}

#[test]
fn logical_operators() {
    let cases = [
        ("not true", false),
        ("not not true", true),
        ("true and false", false),
        ("true and true", true),
        ("false or false", false),
        ("false or true", true),
        ("$flag and $speed > 10", true),
        ("not ($lanes == 3) or $count < 5", false),
    ];
    for (source, expected) in cases {
        assert_eq!(eval(source), Value::Bool(expected), "{source}");
    }
}

#[test]
fn literals_and_whitespace() {
    assert_eq!(eval("42"), Value::Int(42));
    assert_eq!(eval("1.35"), Value::Double(1.35));
    assert_eq!(eval("1e3"), Value::Double(1000.0));
    assert_eq!(eval("1.35E-9"), Value::Double(1.35e-9));
    assert_eq!(eval("true"), Value::Bool(true));
    // Larger than i64::MAX: an unsigned literal.
    assert_eq!(eval("18446744073709551615"), Value::UnsignedInt(u64::MAX));
    // Spaces, tabs and line breaks between tokens.
    assert_eq!(eval(" \t1\n+\r\n2 "), Value::Int(3));
    // A bare parameter reference evaluates to its value, of its type.
    assert_eq!(eval("$name"), Value::String("ego".into()));
}

#[test]
fn parsed_expression_reports_its_parameters_and_reevaluates() {
    let e = scenario::expr::Expression::parse("$a * 2 + max($b, $a)").unwrap();
    assert_eq!(e.parameters(), ["a", "b", "a"]);
    // a = 1.5, b = 4: 3 + 4 = 7.0 (max of a double and an int is a double).
    let first = e.evaluate(&|n: &str| match n {
        "a" => Some(Value::Double(1.5)),
        "b" => Some(Value::Int(4)),
        _ => None,
    });
    assert_eq!(first, Ok(Value::Double(7.0)));
    // a = 5, b = 4 (ints): 10 + 5 = 15, an int.
    let second = e.evaluate(&|n: &str| match n {
        "a" => Some(Value::Int(5)),
        "b" => Some(Value::Int(4)),
        _ => None,
    });
    assert_eq!(second, Ok(Value::Int(15)));
}
