//! The longitudinal built-in controllers `idm` and `acc` (OpenSCENARIO 1.3 §6.6: user-defined
//! controllers of the longitudinal domain): each step the acceleration of their model
//! ([`crate::models::idm`], [`crate::models::acc`]) behind the leader the view finds. With run
//! option `stop_at_red_lights` the `idm` also stops for a red light ahead as for a standing
//! vehicle ([`with_red_light`]); the `acc` does not (it models a driver-assistance function).
//!
//! The desired speed (`idm`) or set speed (`acc`) is the property's value, else the entity's
//! speed when the controller is activated (when that is 0: 120 km/h, the IDM paper's), capped
//! at the vehicle's Performance `maxSpeed`. A SpeedAction (or SpeedProfileAction) of the
//! scenario on the domain the controller holds sets it anew (the controller's reading of that
//! control strategy, module `controller`).
//!
//! **A free-road acceleration handed to the `idm`** (oscsim's
//! `scenario::LongitudinalAction::ModelAcceleration`, [`Strategy::FreeAcceleration`], which the
//! DSL runtime gives a member of random traffic for `acceleration(…)` in a phase of its own,
//! ASAM OpenSCENARIO DSL 2.1 §8.7.18.1: "the behavioral model assigned to each vehicle defines
//! the actual behavior of the vehicle within the group") replaces the IDM's free-road term
//! a·(1 − (v/v0)^δ) and nothing else: the command is that acceleration less the interaction
//! term a·(s*/s)² toward the leader, so on a free road the entity accelerates at it exactly,
//! and behind a leader the IDM's braking still wins where the gap asks for it. Released, the
//! model's own free-road term is back (the `mobil` model, which drives by this IDM, weighs its
//! lane changes with the same term).
//!
//! **A rate toward a speed** ([`Strategy::FreeAccelerationToward`], oscsim's
//! `scenario::ModelAcceleration::Toward`, which the DSL runtime gives a member of random
//! traffic for `acceleration(a)` as the rate of its own speed change, `speed(v, at: end)` or
//! `change_speed(v)` beside a drive) makes v the desired speed and sign(v − v_now)·|a| the
//! free-road term, the interaction term still subtracted, until the entity's speed reaches v:
//! in the step where |v − v_now| < |a|·dt the term is (v − v_now)/dt, so that a free road's
//! step ends at v (within the rounding of v + ((v − v_now)/dt)·dt), as a linear SpeedAction
//! ends at its target. From the first step that starts with the speed at v (within
//! [`REACHED`]) or past it in the change's direction, the term is released: the IDM's own
//! a·(1 − (v/v0)^δ) with v0 = v, 0 at v, so the model holds v. Behind a leader the braking
//! still wins, and v is reached later or not at all; a later speed or free-road acceleration
//! handed to the model replaces the rate.
//!
//! **A rate toward another's speed** (the same strategy with a reference x and a value δ,
//! oscsim's `scenario::ModelAcceleration::Toward` with `of`, which the DSL runtime gives a
//! member of random traffic for `speed(δ, faster_than/slower_than/same_as: x, at: end)` at the
//! rate of `acceleration(a)`): at every step's start the desired speed and v are x's speed
//! in the view plus δ (within 0 and the vehicle's maximum), and the free-road term is the
//! rate toward v, cut as above; it is not released when v is reached (v moves with x), so the
//! model follows x's speed ± δ at up to |a| until a later strategy replaces or releases it
//! (released, the desired speed stays the last one read).

use opendrive::Real;

use super::command::{Command, Controller, FreeAcceleration, Strategy};
use super::view::ControllerView;
use crate::models::acc::AccParameters;
use crate::models::idm::{IdmParameters, Leader};
use crate::world::EntityId;

/// The desired speed when neither the properties nor the entity give one (m/s): 120 km/h.
pub const FALLBACK_DESIRED_SPEED: Real = 120.0 / 3.6;

/// The leader in the view as the models read it.
pub(crate) fn leader(view: &ControllerView<'_>) -> Option<Leader> {
    view.leader().map(|g| Leader {
        gap: g.gap,
        speed: g.speed,
    })
}

/// `leader`, or the red light ahead as a standing obstacle at the signal (run option
/// `stop_at_red_lights`, [`ControllerView::red_light`]) when it is nearer: the driver models
/// (`idm`, `mobil`) stop for red lights as behind a standing vehicle. The `acc` controller, a
/// driver-assistance function that does not see signals, does not use this.
pub(crate) fn with_red_light(view: &ControllerView<'_>, leader: Option<Leader>) -> Option<Leader> {
    nearer(leader, view.red_light())
}

/// `leader`, or a red light `light` m ahead as a standing obstacle when it is nearer: the
/// rule of [`with_red_light`] for a caller that asked for the light once.
pub(crate) fn nearer(leader: Option<Leader>, light: Option<Real>) -> Option<Leader> {
    let light = light.map(|gap| Leader { gap, speed: 0.0 });
    match (leader, light) {
        (Some(l), Some(r)) => Some(if r.gap < l.gap { r } else { l }),
        (l, r) => l.or(r),
    }
}

/// A desired speed from the entity at activation: its speed, or the fallback at rest; capped
/// at its maximum speed.
pub(crate) fn speed_at_activation(view: &ControllerView<'_>) -> Real {
    let e = view.entity();
    let v = if e.speed > 0.0 {
        e.speed
    } else {
        FALLBACK_DESIRED_SPEED
    };
    v.min(e.max_speed())
}

/// The `idm` controller.
#[derive(Debug, Clone)]
pub struct IdmController {
    /// The parameters (the desired speed as in use).
    pub params: IdmParameters,
    desired_given: bool,
    max_speed: Real,
    /// The free-road acceleration handed to it, if any (module doc).
    free: Option<FreeAcceleration>,
    /// With `free`: the speed it is the rate of a change to (module doc, "A rate toward a
    /// speed"). Boxed: few vehicles are handed one, and every step of every `idm` and `mobil`
    /// vehicle moves this controller's fields (the box keeps it 8 bytes; issue 31).
    toward: Option<Box<Toward>>,
}

/// The speed a handed free-road acceleration is the rate of a change to (module doc).
#[derive(Debug, Clone, Copy)]
struct Toward {
    /// The speed (m/s).
    speed: Real,
    /// Whether the change is up (the speed below `speed` at the first step after the hand-off;
    /// `None` before that step).
    up: Option<bool>,
    /// The entity whose speed plus the value is `speed`, read at every step, and the value
    /// (m/s): the speed followed, never released by reaching it (module doc, "A rate toward
    /// another's speed").
    of: Option<(EntityId, Real)>,
}

/// How near its speed (m/s) a change at a handed rate counts as ended: the rounding of the
/// step that reaches it (module doc, "A rate toward a speed").
pub const REACHED: Real = 1e-9;

impl IdmController {
    /// A controller with `params`; `desired_given` false: the desired speed is taken at
    /// activation.
    pub fn new(params: IdmParameters, desired_given: bool) -> Self {
        IdmController {
            params,
            desired_given,
            max_speed: Real::INFINITY,
            free: None,
            toward: None,
        }
    }

    /// The free-road term at speed `v` (≥ 0) in the view: the one handed to the model
    /// (module doc), else the IDM's own a·(1 − (v/v0)^δ).
    #[inline]
    pub(crate) fn free_term(&self, view: &ControllerView<'_>, v: Real) -> Real {
        match &self.free {
            None => self.params.free_acceleration(v),
            Some(f) => self.handed(f, view, v),
        }
    }

    /// The handed free-road term `f` at speed `v`: its value, or as the rate of a change to
    /// a speed, its magnitude toward that speed, cut in the step that reaches it (module doc).
    #[inline]
    fn handed(&self, f: &FreeAcceleration, view: &ControllerView<'_>, v: Real) -> Real {
        let a = f.value(view);
        let Some(t) = self.toward.as_deref() else {
            return a;
        };
        let (gap, dt) = (t.speed - v, view.dt());
        if dt > 0.0 && gap.abs() < a.abs() * dt {
            gap / dt
        } else {
            a.abs().copysign(gap)
        }
    }

    /// Before a step's command: a change at a handed rate whose speed the entity has reached
    /// (within [`REACHED`], or past it in the change's direction) gives the model its own
    /// free-road term back (module doc, "A rate toward a speed").
    #[inline]
    pub(crate) fn settle(&mut self, view: &ControllerView<'_>) {
        if self.toward.is_some() {
            self.settle_toward(view);
        }
    }

    /// [`settle`](Self::settle) with a speed handed: out of line, so that the step of the
    /// many vehicles handed none carries one test (issue 31: inlined whole, it cost the `idm`
    /// stage 17 instructions per entity-step in callgrind at 1,000 vehicles).
    #[cold]
    #[inline(never)]
    fn settle_toward(&mut self, view: &ControllerView<'_>) {
        let Some(t) = self.toward.as_mut() else {
            return;
        };
        // Toward another's speed: read now, the desired speed too; followed, not released.
        if let Some((x, value)) = t.of {
            let v = (view.other(x).speed + value).max(0.0).min(self.max_speed);
            t.speed = v;
            self.params.desired_speed = v;
            return;
        }
        let v = view.speed().max(0.0);
        let up = *t.up.get_or_insert(v < t.speed);
        let reached = if up {
            v >= t.speed - REACHED
        } else {
            v <= t.speed + REACHED
        };
        if reached {
            self.toward = None;
            self.free = None;
        }
    }

    /// The acceleration in the view: the step's command as a number (the controllers stage's
    /// walk of the driver models, controller/drivers.rs, takes it so; inlined there).
    #[inline]
    pub(crate) fn acceleration(&self, view: &ControllerView<'_>) -> Real {
        let v = view.speed().max(0.0);
        let leader = with_red_light(view, leader(view));
        match &self.free {
            None => self.params.acceleration(v, leader),
            Some(f) => self
                .params
                .acceleration_with_free(self.handed(f, view, v), v, leader),
        }
    }

    pub(crate) fn on_activate(&mut self, view: &ControllerView<'_>) {
        self.max_speed = view.entity().max_speed();
        if self.desired_given {
            self.params.desired_speed = self.params.desired_speed.min(self.max_speed);
        } else {
            self.params.desired_speed = speed_at_activation(view);
        }
    }

    pub(crate) fn on_strategy(&mut self, strategy: Strategy) -> Option<String> {
        match strategy {
            Strategy::Speed(v) => {
                self.params.desired_speed = v.max(0.0).min(self.max_speed);
                // A speed replaces a rate toward another (module doc).
                if self.toward.take().is_some() {
                    self.free = None;
                }
                Some(format!("desired speed {} m/s", self.params.desired_speed))
            }
            Strategy::FreeAccelerationToward { speed, rate, of } => {
                self.free = Some(rate);
                let a = match rate {
                    FreeAcceleration::Fixed(a) => format!("{} m/s²", a.abs()),
                    FreeAcceleration::Follow { value, .. } => {
                        format!("the magnitude of the reference's at each step plus {value} m/s²")
                    }
                };
                if let Some(x) = of {
                    // The speed and the desired speed are read at each step (`settle`).
                    self.toward = Some(Box::new(Toward {
                        speed: self.params.desired_speed,
                        up: None,
                        of: Some((x, speed)),
                    }));
                    return Some(format!("desired speed: the reference's at each step plus {speed} m/s, followed at a free-road acceleration of {a} in place of the IDM's a·(1 − (v/v0)^δ), less its interaction term toward the leader"));
                }
                self.params.desired_speed = speed.max(0.0).min(self.max_speed);
                let v = self.params.desired_speed;
                self.toward = Some(Box::new(Toward {
                    speed: v,
                    up: None,
                    of: None,
                }));
                Some(format!("desired speed {v} m/s, reached at a free-road acceleration of {a} in place of the IDM's a·(1 − (v/v0)^δ), less its interaction term toward the leader, then the IDM's own"))
            }
            Strategy::FreeAcceleration(free) => {
                self.toward = None;
                let note = match (free, self.free) {
                    (Some(FreeAcceleration::Fixed(a)), _) => format!("free-road acceleration {a} m/s² in place of the IDM's a·(1 − (v/v0)^δ), less its interaction term toward the leader"),
                    (Some(FreeAcceleration::Follow { value, .. }), _) => format!("free-road acceleration: the reference's at each step plus {value} m/s² in place of the IDM's a·(1 − (v/v0)^δ), less its interaction term toward the leader"),
                    (None, Some(_)) => "free-road acceleration released: the IDM's own a·(1 − (v/v0)^δ)".to_owned(),
                    (None, None) => "no free-road acceleration to release".to_owned(),
                };
                self.free = free;
                Some(note)
            }
            _ => None,
        }
    }
}

impl Controller for IdmController {
    fn model(&self) -> &'static str {
        "idm"
    }

    fn activate(&mut self, view: &ControllerView<'_>) {
        self.on_activate(view);
    }

    fn strategy(&mut self, strategy: Strategy) -> Option<String> {
        self.on_strategy(strategy)
    }

    fn step(&mut self, view: &ControllerView<'_>, _dt: Real) -> Command {
        self.settle(view);
        Command::acceleration(self.acceleration(view))
    }
}

/// The `acc` controller.
#[derive(Debug, Clone)]
pub struct AccController {
    /// The settings (the set speed as in use).
    pub params: AccParameters,
    set_given: bool,
    max_speed: Real,
    /// The last step's command (for the jerk limit).
    previous: Real,
}

impl AccController {
    /// A controller with `params`; `set_given` false: the set speed is taken at activation.
    pub fn new(params: AccParameters, set_given: bool) -> Self {
        AccController {
            params,
            set_given,
            max_speed: Real::INFINITY,
            previous: 0.0,
        }
    }
}

impl Controller for AccController {
    fn model(&self) -> &'static str {
        "acc"
    }

    fn activate(&mut self, view: &ControllerView<'_>) {
        self.max_speed = view.entity().max_speed();
        self.previous = 0.0;
        if self.set_given {
            self.params.set_speed = self.params.set_speed.min(self.max_speed);
        } else {
            self.params.set_speed = speed_at_activation(view);
        }
    }

    fn strategy(&mut self, strategy: Strategy) -> Option<String> {
        let Strategy::Speed(v) = strategy else {
            return None;
        };
        self.params.set_speed = v.max(0.0).min(self.max_speed);
        Some(format!("set speed {} m/s", self.params.set_speed))
    }

    fn step(&mut self, view: &ControllerView<'_>, dt: Real) -> Command {
        let v = view.entity().speed.max(0.0);
        let a = self.params.command(v, leader(view), self.previous, dt);
        self.previous = a;
        Command::acceleration(a)
    }
}
