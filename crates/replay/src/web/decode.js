// decode.js: the data container of the page (see crates/replay/src/pack.rs and page_data.rs):
// base64 -> zlib (the browser's DecompressionStream) -> u32 header length, JSON header, zigzag
// LEB128 varint streams, delta-coded per entity track / per road border.

const UNITS = { pos: 1e-3, road: 1e-2, angle: 1e-4, time: 1e-3 };
// Track columns and their delta order, as page_data.rs COLUMNS writes them.
const TRACK_COLUMNS = [["frame", 1], ["x", 2], ["y", 2], ["z", 1], ["h", 1], ["p", 1], ["r", 1],
  ["v", 1], ["road", 1], ["lane", 1], ["off", 1], ["t", 1], ["s", 2]];
const TRACK_SCALE = { frame: 1, x: UNITS.pos, y: UNITS.pos, z: UNITS.pos, h: UNITS.angle, p: UNITS.angle,
  r: UNITS.angle, v: UNITS.pos, road: 1, lane: 1, off: UNITS.pos, t: UNITS.pos, s: UNITS.pos };

function base64Bytes(text) {
  const bin = atob(text.trim());
  const out = new Uint8Array(bin.length);
  for (let i = 0; i < bin.length; i++) out[i] = bin.charCodeAt(i);
  return out;
}

async function inflate(bytes) {
  if (typeof DecompressionStream === "undefined") {
    throw new Error("this browser has no DecompressionStream (Chrome 80+, Firefox 113+, Safari 16.4+ do)");
  }
  const stream = new Blob([bytes]).stream().pipeThrough(new DecompressionStream("deflate"));
  return new Uint8Array(await new Response(stream).arrayBuffer());
}

// `count` zigzag varints from bytes[off ..]; arithmetic, not bit operations, so that values up
// to 2^53 survive.
function readVarints(bytes, off, count) {
  const out = new Float64Array(count);
  let p = off;
  for (let k = 0; k < count; k++) {
    let z = 0, mul = 1, b;
    do {
      b = bytes[p++];
      z += (b & 127) * mul;
      mul *= 128;
    } while (b & 128);
    out[k] = z % 2 === 1 ? -(z + 1) / 2 : z / 2;
  }
  return out;
}

// Undoes `order` rounds of differences on a[from .. to).
function undelta(a, from, to, order) {
  for (let o = 0; o < order; o++) {
    for (let k = from + 1; k < to; k++) a[k] += a[k - 1];
  }
}

async function decodeData(text) {
  const raw = await inflate(base64Bytes(text));
  const n = raw[0] | (raw[1] << 8) | (raw[2] << 16) | (raw[3] * 16777216);
  const header = JSON.parse(new TextDecoder().decode(raw.subarray(4, 4 + n)));
  const body = 4 + n;
  const stream = (name) => {
    const s = header.streams[name];
    return s ? readVarints(raw, body + s[0], s[2]) : new Float64Array(0);
  };
  const M = { title: header.title, dt: header.dt, events: header.events, measures: header.measures, phases: header.phases || [] };
  const times = stream("time");
  undelta(times, 0, times.length, 1);
  for (let k = 0; k < times.length; k++) times[k] *= UNITS.time;
  M.times = times;
  M.nF = times.length;
  // World origin: the road box's centre (or 0), so canvas transforms stay precise far from 0.
  const rb = header.roadBox;
  M.ox = Math.round((rb[0] + rb[2]) / 2);
  M.oy = Math.round((rb[1] + rb[3]) / 2);
  decodeTracks(M, header, stream);
  decodeRoads(M, header, stream);
  return M;
}

function decodeTracks(M, header, stream) {
  const cols = {};
  for (const [name] of TRACK_COLUMNS) cols[name] = stream(name);
  M.entities = header.entities.map((e) => Object.assign({}, e));
  let at = 0;
  for (const e of M.entities) {
    const from = at, to = at + e.n;
    for (const [name, order] of TRACK_COLUMNS) {
      const a = cols[name];
      undelta(a, from, to, order);
      const scale = TRACK_SCALE[name];
      if (scale !== 1) for (let k = from; k < to; k++) a[k] *= scale;
      e[name] = a.subarray(from, to);
    }
    for (let k = 0; k < e.n; k++) {
      e.x[k] -= M.ox;
      e.y[k] -= M.oy;
    }
    e.first = e.n ? e.frame[0] : -1;
    e.last = e.n ? e.frame[e.n - 1] : -2;
    e.contiguous = e.n > 0 && e.last - e.first === e.n - 1;
    at = to;
  }
  M.byName = new Map(M.entities.map((e, i) => [e.name, i]));
}

function decodeRoads(M, header, stream) {
  const rx = stream("rx"), ry = stream("ry");
  let at = 0;
  M.roads = header.roads.map((road) => ({
    id: road.id,
    junction: road.junction,
    sections: road.sections.map((sec) => {
      const borders = [];
      for (let b = 0; b < sec.nb; b++) {
        undelta(rx, at, at + sec.n, 1);
        undelta(ry, at, at + sec.n, 1);
        const pts = new Float64Array(2 * sec.n);
        for (let k = 0; k < sec.n; k++) {
          pts[2 * k] = rx[at + k] * UNITS.road - M.ox;
          pts[2 * k + 1] = ry[at + k] * UNITS.road - M.oy;
        }
        borders.push(pts);
        at += sec.n;
      }
      return { s0: sec.s0, s1: sec.s1, n: sec.n, borders, lanes: sec.lanes, marks: sec.marks };
    }),
  }));
  M.roadBox = header.roadBox;
}

// Index of entity e's sample at frame k, or -1.
function sampleAt(e, k) {
  if (k < e.first || k > e.last) return -1;
  if (e.contiguous) return k - e.first;
  let lo = 0, hi = e.n - 1;
  while (lo <= hi) {
    const mid = (lo + hi) >> 1;
    if (e.frame[mid] < k) lo = mid + 1;
    else if (e.frame[mid] > k) hi = mid - 1;
    else return mid;
  }
  return -1;
}

// The frame at or before time t (binary search) and the fraction towards the next frame.
function frameAt(M, t) {
  const T = M.times;
  if (M.nF === 0) return [0, 0];
  if (t <= T[0]) return [0, 0];
  if (t >= T[M.nF - 1]) return [M.nF - 1, 0];
  let lo = 0, hi = M.nF - 1;
  while (hi - lo > 1) {
    const mid = (lo + hi) >> 1;
    if (T[mid] <= t) lo = mid;
    else hi = mid;
  }
  const span = T[hi] - T[lo];
  // Times within a microsecond of a frame are that frame (slider values are decimal).
  if (t - T[lo] < 1e-6 || span <= 0) return [lo, 0];
  if (T[hi] - t < 1e-6) return [hi, 0];
  return [lo, (t - T[lo]) / span];
}

// The wrapped difference b - a of two angles.
function angleDiff(a, b) {
  let d = (b - a) % (2 * Math.PI);
  if (d > Math.PI) d -= 2 * Math.PI;
  if (d < -Math.PI) d += 2 * Math.PI;
  return d;
}

// Pose of entity e at (frame k, fraction f): {i, x, y, h, v} or null when absent.
function poseAt(e, k, f) {
  const i = sampleAt(e, k);
  if (i < 0) return null;
  if (f === 0) return { i, x: e.x[i], y: e.y[i], h: e.h[i], v: e.v[i] };
  const j = sampleAt(e, k + 1);
  if (j < 0) return { i, x: e.x[i], y: e.y[i], h: e.h[i], v: e.v[i] };
  return {
    i,
    x: e.x[i] + (e.x[j] - e.x[i]) * f,
    y: e.y[i] + (e.y[j] - e.y[i]) * f,
    h: e.h[i] + angleDiff(e.h[i], e.h[j]) * f,
    v: e.v[i] + (e.v[j] - e.v[i]) * f,
  };
}
