//! OpenSCENARIO 1.3 §9.5 parameter value distribution files: any text read and expanded into
//! its parameter sets (deterministic cross products, seeded stochastic draws). Must not panic
//! or hang; an error names a line:column inside the text; no plan exceeds `MAX_RUNS` sets.
#![no_main]

use std::path::Path;

use libfuzzer_sys::fuzz_target;

mod support;
use scenario::distribution::{self, DistributionPlan, MAX_RUNS};

fuzz_target!(|data: &[u8]| {
    support::watchdog::start(data);
    let Ok(text) = std::str::from_utf8(data) else {
        return;
    };
    let path = Path::new("/fuzz/dist.xosc");
    match distribution::read(text, path) {
        Ok(d) => match DistributionPlan::from_distribution(&d, path) {
            Ok(plan) => assert!(plan.runs.len() <= MAX_RUNS, "{}", plan.runs.len()),
            Err(e) => {
                let _ = e.to_string();
            }
        },
        Err(e) => {
            let message = e.to_string();
            let lines = text.split('\n').count() as u32;
            assert!(e.pos().row >= 1 && e.pos().row <= lines, "{message}");
            assert!(e.pos().col >= 1, "{message}");
        }
    }
});
