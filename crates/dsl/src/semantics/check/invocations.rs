//! Invocations that reach the behavior they are written in (ASAM OpenSCENARIO DSL 2.1 §7.3.9
//! behavior invocation). Each invocation of a behavior with a `do` is an instance of it, so a
//! behavior that invokes itself, directly or through others, would be an infinite tree of
//! instances: an error at the invocation that closes the cycle, naming the chain.

use std::collections::BTreeSet;

use super::super::diagnostic::{Diagnostic, DiagnosticKind as K};
use super::super::model::Model;
use super::super::types::CompoundId;
use super::Invocation;

/// One error per cycle of invocations, at the first invocation (in source order) that closes
/// it.
pub(crate) fn recursion(model: &Model, invocations: &[Invocation]) -> Vec<Diagnostic> {
    let mut seen: Vec<BTreeSet<CompoundId>> = Vec::new();
    let mut out = Vec::new();
    let mut order: Vec<&Invocation> = invocations.iter().collect();
    order.sort_by_key(|i| (i.span.file, i.span.start));
    for inv in order {
        let Some(chain) = chain(invocations, inv.callee, inv.caller) else {
            continue;
        };
        let members: BTreeSet<CompoundId> = chain.iter().copied().collect();
        if seen.contains(&members) {
            continue;
        }
        seen.push(members);
        let names: Vec<String> = std::iter::once(inv.caller)
            .chain(chain)
            .map(|c| format!("`{}`", model.compound(c).name))
            .collect();
        out.push(Diagnostic::new(
            K::Recursion,
            inv.name_span,
            format!(
                "expected an invocation of a behavior that does not invoke this one, found a recursive invocation: {}",
                names.join(" invokes ")
            ),
        ));
    }
    out
}

/// The behaviors from `from` to `to` along invocations (both ends included), the shortest
/// such chain; `None` when `from` does not reach `to`.
fn chain(invocations: &[Invocation], from: CompoundId, to: CompoundId) -> Option<Vec<CompoundId>> {
    let mut parent: Vec<(CompoundId, Option<CompoundId>)> = vec![(from, None)];
    let mut i = 0;
    while i < parent.len() {
        let cur = parent[i].0;
        if cur == to {
            let mut out = vec![cur];
            let mut at = parent[i].1;
            while let Some(p) = at {
                out.push(p);
                at = parent.iter().find(|(c, _)| *c == p).and_then(|(_, q)| *q);
            }
            out.reverse();
            return Some(out);
        }
        for inv in invocations.iter().filter(|v| v.caller == cur) {
            if !parent.iter().any(|(c, _)| *c == inv.callee) {
                parent.push((inv.callee, Some(cur)));
            }
        }
        i += 1;
    }
    None
}
