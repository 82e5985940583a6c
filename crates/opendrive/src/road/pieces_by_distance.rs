//! The pieces of one road in order of their box's distance from a point, without allocation
//! (for [`RoadNetwork::locate_point_on_road`](crate::RoadNetwork::locate_point_on_road), the
//! inverse of OpenDRIVE 1.8 §8.3's reference-line coordinates on a given road).
//!
//! The order is exactly that of sorting the road's pieces by (squared box distance, piece
//! index) — a stable sort by distance — but the caller usually stops after two or three
//! pieces, so the pieces are found a few at a time: one pass over the road keeps the
//! [`BATCH`] nearest not yet given, skipping every run of [`GROUP`](super::spatial::GROUP) consecutive pieces whose
//! joint box is farther than the farthest kept (the joint box holds its pieces' boxes, so none
//! of them can be nearer), after the run whose joint box is nearest (`pass`). A long road (a
//! 20 km highway has 2,000 pieces) then costs two passes over its runs' boxes and a few
//! runs' pieces, not a sort of all its pieces.

use super::spatial::{PieceGroup, SpatialIndex};
use crate::math::Real;

/// Pieces found per pass.
const BATCH: usize = 4;

/// A piece and its box's squared distance from the point: the sort key, compared by distance
/// (`total_cmp`) and then by piece index.
type Key = (Real, usize);

fn before(a: Key, b: Key) -> bool {
    a.0.total_cmp(&b.0).then(a.1.cmp(&b.1)).is_lt()
}

/// The pieces of one road, nearest box first, as (piece index, squared box distance).
pub(crate) struct PiecesByDistance<'a> {
    index: &'a SpatialIndex,
    groups: &'a [PieceGroup],
    point: [Real; 2],
    /// The pieces of the current pass, in order; `batch[next..len]` are still to give.
    batch: [Key; BATCH],
    len: usize,
    next: usize,
    /// Whether no piece remains after the current pass's.
    last_pass: bool,
}

impl<'a> PiecesByDistance<'a> {
    /// The pieces of road `road` by distance from (x, y).
    pub(crate) fn new(index: &'a SpatialIndex, road: usize, x: Real, y: Real) -> Self {
        let mut it = Self {
            index,
            groups: &index.groups[index.groups_per_road[road].clone()],
            point: [x, y],
            batch: [(0.0, 0); BATCH],
            len: 0,
            next: 0,
            last_pass: false,
        };
        it.pass(None);
        it
    }

    /// Fills the batch with the (up to) [`BATCH`] nearest pieces after key `after`.
    ///
    /// The group whose joint box is nearest is scanned first: its pieces fill the batch with
    /// near keys, so the other groups' boxes are mostly farther than the farthest kept and
    /// skipped. In road order alone, every group between the road's start and the point
    /// comes nearer than the farthest kept so far and is scanned piece by piece: a point at s
    /// cost the road's pieces up to s, which made placing n vehicles along a stretch n times
    /// as long cost n² (`make_scale.py`'s 4,000 vehicles on 15 km of its 20 km road: 875 M
    /// instructions, 14 times the 1,000's on 3.8 km). The order of the scan does not change the batch:
    /// it keeps the [`BATCH`] least keys after `after` of every piece not skipped, and a
    /// group is skipped only when its joint box, and so each of its pieces' boxes, is
    /// farther than the farthest kept.
    fn pass(&mut self, after: Option<Key>) {
        self.len = 0;
        self.next = 0;
        let groups = self.groups;
        let nearest = self.nearest_group();
        if let Some(g) = nearest {
            self.scan(&groups[g], after);
        }
        for (gi, g) in groups.iter().enumerate() {
            if Some(gi) == nearest
                || (self.len == BATCH && g.env.distance_2(&self.point) > self.batch[BATCH - 1].0)
            {
                continue;
            }
            self.scan(g, after);
        }
        self.last_pass = self.len < BATCH;
    }

    /// The group whose joint box is nearest the point (the first of equals).
    fn nearest_group(&self) -> Option<usize> {
        let mut best: Option<(Real, usize)> = None;
        for (gi, g) in self.groups.iter().enumerate() {
            let d = g.env.distance_2(&self.point);
            if best.is_none_or(|(b, _)| d < b) {
                best = Some((d, gi));
            }
        }
        best.map(|(_, gi)| gi)
    }

    /// Keeps, of group `g`'s pieces after key `after`, those among the [`BATCH`] least keys.
    fn scan(&mut self, g: &PieceGroup, after: Option<Key>) {
        for i in g.pieces.clone() {
            let key = (self.index.boxes[i].distance_2(&self.point), i);
            if after.is_some_and(|a| !before(a, key)) {
                continue;
            }
            if self.len == BATCH && !before(key, self.batch[BATCH - 1]) {
                continue;
            }
            // Insert in order, dropping the farthest when full.
            let mut at = self.len.min(BATCH - 1);
            while at > 0 && before(key, self.batch[at - 1]) {
                self.batch[at] = self.batch[at - 1];
                at -= 1;
            }
            self.batch[at] = key;
            self.len = (self.len + 1).min(BATCH);
        }
    }
}

impl Iterator for PiecesByDistance<'_> {
    type Item = (usize, Real);

    fn next(&mut self) -> Option<Self::Item> {
        if self.next == self.len {
            if self.last_pass {
                return None;
            }
            self.pass(Some(self.batch[BATCH - 1]));
            if self.len == 0 {
                return None;
            }
        }
        let (d2, i) = self.batch[self.next];
        self.next += 1;
        Some((i, d2))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::road::frame::tests::straight_road;
    use crate::road::lane_span::tests::centre_only_section;

    /// The reference order: every piece of the road, stably sorted by box distance.
    fn sorted(index: &SpatialIndex, road: usize, x: Real, y: Real) -> Vec<(usize, Real)> {
        let mut all: Vec<(usize, Real)> = (0..index.pieces.len())
            .filter(|&i| index.pieces[i].road == road)
            .map(|i| (i, index.boxes[i].distance_2(&[x, y])))
            .collect();
        all.sort_by(|a, b| a.1.total_cmp(&b.1));
        all
    }

    /// Asserts that road `road`'s `count` pieces come in the full sort's order from each point.
    fn assert_sorted_order(
        index: &SpatialIndex,
        road: usize,
        count: usize,
        points: &[(Real, Real)],
    ) {
        for &(x, y) in points {
            let got: Vec<(usize, Real)> = PiecesByDistance::new(index, road, x, y).collect();
            let want = sorted(index, road, x, y);
            assert_eq!(got.len(), count, "({x}, {y})");
            assert!(
                got.iter().zip(&want).all(|(a, b)| a.0 == b.0 && a.1 == b.1),
                "({x}, {y}): {:?} vs {:?}",
                &got[..6],
                &want[..6]
            );
        }
    }

    #[test]
    fn gives_the_stable_sort_order_of_every_piece() {
        // A straight 1,000 m road without lanes: 100 pieces of 10 m, boxes [10k − 0.5,
        // 10k + 10.5] × [−0.5, 0.5] (MARGIN 0.5), so neighbouring boxes overlap by 1 m and
        // points there tie at distance 0 (the lower index comes first). Points on the road,
        // on a shared margin, beside it and beyond both ends.
        let centre_only = centre_only_section();
        let roads = vec![
            straight_road(30.0, vec![], vec![centre_only.clone()]),
            straight_road(1000.0, vec![], vec![centre_only]),
        ];
        let index = SpatialIndex::build(&roads);
        assert_eq!(index.pieces.iter().filter(|p| p.road == 1).count(), 100);
        assert_sorted_order(
            &index,
            1,
            100,
            &[
                (505.0, 0.0),
                (500.2, 0.1),
                (0.0, 0.0),
                (733.3, 40.0),
                (-50.0, 3.0),
                (1200.0, -7.0),
                (250.0, 1e6),
            ],
        );
        // (500.2, 0.1) lies in the boxes of pieces 49 (ends at 500.5) and 50 (starts at
        // 499.5): both at distance 0, 49 first; road 1's pieces follow road 0's 3.
        let first: Vec<(usize, Real)> = PiecesByDistance::new(&index, 1, 500.2, 0.1)
            .take(3)
            .collect();
        let base = 3; // road 0's pieces come first
        assert_eq!(first[0], (base + 49, 0.0));
        assert_eq!(first[1], (base + 50, 0.0));
        // The third: piece 51's box starts at 509.5, 9.3 m away (piece 48's ends at 490.5,
        // 9.7 m away).
        assert_eq!(first[2].0, base + 51);
        assert!((first[2].1 - 9.3 * 9.3).abs() < 1e-9, "{:?}", first[2]);
    }

    #[test]
    fn the_nearest_group_first_gives_the_same_order_on_a_long_road() {
        // A straight 20 km road: 2,000 pieces of 10 m in 125 groups of 16. Points near its
        // far end (where the road-order scan went through every group before them), in the
        // middle, on a group's joint edge (piece 1,600 starts at 16,000 m, group 100's first
        // piece), beside the road and off both ends; every piece in the full sort's order.
        let road = straight_road(20_000.0, vec![], vec![centre_only_section()]);
        let index = SpatialIndex::build(&[road]);
        assert_eq!(index.pieces.len(), 2_000);
        assert_sorted_order(
            &index,
            0,
            2_000,
            &[
                (19_995.0, 0.0),
                (19_999.9, 1.5),
                (10_003.0, -0.2),
                (16_000.0, 0.0),
                (7_777.0, 300.0),
                (-20.0, 0.0),
                (20_050.0, -4.0),
            ],
        );
        // (19,995, 0) lies in piece 1,999's box only (piece 1,998's ends at 19,990.5):
        // distance 0 first, then piece 1,998 at 4.5 m.
        let first: Vec<(usize, Real)> = PiecesByDistance::new(&index, 0, 19_995.0, 0.0)
            .take(2)
            .collect();
        assert_eq!(first[0], (1_999, 0.0));
        assert_eq!(first[1].0, 1_998);
        assert!((first[1].1 - 4.5 * 4.5).abs() < 1e-9, "{:?}", first[1]);
    }
}
