//! The domains a controller is active on (OpenSCENARIO 1.3 §6.6.1 "Controller": longitudinal,
//! lateral, lighting, animation), as ActivateControllerAction and AssignControllerAction
//! leave them; the event log reports them.

/// Domains active on one controller (the four of §6.6.1).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct ActiveDomains {
    /// Longitudinal.
    pub longitudinal: bool,
    /// Lateral.
    pub lateral: bool,
    /// Lighting.
    pub lighting: bool,
    /// Animation.
    pub animation: bool,
}
