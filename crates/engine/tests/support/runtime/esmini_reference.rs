//! Readers of esmini 3.6.0's reference runs in the shared corpus
//! (`shared/corpus/reference/esmini/NAME.csv` and `NAME.events.txt`, made with the default
//! controllers at dt 0.05 s; the corpus's `reference/README.md` says how): the CSV rows
//! `time,id,name,x,y,z,h,p,r,roadId,laneId,offset,t,s,speed` and the storyboard transition
//! lines `TIME ELEMENT FROM -> TRANSITION -> TO` (OpenSCENARIO 1.3 §8.2 states and
//! transitions, with esmini's `initState` for elements not yet initialised).
//!
//! Both readers panic with the file and 1-based line of anything they cannot read: the
//! references are part of the corpus, so a bad one is a broken test setup, not a result.

use engine::storyboard::Transition;

use super::corpus;

/// The CSV columns, in the names of the reference header.
const COLUMNS: [&str; 15] = [
    "time", "id", "name", "x", "y", "z", "h", "p", "r", "roadId", "laneId", "offset", "t", "s",
    "speed",
];

/// One entity in one row of a reference CSV. Positions in m, angles in rad, speed in m/s, as
/// esmini prints them (3 decimals).
#[derive(Debug, Clone, PartialEq)]
pub struct RefRow {
    /// Simulation time (s).
    pub time: f64,
    /// esmini's object id.
    pub id: u32,
    /// The entity's name.
    pub name: String,
    /// World x (m).
    pub x: f64,
    /// World y (m).
    pub y: f64,
    /// World z (m).
    pub z: f64,
    /// Heading (rad).
    pub h: f64,
    /// Pitch (rad).
    pub p: f64,
    /// Roll (rad).
    pub r: f64,
    /// OpenDRIVE road id.
    pub road_id: String,
    /// OpenDRIVE lane id.
    pub lane_id: i32,
    /// Lateral offset from the lane's centre (m).
    pub offset: f64,
    /// Lateral road coordinate t (m).
    pub t: f64,
    /// Road coordinate s (m).
    pub s: f64,
    /// Speed (m/s).
    pub speed: f64,
}

/// Every row of esmini's reference run of `scenario` (`reference/esmini/{scenario}.csv`), in
/// file order. Columns are found by their header names.
pub fn esmini_reference(scenario: &str) -> Vec<RefRow> {
    let path = corpus(&format!("reference/esmini/{scenario}.csv"));
    let file = path.display().to_string();
    let text = std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{file}: {e}"));
    parse_reference(&file, &text)
}

/// The rows of reference CSV `text`; `file` names it in the panic messages.
pub fn parse_reference(file: &str, text: &str) -> Vec<RefRow> {
    let mut lines = text.lines();
    let header: Vec<&str> = lines
        .next()
        .unwrap_or_else(|| panic!("{file}:1: expected the header, found an empty file"))
        .split(',')
        .map(str::trim)
        .collect();
    let index = COLUMNS.map(|name| {
        header
            .iter()
            .position(|h| *h == name)
            .unwrap_or_else(|| panic!("{file}:1: expected a column `{name}` in the header"))
    });
    lines
        .enumerate()
        .filter(|(_, line)| !line.trim().is_empty())
        .map(|(n, line)| {
            let row = Fields {
                file,
                // 1-based, the header being line 1.
                line: n + 2,
                values: line.split(',').map(str::trim).collect(),
                index,
            };
            RefRow {
                time: row.get(0),
                id: row.get(1),
                name: row.get(2),
                x: row.get(3),
                y: row.get(4),
                z: row.get(5),
                h: row.get(6),
                p: row.get(7),
                r: row.get(8),
                road_id: row.get(9),
                lane_id: row.get(10),
                offset: row.get(11),
                t: row.get(12),
                s: row.get(13),
                speed: row.get(14),
            }
        })
        .collect()
}

/// The values of one CSV line and where they are.
struct Fields<'a> {
    file: &'a str,
    line: usize,
    values: Vec<&'a str>,
    /// Position in the line of each of [`COLUMNS`].
    index: [usize; 15],
}

impl Fields<'_> {
    /// The value of [`COLUMNS`]`[column]`, read as a `T`.
    fn get<T: std::str::FromStr>(&self, column: usize) -> T {
        let (file, at, name) = (self.file, self.line, COLUMNS[column]);
        let value = self.values.get(self.index[column]).unwrap_or_else(|| {
            panic!("{file}:{at}: expected a value in column `{name}`, found none")
        });
        value.parse().unwrap_or_else(|_| {
            let kind = std::any::type_name::<T>();
            panic!("{file}:{at}: expected {kind} in column `{name}`, found `{value}`")
        })
    }
}

/// One line of a reference transition log: `TIME ELEMENT FROM -> TRANSITION -> TO`.
#[derive(Debug, Clone, PartialEq)]
pub struct RefEvent {
    /// Simulation time of the step (s).
    pub time: f64,
    /// The storyboard element's name (it may contain spaces).
    pub element: String,
    /// The state left, e.g. `standbyState` (esmini also writes `initState`).
    pub from: String,
    /// The transition taken.
    pub transition: Transition,
    /// The state entered, e.g. `runningState`.
    pub to: String,
}

/// Every transition of esmini's reference log of `scenario`
/// (`reference/esmini/{scenario}.events.txt`), in file order.
pub fn esmini_reference_events(scenario: &str) -> Vec<RefEvent> {
    let path = corpus(&format!("reference/esmini/{scenario}.events.txt"));
    let file = path.display().to_string();
    let text = std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{file}: {e}"));
    parse_reference_events(&file, &text)
}

/// The transitions of reference log `text`; `file` names it in the panic messages.
pub fn parse_reference_events(file: &str, text: &str) -> Vec<RefEvent> {
    text.lines()
        .enumerate()
        .filter(|(_, line)| !line.trim().is_empty())
        .map(|(n, line)| {
            let at = n + 1;
            let bad = || -> ! {
                panic!(
                    "{file}:{at}: expected `TIME ELEMENT FROM -> TRANSITION -> TO`, \
                     found `{line}`"
                )
            };
            let (time, rest) = line.split_once(' ').unwrap_or_else(|| bad());
            // The element's name may hold spaces: the five words after it are fixed.
            let words: Vec<&str> = rest.rsplitn(6, ' ').collect();
            let [to, "->", transition, "->", from, element] = words[..] else {
                bad()
            };
            let transition = Transition::ALL
                .into_iter()
                .find(|t| t.as_str() == transition)
                .unwrap_or_else(|| bad());
            RefEvent {
                time: time.parse().unwrap_or_else(|_| bad()),
                element: element.to_owned(),
                from: from.to_owned(),
                transition,
                to: to.to_owned(),
            }
        })
        .collect()
}

/// The time of the first `transition` of storyboard element `element` in `events`.
pub fn first_transition(events: &[RefEvent], element: &str, transition: Transition) -> Option<f64> {
    events
        .iter()
        .find(|e| e.element == element && e.transition == transition)
        .map(|e| e.time)
}
