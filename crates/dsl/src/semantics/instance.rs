//! The instance tree of a program: one node per field of every global, top-level field and
//! scenario, down to scalars, each scalar a solver variable. Lists hold a size variable and,
//! once their size is decided, their elements. References into the road network (route,
//! junction, map and their subtypes) are not expanded: the runtime finds them in the map.
//!
//! Each invocation of a behavior with a `do` in a scenario's `do` (ASAM OpenSCENARIO DSL 2.1
//! §7.3.9) is an instance of the invoked behavior of its own, a root named by the caller's
//! instance and the invocation's phase path (`main.do.round_two`), expanded in turn (invocations
//! in its `do`: `main.do.round_two.do.slow`). A parameter given an actor or struct of the
//! caller is that instance (the same node); the other parameters are nodes of their own. An
//! invocation of an action with `keep(…)` in its `with:` is an instance the same way, so the
//! keep constrains that invocation's arguments.

use std::collections::HashMap;

use super::check::{Invocation, Place, Seg, TExpr, TKind};
use super::hir::CompoundKind;
use super::model::Model;
use super::solver::{Problem, VarId, VarKind};
use super::types::{CompoundId, Ty};

/// Index of a node in [`Tree::nodes`].
pub type NodeId = usize;

/// Deepest nesting expanded; deeper fields are left as references (a guard against
/// self-containing user types).
const MAX_DEPTH: usize = 24;

/// A node of the instance tree.
#[derive(Debug, Clone, PartialEq)]
pub enum Node {
    /// A scalar field and its variable.
    Scalar(VarId, Ty),
    /// A struct or actor instance with its fields.
    Compound(CompoundId, Vec<(String, NodeId)>),
    /// A list: its size variable and, once sized, its elements.
    List(Ty, VarId, Option<Vec<NodeId>>),
    /// A reference resolved at run time (road network element, or a cut cycle).
    Reference(Ty),
    /// A state variable (`var`): it has values only while the scenario runs.
    State(Ty),
}

/// The instance tree and the variables of its scalars.
#[derive(Debug, Clone, Default)]
pub struct Tree {
    /// All nodes.
    pub nodes: Vec<Node>,
    /// The roots: globals and top-level fields, then scenarios.
    pub roots: Vec<(String, NodeId)>,
    /// Compound instances (node, type), for instantiating type-level constraints.
    pub instances: Vec<(NodeId, CompoundId)>,
    /// The path of each node, for messages and list-size decisions.
    pub paths: Vec<String>,
    /// Invocation instances: (index of the invocation, the caller's node, the instance).
    pub invocations: Vec<(usize, NodeId, NodeId)>,
    /// The variables.
    pub problem: Problem,
}

impl Tree {
    /// Builds the tree; `sizes` holds the decided size of lists by path, `invocations` the
    /// program's invocations of behaviors with a `do`.
    pub fn build(
        model: &Model,
        sizes: &HashMap<String, usize>,
        invocations: &[Invocation],
    ) -> Tree {
        let mut t = Tree::default();
        let mut b = Builder {
            model,
            sizes,
            tree: &mut t,
            stack: Vec::new(),
        };
        for g in &model.globals {
            let n = if g.is_var {
                b.push(Node::State(g.ty.clone()), g.name.clone())
            } else {
                b.node(&g.ty, g.name.clone())
            };
            b.tree.roots.push((g.name.clone(), n));
        }
        let mut scenarios = Vec::new();
        for (i, c) in model.compounds.iter().enumerate() {
            if c.kind == CompoundKind::Scenario && !is_library(model, CompoundId(i as u32)) {
                let n = b.node(&Ty::Compound(CompoundId(i as u32)), c.name.clone());
                b.tree.roots.push((c.name.clone(), n));
                scenarios.push((CompoundId(i as u32), n, c.name.clone()));
            }
        }
        for (c, n, name) in scenarios {
            b.invocations(invocations, c, n, &name, &mut vec![c]);
        }
        t
    }

    /// The scalar variables of node `n` and everything under it (list sizes are not among
    /// them: a sized list's size is fixed by a hard constraint of the resolver's stage).
    pub fn vars_under(&self, n: NodeId) -> Vec<VarId> {
        let mut out = Vec::new();
        let mut stack = vec![n];
        while let Some(n) = stack.pop() {
            match &self.nodes[n] {
                Node::Scalar(v, _) => out.push(*v),
                Node::Compound(_, fields) => stack.extend(fields.iter().map(|f| f.1)),
                Node::List(_, _, items) => stack.extend(items.iter().flatten()),
                Node::Reference(_) | Node::State(_) => {}
            }
        }
        out
    }

    /// Lists whose size is not decided yet, in tree order.
    pub fn unsized_lists(&self) -> Vec<NodeId> {
        (0..self.nodes.len())
            .filter(|n| matches!(self.nodes[*n], Node::List(_, _, None)))
            .collect()
    }
}

/// Scenarios of the library are not instantiated (only those of the user's files).
pub(super) fn is_library(model: &Model, id: CompoundId) -> bool {
    model.compound(id).span.file.0 < model.library_files
}

struct Builder<'a> {
    model: &'a Model,
    sizes: &'a HashMap<String, usize>,
    tree: &'a mut Tree,
    stack: Vec<CompoundId>,
}

impl Builder<'_> {
    /// The instances of the invocations in the `do` of `caller` (its instance `node` at
    /// `path`), each a root, and theirs in turn; `open` holds the behaviors being expanded (a
    /// recursive invocation, reported by the checker, is not expanded again).
    fn invocations(
        &mut self,
        invocations: &[Invocation],
        caller: CompoundId,
        node: NodeId,
        path: &str,
        open: &mut Vec<CompoundId>,
    ) {
        if open.len() > MAX_DEPTH {
            return;
        }
        for (k, inv) in invocations.iter().enumerate() {
            if inv.caller != caller || open.contains(&inv.callee) {
                continue;
            }
            let here = format!("{path}.{}", inv.path);
            let id = self.push(Node::Compound(inv.callee, Vec::new()), here.clone());
            self.tree.instances.push((id, inv.callee));
            let mut fields = Vec::new();
            for f in self.model.all_fields(inv.callee) {
                let alias = inv
                    .aliases
                    .iter()
                    .find(|(p, _)| *p == f.name)
                    .and_then(|(_, e)| self.place(e, node));
                let n = match alias {
                    Some(n) => n,
                    None => {
                        let p = format!("{here}.{}", f.name);
                        if f.is_var {
                            self.push(Node::State(f.ty.clone()), p)
                        } else {
                            self.node(&f.ty, p)
                        }
                    }
                };
                fields.push((f.name.clone(), n));
            }
            self.tree.nodes[id] = Node::Compound(inv.callee, fields);
            self.tree.roots.push((here.clone(), id));
            self.tree.invocations.push((k, node, id));
            open.push(inv.callee);
            self.invocations(invocations, inv.callee, id, &here, open);
            open.pop();
        }
    }

    /// The node a path argument names, in the caller's instance `this` (`None`: not a path
    /// the tree holds yet, such as an element of a list not sized yet).
    fn place(&self, e: &TExpr, this: NodeId) -> Option<NodeId> {
        let TKind::Path(place, segs) = &e.kind else {
            return None;
        };
        let mut cur = match place {
            Place::This => this,
            Place::Global(i) => self.tree.roots.get(*i)?.1,
            Place::Local(_) | Place::It => return None,
        };
        for seg in segs {
            cur = match (seg, &self.tree.nodes[cur]) {
                (Seg::Field(f), Node::Compound(_, fields)) => {
                    fields.iter().find(|(n, _)| n == f)?.1
                }
                (Seg::Index(i), Node::List(_, _, Some(items))) => match i.kind {
                    TKind::Number(x) if x >= 0.0 && x.fract() == 0.0 => *items.get(x as usize)?,
                    _ => return None,
                },
                _ => return None,
            };
        }
        Some(cur)
    }

    fn push(&mut self, n: Node, path: String) -> NodeId {
        self.tree.nodes.push(n);
        self.tree.paths.push(path);
        self.tree.nodes.len() - 1
    }

    fn var(&mut self, path: &str, kind: VarKind) -> VarId {
        self.tree.problem.add_var(path, kind)
    }

    fn node(&mut self, ty: &Ty, path: String) -> NodeId {
        let num = |integer, lo| VarKind::Number {
            integer,
            lo,
            hi: None,
        };
        match ty {
            Ty::Bool => {
                let v = self.var(&path, VarKind::Enum { count: 2 });
                self.push(Node::Scalar(v, ty.clone()), path)
            }
            Ty::Int | Ty::Uint | Ty::Float | Ty::Physical(_) => {
                let kind = match ty {
                    Ty::Int => num(true, None),
                    Ty::Uint => num(true, Some(0.0)),
                    _ => num(false, None),
                };
                let v = self.var(&path, kind);
                self.push(Node::Scalar(v, ty.clone()), path)
            }
            Ty::Enum(e) => {
                let count = self.model.enum_def(*e).members.len() as u32;
                let v = self.var(&path, VarKind::Enum { count });
                self.push(Node::Scalar(v, ty.clone()), path)
            }
            Ty::Str => {
                let v = self.var(&path, VarKind::Text);
                self.push(Node::Scalar(v, ty.clone()), path)
            }
            Ty::Compound(c) => {
                if is_reference(self.model, *c)
                    || self.stack.contains(c)
                    || self.stack.len() >= MAX_DEPTH
                {
                    return self.push(Node::Reference(ty.clone()), path);
                }
                let id = self.push(Node::Compound(*c, Vec::new()), path.clone());
                self.tree.instances.push((id, *c));
                self.stack.push(*c);
                let mut fields = Vec::new();
                for f in self.model.all_fields(*c) {
                    let p = format!("{path}.{}", f.name);
                    let n = if f.is_var {
                        self.push(Node::State(f.ty.clone()), p)
                    } else {
                        self.node(&f.ty, p)
                    };
                    fields.push((f.name.clone(), n));
                }
                self.stack.pop();
                self.tree.nodes[id] = Node::Compound(*c, fields);
                id
            }
            Ty::List(elem) => {
                let size = self.var(&format!("{path}.size()"), num(true, Some(0.0)));
                let id = self.push(Node::List((**elem).clone(), size, None), path.clone());
                if let Some(&n) = self.sizes.get(&path) {
                    let items = (0..n)
                        .map(|i| self.node(elem, format!("{path}[{i}]")))
                        .collect();
                    self.tree.nodes[id] = Node::List((**elem).clone(), size, Some(items));
                }
                id
            }
            Ty::Range(_) | Ty::Event | Ty::Error => self.push(Node::Reference(ty.clone()), path),
        }
    }
}

/// Road-network types and the map's traffic lights (§8.14.7): found in the map by the runtime,
/// not sampled.
fn is_reference(model: &Model, c: CompoundId) -> bool {
    model.ancestry(c).into_iter().any(|a| {
        let d = model.compound(a);
        // The library's name, whether or not a file's own `route` made it `std::route`.
        let bare = d.name.strip_prefix("std::").unwrap_or(&d.name);
        is_library(model, a)
            && matches!(
                bare,
                "route" | "junction" | "map" | "traffic_light" | "traffic_light_group"
            )
    })
}
