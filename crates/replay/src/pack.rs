//! The replay's data container: a JSON header and integer streams in one zlib stream, base64
//! encoded for inlining in the page; `web/decode.js` reads it back.
//!
//! Layout before compression: `u32` (little-endian) length of the header, the header (UTF-8
//! JSON), then the streams back to back. Each stream is a list of integers written as
//! zigzag LEB128 varints (small magnitudes take one byte). The header names each stream with
//! its byte offset and length (`"streams": {"name": [offset, length, count]}`).
//!
//! Quantities are stored as integers of a fixed unit and delta-coded along time (order 1, or
//! order 2 for positions, whose first difference is nearly constant at constant speed), which
//! is what makes the compressed size small: a vehicle at constant speed costs about one byte
//! per coordinate per frame before deflate, and almost nothing after.
//!
//! Written by hand: the varint and delta coding are a few lines each and the format must match
//! the decoder in `web/decode.js` exactly; zlib comes from `miniz_oxide`, base64 from `base64`.

use std::collections::BTreeMap;

use base64::Engine as _;
use serde_json::Value;

/// Integer streams and their names.
#[derive(Debug, Default)]
pub struct Streams {
    bytes: Vec<u8>,
    index: BTreeMap<String, (usize, usize, usize)>,
}

/// Appends `v` as a zigzag LEB128 varint.
fn varint(out: &mut Vec<u8>, v: i64) {
    let mut z = ((v << 1) ^ (v >> 63)) as u64;
    loop {
        let byte = (z & 0x7f) as u8;
        z >>= 7;
        if z == 0 {
            out.push(byte);
            return;
        }
        out.push(byte | 0x80);
    }
}

/// `values` delta-coded `order` times (0, 1 or 2): the first values stay, the rest become
/// differences.
pub fn delta(values: &[i64], order: u8) -> Vec<i64> {
    let mut v = values.to_vec();
    for _ in 0..order {
        for k in (1..v.len()).rev() {
            v[k] = v[k].wrapping_sub(v[k - 1]);
        }
    }
    v
}

/// `x / unit` rounded to the nearest integer (saturating at ±2⁵³ so that the decoder's
/// doubles hold it exactly).
pub fn quantize(x: f64, unit: f64) -> i64 {
    const LIMIT: f64 = 9_007_199_254_740_992.0;
    (x / unit).round().clamp(-LIMIT, LIMIT) as i64
}

impl Streams {
    /// No streams.
    pub fn new() -> Self {
        Self::default()
    }

    /// Adds stream `name` holding `values` (already delta-coded as wanted).
    pub fn push(&mut self, name: &str, values: &[i64]) {
        let start = self.bytes.len();
        for &v in values {
            varint(&mut self.bytes, v);
        }
        self.index.insert(
            name.to_owned(),
            (start, self.bytes.len() - start, values.len()),
        );
    }

    /// The container with `header` (to which the stream index is added as `"streams"`),
    /// zlib-compressed and base64-encoded.
    pub fn finish(self, mut header: serde_json::Map<String, Value>) -> String {
        let index: serde_json::Map<String, Value> = self
            .index
            .into_iter()
            .map(|(k, (o, l, n))| (k, Value::from(vec![o, l, n])))
            .collect();
        header.insert("streams".into(), Value::Object(index));
        // A map of plain JSON values always serializes.
        let json = serde_json::to_vec(&Value::Object(header)).unwrap_or_default();
        let mut raw = Vec::with_capacity(4 + json.len() + self.bytes.len());
        raw.extend_from_slice(&(json.len() as u32).to_le_bytes());
        raw.extend_from_slice(&json);
        raw.extend_from_slice(&self.bytes);
        let packed = miniz_oxide::deflate::compress_to_vec_zlib(&raw, 9);
        base64::engine::general_purpose::STANDARD.encode(packed)
    }
}

/// Reads a container back (tests and tools): the header and the decoded (still
/// delta-coded) streams by name.
pub fn unpack(text: &str) -> Option<(Value, BTreeMap<String, Vec<i64>>)> {
    let packed = base64::engine::general_purpose::STANDARD
        .decode(text)
        .ok()?;
    let raw = miniz_oxide::inflate::decompress_to_vec_zlib(&packed).ok()?;
    let n = u32::from_le_bytes(raw.get(..4)?.try_into().ok()?) as usize;
    let header: Value = serde_json::from_slice(raw.get(4..4 + n)?).ok()?;
    let body = raw.get(4 + n..)?;
    let mut streams = BTreeMap::new();
    for (name, entry) in header.get("streams")?.as_object()? {
        let at = |k: usize| entry.get(k).and_then(Value::as_u64).map(|v| v as usize);
        let (o, l, count) = (at(0)?, at(1)?, at(2)?);
        let mut bytes = body.get(o..o + l)?.iter();
        let mut values = Vec::with_capacity(count);
        for _ in 0..count {
            let (mut z, mut shift) = (0u64, 0);
            loop {
                let b = *bytes.next()?;
                z |= u64::from(b & 0x7f) << shift;
                shift += 7;
                if b & 0x80 == 0 {
                    break;
                }
            }
            values.push(((z >> 1) as i64) ^ -((z & 1) as i64));
        }
        streams.insert(name.clone(), values);
    }
    Some((header, streams))
}

/// Undoes [`delta`].
pub fn undelta(values: &[i64], order: u8) -> Vec<i64> {
    let mut v = values.to_vec();
    for _ in 0..order {
        for k in 1..v.len() {
            v[k] = v[k].wrapping_add(v[k - 1]);
        }
    }
    v
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn varints_are_zigzag_leb128() {
        let mut out = Vec::new();
        for v in [0, -1, 1, 63, -64, 64, 300] {
            varint(&mut out, v);
        }
        // zigzag: 0→0, −1→1, 1→2, 63→126, −64→127, 64→128 (0x80 0x01), 300→600 (0xd8 0x04).
        assert_eq!(out, vec![0, 1, 2, 126, 127, 0x80, 0x01, 0xd8, 0x04]);
    }

    #[test]
    fn second_order_deltas_of_constant_speed_are_zero() {
        let x: Vec<i64> = (0..5).map(|k| 1000 + 1250 * k).collect();
        // First differences: 1000, 1250, 1250, …; their differences: 1000, 250, 0, 0, 0.
        assert_eq!(delta(&x, 2), vec![1000, 250, 0, 0, 0]);
        assert_eq!(undelta(&delta(&x, 2), 2), x);
    }

    #[test]
    fn containers_round_trip() {
        let mut s = Streams::new();
        s.push("a", &[1, -2, 3_000_000_000]);
        s.push("b", &[]);
        let mut header = serde_json::Map::new();
        header.insert("title".into(), "t".into());
        let (h, streams) = unpack(&s.finish(header)).expect("own output reads back");
        assert_eq!(h["title"], "t");
        assert_eq!(streams["a"], vec![1, -2, 3_000_000_000]);
        assert!(streams["b"].is_empty());
    }
}
