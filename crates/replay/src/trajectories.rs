//! Reads the trajectory CSV that `oscsim run --csv` writes (and esmini's reference files,
//! which share its layout): header `time,id,name,x,y,z,h,p,r,roadId,laneId,offset,t,s,speed`,
//! one row per placed entity per frame, rows of a frame together, frames in time order.
//! Names are quoted as RFC 4180 says when they hold a comma or a quote.
//!
//! Written by hand: one fixed layout of numbers; a CSV crate would add only the quoting,
//! which `field` below does in a few lines.

use std::path::Path;

use crate::error::{Error, Result};

/// The columns, in order.
pub const COLUMNS: [&str; 15] = [
    "time", "id", "name", "x", "y", "z", "h", "p", "r", "roadId", "laneId", "offset", "t", "s",
    "speed",
];

/// One entity in one frame, as the CSV row gives it.
#[derive(Debug, Clone, PartialEq)]
pub struct Sample {
    /// Index of the frame in [`Trajectories::times`].
    pub frame: u32,
    /// World pose of the reference point: x, y, z (m), heading, pitch, roll (rad).
    pub pose: [f64; 6],
    /// Road id, lane id, lane offset (m), t (m), s (m); `None` off the road.
    pub road: Option<RoadSample>,
    /// Signed speed (m/s).
    pub speed: f64,
}

/// The road columns of a row.
#[derive(Debug, Clone, PartialEq)]
pub struct RoadSample {
    /// `roadId`.
    pub road_id: String,
    /// `laneId`.
    pub lane_id: i32,
    /// `offset` from the lane centre (m).
    pub offset: f64,
    /// `t` (m).
    pub t: f64,
    /// `s` (m).
    pub s: f64,
}

/// The samples of one entity, in frame order.
#[derive(Debug, Clone, PartialEq)]
pub struct Track {
    /// The `id` column.
    pub id: u32,
    /// The `name` column.
    pub name: String,
    /// Its rows.
    pub samples: Vec<Sample>,
}

/// A whole trajectory file.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Trajectories {
    /// Time of each frame (s).
    pub times: Vec<f64>,
    /// One track per id, by id.
    pub tracks: Vec<Track>,
}

/// Splits one CSV line into fields (RFC 4180 quotes); `None` for an unterminated quote.
fn fields(line: &str) -> Option<Vec<String>> {
    let mut out = Vec::with_capacity(COLUMNS.len());
    let mut chars = line.chars().peekable();
    loop {
        let mut field = String::new();
        if chars.peek() == Some(&'"') {
            chars.next();
            loop {
                match chars.next()? {
                    '"' if chars.peek() == Some(&'"') => {
                        chars.next();
                        field.push('"');
                    }
                    '"' => break,
                    c => field.push(c),
                }
            }
        }
        for c in chars.by_ref() {
            if c == ',' {
                out.push(field);
                field = String::new();
                break;
            }
            field.push(c);
        }
        if chars.peek().is_none() {
            out.push(field);
            return Some(out);
        }
    }
}

impl Trajectories {
    /// Reads CSV `text`; `path` names the file in errors.
    pub fn parse(text: &str, path: &Path) -> Result<Trajectories> {
        let mut lines = text.lines().enumerate();
        let header = lines.next().map(|(_, l)| l.trim_end_matches('\r'));
        if header != Some(COLUMNS.join(",").as_str()) {
            return Err(Error::invalid(
                path,
                1,
                1,
                format!("the header {}", COLUMNS.join(",")),
                format!("'{}'", header.unwrap_or("")),
            ));
        }
        let mut out = Trajectories::default();
        let mut by_id: std::collections::BTreeMap<u32, Track> = Default::default();
        let mut last_time = f64::NEG_INFINITY;
        for (i, line) in lines {
            let line = line.trim_end_matches('\r');
            if line.is_empty() {
                continue;
            }
            let row = i + 1;
            let f = fields(line)
                .filter(|f| f.len() == COLUMNS.len())
                .ok_or_else(|| {
                    Error::invalid(
                        path,
                        row,
                        1,
                        "15 comma-separated fields",
                        format!("'{line}'"),
                    )
                })?;
            // 1-based column of field k: the characters before it plus one.
            let col = |k: usize| f[..k].iter().map(|s| s.chars().count() + 1).sum::<usize>() + 1;
            let num = |k: usize| -> Result<f64> {
                f[k].trim()
                    .parse::<f64>()
                    .ok()
                    .filter(|v| v.is_finite())
                    .ok_or_else(|| {
                        Error::invalid(
                            path,
                            row,
                            col(k),
                            format!("a finite number for {}", COLUMNS[k]),
                            format!("'{}'", f[k]),
                        )
                    })
            };
            let time = num(0)?;
            let id = f[1].trim().parse::<u32>().map_err(|_| {
                Error::invalid(
                    path,
                    row,
                    col(1),
                    "an entity id (0, 1, …)",
                    format!("'{}'", f[1]),
                )
            })?;
            if time < last_time {
                return Err(Error::invalid(
                    path,
                    row,
                    1,
                    format!("a time >= {last_time:.3} (frames in time order)"),
                    format!("{time}"),
                ));
            }
            if time > last_time {
                out.times.push(time);
                last_time = time;
            }
            let road = if f[9].is_empty() {
                None
            } else {
                let lane_id = f[10].trim().parse::<i32>().map_err(|_| {
                    Error::invalid(path, row, col(10), "a lane id", format!("'{}'", f[10]))
                })?;
                Some(RoadSample {
                    road_id: f[9].clone(),
                    lane_id,
                    offset: num(11)?,
                    t: num(12)?,
                    s: num(13)?,
                })
            };
            let sample = Sample {
                frame: (out.times.len() - 1) as u32,
                pose: [num(3)?, num(4)?, num(5)?, num(6)?, num(7)?, num(8)?],
                road,
                speed: num(14)?,
            };
            let track = by_id.entry(id).or_insert_with(|| Track {
                id,
                name: f[2].clone(),
                samples: Vec::new(),
            });
            if track
                .samples
                .last()
                .is_some_and(|s| s.frame == sample.frame)
            {
                return Err(Error::invalid(
                    path,
                    row,
                    col(1),
                    format!("one row per entity per frame (id {id} at t = {time})"),
                    "a second row",
                ));
            }
            track.samples.push(sample);
        }
        out.tracks = by_id.into_values().collect();
        Ok(out)
    }

    /// Reads the CSV file at `path`.
    pub fn read(path: &Path) -> Result<Trajectories> {
        let text = std::fs::read_to_string(path).map_err(|e| Error::io("cannot read", path, e))?;
        Trajectories::parse(&text, path)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn quoted_names_keep_commas_and_quotes() {
        assert_eq!(
            fields(r#"0.000,0,"a, ""b""",1"#),
            Some(vec![
                "0.000".into(),
                "0".into(),
                r#"a, "b""#.into(),
                "1".into()
            ])
        );
        assert_eq!(fields(r#"0,"open"#), None);
    }

    #[test]
    fn a_bad_number_names_its_row_and_column() {
        let text = format!(
            "{}\n0.000,0,Ego,1.5,oops,0,0,0,0,,,,,,3\n",
            COLUMNS.join(",")
        );
        let err = Trajectories::parse(&text, Path::new("t.csv")).expect_err("y is not a number");
        // "0.000,0,Ego,1.5," is 16 characters: y starts in column 17.
        assert_eq!(
            err.to_string(),
            "expected a finite number for y, found 'oops' at t.csv:2:17"
        );
    }

    #[test]
    fn frames_and_tracks_are_grouped() {
        let text = format!(
            "{}\n0.000,0,A,0,0,0,0,0,0,1,-1,0,-1.5,0,10\n0.000,1,B,5,0,0,0,0,0,,,,,,0\n\
             0.050,0,A,0.5,0,0,0,0,0,1,-1,0,-1.5,0.5,10\n",
            COLUMNS.join(",")
        );
        let t = Trajectories::parse(&text, Path::new("t.csv")).expect("valid");
        assert_eq!(t.times, vec![0.0, 0.05]);
        assert_eq!(t.tracks.len(), 2);
        assert_eq!(t.tracks[0].samples.len(), 2);
        assert_eq!(t.tracks[0].samples[1].frame, 1);
        assert_eq!(t.tracks[1].samples[0].road, None);
    }
}
