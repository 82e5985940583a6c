//! The instance tree of a program: one node per field of every global, top-level field and
//! scenario, down to scalars, each scalar a solver variable. Lists hold a size variable and,
//! once their size is decided, their elements. References into the road network (route,
//! junction, map and their subtypes) are not expanded: the runtime finds them in the map.

use std::collections::HashMap;

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
    /// The variables.
    pub problem: Problem,
}

impl Tree {
    /// Builds the tree; `sizes` holds the decided size of lists by path.
    pub fn build(model: &Model, sizes: &HashMap<String, usize>) -> Tree {
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
        for (i, c) in model.compounds.iter().enumerate() {
            if c.kind == CompoundKind::Scenario && !is_library(model, CompoundId(i as u32)) {
                let n = b.node(&Ty::Compound(CompoundId(i as u32)), c.name.clone());
                b.tree.roots.push((c.name.clone(), n));
            }
        }
        t
    }

    /// Lists whose size is not decided yet, in tree order.
    pub fn unsized_lists(&self) -> Vec<NodeId> {
        (0..self.nodes.len())
            .filter(|n| matches!(self.nodes[*n], Node::List(_, _, None)))
            .collect()
    }
}

/// Scenarios of the library are not instantiated (only those of the user's files).
fn is_library(model: &Model, id: CompoundId) -> bool {
    model.compound(id).span.file.0 < model.library_files
}

struct Builder<'a> {
    model: &'a Model,
    sizes: &'a HashMap<String, usize>,
    tree: &'a mut Tree,
    stack: Vec<CompoundId>,
}

impl Builder<'_> {
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

/// Road-network types: found in the map by the runtime, not sampled.
fn is_reference(model: &Model, c: CompoundId) -> bool {
    model.ancestry(c).into_iter().any(|a| {
        let d = model.compound(a);
        // The library's name, whether or not a file's own `route` made it `std::route`.
        let bare = d.name.strip_prefix("std::").unwrap_or(&d.name);
        is_library(model, a) && matches!(bare, "route" | "junction" | "map")
    })
}
