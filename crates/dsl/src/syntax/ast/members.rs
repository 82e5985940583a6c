//! Typed wrappers of members (ASAM OpenSCENARIO DSL 2.1 §7.2.2.4): fields, events,
//! constraints, methods, coverage, modifier application, behavior directives.

use super::{
    ast_nodes, child, children, token, ArgList, Block, CallExpr, EventSpec, Expr, Name, NameRef,
    ParamList, Type,
};
use crate::syntax::kind::{SyntaxKind::*, SyntaxNode};

ast_nodes! {
    /// `event name[(params)] [is spec]`.
    EventDecl = EVENT_DECL;
    /// `a, b: type [= default] [with: …]`.
    ParamDecl = PARAM_DECL;
    /// `var a: type [= default | sample(…)]`.
    VarDecl = VAR_DECL;
    /// The names of a parameter or variable declaration.
    FieldNames = FIELD_NAMES;
    /// `with:` block of a parameter.
    ParamWith = PARAM_WITH;
    /// `keep([default|hard] expression)`.
    KeepConstraint = KEEP_CONSTRAINT;
    /// `remove_default(parameter)`.
    RemoveDefault = REMOVE_DEFAULT;
    /// `def name(params) [-> type] is …`.
    MethodDecl = METHOD_DECL;
    /// `-> type` of a method.
    ReturnType = RETURN_TYPE;
    /// `is [only] expression … | undefined | external …(…)`.
    MethodBody = METHOD_BODY;
    /// `cover(…)` or `record(…)`.
    CoverageDecl = COVERAGE_DECL;
    /// `[actor.]modifier(args)` as a member.
    ModifierApplication = MODIFIER_APPLICATION;
    /// `for v in list:` constraint loop (domain model example, §8.7.18.1.1).
    ForConstraint = FOR_CONSTRAINT;
    /// `on event-spec:` block.
    OnDirective = ON_DIRECTIVE;
    /// `do member`.
    DoDirective = DO_DIRECTIVE;
    /// `label:` before a do-member.
    Label = LABEL;
    /// `serial|parallel|one_of [(args)]:` block `[with: …]`.
    Composition = COMPOSITION;
    /// `[actor.]behavior(args) [with: …]`.
    BehaviorInvocation = BEHAVIOR_INVOCATION;
    /// `with:` block of an invocation or composition.
    BehaviorWith = BEHAVIOR_WITH;
    /// `wait event-spec`.
    WaitDirective = WAIT_DIRECTIVE;
    /// `emit event[(args)]`.
    EmitDirective = EMIT_DIRECTIVE;
    /// `call path.method(args)`.
    CallDirective = CALL_DIRECTIVE;
    /// `until event-spec`.
    UntilDirective = UNTIL_DIRECTIVE;
}

fn block_members(node: &SyntaxNode) -> impl Iterator<Item = super::Member> {
    child::<Block>(node)
        .into_iter()
        .flat_map(|b| b.members().collect::<Vec<_>>())
}

impl EventDecl {
    /// The event's name.
    pub fn name(&self) -> Option<Name> {
        child(&self.0)
    }
    /// Its parameters, if declared.
    pub fn params(&self) -> Option<ParamList> {
        child(&self.0)
    }
    /// `is …`, if given.
    pub fn spec(&self) -> Option<EventSpec> {
        child(&self.0)
    }
}

/// Accessors shared by parameter and variable declarations.
macro_rules! field_accessors {
    ($($ty:ident),*) => {$(
        impl $ty {
            /// The declared names (`a, b: int` declares two fields).
            pub fn names(&self) -> impl Iterator<Item = Name> {
                child::<FieldNames>(&self.0).into_iter().flat_map(|n| children(&n.0).collect::<Vec<_>>())
            }
            /// The type.
            pub fn ty(&self) -> Option<Type> {
                child(&self.0)
            }
            /// The default value expression, if any (not a `sample(…)`).
            pub fn default(&self) -> Option<Expr> {
                child(&self.0)
            }
            /// The `sample(…)` value, if any.
            pub fn sample(&self) -> Option<super::SampleExpr> {
                child(&self.0)
            }
        }
    )*};
}
field_accessors!(ParamDecl, VarDecl);

impl ParamDecl {
    /// The constraints of the `with:` block, if any.
    pub fn with_members(&self) -> impl Iterator<Item = super::Member> {
        child::<ParamWith>(&self.0)
            .into_iter()
            .flat_map(|w| block_members(&w.0).collect::<Vec<_>>())
    }
}

/// `default` or `hard` in `keep(…)` (§7.2.2.4.3).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum ConstraintQualifier {
    /// `keep(default …)`: a soft default, overridden by hard constraints.
    Default,
    /// `keep(hard …)`: explicitly hard (the default without qualifier).
    Hard,
}

impl KeepConstraint {
    /// The qualifier, if written.
    pub fn qualifier(&self) -> Option<ConstraintQualifier> {
        if token(&self.0, DEFAULT_KW).is_some() {
            Some(ConstraintQualifier::Default)
        } else if token(&self.0, HARD_KW).is_some() {
            Some(ConstraintQualifier::Hard)
        } else {
            None
        }
    }
    /// The constraint expression.
    pub fn expr(&self) -> Option<Expr> {
        child(&self.0)
    }
}

impl RemoveDefault {
    /// The parameter whose default constraints are removed.
    pub fn parameter(&self) -> Option<Expr> {
        child(&self.0)
    }
}

/// How a method is implemented (§7.2.2.4.4).
#[derive(Debug, Clone, PartialEq, Eq, Hash)]
pub enum MethodImpl {
    /// `is expression e`.
    Expression(Expr),
    /// `is undefined`.
    Undefined,
    /// `is external lib.function(args)`.
    External(CallExpr),
}

impl MethodDecl {
    /// The method's name.
    pub fn name(&self) -> Option<Name> {
        child(&self.0)
    }
    /// The parameters, if any.
    pub fn params(&self) -> Option<ParamList> {
        child(&self.0)
    }
    /// The return type, if declared.
    pub fn return_type(&self) -> Option<Type> {
        child::<ReturnType>(&self.0).and_then(|r| child(&r.0))
    }
    /// The implementation.
    pub fn body(&self) -> Option<MethodBody> {
        child(&self.0)
    }
}

impl MethodBody {
    /// Whether the `only` qualifier is given.
    pub fn is_only(&self) -> bool {
        token(&self.0, ONLY_KW).is_some()
    }
    /// The implementation, if complete.
    pub fn implementation(&self) -> Option<MethodImpl> {
        if token(&self.0, UNDEFINED_KW).is_some() {
            Some(MethodImpl::Undefined)
        } else if token(&self.0, EXTERNAL_KW).is_some() {
            child(&self.0).map(MethodImpl::External)
        } else {
            child(&self.0).map(MethodImpl::Expression)
        }
    }
}

impl CoverageDecl {
    /// Whether this is `record(…)` rather than `cover(…)`.
    pub fn is_record(&self) -> bool {
        token(&self.0, RECORD_KW).is_some()
    }
    /// The arguments.
    pub fn args(&self) -> Option<ArgList> {
        child(&self.0)
    }
}

impl ModifierApplication {
    /// The call `[actor.]modifier(args)`.
    pub fn call(&self) -> Option<CallExpr> {
        child(&self.0)
    }
}

impl ForConstraint {
    /// The loop variable.
    pub fn variable(&self) -> Option<Name> {
        child(&self.0)
    }
    /// The list iterated.
    pub fn iterable(&self) -> Option<Expr> {
        child(&self.0)
    }
    /// The constraints inside.
    pub fn members(&self) -> impl Iterator<Item = super::Member> {
        block_members(&self.0)
    }
}

impl OnDirective {
    /// The event specification.
    pub fn event(&self) -> Option<EventSpec> {
        child(&self.0)
    }
    /// The `call` / `emit` members.
    pub fn members(&self) -> impl Iterator<Item = super::Member> {
        block_members(&self.0)
    }
}

impl DoDirective {
    /// The do-member: composition, invocation, wait, emit or call.
    pub fn member(&self) -> Option<super::Member> {
        child(&self.0)
    }
}

impl Label {
    /// The label's name.
    pub fn name(&self) -> Option<Name> {
        child(&self.0)
    }
}

/// The composition operators (§7.2.2.4.7).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum CompositionOperator {
    /// `serial`
    Serial,
    /// `parallel`
    Parallel,
    /// `one_of`
    OneOf,
}

impl Composition {
    /// The label, if any.
    pub fn label(&self) -> Option<Label> {
        child(&self.0)
    }
    /// `serial`, `parallel` or `one_of`.
    pub fn operator(&self) -> Option<CompositionOperator> {
        self.0
            .children_with_tokens()
            .filter_map(|e| e.into_token())
            .find_map(|t| match t.kind() {
                SERIAL_KW => Some(CompositionOperator::Serial),
                PARALLEL_KW => Some(CompositionOperator::Parallel),
                ONE_OF_KW => Some(CompositionOperator::OneOf),
                _ => None,
            })
    }
    /// The arguments `(duration: 5s)`, if any.
    pub fn args(&self) -> Option<ArgList> {
        child(&self.0)
    }
    /// The do-members of the body.
    pub fn members(&self) -> impl Iterator<Item = super::Member> {
        block_members(&self.0)
    }
    /// The `with:` block after the body, if any.
    pub fn with(&self) -> Option<BehaviorWith> {
        child(&self.0)
    }
}

impl BehaviorInvocation {
    /// The label, if any.
    pub fn label(&self) -> Option<Label> {
        child(&self.0)
    }
    /// The call `[actor.]behavior(args)`.
    pub fn call(&self) -> Option<CallExpr> {
        child(&self.0)
    }
    /// The `with:` block, if any.
    pub fn with(&self) -> Option<BehaviorWith> {
        child(&self.0)
    }
}

impl BehaviorWith {
    /// Constraints, modifier applications and `until` directives.
    pub fn members(&self) -> impl Iterator<Item = super::Member> {
        block_members(&self.0)
    }
}

impl WaitDirective {
    /// The label, if any.
    pub fn label(&self) -> Option<Label> {
        child(&self.0)
    }
    /// The event waited for.
    pub fn event(&self) -> Option<EventSpec> {
        child(&self.0)
    }
}

impl UntilDirective {
    /// The event that ends the behavior.
    pub fn event(&self) -> Option<EventSpec> {
        child(&self.0)
    }
}

impl EmitDirective {
    /// The label, if any.
    pub fn label(&self) -> Option<Label> {
        child(&self.0)
    }
    /// The event emitted.
    pub fn event(&self) -> Option<NameRef> {
        child(&self.0)
    }
    /// The event's arguments, if any.
    pub fn args(&self) -> Option<ArgList> {
        child(&self.0)
    }
}

impl CallDirective {
    /// The label, if any.
    pub fn label(&self) -> Option<Label> {
        child(&self.0)
    }
    /// The method call.
    pub fn call(&self) -> Option<CallExpr> {
        child(&self.0)
    }
}
