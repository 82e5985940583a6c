//! [`RoadNetwork`]: a loaded `.xodr` file (OpenDRIVE 1.8, `<OpenDRIVE>` root element) with its id
//! tables and spatial index, and the loaders.

use std::collections::HashMap;
use std::path::Path;

use crate::error::{Error, ErrorKind};
use crate::model::{Header, Junction, Road};
use crate::parse::{check_references, child, read_header, read_junction, read_road, Ids, Reader};
use crate::query::SpatialIndex;

/// A loaded OpenDRIVE road network. Immutable after loading; all queries take `&self`.
#[derive(Debug, Clone)]
pub struct RoadNetwork {
    pub(crate) header: Header,
    pub(crate) roads: Vec<Road>,
    pub(crate) road_index: HashMap<String, usize>,
    pub(crate) junctions: Vec<Junction>,
    pub(crate) junction_index: HashMap<String, usize>,
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
        let opts = roxmltree::ParsingOptions {
            allow_dtd: true,
            ..Default::default()
        };
        let doc = roxmltree::Document::parse_with_options(text, opts).map_err(|e| {
            let p = e.pos();
            // roxmltree's message ends in " at row:col"; the position is reported once.
            let msg = e.to_string();
            let suffix = format!(" at {}:{}", p.row, p.col);
            let msg = msg.strip_suffix(&suffix).unwrap_or(&msg).to_string();
            Error::at(
                ErrorKind::Xml(msg),
                path,
                crate::error::TextPos {
                    row: p.row,
                    col: p.col,
                },
            )
        })?;
        let r = Reader::new(&doc, path);
        let root = doc.root_element();
        if root.tag_name().name() != "OpenDRIVE" {
            return Err(r.error_at(
                root,
                ErrorKind::NotOpenDrive(root.tag_name().name().to_string()),
            ));
        }
        let header = match child(root, "header") {
            Some(h) => read_header(&r, h)?,
            None => Header::default(),
        };
        let mut roads = Vec::new();
        let mut road_index = HashMap::new();
        let mut warnings = Vec::new();
        for node in root.children().filter(|n| n.has_tag_name("road")) {
            let road = read_road(&r, node, &mut warnings)?;
            if road_index.insert(road.id.clone(), roads.len()).is_some() {
                return Err(r.invalid(node, "id", "a road id not used before", &road.id));
            }
            roads.push(road);
        }
        let mut junctions = Vec::new();
        let mut junction_index = HashMap::new();
        for node in root.children().filter(|n| n.has_tag_name("junction")) {
            let j = read_junction(&r, node)?;
            if junction_index
                .insert(j.id.clone(), junctions.len())
                .is_some()
            {
                return Err(r.invalid(node, "id", "a junction id not used before", &j.id));
            }
            junctions.push(j);
        }
        warnings.extend(check_references(
            &r,
            root,
            &Ids {
                roads: &road_index,
                road_list: &roads,
                junctions: &junction_index,
            },
        )?);
        let spatial = SpatialIndex::build(&roads);
        Ok(Self {
            header,
            roads,
            road_index,
            junctions,
            junction_index,
            spatial,
            warnings,
        })
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
