//! Type checking of members, constraints and behaviors over the collected [`Model`]
//! (ASAM OpenSCENARIO DSL 2.1 §7.3 types, §7.4 expressions, §7.3.6 constraints, §7.3.9
//! behaviors, §8.9 modifier applicability; `conversion.rs`: the `is` and `as` operators,
//! §7.4.2.5, §7.4.2.6). Every error is pushed and checking goes on, so one
//! pass reports all of them; an expression that failed has type `Ty::Error`, which fits
//! everywhere, so a mistake is reported once.
//!
//! The checker also turns each `keep` into a [`Template`]: a typed expression over places
//! (`this.bounding_box.width`, a global, a `for` element) that `resolve` instantiates per
//! instance and lowers to the solver.

mod behavior;
mod conversion;
mod expr;
mod invocations;
mod members;

use super::diagnostic::Diagnostic;
use super::hir::{BinOp, Span};
use super::model::Model;
use super::solver::Strength;
use super::types::{CompoundId, EnumId, Ty};

pub use members::check_model;

/// Where a path starts.
#[derive(Debug, Clone, PartialEq)]
pub enum Place {
    /// A global parameter or top-level field (index into `Model::globals`).
    Global(usize),
    /// The instance the constraint belongs to.
    This,
    /// The element bound by the `k`-th enclosing `for`.
    Local(usize),
    /// The invoked scenario's instance, in an invocation's arguments and `with:` block (`it`).
    It,
}

/// One step of a path.
#[derive(Debug, Clone, PartialEq)]
pub enum Seg {
    /// `.name`
    Field(String),
    /// `[i]`
    Index(Box<TExpr>),
}

/// A typed expression.
#[derive(Debug, Clone, PartialEq)]
pub struct TExpr {
    /// What it is.
    pub kind: TKind,
    /// Its type.
    pub ty: Ty,
    /// Where.
    pub span: Span,
}

/// Kinds of typed expression.
#[derive(Debug, Clone, PartialEq)]
pub enum TKind {
    /// A number (SI units for physical quantities).
    Number(f64),
    /// A boolean.
    Bool(bool),
    /// A string.
    Str(String),
    /// An enumeration member.
    Member(EnumId, u32),
    /// A field path.
    Path(Place, Vec<Seg>),
    /// `list.size()`.
    Size(Box<TExpr>),
    /// A method call on a value (evaluated at run time).
    Call(Box<TExpr>, String, Vec<TExpr>),
    /// `-e`
    Neg(Box<TExpr>),
    /// `not e`
    Not(Box<TExpr>),
    /// `a op b`
    Binary(BinOp, Box<TExpr>, Box<TExpr>),
    /// `[a, b]`
    List(Vec<TExpr>),
    /// `[a..b]`
    Range(Box<TExpr>, Box<TExpr>),
    /// `x.as(int)` / `x.as(uint)` of a `float`: its whole part, rounded toward zero.
    Truncate(Box<TExpr>),
    /// Anything else (events, downcasts, ternaries, fields of call results): checked, but not
    /// something the solver reads.
    Opaque(&'static str),
}

/// Who a constraint belongs to.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Owner {
    /// The top level (global parameters and top-level fields).
    Top,
    /// Every instance of this type and of its subtypes.
    Compound(CompoundId),
    /// One invocation of a behavior with a `do` (index into [`Checked::invocations`]): once
    /// per instance of its caller, with `this` the caller and `it` the invoked instance.
    Invocation(usize),
}

/// An invocation of a behavior that has a `do` of its own (a scenario, or an action or
/// scenario declared on an actor) in the `do` of another (ASAM OpenSCENARIO DSL 2.1 §7.3.9
/// behavior invocation). Each invocation is an instance of the invoked behavior with its own
/// parameters: arguments of numbers, enumerations, booleans and strings become hard
/// constraints on them (templates owned by the invocation), arguments naming an actor or
/// struct make the parameter that very instance.
#[derive(Debug, Clone, PartialEq)]
pub struct Invocation {
    /// The behavior whose `do` holds the invocation.
    pub caller: CompoundId,
    /// The phase path in the caller's `do`: `do`, its label, then each member's label (or
    /// index), joined by `.` (`do.round_two`).
    pub path: String,
    /// The invoked behavior.
    pub callee: CompoundId,
    /// Parameters bound to an instance of the caller's: the parameter and the path argument.
    pub aliases: Vec<(String, TExpr)>,
    /// The behavior's name as written.
    pub name_span: Span,
    /// The whole invocation.
    pub span: Span,
}

/// A checked `keep` (or field default) ready to be instantiated.
#[derive(Debug, Clone, PartialEq)]
pub struct Template {
    /// Who it belongs to.
    pub owner: Owner,
    /// Hard or default.
    pub strength: Strength,
    /// A boolean expression.
    pub expr: TExpr,
    /// The lists the `Place::Local(k)` elements range over, outermost first.
    pub loops: Vec<TExpr>,
    /// The field a default value belongs to (`f: T = value`): only a hard constraint on it
    /// overrides the default, not one on a field the value reads.
    pub subject: Option<TExpr>,
    /// The whole `keep(...)`.
    pub span: Span,
}

/// The result of checking: diagnostics and the constraint templates.
#[derive(Debug, Clone, Default)]
pub struct Checked {
    /// Errors, in the order found.
    pub diags: Vec<Diagnostic>,
    /// Constraints.
    pub templates: Vec<Template>,
    /// Invocations of behaviors with a `do`, in source order.
    pub invocations: Vec<Invocation>,
    /// The names resolved to a member of the enum their place expects (see
    /// [`Model::enum_member_names`]).
    pub enum_member_names: std::collections::HashSet<Span>,
}

/// A name in scope besides fields and globals: a `for` element, `it`, a method parameter.
#[derive(Debug, Clone)]
pub(crate) struct Local {
    pub name: String,
    pub value: TExpr,
}

/// What names mean where an expression is checked.
#[derive(Debug, Clone, Default)]
pub(crate) struct Scope {
    /// The compound whose members are in scope.
    pub this: Option<CompoundId>,
    /// The actor of the behavior being checked (`actor`).
    pub actor: Option<CompoundId>,
    /// Innermost last.
    pub locals: Vec<Local>,
}

/// Shared state of one check.
pub(crate) struct Cx<'m> {
    pub model: &'m Model,
    pub out: Checked,
}
