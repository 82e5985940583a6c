//! Sinks that record a run as it happens: [`EntityCatalog`] keeps what the run manifest needs
//! of every entity that appears (box, kind, colour, trailer), and [`Recorder`] keeps the
//! trajectory CSV and the event log in memory, written by the engine's own writers, so that
//! a replay of a scenario run here reads exactly what `oscsim run` would have written.

use engine::output::{CsvWriter, EntityFrame, JsonlWriter};
use engine::runtime::EntityKind;
use engine::{EventRecord, EventSink, Frame, FrameSink};

use crate::manifest::EntityInfo;

/// The XSD name of an entity kind.
fn kind_name(kind: EntityKind) -> &'static str {
    match kind {
        EntityKind::Vehicle => "vehicle",
        EntityKind::Pedestrian => "pedestrian",
        EntityKind::MiscObject => "miscObject",
        EntityKind::External => "external",
    }
}

/// The manifest entry of an entity as a frame shows it.
fn info(e: &EntityFrame<'_>) -> EntityInfo {
    let b = e.bounding_box;
    let c = b.center();
    EntityInfo {
        id: e.id,
        name: e.name.to_owned(),
        kind: kind_name(e.kind).to_owned(),
        category: e
            .vehicle_category
            .map(|c| c.as_str())
            .or(e.pedestrian_category.map(|c| c.as_str()))
            .or(e.misc_object_category.map(|c| c.as_str()))
            .map(str::to_owned),
        color: e.color.map(|c| c.rgb()),
        box_center: [c.x, c.y, c.z],
        box_size: [b.length(), b.width(), b.height()],
        trailer: e.trailer,
        controllers: Vec::new(),
    }
}

/// Every entity seen in the frames, by id; the first frame that shows an entity gives its
/// box and kind, a later frame only adds a trailer link made during the run.
#[derive(Debug, Default)]
pub struct EntityCatalog {
    /// By id: the engine's ids index its entity store, so they are dense (a vector instead of
    /// a map: this runs for every entity of every frame of a `--csv` run).
    entities: Vec<Option<EntityInfo>>,
}

impl EntityCatalog {
    /// An empty catalog.
    pub fn new() -> Self {
        Self::default()
    }

    /// The entities seen, by id.
    pub fn into_entities(self) -> Vec<EntityInfo> {
        self.entities.into_iter().flatten().collect()
    }
}

impl FrameSink for EntityCatalog {
    fn frame(&mut self, frame: &Frame<'_>) -> Result<(), engine::SinkError> {
        for e in frame.objects() {
            let i = e.id as usize;
            if i >= self.entities.len() {
                self.entities.resize(i + 1, None);
            }
            let entry = self.entities[i].get_or_insert_with(|| info(&e));
            if entry.trailer.is_none() {
                entry.trailer = e.trailer;
            }
        }
        Ok(())
    }
}

/// Records a run in memory: the CSV `oscsim run --csv` would write, and the entity catalog.
#[derive(Debug)]
pub struct Recorder {
    csv: CsvWriter<Vec<u8>>,
    catalog: EntityCatalog,
}

impl Default for Recorder {
    fn default() -> Self {
        Recorder {
            csv: CsvWriter::new(Vec::new()),
            catalog: EntityCatalog::new(),
        }
    }
}

impl Recorder {
    /// An empty recorder.
    pub fn new() -> Self {
        Self::default()
    }

    /// The CSV text and the entities seen.
    pub fn into_parts(self) -> (Vec<u8>, Vec<EntityInfo>) {
        (self.csv.into_inner(), self.catalog.into_entities())
    }
}

impl FrameSink for Recorder {
    fn frame(&mut self, frame: &Frame<'_>) -> Result<(), engine::SinkError> {
        self.csv.frame(frame)?;
        self.catalog.frame(frame)
    }
}

/// Records the event log in memory, as `oscsim run --events` would write it.
#[derive(Debug)]
pub struct EventRecorder(JsonlWriter<Vec<u8>>);

impl Default for EventRecorder {
    fn default() -> Self {
        EventRecorder(JsonlWriter::new(Vec::new()))
    }
}

impl EventRecorder {
    /// An empty recorder.
    pub fn new() -> Self {
        Self::default()
    }

    /// The event log text.
    pub fn into_inner(self) -> Vec<u8> {
        self.0.into_inner()
    }
}

impl EventSink for EventRecorder {
    fn event(&mut self, record: &EventRecord) -> Result<(), engine::SinkError> {
        self.0.event(record)
    }
}
