//! Bad trace files give errors that name the file and the place, never a panic.

mod common;

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
