//! `oscsim run X.osc --coverage FILE.csv`: what one run sampled of an OpenSCENARIO DSL
//! scenario's `cover(…)` and `record(…)` items (ASAM OpenSCENARIO DSL 2.1 §7.3.12), each at
//! its event (`load::Sampler`), as a long CSV: `item,value,unit,bucket`, one row per sample,
//! items in source order and each item's samples in time order.
//!
//! - `item` is the item's column in a batch's results table, `cover:NAME` or `record:NAME`;
//! - `value` as that table writes it: a number in the item's unit with 6 decimals, an enum
//!   member or `true`/`false`, or `no value` where the expression had none at the event;
//! - `unit` the item's `unit:` (empty: SI, or not a number);
//! - `bucket` the label of the `cover` bucket the sample falls in, as `coverage.csv` writes it
//!   (`[60..70)`, a member); empty for a `record`, a cover without buckets, or a sample in no
//!   bucket (outside the range, no value).
//!
//! An item whose event never occurred in the run, or whose samples `ignore` dropped, has no
//! row. The values are those of the batch row of the same seed (`oscsim batch --seeds S..S`),
//! so a single run explains a batch's count. An XML scenario has no items: the file holds the
//! header alone, and a warning says why.

use load::{CoverItem, Sample};

/// The CSV text of `samples` (one list per item of `items`, as `load::Sampler::finish`
/// gives them), module doc.
pub(crate) fn to_csv(items: &[CoverItem], samples: &[Vec<Sample>]) -> String {
    let defs = batch::coverage_definitions(items);
    let mut out = String::from("item,value,unit,bucket\n");
    for (item, samples) in items.iter().zip(samples) {
        let column = batch::coverage_column(item);
        let def = defs.iter().find(|d| d.column == column);
        let unit = item.unit.as_ref().map_or("", |u| u.name.as_str());
        for s in samples {
            let bucket = def
                .and_then(|d| d.bucket_of(s))
                .map(|b| b.label())
                .unwrap_or_default();
            out.push_str(&format!("{column},{},{unit},{bucket}\n", s.text()));
        }
    }
    out
}
