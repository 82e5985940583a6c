//! Evaluation of OpenSCENARIO 1.3 §9.2 expressions: syntax tree + parameter values → typed
//! [`Value`], with the operator rules of `arith` and the functions of `function`.
//!
//! Both operands of every operator are evaluated (no short-circuit of `and`/`or`), so a type
//! error or unknown parameter anywhere in an expression is always reported, whatever the
//! values. Evaluation has no side effects and depends only on the source and the parameter
//! values: the same input gives the same bits on every machine.

use super::error::{ExprError, ExprErrorKind};
use super::lexer::tokenize;
use super::parser::{parse, Node, NodeKind};
use super::value::Value;

/// A parsed expression, ready to be evaluated many times with different parameter values.
#[derive(Debug, Clone, PartialEq)]
pub struct Expression {
    root: Node,
}

impl Expression {
    /// Parses `source`, the text between `${` and `}`.
    pub fn parse(source: &str) -> Result<Self, ExprError> {
        let tokens = tokenize(source)?;
        Ok(Self {
            root: parse(&tokens)?,
        })
    }

    /// Evaluates the expression; `lookup` gives the value of a parameter named without `$`.
    pub fn evaluate(&self, lookup: &dyn Fn(&str) -> Option<Value>) -> Result<Value, ExprError> {
        eval(&self.root, lookup)
    }

    /// The names (without `$`) of the parameters the expression reads, in source order, with
    /// repeats.
    pub fn parameters(&self) -> Vec<&str> {
        let mut names = Vec::new();
        collect_parameters(&self.root, &mut names);
        names
    }
}

/// Parses and evaluates `source`, the text between `${` and `}`; `lookup` resolves a
/// parameter name given without `$`.
///
/// ```
/// use scenario::expr::{evaluate, Value};
/// let lookup = |name: &str| (name == "speed").then_some(Value::Double(20.0));
/// assert_eq!(evaluate("5/2", &lookup), Ok(Value::Double(2.5)));
/// assert_eq!(evaluate("$speed * 2 > 30 and not false", &lookup), Ok(Value::Bool(true)));
/// assert_eq!(evaluate("round(2.5)", &lookup), Ok(Value::Int(3)));
/// ```
pub fn evaluate(source: &str, lookup: &dyn Fn(&str) -> Option<Value>) -> Result<Value, ExprError> {
    Expression::parse(source)?.evaluate(lookup)
}

/// Splits an attribute value of the form `${…}` into the expression source between the
/// delimiters; `None` for any other text (a literal or a `$name` reference). The source starts
/// at byte 2 of the attribute, which maps [`ExprError::offset`] back into the attribute.
///
/// ```
/// assert_eq!(scenario::expr::expression_source("${$a + 1}"), Some("$a + 1"));
/// assert_eq!(scenario::expr::expression_source("$a"), None);
/// ```
pub fn expression_source(attribute: &str) -> Option<&str> {
    attribute.strip_prefix("${")?.strip_suffix('}')
}

/// Recursion depth is bounded by the tree's height (≤ `MAX_DEPTH`, checked by the parser).
fn eval(node: &Node, lookup: &dyn Fn(&str) -> Option<Value>) -> Result<Value, ExprError> {
    match &node.kind {
        NodeKind::Literal(value) => Ok(value.clone()),
        NodeKind::Parameter(name) => lookup(name).ok_or_else(|| {
            ExprError::new(
                ExprErrorKind::UnknownParameter { name: name.clone() },
                node.offset,
            )
        }),
        NodeKind::Unary(op, operand) => op.apply(&eval(operand, lookup)?, node.offset),
        NodeKind::Binary(op, lhs, rhs) => {
            let lhs = eval(lhs, lookup)?;
            let rhs = eval(rhs, lookup)?;
            op.apply(&lhs, &rhs, node.offset)
        }
        NodeKind::Call(function, args) => {
            // Arity is at most 2 (checked by the parser): evaluate into a fixed array rather
            // than a Vec, so a call allocates nothing.
            let mut values = [Value::Bool(false), Value::Bool(false)];
            for (slot, arg) in values.iter_mut().zip(args) {
                *slot = eval(arg, lookup)?;
            }
            function.apply(&values[..args.len().min(2)], node.offset)
        }
    }
}

fn collect_parameters<'n>(node: &'n Node, names: &mut Vec<&'n str>) {
    match &node.kind {
        NodeKind::Literal(_) => {}
        NodeKind::Parameter(name) => names.push(name),
        NodeKind::Unary(_, operand) => collect_parameters(operand, names),
        NodeKind::Binary(_, lhs, rhs) => {
            collect_parameters(lhs, names);
            collect_parameters(rhs, names);
        }
        NodeKind::Call(_, args) => args.iter().for_each(|a| collect_parameters(a, names)),
    }
}
