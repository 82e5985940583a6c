//! Lexer for OpenSCENARIO 1.3 §9.2 expressions: the text between `${` and `}` → tokens.
//!
//! Tokens follow the standard's published expression grammar (OscExprLexer): number literals
//! `INT ['.' DIGITS] [EXP]`, parameter references `'$' [A-Za-z_][A-Za-z0-9_]*`, bare names
//! (the functions and the words `true`, `false`, `not`, `and`, `or`), `( ) ,`, the arithmetic
//! operators `+ - * / %` and the comparisons `== != < <= > >=`. Spaces, tabs and line breaks
//! separate tokens. Every token keeps the byte offset where it starts.

use super::error::{ExprError, ExprErrorKind};

/// One token with the byte offset where it starts.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Token<'a> {
    pub kind: TokenKind<'a>,
    pub offset: usize,
}

/// The token kinds of the grammar.
#[derive(Debug, Clone, PartialEq)]
pub(crate) enum TokenKind<'a> {
    /// An integer literal (no `.`, no exponent).
    Integer(u64),
    /// A literal with a fraction or an exponent.
    Double(f64),
    /// `$name` (the name without `$`).
    Parameter(&'a str),
    /// A bare name: a function or one of `true false not and or`.
    Name(&'a str),
    LParen,
    RParen,
    Comma,
    Plus,
    Minus,
    Star,
    Slash,
    Percent,
    EqEq,
    NotEq,
    Less,
    LessEq,
    Greater,
    GreaterEq,
    /// End of the source.
    End,
}

impl TokenKind<'_> {
    /// The token as a reader would name it in "found …".
    pub fn describe(&self) -> String {
        match self {
            Self::Integer(i) => format!("number {i}"),
            Self::Double(d) => format!("number {d}"),
            Self::Parameter(name) => format!("parameter '${name}'"),
            Self::Name(name) => format!("'{name}'"),
            Self::End => "end of expression".to_owned(),
            other => format!("'{}'", other.symbol()),
        }
    }

    /// The spelling of a punctuation or operator token.
    pub fn symbol(&self) -> &'static str {
        match self {
            Self::LParen => "(",
            Self::RParen => ")",
            Self::Comma => ",",
            Self::Plus => "+",
            Self::Minus => "-",
            Self::Star => "*",
            Self::Slash => "/",
            Self::Percent => "%",
            Self::EqEq => "==",
            Self::NotEq => "!=",
            Self::Less => "<",
            Self::LessEq => "<=",
            Self::Greater => ">",
            Self::GreaterEq => ">=",
            _ => "",
        }
    }
}

/// Splits `source` into tokens, ending with [`TokenKind::End`] at `source.len()`.
pub(crate) fn tokenize(source: &str) -> Result<Vec<Token<'_>>, ExprError> {
    let bytes = source.as_bytes();
    let mut tokens = Vec::new();
    let mut i = 0;
    while i < bytes.len() {
        let start = i;
        let b = bytes[i];
        let (kind, len) = match b {
            b' ' | b'\t' | b'\r' | b'\n' => {
                i += 1;
                continue;
            }
            b'0'..=b'9' => number(source, start)?,
            b'$' => {
                let len = name_len(&bytes[start + 1..]);
                if len == 0 {
                    let found = source[start + 1..]
                        .chars()
                        .next()
                        .map_or_else(|| "end of expression".to_owned(), |c| format!("'{c}'"));
                    return Err(ExprError::new(
                        ExprErrorKind::UnexpectedToken {
                            expected: "a parameter name after '$'",
                            found,
                        },
                        start + 1,
                    ));
                }
                (
                    TokenKind::Parameter(&source[start + 1..start + 1 + len]),
                    len + 1,
                )
            }
            b'a'..=b'z' | b'A'..=b'Z' | b'_' => {
                let len = name_len(&bytes[start..]);
                (TokenKind::Name(&source[start..start + len]), len)
            }
            b'(' => (TokenKind::LParen, 1),
            b')' => (TokenKind::RParen, 1),
            b',' => (TokenKind::Comma, 1),
            b'+' => (TokenKind::Plus, 1),
            b'-' => (TokenKind::Minus, 1),
            b'*' => (TokenKind::Star, 1),
            b'/' => (TokenKind::Slash, 1),
            b'%' => (TokenKind::Percent, 1),
            b'=' if bytes.get(i + 1) == Some(&b'=') => (TokenKind::EqEq, 2),
            b'!' if bytes.get(i + 1) == Some(&b'=') => (TokenKind::NotEq, 2),
            b'<' if bytes.get(i + 1) == Some(&b'=') => (TokenKind::LessEq, 2),
            b'<' => (TokenKind::Less, 1),
            b'>' if bytes.get(i + 1) == Some(&b'=') => (TokenKind::GreaterEq, 2),
            b'>' => (TokenKind::Greater, 1),
            _ => {
                // `start` is on a char boundary: every branch above advances over ASCII only.
                let found = source[start..].chars().next().unwrap_or('\u{fffd}');
                return Err(ExprError::new(
                    ExprErrorKind::UnexpectedChar { found },
                    start,
                ));
            }
        };
        tokens.push(Token {
            kind,
            offset: start,
        });
        i = start + len;
    }
    tokens.push(Token {
        kind: TokenKind::End,
        offset: source.len(),
    });
    Ok(tokens)
}

/// Length of `[A-Za-z_][A-Za-z0-9_]*` at the start of `bytes` (0 if none).
fn name_len(bytes: &[u8]) -> usize {
    match bytes.first() {
        Some(b) if b.is_ascii_alphabetic() || *b == b'_' => bytes
            .iter()
            .take_while(|b| b.is_ascii_alphanumeric() || **b == b'_')
            .count(),
        _ => 0,
    }
}

/// Reads `DIGITS ['.' DIGITS] [('e'|'E') ['+'|'-'] DIGITS]` at `start`.
fn number(source: &str, start: usize) -> Result<(TokenKind<'_>, usize), ExprError> {
    let bytes = source.as_bytes();
    let digits = |from: usize| {
        bytes[from..]
            .iter()
            .take_while(|b| b.is_ascii_digit())
            .count()
    };
    let mut end = start + digits(start);
    let mut is_double = false;
    let mut well_formed = true;
    if bytes.get(end) == Some(&b'.') {
        is_double = true;
        let n = digits(end + 1);
        well_formed &= n > 0;
        end += 1 + n;
    }
    if matches!(bytes.get(end), Some(b'e' | b'E')) {
        is_double = true;
        let mut after = end + 1;
        if matches!(bytes.get(after), Some(b'+' | b'-')) {
            after += 1;
        }
        let n = digits(after);
        well_formed &= n > 0;
        end = after + n;
    }
    // A name glued to a number (`2x`, `1.5e3f`) is no token of the grammar.
    let tail = name_len(&bytes[end..]);
    let text = &source[start..end + tail];
    let invalid = || {
        ExprError::new(
            ExprErrorKind::InvalidNumber {
                text: text.to_owned(),
            },
            start,
        )
    };
    if !well_formed || tail > 0 {
        return Err(invalid());
    }
    let kind = if is_double {
        match text.parse::<f64>() {
            Ok(d) if d.is_finite() => TokenKind::Double(d),
            _ => return Err(invalid()),
        }
    } else {
        TokenKind::Integer(text.parse::<u64>().map_err(|_| invalid())?)
    };
    Ok((kind, end - start))
}
