//! `<object>` and `<signal>` of a road (OpenDRIVE 1.8 chapters "Objects" and "Signals"), kept as data
//! for later use (OSI stationary objects, traffic signs, crosswalks), with an object's
//! outlines (OpenDRIVE 1.8 §13.3 "Object outline": corners in road or local coordinates).

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
    /// The `<outline>`s (inside `<outlines>`, or the OpenDRIVE 1.4 `<outline>` child), each
    /// its corners in order; empty when the object has none.
    pub outlines: Vec<Vec<Corner>>,
}

/// A corner of an object's outline (OpenDRIVE 1.8 §13.3: `<cornerRoad>`, `<cornerLocal>`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Corner {
    /// `<cornerRoad s t dz height>`: a point in the road's reference-line coordinates (m).
    Road {
        /// `s`.
        s: f64,
        /// `t`.
        t: f64,
    },
    /// `<cornerLocal u v z height>`: a point in the object's local frame, u along its heading
    /// `hdg` and v to its left, from the object's (s, t) (m).
    Local {
        /// `u`.
        u: f64,
        /// `v`.
        v: f64,
    },
}

impl Object {
    /// Whether the object is a crosswalk (OpenDRIVE 1.8 §13.11 object types: `crosswalk`).
    pub fn is_crosswalk(&self) -> bool {
        self.object_type == "crosswalk"
    }
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
    /// The `<validity>` children as (`fromLane`, `toLane`), both inclusive (OpenDRIVE 1.8
    /// §14.2 "Lane validity for signals"); empty: valid for every lane of the road in the
    /// `orientation`'s direction of travel.
    pub validity: Vec<(i32, i32)>,
}

impl Signal {
    /// Whether the signal applies to lane `lane_id` by its `<validity>` elements (OpenDRIVE 1.8
    /// §14.2): true when it has none, else when the id lies in one of their ranges. The
    /// direction of travel is the `orientation`'s business, checked separately.
    pub fn valid_for_lane(&self, lane_id: i32) -> bool {
        self.validity.is_empty()
            || self
                .validity
                .iter()
                .any(|&(from, to)| from.min(to) <= lane_id && lane_id <= from.max(to))
    }
}
