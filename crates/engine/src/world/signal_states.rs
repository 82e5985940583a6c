//! The state each traffic signal shows (OpenSCENARIO 1.3 §7.2.2.4 TrafficSignalController
//! phases, §7.7.1 TrafficSignalStateAction): signal id → state, as the controllers stage
//! (module `signals`) last set it. Frames carry it to the sinks.

use std::collections::BTreeMap;

/// Signal id → the state it shows (e.g. `"off;off;on"`), for every signal a phase or a
/// TrafficSignalStateAction has set; ordered by id.
#[derive(Debug, Clone, Default, PartialEq, Eq)]
pub struct SignalStates(pub(crate) BTreeMap<String, String>);

impl SignalStates {
    /// The current state of signal `id`, if any was set.
    pub fn state(&self, id: &str) -> Option<&str> {
        self.0.get(id).map(String::as_str)
    }

    /// Every signal id with a state, and the state, in id order.
    pub fn states(&self) -> impl Iterator<Item = (&str, &str)> {
        self.0.iter().map(|(k, v)| (k.as_str(), v.as_str()))
    }
}
