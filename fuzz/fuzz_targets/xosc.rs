//! OpenSCENARIO 1.x XML: a scenario with its catalogs and referenced files, all in memory
//! ([`scenario::MemoryFiles`]), loaded and resolved (parameters, expressions, catalog
//! references, entity selections). The input is the scenario text, then any number of
//! further files, each `\0PATH\nCONTENTS` with PATH relative to the scenario's folder's parent
//! (`xosc/Catalogs/Vehicles/cars.xosc`, `xodr/road.xodr`); the scenario itself is
//! `xosc/main.xosc` (NUL never occurs in XML, so splitting never cuts a valid file).
//! A load must not panic or hang, and an error must name a file of the set and a line:column
//! inside that file's text.
#![no_main]

use std::path::{Path, PathBuf};

use libfuzzer_sys::fuzz_target;

mod support;
use scenario::{MemoryFiles, Scenario};

const ROOT: &str = "/fuzz";

fuzz_target!(|data: &[u8]| {
    support::watchdog::start(data);
    let mut parts = data.split(|&b| b == 0);
    let main = parts.next().unwrap_or_default();
    let root = Path::new(ROOT);
    let main_path = root.join("xosc/main.xosc");
    let mut files = MemoryFiles::new();
    let mut texts: Vec<(PathBuf, &[u8])> = vec![(main_path.clone(), main)];
    files.insert(main_path.clone(), main);
    for part in parts {
        let (name, contents) = match part.iter().position(|&b| b == b'\n') {
            Some(i) => (&part[..i], &part[i + 1..]),
            None => (part, &[][..]),
        };
        let Ok(name) = std::str::from_utf8(name) else {
            continue;
        };
        let path = root.join(name.trim());
        files.insert(path.clone(), contents);
        texts.push((path, contents));
    }
    match Scenario::load_with_files(&files, &main_path, &[]) {
        Ok(s) => {
            // Resolved values are printable (Debug walks the whole model).
            let _ = format!("{s:?}");
        }
        Err(e) => {
            let message = e.to_string();
            assert!(!message.is_empty());
            let pos = e.pos();
            assert!(pos.line >= 1 && pos.col >= 1, "{message}");
            // The last text stored under the path is the one the loader read.
            if let Some((_, text)) = texts.iter().rev().find(|(p, _)| **p == *pos.file) {
                assert!(support::has_line(text, pos.line), "{message}");
            }
        }
    }
});
