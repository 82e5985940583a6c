//! Builds the checker's [`hir`](super::hir) from the parser's typed AST
//! (`crate::syntax::ast`): names, spans, and the shapes the checker reads. Pieces the parser
//! reported as errors become `ExprKind::Error` and are not reported again.

use crate::syntax::ast::{self, AstNode};

use super::hir::*;

/// Lowers one parsed file (file `file` of the program).
pub fn lower_file(tree: &ast::SourceFile, file: FileId) -> SourceFile {
    let cx = Cx { file };
    SourceFile {
        items: tree.items().filter_map(|i| cx.item(&i)).collect(),
    }
}

struct Cx {
    file: FileId,
}

impl Cx {
    fn span(&self, n: &impl AstNode) -> Span {
        let r = n.syntax().text_range();
        Span {
            file: self.file,
            start: r.start().into(),
            end: r.end().into(),
        }
    }

    fn name(&self, n: &ast::Name) -> Name {
        Name {
            text: n.qualified_text(),
            span: self.span(n),
        }
    }

    fn name_ref(&self, n: &ast::NameRef) -> Name {
        Name {
            text: n.qualified_text(),
            span: self.span(n),
        }
    }

    /// The members of an enum declaration or extension whose value names another member.
    fn enum_references(&self, members: impl Iterator<Item = ast::EnumMember>) -> Vec<(Name, Expr)> {
        members
            .filter_map(|m| {
                let value = m.value()?;
                matches!(value, ast::Expr::Name(_) | ast::Expr::EnumValue(_))
                    .then(|| Some((self.name(&m.name()?), self.expr(&value))))?
            })
            .collect()
    }

    fn qual(&self, parts: Vec<Name>, span: Span) -> QualName {
        QualName { parts, span }
    }

    fn named_type(&self, t: &ast::NamedType) -> QualName {
        let mut parts: Vec<Name> = t.name().iter().map(|n| self.name_ref(n)).collect();
        parts.extend(t.behavior().iter().map(|n| self.name_ref(n)));
        self.qual(parts, self.span(t))
    }

    fn behavior_name(&self, b: &ast::BehaviorName) -> QualName {
        let mut parts: Vec<Name> = b.actor().iter().map(|n| self.name_ref(n)).collect();
        parts.extend(b.name().iter().map(|n| self.name(n)));
        self.qual(parts, self.span(b))
    }

    fn ty(&self, t: &ast::Type) -> TypeRef {
        let span = self.span(t);
        match t {
            ast::Type::Primitive(p) => {
                let text = p
                    .kind()
                    .and_then(|k| k.keyword_text())
                    .unwrap_or("?")
                    .to_string();
                TypeRef::Primitive(Name { text, span })
            }
            ast::Type::Named(n) => TypeRef::Named(self.named_type(n)),
            ast::Type::List(l) => TypeRef::List(Box::new(self.opt_ty(l.element(), span)), span),
            ast::Type::Range(r) => TypeRef::Range(Box::new(self.opt_ty(r.element(), span)), span),
        }
    }

    fn opt_ty(&self, t: Option<ast::Type>, span: Span) -> TypeRef {
        match t {
            Some(t) => self.ty(&t),
            None => TypeRef::Primitive(Name {
                text: "?".into(),
                span,
            }),
        }
    }

    fn item(&self, item: &ast::Item) -> Option<Item> {
        let span = self.span(item);
        Some(match item {
            ast::Item::Import(i) => {
                let r = i.reference()?;
                let target = if i.is_path() {
                    ImportTarget::File(r)
                } else {
                    let parts = r
                        .split('.')
                        .map(|p| Name {
                            text: p.to_string(),
                            span,
                        })
                        .collect();
                    ImportTarget::Library(self.qual(parts, span))
                };
                Item::Import { target, span }
            }
            ast::Item::Namespace(n) => Item::Namespace {
                name: n.name().map(|x| x.text()).unwrap_or_default(),
                uses: n.uses().map(|u| self.name_ref(&u)).collect(),
                span,
            },
            ast::Item::Export(e) => Item::Export {
                specs: e
                    .specs()
                    .filter_map(|x| {
                        if x.is_wildcard() {
                            Some(ExportSpec::Wildcard(x.wildcard_namespace(), self.span(&x)))
                        } else {
                            x.name().map(|n| ExportSpec::Name(self.name_ref(&n)))
                        }
                    })
                    .collect(),
                span,
            },
            ast::Item::PhysicalType(p) => Item::PhysicalType {
                name: self.name(&p.name()?),
                si: self.si(p.si()),
                span,
            },
            ast::Item::Unit(u) => Item::Unit {
                name: self.name(&u.name()?),
                of: {
                    let n = self.name_ref(&u.physical_type()?);
                    let s = n.span;
                    self.qual(vec![n], s)
                },
                si: self.si(u.si()),
                span,
            },
            ast::Item::Enum(e) => Item::Enum {
                name: self.name(&e.name()?),
                members: e
                    .members()
                    .filter_map(|m| m.name().map(|n| self.name(&n)))
                    .collect(),
                references: self.enum_references(e.members()),
                span,
            },
            ast::Item::EnumExtension(e) => Item::EnumExtension {
                name: self.named_type(&e.target()?),
                members: e
                    .members()
                    .filter_map(|m| m.name().map(|n| self.name(&n)))
                    .collect(),
                references: self.enum_references(e.members()),
                span,
            },
            ast::Item::Struct(d) => self.compound(
                CompoundKind::Struct,
                self.simple(d.name()),
                None,
                d.inherits(),
                d.members(),
                span,
            )?,
            ast::Item::Actor(d) => self.compound(
                CompoundKind::Actor,
                self.simple(d.name()),
                None,
                d.inherits(),
                d.members(),
                span,
            )?,
            ast::Item::Scenario(d) => self.compound(
                CompoundKind::Scenario,
                d.name().map(|b| self.behavior_name(&b)),
                None,
                d.inherits(),
                d.members(),
                span,
            )?,
            ast::Item::Action(d) => self.compound(
                CompoundKind::Action,
                d.name().map(|b| self.behavior_name(&b)),
                None,
                d.inherits(),
                d.members(),
                span,
            )?,
            ast::Item::Modifier(d) => {
                let of = d.of().map(|t| self.named_type(&t));
                self.compound(
                    CompoundKind::Modifier,
                    d.name().map(|b| self.behavior_name(&b)),
                    of,
                    d.inherits(),
                    d.members(),
                    span,
                )?
            }
            ast::Item::Extend(d) => {
                let target = match d.target()? {
                    ast::Type::Named(n) => self.named_type(&n),
                    other => {
                        let s = self.span(&other);
                        self.qual(
                            vec![Name {
                                text: other.syntax().text().to_string(),
                                span: s,
                            }],
                            s,
                        )
                    }
                };
                Item::Extend {
                    target,
                    members: self.members(d.members()),
                    span,
                }
            }
            ast::Item::Global(g) => Item::Global(self.field(&g.param()?, false)?),
            ast::Item::Param(p) => Item::Member(Member::Field(self.field(p, false)?)),
            ast::Item::Keep(k) => Item::Member(Member::Keep(self.keep(k)?)),
            ast::Item::RemoveDefault(r) => Item::Member(Member::RemoveDefault(
                self.opt_expr(r.parameter(), span),
                span,
            )),
            ast::Item::ModifierApplication(m) => {
                Item::Member(Member::Modifier(self.modifier_app(m)?))
            }
            ast::Item::For(f) => Item::Member(self.for_member(f)?),
        })
    }

    fn simple(&self, n: Option<ast::Name>) -> Option<QualName> {
        let n = self.name(&n?);
        let s = n.span;
        Some(self.qual(vec![n], s))
    }

    fn compound(
        &self,
        kind: CompoundKind,
        name: Option<QualName>,
        of: Option<QualName>,
        inherits: Option<ast::Inherits>,
        members: impl Iterator<Item = ast::Member>,
        span: Span,
    ) -> Option<Item> {
        let inherits = match inherits {
            Some(i) => Some(Inherits {
                parent: self.named_type(&i.parent()?),
                condition: i.condition().map(|c| {
                    let cs = self.span(&c);
                    let field = c.field().map(|f| Expr {
                        kind: ExprKind::Name(f.text()),
                        span: self.span(&f),
                    });
                    let value = self.opt_expr(c.value(), cs);
                    let lhs = field.unwrap_or(Expr {
                        kind: ExprKind::Error,
                        span: cs,
                    });
                    Expr {
                        kind: ExprKind::Binary(BinOp::Eq, Box::new(lhs), Box::new(value)),
                        span: cs,
                    }
                }),
            }),
            None => None,
        };
        let name = name.filter(|n| !n.parts.is_empty())?;
        Some(Item::Compound(CompoundDecl {
            kind,
            name,
            of,
            inherits,
            members: self.members(members),
            span,
        }))
    }

    fn si(&self, si: Option<ast::SiSpec>) -> Vec<SiArg> {
        si.iter()
            .flat_map(|s| s.args())
            .filter_map(|a| {
                let span = self.span(&a);
                Some(SiArg {
                    name: Name {
                        text: a.name()?,
                        span,
                    },
                    value: self.opt_expr(a.value(), span),
                })
            })
            .collect()
    }

    fn members(&self, members: impl Iterator<Item = ast::Member>) -> Vec<Member> {
        members.filter_map(|m| self.member(&m)).collect()
    }

    fn member(&self, m: &ast::Member) -> Option<Member> {
        let span = self.span(m);
        Some(match m {
            ast::Member::Param(p) => Member::Field(self.field(p, false)?),
            ast::Member::Var(v) => Member::Field(self.var_field(v)?),
            ast::Member::Keep(k) => Member::Keep(self.keep(k)?),
            ast::Member::RemoveDefault(r) => {
                Member::RemoveDefault(self.opt_expr(r.parameter(), span), span)
            }
            ast::Member::Method(md) => Member::Method(self.method(md)?),
            ast::Member::Event(e) => Member::Event(EventDecl {
                name: self.name(&e.name()?),
                spec: e.spec().map(|s| self.event_spec(&s)),
                span,
            }),
            ast::Member::Coverage(c) => Member::Coverage(
                if c.is_record() {
                    CoverageKind::Record
                } else {
                    CoverageKind::Cover
                },
                self.args(c.args()),
                span,
            ),
            ast::Member::ModifierApplication(a) => Member::Modifier(self.modifier_app(a)?),
            ast::Member::On(o) => Member::On(
                o.event().map(|e| self.event_spec(&e)).unwrap_or(Expr {
                    kind: ExprKind::Error,
                    span,
                }),
                o.members().filter_map(|m| self.behavior(&m)).collect(),
                span,
            ),
            ast::Member::Do(d) => Member::Do(self.behavior(&d.member()?)?, span),
            ast::Member::For(f) => self.for_member(f)?,
            // Behaviors written directly as members (inside `do` bodies) are reached through
            // `behavior`; met here they are lowered as a `do`.
            other => Member::Do(self.behavior(other)?, span),
        })
    }

    fn for_member(&self, f: &ast::ForConstraint) -> Option<Member> {
        let span = self.span(f);
        Some(Member::For {
            var: self.name(&f.variable()?),
            list: self.opt_expr(f.iterable(), span),
            body: self.members(f.members()),
            span,
        })
    }

    fn field(&self, p: &ast::ParamDecl, is_var: bool) -> Option<FieldDecl> {
        let span = self.span(p);
        let keeps = p
            .with_members()
            .filter_map(|m| match m {
                ast::Member::Keep(k) => self.keep(&k),
                _ => None,
            })
            .collect();
        Some(FieldDecl {
            names: p.names().map(|n| self.name(&n)).collect(),
            ty: self.opt_ty(p.ty(), span),
            default: p
                .default()
                .map(|e| self.expr(&e))
                .or_else(|| p.sample().map(|s| self.sample(&s))),
            is_var,
            keeps,
            span,
        })
    }

    fn var_field(&self, v: &ast::VarDecl) -> Option<FieldDecl> {
        let span = self.span(v);
        Some(FieldDecl {
            names: v.names().map(|n| self.name(&n)).collect(),
            ty: self.opt_ty(v.ty(), span),
            default: v
                .default()
                .map(|e| self.expr(&e))
                .or_else(|| v.sample().map(|s| self.sample(&s))),
            is_var: true,
            keeps: Vec::new(),
            span,
        })
    }

    fn keep(&self, k: &ast::KeepConstraint) -> Option<Keep> {
        let span = self.span(k);
        Some(Keep {
            default: k.qualifier() == Some(ast::ConstraintQualifier::Default),
            expr: self.opt_expr(k.expr(), span),
            span,
        })
    }

    fn method(&self, md: &ast::MethodDecl) -> Option<MethodDecl> {
        let span = self.span(md);
        let params = md
            .params()
            .iter()
            .flat_map(|l| l.params())
            .filter_map(|p| {
                let ps = self.span(&p);
                Some(Param {
                    name: self.name(&p.name()?),
                    ty: self.opt_ty(p.ty(), ps),
                    default: p.default().map(|e| self.expr(&e)),
                })
            })
            .collect();
        let body = match md.body().and_then(|b| b.implementation()) {
            Some(ast::MethodImpl::Expression(e)) => MethodBody::Expression(self.expr(&e)),
            Some(ast::MethodImpl::Undefined) => MethodBody::Undefined,
            Some(ast::MethodImpl::External(_)) => MethodBody::External,
            None => MethodBody::Missing,
        };
        Some(MethodDecl {
            name: self.name(&md.name()?),
            params,
            ret: md.return_type().map(|t| self.ty(&t)),
            body,
            only: md.body().is_some_and(|b| b.is_only()),
            span,
        })
    }

    fn modifier_app(&self, a: &ast::ModifierApplication) -> Option<ModifierApp> {
        let call = a.call()?;
        Some(ModifierApp {
            target: call.receiver().map(|r| self.expr(&r)),
            name: self.name_ref(&call.name()?),
            args: self.args(call.args()),
            span: self.span(a),
        })
    }

    fn label(&self, l: Option<ast::Label>) -> Option<Name> {
        l.and_then(|l| l.name()).map(|n| self.name(&n))
    }

    fn behavior(&self, m: &ast::Member) -> Option<Labeled> {
        let span = self.span(m);
        Some(match m {
            ast::Member::Composition(c) => Labeled {
                label: self.label(c.label()),
                behavior: Behavior::Composition {
                    op: match c.operator() {
                        Some(ast::CompositionOperator::Parallel) => CompositionOp::Parallel,
                        Some(ast::CompositionOperator::OneOf) => CompositionOp::OneOf,
                        _ => CompositionOp::Serial,
                    },
                    args: self.args(c.args()),
                    children: c.members().filter_map(|m| self.behavior(&m)).collect(),
                    with: c
                        .with()
                        .iter()
                        .flat_map(|w| w.members())
                        .filter_map(|m| self.with_member(&m))
                        .collect(),
                    span,
                },
            },
            ast::Member::Invocation(i) => {
                let call = i.call()?;
                let with = i
                    .with()
                    .iter()
                    .flat_map(|w| w.members())
                    .filter_map(|m| self.with_member(&m))
                    .collect();
                Labeled {
                    label: self.label(i.label()),
                    behavior: Behavior::Invocation {
                        actor: call.receiver().map(|r| self.expr(&r)),
                        name: self.name_ref(&call.name()?),
                        args: self.args(call.args()),
                        with,
                        span,
                    },
                }
            }
            ast::Member::Wait(w) => Labeled {
                label: self.label(w.label()),
                behavior: Behavior::Wait(
                    w.event().map(|e| self.event_spec(&e)).unwrap_or(Expr {
                        kind: ExprKind::Error,
                        span,
                    }),
                    span,
                ),
            },
            ast::Member::Emit(e) => Labeled {
                label: self.label(e.label()),
                behavior: Behavior::Emit(self.name_ref(&e.event()?), self.args(e.args()), span),
            },
            ast::Member::Call(c) => Labeled {
                label: self.label(c.label()),
                behavior: Behavior::Call(
                    c.call()
                        .map(|c| self.expr(&ast::Expr::Call(c)))
                        .unwrap_or(Expr {
                            kind: ExprKind::Error,
                            span,
                        }),
                    span,
                ),
            },
            ast::Member::Do(d) => return self.behavior(&d.member()?),
            _ => return None,
        })
    }

    fn with_member(&self, m: &ast::Member) -> Option<WithMember> {
        let span = self.span(m);
        Some(match m {
            ast::Member::Keep(k) => WithMember::Keep(self.keep(k)?),
            ast::Member::ModifierApplication(a) => WithMember::Modifier(self.modifier_app(a)?),
            ast::Member::Until(u) => WithMember::Until(
                u.event().map(|e| self.event_spec(&e)).unwrap_or(Expr {
                    kind: ExprKind::Error,
                    span,
                }),
                span,
            ),
            ast::Member::Invocation(i) => {
                // `speed(50kph)` in a with-block may parse as an invocation: it is a modifier.
                let call = i.call()?;
                WithMember::Modifier(ModifierApp {
                    target: call.receiver().map(|r| self.expr(&r)),
                    name: self.name_ref(&call.name()?),
                    args: self.args(call.args()),
                    span,
                })
            }
            _ => return None,
        })
    }

    fn args(&self, list: Option<ast::ArgList>) -> Vec<Arg> {
        list.iter()
            .flat_map(|l| l.args())
            .map(|a| match a {
                ast::Argument::Positional(p) => {
                    let s = self.span(&p);
                    Arg {
                        name: None,
                        value: self.opt_expr(p.value(), s),
                    }
                }
                ast::Argument::Named(n) => {
                    let s = self.span(&n);
                    Arg {
                        name: n.name().map(|x| self.name_ref(&x)),
                        value: self.opt_expr(n.value(), s),
                    }
                }
            })
            .collect()
    }

    fn event_spec(&self, s: &ast::EventSpec) -> Expr {
        let span = self.span(s);
        match s.condition() {
            Some(c) => self.event_condition(&c),
            None => match s.event_ref().and_then(|r| r.path()) {
                Some(p) => {
                    let e = self.expr(&p);
                    Expr {
                        kind: ExprKind::Temporal(
                            Name {
                                text: "@".into(),
                                span,
                            },
                            vec![Arg {
                                name: None,
                                value: e,
                            }],
                        ),
                        span,
                    }
                }
                None => Expr {
                    kind: ExprKind::Error,
                    span,
                },
            },
        }
    }

    fn event_condition(&self, c: &ast::EventCondition) -> Expr {
        let span = self.span(c);
        let temporal = |name: &str, args: Vec<Expr>| Expr {
            kind: ExprKind::Temporal(
                Name {
                    text: name.into(),
                    span,
                },
                args.into_iter()
                    .map(|value| Arg { name: None, value })
                    .collect(),
            ),
            span,
        };
        match c {
            ast::EventCondition::Expr(e) => self.expr(e),
            ast::EventCondition::Rise(r) => {
                temporal("rise", vec![self.opt_expr(r.operand(), span)])
            }
            ast::EventCondition::Fall(r) => {
                temporal("fall", vec![self.opt_expr(r.operand(), span)])
            }
            ast::EventCondition::Elapsed(r) => {
                temporal("elapsed", vec![self.opt_expr(r.operand(), span)])
            }
            ast::EventCondition::Every(r) => {
                let mut args = vec![self.opt_expr(r.period(), span)];
                args.extend(r.offset().map(|o| self.expr(&o)));
                temporal("every", args)
            }
        }
    }

    fn sample(&self, s: &ast::SampleExpr) -> Expr {
        let span = self.span(s);
        let mut args = vec![Arg {
            name: None,
            value: self.opt_expr(s.expr(), span),
        }];
        if let Some(e) = s.event() {
            args.push(Arg {
                name: None,
                value: self.event_spec(&e),
            });
        }
        Expr {
            kind: ExprKind::Temporal(
                Name {
                    text: "sample".into(),
                    span,
                },
                args,
            ),
            span,
        }
    }

    fn opt_expr(&self, e: Option<ast::Expr>, span: Span) -> Expr {
        match e {
            Some(e) => self.expr(&e),
            None => Expr {
                kind: ExprKind::Error,
                span,
            },
        }
    }

    fn expr(&self, e: &ast::Expr) -> Expr {
        let span = self.span(e);
        let b = |x: Option<ast::Expr>| Box::new(self.opt_expr(x, span));
        let kind = match e {
            ast::Expr::Literal(l) => match l.value() {
                Ok(ast::LiteralValue::Number(n)) => number(n),
                Ok(ast::LiteralValue::Physical(n, unit)) => {
                    let v = match n {
                        ast::Number::UInt(u) => u as f64,
                        ast::Number::Int(i) => i as f64,
                        ast::Number::Float(f) => f,
                    };
                    ExprKind::Physical(v, Name { text: unit, span })
                }
                Ok(ast::LiteralValue::Bool(x)) => ExprKind::Bool(x),
                Ok(ast::LiteralValue::String(s)) => ExprKind::Str(s),
                Err(_) => ExprKind::Error,
            },
            ast::Expr::List(l) => ExprKind::List(l.elements().map(|x| self.expr(&x)).collect()),
            ast::Expr::Range(r) => ExprKind::Range(b(r.start()), b(r.end())),
            ast::Expr::Paren(p) => return self.opt_expr(p.expr(), span),
            ast::Expr::Name(n) => match n.name() {
                Some(n) => ExprKind::Name(n.qualified_text()),
                None => ExprKind::Error,
            },
            ast::Expr::It(_) => ExprKind::It,
            ast::Expr::EnumValue(v) => match (v.enum_name(), v.member()) {
                (Some(t), Some(m)) => {
                    let t = self.name_ref(&t);
                    let ts = t.span;
                    ExprKind::EnumValue(self.qual(vec![t], ts), self.name_ref(&m))
                }
                _ => ExprKind::Error,
            },
            ast::Expr::Bin(x) => match x.op() {
                Some(op) => ExprKind::Binary(op, b(x.lhs()), b(x.rhs())),
                None => ExprKind::Error,
            },
            ast::Expr::Prefix(p) => match p.op() {
                Some(ast::PrefixOp::Not) => ExprKind::Not(b(p.operand())),
                Some(ast::PrefixOp::Neg) => match p.operand() {
                    // `-5` is the literal -5 (integers keep `int` rather than negated `uint`).
                    Some(ast::Expr::Literal(l))
                        if matches!(
                            l.value(),
                            Ok(ast::LiteralValue::Number(ast::Number::UInt(_)))
                        ) =>
                    {
                        match l.value() {
                            Ok(ast::LiteralValue::Number(ast::Number::UInt(u))) => {
                                ExprKind::Int(-(u as i128))
                            }
                            _ => ExprKind::Error,
                        }
                    }
                    other => ExprKind::Neg(b(other)),
                },
                None => ExprKind::Error,
            },
            ast::Expr::Ternary(t) => {
                ExprKind::Ternary(b(t.condition()), b(t.then_expr()), b(t.else_expr()))
            }
            ast::Expr::Field(f) => match f.field() {
                Some(n) => ExprKind::Field(b(f.receiver()), self.name_ref(&n)),
                None => ExprKind::Error,
            },
            ast::Expr::Index(i) => ExprKind::Index(b(i.base()), b(i.index())),
            ast::Expr::Call(c) => {
                let callee = c.callee();
                let args = self.args(c.args());
                match (&callee, c.name()) {
                    (Some(ast::Expr::Name(_)), Some(n)) if is_temporal(&n.text()) => {
                        ExprKind::Temporal(self.name_ref(&n), args)
                    }
                    _ => ExprKind::Call(b(callee), args),
                }
            }
            ast::Expr::Cast(c) => ExprKind::Cast(b(c.expr()), self.opt_ty(c.ty(), span)),
            ast::Expr::TypeTest(t) => ExprKind::TypeTest(b(t.expr()), self.opt_ty(t.ty(), span)),
        };
        Expr { kind, span }
    }
}

fn is_temporal(name: &str) -> bool {
    matches!(name, "rise" | "fall" | "elapsed" | "every" | "sample")
}

fn number(n: ast::Number) -> ExprKind {
    match n {
        ast::Number::UInt(u) => ExprKind::Int(u as i128),
        ast::Number::Int(i) => ExprKind::Int(i as i128),
        ast::Number::Float(f) => ExprKind::Float(f),
    }
}
