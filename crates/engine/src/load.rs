//! The loading layer: the one place the engine reads files. A scenario (OpenSCENARIO 1.3 XML,
//! with its catalogs, §9.4) is read by the `scenario` crate; the road network its
//! `RoadNetwork/LogicFile` names (ASAM OpenDRIVE) is read here, once, into an
//! `Arc<RoadNetwork>` that every engine built on it shares ([`Engine::new`]).
//!
//! [`Engine::load`] is the convenience for one run: scenario, road network, engine.
//! [`RoadNetworks`] keeps the networks already read, by file, for batches of scenarios that
//! share roads. A batch of variants of one scenario loads it once and derives each variant
//! with [`Scenario::with_parameters`], which reads no file its first load read; a variant whose
//! parameters name another road file gets that road's network from [`RoadNetworks`]:
//!
//! ```no_run
//! use std::path::Path;
//! use engine::{load, Engine, EngineConfig};
//!
//! let base = scenario::Scenario::load(Path::new("cut-in.xosc"))?;
//! let network = load::road_network(&base)?;
//! for speed in [20, 25, 30] {
//!     let variant = base.with_parameters(&[("EgoSpeed".into(), speed.to_string())])?;
//!     let mut engine = Engine::new(&variant, network.clone(), EngineConfig::default())?;
//!     engine.run(&mut (), &mut ())?;
//! }
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

use std::collections::HashMap;
use std::path::{Path, PathBuf};
use std::sync::Arc;

use opendrive::RoadNetwork;
use scenario::Scenario;

use crate::runtime::{Engine, EngineConfig};
use crate::Error;

/// The road network of a scenario that names none: no roads (entities then move in the
/// world frame only).
const EMPTY_NETWORK: &str = r#"<OpenDRIVE><header revMajor="1" revMinor="6"/></OpenDRIVE>"#;

/// Reads the road network `scenario` names (`RoadNetwork/LogicFile`), or gives the empty
/// network when it names none.
pub fn road_network(scenario: &Scenario) -> Result<Arc<RoadNetwork>, opendrive::Error> {
    let loaded = match &scenario.road_network.logic_file {
        Some(path) => RoadNetwork::from_file(path),
        None => RoadNetwork::from_str(EMPTY_NETWORK, &scenario.path),
    };
    loaded.map(Arc::new)
}

/// Road networks read so far, by the path of their file: the scenarios of a batch that name
/// the same `.xodr` share one network, read once.
#[derive(Debug, Default)]
pub struct RoadNetworks {
    by_file: HashMap<PathBuf, Arc<RoadNetwork>>,
}

impl RoadNetworks {
    /// None read yet.
    pub fn new() -> Self {
        Self::default()
    }

    /// The road network `scenario` names: the one read before for the same file (the path
    /// as the scenario resolved it), else read now and kept.
    pub fn get(&mut self, scenario: &Scenario) -> Result<Arc<RoadNetwork>, Error> {
        let Some(path) = &scenario.road_network.logic_file else {
            return Ok(road_network(scenario)?);
        };
        if let Some(network) = self.by_file.get(path) {
            return Ok(network.clone());
        }
        let network = road_network(scenario)?;
        self.by_file.insert(path.clone(), network.clone());
        Ok(network)
    }

    /// Keeps `network`, read elsewhere, as the one of the file `scenario` names (nothing for
    /// a scenario that names none).
    pub fn keep(&mut self, scenario: &Scenario, network: Arc<RoadNetwork>) {
        if let Some(path) = &scenario.road_network.logic_file {
            self.by_file.insert(path.clone(), network);
        }
    }

    /// How many networks have been read.
    pub fn len(&self) -> usize {
        self.by_file.len()
    }

    /// Whether none has been read.
    pub fn is_empty(&self) -> bool {
        self.by_file.is_empty()
    }
}

impl Engine {
    /// Loads the scenario at `path` with global parameter overrides `params` (name, value),
    /// reads the road network it names and builds the engine: [`Scenario::load_with_parameters`],
    /// [`road_network`], [`Engine::new`].
    pub fn load(
        path: &Path,
        params: &[(String, String)],
        config: EngineConfig,
    ) -> Result<Engine, Error> {
        let scenario = Scenario::load_with_parameters(path, params)?;
        let network = road_network(&scenario)?;
        Engine::new(&scenario, network, config)
    }
}
