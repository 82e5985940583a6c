//! OpenSCENARIO 1.3 §9.5 parameter value distribution files: any text read and expanded into
//! its parameter sets (deterministic cross products, seeded stochastic draws). Must not panic
//! or hang; an error names a line:column inside the text (lines end at `\n`, `\r\n` or a lone
//! `\r`); no plan exceeds `MAX_RUNS` sets.
//! A stochastic plan of more than `RUNS_EXPANDED` runs is expanded with that many (each run
//! does the same work, and a plan of 90 000 runs costs 0.4 s, which starves the search); the
//! run-count limit itself is checked on the plan as read.
#![no_main]

use std::path::Path;

use libfuzzer_sys::fuzz_target;

mod support;
use scenario::distribution::model::DistributionDefinition;
use scenario::distribution::{self, DistributionPlan, MAX_RUNS};

/// Most stochastic runs expanded per input.
const RUNS_EXPANDED: u32 = 1000;

fuzz_target!(|data: &[u8]| {
    support::watchdog::start(data);
    let Ok(text) = std::str::from_utf8(data) else {
        return;
    };
    let path = Path::new("/fuzz/dist.xosc");
    match distribution::read(text, path) {
        Ok(mut d) => {
            if let DistributionDefinition::Stochastic(s) = &mut d.definition {
                if s.number_of_test_runs as usize > MAX_RUNS {
                    assert!(DistributionPlan::from_distribution(&d, path).is_err());
                    return;
                }
                s.number_of_test_runs = s.number_of_test_runs.min(RUNS_EXPANDED);
            }
            match DistributionPlan::from_distribution(&d, path) {
                Ok(plan) => assert!(plan.runs.len() <= MAX_RUNS, "{}", plan.runs.len()),
                Err(e) => {
                    let _ = e.to_string();
                }
            }
        }
        Err(e) => {
            let message = e.to_string();
            assert!(support::has_line(data, e.pos().line), "{message}");
            assert!(e.pos().col >= 1, "{message}");
        }
    }
});
