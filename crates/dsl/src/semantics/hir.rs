//! The checker's view of a source file: declarations, members, behaviors and expressions with
//! their spans, independent of the concrete syntax tree (`lower_ast` builds it from the parser's
//! typed AST). Names follow the productions of ASAM OpenSCENARIO DSL 2.1 §7.2.2.

/// Index of a source file in the program's file list.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct FileId(pub u32);

/// A byte range in one file.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct Span {
    /// The file.
    pub file: FileId,
    /// First byte.
    pub start: u32,
    /// One past the last byte.
    pub end: u32,
}

/// A name with where it was written.
#[derive(Debug, Clone, PartialEq)]
pub struct Name {
    /// The text.
    pub text: String,
    /// Where.
    pub span: Span,
}

/// A possibly qualified name: `vehicle.drive`, `osc.standard`.
#[derive(Debug, Clone, PartialEq)]
pub struct QualName {
    /// The parts, outermost first.
    pub parts: Vec<Name>,
    /// The whole name's span.
    pub span: Span,
}

impl QualName {
    /// The dotted text.
    pub fn text(&self) -> String {
        self.parts
            .iter()
            .map(|p| p.text.as_str())
            .collect::<Vec<_>>()
            .join(".")
    }

    /// The last part (the name itself, without qualifier); empty for an empty name.
    pub fn last_text(&self) -> &str {
        self.parts.last().map_or("", |p| p.text.as_str())
    }
}

/// A type as written.
#[derive(Debug, Clone, PartialEq)]
pub enum TypeRef {
    /// `bool`, `int`, `uint`, `float`, `string`.
    Primitive(Name),
    /// A declared type's name.
    Named(QualName),
    /// `list of T`.
    List(Box<TypeRef>, Span),
    /// `range of T`.
    Range(Box<TypeRef>, Span),
}

impl TypeRef {
    /// Where it was written.
    pub fn span(&self) -> Span {
        match self {
            TypeRef::Primitive(n) => n.span,
            TypeRef::Named(q) => q.span,
            TypeRef::List(_, s) | TypeRef::Range(_, s) => *s,
        }
    }
}

/// Binary operators: the parser's (ASAM OpenSCENARIO DSL 2.1 §7.2.2.6).
pub use crate::syntax::ast::BinaryOp as BinOp;

/// An operator as written, for messages.
pub fn op_text(op: BinOp) -> &'static str {
    match op {
        BinOp::Add => "+",
        BinOp::Sub => "-",
        BinOp::Mul => "*",
        BinOp::Div => "/",
        BinOp::Rem => "%",
        BinOp::Eq => "==",
        BinOp::Ne => "!=",
        BinOp::Lt => "<",
        BinOp::Le => "<=",
        BinOp::Gt => ">",
        BinOp::Ge => ">=",
        BinOp::And => "and",
        BinOp::Or => "or",
        BinOp::Implies => "=>",
        BinOp::In => "in",
    }
}

/// An expression (§7.4).
#[derive(Debug, Clone, PartialEq)]
pub struct Expr {
    /// What it is.
    pub kind: ExprKind,
    /// Where.
    pub span: Span,
}

/// An argument of a call or invocation: positional or `name: value`.
#[derive(Debug, Clone, PartialEq)]
pub struct Arg {
    /// The parameter name, for a named argument.
    pub name: Option<Name>,
    /// The value.
    pub value: Expr,
}

/// The kinds of expression.
#[derive(Debug, Clone, PartialEq)]
pub enum ExprKind {
    /// An integer literal.
    Int(i128),
    /// A float literal.
    Float(f64),
    /// A physical literal: number and unit (`1.95m`).
    Physical(f64, Name),
    /// `true` / `false`.
    Bool(bool),
    /// A string literal (unescaped).
    Str(String),
    /// A name (field, parameter, enum member, `actor`).
    Name(String),
    /// `it`.
    It,
    /// `enum_type!member`.
    EnumValue(QualName, Name),
    /// `e.field`.
    Field(Box<Expr>, Name),
    /// `e[i]`.
    Index(Box<Expr>, Box<Expr>),
    /// `f(args)` / `e.m(args)`.
    Call(Box<Expr>, Vec<Arg>),
    /// `a op b`.
    Binary(BinOp, Box<Expr>, Box<Expr>),
    /// `-e`.
    Neg(Box<Expr>),
    /// `not e`.
    Not(Box<Expr>),
    /// `c ? a : b`.
    Ternary(Box<Expr>, Box<Expr>, Box<Expr>),
    /// `[a, b]`.
    List(Vec<Expr>),
    /// `[a..b]` / `range(a, b)`.
    Range(Box<Expr>, Box<Expr>),
    /// `e.as(T)`.
    Cast(Box<Expr>, TypeRef),
    /// `e.is(T)`.
    TypeTest(Box<Expr>, TypeRef),
    /// An event or time form met in expression position (`rise(…)`, `sample(…)`, `every(…)`):
    /// its name and arguments, type checked by the behavior checker.
    Temporal(Name, Vec<Arg>),
    /// A piece the parser could not read; never reported again.
    Error,
}

/// A `keep(...)` constraint.
#[derive(Debug, Clone, PartialEq)]
pub struct Keep {
    /// `keep(default …)`.
    pub default: bool,
    /// The constraint.
    pub expr: Expr,
    /// The whole `keep(...)`.
    pub span: Span,
}

/// A field (parameter or `var`) declaration: `a, b: T = v with: keep(it …)`.
#[derive(Debug, Clone, PartialEq)]
pub struct FieldDecl {
    /// The names declared.
    pub names: Vec<Name>,
    /// The type.
    pub ty: TypeRef,
    /// `= value`.
    pub default: Option<Expr>,
    /// A `var` (state variable) rather than a parameter.
    pub is_var: bool,
    /// Constraints in its `with:` block (over `it`).
    pub keeps: Vec<Keep>,
    /// The whole declaration.
    pub span: Span,
}

/// A method parameter.
#[derive(Debug, Clone, PartialEq)]
pub struct Param {
    /// Its name.
    pub name: Name,
    /// Its type.
    pub ty: TypeRef,
    /// `= default`.
    pub default: Option<Expr>,
}

/// How a method is implemented.
#[derive(Debug, Clone, PartialEq)]
pub enum MethodBody {
    /// `is expression e` / `is e`.
    Expression(Expr),
    /// `is undefined`.
    Undefined,
    /// `is external …`.
    External,
    /// Missing (a syntax error was reported).
    Missing,
}

/// `def name(params) -> T is …`.
#[derive(Debug, Clone, PartialEq)]
pub struct MethodDecl {
    /// Its name.
    pub name: Name,
    /// Parameters.
    pub params: Vec<Param>,
    /// Return type.
    pub ret: Option<TypeRef>,
    /// Body.
    pub body: MethodBody,
    /// `is only …`: overrides a method of a parent or an earlier declaration (§7.3.7.2).
    pub only: bool,
    /// The whole declaration.
    pub span: Span,
}

/// `event name(params) is spec`.
#[derive(Debug, Clone, PartialEq)]
pub struct EventDecl {
    /// Its name.
    pub name: Name,
    /// The defining expression, if any.
    pub spec: Option<Expr>,
    /// The whole declaration.
    pub span: Span,
}

/// A modifier applied to a behavior or scenario: `speed(50kph)`, `my_building.location(p)`.
#[derive(Debug, Clone, PartialEq)]
pub struct ModifierApp {
    /// `target.` before the modifier name.
    pub target: Option<Expr>,
    /// The modifier's name.
    pub name: Name,
    /// Arguments.
    pub args: Vec<Arg>,
    /// The whole application.
    pub span: Span,
}

/// Composition operators (§7.3.9.4).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum CompositionOp {
    /// `serial`
    Serial,
    /// `parallel`
    Parallel,
    /// `one_of`
    OneOf,
}

/// A member of a `with:` block of an invocation.
#[derive(Debug, Clone, PartialEq)]
pub enum WithMember {
    /// A modifier.
    Modifier(ModifierApp),
    /// A constraint.
    Keep(Keep),
    /// `until event`.
    Until(Expr, Span),
}

/// A behavior (§7.3.9: `do` directive bodies).
#[derive(Debug, Clone, PartialEq)]
pub enum Behavior {
    /// `serial:` / `parallel:` / `one_of:` with its arguments and children.
    Composition {
        /// The operator.
        op: CompositionOp,
        /// Its arguments (`duration: …`, `overlap: …`).
        args: Vec<Arg>,
        /// The children.
        children: Vec<Labeled>,
        /// The `with:` block after the children (§7.3.9 composition: `until`, `keep`, modifiers).
        with: Vec<WithMember>,
        /// Where.
        span: Span,
    },
    /// `actor.behavior(args) with: …`.
    Invocation {
        /// The actor expression before the name, if any.
        actor: Option<Expr>,
        /// The action or scenario name.
        name: Name,
        /// Arguments.
        args: Vec<Arg>,
        /// The `with:` block.
        with: Vec<WithMember>,
        /// Where.
        span: Span,
    },
    /// `wait expr`.
    Wait(Expr, Span),
    /// `emit event(args)`.
    Emit(Name, Vec<Arg>, Span),
    /// `call method(args)`.
    Call(Expr, Span),
}

/// A behavior with an optional label.
#[derive(Debug, Clone, PartialEq)]
pub struct Labeled {
    /// `label:`.
    pub label: Option<Name>,
    /// The behavior.
    pub behavior: Behavior,
}

/// A member of a struct, actor, scenario, action, modifier or extension, or a top-level member.
#[derive(Debug, Clone, PartialEq)]
pub enum Member {
    /// A field.
    Field(FieldDecl),
    /// A constraint.
    Keep(Keep),
    /// `remove_default(expr)`.
    RemoveDefault(Expr, Span),
    /// `for v in list: members` (the seed's vehicle_group example).
    For {
        /// The element name.
        var: Name,
        /// The list.
        list: Expr,
        /// The constraints inside.
        body: Vec<Member>,
        /// Where.
        span: Span,
    },
    /// A method.
    Method(MethodDecl),
    /// An event.
    Event(EventDecl),
    /// A modifier application.
    Modifier(ModifierApp),
    /// `do behavior`.
    Do(Labeled, Span),
    /// `on event: …`: the event and the body's `emit` / `call` members, checked as the
    /// same members of a `do`.
    On(Expr, Vec<Labeled>, Span),
    /// `cover(…)` / `record(…)` (§7.3.12): which, and the arguments, checked as expressions.
    Coverage(CoverageKind, Vec<Arg>, Span),
}

/// Which coverage member (§7.3.12).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum CoverageKind {
    /// `cover(…)`: values sampled into buckets.
    Cover,
    /// `record(…)`: values sampled and kept.
    Record,
}

/// The kinds of compound type (§7.3.7).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum CompoundKind {
    /// `struct`
    Struct,
    /// `actor`
    Actor,
    /// `scenario`
    Scenario,
    /// `action`
    Action,
    /// `modifier`
    Modifier,
}

impl CompoundKind {
    /// The keyword.
    pub fn keyword(self) -> &'static str {
        match self {
            CompoundKind::Struct => "struct",
            CompoundKind::Actor => "actor",
            CompoundKind::Scenario => "scenario",
            CompoundKind::Action => "action",
            CompoundKind::Modifier => "modifier",
        }
    }
}

/// `inherits Parent(field == value)`.
#[derive(Debug, Clone, PartialEq)]
pub struct Inherits {
    /// The parent's name.
    pub parent: QualName,
    /// The condition of a conditional inheritance.
    pub condition: Option<Expr>,
}

/// A struct, actor, scenario, action or modifier declaration.
#[derive(Debug, Clone, PartialEq)]
pub struct CompoundDecl {
    /// Which kind.
    pub kind: CompoundKind,
    /// Its name; scenarios, actions and modifiers may be qualified by an actor
    /// (`vehicle.drive`).
    pub name: QualName,
    /// `of behavior` for a modifier.
    pub of: Option<QualName>,
    /// The parent.
    pub inherits: Option<Inherits>,
    /// The members.
    pub members: Vec<Member>,
    /// The whole declaration.
    pub span: Span,
}

/// One `SI(…)` argument: `m: 1`, `factor: 0.27`, `offset: 273.15`.
#[derive(Debug, Clone, PartialEq)]
pub struct SiArg {
    /// The base unit or `factor`/`offset`.
    pub name: Name,
    /// The value (an integer exponent for base units).
    pub value: Expr,
}

/// A top-level item.
#[derive(Debug, Clone, PartialEq)]
pub enum Item {
    /// `namespace name [use a, b]` (§7.7.4): `""` is the global (`null`) namespace.
    Namespace {
        /// The namespace switched to.
        name: String,
        /// The namespaces after `use`.
        uses: Vec<Name>,
        /// Where.
        span: Span,
    },
    /// `export a, ns::b, *, ns::*` (§7.7.4.1).
    Export {
        /// The specifications.
        specs: Vec<ExportSpec>,
        /// Where.
        span: Span,
    },
    /// `import a.b` / `import "file.osc"`.
    Import {
        /// A library name or a relative file path.
        target: ImportTarget,
        /// Where.
        span: Span,
    },
    /// `type NAME is SI(…)`.
    PhysicalType {
        /// Its name.
        name: Name,
        /// `SI(…)` arguments.
        si: Vec<SiArg>,
        /// Where.
        span: Span,
    },
    /// `unit NAME of TYPE is SI(…)`.
    Unit {
        /// Its name.
        name: Name,
        /// The physical type.
        of: QualName,
        /// `SI(…)` arguments.
        si: Vec<SiArg>,
        /// Where.
        span: Span,
    },
    /// `enum NAME: [members]`.
    Enum {
        /// Its name.
        name: Name,
        /// Members.
        members: Vec<Name>,
        /// Members whose value names another member (`a = b`, `a = colors!b`).
        references: Vec<(Name, Expr)>,
        /// Where.
        span: Span,
    },
    /// `extend ENUM: [members]`.
    EnumExtension {
        /// The enum.
        name: QualName,
        /// New members.
        members: Vec<Name>,
        /// Members whose value names another member.
        references: Vec<(Name, Expr)>,
        /// Where.
        span: Span,
    },
    /// A compound type.
    Compound(CompoundDecl),
    /// `extend TYPE: members`.
    Extend {
        /// The extended type.
        target: QualName,
        /// New members.
        members: Vec<Member>,
        /// Where.
        span: Span,
    },
    /// `global name: T = v`.
    Global(FieldDecl),
    /// A member written at the top level (the seed's examples declare `my_wide_car: vehicle`
    /// and its `keep`s there).
    Member(Member),
}

/// One specification of an `export` statement.
#[derive(Debug, Clone, PartialEq)]
pub enum ExportSpec {
    /// A name, possibly prefixed (`bar`, `foo::ay`).
    Name(Name),
    /// `*` (`None`: the active namespace) or `ns::*` (`Some("")`: the global namespace).
    Wildcard(Option<String>, Span),
}

/// What an `import` names.
#[derive(Debug, Clone, PartialEq)]
pub enum ImportTarget {
    /// A library: `osc.standard`.
    Library(QualName),
    /// A file path relative to the importing file.
    File(String),
}

/// One parsed file.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct SourceFile {
    /// Its items in order.
    pub items: Vec<Item>,
}
