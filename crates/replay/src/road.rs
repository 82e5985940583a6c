//! The road network as drawable shapes (OpenDRIVE 1.8 §9 reference line, §11 lanes, §11.8
//! road markings): per road and lane section, the lane borders sampled along s as world
//! polylines, each lane as the area between its inner and outer border with its lane type, and
//! the road marks as spans of a border.
//!
//! Sampling: breakpoints at the section's ends, the plan-view geometry starts, the lane width
//! records and the road-mark starts; between two breakpoints the interval is halved until the
//! midpoint of every border lies within [`SAG_TOLERANCE`] of its chord (at most
//! [`MAX_STEP`] apart). So a straight line costs two points and an arc of radius R about
//! `sqrt(8 R tol)` per point.

use opendrive::{
    Lane, LaneSection, LaneType, Road, RoadMark, RoadMarkColor, RoadMarkType, RoadNetwork,
};

/// Largest distance (m) between a border's true midpoint and its polyline chord.
pub const SAG_TOLERANCE: f64 = 0.02;
/// Longest step along s (m), so that long straight roads still carry points for hover tests.
pub const MAX_STEP: f64 = 50.0;
/// Shortest step along s (m): the subdivision stops here whatever the deviation.
const MIN_STEP: f64 = 0.05;
/// How far before a lane section's end its last sample is taken (m): at the end s itself the
/// next section's lanes apply (OpenDRIVE 1.8 §11.3), so the end is sampled just before it.
const SECTION_END_EPSILON: f64 = 1e-6;

/// All roads.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct RoadDrawing {
    /// One entry per road, in file order.
    pub roads: Vec<RoadShape>,
}

/// One road.
#[derive(Debug, Clone, PartialEq)]
pub struct RoadShape {
    /// `road/@id`.
    pub id: String,
    /// The junction the road belongs to (a connecting road), if any.
    pub junction: Option<String>,
    /// Its lane sections in s order.
    pub sections: Vec<SectionShape>,
}

/// One lane section, sampled at the same s for every border.
#[derive(Debug, Clone, PartialEq)]
pub struct SectionShape {
    /// The sample positions along the road (m).
    pub s: Vec<f64>,
    /// Lane borders from the leftmost outer border to the rightmost: the left lanes' outer
    /// borders (outermost first), the centre line (lane 0, at laneOffset), the right lanes'
    /// outer borders. Each holds one world point (x, y) per sample.
    pub borders: Vec<Vec<[f64; 2]>>,
    /// The lanes (not lane 0).
    pub lanes: Vec<LaneShape>,
    /// The road marks on the borders.
    pub marks: Vec<MarkSpan>,
}

/// A lane as the area between two borders.
#[derive(Debug, Clone, PartialEq)]
pub struct LaneShape {
    /// `lane/@id`.
    pub id: i32,
    /// `lane/@type`.
    pub lane_type: LaneType,
    /// Index of the border nearer the centre in [`SectionShape::borders`].
    pub inner: usize,
    /// Index of the outer border.
    pub outer: usize,
}

/// A road mark along part of a border.
#[derive(Debug, Clone, PartialEq)]
pub struct MarkSpan {
    /// Index in [`SectionShape::borders`].
    pub border: usize,
    /// First and last sample index it covers (inclusive).
    pub from: usize,
    /// Last sample index (inclusive).
    pub to: usize,
    /// The mark.
    pub mark: RoadMark,
}

impl RoadDrawing {
    /// The shapes of every road of `network`.
    pub fn new(network: &RoadNetwork) -> RoadDrawing {
        RoadDrawing {
            roads: network.roads().iter().map(road_shape).collect(),
        }
    }
}

/// The shapes of one road.
fn road_shape(road: &Road) -> RoadShape {
    let sections = (0..road.lane_sections.len())
        .filter_map(|i| section_shape(road, i))
        .collect();
    RoadShape {
        id: road.id.clone(),
        junction: road.junction.clone().filter(|j| j != "-1"),
        sections,
    }
}

/// The lane ids of a section whose outer borders make its border list, in border order.
fn border_lanes(section: &LaneSection) -> Vec<i32> {
    let left = section.left.iter().rev().map(|l| l.id);
    let right = section.right.iter().map(|l| l.id);
    left.chain(std::iter::once(0)).chain(right).collect()
}

/// The t of each border (outer border of each lane of `ids`) at `s`; `None` if a lane is
/// missing there.
fn border_ts(road: &Road, ids: &[i32], s: f64) -> Option<Vec<f64>> {
    ids.iter()
        .map(|&id| road.lane_span(id, s).ok().map(|sp| sp.outer))
        .collect()
}

/// World points of the borders at `s`.
fn border_points(road: &Road, ids: &[i32], s: f64) -> Option<Vec<[f64; 2]>> {
    border_ts(road, ids, s)?
        .into_iter()
        .map(|t| road.pose(s, t).ok().map(|p| [p.x, p.y]))
        .collect()
}

/// The sampled shape of lane section `index` of `road`; `None` if it is empty or cannot be
/// evaluated (a file whose lanes vanish within the section).
fn section_shape(road: &Road, index: usize) -> Option<SectionShape> {
    let section = &road.lane_sections[index];
    let start = section.s;
    let end = road.lane_section_end(index);
    if end - start < MIN_STEP * 0.5 {
        return None;
    }
    let last = if index + 1 < road.lane_sections.len() {
        end - SECTION_END_EPSILON
    } else {
        end
    };
    let ids = border_lanes(section);
    let mut breaks = vec![start, last];
    breaks.extend(
        road.plan_view
            .geometries()
            .iter()
            .map(|g| g.s)
            .filter(|&s| s > start && s < last),
    );
    for lane in section.lanes() {
        breaks.extend(lane.widths.iter().map(|w| start + w.start));
        breaks.extend(lane.road_marks.iter().map(|m| start + m.s_offset));
    }
    breaks.retain(|&s| s >= start && s <= last);
    breaks.sort_by(f64::total_cmp);
    breaks.dedup_by(|a, b| (*a - *b).abs() < MIN_STEP * 0.5);
    let mut s_values = vec![breaks[0]];
    let mut points = vec![border_points(road, &ids, breaks[0])?];
    for pair in breaks.windows(2) {
        subdivide(road, &ids, (pair[0], pair[1]), &mut s_values, &mut points)?;
    }
    let borders = (0..ids.len())
        .map(|b| points.iter().map(|p| p[b]).collect())
        .collect();
    let centre = ids.iter().position(|&id| id == 0)?;
    let lanes = section
        .lanes()
        .filter(|l| l.id != 0)
        .filter_map(|l| {
            let outer = ids.iter().position(|&id| id == l.id)?;
            let inner = if l.id > 0 { outer + 1 } else { outer - 1 };
            Some(LaneShape {
                id: l.id,
                lane_type: l.lane_type.clone(),
                inner: if l.id.abs() == 1 { centre } else { inner },
                outer,
            })
        })
        .collect();
    let marks = section
        .lanes()
        .filter_map(|l| Some((ids.iter().position(|&id| id == l.id)?, l)))
        .flat_map(|(border, lane)| mark_spans(lane, border, start, &s_values))
        .collect();
    Some(SectionShape {
        s: s_values,
        borders,
        lanes,
        marks,
    })
}

/// Appends samples in (a, b] to `s_values` and `points`, halving until every border's
/// midpoint lies within [`SAG_TOLERANCE`] of its chord and the step is at most [`MAX_STEP`].
fn subdivide(
    road: &Road,
    ids: &[i32],
    (a, b): (f64, f64),
    s_values: &mut Vec<f64>,
    points: &mut Vec<Vec<[f64; 2]>>,
) -> Option<()> {
    // Work list of intervals to close, nearest first (a stack in reverse order).
    let pa = points.last()?.clone();
    let pb = border_points(road, ids, b)?;
    let mut stack = vec![(b, pb)];
    let mut left = (a, pa);
    while let Some((sb, pb)) = stack.pop() {
        let (sa, pa) = &left;
        let mid = 0.5 * (sa + sb);
        let split = sb - sa > 2.0 * MIN_STEP && {
            let pm = border_points(road, ids, mid)?;
            let off = pa.iter().zip(&pb).zip(&pm).any(|((p, q), m)| {
                let (cx, cy) = (0.5 * (p[0] + q[0]), 0.5 * (p[1] + q[1]));
                (m[0] - cx).hypot(m[1] - cy) > SAG_TOLERANCE
            });
            if off || sb - sa > MAX_STEP {
                stack.push((sb, pb.clone()));
                stack.push((mid, pm));
                true
            } else {
                false
            }
        };
        if !split {
            s_values.push(sb);
            points.push(pb.clone());
            left = (sb, pb);
        }
    }
    Some(())
}

/// The road marks of `lane` as spans of the samples `s` (lane section starting at `start`).
fn mark_spans(lane: &Lane, border: usize, start: f64, s: &[f64]) -> Vec<MarkSpan> {
    let mut out = Vec::new();
    for (k, mark) in lane.road_marks.iter().enumerate() {
        if matches!(mark.mark_type, RoadMarkType::None) {
            continue;
        }
        let from_s = start + mark.s_offset;
        let to_s = lane
            .road_marks
            .get(k + 1)
            .map_or(f64::INFINITY, |m| start + m.s_offset);
        let from = s.partition_point(|&v| v < from_s - MIN_STEP * 0.5);
        let to = s
            .partition_point(|&v| v <= to_s + MIN_STEP * 0.5)
            .saturating_sub(1);
        if to > from {
            out.push(MarkSpan {
                border,
                from,
                to,
                mark: mark.clone(),
            });
        }
    }
    out
}

/// A CSS colour for a road mark colour (`standard` is white).
pub fn mark_color(color: &RoadMarkColor) -> &'static str {
    match color {
        RoadMarkColor::Yellow => "#f2c230",
        RoadMarkColor::Blue => "#3b7dd8",
        RoadMarkColor::Green => "#3aa655",
        RoadMarkColor::Red => "#d83b3b",
        RoadMarkColor::Orange => "#f08a24",
        RoadMarkColor::Violet => "#8a4fd8",
        RoadMarkColor::Black => "#111111",
        _ => "#f4f4f4",
    }
}
