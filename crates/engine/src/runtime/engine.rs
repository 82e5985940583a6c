//! The engine: a scenario built into a world, storyboard, action and condition tables, and
//! the API a host program drives it by (OpenSCENARIO 1.3 §8 "Scenario at runtime"). The fixed
//! step and its stages are in `step.rs`.

use std::cell::{Ref, RefCell};
use std::sync::Arc;
use std::time::Duration;

use opendrive::RoadNetwork;
use scenario::Scenario;

use super::build::build;
use super::config::EngineConfig;
use crate::actions::{stop_domain, ActionTable, Domain};
use crate::condition::ConditionStates;
use crate::controller::ControllerTable;
use crate::error::{Error, ErrorKind};
use crate::output::EventRecord;
use crate::snapshot::ScenarioSource;
use crate::store::World;
use crate::storyboard::Storyboard;
use crate::traffic::Traffic;

/// Why a run ended. [`StopReason::name`] is its one name in every output (the batch
/// results' `stop_reason` column, Python's `Simulation.step`/`run`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum StopReason {
    /// The storyboard's stop trigger fired.
    StopTrigger,
    /// Every Story completed and the storyboard has no stop trigger.
    StoriesComplete,
    /// The requested duration elapsed.
    Duration,
    /// The hard cap on simulated time was reached.
    TimeCap,
}

impl StopReason {
    /// Every reason, in declaration order.
    pub const ALL: [StopReason; 4] = [
        StopReason::StopTrigger,
        StopReason::StoriesComplete,
        StopReason::Duration,
        StopReason::TimeCap,
    ];

    /// The reason's name in outputs: `stop_trigger`, `stories_complete`, `duration`,
    /// `time_cap`.
    pub fn name(self) -> &'static str {
        match self {
            StopReason::StopTrigger => "stop_trigger",
            StopReason::StoriesComplete => "stories_complete",
            StopReason::Duration => "duration",
            StopReason::TimeCap => "time_cap",
        }
    }

    /// The reason called `name` ([`StopReason::name`]).
    pub fn from_name(name: &str) -> Option<StopReason> {
        StopReason::ALL.into_iter().find(|r| r.name() == name)
    }
}

impl std::fmt::Display for StopReason {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(match self {
            StopReason::StopTrigger => "the storyboard's stop trigger fired",
            StopReason::StoriesComplete => "every story completed",
            StopReason::Duration => "the requested duration elapsed",
            StopReason::TimeCap => "the hard cap on simulated time was reached",
        })
    }
}

/// Wall time spent in each stage of [`Engine::step`] since the engine was built.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct StageCounters {
    /// Stage 1, `triggers`.
    pub triggers: Duration,
    /// Stage 2, `actions`.
    pub actions: Duration,
    /// Stage 3, `controllers`.
    pub controllers: Duration,
    /// Stage 4, `measurements`.
    pub measurements: Duration,
    /// Stage 5, `output`.
    pub output: Duration,
}

/// A scenario ready to run: world, storyboard, action and condition tables.
#[derive(Debug)]
pub struct Engine {
    pub(super) world: RefCell<World>,
    pub(super) storyboard: Storyboard,
    pub(super) actions: ActionTable,
    /// The user controllers of every entity: the controllers stage's table.
    pub(super) controllers: ControllerTable,
    /// The traffic actions at work: the traffic stage's table.
    pub(super) traffic: Traffic,
    pub(super) conditions: Vec<scenario::Condition>,
    /// Per condition: its names resolved (condition/refs.rs).
    pub(super) condition_refs: Vec<crate::condition::ConditionRefs>,
    pub(super) condition_states: ConditionStates,
    pub(super) reported: Vec<bool>,
    pub(super) has_stop_trigger: bool,
    pub(super) config: EngineConfig,
    pub(super) step: u64,
    pub(super) stopped: Option<StopReason>,
    pub(super) counters: StageCounters,
    /// User-defined values still to be set, by time (user_values.rs).
    pub(super) scheduled_values: std::collections::VecDeque<crate::user_values::TimedValue>,
    /// Records of changes the host program made between steps (a controller attached), written
    /// with the next step's records.
    pub(super) host_events: Vec<EventRecord>,
    /// The scenario and road files (on every frame).
    pub(super) source: ScenarioSource,
}

impl Engine {
    /// Builds an engine for `scenario` on `network`, the road network its
    /// `RoadNetwork/LogicFile` names ([`load::road_network`](crate::load::road_network)). The
    /// network is shared, not copied: every engine of a batch can run on one `Arc`. Reads no
    /// file.
    pub fn new(
        scenario: &Scenario,
        network: Arc<RoadNetwork>,
        config: EngineConfig,
    ) -> Result<Engine, Error> {
        config.validate()?;
        // Places the road network does not have are refused now, not when first needed.
        crate::position::check_positions(scenario, &network)
            .map_err(|e| Error::new(ErrorKind::Position(e)))?;
        let mut built = build(scenario, network, config.seed)?;
        let traffic = Traffic::new(config.traffic_model);
        built
            .world
            .signals
            .set_stop_at_red_lights(config.stop_at_red_lights);
        let mut host_events = Vec::new();
        if let Some(model) = config.vehicle_model {
            crate::traffic::equip_scenario_vehicles(
                &mut built.world,
                &mut built.controllers,
                model,
                &mut host_events,
            )?;
        }
        let storyboard = Storyboard::new(&built.desc)?;
        Ok(Engine {
            world: RefCell::new(built.world),
            storyboard,
            actions: built.actions,
            controllers: built.controllers,
            traffic,
            reported: vec![false; built.conditions.len()],
            conditions: built.conditions,
            condition_refs: built.condition_refs,
            condition_states: ConditionStates::new(),
            has_stop_trigger: built.desc.stop_trigger.is_some(),
            config,
            step: 0,
            stopped: None,
            counters: StageCounters::default(),
            scheduled_values: std::collections::VecDeque::new(),
            host_events,
            source: ScenarioSource::of(scenario),
        })
    }

    /// The scenario and road files the engine was built from.
    pub fn source(&self) -> &ScenarioSource {
        &self.source
    }

    /// The world (entities, road network, values) as it is now.
    pub(crate) fn world(&self) -> Ref<'_, World> {
        self.world.borrow()
    }

    /// The storyboard and its element states.
    pub fn storyboard(&self) -> &Storyboard {
        &self.storyboard
    }

    /// The settings.
    pub fn config(&self) -> &EngineConfig {
        &self.config
    }

    /// Simulation time of the next step (s).
    pub fn time(&self) -> f64 {
        self.step as f64 * self.config.dt
    }

    /// Number of steps run.
    pub fn steps(&self) -> u64 {
        self.step
    }

    /// Why the run ended, once it has.
    pub fn stop_reason(&self) -> Option<StopReason> {
        self.stopped
    }

    /// Sets the user-defined value `name` (UserDefinedValueCondition) from now on: conditions
    /// evaluated in the next step read it.
    pub fn set_user_value(&mut self, name: &str, value: scenario::expr::Value) {
        self.world.get_mut().user_values.set(name, value);
    }

    /// Sets global parameter `name` from outside between steps, as a ParameterSetAction would
    /// (OpenSCENARIO 1.3 §7.7.1): `value` is converted to the parameter's declared type without
    /// loss ([`scenario::expr::Value::convert_to`]; text is parsed as the type); conditions of
    /// the next step read it. The value must meet the parameter's ConstraintGroups, as a
    /// ParameterSetAction's must (actions/parameter.rs). Returns `Ok(false)`, changing nothing,
    /// when the scenario declares no global parameter `name`; an error
    /// ([`ErrorKind::ParameterValue`](crate::ErrorKind::ParameterValue)), changing nothing,
    /// when the value does not convert or breaks the constraints.
    pub fn set_parameter(
        &mut self,
        name: &str,
        value: &scenario::expr::Value,
    ) -> Result<bool, Error> {
        use scenario::expr::Value;
        let world = self.world.get_mut();
        let Some(old) = world.parameters.get(name) else {
            return Ok(false);
        };
        let ty = old.value_type();
        let refused = |expected: String, found: String| {
            Error::new(ErrorKind::ParameterValue {
                name: name.to_owned(),
                expected,
                found,
            })
        };
        let new = match value {
            Value::String(text) => Value::parse(ty, text),
            v => v.convert_to(ty),
        }
        .map_err(|e| {
            let found = match value {
                Value::String(text) => format!("'{text}' ({e})"),
                v => format!("{v} ({e})"),
            };
            refused(format!("a value of type {}", ty.xsd_name()), found)
        })?;
        crate::actions::parameter::meets_constraints(&world.parameter_constraints, name, &new)
            .map_err(|expected| refused(expected, new.to_string()))?;
        world.parameters.insert(name.to_owned(), new);
        Ok(true)
    }

    /// Sets each of `values` at the start of the first step at or after its time (before the
    /// step's triggers), in time order; values of equal time in the order given.
    pub fn schedule_user_values(&mut self, values: &[crate::user_values::TimedValue]) {
        let mut all: Vec<_> = self
            .scheduled_values
            .drain(..)
            .chain(values.iter().cloned())
            .collect();
        all.sort_by(|a, b| a.time.total_cmp(&b.time));
        self.scheduled_values = all.into();
    }

    /// The current value of every monitor (MonitorDeclaration), by name.
    pub fn monitors(&self) -> Vec<(String, bool)> {
        let world = self.world.borrow();
        world
            .monitors
            .iter()
            .map(|(k, v)| (k.clone(), *v))
            .collect()
    }

    /// The current state of every traffic signal that has one, by signal id.
    pub fn signal_states(&self) -> Vec<(String, String)> {
        let world = self.world.borrow();
        world
            .signals
            .states()
            .map(|(k, v)| (k.to_owned(), v.to_owned()))
            .collect()
    }

    /// Wall time per stage so far.
    pub fn counters(&self) -> &StageCounters {
        &self.counters
    }

    /// Hands entity `name` to the host program: assigns it an `external` controller (named
    /// "external") activated on the longitudinal and lateral domains, as an
    /// AssignControllerAction with both `activate*` flags would, and stops the motion actions
    /// running on it (engine module `controller`). Until the first
    /// [`set_external_input`](Self::set_external_input) the entity drives as under the default
    /// controller. Logged with the next step's records (element "host").
    pub fn attach_external(&mut self, name: &str) -> Result<(), Error> {
        let time = self.time();
        let world = self.world.get_mut();
        let id = world.id(name).ok_or_else(|| {
            Error::new(ErrorKind::NotExternal {
                found: format!("no entity named '{name}'"),
            })
        })?;
        let pos =
            scenario::SourcePos::start_of(std::sync::Arc::from(std::path::Path::new("<host>")));
        let controller = scenario::Controller {
            name: "external".to_owned(),
            controller_type: None,
            properties: scenario::Properties {
                properties: vec![("model".to_owned(), "external".to_owned())],
                ..scenario::Properties::default()
            },
            catalog: None,
            pos: pos.clone(),
        };
        let origin = crate::controller::Origin {
            element: "host",
            time,
            pos: &pos,
        };
        let both = scenario::ControllerDomains {
            longitudinal: Some(true),
            lateral: Some(true),
            ..scenario::ControllerDomains::default()
        };
        let taken = crate::controller::assign(
            world,
            &mut self.controllers,
            id,
            &controller,
            None,
            &both,
            &origin,
            &mut self.host_events,
        )?;
        if taken.longitudinal {
            stop_domain(&mut self.actions, world, id, Domain::Longitudinal);
        }
        if taken.lateral {
            stop_domain(&mut self.actions, world, id, Domain::Lateral);
        }
        Ok(())
    }

    /// Gives entity `name`'s active `external` controller its input for the next steps (engine
    /// module `controller`, `external`): a pose, an acceleration with an optional wheel angle,
    /// or driver inputs. The input holds until the next call. Errors, keeping the input in
    /// force, when the input is not one the engine takes
    /// ([`ExternalInput::check`](crate::controller::ExternalInput::check): a number that is not
    /// finite, a pedal outside 0..1), when the entity does not exist or when no active
    /// `external` controller holds one of its motion domains.
    pub fn set_external_input(
        &mut self,
        name: &str,
        input: crate::controller::ExternalInput,
    ) -> Result<(), Error> {
        input.check().map_err(|e| {
            Error::new(ErrorKind::ExternalInput {
                expected: e.expected,
                found: e.found,
            })
        })?;
        let world = self.world.get_mut();
        let not_external = |found: String| Error::new(ErrorKind::NotExternal { found });
        let id = world
            .id(name)
            .ok_or_else(|| not_external(format!("no entity named '{name}'")))?;
        let ctrl = self.controllers.of_mut(id.index());
        let external = ctrl
            .assigned
            .iter()
            .any(|a| a.model_name() == "external" && a.holds() != Default::default());
        if !external {
            return Err(not_external(format!(
                "'{name}' without one (assign a Controller with <Property name=\"model\" value=\"external\"/> and activate it)"
            )));
        }
        ctrl.external = Some(input);
        Ok(())
    }
}
