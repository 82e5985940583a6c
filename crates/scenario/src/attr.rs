//! Conversion of resolved attribute text into the XSD's simple types (OpenSCENARIO 1.3,
//! XSD simple types `Double`, `Int`, `UnsignedInt`, `UnsignedShort`, `Boolean`, `String` and
//! the enumerations).
//!
//! Each enumeration of the model implements [`FromAttr`] through the `xsd_enum!` macro, which
//! also maps the literals that 1.0–1.2 spelled differently (flagged so the reader can warn).

/// A value type an attribute can be read as.
pub(crate) trait FromAttr: Sized {
    /// Parses resolved attribute text; the flag is `true` for a deprecated spelling.
    fn from_attr(text: &str) -> Option<(Self, bool)>;
    /// What the schema expects, for error messages ("a double", "one of a, b").
    fn expected() -> String;
    /// The value as its 1.3 literal, for messages about deprecated spellings.
    fn literal(&self) -> String {
        String::new()
    }
}

impl FromAttr for f64 {
    fn from_attr(text: &str) -> Option<(Self, bool)> {
        let t = text.trim();
        let v = match t {
            "INF" => f64::INFINITY,
            "-INF" => f64::NEG_INFINITY,
            _ => t.parse::<f64>().ok().filter(|d| d.is_finite())?,
        };
        Some((v, false))
    }
    fn expected() -> String {
        "a double".into()
    }
}

impl FromAttr for i32 {
    fn from_attr(text: &str) -> Option<(Self, bool)> {
        text.trim().parse().ok().map(|v| (v, false))
    }
    fn expected() -> String {
        "an int".into()
    }
}

impl FromAttr for u32 {
    fn from_attr(text: &str) -> Option<(Self, bool)> {
        text.trim().parse().ok().map(|v| (v, false))
    }
    fn expected() -> String {
        "an unsignedInt".into()
    }
}

impl FromAttr for u16 {
    fn from_attr(text: &str) -> Option<(Self, bool)> {
        text.trim().parse().ok().map(|v| (v, false))
    }
    fn expected() -> String {
        "an unsignedShort".into()
    }
}

impl FromAttr for bool {
    fn from_attr(text: &str) -> Option<(Self, bool)> {
        match text.trim() {
            "true" | "1" => Some((true, false)),
            "false" | "0" => Some((false, false)),
            _ => None,
        }
    }
    fn expected() -> String {
        "a boolean (true or false)".into()
    }
}

impl FromAttr for String {
    fn from_attr(text: &str) -> Option<(Self, bool)> {
        Some((text.to_owned(), false))
    }
    fn expected() -> String {
        "a string".into()
    }
}

/// Declares a model enum for an XSD enumeration: variants with their literal, optional
/// deprecated spellings after `|`, [`FromAttr`], `as_str` and Display.
macro_rules! xsd_enum {
    ($(#[$meta:meta])* $name:ident {
        $($(#[$vmeta:meta])* $variant:ident = $lit:literal $(| $alias:literal)*,)+
    }) => {
        $(#[$meta])*
        #[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
        #[non_exhaustive]
        pub enum $name {
            $($(#[$vmeta])* $variant,)+
        }

        impl $name {
            /// The 1.3 literal.
            pub fn as_str(self) -> &'static str {
                match self {
                    $(Self::$variant => $lit,)+
                }
            }
        }

        impl std::fmt::Display for $name {
            fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
                f.write_str(self.as_str())
            }
        }

        impl $crate::attr::FromAttr for $name {
            fn from_attr(text: &str) -> Option<(Self, bool)> {
                match text.trim() {
                    $($lit => Some((Self::$variant, false)),
                    $($alias => Some((Self::$variant, true)),)*)+
                    _ => None,
                }
            }
            fn expected() -> String {
                let all: &[&str] = &[$($lit),+];
                format!("one of {}", all.join(", "))
            }
            fn literal(&self) -> String {
                self.as_str().to_owned()
            }
        }
    };
}

pub(crate) use xsd_enum;

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn doubles_take_xsd_infinity_and_reject_nan() {
        assert_eq!(f64::from_attr("INF").map(|v| v.0), Some(f64::INFINITY));
        assert!(f64::from_attr("NaN").is_none());
        assert!(f64::from_attr("1.5e3").is_some_and(|(v, _)| (v - 1500.0).abs() < 1e-12));
    }

    #[test]
    fn integers_reject_fractions() {
        assert!(i32::from_attr("2.5").is_none());
        assert_eq!(u16::from_attr("65535").map(|v| v.0), Some(65535));
        assert!(u16::from_attr("65536").is_none());
    }
}
