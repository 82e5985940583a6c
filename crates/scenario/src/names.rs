//! Qualified names of storyboard elements and how a reference picks its element: the naming
//! rule of OpenSCENARIO (1.1 User Guide §1.4.5 "Naming conventions for OpenSCENARIO
//! references", kept in the 1.2 and 1.3 general concepts "Naming" / "References").
//!
//! * An element is known by its name path: the names of its enclosing storyboard elements,
//!   outermost first, then its own, joined by `::` — `Story::Act::ManeuverGroup::Maneuver::
//!   Event::Action`. Element names shall not contain `::` (the separator is reserved).
//! * A reference is a name, optionally preceded by prefixes (`Maneuver::Event`); it designates
//!   every element of the referenced type whose name path ends with the reference's parts
//!   (unique-suffix matching: the prefixes need not start at the Story). A reference that
//!   starts with `::` is absolute: its parts must be the whole path.
//! * A reference shall designate exactly one element. Several candidates make the reference
//!   ambiguous — the standard's remedy is to add prefixes until it is unique — so oscsim
//!   rejects it at load, naming the candidates; none is an unknown element.
//!
//! Both the reader (which checks every reference at load) and the engine (which finds the
//! element it watches) match through [`QualifiedName::matches`].

use std::fmt;

/// The separator of name prefixes.
pub const SEPARATOR: &str = "::";

/// A parsed storyboard element reference: optional prefixes and the element's name.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct QualifiedName<'a> {
    /// Written with a leading `::`: the parts are the whole path from the Story down.
    pub absolute: bool,
    /// Prefixes, outermost first, then the element's own name (never empty).
    pub parts: Vec<&'a str>,
}

impl<'a> QualifiedName<'a> {
    /// Splits `reference` at `::`. Surrounding whitespace of each part is kept (names are
    /// compared as written).
    pub fn parse(reference: &'a str) -> Self {
        let (absolute, rest) = match reference.strip_prefix(SEPARATOR) {
            Some(rest) => (true, rest),
            None => (false, reference),
        };
        QualifiedName {
            absolute,
            parts: rest.split(SEPARATOR).collect(),
        }
    }

    /// True if the reference has prefixes (or is absolute).
    pub fn is_qualified(&self) -> bool {
        self.absolute || self.parts.len() > 1
    }

    /// True if the element with name path `path` (outermost first, the element's own name
    /// last) is designated: `path` ends with the parts (and, if absolute, equals them).
    pub fn matches<S: AsRef<str>>(&self, path: &[S]) -> bool {
        if self.absolute && path.len() != self.parts.len() {
            return false;
        }
        path.len() >= self.parts.len()
            && path[path.len() - self.parts.len()..]
                .iter()
                .zip(&self.parts)
                .all(|(p, q)| p.as_ref() == *q)
    }
}

impl fmt::Display for QualifiedName<'_> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if self.absolute {
            f.write_str(SEPARATOR)?;
        }
        f.write_str(&self.parts.join(SEPARATOR))
    }
}

/// A name path written out with `::`.
pub fn join_path<S: AsRef<str>>(path: &[S]) -> String {
    path.iter()
        .map(|p| p.as_ref())
        .collect::<Vec<_>>()
        .join(SEPARATOR)
}

#[cfg(test)]
mod tests {
    use super::*;

    const PATH: [&str; 5] = ["Story", "Act", "MG", "Maneuver1", "Event1"];

    #[test]
    fn a_plain_name_matches_the_last_part() {
        assert!(QualifiedName::parse("Event1").matches(&PATH));
        assert!(!QualifiedName::parse("Maneuver1").matches(&PATH));
    }

    #[test]
    fn prefixes_match_a_suffix_of_the_path() {
        assert!(QualifiedName::parse("Maneuver1::Event1").matches(&PATH));
        assert!(QualifiedName::parse("MG::Maneuver1::Event1").matches(&PATH));
        assert!(QualifiedName::parse("Story::Act::MG::Maneuver1::Event1").matches(&PATH));
        // A gap is not a suffix: Act is not Maneuver1's parent.
        assert!(!QualifiedName::parse("Act::Event1").matches(&PATH));
        assert!(!QualifiedName::parse("X::Story::Act::MG::Maneuver1::Event1").matches(&PATH));
    }

    #[test]
    fn a_leading_separator_asks_for_the_whole_path() {
        assert!(QualifiedName::parse("::Story::Act::MG::Maneuver1::Event1").matches(&PATH));
        assert!(!QualifiedName::parse("::Maneuver1::Event1").matches(&PATH));
        assert_eq!(
            QualifiedName::parse("::A::B").to_string(),
            "::A::B",
            "display keeps the form written"
        );
    }

    #[test]
    fn qualified_or_not() {
        assert!(!QualifiedName::parse("E").is_qualified());
        assert!(QualifiedName::parse("M::E").is_qualified());
        assert!(QualifiedName::parse("::E").is_qualified());
        assert_eq!(join_path(&PATH[3..]), "Maneuver1::Event1");
    }
}
