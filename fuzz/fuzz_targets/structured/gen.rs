//! A small valid OpenSCENARIO 1.3 scenario on `examples/roads/highway.xodr`, drawn from the
//! fuzzer's bytes with `arbitrary`: 1–4 entities placed on road 0 with an initial speed, and up
//! to 8 events, each one action under one start condition, in ManeuverGroups that may repeat.
//! Every value is finite and within the XSD's domain, so a load or build error is a finding.

use std::fmt::Write;

use arbitrary::{Arbitrary, Result, Unstructured};

/// A number drawn as one of a few interesting values or uniformly in [lo, hi].
fn num(u: &mut Unstructured<'_>, lo: f64, hi: f64) -> Result<f64> {
    Ok(match u.int_in_range(0u8..=7)? {
        0 => lo,
        1 => hi,
        2 => lo.max(0.0).min(hi),
        3 => (lo.max(1e-9)).min(hi),
        _ => lo + (hi - lo) * (u.int_in_range(0u32..=1_000_000)? as f64 / 1e6),
    })
}

/// One of `items`.
fn pick<T: Copy>(u: &mut Unstructured<'_>, items: &[T]) -> Result<T> {
    Ok(*u.choose(items)?)
}

const RULES: [&str; 6] = [
    "greaterThan",
    "lessThan",
    "equalTo",
    "greaterOrEqual",
    "lessOrEqual",
    "notEqualTo",
];
const SHAPES: [&str; 4] = ["linear", "cubic", "sinusoidal", "step"];
const DIMENSIONS: [&str; 3] = ["time", "rate", "distance"];
const LANES: [i32; 3] = [-2, -1, 1];
const CATEGORIES: [&str; 4] = ["car", "truck", "bus", "bicycle"];

/// The scenario to build.
#[derive(Debug)]
pub struct Plan {
    /// Entities: (category, lane, s, speed).
    pub entities: Vec<(&'static str, i32, f64, f64)>,
    /// Events: (ManeuverGroup maximumExecutionCount, priority, action XML, condition XML).
    pub events: Vec<(u32, &'static str, String, String)>,
    /// The storyboard's stop time (s).
    pub stop_time: f64,
}

impl<'a> Arbitrary<'a> for Plan {
    fn arbitrary(u: &mut Unstructured<'a>) -> Result<Self> {
        let n = u.int_in_range(1usize..=4)?;
        let mut entities = Vec::with_capacity(n);
        for _ in 0..n {
            entities.push((
                pick(u, &CATEGORIES)?,
                pick(u, &LANES)?,
                num(u, 0.0, 150.0)?,
                num(u, 0.0, 60.0)?,
            ));
        }
        let m = u.int_in_range(0usize..=8)?;
        let mut events = Vec::with_capacity(m);
        for i in 0..m {
            let action = action(u, n)?;
            let condition = condition(u, n, i)?;
            events.push((
                u.int_in_range(1u32..=3)?,
                pick(u, &["override", "skip", "parallel"])?,
                action,
                condition,
            ));
        }
        Ok(Plan {
            entities,
            events,
            stop_time: num(u, 0.0, 30.0)?,
        })
    }
}

fn entity(u: &mut Unstructured<'_>, n: usize) -> Result<String> {
    Ok(format!("E{}", u.int_in_range(0..=n - 1)?))
}

fn dynamics(u: &mut Unstructured<'_>, element: &str, rate_ok: bool) -> Result<String> {
    let shape = pick(u, &SHAPES)?;
    let dim = if rate_ok {
        pick(u, &DIMENSIONS)?
    } else {
        pick(u, &["time", "distance"])?
    };
    let value = num(u, 0.0, 20.0)?;
    Ok(format!(
        r#"<{element} dynamicsShape="{shape}" dynamicsDimension="{dim}" value="{value}"/>"#
    ))
}

/// One PrivateAction (the event's actor is E0 … E(n−1), chosen by the ManeuverGroup).
fn action(u: &mut Unstructured<'_>, n: usize) -> Result<String> {
    Ok(match u.int_in_range(0u8..=8)? {
        0 => format!(
            r#"<LongitudinalAction><SpeedAction>{}<SpeedActionTarget><AbsoluteTargetSpeed value="{}"/></SpeedActionTarget></SpeedAction></LongitudinalAction>"#,
            dynamics(u, "SpeedActionDynamics", true)?,
            num(u, 0.0, 70.0)?
        ),
        1 => format!(
            r#"<LongitudinalAction><SpeedAction>{}<SpeedActionTarget><RelativeTargetSpeed entityRef="{}" value="{}" speedTargetValueType="{}" continuous="{}"/></SpeedActionTarget></SpeedAction></LongitudinalAction>"#,
            dynamics(u, "SpeedActionDynamics", true)?,
            entity(u, n)?,
            num(u, -20.0, 20.0)?,
            pick(u, &["delta", "factor"])?,
            u.arbitrary::<bool>()?
        ),
        2 => format!(
            r#"<LateralAction><LaneChangeAction>{}<LaneChangeTarget><RelativeTargetLane entityRef="{}" value="{}"/></LaneChangeTarget></LaneChangeAction></LateralAction>"#,
            dynamics(u, "LaneChangeActionDynamics", false)?,
            entity(u, n)?,
            u.int_in_range(-2i32..=2)?
        ),
        3 => format!(
            r#"<LateralAction><LaneOffsetAction continuous="{}"><LaneOffsetActionDynamics maxLateralAcc="{}" dynamicsShape="{}"/><LaneOffsetTarget><AbsoluteTargetLaneOffset value="{}"/></LaneOffsetTarget></LaneOffsetAction></LateralAction>"#,
            u.arbitrary::<bool>()?,
            num(u, 0.1, 10.0)?,
            pick(u, &SHAPES)?,
            num(u, -3.0, 3.0)?
        ),
        4 => format!(
            r#"<TeleportAction><Position><LanePosition roadId="0" laneId="{}" offset="{}" s="{}"/></Position></TeleportAction>"#,
            pick(u, &LANES)?,
            num(u, -1.0, 1.0)?,
            num(u, 0.0, 200.0)?
        ),
        5 => format!(
            r#"<TeleportAction><Position><RelativeObjectPosition entityRef="{}" dx="{}" dy="{}"/></Position></TeleportAction>"#,
            entity(u, n)?,
            num(u, -50.0, 50.0)?,
            num(u, -5.0, 5.0)?
        ),
        6 => format!(
            r#"<LongitudinalAction><LongitudinalDistanceAction entityRef="{}" freespace="{}" continuous="{}" {}="{}" coordinateSystem="{}" displacement="{}"><DynamicConstraints maxAcceleration="{}" maxDeceleration="{}" maxSpeed="{}"/></LongitudinalDistanceAction></LongitudinalAction>"#,
            entity(u, n)?,
            u.arbitrary::<bool>()?,
            u.arbitrary::<bool>()?,
            pick(u, &["distance", "timeGap"])?,
            num(u, 0.0, 50.0)?,
            pick(u, &["entity", "road", "lane"])?,
            pick(
                u,
                &["any", "leadingReferencedEntity", "trailingReferencedEntity"]
            )?,
            num(u, 0.1, 10.0)?,
            num(u, 0.1, 10.0)?,
            num(u, 1.0, 60.0)?
        ),
        7 => format!(
            r#"<LongitudinalAction><SpeedProfileAction followingMode="{}"><SpeedProfileEntry speed="{}" time="{}"/><SpeedProfileEntry speed="{}" time="{}"/></SpeedProfileAction></LongitudinalAction>"#,
            pick(u, &["position", "follow"])?,
            num(u, 0.0, 40.0)?,
            num(u, 0.0, 10.0)?,
            num(u, 0.0, 40.0)?,
            num(u, 0.0, 10.0)?
        ),
        _ => format!(
            r#"<VisibilityAction graphics="{}" traffic="{}" sensors="{}"/>"#,
            u.arbitrary::<bool>()?,
            u.arbitrary::<bool>()?,
            u.arbitrary::<bool>()?
        ),
    })
}

/// One start Condition of event `i`.
fn condition(u: &mut Unstructured<'_>, n: usize, i: usize) -> Result<String> {
    let edge = pick(u, &["none", "rising", "falling", "risingOrFalling"])?;
    let delay = num(u, 0.0, 3.0)?;
    let rule = pick(u, &RULES)?;
    let by_entity = |u: &mut Unstructured<'_>, inner: String| -> Result<String> {
        Ok(format!(
            r#"<ByEntityCondition><TriggeringEntities triggeringEntitiesRule="{}"><EntityRef entityRef="{}"/></TriggeringEntities><EntityCondition>{inner}</EntityCondition></ByEntityCondition>"#,
            pick(u, &["any", "all"])?,
            entity(u, n)?
        ))
    };
    let body = match u.int_in_range(0u8..=8)? {
        0 => format!(
            r#"<ByValueCondition><SimulationTimeCondition value="{}" rule="{rule}"/></ByValueCondition>"#,
            num(u, 0.0, 20.0)?
        ),
        1 => {
            let inner = format!(
                r#"<SpeedCondition value="{}" rule="{rule}"/>"#,
                num(u, 0.0, 60.0)?
            );
            by_entity(u, inner)?
        }
        2 => {
            let other = entity(u, n)?;
            let inner = format!(
                r#"<RelativeDistanceCondition entityRef="{other}" relativeDistanceType="{}" coordinateSystem="{}" freespace="{}" value="{}" rule="{rule}"/>"#,
                pick(u, &["longitudinal", "lateral", "euclidianDistance"])?,
                pick(u, &["entity", "road", "lane"])?,
                u.arbitrary::<bool>()?,
                num(u, 0.0, 100.0)?
            );
            by_entity(u, inner)?
        }
        3 => {
            let other = entity(u, n)?;
            let inner = format!(
                r#"<TimeHeadwayCondition entityRef="{other}" value="{}" freespace="{}" rule="{rule}"/>"#,
                num(u, 0.0, 10.0)?,
                u.arbitrary::<bool>()?
            );
            by_entity(u, inner)?
        }
        4 => {
            let other = entity(u, n)?;
            let inner = format!(
                r#"<TimeToCollisionCondition value="{}" freespace="{}" rule="{rule}"><TimeToCollisionConditionTarget><EntityRef entityRef="{other}"/></TimeToCollisionConditionTarget></TimeToCollisionCondition>"#,
                num(u, 0.0, 10.0)?,
                u.arbitrary::<bool>()?
            );
            by_entity(u, inner)?
        }
        5 => {
            let inner = format!(
                r#"<TraveledDistanceCondition value="{}"/>"#,
                num(u, 0.0, 300.0)?
            );
            by_entity(u, inner)?
        }
        6 => {
            let inner = format!(r#"<StandStillCondition duration="{}"/>"#, num(u, 0.0, 5.0)?);
            by_entity(u, inner)?
        }
        7 if i > 0 => format!(
            r#"<ByValueCondition><StoryboardElementStateCondition storyboardElementType="event" storyboardElementRef="Event{}" state="{}"/></ByValueCondition>"#,
            u.int_in_range(0..=i - 1)?,
            pick(
                u,
                &[
                    "standbyState",
                    "runningState",
                    "completeState",
                    "startTransition",
                    "endTransition",
                    "stopTransition",
                    "skipTransition"
                ]
            )?
        ),
        _ => by_entity(u, r#"<EndOfRoadCondition duration="0"/>"#.to_owned())?,
    };
    Ok(format!(
        r#"<Condition name="C{i}" delay="{delay}" conditionEdge="{edge}">{body}</Condition>"#
    ))
}

/// The scenario's XML text; the road network is `road` (a path).
pub fn scenario_xml(plan: &Plan, road: &str) -> String {
    let mut x = String::with_capacity(4096);
    x.push_str(r#"<?xml version="1.0"?><OpenSCENARIO><FileHeader revMajor="1" revMinor="3" date="2026-01-01T00:00:00" description="structured fuzz" author="oscsim-fuzz"/>"#);
    let _ = write!(
        x,
        r#"<RoadNetwork><LogicFile filepath="{road}"/></RoadNetwork><Entities>"#
    );
    for (i, (category, ..)) in plan.entities.iter().enumerate() {
        let _ = write!(
            x,
            r#"<ScenarioObject name="E{i}"><Vehicle name="v{i}" vehicleCategory="{category}"><BoundingBox><Center x="1.4" y="0" z="0.75"/><Dimensions width="2" length="5" height="1.5"/></BoundingBox><Performance maxSpeed="70" maxAcceleration="10" maxDeceleration="10"/><Axles><FrontAxle maxSteering="0.5" wheelDiameter="0.8" trackWidth="1.68" positionX="2.98" positionZ="0.4"/><RearAxle maxSteering="0" wheelDiameter="0.8" trackWidth="1.68" positionX="0" positionZ="0.4"/></Axles></Vehicle></ScenarioObject>"#
        );
    }
    x.push_str("</Entities><Storyboard><Init><Actions>");
    for (i, (_, lane, s, speed)) in plan.entities.iter().enumerate() {
        let _ = write!(
            x,
            r#"<Private entityRef="E{i}"><PrivateAction><TeleportAction><Position><LanePosition roadId="0" laneId="{lane}" offset="0" s="{s}"/></Position></TeleportAction></PrivateAction><PrivateAction><LongitudinalAction><SpeedAction><SpeedActionDynamics dynamicsShape="step" dynamicsDimension="time" value="0"/><SpeedActionTarget><AbsoluteTargetSpeed value="{speed}"/></SpeedActionTarget></SpeedAction></LongitudinalAction></PrivateAction></Private>"#
        );
    }
    x.push_str(r#"</Actions></Init><Story name="S"><Act name="A">"#);
    for (i, (count, priority, action, condition)) in plan.events.iter().enumerate() {
        let actor = i % plan.entities.len();
        let _ = write!(
            x,
            r#"<ManeuverGroup maximumExecutionCount="{count}" name="G{i}"><Actors selectTriggeringEntities="false"><EntityRef entityRef="E{actor}"/></Actors><Maneuver name="M{i}"><Event name="Event{i}" priority="{priority}" maximumExecutionCount="{count}"><Action name="Action{i}"><PrivateAction>{action}</PrivateAction></Action><StartTrigger><ConditionGroup>{condition}</ConditionGroup></StartTrigger></Event></Maneuver></ManeuverGroup>"#
        );
    }
    if plan.events.is_empty() {
        // An Act needs a ManeuverGroup (XSD minOccurs 1).
        x.push_str(r#"<ManeuverGroup maximumExecutionCount="1" name="G"><Actors selectTriggeringEntities="false"/></ManeuverGroup>"#);
    }
    let _ = write!(
        x,
        r#"<StartTrigger><ConditionGroup><Condition name="ActStart" delay="0" conditionEdge="none"><ByValueCondition><SimulationTimeCondition value="0" rule="greaterOrEqual"/></ByValueCondition></Condition></ConditionGroup></StartTrigger></Act></Story><StopTrigger><ConditionGroup><Condition name="End" delay="0" conditionEdge="none"><ByValueCondition><SimulationTimeCondition value="{}" rule="greaterThan"/></ByValueCondition></Condition></ConditionGroup></StopTrigger></Storyboard></OpenSCENARIO>"#,
        plan.stop_time
    );
    x
}
