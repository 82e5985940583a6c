// entities.js: every entity present at the current time as its oriented bounding box (box
// centre and size relative to the reference point, OpenSCENARIO 1.3 BoundingBox), filled with
// its colour, with a heading mark, its name, the coupling to its trailer; picking by box.

// Poses of all entities at (k, f): array indexed like M.entities, null where absent.
function posesAt(M, k, f) {
  return M.entities.map((e) => poseAt(e, k, f));
}

// The four corners of e's box at pose p (world).
function boxCorners(e, p) {
  const [cx, cy, , l, w] = e.box;
  const c = Math.cos(p.h), s = Math.sin(p.h);
  const pts = [[cx + l / 2, cy + w / 2], [cx - l / 2, cy + w / 2], [cx - l / 2, cy - w / 2], [cx + l / 2, cy - w / 2]];
  return pts.map(([u, v]) => [p.x + c * u - s * v, p.y + s * u + c * v]);
}

// World point u metres ahead of and v left of e's reference point at p.
function local(p, u, v) {
  const c = Math.cos(p.h), s = Math.sin(p.h);
  return [p.x + c * u - s * v, p.y + s * u + c * v];
}

function drawEntities(ctx, M, poses, selected, hovered) {
  worldTransform(ctx);
  const px = 1 / Cam.scale;
  // Couplings first, under the boxes: from the tow's rear to the trailer's front.
  ctx.strokeStyle = "#222";
  ctx.lineWidth = Math.max(0.15, 2 * px);
  M.entities.forEach((e, i) => {
    const p = poses[i];
    if (!p || e.trailer === null || e.trailer === undefined) return;
    const q = poses[e.trailer];
    if (!q) return;
    const t = M.entities[e.trailer];
    const a = local(p, e.box[0] - e.box[3] / 2, e.box[1]);
    const b = local(q, t.box[0] + t.box[3] / 2, t.box[1]);
    ctx.beginPath();
    ctx.moveTo(a[0], a[1]);
    ctx.lineTo(b[0], b[1]);
    ctx.stroke();
  });
  M.entities.forEach((e, i) => {
    const p = poses[i];
    if (!p) return;
    const [cx, cy, , l, w] = e.box;
    const c = Math.cos(p.h), s = Math.sin(p.h);
    const s0 = Cam.scale * Cam.dpr;
    // Entity frame: world transform, then translate to the reference point and rotate.
    ctx.setTransform(s0 * c, -s0 * s, -s0 * s, -s0 * c,
      Cam.dpr * (Cam.width / 2) + s0 * (p.x - Cam.cx), Cam.dpr * (Cam.height / 2) - s0 * (p.y - Cam.cy));
    // Keep tiny objects visible: at least 3 px.
    const L = Math.max(l, 3 * px), W = Math.max(w, 3 * px);
    ctx.fillStyle = e.color;
    ctx.fillRect(cx - L / 2, cy - W / 2, L, W);
    ctx.lineWidth = (i === selected ? 3 : i === hovered ? 2 : 1) * px;
    ctx.strokeStyle = i === selected ? "#ffd400" : "#111";
    ctx.strokeRect(cx - L / 2, cy - W / 2, L, W);
    // Heading mark: a triangle in the front fifth of the box.
    ctx.fillStyle = "rgba(0, 0, 0, 0.45)";
    ctx.beginPath();
    ctx.moveTo(cx + L / 2, cy);
    ctx.lineTo(cx + L / 2 - Math.min(L / 5, 1.2), cy + W / 3);
    ctx.lineTo(cx + L / 2 - Math.min(L / 5, 1.2), cy - W / 3);
    ctx.closePath();
    ctx.fill();
  });
  // Names in screen space, above each box, when there is room.
  screenTransform(ctx);
  const many = M.entities.length > 40 && Cam.scale < 3;
  ctx.font = "12px system-ui, sans-serif";
  ctx.textAlign = "center";
  ctx.textBaseline = "bottom";
  M.entities.forEach((e, i) => {
    const p = poses[i];
    if (!p || (many && i !== selected && i !== hovered)) return;
    const [sx, sy] = worldToScreen(p.x, p.y);
    const r = Math.max(e.box[3], e.box[4]) * Cam.scale / 2;
    ctx.fillStyle = "rgba(255, 255, 255, 0.85)";
    const tw = ctx.measureText(e.name).width;
    ctx.fillRect(sx - tw / 2 - 2, sy - r - 18, tw + 4, 15);
    ctx.fillStyle = "#111";
    ctx.fillText(e.name, sx, sy - r - 4);
  });
}

// Index of the entity whose box holds screen point (px, py), or -1.
function entityAt(M, poses, px, py) {
  const [x, y] = screenToWorld(px, py);
  const slack = 3 / Cam.scale;
  for (let i = M.entities.length - 1; i >= 0; i--) {
    const p = poses[i];
    if (!p) continue;
    const e = M.entities[i];
    const c = Math.cos(p.h), s = Math.sin(p.h);
    const dx = x - p.x, dy = y - p.y;
    const u = c * dx + s * dy - e.box[0], v = -s * dx + c * dy - e.box[1];
    if (Math.abs(u) <= e.box[3] / 2 + slack && Math.abs(v) <= e.box[4] / 2 + slack) return i;
  }
  return -1;
}
