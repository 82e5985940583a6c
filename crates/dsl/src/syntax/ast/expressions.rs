//! Typed wrappers of expressions (ASAM OpenSCENARIO DSL 2.1 §7.2.2.6), literal values
//! (§7.2.1.5.2), type declarators (§7.2.2.2), argument lists (§7.2.2.5) and event
//! specifications (§7.2.2.4.1).

use super::{ast_enum, ast_nodes, child, children, token, AstNode, Name, NameRef};
use crate::syntax::kind::{SyntaxKind, SyntaxKind::*, SyntaxToken};

ast_nodes! {
    /// A literal: number, physical quantity, string, bool, `inf`, `nan`.
    Literal = LITERAL;
    /// `[a, b]`.
    ListExpr = LIST_EXPR;
    /// `[a..b]` or `range(a, b)`.
    RangeExpr = RANGE_EXPR;
    /// `(e)`.
    ParenExpr = PAREN_EXPR;
    /// A name used as a value.
    NameExpr = NAME_EXPR;
    /// `it`.
    ItExpr = IT_EXPR;
    /// `enum!member`.
    EnumValueExpr = ENUM_VALUE_EXPR;
    /// `a op b`.
    BinExpr = BIN_EXPR;
    /// `not a`, `-a`.
    PrefixExpr = PREFIX_EXPR;
    /// `c ? a : b`.
    TernaryExpr = TERNARY_EXPR;
    /// `e.field`.
    FieldExpr = FIELD_EXPR;
    /// `e[i]`.
    IndexExpr = INDEX_EXPR;
    /// `e(args)`.
    CallExpr = CALL_EXPR;
    /// `e.as(type)`.
    CastExpr = CAST_EXPR;
    /// `e.is(type)`.
    TypeTestExpr = TYPE_TEST_EXPR;
    /// `int`, `uint`, `float`, `bool`, `string`.
    PrimitiveType = PRIMITIVE_TYPE;
    /// A struct, actor, enum, physical type or `actor.behavior` by name.
    NamedType = NAMED_TYPE;
    /// `list of T`.
    ListType = LIST_TYPE;
    /// `range of T`.
    RangeType = RANGE_TYPE;
    /// `(a, b: 1)`.
    ArgList = ARG_LIST;
    /// A positional argument.
    Arg = ARG;
    /// `name: value`.
    NamedArg = NAMED_ARG;
    /// `name: type [= default], …` of a method or event.
    ParamList = PARAM_LIST;
    /// One `name: type [= default]`.
    Param = PARAM;
    /// An event specification.
    EventSpec = EVENT_SPEC;
    /// `@path.event`.
    EventRef = EVENT_REF;
    /// `as name` after an event reference.
    EventField = EVENT_FIELD;
    /// `rise(e)`.
    RiseExpr = RISE_EXPR;
    /// `fall(e)`.
    FallExpr = FALL_EXPR;
    /// `elapsed(d)`.
    ElapsedExpr = ELAPSED_EXPR;
    /// `every(d [, offset: o])`.
    EveryExpr = EVERY_EXPR;
    /// `sample(e, event [, default])`.
    SampleExpr = SAMPLE_EXPR;
}

ast_enum! {
    /// Any expression.
    Expr {
        Literal(Literal), List(ListExpr), Range(RangeExpr), Paren(ParenExpr), Name(NameExpr),
        It(ItExpr), EnumValue(EnumValueExpr), Bin(BinExpr), Prefix(PrefixExpr),
        Ternary(TernaryExpr), Field(FieldExpr), Index(IndexExpr), Call(CallExpr),
        Cast(CastExpr), TypeTest(TypeTestExpr),
    }
}

ast_enum! {
    /// A type declarator.
    Type { Primitive(PrimitiveType), Named(NamedType), List(ListType), Range(RangeType) }
}

ast_enum! {
    /// An event condition (§7.2.2.4.1).
    EventCondition {
        Expr(Expr), Rise(RiseExpr), Fall(FallExpr), Elapsed(ElapsedExpr), Every(EveryExpr),
    }
}

/// A number literal's value (§7.2.1.5.2).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Number {
    /// A non-negative integer (`uint`).
    UInt(u64),
    /// A negative integer (`int`).
    Int(i64),
    /// A floating-point number.
    Float(f64),
}

/// A literal's value.
#[derive(Debug, Clone, PartialEq)]
pub enum LiteralValue {
    /// A number without unit.
    Number(Number),
    /// A number with its unit name: `30kph`.
    Physical(Number, String),
    /// `true` / `false`.
    Bool(bool),
    /// A string, escapes resolved.
    String(String),
}

/// The value of a string literal's source text: quotes removed, `\x` escapes resolved (`\n`,
/// `\t`, `\r`, `\0` as in Python; any other escaped character stands for itself, §7.2.1.5.2
/// `string-escape-seq ::= '\' any-char`).
pub fn string_value(text: &str) -> Result<String, String> {
    let quote_len = if text.starts_with("\"\"\"") || text.starts_with("'''") {
        3
    } else {
        1
    };
    if text.len() < 2 * quote_len {
        return Err("unterminated string literal".to_string());
    }
    let inner = &text[quote_len..text.len() - quote_len];
    let mut out = String::with_capacity(inner.len());
    let mut chars = inner.chars();
    while let Some(c) = chars.next() {
        if c != '\\' {
            out.push(c);
            continue;
        }
        match chars.next() {
            Some('n') => out.push('\n'),
            Some('t') => out.push('\t'),
            Some('r') => out.push('\r'),
            Some('0') => out.push('\0'),
            Some(other) => out.push(other),
            None => out.push('\\'),
        }
    }
    Ok(out)
}

fn number_value(negative: bool, token: &SyntaxToken) -> Result<Number, String> {
    let text = token.text();
    let sign = if negative { "-" } else { "" };
    match token.kind() {
        INF_KW => Ok(Number::Float(if negative {
            f64::NEG_INFINITY
        } else {
            f64::INFINITY
        })),
        NAN_KW => Ok(Number::Float(f64::NAN)),
        FLOAT_NUMBER => {
            let value: f64 = format!("{sign}{text}")
                .parse()
                .map_err(|_| format!("invalid float literal `{text}`"))?;
            if value.is_finite() {
                Ok(Number::Float(value))
            } else {
                Err(format!(
                    "float literal `{}` is out of range (beyond ±1.8e308)",
                    abbreviate(text)
                ))
            }
        }
        _ => {
            let (digits, radix) = match text.strip_prefix("0x").or_else(|| text.strip_prefix("0X"))
            {
                Some(hex) => (hex, 16),
                None => (text, 10),
            };
            if negative {
                i64::from_str_radix(&format!("-{digits}"), radix)
                    .map(Number::Int)
                    .map_err(|_| {
                        format!(
                            "integer literal `-{}` does not fit int (64-bit signed)",
                            abbreviate(text)
                        )
                    })
            } else {
                u64::from_str_radix(digits, radix)
                    .map(Number::UInt)
                    .map_err(|_| {
                        format!(
                            "integer literal `{}` does not fit uint (64-bit unsigned)",
                            abbreviate(text)
                        )
                    })
            }
        }
    }
}

fn abbreviate(text: &str) -> String {
    if text.chars().count() <= 24 {
        text.to_string()
    } else {
        let head: String = text.chars().take(20).collect();
        format!("{head}… ({} characters)", text.chars().count())
    }
}

impl Literal {
    fn tokens(&self) -> impl Iterator<Item = SyntaxToken> {
        self.0
            .children_with_tokens()
            .filter_map(|e| e.into_token())
            .filter(|t| !t.kind().is_trivia())
    }

    /// The main token's kind: INT_NUMBER, FLOAT_NUMBER, STRING, TRUE_KW, FALSE_KW, INF_KW,
    /// NAN_KW.
    pub fn kind(&self) -> Option<SyntaxKind> {
        self.tokens()
            .map(|t| t.kind())
            .find(|k| !matches!(k, MINUS | PLUS | UNIT))
    }

    /// The unit of a physical literal (`kph` in `30kph`).
    pub fn unit(&self) -> Option<String> {
        token(&self.0, UNIT).map(|t| super::identifier_text(&t).to_string())
    }

    /// The value; an error message if it cannot be represented (too large, bad escape).
    pub fn value(&self) -> Result<LiteralValue, String> {
        let negative = token(&self.0, MINUS).is_some();
        let Some(main) = self
            .tokens()
            .find(|t| !matches!(t.kind(), MINUS | PLUS | UNIT))
        else {
            return Err("empty literal".to_string());
        };
        match main.kind() {
            TRUE_KW => Ok(LiteralValue::Bool(true)),
            FALSE_KW => Ok(LiteralValue::Bool(false)),
            STRING => string_value(main.text()).map(LiteralValue::String),
            _ => {
                let number = number_value(negative, &main)?;
                Ok(match self.unit() {
                    Some(unit) => LiteralValue::Physical(number, unit),
                    None => LiteralValue::Number(number),
                })
            }
        }
    }
}

impl ListExpr {
    /// The elements.
    pub fn elements(&self) -> impl Iterator<Item = Expr> {
        children(&self.0)
    }
}

impl RangeExpr {
    /// Lower bound.
    pub fn start(&self) -> Option<Expr> {
        children(&self.0).next()
    }
    /// Upper bound.
    pub fn end(&self) -> Option<Expr> {
        children(&self.0).nth(1)
    }
}

impl ParenExpr {
    /// The inner expression.
    pub fn expr(&self) -> Option<Expr> {
        child(&self.0)
    }
}

impl NameExpr {
    /// The name.
    pub fn name(&self) -> Option<NameRef> {
        child(&self.0)
    }
}

impl EnumValueExpr {
    /// The enum's name.
    pub fn enum_name(&self) -> Option<NameRef> {
        children(&self.0).next()
    }
    /// The member's name.
    pub fn member(&self) -> Option<NameRef> {
        children(&self.0).nth(1)
    }
}

/// Binary operators (§7.2.2.6.2–§7.2.2.6.4).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[allow(missing_docs)]
pub enum BinaryOp {
    Implies,
    Or,
    And,
    Eq,
    Ne,
    Lt,
    Le,
    Gt,
    Ge,
    In,
    Add,
    Sub,
    Mul,
    Div,
    Rem,
}

impl BinExpr {
    /// Left operand.
    pub fn lhs(&self) -> Option<Expr> {
        children(&self.0).next()
    }
    /// Right operand.
    pub fn rhs(&self) -> Option<Expr> {
        children(&self.0).nth(1)
    }
    /// The operator.
    pub fn op(&self) -> Option<BinaryOp> {
        self.op_token().and_then(|t| {
            Some(match t.kind() {
                FAT_ARROW => BinaryOp::Implies,
                OR_KW => BinaryOp::Or,
                AND_KW => BinaryOp::And,
                EQ2 => BinaryOp::Eq,
                NEQ => BinaryOp::Ne,
                LT => BinaryOp::Lt,
                LTEQ => BinaryOp::Le,
                GT => BinaryOp::Gt,
                GTEQ => BinaryOp::Ge,
                IN_KW => BinaryOp::In,
                PLUS => BinaryOp::Add,
                MINUS => BinaryOp::Sub,
                STAR => BinaryOp::Mul,
                SLASH => BinaryOp::Div,
                PERCENT => BinaryOp::Rem,
                _ => return None,
            })
        })
    }
    /// The operator token (for its span).
    pub fn op_token(&self) -> Option<SyntaxToken> {
        self.0
            .children_with_tokens()
            .filter_map(|e| e.into_token())
            .find(|t| !t.kind().is_trivia())
    }
}

/// Prefix operators.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum PrefixOp {
    /// `not`
    Not,
    /// `-`
    Neg,
}

impl PrefixExpr {
    /// The operator.
    pub fn op(&self) -> Option<PrefixOp> {
        if token(&self.0, NOT_KW).is_some() {
            Some(PrefixOp::Not)
        } else if token(&self.0, MINUS).is_some() {
            Some(PrefixOp::Neg)
        } else {
            None
        }
    }
    /// The operand.
    pub fn operand(&self) -> Option<Expr> {
        child(&self.0)
    }
}

impl TernaryExpr {
    /// The condition.
    pub fn condition(&self) -> Option<Expr> {
        children(&self.0).next()
    }
    /// The value when true.
    pub fn then_expr(&self) -> Option<Expr> {
        children(&self.0).nth(1)
    }
    /// The value when false.
    pub fn else_expr(&self) -> Option<Expr> {
        children(&self.0).nth(2)
    }
}

impl FieldExpr {
    /// The expression whose field is read.
    pub fn receiver(&self) -> Option<Expr> {
        child(&self.0)
    }
    /// The field's name.
    pub fn field(&self) -> Option<NameRef> {
        child(&self.0)
    }
}

impl IndexExpr {
    /// The list indexed.
    pub fn base(&self) -> Option<Expr> {
        children(&self.0).next()
    }
    /// The index.
    pub fn index(&self) -> Option<Expr> {
        children(&self.0).nth(1)
    }
}

impl CallExpr {
    /// The callee: a name (`f(…)`) or a field access (`actor.method(…)`).
    pub fn callee(&self) -> Option<Expr> {
        child(&self.0)
    }
    /// The arguments.
    pub fn args(&self) -> Option<ArgList> {
        child(&self.0)
    }
    /// The called name: `drive` in `ego.drive()` and in `drive()`.
    pub fn name(&self) -> Option<NameRef> {
        match self.callee()? {
            Expr::Name(n) => n.name(),
            Expr::Field(f) => f.field(),
            _ => None,
        }
    }
    /// The receiver: `ego` in `ego.drive()`, none for `drive()`.
    pub fn receiver(&self) -> Option<Expr> {
        match self.callee()? {
            Expr::Field(f) => f.receiver(),
            _ => None,
        }
    }
}

impl CastExpr {
    /// The expression cast.
    pub fn expr(&self) -> Option<Expr> {
        child(&self.0)
    }
    /// The target type.
    pub fn ty(&self) -> Option<Type> {
        child(&self.0)
    }
}

impl TypeTestExpr {
    /// The expression tested.
    pub fn expr(&self) -> Option<Expr> {
        child(&self.0)
    }
    /// The type tested for.
    pub fn ty(&self) -> Option<Type> {
        child(&self.0)
    }
}

impl PrimitiveType {
    /// The keyword kind: INT_KW, UINT_KW, FLOAT_KW, BOOL_KW or STRING_KW.
    pub fn kind(&self) -> Option<SyntaxKind> {
        self.0
            .children_with_tokens()
            .filter_map(|e| e.into_token())
            .map(|t| t.kind())
            .find(|k| k.is_keyword())
    }
}

impl NamedType {
    /// The type's name (the actor in `actor.behavior`).
    pub fn name(&self) -> Option<NameRef> {
        children(&self.0).next()
    }
    /// The behavior in `actor.behavior`, if qualified.
    pub fn behavior(&self) -> Option<NameRef> {
        children(&self.0).nth(1)
    }
}

impl ListType {
    /// The element type.
    pub fn element(&self) -> Option<Type> {
        child(&self.0)
    }
}

impl RangeType {
    /// The numeric element type.
    pub fn element(&self) -> Option<Type> {
        child(&self.0)
    }
}

/// One argument of a call.
#[derive(Debug, Clone, PartialEq, Eq, Hash)]
pub enum Argument {
    /// A positional argument.
    Positional(Arg),
    /// `name: value`.
    Named(NamedArg),
}

impl ArgList {
    /// The arguments in order.
    pub fn args(&self) -> impl Iterator<Item = Argument> {
        self.0.children().filter_map(|n| match n.kind() {
            ARG => Arg::cast(n).map(Argument::Positional),
            NAMED_ARG => NamedArg::cast(n).map(Argument::Named),
            _ => None,
        })
    }
}

impl Arg {
    /// The value.
    pub fn value(&self) -> Option<Expr> {
        child(&self.0)
    }
}

impl NamedArg {
    /// The argument's name.
    pub fn name(&self) -> Option<NameRef> {
        child(&self.0)
    }
    /// The value.
    pub fn value(&self) -> Option<Expr> {
        child(&self.0)
    }
}

impl ParamList {
    /// The parameters.
    pub fn params(&self) -> impl Iterator<Item = Param> {
        children(&self.0)
    }
}

impl Param {
    /// The parameter's name.
    pub fn name(&self) -> Option<Name> {
        child(&self.0)
    }
    /// Its type.
    pub fn ty(&self) -> Option<Type> {
        child(&self.0)
    }
    /// Its default value.
    pub fn default(&self) -> Option<Expr> {
        child(&self.0)
    }
}

impl EventSpec {
    /// `@path.event`, if the specification starts with one.
    pub fn event_ref(&self) -> Option<EventRef> {
        child(&self.0)
    }
    /// `as name`, if given.
    pub fn field(&self) -> Option<Name> {
        child::<EventField>(&self.0).and_then(|f| child(&f.0))
    }
    /// The condition (after `if`, or the whole specification).
    pub fn condition(&self) -> Option<EventCondition> {
        child(&self.0)
    }
}

impl EventRef {
    /// The event path after `@`.
    pub fn path(&self) -> Option<Expr> {
        child(&self.0)
    }
}

/// Accessors of the single-operand event conditions.
macro_rules! operand_accessor {
    ($($ty:ident),*) => {$(
        impl $ty {
            /// The operand (condition or duration).
            pub fn operand(&self) -> Option<Expr> {
                child(&self.0)
            }
        }
    )*};
}
operand_accessor!(RiseExpr, FallExpr, ElapsedExpr);

impl EveryExpr {
    /// The period.
    pub fn period(&self) -> Option<Expr> {
        children(&self.0).next()
    }
    /// The `offset:`, if any.
    pub fn offset(&self) -> Option<Expr> {
        children(&self.0).nth(1)
    }
}

impl SampleExpr {
    /// The expression sampled.
    pub fn expr(&self) -> Option<Expr> {
        children(&self.0).next()
    }
    /// When it is sampled.
    pub fn event(&self) -> Option<EventSpec> {
        child(&self.0)
    }
    /// The value before the first sample, if given.
    pub fn default(&self) -> Option<Expr> {
        children(&self.0).nth(1)
    }
}
