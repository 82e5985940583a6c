//! Errors of the storyboard: a bad description (OpenSCENARIO 1.3 value constraints of
//! `Condition` and `ConditionGroup`) or a bad step time.
//!
//! Messages follow the project's form "expected X, found Y at PLACE". The place of a description
//! error is the element (kind and name), the trigger and the condition, followed by the
//! condition's file position when the runtime supplied one ([`ConditionDesc::origin`]).
//!
//! [`ConditionDesc::origin`]: super::ConditionDesc::origin

use std::fmt;

/// An error building or stepping a [`Storyboard`](super::Storyboard).
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("{kind}")]
pub struct StoryboardError {
    kind: ErrorKind,
}

impl StoryboardError {
    pub(crate) fn new(kind: ErrorKind) -> Self {
        StoryboardError { kind }
    }

    /// What went wrong.
    pub fn kind(&self) -> &ErrorKind {
        &self.kind
    }
}

/// Which trigger of an element an error concerns.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum TriggerRole {
    /// The `StartTrigger`.
    Start,
    /// The `StopTrigger`.
    Stop,
}

impl fmt::Display for TriggerRole {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            TriggerRole::Start => "StartTrigger",
            TriggerRole::Stop => "StopTrigger",
        })
    }
}

/// The kinds of [`StoryboardError`].
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub enum ErrorKind {
    /// A condition's `delay` is negative, infinite or NaN.
    InvalidDelay {
        /// The element owning the trigger, e.g. `act 'CutInAct'`.
        element: String,
        /// Start or stop trigger.
        trigger: TriggerRole,
        /// The condition's name.
        condition: String,
        /// The delay found.
        found: f64,
        /// The condition's file position, if known.
        origin: Option<String>,
    },
    /// A `ConditionGroup` without conditions (the XSD requires at least one).
    EmptyConditionGroup {
        /// The element owning the trigger.
        element: String,
        /// Start or stop trigger.
        trigger: TriggerRole,
        /// 1-based position of the group in the trigger.
        group: usize,
    },
    /// The description has more elements than an [`ElementId`](super::ElementId) can address
    /// (2³²).
    TooManyElements {
        /// The number of elements reached.
        found: usize,
    },
    /// The step's time is not finite.
    InvalidTime {
        /// The time found, in seconds.
        found: f64,
    },
    /// The step's time is not after the previous step's.
    TimeNotIncreasing {
        /// The previous step's time, in seconds.
        previous: f64,
        /// The time found, in seconds.
        found: f64,
    },
    /// The step length is not finite and positive.
    InvalidStepLength {
        /// The step length found, in seconds.
        found: f64,
    },
}

impl fmt::Display for ErrorKind {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            ErrorKind::InvalidDelay {
                element,
                trigger,
                condition,
                found,
                origin,
            } => {
                write!(
                    f,
                    "expected a finite delay >= 0 s, found {found} in condition '{condition}' of \
                     the {trigger} of {element}"
                )?;
                match origin {
                    Some(origin) => write!(f, " at {origin}"),
                    None => Ok(()),
                }
            }
            ErrorKind::EmptyConditionGroup {
                element,
                trigger,
                group,
            } => write!(
                f,
                "expected at least one Condition, found an empty ConditionGroup #{group} in the \
                 {trigger} of {element}"
            ),
            ErrorKind::TooManyElements { found } => write!(
                f,
                "expected at most {} storyboard elements, found {found}",
                u32::MAX
            ),
            ErrorKind::InvalidTime { found } => {
                write!(f, "expected a finite simulation time, found {found} s")
            }
            ErrorKind::TimeNotIncreasing { previous, found } => write!(
                f,
                "expected a simulation time after the previous step's {previous} s, found {found} s"
            ),
            ErrorKind::InvalidStepLength { found } => {
                write!(f, "expected a finite step length > 0 s, found {found} s")
            }
        }
    }
}
