//! The grammar of ASAM OpenSCENARIO DSL 2.1 §7.2.2, one function per production.
//!
//! | file | productions |
//! | --- | --- |
//! | `mod.rs` | osc-file, member dispatch by context, indented blocks |
//! | `items.rs` | prelude and main statements, type declarations, extensions, globals |
//! | `members.rs` | events, fields, constraints, methods, coverage, modifier application, argument list specifications |
//! | `behavior.rs` | on / do directives, compositions, invocations, wait / emit / call / until |
//! | `events.rs` | event specifications and conditions, sample |
//! | `types.rs` | names, type declarators |
//! | `expressions.rs` | expressions, argument lists |
//!
//! Every block (`':' NEWLINE INDENT member+ DEDENT`) is parsed by one routine, [`block`], for a
//! [`Ctx`]; [`member`] recognises any member in any context and reports the ones the context does
//! not allow ("expected a struct member …, found a `do` directive"), so a misplaced member is one
//! precise error and the rest of the file still parses.

mod behavior;
mod events;
mod expressions;
mod items;
mod members;
mod types;

use crate::syntax::kind::SyntaxKind::*;
use crate::syntax::parser::Parser;

/// Where a member stands; decides which members are allowed.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Ctx {
    /// The file itself.
    Top,
    /// struct or actor body.
    Struct,
    /// scenario or action body.
    Scenario,
    /// modifier body.
    Modifier,
    /// Body of `extend` of a struct, actor, scenario or action.
    Extend,
    /// Body of `extend` of a primitive type: methods only.
    ExtendPrimitive,
    /// `with:` block of a parameter: constraints only.
    ParamWith,
    /// `with:` block of a behavior invocation or composition.
    BehaviorWith,
    /// `on` block: call and emit.
    On,
    /// Body of a composition (`serial:`, `parallel:`, `one_of:`).
    Do,
    /// Body of a `for v in list:` constraint loop.
    For,
}

impl Ctx {
    /// What is expected in this context, for "expected …" messages.
    fn expected(self) -> &'static str {
        match self {
            Ctx::Top => "a declaration (import, namespace, export, type, unit, enum, struct, actor, scenario, action, modifier, extend, global)",
            Ctx::Struct => "a struct or actor member (event, field, var, keep, remove_default, def, cover, record)",
            Ctx::Scenario => "a scenario member (event, field, var, keep, remove_default, def, cover, record, modifier application, on, do)",
            Ctx::Modifier => "a modifier member (event, field, var, keep, remove_default, def, cover, record, modifier application, on)",
            Ctx::Extend => "an extension member (event, field, var, keep, remove_default, def, cover, record, modifier application, on, do)",
            Ctx::ExtendPrimitive => "a method declaration `def`",
            Ctx::ParamWith => "a constraint (keep, remove_default)",
            Ctx::BehaviorWith => "a constraint, modifier application or `until`",
            Ctx::On => "a `call` or `emit` directive",
            Ctx::Do => "a behavior (serial, parallel, one_of, invocation, wait, emit, call)",
            Ctx::For => "a constraint (keep, remove_default, for)",
        }
    }
}

/// What a member is, from its first tokens.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Member {
    Import,
    Namespace,
    Export,
    PhysicalType,
    Unit,
    Enum,
    Struct,
    Actor,
    Scenario,
    Action,
    Modifier,
    Extend,
    Global,
    Event,
    Field,
    Var,
    Keep,
    RemoveDefault,
    Def,
    Coverage,
    On,
    Do,
    For,
    Until,
    Call,
    Emit,
    Wait,
    Composition,
    Label,
    /// `[actor.]name(args)`: a modifier application, or in a `do` a behavior invocation.
    Invocation,
    Unknown,
}

impl Member {
    fn describe(self) -> &'static str {
        match self {
            Member::Import => "an `import`",
            Member::Namespace => "a `namespace` statement",
            Member::Export => "an `export` statement",
            Member::PhysicalType => "a physical type declaration",
            Member::Unit => "a unit declaration",
            Member::Enum => "an enum declaration",
            Member::Struct => "a struct declaration",
            Member::Actor => "an actor declaration",
            Member::Scenario => "a scenario declaration",
            Member::Action => "an action declaration",
            Member::Modifier => "a modifier declaration",
            Member::Extend => "an `extend`",
            Member::Global => "a global parameter",
            Member::Event => "an event declaration",
            Member::Field => "a field declaration",
            Member::Var => "a `var` declaration",
            Member::Keep => "a `keep` constraint",
            Member::RemoveDefault => "a `remove_default`",
            Member::Def => "a method declaration",
            Member::Coverage => "a coverage declaration",
            Member::On => "an `on` directive",
            Member::Do => "a `do` directive",
            Member::For => "a `for` constraint",
            Member::Until => "an `until` directive",
            Member::Call => "a `call` directive",
            Member::Emit => "an `emit` directive",
            Member::Wait => "a `wait` directive",
            Member::Composition | Member::Label => "a composition",
            Member::Invocation => "an invocation",
            Member::Unknown => "",
        }
    }

    /// struct-member-decl / actor-member-decl (§7.2.2.2.4), plus the seed's `for`.
    fn is_struct_member(self) -> bool {
        use Member as M;
        matches!(
            self,
            M::Event
                | M::Field
                | M::Var
                | M::Keep
                | M::RemoveDefault
                | M::Def
                | M::Coverage
                | M::For
        )
    }

    fn allowed_in(self, ctx: Ctx) -> bool {
        use Member as M;
        match ctx {
            // Fields, constraints, modifier applications and `for` at top level: the domain
            // model's examples (§8.7) write them there; accepted as the seed shows.
            Ctx::Top => matches!(
                self,
                M::Import
                    | M::Namespace
                    | M::Export
                    | M::PhysicalType
                    | M::Unit
                    | M::Enum
                    | M::Struct
                    | M::Actor
                    | M::Scenario
                    | M::Action
                    | M::Modifier
                    | M::Extend
                    | M::Global
                    | M::Field
                    | M::Keep
                    | M::RemoveDefault
                    | M::Invocation
                    | M::For
            ),
            Ctx::Struct => self.is_struct_member(),
            Ctx::Modifier => self.is_struct_member() || matches!(self, M::Invocation | M::On),
            Ctx::Scenario | Ctx::Extend => {
                self.is_struct_member() || matches!(self, M::Invocation | M::On | M::Do)
            }
            Ctx::ExtendPrimitive => self == M::Def,
            Ctx::ParamWith => matches!(self, M::Keep | M::RemoveDefault),
            Ctx::For => matches!(self, M::Keep | M::RemoveDefault | M::For),
            Ctx::BehaviorWith => {
                matches!(self, M::Keep | M::RemoveDefault | M::Invocation | M::Until)
            }
            Ctx::On => matches!(self, M::Call | M::Emit),
            Ctx::Do => matches!(
                self,
                M::Composition | M::Label | M::Invocation | M::Wait | M::Emit | M::Call
            ),
        }
    }
}

/// Recognises the member at the cursor. Keywords are contextual: a keyword followed by `:` or
/// `,` names a field (`event: int`), except where the grammar puts a `:` after the keyword.
fn classify(p: &Parser, ctx: Ctx) -> Member {
    use Member as M;
    if !p.at(IDENT) {
        return if p.at(COLON2) {
            M::Invocation
        } else {
            M::Unknown
        };
    }
    let next = p.nth(1);
    let field_like = matches!(next, COLON | COMMA);
    if ctx == Ctx::Do {
        if matches!(p.nth_text(0), "serial" | "parallel" | "one_of")
            && (next == L_PAREN || (next == COLON && p.nth(2) == NEWLINE))
        {
            return M::Composition;
        }
        if next == COLON {
            return M::Label;
        }
    }
    if field_like {
        return M::Field;
    }
    let word_next = next == IDENT;
    // A declared or extended name may carry the global namespace's prefix: `extend ::foo:`
    // (`prefixed-identifier ::= [namespace-name] '::' identifier`, §7.7.4.1).
    let name_next = word_next || (next == COLON2 && p.nth(2) == IDENT);
    match p.nth_text(0) {
        "import" if word_next || next == STRING => M::Import,
        "namespace" if word_next => M::Namespace,
        "export" if word_next || matches!(next, STAR | COLON2) => M::Export,
        "type" if name_next => M::PhysicalType,
        "unit" if name_next => M::Unit,
        "enum" if name_next => M::Enum,
        "struct" if name_next => M::Struct,
        "actor" if name_next => M::Actor,
        "scenario" if name_next => M::Scenario,
        "action" if name_next => M::Action,
        "modifier" if name_next => M::Modifier,
        "extend" if name_next => M::Extend,
        "global" if name_next => M::Global,
        "event" if word_next => M::Event,
        "var" if word_next => M::Var,
        "keep" if next != DOT => M::Keep,
        "remove_default" if next != DOT => M::RemoveDefault,
        "def" if word_next => M::Def,
        "cover" | "record" if next != DOT => M::Coverage,
        // A keyword is a keyword where the grammar places it (§7.2.1.5.1), also before a
        // parenthesised condition (`until (a > b)`, `wait (x > 1)`, `on (c):`): in those
        // places the word cannot be a modifier or behavior name.
        "on" if next != DOT
            && (next != L_PAREN || (M::On.allowed_in(ctx) && p.line_ends_with(COLON))) =>
        {
            M::On
        }
        "do" if next != L_PAREN && next != DOT => M::Do,
        "for" if word_next && p.nth_word(2, "in") => M::For,
        "until" if next != DOT && (next != L_PAREN || ctx == Ctx::BehaviorWith) => M::Until,
        "call" if next != DOT && (next != L_PAREN || matches!(ctx, Ctx::Do | Ctx::On)) => M::Call,
        "emit" if word_next => M::Emit,
        "wait" if next != DOT && (next != L_PAREN || ctx == Ctx::Do) => M::Wait,
        _ => M::Invocation,
    }
}

/// `osc-file ::= prelude-statement* main-statement*` as the [`SOURCE_FILE`] root.
pub(crate) fn source_file(p: &mut Parser) {
    p.start_root(SOURCE_FILE);
    let mut seen_main = false;
    while !p.at_eof() {
        if p.at(DEDENT) {
            // Only after a recovered indentation error; keep it in the tree.
            p.start(ERROR);
            p.bump();
            p.finish_node();
            continue;
        }
        let is_import = classify(p, Ctx::Top) == Member::Import;
        if is_import && seen_main {
            let range = p.current_range();
            p.error_at(range, "expected a main statement, found an `import` after other statements (imports form the prelude and come first, §7.2.2.1.1)");
        }
        seen_main |= !is_import && !p.at(INDENT);
        member(p, Ctx::Top);
    }
    p.bump_remaining();
    p.finish_node();
}

/// `NEWLINE INDENT member+ DEDENT` after a `:` the caller consumed, as a [`BLOCK`] node.
pub(crate) fn block(p: &mut Parser, ctx: Ctx) {
    p.start(BLOCK);
    if !p.eat(NEWLINE) {
        p.error_expected("end of line after `:` (a block goes on the next lines, indented)");
        p.skip_line();
        p.finish_node();
        return;
    }
    if !p.at(INDENT) {
        p.error_expected("an indented block");
        p.finish_node();
        return;
    }
    if !p.enter() {
        p.skip_block();
        p.finish_node();
        return;
    }
    indented_members(p, ctx);
    p.finish_node();
}

/// INDENT member* DEDENT, one nesting level deeper (the caller checked [`Parser::enter`]).
fn indented_members(p: &mut Parser, ctx: Ctx) {
    p.bump();
    while !p.at_eof() && !p.at(DEDENT) {
        member(p, ctx);
    }
    p.eat(DEDENT);
    p.leave();
}

/// Parses one member of any kind, reporting it if `ctx` does not allow it.
pub(crate) fn member(p: &mut Parser, ctx: Ctx) {
    if p.at(INDENT) {
        let range = p.current_range();
        p.error_at(
            range,
            "unexpected indentation: an indented block must follow a line ending in `:`",
        );
        if !p.enter() {
            p.skip_block();
            return;
        }
        p.start(ERROR);
        indented_members(p, ctx);
        p.finish_node();
        return;
    }
    let kind = classify(p, ctx);
    if kind == Member::Unknown {
        p.error_expected(ctx.expected());
        p.skip_line();
        return;
    }
    if !kind.allowed_in(ctx) {
        let range = p.current_range();
        p.error_at(
            range,
            format!("expected {}, found {}", ctx.expected(), kind.describe()),
        );
    }
    let before = p.current_range();
    parse_member(p, kind, ctx);
    if p.current_range() == before && !p.at_eof() {
        // No progress: never loop.
        p.error_expected(ctx.expected());
        p.skip_line();
    }
}

fn parse_member(p: &mut Parser, kind: Member, ctx: Ctx) {
    use Member as M;
    match kind {
        M::Import => items::import(p),
        M::Namespace => items::namespace(p),
        M::Export => items::export(p),
        M::PhysicalType => items::physical_type(p),
        M::Unit => items::unit(p),
        M::Enum => items::enum_decl(p),
        M::Struct => items::structured(p, STRUCT_DECL, STRUCT_KW),
        M::Actor => items::structured(p, ACTOR_DECL, ACTOR_KW),
        M::Scenario => items::structured(p, SCENARIO_DECL, SCENARIO_KW),
        M::Action => items::structured(p, ACTION_DECL, ACTION_KW),
        M::Modifier => items::modifier(p),
        M::Extend => items::extend(p),
        M::Global => items::global(p),
        M::Event => members::event(p),
        M::Field => members::field(p, PARAM_DECL),
        M::Var => members::field(p, VAR_DECL),
        M::Keep => members::keep(p),
        M::RemoveDefault => members::remove_default(p),
        M::Def => members::method(p),
        M::Coverage => members::coverage(p),
        M::For => members::for_constraint(p),
        M::On => behavior::on(p),
        M::Do => behavior::do_directive(p),
        M::Until => behavior::until(p),
        M::Call | M::Emit | M::Wait | M::Composition | M::Label => behavior::do_member(p),
        M::Invocation if ctx == Ctx::Do => behavior::do_member(p),
        M::Invocation => members::modifier_application(p),
        M::Unknown => p.skip_line(),
    }
}
