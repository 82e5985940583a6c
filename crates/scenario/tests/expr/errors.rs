//! Bad expressions never panic or hang: each case asserts the exact message and the byte
//! offset of the offending token in the expression source.

use scenario::expr::{evaluate, ExprErrorKind, Value, MAX_DEPTH};

fn lookup(name: &str) -> Option<Value> {
    match name {
        "x" => Some(Value::Double(2.0)),
        "s" => Some(Value::String("ego".into())),
        "t" => Some(Value::DateTime("2024-01-01T00:00:00".into())),
        "b" => Some(Value::Bool(true)),
        _ => None,
    }
}

/// One case: the source, the exact message, the offset.
macro_rules! error_case {
    ($name:ident, $source:expr, $message:expr, $offset:expr) => {
        #[test]
        fn $name() {
            let err = evaluate($source, &lookup).expect_err($source);
            assert_eq!(err.to_string(), $message, "source: {}", $source);
            assert_eq!(err.offset(), $offset, "source: {}", $source);
        }
    };
}

// Names.
error_case!(
    unknown_parameter,
    "1 + $speed",
    "expected a declared parameter, found unknown parameter '$speed'",
    4
);
error_case!(
    unknown_function,
    "2 * sqr(4)",
    "expected one of the standard's functions, found unknown function 'sqr'",
    4
);
error_case!(
    bare_name,
    "1 + speed",
    "expected a number, parameter, function call or '(', found 'speed'",
    4
);
error_case!(
    dollar_without_name,
    "$ + 1",
    "expected a parameter name after '$', found ' '",
    1
);
error_case!(
    function_name_is_case_sensitive,
    "SQRT(4)",
    "expected one of the standard's functions, found unknown function 'SQRT'",
    0
);

// Arity.
error_case!(
    too_few_arguments,
    "pow(2)",
    "expected 2 argument(s) for pow, found 1",
    0
);
error_case!(
    too_many_arguments,
    "1 + sqrt(4, 9)",
    "expected 1 argument(s) for sqrt, found 2",
    4
);
error_case!(
    empty_call,
    "max()",
    "expected a number, parameter, function call or '(', found ')'",
    4
);

// Types.
error_case!(
    string_in_arithmetic,
    "$s + 1",
    "expected numeric operand(s) for +, found string",
    3
);
error_case!(
    datetime_in_comparison,
    "$t < 3",
    "expected numeric operand(s) for <, found dateTime",
    3
);
error_case!(
    boolean_in_arithmetic,
    "2 * true",
    "expected numeric operand(s) for *, found boolean",
    2
);
error_case!(
    number_in_and,
    "$b and 1",
    "expected boolean operand(s) for and, found int",
    3
);
error_case!(
    number_in_not,
    "not 0",
    "expected boolean operand(s) for not, found int",
    0
);
error_case!(
    negated_boolean,
    "-$b",
    "expected numeric operand(s) for unary -, found boolean",
    0
);
error_case!(
    boolean_equals_number,
    "true == 1",
    "expected boolean operand(s) for ==, found int",
    5
);
error_case!(
    chained_comparison,
    "1 < 2 < 3",
    "expected numeric operand(s) for <, found boolean",
    6
);
error_case!(
    string_to_function,
    "sqrt($s)",
    "expected numeric operand(s) for sqrt, found string",
    0
);

// Arithmetic.
error_case!(
    division_by_zero,
    "1 / (2 - 2)",
    "expected a non-zero divisor for /, found 0",
    2
);
error_case!(
    division_by_double_zero,
    "$x / 0.0",
    "expected a non-zero divisor for /, found 0",
    3
);
error_case!(
    modulo_by_zero,
    "7 % 0",
    "expected a non-zero divisor for %, found 0",
    2
);
error_case!(
    sqrt_of_negative,
    "sqrt(-1)",
    "expected a finite result of sqrt, found NaN",
    0
);
error_case!(
    asin_out_of_domain,
    "1 + asin(2)",
    "expected a finite result of asin, found NaN",
    4
);
error_case!(
    pow_overflows_to_infinity,
    "pow(10, 400)",
    "expected a finite result of pow, found inf",
    0
);
error_case!(
    product_overflows_to_infinity,
    "1e300 * 1e300",
    "expected a finite result of *, found inf",
    6
);
error_case!(
    integer_overflow,
    "9223372036854775807 + 1",
    "expected a result of + within the 64-bit integer range, found an overflow",
    20
);
error_case!(
    round_too_large,
    "round(1e19)",
    "expected a result of round within the 64-bit integer range, found an overflow",
    0
);

// Syntax.
error_case!(
    empty,
    "",
    "expected a number, parameter, function call or '(', found end of expression",
    0
);
error_case!(
    blank,
    "   ",
    "expected a number, parameter, function call or '(', found end of expression",
    3
);
error_case!(
    missing_operand,
    "1 +",
    "expected a number, parameter, function call or '(', found end of expression",
    3
);
error_case!(
    missing_close,
    "(1 + 2",
    "expected ')' to close the '(' before the end, found end of expression",
    6
);
error_case!(
    extra_close,
    "1 + 2)",
    "expected end of expression (unbalanced ')'), found ')'",
    5
);
error_case!(
    trailing_input,
    "1 2",
    "expected an operator or end of expression, found number 2",
    2
);
error_case!(
    missing_comma,
    "max(1 2)",
    "expected ',' or ')', found number 2",
    6
);
error_case!(
    unexpected_char,
    "1 # 2",
    "expected an operator, operand or parenthesis, found '#'",
    2
);
error_case!(
    non_ascii_char,
    "1 × 2",
    "expected an operator, operand or parenthesis, found '×'",
    2
);
error_case!(
    c_style_and,
    "true && false",
    "expected an operator, operand or parenthesis, found '&'",
    5
);
error_case!(
    single_equals,
    "1 = 1",
    "expected an operator, operand or parenthesis, found '='",
    2
);
error_case!(
    number_without_fraction_digits,
    "1. + 2",
    "expected a number literal, found '1.'",
    0
);
error_case!(
    number_without_exponent_digits,
    "2 * 1e",
    "expected a number literal, found '1e'",
    4
);
error_case!(
    number_glued_to_name,
    "2x",
    "expected a number literal, found '2x'",
    0
);
error_case!(
    integer_too_large,
    "99999999999999999999",
    "expected a number literal, found '99999999999999999999'",
    0
);
error_case!(
    double_too_large,
    "1e999",
    "expected a number literal, found '1e999'",
    0
);
error_case!(
    power_operator_is_not_in_the_grammar,
    "2 ** 3",
    "expected a number, parameter, function call or '(', found '*'",
    3
);

#[test]
fn deep_parentheses_are_refused_without_overflow() {
    // 100 000 nested parentheses. The whole expression is level 1 and the '(' at offset k
    // starts level k + 2, so level MAX_DEPTH + 1, the first refused, starts at the '(' at
    // offset MAX_DEPTH - 1... whose inner expression begins at offset MAX_DEPTH.
    let source = format!("{}1{}", "(".repeat(100_000), ")".repeat(100_000));
    let err = evaluate(&source, &lookup).expect_err("too deep");
    assert_eq!(err.kind(), &ExprErrorKind::TooDeep { limit: MAX_DEPTH });
    assert_eq!(
        err.to_string(),
        format!("expected at most {MAX_DEPTH} nested levels, found more")
    );
    assert_eq!(err.offset(), MAX_DEPTH);
}

#[test]
fn deep_prefix_operators_are_refused_without_overflow() {
    let source = format!("{}1", "-".repeat(100_000));
    let err = evaluate(&source, &lookup).expect_err("too deep");
    assert_eq!(err.kind(), &ExprErrorKind::TooDeep { limit: MAX_DEPTH });
    let source = format!("{}true", "not ".repeat(100_000));
    let err = evaluate(&source, &lookup).expect_err("too deep");
    assert_eq!(err.kind(), &ExprErrorKind::TooDeep { limit: MAX_DEPTH });
}

#[test]
fn long_operator_chains_are_refused_without_overflow() {
    // 1+1+…+1 builds a left-leaning tree as high as the chain is long.
    let source = vec!["1"; 100_000].join("+");
    let err = evaluate(&source, &lookup).expect_err("too deep");
    assert_eq!(err.kind(), &ExprErrorKind::TooDeep { limit: MAX_DEPTH });
    // A chain within the limit evaluates: 200 ones sum to 200.
    let source = vec!["1"; 200].join("+");
    assert_eq!(evaluate(&source, &lookup), Ok(Value::Int(200)));
}

#[test]
fn nesting_at_the_limit_is_accepted() {
    // MAX_DEPTH - 1 parentheses plus the top level make MAX_DEPTH levels.
    let n = MAX_DEPTH - 1;
    let source = format!("{}7{}", "(".repeat(n), ")".repeat(n));
    assert_eq!(evaluate(&source, &lookup), Ok(Value::Int(7)));
}

proptest::proptest! {
    /// Any text over the grammar's alphabet (and a few strangers) gives a value or an error
    /// whose offset lies inside the source — never a panic.
    #[test]
    fn arbitrary_input_never_panics(source in "[0-9a-z$_().,+*/%<>=! eE-]{0,40}") {
        if let Err(e) = evaluate(&source, &lookup) {
            proptest::prop_assert!(e.offset() <= source.len());
        }
    }
}
