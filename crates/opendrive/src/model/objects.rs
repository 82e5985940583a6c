//! `<object>` and `<signal>` of a road (OpenDRIVE 1.8 chapters "Objects" and "Signals"), kept as data
//! for later use (OSI stationary objects, traffic signs).

/// `<object>`.
#[derive(Debug, Clone, PartialEq)]
pub struct Object {
    /// `id`.
    pub id: String,
    /// `name`.
    pub name: String,
    /// `type`.
    pub object_type: String,
    /// `s` (m).
    pub s: f64,
    /// `t` (m).
    pub t: f64,
    /// `zOffset` (m).
    pub z_offset: f64,
    /// `hdg` relative to the road (rad).
    pub hdg: f64,
    /// `pitch` (rad).
    pub pitch: f64,
    /// `roll` (rad).
    pub roll: f64,
    /// `length` (m), if given.
    pub length: Option<f64>,
    /// `width` (m), if given.
    pub width: Option<f64>,
    /// `height` (m), if given.
    pub height: Option<f64>,
    /// `radius` (m), if given.
    pub radius: Option<f64>,
    /// `orientation`: "+", "-" or "none".
    pub orientation: String,
}

/// `<signal>`.
#[derive(Debug, Clone, PartialEq)]
pub struct Signal {
    /// `id`.
    pub id: String,
    /// `name`.
    pub name: String,
    /// `s` (m).
    pub s: f64,
    /// `t` (m).
    pub t: f64,
    /// `zOffset` (m).
    pub z_offset: f64,
    /// `orientation`: "+", "-" or "none".
    pub orientation: String,
    /// `dynamic`: "yes" or "no".
    pub dynamic: bool,
    /// `country`.
    pub country: String,
    /// `type`.
    pub signal_type: String,
    /// `subtype`.
    pub subtype: String,
    /// `value`, if given.
    pub value: Option<f64>,
    /// `unit`.
    pub unit: String,
    /// `hOffset` (rad): heading offset relative to `orientation` (to the reference line when
    /// `orientation` is "none").
    pub h_offset: f64,
    /// `pitch` (rad).
    pub pitch: f64,
    /// `roll` (rad).
    pub roll: f64,
    /// `width` (m), if given.
    pub width: Option<f64>,
    /// `height` (m), if given: measured up from the bottom edge (at `zOffset`).
    pub height: Option<f64>,
    /// `length` (m), the signal's thickness, if given.
    pub length: Option<f64>,
}
