//! Sampling a DSL scenario's coverage items during a run (ASAM OpenSCENARIO DSL 2.1 §7.3.12):
//! each `cover(…)`/`record(…)` is evaluated on the frame of its sampling event — the first
//! frame for `start`, the frame of the step an `emit e` was logged in for `event: e`, the last
//! frame of the run for `end` (the default) — with the engine's §8.7 methods
//! (`engine::domain`) on the frame's entities. A value is converted to the item's unit and
//! kept to 1e-6 (the precision of the results table, so that buckets counted from the table
//! equal the batch's); a sample whose `ignore` holds is dropped. An expression without a value
//! at its event (an entity not in the scene, a method undefined there — no time to collision
//! on a receding pair, off the roads —, a division by zero) records [`Sample::NoValue`],
//! never an error.

use std::cell::RefCell;
use std::rc::Rc;

use dsl_runtime::{CoverItem, Direction, RunExpr, RunOp, SampleAt};
use engine::domain::{time_headway_between, DistanceDirection, DistanceMode, OnRouteType};
use engine::output::{EventRecord, EventSink, Frame, FrameSink};
use engine::EntityState;
use opendrive::RoadNetwork;

/// One sampled value.
#[derive(Debug, Clone, PartialEq)]
pub enum Sample {
    /// A number in the item's unit, rounded to 1e-6.
    Number(f64),
    /// An enum member, or `true`/`false`.
    Text(String),
    /// The expression had no value at the event.
    NoValue,
}

/// The text of [`Sample::NoValue`] in the results table.
pub const NO_VALUE: &str = "no value";

impl Sample {
    /// As the results table writes it: a number with 6 decimals, the text, or `no value`.
    pub fn text(&self) -> String {
        match self {
            Sample::Number(x) => format!("{x:.6}"),
            Sample::Text(t) => t.clone(),
            Sample::NoValue => NO_VALUE.to_owned(),
        }
    }

    /// The sample a cell of the results table holds ([`Sample::text`] read back).
    pub fn parse(text: &str) -> Sample {
        if text == NO_VALUE {
            return Sample::NoValue;
        }
        match text.parse::<f64>() {
            Ok(x) if x.is_finite() => Sample::Number(x),
            _ => Sample::Text(text.to_owned()),
        }
    }
}

/// A value while evaluating.
#[derive(Debug, Clone, PartialEq)]
enum Val {
    Num(f64),
    Bool(bool),
    Text(String),
}

/// The events the run emits, shared between the run's event sink and the [`Sampler`]: an
/// [`EventSink`] that notes each `emit` (a CustomCommandAction of type `emit`, docs/dsl.md).
#[derive(Debug, Clone, Default)]
pub struct Emits(Rc<RefCell<Vec<String>>>);

impl EventSink for Emits {
    fn event(&mut self, record: &EventRecord) -> Result<(), engine::SinkError> {
        if let EventRecord::CustomCommand {
            command_type,
            content,
            ..
        } = record
        {
            if command_type == "emit" {
                self.0.borrow_mut().push(content.clone());
            }
        }
        Ok(())
    }
}

/// A frame sink that samples `items` (module doc); [`Sampler::finish`] after the run gives
/// each item's samples in time order.
pub struct Sampler<'a> {
    items: &'a [CoverItem],
    network: &'a RoadNetwork,
    emits: Emits,
    /// The latest frame's entities (for `end`).
    last: Vec<EntityState>,
    frames: u64,
    samples: Vec<Vec<Sample>>,
}

impl<'a> Sampler<'a> {
    /// A sampler of `items` on `network`.
    pub fn new(items: &'a [CoverItem], network: &'a RoadNetwork) -> Self {
        Sampler {
            items,
            network,
            emits: Emits::default(),
            last: Vec::new(),
            frames: 0,
            samples: vec![Vec::new(); items.len()],
        }
    }

    /// The event sink that must see the run's event records (for `event: e`).
    pub fn emits(&self) -> Emits {
        self.emits.clone()
    }

    /// Samples the `end` items on the last frame and gives every item's samples, in the
    /// order of the items (an item whose event never occurred has none).
    pub fn finish(mut self) -> Vec<Vec<Sample>> {
        if self.frames > 0 {
            let last = std::mem::take(&mut self.last);
            self.sample(&last, |at| *at == SampleAt::End);
        }
        self.samples
    }

    fn sample(&mut self, states: &[EntityState], when: impl Fn(&SampleAt) -> bool) {
        for (k, item) in self.items.iter().enumerate() {
            if !when(&item.at) {
                continue;
            }
            let ignored = item
                .ignore
                .as_ref()
                .is_some_and(|i| eval(i, states, self.network) == Some(Val::Bool(true)));
            if ignored {
                continue;
            }
            let sample = match eval(&item.expr, states, self.network) {
                Some(Val::Num(si)) => {
                    let x = item
                        .unit
                        .as_ref()
                        .map_or(si, |u| (si - u.offset) / u.factor);
                    // Rounded through the 6-decimal text; + 0.0 makes −0 plain 0.
                    match format!("{x:.6}").parse::<f64>() {
                        Ok(q) if q.is_finite() => Sample::Number(q + 0.0),
                        _ => Sample::NoValue,
                    }
                }
                Some(Val::Bool(b)) => Sample::Text(b.to_string()),
                Some(Val::Text(t)) => Sample::Text(t),
                None => Sample::NoValue,
            };
            self.samples[k].push(sample);
        }
    }
}

impl FrameSink for Sampler<'_> {
    fn frame(&mut self, frame: &Frame<'_>) -> Result<(), engine::SinkError> {
        let states: Vec<EntityState> = frame.objects().map(|e| e.to_state()).collect();
        if self.frames == 0 {
            self.sample(&states, |at| *at == SampleAt::Start);
        }
        let emitted = std::mem::take(&mut *self.emits.0.borrow_mut());
        if !emitted.is_empty() {
            self.sample(
                &states,
                |at| matches!(at, SampleAt::Event(e) if emitted.contains(e)),
            );
        }
        self.frames += 1;
        self.last = states;
        Ok(())
    }
}

fn direction(d: Direction) -> DistanceDirection {
    match d {
        Direction::Longitudinal => DistanceDirection::Longitudinal,
        Direction::Lateral => DistanceDirection::Lateral,
    }
}

/// `e` on the entities `states`; `None`: no value (module doc).
fn eval(e: &RunExpr, states: &[EntityState], net: &RoadNetwork) -> Option<Val> {
    let find = |name: &str| states.iter().find(|s| s.name == name);
    let num = |x: f64| x.is_finite().then_some(Val::Num(x));
    match e {
        RunExpr::Num(x) => num(*x),
        RunExpr::Bool(b) => Some(Val::Bool(*b)),
        RunExpr::Enum(m) => Some(Val::Text(m.clone())),
        RunExpr::Speed(a) => num(find(a)?.speed),
        RunExpr::SpaceGap(a, b, d) => {
            let (a, b) = (find(a)?.view(), find(b)?.view());
            let gap = a
                .traffic_participant()
                .space_gap(net, &b.physical_object(), direction(*d));
            num(gap.ok()?)
        }
        RunExpr::ObjectDistance(a, b, d, boxes) => {
            let (a, b) = (find(a)?.view(), find(b)?.view());
            let mode = if *boxes {
                DistanceMode::BoundingBoxes
            } else {
                DistanceMode::ReferencePoints
            };
            num(a
                .physical_object()
                .object_distance(&b.physical_object(), direction(*d), mode))
        }
        RunExpr::TimeHeadway(a, b) => {
            let (a, b) = (find(a)?, find(b)?);
            let (ra, rb) = (a.road_position.as_ref()?, b.road_position.as_ref()?);
            num(time_headway_between(net, ra, a.speed, rb).ok()??)
        }
        RunExpr::TimeToCollision(a, b) => {
            let (a, b) = (find(a)?.view(), find(b)?.view());
            num(a
                .traffic_participant()
                .time_to_collision(&b.traffic_participant())?)
        }
        RunExpr::SCoord(a) => num(find(a)?
            .view()
            .physical_object()
            .get_s_coord(net, OnRouteType::OnRoad)
            .ok()?),
        RunExpr::TCoord(a) => num(find(a)?
            .view()
            .physical_object()
            .get_t_coord(net, OnRouteType::OnRoad)
            .ok()?),
        RunExpr::Neg(x) => match eval(x, states, net)? {
            Val::Num(v) => num(-v),
            _ => None,
        },
        RunExpr::Not(x) => match eval(x, states, net)? {
            Val::Bool(b) => Some(Val::Bool(!b)),
            _ => None,
        },
        RunExpr::Binary(op, a, b) => binary(*op, eval(a, states, net)?, eval(b, states, net)?),
    }
}

fn binary(op: RunOp, a: Val, b: Val) -> Option<Val> {
    use RunOp::*;
    Some(match (op, a, b) {
        (Add, Val::Num(x), Val::Num(y)) => Val::Num(x + y),
        (Sub, Val::Num(x), Val::Num(y)) => Val::Num(x - y),
        (Mul, Val::Num(x), Val::Num(y)) => Val::Num(x * y),
        (Div, Val::Num(x), Val::Num(y)) if y != 0.0 => Val::Num(x / y),
        (Lt, Val::Num(x), Val::Num(y)) => Val::Bool(x < y),
        (Le, Val::Num(x), Val::Num(y)) => Val::Bool(x <= y),
        (Gt, Val::Num(x), Val::Num(y)) => Val::Bool(x > y),
        (Ge, Val::Num(x), Val::Num(y)) => Val::Bool(x >= y),
        (Eq, x, y) => Val::Bool(x == y),
        (Ne, x, y) => Val::Bool(x != y),
        (And, Val::Bool(x), Val::Bool(y)) => Val::Bool(x && y),
        (Or, Val::Bool(x), Val::Bool(y)) => Val::Bool(x || y),
        _ => return None,
    })
    .filter(|v| !matches!(v, Val::Num(x) if !x.is_finite()))
}
