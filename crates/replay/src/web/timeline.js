// timeline.js: the event log under the slider. One row per group of records (storyboard
// structure, events, actions, entities and commands, errors), one tick per record coloured by
// transition (OpenSCENARIO 1.3 §8.2: start, end, stop, skip); hover lists the records near
// the pointer, click jumps to the nearest one. An OpenSCENARIO DSL run adds the phases of its
// `do` tree below, one row per depth (`do`, `do.get_ahead`, `do.get_ahead.0`, …), each phase a
// bar from its Act's start to its end in the event log, labelled by its path.

const ROWS = [
  ["structure", ["storyboard", "story", "act", "maneuverGroup", "maneuver"]],
  ["events", ["event"]],
  ["actions", ["action"]],
  ["entities", ["entity", "customCommand"]],
  ["errors", ["error", "unsupported"]],
];
const TICK_COLORS = { start: "#2f9e44", end: "#1c7ed6", stop: "#e8590c", skip: "#868e96" };
const LABEL_W = 64;
const EVENTS_H = 56;
const PHASE_H = 14;

const Timeline = { canvas: null, rows: [], t0: 0, t1: 1 };

function rowOf(kind) {
  for (let r = 0; r < ROWS.length; r++) if (ROWS[r][1].includes(kind)) return r;
  return 3;
}

function setupTimeline(M, canvas) {
  Timeline.canvas = canvas;
  Timeline.t0 = M.nF ? M.times[0] : 0;
  Timeline.t1 = M.nF ? Math.max(M.times[M.nF - 1], Timeline.t0 + 1e-3) : 1;
  Timeline.marks = M.events.map(([time, element, kind, detail, entity]) => ({
    time, element, kind, detail, entity, row: rowOf(kind),
    color: kind === "error" ? "#c92a2a" : kind === "unsupported" ? "#f59f00"
      : TICK_COLORS[(detail.match(/\((\w+)\)$/) || [])[1]] || "#495057",
  }));
  // DSL phases: each path's Act from its start transition to its end or stop.
  Timeline.phases = (M.phases || []).map((path) => {
    const acts = M.events.filter(([, element, kind]) => kind === "act" && element === path);
    const start = acts.find(([, , , detail]) => /\(start\)$/.test(detail));
    const end = acts.find(([, , , detail]) => /\((end|stop)\)$/.test(detail));
    return {
      path, depth: path.split(".").length - 1,
      start: start ? start[0] : null, end: end ? end[0] : Timeline.t1,
    };
  }).filter((p) => p.start !== null);
  Timeline.depths = Timeline.phases.reduce((d, p) => Math.max(d, p.depth + 1), 0);
  canvas.style.height = EVENTS_H + PHASE_H * Timeline.depths + "px";
}

// The phase bar under (x, y), if any.
function phaseAt(x, y) {
  if (y < EVENTS_H) return null;
  const depth = Math.floor((y - EVENTS_H) / PHASE_H);
  const t = timelineTime(x);
  return Timeline.phases.find((p) => p.depth === depth && p.start <= t && t <= p.end) || null;
}

function timelineX(t) {
  const w = Timeline.canvas.clientWidth - LABEL_W - 4;
  return LABEL_W + ((t - Timeline.t0) / (Timeline.t1 - Timeline.t0)) * w;
}

function timelineTime(x) {
  const w = Timeline.canvas.clientWidth - LABEL_W - 4;
  return Timeline.t0 + ((x - LABEL_W) / w) * (Timeline.t1 - Timeline.t0);
}

function drawTimeline(t) {
  const c = Timeline.canvas;
  const dpr = window.devicePixelRatio || 1;
  const W = c.clientWidth, H = c.clientHeight;
  if (c.width !== Math.round(W * dpr) || c.height !== Math.round(H * dpr)) {
    c.width = Math.round(W * dpr);
    c.height = Math.round(H * dpr);
  }
  const ctx = c.getContext("2d");
  ctx.setTransform(dpr, 0, 0, dpr, 0, 0);
  ctx.clearRect(0, 0, W, H);
  const rh = EVENTS_H / ROWS.length;
  ctx.font = "10px system-ui, sans-serif";
  ctx.textBaseline = "middle";
  ROWS.forEach(([name], r) => {
    ctx.fillStyle = r % 2 ? "#f1f3f5" : "#e9ecef";
    ctx.fillRect(LABEL_W, r * rh, W - LABEL_W, rh);
    ctx.fillStyle = "#5a6572";
    ctx.fillText(name, 2, r * rh + rh / 2);
  });
  for (const m of Timeline.marks) {
    const x = Math.round(timelineX(m.time)) + 0.5;
    ctx.strokeStyle = m.color;
    ctx.lineWidth = 2;
    ctx.beginPath();
    ctx.moveTo(x, m.row * rh + 1);
    ctx.lineTo(x, (m.row + 1) * rh - 1);
    ctx.stroke();
  }
  for (let d = 0; d < Timeline.depths; d++) {
    ctx.fillStyle = d % 2 ? "#f8f9fa" : "#f1f3f5";
    ctx.fillRect(LABEL_W, EVENTS_H + d * PHASE_H, W - LABEL_W, PHASE_H);
    ctx.fillStyle = "#5a6572";
    ctx.fillText(d === 0 ? "phases" : "", 2, EVENTS_H + d * PHASE_H + PHASE_H / 2);
  }
  for (const p of Timeline.phases) {
    const x0 = timelineX(p.start), x1 = Math.max(timelineX(p.end), x0 + 2);
    const y0 = EVENTS_H + p.depth * PHASE_H + 1;
    ctx.fillStyle = "#a5d8ff";
    ctx.fillRect(x0, y0, x1 - x0, PHASE_H - 2);
    ctx.strokeStyle = "#1c7ed6";
    ctx.lineWidth = 1;
    ctx.strokeRect(x0 + 0.5, y0 + 0.5, x1 - x0 - 1, PHASE_H - 3);
    const label = p.path.split(".").pop();
    if (ctx.measureText(label).width < x1 - x0 - 4) {
      ctx.fillStyle = "#0b3d6b";
      ctx.fillText(label, x0 + 3, y0 + PHASE_H / 2 - 1);
    }
  }
  const x = timelineX(t);
  ctx.strokeStyle = "#d6336c";
  ctx.lineWidth = 1.5;
  ctx.beginPath();
  ctx.moveTo(x, 0);
  ctx.lineTo(x, H);
  ctx.stroke();
}

// Records within 4 px of x (all rows), nearest first.
function marksNear(x) {
  return Timeline.marks
    .map((m) => [Math.abs(timelineX(m.time) - x), m])
    .filter(([d]) => d <= 4)
    .sort((a, b) => a[0] - b[0])
    .map(([, m]) => m);
}

function timelineHover(x, y, tip) {
  const phase = x >= LABEL_W ? phaseAt(x, y) : null;
  const near = x >= LABEL_W && !phase ? marksNear(x) : [];
  if (!near.length && !phase) {
    tip.hidden = true;
    return;
  }
  const lines = phase ? [`phase ${phase.path}: ${phase.start.toFixed(3)} s to ${phase.end.toFixed(3)} s`]
    : near.slice(0, 10).map((m) =>
      `${m.time.toFixed(3)} s  ${m.element} (${m.kind}${m.entity ? " " + m.entity : ""}): ${m.detail}`);
  if (near.length > 10) lines.push(`… ${near.length - 10} more`);
  tip.textContent = lines.join("\n");
  tip.hidden = false;
  const fw = tip.parentElement.clientWidth;
  tip.style.left = Math.min(x + 12, Math.max(fw - tip.offsetWidth - 4, 0)) + "px";
  tip.style.bottom = "64px";
}

// The time a click at x goes to: the nearest record's, else the time under the pointer.
function timelineClick(x) {
  const near = marksNear(x);
  return near.length ? near[0].time : timelineTime(x);
}
