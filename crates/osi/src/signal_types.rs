//! What an OpenDRIVE signal means in OSI 3.8 terms: which signals are traffic lights and with
//! which bulbs (osi_trafficlight.proto: one `TrafficLight` per bulb), how an OpenSCENARIO
//! signal state lights a bulb, and which OSI `TrafficSign` type, value and unit a sign has
//! (osi_trafficsign.proto).
//!
//! - Traffic lights: the OpenDRIVE 1.8 signal catalogue of the country `OpenDRIVE` (§14,
//!   "Signals"): type `1000001` is the three-light vehicle signal (red, yellow, green from the
//!   top), `1000002` the two-light pedestrian signal (red, green), `1000007` the two-light
//!   pedestrian and bicycle signal. The type is matched whatever the `country` (files often
//!   write a national country code with these types). Other signals are signs.
//! - States: an OpenSCENARIO `TrafficSignalState/@state` of a light is a `;`-separated list,
//!   one field per bulb from the top (`on;off;off` is red, the convention of the OpenSCENARIO
//!   examples); `on` → `MODE_CONSTANT`, `off` → `MODE_OFF`, `flashing` → `MODE_FLASHING`,
//!   any other word or a missing field → `MODE_OTHER` (known to be something, not which).
//! - Signs of the German catalogue (`country` `DE`, StVO numbers as OSI lists them beside its
//!   types): the common regulatory signs below; any other sign is `TYPE_OTHER` with its
//!   country, code and sub code, which is what OSI asks for a sign it has no type for.

use crate::osi3::traffic_light::classification::{Color, Icon, Mode};
use crate::osi3::traffic_sign::main_sign::classification::Type as SignType;
use crate::osi3::traffic_sign_value::Unit;

/// The bulbs of a traffic light, from the top, and the icon they show.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct LightType {
    /// Semantic colour of each bulb, top first.
    pub bulbs: &'static [Color],
    /// The icon of every bulb.
    pub icon: Icon,
}

const VEHICLE: LightType = LightType {
    bulbs: &[Color::Red, Color::Yellow, Color::Green],
    icon: Icon::None,
};
const PEDESTRIAN: LightType = LightType {
    bulbs: &[Color::Red, Color::Green],
    icon: Icon::Pedestrian,
};
const PEDESTRIAN_AND_BICYCLE: LightType = LightType {
    bulbs: &[Color::Red, Color::Green],
    icon: Icon::PedestrianAndBicycle,
};

/// The traffic light an OpenDRIVE signal `type` names, if it is one (module doc).
pub fn light_type(signal_type: &str) -> Option<LightType> {
    match signal_type.trim() {
        "1000001" => Some(VEHICLE),
        "1000002" => Some(PEDESTRIAN),
        "1000007" => Some(PEDESTRIAN_AND_BICYCLE),
        _ => None,
    }
}

/// The mode of each of `bulbs` bulbs under OpenSCENARIO state `state` (module doc); `None`
/// (no state set yet) leaves every bulb off.
///
/// An iterator, so that writing a frame's lights builds no list.
pub fn bulb_modes(state: Option<&str>, bulbs: usize) -> impl Iterator<Item = Mode> + '_ {
    let mut fields = state.map(|s| s.split(';').map(str::trim));
    (0..bulbs).map(move |_| match fields.as_mut() {
        None => Mode::Off,
        Some(fields) => bulb_mode(fields.next()),
    })
}

/// The mode of one field of a state (`on`, `off`, `flashing` in any case; else other).
fn bulb_mode(field: Option<&str>) -> Mode {
    match field {
        Some(f) if f.eq_ignore_ascii_case("on") => Mode::Constant,
        Some(f) if f.eq_ignore_ascii_case("off") => Mode::Off,
        Some(f) if f.eq_ignore_ascii_case("flashing") => Mode::Flashing,
        _ => Mode::Other,
    }
}

/// The OSI type of a sign of `country` with `code` (OpenDRIVE `type`) and `sub_code`
/// (`subtype`); `TYPE_OTHER` where none fits (module doc).
pub fn sign_type(country: &str, code: &str, sub_code: &str) -> SignType {
    if !country.trim().eq_ignore_ascii_case("DE") {
        return SignType::Other;
    }
    let sub = sub_code.trim();
    let plain = sub.is_empty() || sub == "-1" || sub.eq_ignore_ascii_case("none");
    match (code.trim(), plain) {
        ("101", true) => SignType::DangerSpot,
        ("123", true) => SignType::RoadWorks,
        ("205", true) => SignType::GiveWay,
        ("206", true) => SignType::Stop,
        ("250", true) => SignType::AllProhibited,
        ("267", true) => SignType::DoNotEnter,
        // 274 carries the limit as its value (sub codes 5x give it in the catalogue).
        ("274", _) => SignType::SpeedLimitBegin,
        ("276", true) => SignType::OvertakingBanBegin,
        ("278", _) => SignType::SpeedLimitEnd,
        ("280", true) => SignType::OvertakingBanEnd,
        ("282", true) => SignType::AllRestrictionsEnd,
        ("301", true) => SignType::RightOfWayNextIntersection,
        ("306", true) => SignType::RightOfWayBegin,
        ("307", true) => SignType::RightOfWayEnd,
        ("310", true) => SignType::TownBegin,
        ("311", true) => SignType::TownEnd,
        ("350", true) => SignType::ZebraCrossing,
        _ => SignType::Other,
    }
}

/// The OSI unit of an OpenDRIVE `unit` (OpenDRIVE 1.8 §2.4 units); no unit → `UNIT_NO_UNIT`.
pub fn value_unit(unit: &str) -> Unit {
    match unit.trim() {
        "" => Unit::NoUnit,
        "km/h" => Unit::KilometerPerHour,
        "mph" => Unit::MilePerHour,
        "m" => Unit::Meter,
        "km" => Unit::Kilometer,
        "ft" => Unit::Feet,
        "mile" => Unit::Mile,
        "t" => Unit::MetricTon,
        "%" => Unit::Percentage,
        _ => Unit::Other,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn states_light_bulbs_from_the_top() {
        // Red of a three-light signal: the top bulb on, the others off.
        assert_eq!(
            bulb_modes(Some("on;off;off"), 3).collect::<Vec<_>>(),
            [Mode::Constant, Mode::Off, Mode::Off]
        );
        assert_eq!(
            bulb_modes(Some("off; Flashing"), 3).collect::<Vec<_>>(),
            [Mode::Off, Mode::Flashing, Mode::Other]
        );
        assert_eq!(
            bulb_modes(None, 2).collect::<Vec<_>>(),
            [Mode::Off, Mode::Off]
        );
        assert_eq!(light_type("1000001").map(|l| l.bulbs.len()), Some(3));
        assert_eq!(
            light_type("1000002").map(|l| l.icon),
            Some(Icon::Pedestrian)
        );
        assert_eq!(light_type("274"), None);
    }

    #[test]
    fn german_signs_get_their_types_others_are_other() {
        assert_eq!(sign_type("DE", "206", "-1"), SignType::Stop);
        assert_eq!(sign_type("de", "274", "50"), SignType::SpeedLimitBegin);
        assert_eq!(sign_type("DE", "206", "10"), SignType::Other);
        assert_eq!(sign_type("se", "c", "31"), SignType::Other);
        assert_eq!(value_unit("km/h"), Unit::KilometerPerHour);
        assert_eq!(value_unit(""), Unit::NoUnit);
    }
}
