//! Writing GroundTruth with 1,000 moving objects (the sample scene of tests/it/common with
//! 1,000 vehicles, one pedestrian, one stationary object, no lanes): frames per second
//! is 1 / time per iteration, MB/s is criterion's byte throughput (message + prefix).
//!
//! - `build_1000`: filling the messages from entity states (mapping cost);
//! - `osi_1000`: encoding + length prefix into a discarding writer;
//! - `mcap_1000`: encoding + MCAP chunking into a discarding, seekable writer.
// criterion_group!/criterion_main! make undocumented public functions (workspace lint
// missing_docs).
#![allow(missing_docs)]

#[path = "../tests/it/common/mod.rs"]
mod common;

use criterion::{criterion_group, criterion_main, Criterion, Throughput};
use osi::ids::IdAllocator;
use osi::trace::{McapTraceInfo, McapTraceWriter, OsiFileWriter, TraceWriter};
use std::io::{self, Seek, SeekFrom, Write};
use std::path::Path;
use std::time::Duration;

const OBJECTS: usize = 1000;

/// Discards bytes but keeps a position, so that the MCAP writer may seek.
#[derive(Default)]
struct Discard {
    pos: u64,
    len: u64,
}

impl Write for Discard {
    fn write(&mut self, buf: &[u8]) -> io::Result<usize> {
        self.pos += buf.len() as u64;
        self.len = self.len.max(self.pos);
        Ok(buf.len())
    }
    fn flush(&mut self) -> io::Result<()> {
        Ok(())
    }
}

impl Seek for Discard {
    fn seek(&mut self, to: SeekFrom) -> io::Result<u64> {
        self.pos = match to {
            SeekFrom::Start(p) => p,
            SeekFrom::End(d) => self.len.saturating_add_signed(d),
            SeekFrom::Current(d) => self.pos.saturating_add_signed(d),
        };
        Ok(self.pos)
    }
}

fn bench(c: &mut Criterion) {
    let mut ids = IdAllocator::new();
    let mut gt = common::frame(&mut ids, 10, OBJECTS, false);
    let bytes = prost::Message::encoded_len(&gt) as u64 + 4;

    let mut group = c.benchmark_group("ground_truth");
    group.sample_size(10);
    group.measurement_time(Duration::from_secs(3));
    group.warm_up_time(Duration::from_secs(1));
    group.throughput(Throughput::Bytes(bytes));

    group.bench_function("build_1000", |b| {
        let mut ids = IdAllocator::new();
        let mut k = 0;
        b.iter(|| {
            k += 1;
            common::frame(&mut ids, k, OBJECTS, false)
        })
    });

    // Writers demand increasing time: each iteration writes the frame one step later.
    let mut step = 0i64;
    let mut next = move |gt: &mut osi::osi3::GroundTruth| {
        step += 1;
        gt.timestamp = Some(osi::osi3::Timestamp {
            seconds: Some(step / 20),
            nanos: Some((step % 20) as u32 * 50_000_000),
        });
    };

    group.bench_function("osi_1000", |b| {
        let mut writer = OsiFileWriter::new(io::sink(), Path::new("bench.osi"));
        b.iter(|| {
            next(&mut gt);
            writer.write(&gt).expect("sink accepts everything")
        })
    });

    group.bench_function("mcap_1000", |b| {
        let info = McapTraceInfo::default();
        let mut writer = McapTraceWriter::new(Discard::default(), Path::new("bench.mcap"), &info)
            .expect("discarding writer accepts the header");
        b.iter(|| {
            next(&mut gt);
            writer
                .write(&gt)
                .expect("discarding writer accepts everything")
        })
    });
    group.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
