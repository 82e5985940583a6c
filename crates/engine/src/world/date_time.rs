//! `xsd:dateTime` (the `dateTime` of TimeOfDayCondition, OpenSCENARIO 1.3 §7.6.2; XML Schema
//! Part 2 §3.2.7) to seconds since 1970-01-01T00:00:00Z.
//!
//! Form read: `YYYY-MM-DDThh:mm:ss[.fff][Z|±hh:mm]`; without a zone the time is taken as UTC
//! (XML Schema leaves zone-less times "local"; the scenario's clock has no other zone).
//! Written by hand: one fixed format whose day count is Howard Hinnant's `days_from_civil`
//! (proleptic Gregorian calendar); no date crate is among the workspace's dependencies and the
//! whole job is these few lines.

/// Seconds since 1970-01-01T00:00:00Z of an xsd:dateTime, `None` if `text` is not one.
pub(crate) fn parse_date_time(text: &str) -> Option<f64> {
    parse_zoned_date_time(text).map(|(utc, _)| utc)
}

/// Seconds since 1970-01-01T00:00:00Z of an xsd:dateTime and its zone's offset from UTC (s; 0
/// for `Z` or no zone), `None` if `text` is not one.
pub(crate) fn parse_zoned_date_time(text: &str) -> Option<(f64, i64)> {
    let text = text.trim();
    let (date, rest) = text.split_once('T')?;
    let mut d = date.splitn(3, '-');
    let (year, month, day): (i64, i64, i64) = (
        d.next()?.parse().ok()?,
        d.next()?.parse().ok()?,
        d.next()?.parse().ok()?,
    );
    if !(1..=12).contains(&month) || !(1..=31).contains(&day) {
        return None;
    }
    // Split off the zone: Z, or a sign after the seconds.
    let (clock, zone_seconds) = if let Some(c) = rest.strip_suffix('Z') {
        (c, 0)
    } else if let Some(i) = rest.rfind(['+', '-']) {
        let (c, z) = rest.split_at(i);
        let sign = if z.starts_with('-') { -1 } else { 1 };
        let (zh, zm) = z[1..].split_once(':')?;
        let (zh, zm): (i64, i64) = (zh.parse().ok()?, zm.parse().ok()?);
        (c, sign * (zh * 3600 + zm * 60))
    } else {
        (rest, 0)
    };
    let mut c = clock.splitn(3, ':');
    let (hour, minute): (i64, i64) = (c.next()?.parse().ok()?, c.next()?.parse().ok()?);
    let second: f64 = c.next()?.parse().ok()?;
    if hour > 24 || minute > 59 || !(0.0..61.0).contains(&second) {
        return None;
    }
    let days = days_from_civil(year, month, day);
    Some((
        (days * 86_400 + hour * 3600 + minute * 60 - zone_seconds) as f64 + second,
        zone_seconds,
    ))
}

/// Days from 1970-01-01 to the Gregorian date (y, m, d) (H. Hinnant, "chrono-Compatible
/// Low-Level Date Algorithms").
fn days_from_civil(y: i64, m: i64, d: i64) -> i64 {
    let y = if m <= 2 { y - 1 } else { y };
    let era = y.div_euclid(400);
    let yoe = y - era * 400;
    let mp = (m + 9) % 12;
    let doy = (153 * mp + 2) / 5 + d - 1;
    let doe = yoe * 365 + yoe / 4 - yoe / 100 + doy;
    era * 146_097 + doe - 719_468
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn known_instants() {
        // 2000-03-01 is day 11 017 after the epoch (30 years · 365 + 7 leap days + 31 + 29).
        assert_eq!(days_from_civil(2000, 3, 1), 11_017);
        assert_eq!(days_from_civil(1970, 1, 1), 0);
        assert_eq!(parse_date_time("1970-01-01T00:00:00"), Some(0.0));
        // 12:30:15.5 UTC and the same instant written at +02:00.
        let t = 11_017.0 * 86_400.0 + 12.0 * 3600.0 + 30.0 * 60.0 + 15.5;
        assert_eq!(parse_date_time("2000-03-01T12:30:15.5Z"), Some(t));
        assert_eq!(parse_date_time("2000-03-01T14:30:15.5+02:00"), Some(t));
        assert_eq!(
            parse_zoned_date_time("2000-03-01T09:00:15.5-03:30"),
            Some((t, -12_600))
        );
        assert_eq!(parse_date_time("2000-13-01T00:00:00"), None);
        assert_eq!(parse_date_time("noon"), None);
        assert_eq!(parse_date_time("2000-03-01T-"), None);
        assert_eq!(parse_date_time("2000-03-01T12:00:00+ä"), None);
    }

    proptest::proptest! {
        /// Bad input gives `None`, never a panic.
        #[test]
        fn never_panics(text in "\\PC{0,40}") {
            let _ = parse_date_time(&text);
        }

        /// Every well-formed UTC instant of 1970–2100 reads back to its day and second.
        #[test]
        fn reads_back(days in 0i64..47_482, second in 0i64..86_400) {
            let (y, m, d) = civil_from_days(days);
            let text = format!(
                "{y:04}-{m:02}-{d:02}T{:02}:{:02}:{:02}Z",
                second / 3600,
                second / 60 % 60,
                second % 60
            );
            proptest::prop_assert_eq!(parse_date_time(&text), Some((days * 86_400 + second) as f64));
        }
    }

    /// The inverse of `days_from_civil` (H. Hinnant's `civil_from_days`), for the round trip.
    fn civil_from_days(z: i64) -> (i64, i64, i64) {
        let z = z + 719_468;
        let era = z.div_euclid(146_097);
        let doe = z - era * 146_097;
        let yoe = (doe - doe / 1460 + doe / 36_524 - doe / 146_096) / 365;
        let doy = doe - (365 * yoe + yoe / 4 - yoe / 100);
        let mp = (5 * doy + 2) / 153;
        let d = doy - (153 * mp + 2) / 5 + 1;
        let m = if mp < 10 { mp + 3 } else { mp - 9 };
        (yoe + era * 400 + i64::from(m <= 2), m, d)
    }
}
