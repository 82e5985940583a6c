//! OSI trace file naming convention (ASAM OSI 3.8 §2.2.6.2):
//! `<timestamp>_<type>_<osi-version>_<protobuf-version>_<number-of-frames>_<custom-trace-name>.osi`
//! with the timestamp in ISO 8601 basic format (`20210818T150542Z`), the versions without
//! their dots (`3.8.0` → `380`), and type `gt` for GroundTruth.
//!
//! The UTC calendar date is computed by hand from Unix seconds (the days-to-civil
//! algorithm of H. Hinnant, "chrono-Compatible Low-Level Date Algorithms"): one small
//! function, not worth a date-time dependency.

/// The convention's file name for a GroundTruth trace.
///
/// `unix_seconds` is the UTC time of the recording, `extension` `"osi"` or `"mcap"`.
/// Characters of `scenario_name` that would break the name's fields (`.`, path
/// separators, white space, control characters) become `-`; an empty name becomes
/// `scenario`.
pub fn trace_file_name(
    unix_seconds: i64,
    osi_version: &str,
    protobuf_version: &str,
    frames: u64,
    scenario_name: &str,
    extension: &str,
) -> String {
    format!(
        "{}_gt_{}_{}_{}_{}.{}",
        utc_basic_timestamp(unix_seconds),
        osi_version.replace('.', ""),
        protobuf_version.replace('.', ""),
        frames,
        sanitize(scenario_name),
        extension
    )
}

/// `YYYYMMDDTHHMMSSZ` for the given Unix time (UTC).
pub fn utc_basic_timestamp(unix_seconds: i64) -> String {
    let (y, m, d, hh, mm, ss) = utc_fields(unix_seconds);
    format!("{y:04}{m:02}{d:02}T{hh:02}{mm:02}{ss:02}Z")
}

/// `YYYY-MM-DDTHH:MM:SSZ` (ISO 8601 extended, UTC) for the given Unix time: the MCAP
/// `creation_time` of a pinned recording.
pub fn utc_extended_timestamp(unix_seconds: i64) -> String {
    let (y, m, d, hh, mm, ss) = utc_fields(unix_seconds);
    format!("{y:04}-{m:02}-{d:02}T{hh:02}:{mm:02}:{ss:02}Z")
}

/// Year, month, day, hour, minute, second (UTC) of a Unix time.
fn utc_fields(unix_seconds: i64) -> (i64, u32, u32, i64, i64, i64) {
    let days = unix_seconds.div_euclid(86_400);
    let secs = unix_seconds.rem_euclid(86_400);
    let (y, m, d) = civil_from_days(days);
    (y, m, d, secs / 3600, (secs % 3600) / 60, secs % 60)
}

/// Proleptic Gregorian (year, month, day) of a day count since 1970-01-01.
fn civil_from_days(days: i64) -> (i64, u32, u32) {
    let z = days + 719_468;
    let era = z.div_euclid(146_097);
    let doe = z.rem_euclid(146_097); // day of era, 0..=146096
    let yoe = (doe - doe / 1460 + doe / 36_524 - doe / 146_096) / 365; // year of era
    let doy = doe - (365 * yoe + yoe / 4 - yoe / 100); // day of year, March-based
    let mp = (5 * doy + 2) / 153;
    let d = (doy - (153 * mp + 2) / 5 + 1) as u32;
    let m = if mp < 10 { mp + 3 } else { mp - 9 } as u32;
    let y = yoe + era * 400 + i64::from(m <= 2);
    (y, m, d)
}

fn sanitize(name: &str) -> String {
    let cleaned: String = name
        .chars()
        .map(|c| {
            if c == '.' || c == '/' || c == '\\' || c.is_whitespace() || c.is_control() {
                '-'
            } else {
                c
            }
        })
        .collect();
    if cleaned.is_empty() {
        "scenario".to_string()
    } else {
        cleaned
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_standards_example_timestamp() {
        // OSI 3.8 §2.2.6.2 example: 20210818T150542Z. Unix time by hand:
        // 2021-08-18 is day 18857 since 1970-01-01 (51 years = 18628 days incl. 13 leap
        // days, + 229 days from Jan 1 to Aug 18 in a common year: 31+28+31+30+31+30+31+17),
        // 18857 * 86400 + 15*3600 + 5*60 + 42 = 1_629_299_142.
        assert_eq!(utc_basic_timestamp(1_629_299_142), "20210818T150542Z");
        assert_eq!(
            utc_extended_timestamp(1_629_299_142),
            "2021-08-18T15:05:42Z"
        );
    }

    #[test]
    fn leap_day_and_epoch() {
        assert_eq!(utc_basic_timestamp(0), "19700101T000000Z");
        assert_eq!(utc_extended_timestamp(0), "1970-01-01T00:00:00Z");
        // 2024-02-29 00:00:00 = day 19782 (54 years = 19723 days incl. 13 leap days, + 59).
        assert_eq!(utc_basic_timestamp(19_782 * 86_400), "20240229T000000Z");
    }

    #[test]
    fn name_follows_the_convention() {
        let name = trace_file_name(1_629_299_142, "3.8.0", "0.13.5", 1523, "cut in.v2", "osi");
        assert_eq!(name, "20210818T150542Z_gt_380_0135_1523_cut-in-v2.osi");
        let empty = trace_file_name(0, "3.8.0", "0.13.5", 0, "", "mcap");
        assert_eq!(empty, "19700101T000000Z_gt_380_0135_0_scenario.mcap");
    }
}
