//! The order in which the Init's private actions take effect (OpenSCENARIO 1.3 §7.2.1
//! "Storyboard": the Init "sets the initial states of the scenario elements, such as the
//! position and speed of instances of Entity"; it has no conditions and no order of its own).
//!
//! The Init's actions take effect together at the start: a position or speed given relative
//! to another entity resolves against that entity's *initial* position or speed, wherever the
//! two entities' Private elements stand in the file. ASAM's own `SlowPrecedingVehicle` example
//! teleports Ego to a RelativeLanePosition of A1 before A1's own TeleportAction; read in
//! document order that position would have nothing to refer to.
//!
//! The order is worked out once, from what each action needs and what it sets:
//!
//! * it **sets** its actor's position (TeleportAction, FollowTrajectoryAction — which places an
//!   entity not placed yet on the trajectory's start —, Longitudinal- and
//!   LateralDistanceAction) and/or speed (SpeedAction, SpeedProfileAction,
//!   LongitudinalDistanceAction);
//! * it **needs** another entity's position when a position it names is relative to that
//!   entity (Relative{World,Object,Road,Lane}Position, a RoutePosition FromCurrentEntity, the
//!   positions of a trajectory), or when it keeps a distance to it or changes lane or offset
//!   relative to it; it needs the other entity's speed — and so that entity placed — for a
//!   RelativeTargetSpeed or a LongitudinalDistanceAction (a time gap is measured at the
//!   reference's speed); a distance, lane or offset action needs its own actor placed.
//!
//! An action runs after every action of another entity that sets what it needs. One entity's
//! own actions keep their document order where they touch the same thing (two placements, a
//! placement and a distance action that starts from it); a speed and a placement of one
//! entity are independent. Among actions free to run, document order decides, so a file
//! already written in a workable order runs exactly as written. A true cycle (A's initial
//! position relative to B's, B's relative to A's) cannot be resolved and is a load error
//! naming the chain, from the first of its actions in the file ([`ErrorKind::InitCycle`]).

use std::cmp::Reverse;
use std::collections::{BTreeSet, BinaryHeap, HashMap};

use crate::error::{Error, ErrorKind, Result};
use crate::model::{
    ActionKind, InRoutePosition, Init, LaneChangeTarget, LaneOffsetTarget, LateralAction,
    LongitudinalAction, Position, PositionKind, PrivateAction, RoutingAction, Shape, SpeedTarget,
    Trajectory,
};
use crate::source::SourcePos;

/// One private Init action: `init.privates[private].actions[action]`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub struct InitStep {
    /// Index of the Private element.
    pub private: usize,
    /// Index of the action in it.
    pub action: usize,
}

/// What of an entity's initial state an action sets or needs.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash)]
enum Aspect {
    Position,
    Speed,
}

/// One action's entity, what it sets of it, and what it needs of others.
struct Node<'a> {
    step: InitStep,
    entity: &'a str,
    sets: BTreeSet<Aspect>,
    needs: Vec<(&'a str, Aspect)>,
    kind: &'static str,
    pos: &'a SourcePos,
}

/// The private Init actions of `init` in the order they take effect (module doc); an error
/// naming the entities when their positions or speeds refer to each other in a cycle.
pub fn init_order(init: &Init) -> Result<Vec<InitStep>> {
    let nodes = nodes(init);
    let n = nodes.len();
    // The actions setting each aspect of each entity.
    let mut setters: HashMap<(&str, Aspect), Vec<usize>> = HashMap::new();
    for (i, node) in nodes.iter().enumerate() {
        for &aspect in &node.sets {
            setters.entry((node.entity, aspect)).or_default().push(i);
        }
    }
    // before[j]: the nodes that must run before node j. One entity's own actions in document
    // order where they touch the same aspect: the latest earlier one for each aspect (the
    // earlier ones come before that one in turn).
    let mut before: Vec<Vec<usize>> = vec![Vec::new(); n];
    let mut last_touch: HashMap<(&str, Aspect), usize> = HashMap::new();
    for (j, node) in nodes.iter().enumerate() {
        let touched = node.touched();
        for &aspect in &touched {
            if let Some(i) = last_touch.insert((node.entity, aspect), j) {
                before[j].push(i);
            }
        }
        for &(entity, aspect) in node.needs.iter().filter(|(e, _)| *e != node.entity) {
            before[j].extend(setters.get(&(entity, aspect)).into_iter().flatten());
        }
        before[j].sort_unstable();
        before[j].dedup();
    }
    // Kahn's algorithm, the ready node first in document order taken each time.
    let mut waiting: Vec<usize> = before.iter().map(Vec::len).collect();
    let mut after: Vec<Vec<usize>> = vec![Vec::new(); n];
    for (j, list) in before.iter().enumerate() {
        for &i in list {
            after[i].push(j);
        }
    }
    let mut ready: BinaryHeap<Reverse<usize>> =
        (0..n).filter(|&j| waiting[j] == 0).map(Reverse).collect();
    let mut done = vec![false; n];
    let mut order = Vec::with_capacity(n);
    while let Some(Reverse(next)) = ready.pop() {
        done[next] = true;
        order.push(nodes[next].step);
        for &j in &after[next] {
            waiting[j] -= 1;
            if waiting[j] == 0 {
                ready.push(Reverse(j));
            }
        }
    }
    if order.len() < n {
        return Err(cycle_error(&nodes, &before, &done));
    }
    Ok(order)
}

impl Node<'_> {
    /// What of its own entity the action sets or needs.
    fn touched(&self) -> BTreeSet<Aspect> {
        let own = self
            .needs
            .iter()
            .filter(|(e, _)| *e == self.entity)
            .map(|&(_, a)| a);
        self.sets.iter().copied().chain(own).collect()
    }
}

fn nodes(init: &Init) -> Vec<Node<'_>> {
    let mut out = Vec::new();
    for (p, private) in init.privates.iter().enumerate() {
        for (a, action) in private.actions.iter().enumerate() {
            let mut node = Node {
                step: InitStep {
                    private: p,
                    action: a,
                },
                entity: &private.entity_ref,
                sets: BTreeSet::new(),
                needs: Vec::new(),
                kind: "PrivateAction",
                pos: &action.pos,
            };
            if let ActionKind::Private(action) = &action.kind {
                describe(action, &mut node);
            }
            // A speed is read off a placed entity: needing another's speed needs it placed.
            let speeds: Vec<&str> = (node.needs.iter())
                .filter(|&&(e, a)| a == Aspect::Speed && e != node.entity)
                .map(|&(e, _)| e)
                .collect();
            node.needs
                .extend(speeds.into_iter().map(|e| (e, Aspect::Position)));
            out.push(node);
        }
    }
    out
}

/// Fills in what `action` sets and needs (module doc).
fn describe<'a>(action: &'a PrivateAction, node: &mut Node<'a>) {
    use Aspect::{Position as Pos, Speed};
    match action {
        PrivateAction::Teleport(position) => {
            node.kind = "TeleportAction";
            node.sets.insert(Pos);
            position_needs(position, &mut node.needs);
        }
        PrivateAction::Longitudinal(LongitudinalAction::Speed { target, .. }) => {
            node.kind = "SpeedAction";
            node.sets.insert(Speed);
            if let SpeedTarget::Relative { entity_ref, .. }
            | SpeedTarget::RelativeAtStart { entity_ref, .. } = target
            {
                node.needs.push((entity_ref, Speed));
            }
        }
        PrivateAction::Longitudinal(LongitudinalAction::SpeedProfile { entity_ref, .. }) => {
            node.kind = "SpeedProfileAction";
            node.sets.insert(Speed);
            if let Some(entity_ref) = entity_ref {
                node.needs.push((entity_ref, Speed));
            }
        }
        PrivateAction::Longitudinal(LongitudinalAction::LongitudinalDistance {
            entity_ref,
            ..
        }) => {
            node.kind = "LongitudinalDistanceAction";
            node.sets.extend([Pos, Speed]);
            node.needs
                .extend([(entity_ref.as_str(), Pos), (entity_ref, Speed)]);
            node.needs.push((node.entity, Pos));
        }
        PrivateAction::Lateral(lateral) => {
            // Relative to another entity's lane or place, starting from the actor's own.
            let (kind, reference) = match lateral {
                LateralAction::LateralDistance { entity_ref, .. } => {
                    node.sets.insert(Pos);
                    ("LateralDistanceAction", Some(entity_ref))
                }
                LateralAction::LaneChange {
                    target: LaneChangeTarget::Relative { entity_ref, .. },
                    ..
                } => ("LaneChangeAction", Some(entity_ref)),
                LateralAction::LaneOffset {
                    target: LaneOffsetTarget::Relative { entity_ref, .. },
                    ..
                } => ("LaneOffsetAction", Some(entity_ref)),
                _ => ("LateralAction", None),
            };
            node.kind = kind;
            if let Some(entity_ref) = reference {
                node.needs
                    .extend([(entity_ref.as_str(), Pos), (node.entity, Pos)]);
            }
        }
        PrivateAction::Routing(routing) => match routing.as_ref() {
            RoutingAction::FollowTrajectory { trajectory, .. } => {
                node.kind = "FollowTrajectoryAction";
                node.sets.insert(Pos);
                trajectory_needs(trajectory, &mut node.needs);
            }
            RoutingAction::FollowTrajectoryAtSpeed(a) => {
                node.kind = "FollowTrajectoryAction";
                node.sets.insert(Pos);
                node.needs.push((a.entity_ref.as_str(), Speed));
                trajectory_needs(&a.trajectory, &mut node.needs);
            }
            RoutingAction::AcquirePosition(position) => {
                node.kind = "AcquirePositionAction";
                node.needs.push((node.entity, Pos));
                position_needs(position, &mut node.needs);
            }
            _ => node.kind = "RoutingAction",
        },
        _ => {}
    }
}

/// The entities whose positions `position` is relative to.
fn position_needs<'a>(position: &'a Position, needs: &mut Vec<(&'a str, Aspect)>) {
    match &position.kind {
        PositionKind::RelativeWorld { entity_ref, .. }
        | PositionKind::RelativeObject { entity_ref, .. }
        | PositionKind::RelativeRoad { entity_ref, .. }
        | PositionKind::RelativeLane { entity_ref, .. } => {
            needs.push((entity_ref, Aspect::Position))
        }
        PositionKind::Route {
            in_route: InRoutePosition::FromCurrentEntity { entity_ref },
            ..
        } => needs.push((entity_ref, Aspect::Position)),
        PositionKind::Trajectory { trajectory, .. } => trajectory_needs(trajectory, needs),
        _ => {}
    }
}

fn trajectory_needs<'a>(trajectory: &'a Trajectory, needs: &mut Vec<(&'a str, Aspect)>) {
    match &trajectory.shape {
        Shape::Polyline(vertices) => vertices
            .iter()
            .for_each(|v| position_needs(&v.position, needs)),
        Shape::Clothoid(c) => position_needs(&c.position, needs),
        Shape::ClothoidSpline(s) => s
            .segments
            .iter()
            .filter_map(|seg| seg.position_start.as_ref())
            .for_each(|p| position_needs(p, needs)),
        Shape::Nurbs(n) => n
            .control_points
            .iter()
            .for_each(|c| position_needs(&c.position, needs)),
        Shape::SmoothFromActor(c) => position_needs(&c.end, needs),
        Shape::LineFromActor(c) => position_needs(&c.end, needs),
    }
}

/// The error for the nodes left when none can run: a chain of them, each needing the next's
/// entity, followed until it closes, written "Ego's TeleportAction → A1's TeleportAction →
/// Ego" at the first action of the chain.
fn cycle_error(nodes: &[Node<'_>], before: &[Vec<usize>], done: &[bool]) -> Error {
    // Every node left waits for one not done; walking those waits must revisit a node.
    let start = done.iter().position(|d| !d).unwrap_or(0);
    let mut path = vec![start];
    let mut at = start;
    let first_repeat = loop {
        let next = before[at].iter().copied().find(|&i| !done[i]).unwrap_or(at);
        if let Some(k) = path.iter().position(|&p| p == next) {
            break k;
        }
        path.push(next);
        at = next;
    };
    // Written in the direction of reference: each action refers to the next one's entity.
    let mut chain: Vec<usize> = path[first_repeat..].to_vec();
    chain.reverse();
    // From the first of its actions in the file.
    let first = (0..chain.len()).min_by_key(|&k| chain[k]).unwrap_or(0);
    chain.rotate_left(first);
    // Only the steps between entities tell the story; an entity's own earlier actions do not.
    chain.dedup_by(|a, b| nodes[*a].entity == nodes[*b].entity);
    if chain.len() > 1 && nodes[chain[chain.len() - 1]].entity == nodes[chain[0]].entity {
        chain.pop();
    }
    let mut names: Vec<String> = chain
        .iter()
        .map(|&i| format!("{}'s {}", nodes[i].entity, nodes[i].kind))
        .collect();
    names.push(nodes[chain[0]].entity.to_owned());
    Error::new(
        ErrorKind::InitCycle { cycle: names },
        nodes[chain[0]].pos.clone(),
    )
}

#[cfg(test)]
mod tests {
    use super::{init_order, InitStep};
    use crate::error::ErrorKind;
    use crate::model::{
        Action, ActionKind, DynamicsDimension, DynamicsShape, Init, LongitudinalAction, Position,
        PositionKind, Private, PrivateAction, SpeedTarget, SpeedTargetValueType,
        TransitionDynamics,
    };
    use crate::source::SourcePos;
    use std::path::Path;

    fn at() -> SourcePos {
        SourcePos::start_of(Path::new("init.xosc").into())
    }

    fn action(kind: PrivateAction) -> Action {
        Action {
            name: String::new(),
            kind: ActionKind::Private(kind),
            pos: at(),
        }
    }

    /// A TeleportAction to a lane position, or 10 m ahead of `of` in its lane.
    fn teleport(of: Option<&str>) -> Action {
        let kind = match of {
            Some(e) => PositionKind::RelativeLane {
                entity_ref: e.into(),
                d_lane: 0,
                ds: Some(10.0),
                ds_lane: None,
                offset: None,
                orientation: None,
            },
            None => PositionKind::Lane {
                road_id: "1".into(),
                lane_id: "-1".into(),
                s: 0.0,
                offset: None,
                orientation: None,
            },
        };
        action(PrivateAction::Teleport(Position { kind, pos: at() }))
    }

    /// A step SpeedAction to 10 m/s, or to `of`'s speed.
    fn speed(of: Option<&str>) -> Action {
        let target = match of {
            Some(e) => SpeedTarget::Relative {
                entity_ref: e.into(),
                value: 0.0,
                speed_target_value_type: SpeedTargetValueType::Delta,
                continuous: false,
            },
            None => SpeedTarget::Absolute(10.0),
        };
        action(PrivateAction::Longitudinal(LongitudinalAction::Speed {
            dynamics: TransitionDynamics {
                dynamics_shape: DynamicsShape::Step,
                dynamics_dimension: DynamicsDimension::Time,
                value: 0.0,
                following_mode: None,
            },
            target,
        }))
    }

    fn init(privates: Vec<(&str, Vec<Action>)>) -> Init {
        Init {
            actions: Vec::new(),
            privates: privates
                .into_iter()
                .map(|(e, actions)| Private {
                    entity_ref: e.into(),
                    actions,
                })
                .collect(),
        }
    }

    fn steps(list: &[(usize, usize)]) -> Vec<InitStep> {
        list.iter()
            .map(|&(private, action)| InitStep { private, action })
            .collect()
    }

    #[test]
    fn a_file_in_a_workable_order_keeps_it() {
        let init = init(vec![
            ("A", vec![teleport(None), speed(None)]),
            ("B", vec![teleport(Some("A")), speed(Some("A"))]),
        ]);
        assert_eq!(
            init_order(&init).unwrap(),
            steps(&[(0, 0), (0, 1), (1, 0), (1, 1)])
        );
    }

    #[test]
    fn relative_placements_and_speeds_wait_for_the_entity_they_refer_to() {
        // B's speed of A and its place relative to A come before A's own: A runs first.
        let init = init(vec![
            ("B", vec![speed(Some("A")), teleport(Some("A"))]),
            ("A", vec![speed(None), teleport(None)]),
        ]);
        assert_eq!(
            init_order(&init).unwrap(),
            steps(&[(1, 0), (1, 1), (0, 0), (0, 1)])
        );
    }

    #[test]
    fn a_speed_of_one_entity_and_a_place_of_the_other_cross_without_a_cycle() {
        // A's speed is B's, B is placed relative to A: A's placement, then B's, then A's speed
        // (B placed; B has no speed action to wait for).
        let init = init(vec![
            ("A", vec![speed(Some("B")), teleport(None)]),
            ("B", vec![teleport(Some("A"))]),
        ]);
        assert_eq!(init_order(&init).unwrap(), steps(&[(0, 1), (1, 0), (0, 0)]));
    }

    #[test]
    fn placements_relative_to_each_other_are_a_cycle() {
        let init = init(vec![
            ("A", vec![teleport(Some("B"))]),
            ("B", vec![speed(None), teleport(Some("A"))]),
        ]);
        let err = init_order(&init).unwrap_err();
        assert_eq!(
            *err.kind(),
            ErrorKind::InitCycle {
                cycle: vec![
                    "A's TeleportAction".into(),
                    "B's TeleportAction".into(),
                    "A".into()
                ]
            }
        );
    }
}
