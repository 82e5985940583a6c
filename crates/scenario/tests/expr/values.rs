//! `Value` and `ValueType`: the XSD `ParameterType` names, parsing declared parameter text
//! and the lossless conversions of an expression result to a declared type (OpenSCENARIO 1.3
//! §9.1, §9.2), and Display as written back into attributes.

use scenario::expr::{ExprErrorKind, Value, ValueType};

#[test]
fn xsd_type_names() {
    for (name, ty) in [
        ("boolean", ValueType::Boolean),
        ("int", ValueType::Int),
        ("unsignedInt", ValueType::UnsignedInt),
        ("unsignedShort", ValueType::UnsignedShort),
        ("double", ValueType::Double),
        ("string", ValueType::String),
        ("dateTime", ValueType::DateTime),
    ] {
        assert_eq!(ValueType::from_xsd_name(name), Some(ty));
        assert_eq!(ty.xsd_name(), name);
    }
    // `integer` is the deprecated spelling of int.
    assert_eq!(ValueType::from_xsd_name("integer"), Some(ValueType::Int));
    assert_eq!(ValueType::from_xsd_name("float"), None);
}

#[test]
fn parse_declared_text() {
    assert_eq!(
        Value::parse(ValueType::Double, "13.9"),
        Ok(Value::Double(13.9))
    );
    assert_eq!(
        Value::parse(ValueType::Double, "-2e3"),
        Ok(Value::Double(-2000.0))
    );
    assert_eq!(Value::parse(ValueType::Int, "-42"), Ok(Value::Int(-42)));
    assert_eq!(
        Value::parse(ValueType::UnsignedShort, "65535"),
        Ok(Value::UnsignedInt(65535))
    );
    assert_eq!(
        Value::parse(ValueType::Boolean, "false"),
        Ok(Value::Bool(false))
    );
    assert_eq!(Value::parse(ValueType::Boolean, "1"), Ok(Value::Bool(true)));
    assert_eq!(
        Value::parse(ValueType::String, "car_white"),
        Ok(Value::String("car_white".into()))
    );
    // Out of the XSD ranges: int is 32-bit, unsignedShort 16-bit; no NaN for doubles.
    for (ty, text) in [
        (ValueType::Int, "2147483648"),
        (ValueType::UnsignedInt, "-1"),
        (ValueType::UnsignedShort, "65536"),
        (ValueType::Double, "NaN"),
        (ValueType::Double, "inf"),
        (ValueType::Boolean, "yes"),
    ] {
        let err = Value::parse(ty, text).expect_err(text);
        assert!(
            matches!(err.kind(), ExprErrorKind::Conversion { to, .. } if *to == ty),
            "{text}"
        );
    }
    let err = Value::parse(ValueType::Int, "2.5").expect_err("2.5 as int");
    assert_eq!(
        err.to_string(),
        "expected a value convertible to int, found string 2.5"
    );
}

#[test]
fn lossless_conversions_of_results() {
    // 6.0 (e.g. from 12/2) is integral, so it converts to int 6; 2.5 does not.
    assert_eq!(
        Value::Double(6.0).convert_to(ValueType::Int),
        Ok(Value::Int(6))
    );
    let err = Value::Double(2.5)
        .convert_to(ValueType::Int)
        .expect_err("2.5");
    assert_eq!(
        err.to_string(),
        "expected a value convertible to int, found double 2.5"
    );
    assert_eq!(err.offset(), 0);
    assert_eq!(
        Value::Int(3).convert_to(ValueType::Double),
        Ok(Value::Double(3.0))
    );
    assert!(Value::Int(-1).convert_to(ValueType::UnsignedInt).is_err());
    assert!(Value::Int(70_000)
        .convert_to(ValueType::UnsignedShort)
        .is_err());
    assert!(Value::Bool(true).convert_to(ValueType::Double).is_err());
    assert!(Value::Double(1.0).convert_to(ValueType::Boolean).is_err());
    assert_eq!(
        Value::Double(2.5).convert_to(ValueType::String),
        Ok(Value::String("2.5".into()))
    );
}

#[test]
fn accessors() {
    assert_eq!(Value::Int(3).as_f64(), Some(3.0));
    assert_eq!(Value::UnsignedInt(3).as_i64(), Some(3));
    assert_eq!(Value::Double(-4.0).as_i64(), Some(-4));
    assert_eq!(Value::Double(-4.5).as_i64(), None);
    assert_eq!(Value::Double(1e19).as_i64(), None);
    assert_eq!(
        Value::Double(1e19).as_u64(),
        Some(10_000_000_000_000_000_000)
    );
    assert_eq!(Value::Int(-1).as_u64(), None);
    assert_eq!(Value::Bool(true).as_bool(), Some(true));
    assert_eq!(Value::Int(1).as_bool(), None);
    assert_eq!(
        Value::DateTime("2024-05-01T12:00:00".into()).as_str(),
        Some("2024-05-01T12:00:00")
    );
    assert_eq!(Value::String("x".into()).as_f64(), None);
}

#[test]
fn display_round_trips() {
    assert_eq!(Value::Double(2.5).to_string(), "2.5");
    assert_eq!(Value::Double(6.0).to_string(), "6");
    assert_eq!(Value::Int(-3).to_string(), "-3");
    assert_eq!(Value::Bool(false).to_string(), "false");
    // Shortest round-trip form: the text parses back to the same double.
    for d in [0.1 + 0.2, 1.0 / 3.0, 1e-7, 123_456.789, -0.0] {
        let text = Value::Double(d).to_string();
        assert_eq!(
            text.parse::<f64>().map(f64::to_bits),
            Ok(d.to_bits()),
            "{text}"
        );
    }
}
