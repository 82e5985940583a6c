//! A run turned into the replay page's data container (`pack`): the header (entities, roads,
//! events, measures, action intervals) and the integer streams (frame times, entity tracks,
//! road border points). Units: times in ms, positions and road coordinates in mm (road
//! borders in cm), angles in 1e-4 rad, speeds in mm/s; see `web/decode.js` for the reader.

use serde_json::{json, Map, Value};

use crate::activity::active_actions;
use crate::measures::Series;
use crate::pack::{delta, quantize, Streams};
use crate::road::{mark_color, RoadDrawing};
use crate::run::Run;
use crate::trajectories::Track;

/// Unit of positions, lane offsets, t and s in the streams (m).
pub const POSITION_UNIT: f64 = 1e-3;
/// Unit of road border points (m).
pub const ROAD_UNIT: f64 = 1e-2;
/// Unit of angles (rad).
pub const ANGLE_UNIT: f64 = 1e-4;
/// Unit of times (s).
pub const TIME_UNIT: f64 = 1e-3;

/// Distinct colours for entities the scenario gives none (after Ego-like white).
const PALETTE: [&str; 8] = [
    "#4e79a7", "#f28e2b", "#59a14f", "#b07aa1", "#edc948", "#76b7b2", "#ff9da7", "#9c755f",
];

/// The colour of entity number `k` with RGB `color`, as CSS.
fn css_color(color: Option<[u8; 3]>, k: usize) -> String {
    match color {
        Some([r, g, b]) => format!("#{r:02x}{g:02x}{b:02x}"),
        None => PALETTE[k % PALETTE.len()].to_owned(),
    }
}

/// Rounds to 3 decimals for the JSON header.
fn r3(x: f64) -> Value {
    if x.is_finite() {
        json!((x * 1000.0).round() / 1000.0)
    } else {
        Value::Null
    }
}

/// The header and streams of `run` drawn on `roads` with `series`.
pub fn build(run: &Run, roads: &RoadDrawing, series: &[Series]) -> String {
    let mut streams = Streams::new();
    let times: Vec<i64> = run
        .trajectories
        .times
        .iter()
        .map(|&t| quantize(t, TIME_UNIT))
        .collect();
    streams.push("time", &delta(&times, 1));
    let mut header = Map::new();
    header.insert("version".into(), json!(1));
    header.insert("title".into(), json!(run.title));
    header.insert("dt".into(), json!(run.manifest.dt));
    header.insert("entities".into(), entities(run, &mut streams));
    let (roads_json, bbox) = road_streams(roads, &mut streams);
    header.insert("roads".into(), roads_json);
    header.insert("roadBox".into(), json!(bbox));
    header.insert(
        "events".into(),
        run.events
            .iter()
            .map(|e| json!([r3(e.time), e.element, e.kind, e.detail, e.entity]))
            .collect(),
    );
    header.insert("phases".into(), json!(run.manifest.phases));
    header.insert(
        "measures".into(),
        series
            .iter()
            .map(|s| {
                json!({
                    "quantity": s.spec.quantity,
                    "entity": s.spec.entity,
                    "reference": s.spec.reference,
                    "coordinateSystem": s.spec.coordinate_system,
                    "relativeDistanceType": s.spec.relative_distance_type,
                    "freespace": s.spec.freespace,
                    "method": s.method,
                    "unit": s.unit,
                    "thresholds": s.thresholds.iter().map(|(c, r, v)| json!([c, r, v])).collect::<Vec<_>>(),
                    "values": s.values.iter().map(|v| v.map_or(Value::Null, r3)).collect::<Vec<_>>(),
                })
            })
            .collect(),
    );
    streams.finish(header)
}

/// The entity list of the header; pushes the track streams (entity after entity).
fn entities(run: &Run, streams: &mut Streams) -> Value {
    let tracks = &run.trajectories.tracks;
    let road_ids: Vec<&str> = run
        .network
        .as_ref()
        .map(|n| n.roads().iter().map(|r| r.id.as_str()).collect())
        .unwrap_or_default();
    let active = active_actions(&run.events, &run.manifest.actions);
    let mut columns: [Vec<i64>; 13] = Default::default();
    let mut list = Vec::new();
    for (k, track) in tracks.iter().enumerate() {
        let info = run.manifest.entities.iter().find(|e| e.id == track.id);
        let trailer = info
            .and_then(|i| i.trailer)
            .and_then(|id| tracks.iter().position(|t| t.id == id));
        let (center, size) = info.map_or(([0.0; 3], crate::run::DEFAULT_BOX_SIZE), |i| {
            (i.box_center, i.box_size)
        });
        let actions: Vec<Value> = active
            .get(&track.name)
            .map(|a| {
                a.iter()
                    .map(|a| json!([a.name, a.kind, r3(a.start), a.end.map_or(Value::Null, r3)]))
                    .collect()
            })
            .unwrap_or_default();
        list.push(json!({
            "id": track.id,
            "name": track.name,
            "kind": info.map_or("vehicle", |i| i.kind.as_str()),
            "category": info.and_then(|i| i.category.clone()),
            "color": css_color(info.and_then(|i| i.color), k),
            "box": [center[0], center[1], center[2], size[0], size[1], size[2]],
            "trailer": trailer,
            "controllers": info.map(|i| i.controllers.clone()).unwrap_or_default(),
            "n": track.samples.len(),
            "actions": actions,
        }));
        push_track(track, &road_ids, &mut columns);
    }
    for ((name, _), values) in COLUMNS.iter().zip(&columns) {
        streams.push(name, values);
    }
    Value::Array(list)
}

/// The track streams in the order of `push_track`'s values, with their delta order
/// (positions and s of order 2: nearly constant first differences at constant speed).
const COLUMNS: [(&str, u8); 13] = [
    ("frame", 1),
    ("x", 2),
    ("y", 2),
    ("z", 1),
    ("h", 1),
    ("p", 1),
    ("r", 1),
    ("v", 1),
    ("road", 1),
    ("lane", 1),
    ("off", 1),
    ("t", 1),
    ("s", 2),
];

/// Appends one track's columns, each delta-coded within the track.
fn push_track(track: &Track, road_ids: &[&str], columns: &mut [Vec<i64>; 13]) {
    let mut raw: [Vec<i64>; 13] = Default::default();
    for s in &track.samples {
        let road = s.road.as_ref();
        let values = [
            i64::from(s.frame),
            quantize(s.pose[0], POSITION_UNIT),
            quantize(s.pose[1], POSITION_UNIT),
            quantize(s.pose[2], POSITION_UNIT),
            quantize(s.pose[3], ANGLE_UNIT),
            quantize(s.pose[4], ANGLE_UNIT),
            quantize(s.pose[5], ANGLE_UNIT),
            quantize(s.speed, POSITION_UNIT),
            road.and_then(|r| road_ids.iter().position(|id| *id == r.road_id))
                .map_or(0, |i| i as i64 + 1),
            road.map_or(0, |r| i64::from(r.lane_id)),
            road.map_or(0, |r| quantize(r.offset, POSITION_UNIT)),
            road.map_or(0, |r| quantize(r.t, POSITION_UNIT)),
            road.map_or(0, |r| quantize(r.s, POSITION_UNIT)),
        ];
        for (column, v) in raw.iter_mut().zip(values) {
            column.push(v);
        }
    }
    for ((out, column), (_, order)) in columns.iter_mut().zip(&raw).zip(COLUMNS) {
        out.extend(delta(column, order));
    }
}

/// The road list of the header and the bounding box of all border points; pushes the border
/// points (cm, delta-coded along each border) as streams `rx`, `ry`.
fn road_streams(roads: &RoadDrawing, streams: &mut Streams) -> (Value, [f64; 4]) {
    let (mut rx, mut ry) = (Vec::new(), Vec::new());
    let mut bbox = [
        f64::INFINITY,
        f64::INFINITY,
        f64::NEG_INFINITY,
        f64::NEG_INFINITY,
    ];
    let mut lane_types: Vec<String> = Vec::new();
    let mut list = Vec::new();
    for road in &roads.roads {
        let mut sections = Vec::new();
        for sec in &road.sections {
            for border in &sec.borders {
                let xs: Vec<i64> = border.iter().map(|p| quantize(p[0], ROAD_UNIT)).collect();
                let ys: Vec<i64> = border.iter().map(|p| quantize(p[1], ROAD_UNIT)).collect();
                rx.extend(delta(&xs, 1));
                ry.extend(delta(&ys, 1));
                for p in border {
                    bbox = [
                        bbox[0].min(p[0]),
                        bbox[1].min(p[1]),
                        bbox[2].max(p[0]),
                        bbox[3].max(p[1]),
                    ];
                }
            }
            let lanes: Vec<Value> = sec
                .lanes
                .iter()
                .map(|l| {
                    let name = l.lane_type.name().to_owned();
                    let k = lane_types
                        .iter()
                        .position(|t| *t == name)
                        .unwrap_or_else(|| {
                            lane_types.push(name);
                            lane_types.len() - 1
                        });
                    json!([l.id, lane_types[k], l.inner, l.outer])
                })
                .collect();
            let marks: Vec<Value> = sec
                .marks
                .iter()
                .map(|m| {
                    let (dash, gap) = m
                        .mark
                        .lines
                        .first()
                        .map_or((3.0, 9.0), |l| (l.length, l.space));
                    json!([
                        m.border,
                        m.from,
                        m.to,
                        m.mark.mark_type.name(),
                        mark_color(&m.mark.color),
                        m.mark
                            .lines
                            .first()
                            .and_then(|l| l.width)
                            .or(m.mark.width)
                            .unwrap_or(0.12),
                        dash,
                        gap,
                        m.mark.bold
                    ])
                })
                .collect();
            sections.push(json!({
                "s0": r3(sec.s.first().copied().unwrap_or(0.0)),
                "s1": r3(sec.s.last().copied().unwrap_or(0.0)),
                "n": sec.s.len(),
                "nb": sec.borders.len(),
                "lanes": lanes,
                "marks": marks,
            }));
        }
        list.push(json!({"id": road.id, "junction": road.junction, "sections": sections}));
    }
    streams.push("rx", &rx);
    streams.push("ry", &ry);
    if !bbox[0].is_finite() {
        bbox = [0.0; 4];
    }
    (Value::Array(list), bbox)
}
