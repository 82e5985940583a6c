//! External methods bound by the host (ASAM OpenSCENARIO DSL 2.1 §7.3.6 methods `is external`,
//! §7.3.9 `call`): a Rust closure per method name, given to the front door in
//! [`Options::bindings`](crate::Options), and the [`Host`] that runs them around the engine's
//! steps.
//!
//! - **Load**: with bindings given, every external method the scenario calls (`call m(…)`) or
//!   reads (`until m(…) > 3`) must be bound, else the load fails at the first unbound one's
//!   `FILE:LINE:COL`. Without (`None`) the host binds after the load and checks itself (the
//!   Python package's `Simulation.bind`, kept for compatibility).
//! - **Reads**: before each step (before its triggers), the function of each method read in a
//!   condition is called with the arguments written there and its result set as the engine's
//!   user-defined value named by the call's text (`m(args)`), which the condition's
//!   UserDefinedValueCondition compares: the value the step's triggers see.
//! - **Calls**: a `call m(…)` is the step's `customCommand` of type `call`; its function runs
//!   when the engine hands the step's records to the event sink, at the end of the step (the
//!   entities as the step left them; the same moment as the Python package's).
//!
//! Arguments and results are JSON values (`serde_json::Value`): numbers in SI units, strings,
//! booleans, as the event log writes them. A result is a number, a boolean or a string (the
//! user-defined value's type); a function's `Err` ends the step with an error naming the
//! method and the simulation time.

use std::collections::BTreeMap;
use std::fmt;
use std::sync::Arc;

use engine::{Engine, EventRecord, EventSink, FrameSink, SinkError, StopReason};
use scenario::expr::Value;
use serde_json::Value as Json;

use crate::error::Error;

/// A host function bound to an external method: its arguments, its result or why it failed.
pub type ExternalFn = Arc<dyn Fn(&[Json]) -> Result<Json, String> + Send + Sync>;

/// The host's functions, by external method name.
#[derive(Clone, Default)]
pub struct Bindings {
    fns: BTreeMap<String, ExternalFn>,
}

impl Bindings {
    /// Binds `function` to external method `name` (replacing an earlier binding).
    pub fn bind(
        &mut self,
        name: impl Into<String>,
        function: impl Fn(&[Json]) -> Result<Json, String> + Send + Sync + 'static,
    ) -> &mut Self {
        self.fns.insert(name.into(), Arc::new(function));
        self
    }

    /// Whether a function is bound to `name`.
    pub fn contains(&self, name: &str) -> bool {
        self.fns.contains_key(name)
    }

    /// The bound names, in order.
    pub fn names(&self) -> impl Iterator<Item = &str> {
        self.fns.keys().map(String::as_str)
    }

    /// Checks that every external method of `calls` is bound: an error at the first unbound
    /// one's place.
    pub(crate) fn check(&self, calls: &[dsl_runtime::ExternalCall]) -> Result<(), Error> {
        match calls.iter().find(|c| !self.contains(&c.method)) {
            Some(c) => Err(Error::option(
                format!(
                    "expected a function bound to external method `{}` (load::Options::bindings, the Python package's Simulation(bindings=…)), found none",
                    c.method
                ),
                c.pos.clone(),
            )),
            None => Ok(()),
        }
    }
}

impl fmt::Debug for Bindings {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_set().entries(self.names()).finish()
    }
}

/// Two bindings are equal when they bind the same names to the same functions.
impl PartialEq for Bindings {
    fn eq(&self, other: &Self) -> bool {
        self.fns.len() == other.fns.len()
            && self
                .fns
                .iter()
                .zip(&other.fns)
                .all(|((a, f), (b, g))| a == b && Arc::ptr_eq(f, g))
    }
}

/// A function failed, or gave a result no condition can compare.
#[derive(Debug, Clone, PartialEq)]
pub struct ExternalError {
    /// The method.
    pub method: String,
    /// The simulation time of the step (s).
    pub time: f64,
    /// What the function said, or what was wrong with its result.
    pub message: String,
}

impl fmt::Display for ExternalError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "external method `{}` failed at {:.3} s: {}",
            self.method, self.time, self.message
        )
    }
}

impl std::error::Error for ExternalError {}

/// Why a [`Host`] step failed.
#[derive(Debug)]
#[non_exhaustive]
pub enum HostError {
    /// The engine's step failed (a call's function failing is one: its [`ExternalError`] is
    /// the event sink's error).
    Engine(engine::Error),
    /// A read method's function failed before the step.
    External(ExternalError),
    /// A sink could not be finished at the end of the run.
    Output(SinkError),
}

impl fmt::Display for HostError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            HostError::Engine(e) => e.fmt(f),
            HostError::External(e) => e.fmt(f),
            HostError::Output(e) => write!(f, "cannot finish the output: {e}"),
        }
    }
}

impl std::error::Error for HostError {}

/// A method read in a condition: the user-defined value's name, the method, its arguments and
/// the function bound to it (found once, when the host is made).
#[derive(Clone)]
struct Read {
    value: String,
    method: String,
    args: Vec<Json>,
    function: ExternalFn,
}

impl fmt::Debug for Read {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{} = {}", self.value, self.method)
    }
}

/// The name and the JSON arguments of a call's text `m(a, b)`.
fn parse_call(text: &str) -> Option<(&str, Vec<Json>)> {
    let (name, rest) = text.split_once('(')?;
    let inner = rest.strip_suffix(')')?;
    let args: Vec<Json> = serde_json::from_str(&format!("[{inner}]")).ok()?;
    Some((name, args))
}

/// Runs a loaded scenario's external methods around the engine's steps (module doc).
#[derive(Debug, Clone)]
pub struct Host {
    bindings: Bindings,
    reads: Vec<Read>,
}

impl Host {
    /// The host of a scenario's external methods `calls` (`Loaded::calls`) with `bindings`
    /// (`Loaded::bindings`; [`crate::Loaded::host`] gives both): an error at the first
    /// method that none is bound to.
    pub fn new(bindings: &Bindings, calls: &[dsl_runtime::ExternalCall]) -> Result<Host, Error> {
        bindings.check(calls)?;
        let reads = calls
            .iter()
            .filter_map(|c| {
                let value = c.value.clone()?;
                // The runtime writes the value's name as `m(args as JSON values)`.
                let (_, args) = parse_call(&value)?;
                // `check` above: every method is bound.
                let function = Arc::clone(bindings.fns.get(&c.method)?);
                Some(Read {
                    method: c.method.clone(),
                    value,
                    args,
                    function,
                })
            })
            .collect();
        Ok(Host {
            bindings: bindings.clone(),
            reads,
        })
    }

    /// Sets the value of each read method for the next step (module doc).
    pub fn before_step(&self, engine: &mut Engine) -> Result<(), ExternalError> {
        let time = engine.time();
        for r in &self.reads {
            let fail = |message: String| ExternalError {
                method: r.method.clone(),
                time,
                message,
            };
            let value = match (r.function)(&r.args).map_err(fail)? {
                Json::Number(n) => Value::Double(n.as_f64().unwrap_or(f64::NAN)),
                Json::Bool(b) => Value::Bool(b),
                Json::String(s) => Value::String(s),
                other => {
                    return Err(fail(format!(
                        "expected a number, a boolean or a string as its result, found {other}"
                    )))
                }
            };
            engine.set_user_value(&r.value, value);
        }
        Ok(())
    }

    /// One engine step with the external methods: the reads' values set before it, the
    /// calls' functions run as the step's records reach `events`.
    pub fn step(
        &self,
        engine: &mut Engine,
        frames: &mut dyn FrameSink,
        events: &mut dyn EventSink,
    ) -> Result<Option<StopReason>, HostError> {
        self.before_step(engine).map_err(HostError::External)?;
        let mut sink = Calls {
            bindings: &self.bindings,
            inner: events,
        };
        engine.step(frames, &mut sink).map_err(HostError::Engine)
    }

    /// Steps until the run ends ([`Host::step`]); the sinks are finished at the end.
    pub fn run(
        &self,
        engine: &mut Engine,
        frames: &mut dyn FrameSink,
        events: &mut dyn EventSink,
    ) -> Result<StopReason, HostError> {
        loop {
            if let Some(reason) = self.step(engine, frames, events)? {
                frames.finish().map_err(HostError::Output)?;
                events.finish().map_err(HostError::Output)?;
                return Ok(reason);
            }
        }
    }
}

/// The event sink of a step: runs the function of each `call` record, then hands the record on.
struct Calls<'a> {
    bindings: &'a Bindings,
    inner: &'a mut dyn EventSink,
}

impl EventSink for Calls<'_> {
    fn event(&mut self, record: &EventRecord) -> Result<(), SinkError> {
        self.inner.event(record)?;
        if let EventRecord::CustomCommand {
            time,
            command_type,
            content,
            ..
        } = record
        {
            if command_type == "call" {
                let fail = |method: &str, message: String| {
                    SinkError::sink(ExternalError {
                        method: method.to_string(),
                        time: *time,
                        message,
                    })
                };
                let (name, args) = parse_call(content)
                    .ok_or_else(|| fail(content, "expected `m(JSON values)`".into()))?;
                let f =
                    self.bindings.fns.get(name).ok_or_else(|| {
                        fail(name, "expected a bound function, found none".into())
                    })?;
                f(&args).map_err(|m| fail(name, m))?;
            }
        }
        Ok(())
    }

    fn finish(&mut self) -> Result<(), SinkError> {
        self.inner.finish()
    }
}
