//! From `.xodr` text to the model: the `<OpenDRIVE>` root, `<header>`, every `<road>`,
//! `<junction>` and `<controller>` in file order, and the reference checks (OpenDRIVE 1.8 §8 file structure).
//!
//! Large files are read in parts, in parallel (rayon): the text is cut before top-level
//! `<road>` / `<junction>` start tags into parts of about [`PART_BYTES`], each part is parsed
//! by roxmltree as the content of a stand-in `<OpenDRIVE>` element and read into roads and
//! junctions, and the parts are joined in file order — the same model as reading the whole
//! file at once, since every road and junction is read from its own element alone. A cut is
//! only trusted when every part parses: a cut inside a comment, a CDATA section or a nested
//! element leaves some part unbalanced, and the file is then read whole. Files with a DTD or
//! namespace declarations on the root are read whole too (both would reach into later parts),
//! and so is any file with an error, a duplicate id, an unresolved reference or a tolerated
//! problem other than plan-view gaps, so that errors and warnings are exactly those of
//! the whole-file reading, positions included (each part maps its positions back to the
//! file's).

use std::path::Path;
use std::sync::Arc;

use rayon::prelude::*;
use roxmltree::{Document, ParsingOptions};
use rustc_hash::FxHashMap;
use source::SourcePos;

use super::{
    check_references, child, read_controller, read_header, read_junction, read_road, Ids, Reader,
};
use crate::error::{Error, ErrorKind};
use crate::model::{Controller, Header, Junction, Road};

/// Files below this size are read whole (bytes).
const SPLIT_THRESHOLD: usize = 8 << 20;
/// Target size of one part (bytes).
const PART_BYTES: usize = 2 << 20;
/// The root element's name.
const ROOT: &str = "OpenDRIVE";

/// What a file holds, read and checked.
pub(crate) struct Loaded {
    pub(crate) header: Header,
    pub(crate) roads: Vec<Road>,
    pub(crate) road_index: FxHashMap<String, usize>,
    pub(crate) junctions: Vec<Junction>,
    pub(crate) junction_index: FxHashMap<String, usize>,
    pub(crate) controllers: Vec<Controller>,
    pub(crate) warnings: Vec<Error>,
}

/// Reads `.xodr` text; `path` is for messages.
pub(crate) fn load(text: &str, path: &Path) -> Result<Loaded, Error> {
    if text.len() >= SPLIT_THRESHOLD {
        if let Some(loaded) = load_in_parts(text, path, PART_BYTES) {
            return Ok(loaded);
        }
    }
    load_whole(text, path)
}

fn options<'a>() -> ParsingOptions<'a> {
    ParsingOptions {
        allow_dtd: true,
        ..Default::default()
    }
}

/// The roxmltree error as this crate's, at its position.
fn xml_error(e: &roxmltree::Error, path: &Path) -> Error {
    let p = e.pos();
    let pos = SourcePos::new(Arc::from(path), p.row, p.col);
    Error::at(
        ErrorKind::Xml(pos.strip_from(&e.to_string()).to_owned()),
        pos,
    )
}

/// Reads the whole file as one document.
fn load_whole(text: &str, path: &Path) -> Result<Loaded, Error> {
    let doc = Document::parse_with_options(text, options()).map_err(|e| xml_error(&e, path))?;
    let r = Reader::new(&doc, path);
    let root = doc.root_element();
    if root.tag_name().name() != ROOT {
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
    let mut road_index = FxHashMap::default();
    let mut warnings = Vec::new();
    for node in root.children().filter(|n| n.has_tag_name("road")) {
        let road = read_road(&r, node, &mut warnings)?;
        if road_index.insert(road.id.clone(), roads.len()).is_some() {
            return Err(r.invalid(node, "id", "a road id not used before", &road.id));
        }
        roads.push(road);
    }
    let mut junctions = Vec::new();
    let mut junction_index = FxHashMap::default();
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
    let controllers = root
        .children()
        .filter(|n| n.has_tag_name("controller"))
        .map(|n| read_controller(&r, n))
        .collect::<Result<Vec<_>, _>>()?;
    warnings.extend(check_references(
        &r,
        root,
        &Ids {
            roads: &road_index,
            road_list: &roads,
            junctions: &junction_index,
        },
    )?);
    Ok(Loaded {
        header,
        roads,
        road_index,
        junctions,
        junction_index,
        controllers,
        warnings,
    })
}

/// One part's roads, junctions, controllers and warnings; `header` only from the first part.
struct Part {
    header: Option<Header>,
    roads: Vec<Road>,
    junctions: Vec<Junction>,
    controllers: Vec<Controller>,
    warnings: Vec<Error>,
}

/// Reads the file in parts; `None` when it must be read whole (see the module doc).
fn load_in_parts(text: &str, path: &Path, part_bytes: usize) -> Option<Loaded> {
    let root_at = text.find(&format!("<{ROOT}"))?;
    if text[..root_at].contains("<!DOCTYPE") {
        return None;
    }
    let cuts = cuts(text, root_at, part_bytes);
    if cuts.len() < 3 {
        return None;
    }
    let parts: Vec<Option<Part>> = cuts
        .windows(2)
        .enumerate()
        .collect::<Vec<_>>()
        .into_par_iter()
        .map(|(k, w)| read_part(text, path, k == 0, w[0], w[1]))
        .collect();
    let mut loaded = Loaded {
        header: Header::default(),
        roads: Vec::new(),
        road_index: FxHashMap::default(),
        junctions: Vec::new(),
        junction_index: FxHashMap::default(),
        controllers: Vec::new(),
        warnings: Vec::new(),
    };
    for part in parts {
        let part = part?;
        if let Some(h) = part.header {
            loaded.header = h;
        }
        loaded.roads.extend(part.roads);
        loaded.junctions.extend(part.junctions);
        loaded.controllers.extend(part.controllers);
        loaded.warnings.extend(part.warnings);
    }
    // Roads first, then junctions, as the whole-file reading orders them.
    for (i, road) in loaded.roads.iter().enumerate() {
        if loaded.road_index.insert(road.id.clone(), i).is_some() {
            return None;
        }
    }
    for (i, j) in loaded.junctions.iter().enumerate() {
        if loaded.junction_index.insert(j.id.clone(), i).is_some() {
            return None;
        }
    }
    references_resolve(&loaded).then_some(loaded)
}

/// Byte offsets where parts start, and the text's end: 0, then before the first top-level
/// `<road` or `<junction` tag at least `part_bytes` after the previous cut.
fn cuts(text: &str, root_at: usize, part_bytes: usize) -> Vec<usize> {
    let bytes = text.as_bytes();
    let mut cuts = vec![0];
    let mut from = root_at + part_bytes;
    while from < text.len() {
        let Some(found) = text[from..].find('<') else {
            break;
        };
        let at = from + found;
        let rest = &bytes[at + 1..];
        let named = |name: &[u8]| {
            rest.starts_with(name)
                && rest
                    .get(name.len())
                    .is_some_and(|b| b.is_ascii_whitespace() || *b == b'>' || *b == b'/')
        };
        if named(b"road") || named(b"junction") {
            cuts.push(at);
            from = at + part_bytes;
        } else {
            from = at + 1;
        }
    }
    cuts.push(text.len());
    cuts
}

/// Parses and reads the part `text[start..end]`; `None` if it does not parse on its own or
/// holds anything the whole-file reading would report otherwise.
fn read_part(text: &str, path: &Path, first: bool, start: usize, end: usize) -> Option<Part> {
    // The part's text in a buffer kept per thread: the pages stay mapped from part to part.
    thread_local!(static BUFFER: std::cell::RefCell<String> = const { std::cell::RefCell::new(String::new()) });
    BUFFER.with_borrow_mut(|buffer| {
        buffer.clear();
        let prefix = if first { 0 } else { ROOT.len() + 2 };
        if !first {
            buffer.extend(["<", ROOT, ">"]);
        }
        buffer.push_str(&text[start..end]);
        if end < text.len() {
            buffer.extend(["</", ROOT, ">"]);
        }
        read_part_text(buffer, text, path, first, start, prefix)
    })
}

/// [`read_part`] on the part's text `doc_text`, which starts at byte `start` of the file
/// after `prefix` bytes put before it.
fn read_part_text(
    doc_text: &str,
    text: &str,
    path: &Path,
    first: bool,
    start: usize,
    prefix: usize,
) -> Option<Part> {
    let doc = Document::parse_with_options(doc_text, options()).ok()?;
    let root = doc.root_element();
    if root.tag_name().name() != ROOT
        || root.tag_name().namespace().is_some()
        || root.namespaces().any(|ns| ns.name() != Some("xml"))
    {
        return None;
    }
    let r = Reader::chunk(text, path, start, prefix);
    let header = match child(root, "header") {
        Some(h) if first => Some(read_header(&r, h).ok()?),
        Some(_) => return None,
        None => None,
    };
    let mut warnings = Vec::new();
    let mut roads = Vec::new();
    for node in root.children().filter(|n| n.has_tag_name("road")) {
        roads.push(read_road(&r, node, &mut warnings).ok()?);
    }
    let mut junctions = Vec::new();
    for node in root.children().filter(|n| n.has_tag_name("junction")) {
        junctions.push(read_junction(&r, node).ok()?);
    }
    let mut controllers = Vec::new();
    for node in root.children().filter(|n| n.has_tag_name("controller")) {
        controllers.push(read_controller(&r, node).ok()?);
    }
    Some(Part {
        header,
        roads,
        junctions,
        controllers,
        warnings,
    })
}

/// Whether every reference of the model resolves and every junction lane link names a lane
/// of its road: what `check_references` checks on the XML, here on the model (with no
/// positions: when this fails the file is read whole for the exact errors and warnings).
fn references_resolve(l: &Loaded) -> bool {
    let road = |id: &str| l.road_index.get(id).map(|&i| &l.roads[i]);
    let has_lane = |road: &Road, id: i32| road.lane_sections.iter().any(|ls| ls.lane(id).is_some());
    let roads_ok = l.roads.iter().all(|r| {
        r.junction
            .as_deref()
            .is_none_or(|j| l.junction_index.contains_key(j))
            && [&r.links.predecessor, &r.links.successor]
                .into_iter()
                .flatten()
                .all(|link| match link.element_type {
                    crate::model::ElementType::Road => road(&link.element_id).is_some(),
                    crate::model::ElementType::Junction => {
                        l.junction_index.contains_key(link.element_id.as_str())
                    }
                })
    });
    roads_ok
        && l.junctions.iter().flat_map(|j| &j.connections).all(|c| {
            match (road(&c.incoming_road), road(&c.connecting_road)) {
                (Some(inc), Some(con)) => c
                    .lane_links
                    .iter()
                    .all(|ll| has_lane(inc, ll.from) && has_lane(con, ll.to)),
                _ => false,
            }
        })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn corpus_file(name: &str) -> (String, std::path::PathBuf) {
        let path = std::path::PathBuf::from(concat!(
            env!("CARGO_MANIFEST_DIR"),
            "/../../../shared/corpus/esmini/xodr/"
        ))
        .join(name);
        let text = std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{e}"));
        (text, path)
    }

    fn same(a: &Loaded, b: &Loaded) {
        assert_eq!(a.header, b.header);
        assert_eq!(a.roads, b.roads);
        assert_eq!(a.junctions, b.junctions);
        assert_eq!(a.road_index, b.road_index);
        assert_eq!(a.junction_index, b.junction_index);
        assert_eq!(
            a.warnings
                .iter()
                .map(ToString::to_string)
                .collect::<Vec<_>>(),
            b.warnings
                .iter()
                .map(ToString::to_string)
                .collect::<Vec<_>>()
        );
    }

    #[test]
    fn parts_read_the_same_model_as_the_whole_file() {
        // multi_intersections.xodr (490 kB, roads and junctions) in parts of about 10 kB:
        // dozens of parts, and the same model as reading the file whole.
        let (text, path) = corpus_file("multi_intersections.xodr");
        let whole = load_whole(&text, &path).unwrap_or_else(|e| panic!("{e}"));
        let cut = cuts(&text, text.find("<OpenDRIVE").unwrap_or(0), 10_000);
        assert!(cut.len() > 20, "{} parts", cut.len() - 1);
        let parts = load_in_parts(&text, &path, 10_000).unwrap_or_else(|| panic!("read whole"));
        same(&parts, &whole);
    }

    #[test]
    fn a_cut_inside_a_comment_reads_the_file_whole() {
        // A comment holding a road start tag right where the first cut falls: the part before
        // it does not parse (unterminated comment), so the file is read whole; the road in the
        // comment is not read.
        let (text, path) = corpus_file("multi_intersections.xodr");
        let at = text.find("<road").unwrap_or_else(|| panic!("no road"));
        let commented = format!(
            "{}<!-- <road id=\"ghost\"> -->\n{}",
            &text[..at],
            &text[at..]
        );
        let part_bytes =
            commented.find("<!--").unwrap_or(0) + 5 - commented.find("<OpenDRIVE").unwrap_or(0);
        assert!(load_in_parts(&commented, &path, part_bytes).is_none());
        let whole = load_whole(&commented, &path).unwrap_or_else(|e| panic!("{e}"));
        assert!(!whole.road_index.contains_key("ghost"));
    }

    #[test]
    fn a_bad_value_in_a_part_gives_the_whole_file_error() {
        // A negative road length in the last road: reading in parts gives up, and `load`
        // reports what the whole-file reading does, with the row and column in the file.
        let (text, path) = corpus_file("multi_intersections.xodr");
        let at = text.rfind("<road ").unwrap_or_else(|| panic!("no road"));
        let len_at = at + text[at..].find("length=\"").unwrap_or(0) + 8;
        let bad = format!("{}-{}", &text[..len_at], &text[len_at..]);
        assert!(load_in_parts(&bad, &path, 10_000).is_none());
        let e = load(&bad, &path).err().unwrap_or_else(|| panic!("loaded"));
        let whole = load_whole(&bad, &path)
            .err()
            .unwrap_or_else(|| panic!("loaded"));
        assert_eq!(e.to_string(), whole.to_string());
        let row = bad[..len_at].matches('\n').count() + 1;
        assert!(e.to_string().contains(&format!(":{row}:")), "{e}");
    }
}
