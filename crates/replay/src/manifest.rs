//! The run manifest: what `oscsim run` knows of a run beyond the trajectory CSV and the event
//! log, written beside the CSV as `NAME.run.json` (CSV `NAME.csv`). The CSV keeps its
//! esmini-compatible layout, so entity dimensions, kinds, colours and trailer links, the road
//! network, the distances the scenario's conditions measure and the actors of each action
//! travel here. Paths are relative to the manifest's folder where possible, so a folder of
//! outputs can be moved with its inputs, and so that identical runs write identical manifests.

use std::path::{Component, Path, PathBuf};

use serde::{Deserialize, Serialize};

use crate::error::{Error, Result};

/// The format tag of the manifest's `format` field.
pub const FORMAT: &str = "oscsim-run/1";

/// A run manifest (`NAME.run.json`).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct RunManifest {
    /// Always [`FORMAT`].
    pub format: String,
    /// The scenario that ran, relative to the manifest's folder (or absolute).
    pub scenario: Option<PathBuf>,
    /// The road network (`.xodr`), relative to the manifest's folder (or absolute); `None`
    /// when the scenario names no LogicFile.
    pub road_network: Option<PathBuf>,
    /// `--param` overrides as (name, value).
    pub parameters: Vec<(String, String)>,
    /// Step length (s).
    pub dt: f64,
    /// Seed of the random streams.
    pub seed: u64,
    /// The trajectory CSV, relative to the manifest's folder.
    pub trajectories: Option<PathBuf>,
    /// The event log (JSON lines), relative to the manifest's folder.
    pub events: Option<PathBuf>,
    /// Every entity that appeared in the run, by id.
    pub entities: Vec<EntityInfo>,
    /// The entity-to-entity quantities the scenario's conditions measure.
    pub measures: Vec<MeasureSpec>,
    /// Actions and the entities they act on (Init actions and the ManeuverGroups' actors).
    pub actions: Vec<ActionActors>,
    /// The paths of an OpenSCENARIO DSL scenario's phases (`do`, `do.cut_in`, …; the Acts
    /// the event log names), children before their composition; absent for XML.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub phases: Vec<String>,
}

/// What does not change of an entity through a run (OpenSCENARIO 1.3 `ScenarioObject`).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct EntityInfo {
    /// Id, as in the CSV's `id` column.
    pub id: u32,
    /// Name.
    pub name: String,
    /// `vehicle`, `pedestrian`, `miscObject` or `external`.
    pub kind: String,
    /// The XSD category of its kind: `VehicleCategory` (e.g. `car`), `PedestrianCategory`
    /// (`pedestrian`, `animal`, `wheelchair`) or `MiscObjectCategory` (e.g. `barrier`).
    pub category: Option<String>,
    /// RGB colour, when the scenario gives one.
    pub color: Option<[u8; 3]>,
    /// Bounding-box centre relative to the reference point (m), x forward, y left, z up.
    pub box_center: [f64; 3],
    /// Bounding-box length, width, height (m).
    pub box_size: [f64; 3],
    /// Id of the trailer this entity tows, when it tows one.
    pub trailer: Option<u32>,
    /// The ObjectControllers the scenario assigns (names; empty: the default controller).
    pub controllers: Vec<String>,
}

/// One quantity a condition measures between two entities (OpenSCENARIO 1.3 §7.6:
/// TimeHeadwayCondition, TimeToCollisionCondition, RelativeDistanceCondition).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct MeasureSpec {
    /// The condition's name.
    pub condition: String,
    /// `timeHeadway`, `timeToCollision` or `relativeDistance`.
    pub quantity: String,
    /// The triggering entity (the one that measures).
    pub entity: String,
    /// The reference entity.
    pub reference: String,
    /// `freespace`.
    pub freespace: bool,
    /// `coordinateSystem` (`entity` when absent).
    pub coordinate_system: String,
    /// `relativeDistanceType` (`euclidianDistance` when absent).
    pub relative_distance_type: String,
    /// The rule, e.g. `greaterThan`.
    pub rule: String,
    /// The threshold (s or m).
    pub value: f64,
}

/// The entities an action acts on.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct ActionActors {
    /// The action's element name as the event log writes it (`Init Ego TeleportAction` for an
    /// Init action).
    pub name: String,
    /// The action's kind, e.g. `LaneChangeAction`.
    pub kind: String,
    /// The actors' names.
    pub actors: Vec<String>,
}

impl RunManifest {
    /// The manifest beside trajectory CSV `csv`: `NAME.run.json` for `NAME.csv`.
    pub fn beside(csv: &Path) -> PathBuf {
        let stem = csv.file_stem().unwrap_or_default().to_string_lossy();
        csv.with_file_name(format!("{stem}.run.json"))
    }

    /// Reads a manifest.
    pub fn read(path: &Path) -> Result<RunManifest> {
        let text = std::fs::read_to_string(path).map_err(|e| Error::io("cannot read", path, e))?;
        let manifest: RunManifest = serde_json::from_str(&text).map_err(|e| {
            Error::invalid(path, e.line(), e.column(), "a run manifest", e.to_string())
        })?;
        if manifest.format != FORMAT {
            return Err(Error::invalid(
                path,
                1,
                1,
                format!("format \"{FORMAT}\""),
                format!("\"{}\"", manifest.format),
            ));
        }
        Ok(manifest)
    }

    /// Writes the manifest as pretty JSON with a final newline.
    pub fn write(&self, path: &Path) -> Result<()> {
        // Serializing plain structs of strings and numbers cannot fail (no maps with non-string
        // keys); a NaN would become null, which the reader then refuses.
        let mut text = serde_json::to_string_pretty(self).unwrap_or_default();
        text.push('\n');
        std::fs::write(path, text).map_err(|e| Error::io("cannot write", path, e))
    }

    /// `path` (as written in the manifest) resolved against the manifest at `manifest`.
    pub fn resolve(manifest: &Path, path: &Path) -> PathBuf {
        if path.is_absolute() {
            path.to_owned()
        } else {
            manifest.parent().unwrap_or(Path::new("")).join(path)
        }
    }
}

/// `target` relative to folder `base`, both made absolute against the working directory;
/// absolute `target` when no relative path joins them (another drive).
pub fn relative_to(target: &Path, base: &Path) -> PathBuf {
    let absolute = |p: &Path| {
        let p = if p.is_absolute() {
            p.to_owned()
        } else {
            std::env::current_dir().unwrap_or_default().join(p)
        };
        normalize(&p)
    };
    let (target, base) = (absolute(target), absolute(base));
    let (t, b): (Vec<_>, Vec<_>) = (target.components().collect(), base.components().collect());
    if t.first() != b.first() {
        return target;
    }
    let common = t.iter().zip(&b).take_while(|(x, y)| x == y).count();
    let mut out = PathBuf::new();
    for _ in common..b.len() {
        out.push("..");
    }
    for c in &t[common..] {
        out.push(c.as_os_str());
    }
    out
}

/// `path` without `.` and with `..` applied lexically.
fn normalize(path: &Path) -> PathBuf {
    let mut out = PathBuf::new();
    for c in path.components() {
        match c {
            Component::CurDir => {}
            Component::ParentDir => {
                out.pop();
            }
            other => out.push(other.as_os_str()),
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn relative_paths_walk_up_to_the_common_folder() {
        assert_eq!(
            relative_to(Path::new("/a/b/c.xosc"), Path::new("/a/out")),
            PathBuf::from("../b/c.xosc")
        );
        assert_eq!(
            relative_to(Path::new("/a/./x/../b/c.xosc"), Path::new("/a/b")),
            PathBuf::from("c.xosc")
        );
    }

    #[test]
    fn the_manifest_sits_beside_the_csv() {
        assert_eq!(
            RunManifest::beside(Path::new("out/cut_in.csv")),
            PathBuf::from("out/cut_in.run.json")
        );
    }
}
