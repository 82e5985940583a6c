//! The spatial index's R*-tree flattened into arrays, for the one question the world → road
//! look-up (OpenDRIVE 1.8 §8.3, inverse) asks first: which pieces' boxes hold a point.
//!
//! `rstar` keeps each node's children in a vector of 64-byte enum nodes and walks them with a
//! stack that spills to the heap on deep paths; here every node's children are one run of
//! (box, piece or node) slots, tested before they are entered, and the walk is a recursion
//! as deep as the tree. The pieces come out in exactly the order of `rstar`'s
//! `locate_all_at_point` (its stack pops a node's children last first, each child's subtree
//! before the next), with the same tests (a node is entered when its box `contains_point`, a
//! piece is given when its box's `distance_2` is ≤ 0): a look-up chooses among equally good
//! candidates by that order, so its results are the same bit for bit.

use std::ops::Range;

use rstar::{Envelope, ParentNode, RTree, RTreeNode, RTreeObject, AABB};

use super::spatial::Entry;
use crate::math::Real;

/// A child of a node: its box, and a piece (leaf) or another node.
#[derive(Debug, Clone, PartialEq)]
struct Slot {
    env: AABB<[Real; 2]>,
    /// Piece index (leaf) or node index.
    id: u32,
    leaf: bool,
}

/// The flat tree; node 0 is the root.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct PointTree {
    root_env: AABB<[Real; 2]>,
    /// The children of node i are `slots[nodes[i]]`.
    nodes: Vec<Range<usize>>,
    slots: Vec<Slot>,
}

impl PointTree {
    /// The flat copy of `tree`.
    pub(crate) fn new(tree: &RTree<Entry>) -> Self {
        let mut flat = Self {
            root_env: tree.root().envelope(),
            nodes: Vec::new(),
            slots: Vec::with_capacity(tree.size() + tree.size() / 4),
        };
        flat.add(tree.root());
        flat
    }

    /// Appends `node` and (after its run of slots) its descendants; returns its index.
    fn add(&mut self, node: &ParentNode<Entry>) -> u32 {
        let index = self.nodes.len();
        let first = self.slots.len();
        let children = node.children();
        self.nodes.push(first..first + children.len());
        for child in children {
            // Placeholders: the run must be contiguous, and parents are filled in below.
            let env = child.envelope();
            let (id, leaf) = match child {
                RTreeNode::Leaf(e) => (e.piece as u32, true),
                RTreeNode::Parent(_) => (u32::MAX, false),
            };
            self.slots.push(Slot { env, id, leaf });
        }
        for (k, child) in children.iter().enumerate() {
            if let RTreeNode::Parent(p) = child {
                let id = self.add(p);
                self.slots[first + k].id = id;
            }
        }
        index as u32
    }

    /// The root's box (the union of all boxes).
    pub(crate) fn root_envelope(&self) -> AABB<[Real; 2]> {
        self.root_env
    }

    /// Every piece, in the order [`for_each_containing`](Self::for_each_containing) gives
    /// them when all boxes hold the point.
    pub(crate) fn leaves_in_order(&self) -> Vec<usize> {
        fn walk(tree: &PointTree, node: usize, out: &mut Vec<usize>) {
            for slot in tree.slots[tree.nodes[node].clone()].iter().rev() {
                if slot.leaf {
                    out.push(slot.id as usize);
                } else {
                    walk(tree, slot.id as usize, out);
                }
            }
        }
        let mut out = Vec::new();
        walk(self, 0, &mut out);
        out
    }

    /// Calls `f` with every piece whose box holds (x, y), in `rstar`'s order.
    #[inline]
    pub(crate) fn for_each_containing(&self, x: Real, y: Real, mut f: impl FnMut(usize)) {
        let p = [x, y];
        if !self.nodes[0].is_empty() && self.root_env.contains_point(&p) {
            self.visit(0, &p, &mut f);
        }
    }

    fn visit(&self, node: usize, p: &[Real; 2], f: &mut impl FnMut(usize)) {
        for slot in self.slots[self.nodes[node].clone()].iter().rev() {
            if slot.leaf {
                if slot.env.distance_2(p) <= 0.0 {
                    f(slot.id as usize);
                }
            } else if slot.env.contains_point(p) {
                self.visit(slot.id as usize, p, f);
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn same_pieces_in_the_same_order_as_rstar() {
        // 2,000 overlapping boxes on a 40 × 50 lattice, each 3 × 2.5 units from its lattice
        // point (so most points lie in two to six boxes), queried on a finer lattice that
        // also hits box edges and points outside everything.
        let entries: Vec<Entry> = (0..2000)
            .map(|i| {
                let (x, y) = ((i % 40) as Real * 2.0, (i / 40) as Real * 1.5);
                Entry {
                    env: AABB::from_corners([x, y], [x + 3.0, y + 2.5]),
                    piece: i,
                }
            })
            .collect();
        let tree = RTree::bulk_load(entries);
        let flat = PointTree::new(&tree);
        let mut hits = 0;
        for qx in -4..170 {
            for qy in -4..160 {
                let (x, y) = (qx as Real * 0.5, qy as Real * 0.5);
                let want: Vec<usize> = tree.locate_all_at_point(&[x, y]).map(|e| e.piece).collect();
                let mut got = Vec::new();
                flat.for_each_containing(x, y, |i| got.push(i));
                assert_eq!(got, want, "({x}, {y})");
                hits += got.len();
            }
        }
        // Every box holds 7 × 6 query points (edges included): 2,000 · 42 hits in all.
        assert_eq!(hits, 2000 * 42);
    }
}
