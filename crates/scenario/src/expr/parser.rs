//! Parser for OpenSCENARIO 1.3 §9.2 expressions: tokens → syntax tree.
//!
//! Precedence climbing over the levels of §9.2.1, weakest first, which is this grammar:
//!
//! ```text
//! expr       := and_expr   ( 'or'  and_expr )*
//! and_expr   := not_expr   ( 'and' not_expr )*
//! not_expr   := 'not' not_expr | comparison
//! comparison := additive   ( ('=='|'!='|'<'|'<='|'>'|'>=') additive )*
//! additive   := multiplicative ( ('+'|'-') multiplicative )*
//! multiplicative := unary  ( ('*'|'/'|'%') unary )*
//! unary      := '-' unary | primary
//! primary    := NUMBER | 'true' | 'false' | '$'NAME | NAME '(' expr (',' expr)* ')' | '(' expr ')'
//! ```
//!
//! Binary operators associate to the left. Nesting (parentheses, calls, prefix operators and
//! operator chains alike) is bounded by [`MAX_DEPTH`], so neither parsing, evaluating nor
//! dropping a tree can overflow the stack, whatever the input.

use super::arith::{BinaryOp, UnaryOp};
use super::error::{ExprError, ExprErrorKind};
use super::function::Function;
use super::lexer::{Token, TokenKind};
use super::value::Value;

/// The deepest nesting an expression may have: parentheses, calls, prefix operators and the
/// height of operator chains all count.
pub const MAX_DEPTH: usize = 256;

/// A node of the syntax tree with the byte offset of its operator, function or operand.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Node {
    pub kind: NodeKind,
    pub offset: usize,
    /// Height of the subtree (a leaf has 1), at most [`MAX_DEPTH`].
    height: usize,
}

/// What a node computes.
#[derive(Debug, Clone, PartialEq)]
pub(crate) enum NodeKind {
    Literal(Value),
    Parameter(String),
    Unary(UnaryOp, Box<Node>),
    Binary(BinaryOp, Box<Node>, Box<Node>),
    Call(Function, Vec<Node>),
}

/// Parses a token list (ending with [`TokenKind::End`]) into one tree.
pub(crate) fn parse(tokens: &[Token<'_>]) -> Result<Node, ExprError> {
    let mut parser = Parser {
        tokens,
        pos: 0,
        depth: 0,
    };
    let node = parser.expr()?;
    let end = parser.peek();
    if end.kind != TokenKind::End {
        let expected = if end.kind == TokenKind::RParen {
            "end of expression (unbalanced ')')"
        } else {
            "an operator or end of expression"
        };
        return Err(unexpected(expected, end));
    }
    Ok(node)
}

fn unexpected(expected: &'static str, found: &Token<'_>) -> ExprError {
    ExprError::new(
        ExprErrorKind::UnexpectedToken {
            expected,
            found: found.kind.describe(),
        },
        found.offset,
    )
}

struct Parser<'t, 'a> {
    tokens: &'t [Token<'a>],
    pos: usize,
    depth: usize,
}

impl<'a> Parser<'_, 'a> {
    fn peek(&self) -> &Token<'a> {
        // The list ends with End, and `advance` never moves past it.
        &self.tokens[self.pos.min(self.tokens.len() - 1)]
    }

    fn advance(&mut self) -> Token<'a> {
        let token = self.peek().clone();
        if token.kind != TokenKind::End {
            self.pos += 1;
        }
        token
    }

    /// Enters one level of recursion, failing beyond [`MAX_DEPTH`].
    fn enter(&mut self, offset: usize) -> Result<(), ExprError> {
        self.depth += 1;
        if self.depth > MAX_DEPTH {
            return Err(ExprError::new(
                ExprErrorKind::TooDeep { limit: MAX_DEPTH },
                offset,
            ));
        }
        Ok(())
    }

    fn leave(&mut self) {
        self.depth -= 1;
    }

    fn expr(&mut self) -> Result<Node, ExprError> {
        self.enter(self.peek().offset)?;
        let node = self.climb(Precedence::Or);
        self.leave();
        node
    }

    /// Precedence climbing: parses operands joined by binary operators of precedence at
    /// least `min`, each operator's right side at one level higher (left associativity).
    fn climb(&mut self, min: Precedence) -> Result<Node, ExprError> {
        let mut lhs = if min <= Precedence::Not {
            self.not_expr()?
        } else {
            self.unary()?
        };
        loop {
            let token = self.peek();
            let Some((op, precedence)) = binary_op(&token.kind) else {
                return Ok(lhs);
            };
            if precedence < min {
                return Ok(lhs);
            }
            let offset = token.offset;
            self.advance();
            let rhs = self.climb(precedence.next())?;
            lhs = node(NodeKind::Binary(op, Box::new(lhs), Box::new(rhs)), offset)?;
        }
    }

    /// `'not' not_expr | comparison`.
    fn not_expr(&mut self) -> Result<Node, ExprError> {
        if self.peek().kind == TokenKind::Name("not") {
            self.prefix(UnaryOp::Not, Self::not_expr)
        } else {
            self.climb(Precedence::Comparison)
        }
    }

    /// `'-' unary | primary`.
    fn unary(&mut self) -> Result<Node, ExprError> {
        if self.peek().kind == TokenKind::Minus {
            self.prefix(UnaryOp::Neg, Self::unary)
        } else {
            self.primary()
        }
    }

    fn prefix(
        &mut self,
        op: UnaryOp,
        operand: fn(&mut Self) -> Result<Node, ExprError>,
    ) -> Result<Node, ExprError> {
        let offset = self.advance().offset;
        self.enter(offset)?;
        let inner = operand(self);
        self.leave();
        node(NodeKind::Unary(op, Box::new(inner?)), offset)
    }

    fn primary(&mut self) -> Result<Node, ExprError> {
        let token = self.advance();
        let offset = token.offset;
        let kind = match token.kind {
            TokenKind::Integer(u) => NodeKind::Literal(match i64::try_from(u) {
                Ok(i) => Value::Int(i),
                Err(_) => Value::UnsignedInt(u),
            }),
            TokenKind::Double(d) => NodeKind::Literal(Value::Double(d)),
            TokenKind::Parameter(name) => NodeKind::Parameter(name.to_owned()),
            TokenKind::Name("true") => NodeKind::Literal(Value::Bool(true)),
            TokenKind::Name("false") => NodeKind::Literal(Value::Bool(false)),
            TokenKind::Name(name) if self.peek().kind == TokenKind::LParen => {
                return self.call(name, offset)
            }
            TokenKind::LParen => {
                let inner = self.expr()?;
                self.expect_close()?;
                return Ok(inner);
            }
            _ => {
                return Err(unexpected(
                    "a number, parameter, function call or '('",
                    &token,
                ))
            }
        };
        node(kind, offset)
    }

    fn call(&mut self, name: &str, offset: usize) -> Result<Node, ExprError> {
        let function = Function::from_name(name).ok_or_else(|| {
            ExprError::new(
                ExprErrorKind::UnknownFunction {
                    name: name.to_owned(),
                },
                offset,
            )
        })?;
        self.advance(); // '('
        let mut args = vec![self.expr()?];
        while self.peek().kind == TokenKind::Comma {
            self.advance();
            args.push(self.expr()?);
        }
        self.expect_close()?;
        if args.len() != function.arity() {
            return Err(ExprError::new(
                ExprErrorKind::WrongArity {
                    function: function.name(),
                    expected: function.arity(),
                    found: args.len(),
                },
                offset,
            ));
        }
        node(NodeKind::Call(function, args), offset)
    }

    /// Consumes the `)` closing a `(` or a call.
    fn expect_close(&mut self) -> Result<(), ExprError> {
        let token = self.peek();
        if token.kind == TokenKind::RParen {
            self.advance();
            return Ok(());
        }
        let expected = if token.kind == TokenKind::End {
            "')' to close the '(' before the end"
        } else {
            "',' or ')'"
        };
        Err(unexpected(expected, token))
    }
}

/// Binding strength of the binary operators and of `not`, weakest first (§9.2.1).
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
enum Precedence {
    Or,
    And,
    Not,
    Comparison,
    Additive,
    Multiplicative,
    /// Operands of `* / %`: unary minus and primaries; no binary operator binds this strongly.
    Prefix,
}

impl Precedence {
    /// The next stronger level (the right operand of a left-associative operator).
    fn next(self) -> Self {
        match self {
            Self::Or => Self::And,
            Self::And => Self::Not,
            Self::Not => Self::Comparison,
            Self::Comparison => Self::Additive,
            Self::Additive => Self::Multiplicative,
            Self::Multiplicative | Self::Prefix => Self::Prefix,
        }
    }
}

/// The binary operator of `kind` and its precedence, if `kind` is one.
fn binary_op(kind: &TokenKind<'_>) -> Option<(BinaryOp, Precedence)> {
    Some(match kind {
        TokenKind::Name("or") => (BinaryOp::Or, Precedence::Or),
        TokenKind::Name("and") => (BinaryOp::And, Precedence::And),
        TokenKind::EqEq => (BinaryOp::Eq, Precedence::Comparison),
        TokenKind::NotEq => (BinaryOp::Ne, Precedence::Comparison),
        TokenKind::Less => (BinaryOp::Lt, Precedence::Comparison),
        TokenKind::LessEq => (BinaryOp::Le, Precedence::Comparison),
        TokenKind::Greater => (BinaryOp::Gt, Precedence::Comparison),
        TokenKind::GreaterEq => (BinaryOp::Ge, Precedence::Comparison),
        TokenKind::Plus => (BinaryOp::Add, Precedence::Additive),
        TokenKind::Minus => (BinaryOp::Sub, Precedence::Additive),
        TokenKind::Star => (BinaryOp::Mul, Precedence::Multiplicative),
        TokenKind::Slash => (BinaryOp::Div, Precedence::Multiplicative),
        TokenKind::Percent => (BinaryOp::Rem, Precedence::Multiplicative),
        _ => return None,
    })
}

/// Builds a node, checking that its height stays within [`MAX_DEPTH`].
fn node(kind: NodeKind, offset: usize) -> Result<Node, ExprError> {
    let children_height = match &kind {
        NodeKind::Literal(_) | NodeKind::Parameter(_) => 0,
        NodeKind::Unary(_, inner) => inner.height,
        NodeKind::Binary(_, lhs, rhs) => lhs.height.max(rhs.height),
        NodeKind::Call(_, args) => args.iter().map(|a| a.height).max().unwrap_or(0),
    };
    let height = children_height + 1;
    if height > MAX_DEPTH {
        return Err(ExprError::new(
            ExprErrorKind::TooDeep { limit: MAX_DEPTH },
            offset,
        ));
    }
    Ok(Node {
        kind,
        offset,
        height,
    })
}
