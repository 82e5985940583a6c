// road_draw.js: the road network as Path2D objects in world metres, built once: lane areas
// grouped by lane type (OpenDRIVE 1.8 §11 lane types), junction areas (the lanes of connecting
// roads), road marks (§11.8: solid / broken, single or double, by colour and width); and the
// lane under a point for hover.

const LANE_COLORS = {
  driving: "#6b6f75", entry: "#6b6f75", exit: "#6b6f75", onRamp: "#6b6f75", offRamp: "#6b6f75",
  connectingRamp: "#6b6f75", slipLane: "#6b6f75", bidirectional: "#70747a", bus: "#7a5a5a",
  taxi: "#7a705a", HOV: "#6a6a80", shoulder: "#8d8f86", border: "#9b9d94", stop: "#8a8d88",
  restricted: "#8a7f74", parking: "#5f6f7f", median: "#7d9a6a", biking: "#8a5f5f",
  sidewalk: "#b9b5ac", walking: "#b9b5ac", curb: "#c8c4bc", tram: "#7b7368", rail: "#7b7368",
  roadWorks: "#c28a3c", none: "#7d8a74",
};

const Road = { lanes: [], junctions: null, marks: [], hits: [] };

// The lane id whose outer border is border b of section sec (0 for the centre line).
function borderLane(sec, b) {
  for (const l of sec.lanes) if (l[3] === b) return l[0];
  return 0;
}

// Adds the polyline of border pts from sample i to j (inclusive), shifted by d metres to its
// left, to path.
function addPolyline(path, pts, i, j, d) {
  for (let k = i; k <= j; k++) {
    let x = pts[2 * k], y = pts[2 * k + 1];
    if (d !== 0) {
      const a = Math.max(k - 1, i), b = Math.min(k + 1, j);
      const tx = pts[2 * b] - pts[2 * a], ty = pts[2 * b + 1] - pts[2 * a + 1];
      const len = Math.hypot(tx, ty) || 1;
      x -= (ty / len) * d;
      y += (tx / len) * d;
    }
    if (k === i) path.moveTo(x, y);
    else path.lineTo(x, y);
  }
}

function buildRoads(M) {
  const byType = new Map();
  const junctions = new Path2D();
  const marks = new Map();
  const hits = [];
  M.roads.forEach((road) => {
    for (const sec of road.sections) {
      for (const [id, type, inner, outer] of sec.lanes) {
        const o = sec.borders[outer], n = sec.n;
        const p = byType.get(type) || new Path2D();
        byType.set(type, p);
        const ring = new Float64Array(4 * n);
        for (let k = 0; k < n; k++) {
          ring[2 * k] = o[2 * k];
          ring[2 * k + 1] = o[2 * k + 1];
        }
        const inn = sec.borders[inner];
        for (let k = 0; k < n; k++) {
          ring[2 * n + 2 * k] = inn[2 * (n - 1 - k)];
          ring[2 * n + 2 * k + 1] = inn[2 * (n - 1 - k) + 1];
        }
        const poly = new Path2D();
        let x0 = Infinity, y0 = Infinity, x1 = -Infinity, y1 = -Infinity;
        for (let k = 0; k < 2 * n; k++) {
          const x = ring[2 * k], y = ring[2 * k + 1];
          if (k === 0) poly.moveTo(x, y);
          else poly.lineTo(x, y);
          x0 = Math.min(x0, x); y0 = Math.min(y0, y); x1 = Math.max(x1, x); y1 = Math.max(y1, y);
        }
        poly.closePath();
        p.addPath(poly);
        if (road.junction !== null) junctions.addPath(poly);
        hits.push({ road, sec, id, type, ring, box: [x0, y0, x1, y1] });
      }
      for (const [b, from, to, type, color, width, dash, gap, bold] of sec.marks) {
        const w = bold ? width * 1.5 : width;
        const lane = borderLane(sec, b);
        // Double lines are named from the inside of the road outwards (left to right on the
        // centre line): the inside of a right lane's border is its left.
        const inward = lane > 0 ? -1 : 1;
        const parts = type.includes(" ") && type !== "botts dots"
          ? type.split(" ").map((t, k) => [t, (k === 0 ? inward : -inward) * w])
          : [[type, 0]];
        for (const [t, d] of parts) {
          const dots = t.startsWith("botts");
          const broken = t === "broken" || dots;
          const key = color + "|" + w + "|" + (broken ? dash + "," + gap : "solid");
          let m = marks.get(key);
          if (!m) {
            m = { color, width: w, dash: broken ? (dots ? [0.1, 1.5] : [dash, gap]) : null, path: new Path2D() };
            marks.set(key, m);
          }
          addPolyline(m.path, sec.borders[b], from, to, d);
        }
      }
    }
  });
  Road.lanes = Array.from(byType, ([type, path]) => ({ type, path, color: LANE_COLORS[type] || "#7a7a7a" }));
  Road.junctions = junctions;
  Road.marks = Array.from(marks.values());
  Road.hits = hits;
}

function drawRoads(ctx) {
  worldTransform(ctx);
  for (const l of Road.lanes) {
    ctx.fillStyle = l.color;
    ctx.fill(l.path);
    // Hairline seams between lanes of one type would show the background: stroke them too.
    ctx.strokeStyle = l.color;
    ctx.lineWidth = 1 / Cam.scale;
    ctx.stroke(l.path);
  }
  ctx.fillStyle = "rgba(60, 90, 160, 0.16)";
  ctx.fill(Road.junctions);
  const px = 1 / Cam.scale;
  for (const m of Road.marks) {
    ctx.strokeStyle = m.color;
    ctx.lineWidth = Math.max(m.width, 0.8 * px);
    ctx.setLineDash(m.dash || []);
    ctx.stroke(m.path);
  }
  ctx.setLineDash([]);
}

// Even-odd test of point (x, y) against a ring of interleaved coordinates.
function inRing(ring, x, y) {
  let inside = false;
  const n = ring.length / 2;
  for (let i = 0, j = n - 1; i < n; j = i++) {
    const xi = ring[2 * i], yi = ring[2 * i + 1], xj = ring[2 * j], yj = ring[2 * j + 1];
    if ((yi > y) !== (yj > y) && x < ((xj - xi) * (y - yi)) / (yj - yi) + xi) inside = !inside;
  }
  return inside;
}

// The lane under world point (x, y): {road, sec, id, type} or null.
function laneAt(x, y) {
  for (const h of Road.hits) {
    const b = h.box;
    if (x < b[0] || x > b[2] || y < b[1] || y > b[3]) continue;
    if (inRing(h.ring, x, y)) return h;
  }
  return null;
}
