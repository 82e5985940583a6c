//! `<controller>` of the road network (OpenDRIVE 1.8 §14, "Controllers"; XSD `t_controller`):
//! a set of dynamic signals switched together, listed by its `<control>` children. An
//! OpenSCENARIO TrafficSignalController names one by its id.

/// `<controller>`.
#[derive(Debug, Clone, PartialEq)]
pub struct Controller {
    /// `id`.
    pub id: String,
    /// `name` (empty when absent).
    pub name: String,
    /// The `signalId` of each `<control>`, in file order.
    pub signal_ids: Vec<String>,
}
