//! [`RoadNetwork`]: a loaded `.xodr` file (OpenDRIVE 1.8, `<OpenDRIVE>` root element) with its id
//! tables and spatial index, and the loaders.

use std::path::Path;

use rustc_hash::FxHashMap;

use crate::error::{Error, ErrorKind};
use crate::handles::{JunctionHandle, LaneGraph, RoadHandle, Topology};
use crate::model::{Controller, Header, Junction, Road};
use crate::parse::{load, Loaded};
use crate::road::SpatialIndex;

/// A loaded OpenDRIVE road network. Immutable after loading; all queries take `&self`.
#[derive(Debug, Clone)]
pub struct RoadNetwork {
    pub(crate) header: Header,
    pub(crate) roads: Vec<Road>,
    pub(crate) road_index: FxHashMap<String, usize>,
    pub(crate) junctions: Vec<Junction>,
    pub(crate) junction_index: FxHashMap<String, usize>,
    pub(crate) controllers: Vec<Controller>,
    pub(crate) topology: Topology,
    /// The lane graph's edges, from `topology` and the lane links (`handles::LaneGraph`).
    pub(crate) lane_graph: LaneGraph,
    pub(crate) spatial: SpatialIndex,
    pub(crate) warnings: Vec<Error>,
}

impl RoadNetwork {
    /// Reads and parses an `.xodr` file.
    pub fn from_file(path: &Path) -> Result<Self, Error> {
        let text = std::fs::read_to_string(path)
            .map_err(|e| Error::in_file(ErrorKind::Io(e.to_string()), path))?;
        Self::from_str(&text, path)
    }

    /// Parses `.xodr` text; `path` is used in error messages only.
    #[allow(clippy::should_implement_trait)] // FromStr cannot carry the path for messages.
    pub fn from_str(text: &str, path: &Path) -> Result<Self, Error> {
        let Loaded {
            header,
            roads,
            road_index,
            junctions,
            junction_index,
            controllers,
            warnings,
        } = load(text, path)?;
        let spatial = SpatialIndex::build(&roads);
        let topology = Topology::build(
            &roads,
            &junctions,
            |id| road_index.get(id).map(|&i| i as u32),
            |id| junction_index.get(id).map(|&i| i as u32),
        );
        let mut network = Self {
            header,
            roads,
            road_index,
            junctions,
            junction_index,
            controllers,
            topology,
            lane_graph: LaneGraph::default(),
            spatial,
            warnings,
        };
        network.lane_graph = network.build_lane_graph();
        Ok(network)
    }

    /// The signal controllers (`<controller>`, OpenDRIVE 1.8 §14), in file order.
    pub fn controllers(&self) -> &[Controller] {
        &self.controllers
    }

    /// The controller with id `id`, if any (first of that id).
    pub fn controller(&self, id: &str) -> Option<&Controller> {
        self.controllers.iter().find(|c| c.id == id)
    }

    /// Problems the loader tolerated, each with file and position: junction lane links that
    /// name a lane the road does not have (the lane graph ignores them), and plan-view
    /// geometries that do not start where the previous one ends.
    pub fn warnings(&self) -> &[Error] {
        &self.warnings
    }

    /// `<header>`.
    pub fn header(&self) -> &Header {
        &self.header
    }

    /// All roads, in file order.
    pub fn roads(&self) -> &[Road] {
        &self.roads
    }

    /// The road with this id.
    pub fn road(&self, id: &str) -> Option<&Road> {
        self.road_index.get(id).map(|&i| &self.roads[i])
    }

    /// All junctions, in file order.
    pub fn junctions(&self) -> &[Junction] {
        &self.junctions
    }

    /// The junction with this id.
    pub fn junction(&self, id: &str) -> Option<&Junction> {
        self.junction_index.get(id).map(|&i| &self.junctions[i])
    }

    /// The handle of the road with this id (one hash of the id; keep the handle).
    pub fn road_handle(&self, id: &str) -> Option<RoadHandle> {
        self.road_index.get(id).map(|&i| RoadHandle(i as u32))
    }

    /// The road of a handle this network gave.
    ///
    /// # Panics
    /// If the handle is of another, larger network.
    #[inline]
    pub fn road_at(&self, h: RoadHandle) -> &Road {
        &self.roads[h.index()]
    }

    /// The handle of the junction with this id.
    pub fn junction_handle(&self, id: &str) -> Option<JunctionHandle> {
        self.junction_index
            .get(id)
            .map(|&i| JunctionHandle(i as u32))
    }

    /// The junction of a handle this network gave.
    ///
    /// # Panics
    /// If the handle is of another, larger network.
    #[inline]
    pub fn junction_at(&self, h: JunctionHandle) -> &Junction {
        &self.junctions[h.index()]
    }

    /// The junction road `h` belongs to (`road/@junction`), if any.
    #[inline]
    pub fn road_junction(&self, h: RoadHandle) -> Option<JunctionHandle> {
        self.topology.junction_of[h.index()].map(JunctionHandle)
    }

    /// The road with this id, or a [`ErrorKind::NoSuchRoad`] error.
    pub(crate) fn road_or_err(&self, id: &str) -> Result<(usize, &Road), Error> {
        self.road_index
            .get(id)
            .map(|&i| (i, &self.roads[i]))
            .ok_or_else(|| Error::new(ErrorKind::NoSuchRoad(id.to_string())))
    }

    /// Axis-aligned bounding box of all road surfaces: (min x, min y, max x, max y).
    pub fn bounding_box(&self) -> Option<[f64; 4]> {
        self.spatial.bounds()
    }
}
