//! A uniform grid over the road pieces' boxes for the first question of the world → road
//! look-up (OpenDRIVE 1.8 §8.3, inverse): which boxes hold a point. Each cell lists the boxes
//! that reach into it; a look-up tests only its cell's few boxes instead of walking the
//! R*-tree (tens of box tests per point on the 60 MB town grid).
//!
//! Same answer, same order as the tree (`rstar`'s `locate_all_at_point`), which decides
//! between equally good candidates: that walk gives the boxes holding the point in one fixed
//! order of all leaves (the order of `RTree::iter`, the same walk without the tests), so each
//! cell lists its boxes in that order, and the few boxes too large to list in every cell they
//! cover are merged in by it. The tree gives a leaf when every ancestor's box `contains_point` and the leaf's
//! `distance_2` is ≤ 0; for finite boxes and a point with |x|, |y| ≥ [`TINY`] that is exactly
//! "the leaf's box contains the point" (an ancestor's box is the component-wise min/max of
//! its children's, so it holds what they hold; and a point outside a box by at least one ulp
//! of a coordinate that large has a squared distance > 0, no underflow). Anything else — a
//! network with a non-finite box, a point nearer an axis than [`TINY`] — is asked of the tree.

use rstar::{Envelope, PointDistance, RTree, RTreeObject, AABB};

use crate::math::Real;

/// An index entry: a piece's box and its index in `SpatialIndex::pieces` (`spatial`).
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Entry {
    pub(crate) env: AABB<[Real; 2]>,
    pub(crate) piece: usize,
}

impl RTreeObject for Entry {
    type Envelope = AABB<[Real; 2]>;
    fn envelope(&self) -> Self::Envelope {
        self.env
    }
}

impl PointDistance for Entry {
    fn distance_2(&self, point: &[Real; 2]) -> Real {
        self.env.distance_2(point)
    }
}

/// Points with a coordinate smaller than this in magnitude are looked up in the tree.
const TINY: Real = 1e-100;
/// Most cells along one axis.
const MAX_CELLS_PER_AXIS: usize = 4096;
/// A box reaching into more cells than this is kept on the list of large boxes instead.
const MAX_CELLS_PER_BOX: usize = 64;

/// The grid.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct PointGrid {
    /// The tree's root box: nothing outside it holds a point.
    root: AABB<[Real; 2]>,
    origin: [Real; 2],
    cell: [Real; 2],
    cells: [usize; 2],
    /// The pieces whose boxes reach into cell (i, j) are `items[start[k]..start[k + 1]]`,
    /// k = j·cells[0] + i, in the tree's order.
    start: Vec<u32>,
    items: Vec<u32>,
    /// Pieces whose boxes reach into more than [`MAX_CELLS_PER_BOX`] cells, in the tree's
    /// order.
    large: Vec<u32>,
    /// Each piece's position in the tree's order of all leaves (to merge `large` in).
    rank: Vec<u32>,
}

impl PointGrid {
    /// The grid over the boxes of `tree` (`boxes[piece]`); `None` when a box is not finite
    /// (the tree answers every look-up then) or there are no boxes.
    pub(crate) fn new(tree: &RTree<Entry>, boxes: &[AABB<[Real; 2]>]) -> Option<Self> {
        let finite = |b: &AABB<[Real; 2]>| {
            let (lo, hi) = (b.lower(), b.upper());
            lo.iter().chain(&hi).all(|v| v.is_finite()) && lo[0] <= hi[0] && lo[1] <= hi[1]
        };
        if boxes.is_empty() || !boxes.iter().all(finite) {
            return None;
        }
        let root = tree.root().envelope();
        let (lo, hi) = (root.lower(), root.upper());
        let size = [hi[0] - lo[0], hi[1] - lo[1]];
        if !(size[0].is_finite() && size[1].is_finite()) {
            return None;
        }
        // About one cell per box, square where the bounds allow.
        let side = (size[0] * size[1] / boxes.len() as Real).sqrt().max(1e-3);
        let count = |len: Real| ((len / side).ceil() as usize).clamp(1, MAX_CELLS_PER_AXIS);
        let cells = [count(size[0]), count(size[1])];
        let mut grid = Self {
            root,
            origin: lo,
            cell: [size[0] / cells[0] as Real, size[1] / cells[1] as Real],
            cells,
            start: vec![0; cells[0] * cells[1] + 1],
            items: Vec::new(),
            large: Vec::new(),
            rank: vec![0; boxes.len()],
        };
        let order: Vec<usize> = tree.iter().map(|e| e.piece).collect();
        // Two passes: count per cell, then fill in the tree's order.
        for &piece in &order {
            for k in grid.listing_cells(&boxes[piece]).into_iter().flatten() {
                grid.start[k + 1] += 1;
            }
        }
        for k in 1..grid.start.len() {
            grid.start[k] += grid.start[k - 1];
        }
        let total = grid.start[grid.start.len() - 1] as usize;
        let mut fill: Vec<u32> = grid.start[..grid.start.len() - 1].to_vec();
        grid.items = vec![0; total];
        for (rank, &piece) in order.iter().enumerate() {
            grid.rank[piece] = rank as u32;
            match grid.listing_cells(&boxes[piece]) {
                Some(ks) => {
                    for k in ks {
                        grid.items[fill[k] as usize] = piece as u32;
                        fill[k] += 1;
                    }
                }
                None => grid.large.push(piece as u32),
            }
        }
        Some(grid)
    }

    /// The cell of (x, y), clamped to the grid.
    #[inline]
    fn cell_of(&self, p: [Real; 2]) -> [usize; 2] {
        let index = |a: usize| {
            // `as` saturates: below the origin gives 0.
            (((p[a] - self.origin[a]) / self.cell[a]) as usize).min(self.cells[a] - 1)
        };
        [index(0), index(1)]
    }

    /// The cells (as indices k) that list box `b`: every cell it reaches into, or `None` for
    /// a box reaching into more than [`MAX_CELLS_PER_BOX`] (kept with the large ones).
    fn listing_cells(&self, b: &AABB<[Real; 2]>) -> Option<impl Iterator<Item = usize>> {
        let ([i0, j0], [i1, j1]) = (self.cell_of(b.lower()), self.cell_of(b.upper()));
        let width = self.cells[0];
        ((i1 - i0 + 1) * (j1 - j0 + 1) <= MAX_CELLS_PER_BOX)
            .then(|| (j0..=j1).flat_map(move |j| (i0..=i1).map(move |i| j * width + i)))
    }

    /// Calls `f` with every piece whose box (`boxes[piece]`, the boxes the grid was built
    /// on) holds (x, y), in the tree's order; `false` (and no call) when the point is one the
    /// tree must answer (module doc).
    #[inline]
    pub(crate) fn for_each_containing(
        &self,
        boxes: &[AABB<[Real; 2]>],
        x: Real,
        y: Real,
        mut f: impl FnMut(usize),
    ) -> bool {
        if !(x.abs() >= TINY && y.abs() >= TINY) {
            return false;
        }
        let p = [x, y];
        if !self.root.contains_point(&p) {
            return true;
        }
        let [i, j] = self.cell_of(p);
        let k = j * self.cells[0] + i;
        let cell = &self.items[self.start[k] as usize..self.start[k + 1] as usize];
        let mut test = |piece: u32| {
            if boxes[piece as usize].contains_point(&p) {
                f(piece as usize);
            }
        };
        if self.large.is_empty() {
            cell.iter().for_each(|&piece| test(piece));
            return true;
        }
        // Merge the cell's list and the large boxes by rank.
        let (mut a, mut b) = (cell.iter().peekable(), self.large.iter().peekable());
        loop {
            let rank = |piece: &&u32| self.rank[**piece as usize];
            let next = match (a.peek(), b.peek()) {
                (Some(x), Some(y)) if rank(x) < rank(y) => a.next(),
                (Some(_), Some(_)) | (None, Some(_)) => b.next(),
                (Some(_), None) => a.next(),
                (None, None) => break,
            };
            if let Some(&piece) = next {
                test(piece);
            }
        }
        true
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// 3,000 boxes of assorted sizes on a lattice; with `large`, every 997th is 60 × 40 (over
    /// MAX_CELLS_PER_BOX cells).
    fn boxes(large: bool) -> Vec<AABB<[Real; 2]>> {
        (0..3000)
            .map(|i| {
                let (x, y) = ((i % 50) as Real * 2.0 + 0.5, (i / 50) as Real * 1.5 + 0.25);
                let (w, h) = if large && i % 997 == 0 {
                    (60.0, 40.0)
                } else {
                    (1.0 + (i % 7) as Real * 0.5, 0.5 + (i % 5) as Real * 0.75)
                };
                AABB::from_corners([x, y], [x + w, y + h])
            })
            .collect()
    }

    fn tree(boxes: &[AABB<[Real; 2]>]) -> RTree<Entry> {
        let entries: Vec<Entry> = boxes
            .iter()
            .enumerate()
            .map(|(piece, &env)| Entry { env, piece })
            .collect();
        RTree::bulk_load(entries)
    }

    #[test]
    fn same_pieces_in_the_same_order_as_the_tree() {
        // Queried on a finer lattice with points on box edges and outside everything: every
        // point the grid answers gets the tree's list, with and without large boxes.
        for large in [true, false] {
            let boxes = boxes(large);
            let tree = tree(&boxes);
            let grid = PointGrid::new(&tree, &boxes).expect("finite boxes");
            assert_eq!(grid.large.is_empty(), !large);
            let (mut points, mut hits) = (0, 0);
            for qx in -4..220 {
                for qy in -4..190 {
                    let (x, y) = (qx as Real * 0.5, qy as Real * 0.5);
                    let want: Vec<usize> =
                        tree.locate_all_at_point(&[x, y]).map(|e| e.piece).collect();
                    let mut got = Vec::new();
                    if grid.for_each_containing(&boxes, x, y, |i| got.push(i)) {
                        assert_eq!(got, want, "({x}, {y})");
                        points += 1;
                        hits += got.len();
                    } else {
                        // Only points on an axis go to the tree.
                        assert!(x == 0.0 || y == 0.0, "({x}, {y})");
                    }
                }
            }
            assert_eq!(points, 223 * 193);
            assert!(
                hits > points,
                "most points lie in more than one box: {hits}"
            );
        }
    }

    #[test]
    fn no_grid_over_a_non_finite_box() {
        let mut boxes = boxes(false);
        let tree = tree(&boxes);
        boxes[7] = AABB::from_corners([0.0, 0.0], [Real::INFINITY, 1.0]);
        assert!(PointGrid::new(&tree, &boxes).is_none());
    }
}
