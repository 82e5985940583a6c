//! Condition edges, OpenSCENARIO 1.3 §7.6 "Conditions and triggers" and the class `Condition`
//! (attribute `conditionEdge`).
//!
//! A condition "operates on the current and previous evaluations of its logical expressions"
//! (§7.6). With `rising` it is true when the expression was false at the previous evaluation and
//! is true now; `falling` the reverse; `risingOrFalling` either; `none` passes the expression
//! through.
//!
//! # First evaluation
//!
//! At its first evaluation an edged condition has no previous value. oscsim follows the
//! OpenSCENARIO 1.0 User Guide, which states that all conditions defined with `rising`, `falling`
//! or `risingOrFalling` are expected to return false the first time they are checked by a
//! simulation engine (quoted in esmini issue #29): the first evaluation only records the value.
//! So `SimulationTime > 0, rising` on an Act first evaluated at t = 0 (false) fires at the next
//! step, and an edged condition that is already true when its trigger starts being evaluated
//! waits for the expression to fall and rise again. Each time an element enters `standbyState`
//! its start trigger begins a new series of evaluations (see [`EdgeDetector::reset`]).

/// The `conditionEdge` of a condition (XSD enumeration `ConditionEdge`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum ConditionEdge {
    /// `rising`: true when the expression goes from false to true.
    Rising,
    /// `falling`: true when the expression goes from true to false.
    Falling,
    /// `risingOrFalling`: true when the expression changes.
    RisingOrFalling,
    /// `none`: true whenever the expression is true.
    None,
}

/// Applies a [`ConditionEdge`] to a series of raw values of one condition.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct EdgeDetector {
    edge: ConditionEdge,
    previous: Option<bool>,
}

impl EdgeDetector {
    /// A detector with no previous value.
    pub fn new(edge: ConditionEdge) -> Self {
        EdgeDetector {
            edge,
            previous: None,
        }
    }

    /// Forgets the previous value: the next evaluation counts as the first.
    pub fn reset(&mut self) {
        self.previous = None;
    }

    /// Feeds the raw value of the expression at this evaluation and returns the condition's
    /// edge output. The first evaluation after [`new`](Self::new) or [`reset`](Self::reset)
    /// returns false for every edge but `none` (see the module documentation).
    pub fn update(&mut self, raw: bool) -> bool {
        let previous = self.previous.replace(raw);
        match (self.edge, previous) {
            (ConditionEdge::None, _) => raw,
            (_, None) => false,
            (ConditionEdge::Rising, Some(before)) => !before && raw,
            (ConditionEdge::Falling, Some(before)) => before && !raw,
            (ConditionEdge::RisingOrFalling, Some(before)) => before != raw,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn run(edge: ConditionEdge, raw: &[bool]) -> Vec<bool> {
        let mut detector = EdgeDetector::new(edge);
        raw.iter().map(|&value| detector.update(value)).collect()
    }

    // Truth tables of §7.6 for the series F T T F T, and the first-evaluation rule.
    const SERIES: [bool; 5] = [false, true, true, false, true];

    #[test]
    fn rising_fires_on_false_to_true_only() {
        assert_eq!(
            run(ConditionEdge::Rising, &SERIES),
            [false, true, false, false, true]
        );
    }

    #[test]
    fn falling_fires_on_true_to_false_only() {
        assert_eq!(
            run(ConditionEdge::Falling, &SERIES),
            [false, false, false, true, false]
        );
    }

    #[test]
    fn rising_or_falling_fires_on_every_change() {
        assert_eq!(
            run(ConditionEdge::RisingOrFalling, &SERIES),
            [false, true, false, true, true]
        );
    }

    #[test]
    fn none_passes_the_value_through() {
        assert_eq!(run(ConditionEdge::None, &SERIES), SERIES);
    }

    #[test]
    fn first_evaluation_of_an_edge_is_false_even_when_true() {
        // OpenSCENARIO 1.0 User Guide: edged conditions return false when first checked.
        for edge in [
            ConditionEdge::Rising,
            ConditionEdge::Falling,
            ConditionEdge::RisingOrFalling,
        ] {
            assert_eq!(run(edge, &[true]), [false], "{edge:?}");
            assert_eq!(run(edge, &[false]), [false], "{edge:?}");
        }
    }

    #[test]
    fn reset_makes_the_next_evaluation_the_first() {
        let mut detector = EdgeDetector::new(ConditionEdge::Rising);
        assert!(!detector.update(false));
        detector.reset();
        // Would be a rising edge without the reset.
        assert!(!detector.update(true));
    }
}
