//! What a simulation keeps for Python while it steps: the trajectories (one row per placed
//! entity per frame, the rows of the trajectory CSV, `engine::output::CsvWriter`, plus world
//! velocity and acceleration) in columns, and the event log as the JSON lines of
//! `engine::output::JsonlWriter` (the same text `oscsim run --events` writes).

use std::fs::File;
use std::io::BufWriter;

use engine::output::{CsvWriter, EventRecord, EventSink, Frame, FrameSink, JsonlWriter};
use osi::sink::StepFrames;

/// The numeric columns, in the order of [`Trajectories::NUMERIC`].
#[derive(Debug, Default)]
pub struct Trajectories {
    /// Frame time (s).
    pub time: Vec<f64>,
    /// Entity index in declaration order.
    pub id: Vec<i64>,
    /// Entity name per row.
    pub name: Vec<String>,
    /// Road id per row, empty off the roads.
    pub road_id: Vec<String>,
    /// Lane id, 0 off the roads.
    pub lane_id: Vec<i64>,
    /// x, y, z, h, p, r, offset, t, s, speed, vx, vy, vz, ax, ay, az, yaw_rate: see
    /// [`Trajectories::NUMERIC`]; NaN for road columns off the roads.
    pub values: [Vec<f64>; 17],
    /// Whether recording is on.
    pub enabled: bool,
}

impl Trajectories {
    /// Names of the columns in `values`: the CSV's, then world-axes velocity and acceleration
    /// and the yaw rate.
    pub const NUMERIC: [&'static str; 17] = [
        "x", "y", "z", "h", "p", "r", "offset", "t", "s", "speed", "vx", "vy", "vz", "ax", "ay",
        "az", "yaw_rate",
    ];

    /// Rows recorded.
    pub fn len(&self) -> usize {
        self.time.len()
    }

    /// Forgets every row.
    pub fn clear(&mut self) {
        let enabled = self.enabled;
        *self = Trajectories {
            enabled,
            ..Trajectories::default()
        };
    }
}

impl FrameSink for Trajectories {
    fn frame(&mut self, frame: &Frame<'_>) -> Result<(), engine::SinkError> {
        if !self.enabled {
            return Ok(());
        }
        for e in frame.objects() {
            let p = e.pose;
            self.time.push(frame.time);
            self.id.push(i64::from(e.id));
            self.name.push(e.name.to_owned());
            let (road, lane, offset, t, s) = match e.road_position {
                Some(rp) => (
                    rp.road_id.clone(),
                    i64::from(rp.lane_id),
                    rp.offset,
                    rp.t,
                    rp.s,
                ),
                None => (String::new(), 0, f64::NAN, f64::NAN, f64::NAN),
            };
            self.road_id.push(road);
            self.lane_id.push(lane);
            let (v, a) = (e.velocity, e.acceleration);
            let row = [
                p.x, p.y, p.z, p.h, p.p, p.r, offset, t, s, e.speed, v.x, v.y, v.z, a.x, a.y, a.z,
                e.yaw_rate,
            ];
            for (column, value) in self.values.iter_mut().zip(row) {
                column.push(value);
            }
        }
        Ok(())
    }
}

/// The event log as JSON lines (each record written by a `JsonlWriter`, which keeps no state
/// between records).
#[derive(Debug, Default)]
pub struct Events {
    /// The lines so far, without line breaks.
    pub lines: Vec<String>,
}

impl EventSink for Events {
    fn event(&mut self, record: &EventRecord) -> Result<(), engine::SinkError> {
        let mut writer = JsonlWriter::new(Vec::new());
        writer.event(record)?;
        let text = String::from_utf8(writer.into_inner())
            .map_err(|e| std::io::Error::new(std::io::ErrorKind::InvalidData, e))?;
        self.lines.extend(text.lines().map(str::to_owned));
        Ok(())
    }
}

/// Everything a step reports to: the trajectories, and the CSV file and the ground truth when
/// asked for.
pub struct Recorders<'a> {
    /// The trajectories.
    pub trajectories: &'a mut Trajectories,
    /// The trajectory CSV file.
    pub csv: Option<&'a mut CsvWriter<BufWriter<File>>>,
    /// The ground truth, if the simulation makes it.
    pub osi: Option<&'a mut StepFrames>,
}

impl FrameSink for Recorders<'_> {
    fn frame(&mut self, frame: &Frame<'_>) -> Result<(), engine::SinkError> {
        self.trajectories.frame(frame)?;
        if let Some(csv) = &mut self.csv {
            csv.frame(frame)?;
        }
        match &mut self.osi {
            Some(osi) => osi.frame(frame),
            None => Ok(()),
        }
    }
}
