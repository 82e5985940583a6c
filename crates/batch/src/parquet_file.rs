//! `results.parquet`: the results table as one Apache Parquet file (arrow + parquet crates), the
//! same columns as `results.csv` (table.rs), typed:
//!
//! | column | Arrow type |
//! | --- | --- |
//! | `variant`, `events_started` | UInt64 |
//! | a parameter | Float64 when every value is a finite number, else Utf8 |
//! | `stop_reason`, `error` | Utf8 |
//! | `end_time`, `first_collision_time`, `min_ttc`, `min_headway`, `min_gap` | Float64 |
//! | `collision`, `monitor:<name>` | Boolean |
//! | `cover:<name>`, `record:<name>` | Utf8 (the CSV cell: samples separated by `;`) |
//!
//! Empty CSV cells are nulls. The file is uncompressed and written with fixed writer
//! properties, so the same table gives the same bytes.

use std::sync::Arc;

use arrow_array::{ArrayRef, BooleanArray, Float64Array, RecordBatch, StringArray, UInt64Array};
use arrow_schema::{DataType, Field, Schema};
use parquet::arrow::ArrowWriter;
use parquet::file::properties::WriterProperties;

use crate::error::{Error, ParquetErrorKind};
use crate::table::{Outcome, Row, Table, FIXED_COLUMNS};

/// The Parquet bytes of `table`.
pub fn to_parquet(table: &Table) -> Result<Vec<u8>, Error> {
    let ok: Vec<Option<&Outcome>> = table.rows.iter().map(|r| r.result.as_ref().ok()).collect();
    let float = |f: &dyn Fn(&Outcome) -> Option<f64>| -> ArrayRef {
        Arc::new(ok.iter().map(|o| o.and_then(f)).collect::<Float64Array>())
    };
    let mut fields = vec![Field::new("variant", DataType::UInt64, false)];
    let mut columns: Vec<ArrayRef> = vec![Arc::new(
        table
            .rows
            .iter()
            .map(|r| r.variant)
            .collect::<UInt64Array>(),
    )];
    for (k, name) in table.parameters.iter().enumerate() {
        let values: Vec<&str> = table.rows.iter().map(|r| r.params[k].as_str()).collect();
        let numbers: Option<Vec<f64>> = values
            .iter()
            .map(|v| v.trim().parse::<f64>().ok().filter(|x| x.is_finite()))
            .collect();
        match numbers {
            Some(n) if !values.is_empty() => {
                fields.push(Field::new(name, DataType::Float64, false));
                columns.push(Arc::new(Float64Array::from(n)));
            }
            _ => {
                fields.push(Field::new(name, DataType::Utf8, false));
                columns.push(Arc::new(StringArray::from(values)));
            }
        }
    }
    let [stop, end, collision, first, ttc, headway, gap, events, error] = FIXED_COLUMNS;
    let fixed: [(&str, DataType, ArrayRef); 9] = [
        (
            stop,
            DataType::Utf8,
            Arc::new(
                table
                    .rows
                    .iter()
                    .map(Row::stop_reason)
                    .collect::<StringArray>(),
            ),
        ),
        (end, DataType::Float64, float(&|o| Some(o.end_time))),
        (
            collision,
            DataType::Boolean,
            Arc::new(
                ok.iter()
                    .map(|o| o.map(|o| o.collision))
                    .collect::<BooleanArray>(),
            ),
        ),
        (first, DataType::Float64, float(&|o| o.first_collision_time)),
        (ttc, DataType::Float64, float(&|o| o.min_ttc)),
        (headway, DataType::Float64, float(&|o| o.min_headway)),
        (gap, DataType::Float64, float(&|o| o.min_gap)),
        (
            events,
            DataType::UInt64,
            Arc::new(
                ok.iter()
                    .map(|o| o.map(|o| o.events_started))
                    .collect::<UInt64Array>(),
            ),
        ),
        (
            error,
            DataType::Utf8,
            Arc::new(
                table
                    .rows
                    .iter()
                    .map(|r| r.result.as_ref().err().map(String::as_str))
                    .collect::<StringArray>(),
            ),
        ),
    ];
    for (name, ty, column) in fixed {
        fields.push(Field::new(name, ty, true));
        columns.push(column);
    }
    for m in &table.monitors {
        fields.push(Field::new(format!("monitor:{m}"), DataType::Boolean, true));
        let values: BooleanArray = ok
            .iter()
            .map(|o| o.and_then(|o| o.monitors.iter().find(|(n, _)| n == m).map(|(_, v)| *v)))
            .collect();
        columns.push(Arc::new(values));
    }
    for (k, c) in table.coverage.iter().enumerate() {
        fields.push(Field::new(c, DataType::Utf8, true));
        let values: StringArray = ok
            .iter()
            .map(|o| {
                o.map(|o| {
                    let samples = o.samples.get(k).map_or(&[][..], Vec::as_slice);
                    samples
                        .iter()
                        .map(load::Sample::text)
                        .collect::<Vec<_>>()
                        .join(";")
                })
            })
            .collect();
        columns.push(Arc::new(values));
    }
    let schema = Arc::new(Schema::new(fields));
    let batch = RecordBatch::try_new(schema.clone(), columns)
        .map_err(|e| ParquetErrorKind(e.to_string()))?;
    let props = WriterProperties::builder()
        .set_created_by("oscsim batch".to_owned())
        .build();
    let mut bytes = Vec::new();
    let mut writer = ArrowWriter::try_new(&mut bytes, schema, Some(props))
        .map_err(|e| ParquetErrorKind(e.to_string()))?;
    writer
        .write(&batch)
        .map_err(|e| ParquetErrorKind(e.to_string()))?;
    writer
        .close()
        .map_err(|e| ParquetErrorKind(e.to_string()))?;
    Ok(bytes)
}
