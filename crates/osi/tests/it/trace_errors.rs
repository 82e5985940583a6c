//! Bad trace files give errors that name the file and the place, never a panic.
// An integration-test crate: its helpers outside #[test] functions may unwrap too (the
// workspace lint clippy::unwrap_used is for library code; a panic here is the test failing).
#![allow(clippy::unwrap_used)]

use crate::common;

use osi::trace::{read_mcap_bytes, read_osi_bytes, OsiFileWriter, TraceWriter};
use osi::ErrorKind;
use std::path::Path;

fn two_frames() -> Vec<u8> {
    let frames = common::frames(2, 1);
    let mut writer = OsiFileWriter::new(Vec::new(), Path::new("mem.osi"));
    for gt in &frames {
        writer.write(gt).unwrap();
    }
    writer.into_inner().unwrap().unwrap()
}

#[test]
fn truncated_osi_names_file_and_offset() {
    let bytes = two_frames();
    let cut = &bytes[..bytes.len() - 3];
    let first_len = u32::from_le_bytes(bytes[0..4].try_into().unwrap()) as usize;
    let second_len = u32::from_le_bytes(bytes[4 + first_len..8 + first_len].try_into().unwrap());
    let err = read_osi_bytes(cut, Path::new("run.osi")).unwrap_err();
    // The second message starts after the first (4 + len) and its own 4-byte prefix.
    let offset = 8 + first_len;
    assert_eq!(
        err.to_string(),
        format!(
            "expected a message of {second_len} bytes, found only {} bytes at run.osi:byte {offset}",
            second_len - 3
        )
    );
    assert!(matches!(err.kind(), ErrorKind::Truncated { .. }));
}

#[test]
fn short_length_prefix_and_garbage() {
    let err = read_osi_bytes(&[1, 0], Path::new("a.osi")).unwrap_err();
    assert_eq!(
        err.to_string(),
        "expected a message of 4 bytes, found only 2 bytes at a.osi:byte 0"
    );
    // Length 2, then a tag with wire type 7, which protobuf does not have.
    let err = read_osi_bytes(&[2, 0, 0, 0, 0x0F, 0x00], Path::new("b.osi")).unwrap_err();
    assert!(matches!(err.kind(), ErrorKind::Decode { offset: 4, .. }));
    assert!(err.to_string().ends_with("at b.osi:byte 4"), "{err}");
}

#[test]
fn not_an_mcap_file() {
    let err = read_mcap_bytes(b"hello", Path::new("c.mcap")).unwrap_err();
    assert!(matches!(err.kind(), ErrorKind::Mcap(_)));
    assert!(err.to_string().contains("c.mcap"), "{err}");
}

#[test]
fn writing_after_finish_fails() {
    let mut writer = OsiFileWriter::new(Vec::new(), Path::new("d.osi"));
    writer.finish().unwrap();
    let err = writer.write(&Default::default()).unwrap_err();
    assert_eq!(
        err.to_string(),
        "expected an open trace, found d.osi already finished"
    );
}

#[test]
fn missing_file_names_the_path() {
    let err = osi::trace::read_osi(Path::new("/nonexistent/x.osi")).unwrap_err();
    assert!(
        err.to_string()
            .starts_with("cannot access /nonexistent/x.osi"),
        "{err}"
    );
}

#[test]
fn time_must_increase_and_be_set() {
    let frames = common::frames(3, 1);
    let mut writer = OsiFileWriter::new(Vec::new(), Path::new("e.osi"));
    writer.write(&frames[1]).unwrap();
    // Frame 0 (t = 0) after frame 1 (t = 50 ms).
    let err = writer.write(&frames[0]).unwrap_err();
    assert_eq!(
        err.to_string(),
        "expected a timestamp after 50000000 ns, found 0 ns in e.osi"
    );
    // The same time again is not later either.
    assert!(writer.write(&frames[1]).is_err());
    writer.write(&frames[2]).unwrap();
    let mut no_time = frames[2].clone();
    no_time.timestamp = None;
    let err = writer.write(&no_time).unwrap_err();
    assert!(matches!(err.kind(), ErrorKind::MissingTimestamp));
    // Only the two good frames are in the trace.
    let bytes = writer.into_inner().unwrap().unwrap();
    let back = read_osi_bytes(&bytes, Path::new("e.osi")).unwrap();
    assert_eq!(back, vec![frames[1].clone(), frames[2].clone()]);
}

#[test]
fn truncated_mcap_never_panics() {
    let tmp = common::temp_dir("truncated-mcap");
    let dir = tmp.path();
    let path = dir.join("t.mcap");
    let mut writer =
        osi::trace::McapTraceWriter::create(&path, &osi::trace::McapTraceInfo::default()).unwrap();
    for gt in &common::frames(5, 2) {
        writer.write(gt).unwrap();
    }
    writer.finish().unwrap();
    let bytes = std::fs::read(&path).unwrap();
    // Every cut of the file is rejected with an error, none read as a full trace.
    for cut in (0..bytes.len()).step_by(97) {
        let result = read_mcap_bytes(&bytes[..cut], Path::new("t.mcap"));
        assert!(result.is_err(), "cut at {cut} read as a trace");
    }
    assert_eq!(
        read_mcap_bytes(&bytes, Path::new("t.mcap"))
            .unwrap()
            .frames
            .len(),
        5
    );
}

proptest::proptest! {
    #[test]
    fn random_bytes_never_panic(bytes in proptest::collection::vec(proptest::prelude::any::<u8>(), 0..512)) {
        let _ = read_osi_bytes(&bytes, Path::new("r.osi"));
        let _ = read_mcap_bytes(&bytes, Path::new("r.mcap"));
    }
}
