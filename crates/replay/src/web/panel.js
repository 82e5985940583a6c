// panel.js: the state of the selected (or hovered) entity at the current time: pose, speed,
// acceleration (the speed's backward difference: the CSV has no acceleration column), road
// position, the actions running for it (from the event log) and its controllers; without a
// selection, a summary of the run.

function esc(text) {
  return String(text).replace(/[&<>"]/g, (c) => ({ "&": "&amp;", "<": "&lt;", ">": "&gt;", '"': "&quot;" })[c]);
}

function row(name, value) {
  return `<tr><td>${esc(name)}</td><td>${value}</td></tr>`;
}

// Backward-difference acceleration of e at sample i (0 at its first sample).
function acceleration(M, e, i) {
  if (i <= 0) return 0;
  const dt = M.times[e.frame[i]] - M.times[e.frame[i - 1]];
  return dt > 0 ? (e.v[i] - e.v[i - 1]) / dt : 0;
}

function entityPanel(M, index, k, t) {
  const e = M.entities[index];
  const i = sampleAt(e, k);
  let html = `<h3><span class="swatch" style="background:${esc(e.color)}"></span>${esc(e.name)}</h3><table>`;
  html += row("kind", esc(e.kind + (e.category ? " (" + e.category + ")" : "")));
  html += row("box", `${e.box[3].toFixed(2)} × ${e.box[4].toFixed(2)} × ${e.box[5].toFixed(2)} m`);
  if (i < 0) {
    html += row("t", `${t.toFixed(3)} s`) + row("state", e.n ? `not present (${M.times[e.first].toFixed(2)}–${M.times[e.last].toFixed(2)} s)` : "never placed");
    return html + "</table>";
  }
  const deg = (r) => ((r * 180) / Math.PI).toFixed(1) + "°";
  html += row("t", `${M.times[k].toFixed(3)} s`);
  html += row("x, y, z", `${(e.x[i] + M.ox).toFixed(3)}, ${(e.y[i] + M.oy).toFixed(3)}, ${e.z[i].toFixed(3)} m`);
  html += row("heading", `${deg(e.h[i])} (${e.h[i].toFixed(4)} rad)`);
  if (e.p[i] || e.r[i]) html += row("pitch, roll", `${deg(e.p[i])}, ${deg(e.r[i])}`);
  html += row("speed", `${e.v[i].toFixed(3)} m/s (${(e.v[i] * 3.6).toFixed(1)} km/h)`);
  html += row("acceleration", `${acceleration(M, e, i).toFixed(2)} m/s²`);
  if (e.road[i] > 0) {
    const road = M.roads[e.road[i] - 1];
    html += row("road, lane", `${esc(road ? road.id : "?")}, ${e.lane[i]}${road && road.junction !== null ? " (junction " + esc(road.junction) + ")" : ""}`);
    html += row("s, t", `${e.s[i].toFixed(3)}, ${e.t[i].toFixed(3)} m`);
    html += row("lane offset", `${e.off[i].toFixed(3)} m`);
  } else {
    html += row("road", "off the road");
  }
  if (e.trailer !== null && e.trailer !== undefined) html += row("tows", esc(M.entities[e.trailer].name));
  const tow = M.entities.findIndex((o) => o.trailer === index);
  if (tow >= 0) html += row("towed by", esc(M.entities[tow].name));
  html += row("controllers", e.controllers.length ? esc(e.controllers.join(", ")) : "default controller");
  const now = M.times[k];
  const running = e.actions.filter(([, , a, b]) => a <= now + 1e-9 && (b === null || now < b - 1e-9));
  html += row("active actions", running.length
    ? "<ul>" + running.map(([n, kind, a]) => `<li>${esc(n)} <small>(${esc(kind)}, since ${a.toFixed(2)} s)</small></li>`).join("") + "</ul>"
    : "none");
  return html + "</table>";
}

function runPanel(M) {
  const dur = M.nF ? M.times[M.nF - 1] - M.times[0] : 0;
  let html = `<h3>${esc(M.title)}</h3><table>`;
  html += row("duration", `${dur.toFixed(3)} s, ${M.nF} frames`);
  html += row("entities", String(M.entities.length));
  html += row("events", String(M.events.length));
  html += row("roads", String(M.roads.length));
  html += "</table><p><small>Click an entity for its state; hover the road for its ids.</small></p>";
  const types = new Set(Road.lanes.map((l) => l.type));
  html += "<table>" + Array.from(types).map((ty) =>
    row(ty, `<span class="swatch" style="background:${LANE_COLORS[ty] || "#7a7a7a"}"></span>`)).join("") + "</table>";
  return html;
}
