//! Static types of the checker (ASAM OpenSCENARIO DSL 2.1 §7.3.1 type system).
//!
//! Physical types are identified by their [`Dimension`]: `speed` and any other type declared
//! `SI(m: 1, s: -1)` are the same type, so `kph + mps` is a speed and `m + s` an error.

use super::units::Dimension;

/// Index of a compound type (struct, actor, scenario, action, modifier) in the model.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct CompoundId(pub u32);

/// Index of an enumeration type in the model.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct EnumId(pub u32);

/// A static type.
#[derive(Debug, Clone, PartialEq)]
pub enum Ty {
    /// `bool`
    Bool,
    /// `int`
    Int,
    /// `uint`
    Uint,
    /// `float`
    Float,
    /// `string`
    Str,
    /// A physical quantity of this dimension.
    Physical(Dimension),
    /// An enumeration.
    Enum(EnumId),
    /// A struct, actor or behavior.
    Compound(CompoundId),
    /// `list of T`.
    List(Box<Ty>),
    /// `range of T`, and the value of `[a..b]`.
    Range(Box<Ty>),
    /// An event (`rise(…)`, `every(…)`, a declared event).
    Event,
    /// The type of an expression that already produced an error; accepted everywhere so that
    /// one mistake is reported once.
    Error,
}

impl Ty {
    /// `int`, `uint` or `float`.
    pub fn is_plain_number(&self) -> bool {
        matches!(self, Ty::Int | Ty::Uint | Ty::Float)
    }

    /// A plain number or a physical quantity.
    pub fn is_numeric(&self) -> bool {
        self.is_plain_number() || matches!(self, Ty::Physical(_))
    }

    /// `int` or `uint`.
    pub fn is_integer(&self) -> bool {
        matches!(self, Ty::Int | Ty::Uint)
    }
}
