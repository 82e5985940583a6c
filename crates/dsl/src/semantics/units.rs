//! Physical quantities: dimensions over the SI base units and unit conversion
//! (ASAM OpenSCENARIO DSL 2.1 §7.3.4 physical types and units; the standard library's
//! `type length is SI(m: 1)` and `unit kph of speed is SI(m: 1, s: -1, factor: …)`).
//!
//! A [`Dimension`] is the vector of exponents over the eight base units the language's `SI(…)`
//! form accepts (kg, m, s, A, K, mol, cd, rad). A [`Unit`] converts a literal to SI:
//! `value_si = value * factor + offset`. Every number the checker and the solver hold is in SI,
//! so `10kph + 1mps` is `3.7778 m/s`, and adding a length to a time is a dimension error.

use std::fmt;

/// The SI base units `SI(…)` names, in the order of [`Dimension`]'s exponents.
pub const BASE_UNITS: [&str; 8] = ["kg", "m", "s", "A", "K", "mol", "cd", "rad"];

/// Exponents over [`BASE_UNITS`]; all zero is a plain number.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
pub struct Dimension(pub [i8; 8]);

impl Dimension {
    /// The dimension of a plain number.
    pub const NONE: Dimension = Dimension([0; 8]);

    /// The dimension with exponent `exp` on base unit `name` (one of [`BASE_UNITS`]).
    pub fn base(name: &str, exp: i8) -> Option<Dimension> {
        let i = BASE_UNITS.iter().position(|b| *b == name)?;
        let mut d = [0; 8];
        d[i] = exp;
        Some(Dimension(d))
    }

    /// Whether this is the dimension of a plain number.
    pub fn is_none(self) -> bool {
        self == Self::NONE
    }

    /// The dimension of a product; `None` when an exponent leaves the `i8` range.
    pub fn times(self, other: Dimension) -> Option<Dimension> {
        let mut d = [0i8; 8];
        for (i, slot) in d.iter_mut().enumerate() {
            *slot = self.0[i].checked_add(other.0[i])?;
        }
        Some(Dimension(d))
    }

    /// The dimension of a quotient; `None` when an exponent leaves the `i8` range.
    pub fn per(self, other: Dimension) -> Option<Dimension> {
        let mut d = [0i8; 8];
        for (i, slot) in d.iter_mut().enumerate() {
            *slot = self.0[i].checked_sub(other.0[i])?;
        }
        Some(Dimension(d))
    }
}

impl fmt::Display for Dimension {
    /// `m*s^-1`, or `1` for a plain number.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let mut first = true;
        for (name, exp) in BASE_UNITS.iter().zip(self.0) {
            if exp == 0 {
                continue;
            }
            if !first {
                f.write_str("*")?;
            }
            first = false;
            if exp == 1 {
                write!(f, "{name}")?;
            } else {
                write!(f, "{name}^{exp}")?;
            }
        }
        if first {
            f.write_str("1")?;
        }
        Ok(())
    }
}

/// A unit of a physical type: `unit NAME of TYPE is SI(…, factor: F, offset: O)`.
#[derive(Debug, Clone, PartialEq)]
pub struct Unit {
    /// The unit's name as written after a number (`kph`).
    pub name: String,
    /// The physical type it belongs to (`speed`).
    pub physical_type: String,
    /// Its dimension.
    pub dimension: Dimension,
    /// SI value of one unit (without offset).
    pub factor: f64,
    /// SI value of zero units (temperatures).
    pub offset: f64,
}

impl Unit {
    /// `value` of this unit in SI.
    pub fn to_si(&self, value: f64) -> f64 {
        value * self.factor + self.offset
    }

    /// An SI value expressed in this unit.
    pub fn from_si(&self, si: f64) -> f64 {
        (si - self.offset) / self.factor
    }
}

/// A physical type: `type NAME is SI(…)`.
#[derive(Debug, Clone, PartialEq)]
pub struct PhysicalType {
    /// The type's name (`speed`).
    pub name: String,
    /// Its dimension.
    pub dimension: Dimension,
}

/// The physical types and units of a program, looked up by name.
#[derive(Debug, Clone, Default)]
pub struct UnitTable {
    types: Vec<PhysicalType>,
    units: Vec<Unit>,
}

impl UnitTable {
    /// Adds a physical type; returns false (and keeps the first) when the name is taken.
    pub fn add_type(&mut self, t: PhysicalType) -> bool {
        if self.physical_type(&t.name).is_some() {
            return false;
        }
        self.types.push(t);
        true
    }

    /// Adds a unit; returns false (and keeps the first) when the name is taken.
    pub fn add_unit(&mut self, u: Unit) -> bool {
        if self.unit(&u.name).is_some() {
            return false;
        }
        self.units.push(u);
        true
    }

    /// The physical type called `name`.
    pub fn physical_type(&self, name: &str) -> Option<&PhysicalType> {
        self.types.iter().find(|t| t.name == name)
    }

    /// The unit called `name`.
    pub fn unit(&self, name: &str) -> Option<&Unit> {
        self.units.iter().find(|u| u.name == name)
    }

    /// The physical type of dimension `d`, for naming a computed quantity: the first declared
    /// whose name the program can write unprefixed (not a library type a file's own type of
    /// that name shadows, `stdtypes::length`), else the first.
    pub fn type_of_dimension(&self, d: Dimension) -> Option<&PhysicalType> {
        let mut of_dim = self.types.iter().filter(|t| t.dimension == d);
        let first = of_dim.clone().next();
        of_dim
            .find(|t| !t.name.starts_with("std::") && !t.name.starts_with("stdtypes::"))
            .or(first)
    }

    /// The unit in which values of physical type `ty` are printed: its shortest-named unit of
    /// factor 1 and offset 0 (the SI unit: `m`, `mps`, `K`), else its first unit.
    pub fn display_unit(&self, ty: &str) -> Option<&Unit> {
        let of_type = self.units.iter().filter(|u| u.physical_type == ty);
        let first = of_type.clone().next();
        of_type
            .filter(|u| u.factor == 1.0 && u.offset == 0.0)
            .min_by_key(|u| u.name.len())
            .or(first)
    }

    /// Every physical type, in declaration order.
    pub fn types(&self) -> &[PhysicalType] {
        &self.types
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Tolerance for conversions of exact decimal factors: a few ulps at the magnitudes used.
    const TOL: f64 = 1e-12;

    fn speed() -> Dimension {
        Dimension::base("m", 1)
            .unwrap()
            .per(Dimension::base("s", 1).unwrap())
            .unwrap()
    }

    #[test]
    fn kph_and_mps_share_a_dimension_and_convert() {
        let kph = Unit {
            name: "kph".into(),
            physical_type: "speed".into(),
            dimension: speed(),
            factor: 1.0 / 3.6,
            offset: 0.0,
        };
        // 36 km/h = 36000 m / 3600 s = 10 m/s.
        assert!((kph.to_si(36.0) - 10.0).abs() < TOL);
        assert!((kph.from_si(10.0) - 36.0).abs() < TOL);
        assert_eq!(speed().to_string(), "m*s^-1");
    }

    #[test]
    fn celsius_has_an_offset() {
        let c = Unit {
            name: "celsius".into(),
            physical_type: "temperature".into(),
            dimension: Dimension::base("K", 1).unwrap(),
            factor: 1.0,
            offset: 273.15,
        };
        // 25 °C = 298.15 K.
        assert!((c.to_si(25.0) - 298.15).abs() < TOL);
    }

    #[test]
    fn length_and_time_differ_and_products_add_exponents() {
        let m = Dimension::base("m", 1).unwrap();
        let s = Dimension::base("s", 1).unwrap();
        assert_ne!(m, s);
        assert_eq!(speed().times(s), Some(m));
        assert_eq!(Dimension::NONE.to_string(), "1");
        assert!(Dimension::base("furlong", 1).is_none());
        let big = Dimension([127, 0, 0, 0, 0, 0, 0, 0]);
        assert_eq!(big.times(big), None);
    }
}
