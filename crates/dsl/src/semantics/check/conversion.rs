//! The type check and type conversion operators (ASAM OpenSCENARIO DSL 2.1 §7.4.2.5 `x.is(T)`,
//! §7.4.2.6 `x.as(T)`), resolved where the static types decide them, so a default such as
//! `n: int = x.as(int)` or `f: bool = x.is(float)` is a plain value to the solver.
//!
//! - `x.is(T)` "returns true if the expression is of the specified type": for a primitive,
//!   enum, physical or list type, true exactly when `T` is `x`'s static type ("type checking
//!   does not perform type conversion": `5.is(int)` is false, `5` is a `uint`); for a compound
//!   `x` of type `A`, true when `A` is `T` or inherits from it, and when `T` inherits from `A`
//!   through conditional inheritance only (`actor truck inherits vehicle(vehicle_category ==
//!   truck)`) the conjunction of those conditions on `x` (an instance of `A` with them is a
//!   `T`, §7.3.7.1); otherwise false.
//! - `x.as(T)`: the same value where `T` is `x`'s type or a parent (an upcast); among `int`,
//!   `uint` and `float` a numeric conversion: to `float` exact, `int`↔`uint` the same whole
//!   number, `float` to `int`/`uint` its whole part rounded toward zero (oscsim's choice: the
//!   standard names no rounding; a negative value has no `uint`). A downcast to a subtype is
//!   checked but left to the run time. Any other pair is an error ("an error is raised if the
//!   conversion cannot be performed"): physical types are not converted (§7.4.2.3.1), nor
//!   enums, strings or bools to another type.

use super::super::diagnostic::DiagnosticKind as K;
use super::super::hir::Span;
use super::super::types::{CompoundId, Ty};
use super::{Cx, Place, Scope, TExpr, TKind};
use crate::semantics::hir::BinOp;

impl Cx<'_> {
    /// `x.as(to)`.
    pub(crate) fn convert(&mut self, x: TExpr, to: Ty, span: Span) -> TExpr {
        let retyped = |x: TExpr, ty: Ty| TExpr { ty, span, ..x };
        match (&x.ty, &to) {
            (Ty::Error, _) | (_, Ty::Error) => self.opaque(Ty::Error, span, "error"),
            (a, b) if a == b => retyped(x, to),
            (Ty::Int | Ty::Uint | Ty::Float, Ty::Float) | (Ty::Int | Ty::Uint, Ty::Int) => {
                retyped(x, to)
            }
            (Ty::Int | Ty::Uint | Ty::Float, Ty::Uint | Ty::Int) => {
                let whole = match x.kind {
                    TKind::Number(v) => Some(v.trunc()),
                    _ => None,
                };
                match whole {
                    Some(v) if to == Ty::Uint && v < 0.0 => {
                        let x = match x.kind {
                            TKind::Number(x) => x,
                            _ => v,
                        };
                        self.err(
                            K::Type,
                            span,
                            format!("cannot convert {x} to uint: its whole part {v} is negative"),
                        );
                        self.opaque(Ty::Error, span, "error")
                    }
                    Some(v) => TExpr {
                        kind: TKind::Number(v),
                        ty: to,
                        span,
                    },
                    None if x.ty == Ty::Float => TExpr {
                        kind: TKind::Truncate(Box::new(x)),
                        ty: to,
                        span,
                    },
                    None => retyped(x, to),
                }
            }
            (Ty::Compound(a), Ty::Compound(b)) if self.model.is_subtype(*a, *b) => retyped(x, to),
            (Ty::Compound(a), Ty::Compound(b)) if self.model.is_subtype(*b, *a) => {
                self.opaque(to, span, "downcast (resolved at run time)")
            }
            (a, b) => {
                let (a, b) = (self.model.type_name(a), self.model.type_name(b));
                self.err(
                    K::Type,
                    span,
                    format!("cannot convert {a} to {b}: `as` converts among int, uint and float, and compound types along their inheritance"),
                );
                self.opaque(Ty::Error, span, "error")
            }
        }
    }

    /// `x.is(t)`.
    pub(crate) fn type_test(&mut self, x: TExpr, t: &Ty, span: Span) -> TExpr {
        let constant = |b: bool| TExpr {
            kind: TKind::Bool(b),
            ty: Ty::Bool,
            span,
        };
        match (&x.ty, t) {
            (Ty::Error, _) | (_, Ty::Error) => self.opaque(Ty::Bool, span, "type test"),
            (Ty::Compound(a), Ty::Compound(b)) if self.model.is_subtype(*a, *b) => constant(true),
            (Ty::Compound(a), Ty::Compound(b)) if self.model.is_subtype(*b, *a) => {
                match self.latent_subtype(&x, *a, *b, span) {
                    Some(condition) => condition,
                    None => constant(false),
                }
            }
            (a, b) => constant(a == b),
        }
    }

    /// The conditions under which `x`, an instance of `a`, is also a `sub` (a descendant of
    /// `a`): `None` when a step of the way inherits unconditionally (no instance of `a` is a
    /// `sub`); an opaque value when `x` is not a path the conditions can be put on.
    fn latent_subtype(
        &mut self,
        x: &TExpr,
        a: CompoundId,
        sub: CompoundId,
        span: Span,
    ) -> Option<TExpr> {
        let mut all: Option<TExpr> = None;
        for step in self.model.ancestry(sub).into_iter().take_while(|c| *c != a) {
            let condition = self.model.compound(step).condition.clone()?;
            let TKind::Path(place, base) = &x.kind else {
                return Some(self.opaque(Ty::Bool, span, "type test"));
            };
            // Checked where the subtype declares it (its errors were reported there).
            let reported = self.out.diags.len();
            let scope = Scope {
                this: Some(step),
                actor: None,
                locals: Vec::new(),
            };
            let c = self.expect(&condition, &Ty::Bool, &scope, "a condition");
            self.out.diags.truncate(reported);
            let c = reroot(c, place, base);
            all = Some(match all {
                None => c,
                Some(prev) => TExpr {
                    kind: TKind::Binary(BinOp::And, Box::new(prev), Box::new(c)),
                    ty: Ty::Bool,
                    span,
                },
            });
        }
        all
    }
}

/// `e` with its paths from `this` moved under `place.base` (the instance `x` the condition is
/// about).
fn reroot(e: TExpr, place: &Place, base: &[super::Seg]) -> TExpr {
    let boxed = |b: Box<TExpr>| Box::new(reroot(*b, place, base));
    let kind = match e.kind {
        TKind::Path(Place::This, segs) => {
            TKind::Path(place.clone(), base.iter().cloned().chain(segs).collect())
        }
        TKind::Size(a) => TKind::Size(boxed(a)),
        TKind::Neg(a) => TKind::Neg(boxed(a)),
        TKind::Not(a) => TKind::Not(boxed(a)),
        TKind::Truncate(a) => TKind::Truncate(boxed(a)),
        TKind::Binary(op, a, b) => TKind::Binary(op, boxed(a), boxed(b)),
        TKind::Range(a, b) => TKind::Range(boxed(a), boxed(b)),
        TKind::List(items) => {
            TKind::List(items.into_iter().map(|i| reroot(i, place, base)).collect())
        }
        TKind::Call(r, name, args) => TKind::Call(
            boxed(r),
            name,
            args.into_iter().map(|a| reroot(a, place, base)).collect(),
        ),
        other => other,
    };
    TExpr { kind, ..e }
}
