//! What `oscsim run` records for the replay: with `--csv`, the run manifest `NAME.run.json`
//! beside the CSV (entity boxes, kinds, colours, trailers, road network, the conditions'
//! measured quantities, action actors); with `--html`, the replay page, from the run kept in
//! memory. Only the page needs the run in memory: for the manifest alone the frames feed the
//! entity catalog, so the memory of a `--csv` run stays flat however long it runs (issue 17).

use std::cell::RefCell;
use std::path::{Path, PathBuf};
use std::rc::Rc;

use engine::{EngineConfig, EventRecord, EventSink, Frame, FrameSink};
use replay::manifest::EntityInfo;
use replay::recorder::{EntityCatalog, EventRecorder, Recorder};
use replay::RunManifest;

/// `oscsim run`'s replay flags.
#[derive(clap::Args, Debug)]
pub struct ReplayArgs {
    /// Also write the replay page of the run here (one self-contained HTML file).
    #[arg(long, value_name = "FILE.html")]
    html: Option<PathBuf>,
}

/// The run's recording, shared between the sinks the engine feeds and the end of the run.
struct Shared {
    frames: FrameRecord,
    /// The event log, for the page only.
    events: Option<EventRecorder>,
}

/// What the frames feed: the whole run for the page, else the catalog the manifest needs.
enum FrameRecord {
    Run(Recorder),
    Catalog(EntityCatalog),
}

impl FrameRecord {
    /// The CSV text (empty without the page) and the entities seen.
    fn into_parts(self) -> (Vec<u8>, Vec<EntityInfo>) {
        match self {
            FrameRecord::Run(r) => r.into_parts(),
            FrameRecord::Catalog(c) => (Vec::new(), c.into_entities()),
        }
    }
}

/// Records the run when the manifest or the page is wanted.
pub struct RunRecord {
    shared: Option<Rc<RefCell<Shared>>>,
    html: Option<PathBuf>,
}

/// A frame sink that feeds the shared recorder.
struct Frames(Rc<RefCell<Shared>>);

impl FrameSink for Frames {
    fn frame(&mut self, frame: &Frame<'_>) -> Result<(), engine::SinkError> {
        match &mut self.0.borrow_mut().frames {
            FrameRecord::Run(r) => r.frame(frame),
            FrameRecord::Catalog(c) => c.frame(frame),
        }
    }
}

/// An event sink that feeds the shared recorder.
pub struct Events(Rc<RefCell<Shared>>);

impl EventSink for Events {
    fn event(&mut self, record: &EventRecord) -> Result<(), engine::SinkError> {
        match &mut self.0.borrow_mut().events {
            Some(events) => events.event(record),
            None => Ok(()),
        }
    }
}

impl RunRecord {
    /// Records when `args` asks for a page or the run writes a CSV (its manifest).
    pub fn new(args: &ReplayArgs, csv: Option<&Path>) -> Self {
        let page = args.html.is_some();
        let shared = (page || csv.is_some()).then(|| {
            Rc::new(RefCell::new(Shared {
                frames: if page {
                    FrameRecord::Run(Recorder::new())
                } else {
                    FrameRecord::Catalog(EntityCatalog::new())
                },
                events: page.then(EventRecorder::default),
            }))
        });
        RunRecord {
            shared,
            html: args.html.clone(),
        }
    }

    /// The frame sink to add to the run's sinks, if recording.
    pub fn frame_sink(&self) -> Option<Box<dyn FrameSink>> {
        self.shared
            .as_ref()
            .map(|s| Box::new(Frames(Rc::clone(s))) as Box<dyn FrameSink>)
    }

    /// The event sink that must see every record, if recording.
    pub fn event_sink(&self) -> Option<Events> {
        self.shared.as_ref().map(|s| Events(Rc::clone(s)))
    }

    /// After the run: writes the manifest beside `csv` and the page.
    pub fn finish(
        self,
        loaded: &load::Loaded,
        scenario_path: &Path,
        params: &[(String, String)],
        config: &EngineConfig,
        csv: Option<&Path>,
        events: Option<&Path>,
    ) -> anyhow::Result<()> {
        let Some(shared) = self.shared else {
            return Ok(());
        };
        let shared = Rc::try_unwrap(shared)
            .map_err(|_| anyhow::anyhow!("the run's sinks are still alive"))?
            .into_inner();
        let (csv_text, entities) = shared.frames.into_parts();
        let folder = |p: &Path| p.parent().unwrap_or(Path::new("")).to_owned();
        if let Some(csv) = csv {
            let dir = folder(csv);
            let mut m = replay::manifest_for(
                loaded,
                scenario_path,
                params,
                config,
                entities.clone(),
                &dir,
            );
            m.trajectories = csv.file_name().map(PathBuf::from);
            m.events = events.map(|e| replay::manifest::relative_to(e, &dir));
            m.write(&RunManifest::beside(csv))?;
        }
        if let Some(html) = self.html {
            let run = replay::Run::from_memory(
                loaded,
                scenario_path,
                params,
                config,
                (&csv_text, entities),
                &shared.events.unwrap_or_default().into_inner(),
            )?;
            replay::html::write(&run, &html)?;
        }
        Ok(())
    }
}
