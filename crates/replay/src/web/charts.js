// charts.js: small charts beside the view, synchronised with the time: speed of every entity
// (the selected one drawn on top), and each gap or time the scenario's conditions measure with
// the conditions' thresholds. The lines are drawn once into an offscreen canvas; each frame
// only copies it and draws the time cursor and the values at that time.

const Charts = { list: [] };
const CH = { left: 40, right: 6, top: 6, bottom: 16 };

// A chart: canvas, title, series [{name, color, t: Float64Array, v: Float64Array (NaN gaps)}],
// thresholds [{label, value}], unit.
function makeChart(host, title, unit, series, thresholds) {
  const label = document.createElement("div");
  label.className = "label";
  label.textContent = title;
  const canvas = document.createElement("canvas");
  host.appendChild(label);
  host.appendChild(canvas);
  let lo = Infinity, hi = -Infinity, t0 = Infinity, t1 = -Infinity;
  for (const s of series) {
    for (let k = 0; k < s.v.length; k++) {
      if (!Number.isFinite(s.v[k])) continue;
      lo = Math.min(lo, s.v[k]); hi = Math.max(hi, s.v[k]);
    }
    if (s.t.length) { t0 = Math.min(t0, s.t[0]); t1 = Math.max(t1, s.t[s.t.length - 1]); }
  }
  for (const th of thresholds) { lo = Math.min(lo, th.value); hi = Math.max(hi, th.value); }
  if (!Number.isFinite(lo)) { lo = 0; hi = 1; }
  const pad = Math.max((hi - lo) * 0.08, 0.5);
  const chart = { canvas, title, unit, series, thresholds, lo: lo - pad, hi: hi + pad,
    t0: Number.isFinite(t0) ? t0 : 0, t1: t1 > t0 ? t1 : (Number.isFinite(t0) ? t0 + 1 : 1),
    cache: null, highlight: -1 };
  Charts.list.push(chart);
  return chart;
}

// A line colour that shows on the white chart: very light entity colours (a white Ego) are
// drawn dark grey.
function lineColor(css) {
  const m = /^#([0-9a-f]{2})([0-9a-f]{2})([0-9a-f]{2})$/i.exec(css);
  if (!m) return css;
  const [r, g, b] = [m[1], m[2], m[3]].map((h) => parseInt(h, 16) / 255);
  return 0.2126 * r + 0.7152 * g + 0.0722 * b > 0.8 ? "#495057" : css;
}

function chartX(c, t, w) { return CH.left + ((t - c.t0) / (c.t1 - c.t0)) * (w - CH.left - CH.right); }
function chartY(c, v, h) { return CH.top + (1 - (v - c.lo) / (c.hi - c.lo)) * (h - CH.top - CH.bottom); }

function renderChartCache(c) {
  const dpr = window.devicePixelRatio || 1;
  const w = c.canvas.clientWidth, h = c.canvas.clientHeight;
  const off = document.createElement("canvas");
  off.width = Math.round(w * dpr);
  off.height = Math.round(h * dpr);
  const ctx = off.getContext("2d");
  ctx.setTransform(dpr, 0, 0, dpr, 0, 0);
  ctx.fillStyle = "#fff";
  ctx.fillRect(0, 0, w, h);
  ctx.font = "10px system-ui, sans-serif";
  ctx.fillStyle = "#5a6572";
  ctx.strokeStyle = "#e3e7eb";
  ctx.lineWidth = 1;
  for (let k = 0; k <= 4; k++) {
    const v = c.lo + ((c.hi - c.lo) * k) / 4, y = chartY(c, v, h);
    ctx.beginPath(); ctx.moveTo(CH.left, y); ctx.lineTo(w - CH.right, y); ctx.stroke();
    ctx.textAlign = "right"; ctx.textBaseline = "middle";
    ctx.fillText(v.toFixed(Math.abs(c.hi - c.lo) < 5 ? 2 : 1), CH.left - 3, y);
  }
  ctx.textAlign = "center"; ctx.textBaseline = "top";
  for (let k = 0; k <= 4; k++) {
    const t = c.t0 + ((c.t1 - c.t0) * k) / 4;
    ctx.fillText(t.toFixed(1) + " s", chartX(c, t, w), h - CH.bottom + 3);
  }
  ctx.setLineDash([5, 3]);
  ctx.strokeStyle = "#343a40";
  for (const th of c.thresholds) {
    const y = chartY(c, th.value, h);
    ctx.beginPath(); ctx.moveTo(CH.left, y); ctx.lineTo(w - CH.right, y); ctx.stroke();
  }
  ctx.setLineDash([]);
  const order = c.series.map((_, i) => i).filter((i) => i !== c.highlight);
  if (c.highlight >= 0) order.push(c.highlight);
  for (const i of order) {
    const s = c.series[i];
    ctx.strokeStyle = s.color;
    ctx.lineWidth = i === c.highlight ? 2.5 : c.series.length > 20 ? 0.7 : 1.4;
    ctx.globalAlpha = c.highlight >= 0 && i !== c.highlight ? 0.45 : 1;
    ctx.beginPath();
    let pen = false;
    for (let k = 0; k < s.v.length; k++) {
      if (!Number.isFinite(s.v[k])) { pen = false; continue; }
      const x = chartX(c, s.t[k], w), y = chartY(c, s.v[k], h);
      if (pen) ctx.lineTo(x, y); else ctx.moveTo(x, y);
      pen = true;
    }
    ctx.stroke();
  }
  ctx.globalAlpha = 1;
  c.cache = off;
}

// The value of series s at time t (linear between samples; NaN outside).
function seriesValue(s, t) {
  const T = s.t;
  if (!T.length || t < T[0] || t > T[T.length - 1]) return NaN;
  let lo = 0, hi = T.length - 1;
  while (hi - lo > 1) { const m = (lo + hi) >> 1; if (T[m] <= t) lo = m; else hi = m; }
  if (T[hi] === T[lo]) return s.v[lo];
  const f = (t - T[lo]) / (T[hi] - T[lo]);
  return s.v[lo] + (s.v[hi] - s.v[lo]) * f;
}

function drawCharts(t) {
  const dpr = window.devicePixelRatio || 1;
  for (const c of Charts.list) {
    const w = c.canvas.clientWidth, h = c.canvas.clientHeight;
    if (!w || !h) continue;
    if (c.canvas.width !== Math.round(w * dpr) || c.canvas.height !== Math.round(h * dpr) || !c.cache) {
      c.canvas.width = Math.round(w * dpr);
      c.canvas.height = Math.round(h * dpr);
      renderChartCache(c);
    }
    const ctx = c.canvas.getContext("2d");
    ctx.setTransform(1, 0, 0, 1, 0, 0);
    ctx.drawImage(c.cache, 0, 0);
    ctx.setTransform(dpr, 0, 0, dpr, 0, 0);
    const x = chartX(c, t, w);
    ctx.strokeStyle = "#d6336c";
    ctx.lineWidth = 1;
    ctx.beginPath(); ctx.moveTo(x, CH.top); ctx.lineTo(x, h - CH.bottom); ctx.stroke();
    const shown = c.highlight >= 0 ? [c.highlight] : c.series.length <= 6 ? c.series.map((_, i) => i) : [];
    ctx.font = "10px system-ui, sans-serif";
    ctx.textAlign = x > w * 0.7 ? "right" : "left";
    ctx.textBaseline = "top";
    shown.forEach((i, row) => {
      const s = c.series[i], v = seriesValue(s, t);
      if (!Number.isFinite(v)) return;
      const y = chartY(c, v, h);
      ctx.fillStyle = s.color;
      ctx.beginPath(); ctx.arc(x, y, 3, 0, 2 * Math.PI); ctx.fill();
      ctx.fillStyle = "#212529";
      ctx.fillText(`${s.name}: ${v.toFixed(2)} ${c.unit}`, x + (ctx.textAlign === "left" ? 5 : -5), CH.top + row * 11);
    });
  }
}

// Sets the highlighted series (an entity index for the speed chart) and re-renders caches.
function highlightCharts(name) {
  for (const c of Charts.list) {
    const i = c.series.findIndex((s) => s.name === name);
    if (i !== c.highlight) { c.highlight = i; c.cache = null; }
  }
}

function buildCharts(M, host, onJump) {
  host.textContent = "";
  Charts.list = [];
  const speed = M.entities.map((e) => {
    const t = new Float64Array(e.n);
    for (let k = 0; k < e.n; k++) t[k] = M.times[e.frame[k]];
    return { name: e.name, color: lineColor(e.color), t, v: e.v };
  });
  makeChart(host, "speed (m/s)", "m/s", speed, []);
  for (const m of M.measures) {
    const t = M.times;
    const v = Float64Array.from(m.values, (x) => (x === null ? NaN : x));
    const what = m.quantity === "relativeDistance"
      ? `${m.relativeDistanceType}, ${m.coordinateSystem}${m.freespace ? ", freespace" : ""}` : "";
    const title = `${m.quantity} ${m.entity} → ${m.reference}${what ? " (" + what + ")" : ""} [${m.unit}] by ${m.method}; `
      + m.thresholds.map(([c, r, x]) => `${c}: ${r} ${x}`).join("; ");
    const e = M.byName.get(m.entity);
    makeChart(host, title, m.unit, [{ name: m.entity, color: e === undefined ? "#333" : lineColor(M.entities[e].color), t, v }],
      m.thresholds.map(([c, r, x]) => ({ label: `${c} ${r} ${x}`, value: x })));
  }
  for (const c of Charts.list) {
    c.canvas.addEventListener("click", (ev) => {
      const w = c.canvas.clientWidth;
      const t = c.t0 + ((ev.offsetX - CH.left) / (w - CH.left - CH.right)) * (c.t1 - c.t0);
      onJump(Math.min(Math.max(t, c.t0), c.t1));
    });
  }
}
