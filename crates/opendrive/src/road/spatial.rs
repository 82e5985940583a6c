//! Spatial index over the road surfaces: every geometry is cut into pieces of at most
//! [`PIECE_LENGTH`] metres (longer pieces, at most [`MAX_PIECES`] per geometry, on geometries
//! over 100 km, so that a file with an absurd length builds in bounded time), and each piece's axis-aligned box (reference line ± the outermost
//! lane borders, plus a margin for curvature between samples) goes into an R*-tree (`rstar`)
//! and a uniform grid (`point_grid`, for "which boxes hold this point", in the tree's order).
//! A look-up visits only pieces whose box is near the point, then projects exactly.

use std::ops::Range;

use rayon::prelude::*;
use rstar::{Envelope, RTree, AABB};

use super::lane_span::road_extent;
use super::plan_frame::{plan_frame, Hints};
use super::point_grid::{Entry, PointGrid};
use crate::math::Real;
use crate::model::Road;

/// Longest piece of road per index entry (m), on geometries up to `MAX_PIECES` of them long.
const PIECE_LENGTH: Real = 10.0;
/// Most pieces per geometry (100 km at [`PIECE_LENGTH`]); a longer geometry gets longer pieces,
/// whose boxes still hold its surface (the sagitta margin grows with the piece).
const MAX_PIECES: usize = 10_000;
/// Samples per piece (ends included).
const SAMPLES: usize = 5;
/// Margin added around each box (m): lane heights on banked roads, cubic lane widths
/// between samples.
const MARGIN: Real = 0.5;

/// A stretch [s0, s1] of one road, with what its look-ups need first.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Piece {
    /// Index of the road in the network.
    pub(crate) road: usize,
    /// Start s (m).
    pub(crate) s0: Real,
    /// End s (m).
    pub(crate) s1: Real,
    /// The geometry and profile records valid at the piece's middle.
    pub(crate) hints: Hints,
    /// The road surface's extent where it is the same at every s around the piece's middle.
    pub(crate) extent: Option<ConstantExtent>,
}

/// Over s ∈ [lo, hi] the road surface spans t ∈ [right, left], the same numbers bit for bit
/// as `road_extent` gives at every such s ([`Road::constant_lanes`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct ConstantExtent {
    pub(crate) lo: Real,
    pub(crate) hi: Real,
    pub(crate) right: Real,
    pub(crate) left: Real,
}

impl Piece {
    /// The road surface's extent (right t, left t) at `s` if the piece knows it there.
    #[inline]
    pub(crate) fn extent_at(&self, s: Real) -> Option<(Real, Real)> {
        self.extent
            .filter(|e| e.lo <= s && s <= e.hi)
            .map(|e| (e.right, e.left))
    }

    fn new(road_index: usize, road: &Road, s0: Real, s1: Real) -> Self {
        let mid = 0.5 * (s0 + s1);
        let extent = road.constant_lanes(mid).map(|(lo, hi)| {
            let (right, left) = road_extent(road, road.lane_section_at(mid), mid);
            ConstantExtent {
                lo,
                hi,
                right,
                left,
            }
        });
        Self {
            road: road_index,
            s0,
            s1,
            hints: Hints::at(road, mid),
            extent,
        }
    }
}

/// Consecutive pieces of a road per joint box.
pub(crate) const GROUP: usize = 16;

/// A run of at most [`GROUP`] consecutive pieces of one road and a box holding all their
/// boxes.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct PieceGroup {
    /// The joint box; the whole plane when a piece's box is not finite (never skipped then).
    pub(super) env: AABB<[Real; 2]>,
    /// The pieces, as indices into [`SpatialIndex::pieces`].
    pub(super) pieces: Range<usize>,
}

impl PieceGroup {
    /// The groups of the pieces `range`, whose boxes are `boxes[range]`, in order.
    pub(crate) fn of_road(
        boxes: &[AABB<[Real; 2]>],
        range: Range<usize>,
    ) -> impl Iterator<Item = PieceGroup> + '_ {
        range.clone().step_by(GROUP).map(move |first| {
            let pieces = first..(first + GROUP).min(range.end);
            let finite = boxes[pieces.clone()]
                .iter()
                .all(|b| b.lower().iter().chain(&b.upper()).all(|v| v.is_finite()));
            let env = if finite {
                boxes[pieces.clone()]
                    .iter()
                    .fold(AABB::new_empty(), |acc, b| acc.merged(b))
            } else {
                AABB::from_corners([Real::NEG_INFINITY; 2], [Real::INFINITY; 2])
            };
            PieceGroup { env, pieces }
        })
    }
}

/// The R*-tree of road pieces.
#[derive(Debug, Clone)]
pub(crate) struct SpatialIndex {
    pub(crate) tree: RTree<Entry>,
    /// A grid giving the tree's answers for most points, faster.
    grid: Option<PointGrid>,
    pub(crate) pieces: Vec<Piece>,
    pub(crate) boxes: Vec<AABB<[Real; 2]>>,
    /// Runs of consecutive pieces of one road with their joint boxes, road after road.
    pub(crate) groups: Vec<PieceGroup>,
    /// The runs of road i are `groups[groups_per_road[i]]`.
    pub(crate) groups_per_road: Vec<Range<usize>>,
}

impl SpatialIndex {
    /// Builds the index for all roads.
    pub(crate) fn build(roads: &[Road]) -> Self {
        // Each road's pieces on their own (in parallel: a piece's box reads its road only),
        // then joined in road order, so the index is the same whatever the thread count.
        let per_road_pieces: Vec<Vec<(Piece, AABB<[Real; 2]>)>> = roads
            .par_iter()
            .enumerate()
            .map(|(ri, road)| road_pieces(ri, road))
            .collect();
        let total = per_road_pieces.iter().map(Vec::len).sum();
        let mut pieces = Vec::with_capacity(total);
        let mut boxes = Vec::with_capacity(total);
        let mut per_road = Vec::with_capacity(roads.len());
        for list in per_road_pieces {
            let first = pieces.len();
            for (piece, env) in list {
                pieces.push(piece);
                boxes.push(env);
            }
            per_road.push(first..pieces.len());
        }
        let mut groups = Vec::with_capacity(total / GROUP + roads.len());
        let mut groups_per_road = Vec::with_capacity(roads.len());
        for range in &per_road {
            let first = groups.len();
            groups.extend(PieceGroup::of_road(&boxes, range.clone()));
            groups_per_road.push(first..groups.len());
        }
        let entries = boxes
            .iter()
            .enumerate()
            .map(|(i, env)| Entry {
                env: *env,
                piece: i,
            })
            .collect();
        let tree = RTree::bulk_load(entries);
        Self {
            grid: PointGrid::new(&tree, &boxes),
            tree,
            pieces,
            boxes,
            groups,
            groups_per_road,
        }
    }

    /// Bounding box of everything: [min x, min y, max x, max y].
    pub(crate) fn bounds(&self) -> Option<[Real; 4]> {
        if self.pieces.is_empty() {
            return None;
        }
        let env = self.tree.root().envelope();
        let (lo, hi) = (env.lower(), env.upper());
        Some([lo[0], lo[1], hi[0], hi[1]])
    }

    /// Calls `f` with every piece whose box holds (x, y), in the order of the R*-tree's
    /// `locate_all_at_point`.
    pub(crate) fn for_each_containing(&self, x: Real, y: Real, mut f: impl FnMut(usize)) {
        if let Some(grid) = &self.grid {
            if grid.for_each_containing(&self.boxes, x, y, &mut f) {
                return;
            }
        }
        self.tree
            .locate_all_at_point(&[x, y])
            .for_each(|e| f(e.piece));
    }

    /// Index entries in order of their box's distance to (x, y), with squared distance.
    pub(crate) fn nearest(&self, x: Real, y: Real) -> impl Iterator<Item = (usize, Real)> + '_ {
        self.tree
            .nearest_neighbor_iter_with_distance_2(&[x, y])
            .map(|(e, d2)| (e.piece, d2))
    }
}

/// The pieces of road `ri` with their boxes, in order of s: each geometry cut into equal
/// pieces of at most [`PIECE_LENGTH`].
fn road_pieces(ri: usize, road: &Road) -> Vec<(Piece, AABB<[Real; 2]>)> {
    let mut out = Vec::new();
    let geoms = road.plan_view.geometries();
    for (gi, g) in geoms.iter().enumerate() {
        let g_end = geoms
            .get(gi + 1)
            .map_or(road.length, |n| n.s)
            .min(road.length);
        let g_start = g.s.min(g_end);
        let n = (((g_end - g_start) / PIECE_LENGTH).ceil() as usize).clamp(1, MAX_PIECES);
        let h = (g_end - g_start) / n as Real;
        for k in 0..n {
            let s0 = g_start + h * k as Real;
            let s1 = if k + 1 == n { g_end } else { s0 + h };
            let piece = Piece::new(ri, road, s0, s1);
            out.push((piece, piece_box(road, &piece)));
        }
    }
    out
}

/// Box of the road surface over [s0, s1]: sampled at the ends, interior points and either
/// side of every lane-section start inside, widened by the sagitta between samples and
/// [`MARGIN`]. The samples' places are `plan_frame`'s (the full frame's x and y, bit for bit,
/// without the pitch) and the surface's extent the piece's where the lanes are constant.
fn piece_box(road: &Road, piece: &Piece) -> AABB<[Real; 2]> {
    let (s0, s1) = (piece.s0, piece.s1);
    let mut lo = [Real::INFINITY; 2];
    let mut hi = [Real::NEG_INFINITY; 2];
    let mut max_k: Real = 0.0;
    let mut max_t: Real = 0.0;
    let mut add = |s: Real| {
        let f = plan_frame(road, s, piece.hints);
        let (right, left) = piece.extent_at(s).unwrap_or_else(|| {
            let section = road.lane_section_at(s);
            road_extent(road, section, s)
        });
        max_k = max_k.max(f.curvature.abs());
        max_t = max_t.max(right.abs()).max(left.abs());
        for t in [right, left] {
            let [x, y] = f.place(t);
            lo = [lo[0].min(x), lo[1].min(y)];
            hi = [hi[0].max(x), hi[1].max(y)];
        }
    };
    for k in 0..SAMPLES {
        add(s0 + (s1 - s0) * k as Real / (SAMPLES - 1) as Real);
    }
    for ls in &road.lane_sections {
        if ls.s > s0 && ls.s < s1 {
            add(ls.s);
            add((ls.s - 1e-6).max(s0));
        }
    }
    // Between samples h apart, a curve of curvature κ leaves the chord by at most κh²/8; at
    // lateral offset t the curvature grows to κ/(1 − κt), bounded here by doubling.
    let h = (s1 - s0) / (SAMPLES - 1) as Real;
    let k_eff = if max_k * max_t < 0.5 {
        2.0 * max_k
    } else {
        1.0 / h.max(1e-3)
    };
    let pad = MARGIN + k_eff * h * h / 8.0 + if max_k * max_t >= 0.5 { h } else { 0.0 };
    AABB::from_corners([lo[0] - pad, lo[1] - pad], [hi[0] + pad, hi[1] + pad])
}
