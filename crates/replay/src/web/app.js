// app.js: the page's state and loop: time, playback (0.1x to 20x), selection, follow camera;
// controls, keyboard shortcuts; redraws only when something changed; and `window.oscsimReplay`,
// the page's state for tests and tools (time, camera, each entity's drawn pose and place).

const S = { M: null, t: 0, drawnT: NaN, playing: false, rate: 1, selected: -1, hovered: -1, dirty: true,
  lastNow: 0, drawMs: 0, poses: [], frame: [0, 0] };
const $ = (id) => document.getElementById(id);
let readyResolve, readyReject;
const ready = new Promise((res, rej) => { readyResolve = res; readyReject = rej; });

function fail(err) {
  const box = $("error");
  box.hidden = false;
  box.textContent = "The replay could not be shown: " + (err && err.message ? err.message : err);
  console.error(err);
  readyReject(err);
}

function tEnd() { return S.M.nF ? S.M.times[S.M.nF - 1] : 0; }
function tStart() { return S.M.nF ? S.M.times[0] : 0; }

function setTime(t) {
  S.t = Math.min(Math.max(t, tStart()), tEnd());
  S.dirty = true;
}

function stepFrames(n) {
  const [k] = frameAt(S.M, S.t);
  setTime(S.M.times[Math.min(Math.max(k + n, 0), S.M.nF - 1)]);
}

function setPlaying(on) {
  S.playing = on && S.M.nF > 1;
  if (S.playing && S.t >= tEnd()) setTime(tStart());
  $("play").innerHTML = S.playing ? "&#x2016;" : "&#x25B6;";
  S.lastNow = performance.now();
}

function setRate(r) {
  S.rate = r;
  $("rate").value = String(r);
}

function setFollow(i) {
  Cam.follow = i;
  $("follow").value = String(i);
  S.dirty = true;
}

function resize() {
  const c = $("view");
  Cam.dpr = window.devicePixelRatio || 1;
  Cam.width = c.clientWidth;
  Cam.height = c.clientHeight;
  c.width = Math.round(Cam.width * Cam.dpr);
  c.height = Math.round(Cam.height * Cam.dpr);
  S.dirty = true;
}

function fit() {
  const M = S.M;
  const b = M.roadBox;
  let box = [b[0] - M.ox, b[1] - M.oy, b[2] - M.ox, b[3] - M.oy];
  if (!M.roads.length || b[2] <= b[0]) {
    box = [Infinity, Infinity, -Infinity, -Infinity];
    for (const e of M.entities) for (let k = 0; k < e.n; k++) {
      box = [Math.min(box[0], e.x[k]), Math.min(box[1], e.y[k]), Math.max(box[2], e.x[k]), Math.max(box[3], e.y[k])];
    }
    if (!Number.isFinite(box[0])) box = [-50, -50, 50, 50];
  }
  setFollow(-1);
  fitBox(box);
  S.dirty = true;
}

// Draws the frame at S.t.
function draw() {
  const M = S.M, start = performance.now();
  const [k, f] = frameAt(M, S.t);
  S.frame = [k, f];
  S.drawnT = S.t;
  S.poses = posesAt(M, k, f);
  if (Cam.follow >= 0 && S.poses[Cam.follow]) {
    Cam.cx = S.poses[Cam.follow].x;
    Cam.cy = S.poses[Cam.follow].y;
  }
  const ctx = $("view").getContext("2d");
  ctx.setTransform(1, 0, 0, 1, 0, 0);
  ctx.fillStyle = "#5d7a4f";
  ctx.fillRect(0, 0, $("view").width, $("view").height);
  drawRoads(ctx);
  drawEntities(ctx, M, S.poses, S.selected, S.hovered);
  drawTimeline(S.t);
  drawCharts(S.t);
  $("slider").value = String(S.t);
  $("clock").textContent = `t = ${S.t.toFixed(3)} s`;
  const who = S.selected >= 0 ? S.selected : S.hovered;
  $("info").innerHTML = who >= 0 ? entityPanel(M, who, k, S.t) : runPanel(M);
  S.drawMs = performance.now() - start;
  $("perf").textContent = `${S.drawMs.toFixed(1)} ms`;
}

function loop(now) {
  if (S.playing) {
    setTime(S.t + ((now - S.lastNow) / 1000) * S.rate);
    if (S.t >= tEnd()) setPlaying(false);
  }
  S.lastNow = now;
  if (S.dirty) {
    S.dirty = false;
    draw();
  }
  requestAnimationFrame(loop);
}

function select(i) {
  S.selected = i;
  highlightCharts(i >= 0 ? S.M.entities[i].name : null);
  S.dirty = true;
}

function nextEvent(dir) {
  const times = S.M.events.map((e) => e[0]);
  const t = dir > 0 ? times.find((x) => x > S.t + 1e-6) : times.reverse().find((x) => x < S.t - 1e-6);
  if (t !== undefined) setTime(t);
}

function onKey(ev) {
  if (ev.target.tagName === "SELECT" || ev.ctrlKey || ev.metaKey || ev.altKey) return;
  const rates = [0.1, 0.25, 0.5, 1, 2, 5, 10, 20];
  const r = rates.indexOf(S.rate);
  const keys = {
    " ": () => setPlaying(!S.playing),
    ArrowRight: () => (ev.shiftKey ? setTime(S.t + 1) : stepFrames(1)),
    ArrowLeft: () => (ev.shiftKey ? setTime(S.t - 1) : stepFrames(-1)),
    Home: () => setTime(tStart()),
    End: () => setTime(tEnd()),
    "]": () => setRate(rates[Math.min(r + 1, rates.length - 1)]),
    "[": () => setRate(rates[Math.max(r - 1, 0)]),
    n: () => nextEvent(1),
    p: () => nextEvent(-1),
    f: () => setFollow(Cam.follow >= 0 || S.selected < 0 ? -1 : S.selected),
    0: fit,
    Escape: () => select(-1),
    "?": () => { $("helpbox").hidden = !$("helpbox").hidden; },
  };
  const action = keys[ev.key] || keys[ev.key.toLowerCase()];
  if (action) {
    ev.preventDefault();
    action();
  }
}

function wire(M) {
  document.title = M.title + " — oscsim replay";
  $("title").textContent = M.title;
  const slider = $("slider");
  slider.min = String(tStart());
  slider.max = String(tEnd());
  slider.step = String(M.dt > 0 ? M.dt : "any");
  slider.addEventListener("input", () => { setPlaying(false); setTime(parseFloat(slider.value)); });
  $("play").onclick = () => setPlaying(!S.playing);
  $("back").onclick = () => stepFrames(-1);
  $("fwd").onclick = () => stepFrames(1);
  $("start").onclick = () => setTime(tStart());
  $("end").onclick = () => setTime(tEnd());
  $("rate").onchange = () => setRate(parseFloat($("rate").value));
  $("fit").onclick = fit;
  $("helpbtn").onclick = () => { $("helpbox").hidden = !$("helpbox").hidden; };
  const follow = $("follow");
  M.entities.forEach((e, i) => {
    const o = document.createElement("option");
    o.value = String(i);
    o.textContent = "follow " + e.name;
    follow.appendChild(o);
  });
  follow.onchange = () => setFollow(parseInt(follow.value, 10));
  document.addEventListener("keydown", onKey);
  window.addEventListener("resize", resize);
  const tip = $("tip");
  attachCamera($("view"), {
    onChange: () => { S.dirty = true; },
    onUnfollow: () => setFollow(-1),
    onClick: (x, y) => select(entityAt(M, S.poses, x, y)),
    onDouble: (x, y) => { const i = entityAt(M, S.poses, x, y); if (i >= 0) { select(i); setFollow(i); } },
    onHover: (x, y) => {
      const i = x < 0 ? -1 : entityAt(M, S.poses, x, y);
      if (i !== S.hovered) { S.hovered = i; S.dirty = true; }
      const lane = x < 0 || i >= 0 ? null : laneAt(...screenToWorld(x, y));
      if (i >= 0) {
        const e = M.entities[i], p = S.poses[i];
        tip.textContent = `${e.name}  ${p.v.toFixed(2)} m/s`;
      } else if (lane) {
        tip.textContent = `road ${lane.road.id}, lane ${lane.id} (${lane.type})`
          + (lane.road.junction !== null ? `, junction ${lane.road.junction}` : "")
          + `\nlane section s ${lane.sec.s0}–${lane.sec.s1} m`;
      }
      tip.hidden = !(i >= 0 || lane);
      tip.style.left = x + 14 + "px";
      tip.style.top = y + 10 + "px";
    },
  });
  const tl = $("timeline"), ttip = $("ttip");
  tl.addEventListener("mousemove", (ev) => timelineHover(ev.offsetX, ev.offsetY, ttip));
  tl.addEventListener("mouseleave", () => { ttip.hidden = true; });
  tl.addEventListener("click", (ev) => { setPlaying(false); setTime(timelineClick(ev.offsetX)); });
}

// Reads the canvas pixel at CSS point (x, y): [r, g, b, a].
function pixel(x, y) {
  const ctx = $("view").getContext("2d");
  return Array.from(ctx.getImageData(Math.round(x * Cam.dpr), Math.round(y * Cam.dpr), 1, 1).data);
}

function state() {
  const M = S.M;
  return {
    time: S.t, drawnTime: S.drawnT, frame: S.frame[0], fraction: S.frame[1], playing: S.playing, rate: S.rate,
    camera: { cx: Cam.cx + M.ox, cy: Cam.cy + M.oy, scale: Cam.scale, width: Cam.width, height: Cam.height, dpr: Cam.dpr, follow: Cam.follow },
    drawMs: S.drawMs,
    entities: M.entities.map((e, i) => {
      const p = S.poses[i];
      if (!p) return { name: e.name, present: false };
      const c = local(p, e.box[0], e.box[1]);
      return { name: e.name, present: true, x: p.x + M.ox, y: p.y + M.oy, h: p.h, speed: p.v,
        color: e.color, screen: worldToScreen(p.x, p.y), center: worldToScreen(c[0], c[1]) };
    }),
  };
}

// Draws n frames spread over the run and returns the mean and worst drawing time (ms).
function benchmark(n) {
  const t0 = S.t, times = [];
  for (let j = 0; j < n; j++) {
    setTime(tStart() + ((tEnd() - tStart()) * j) / Math.max(n - 1, 1));
    const a = performance.now();
    draw();
    times.push(performance.now() - a);
  }
  setTime(t0);
  draw();
  const mean = times.reduce((a, b) => a + b, 0) / times.length;
  return { frames: n, meanMs: mean, maxMs: Math.max(...times), fps: 1000 / mean };
}

window.oscsimReplay = {
  ready,
  setTime: (t) => { setTime(t); draw(); },
  state, pixel, benchmark,
  fit: () => { fit(); draw(); },
  // Selects (and with follow = true follows) the entity called name.
  select: (name, follow) => {
    const i = S.M.byName.has(name) ? S.M.byName.get(name) : -1;
    select(i);
    if (follow) setFollow(i);
    draw();
  },
  // Sets the camera: centre (world metres) and scale (pixels per metre); stops following.
  setView: (cx, cy, scale) => { setFollow(-1); Cam.cx = cx - S.M.ox; Cam.cy = cy - S.M.oy; Cam.scale = scale; draw(); },
  worldToScreen: (x, y) => worldToScreen(x - S.M.ox, y - S.M.oy),
};

async function main() {
  try {
    const M = await decodeData($("oscsim-data").textContent);
    S.M = M;
    buildRoads(M);
    wire(M);
    resize();
    setupTimeline(M, $("timeline"));
    buildCharts(M, $("charts"), (t) => { setPlaying(false); setTime(t); });
    fit();
    setTime(tStart());
    draw();
    S.dirty = false;
    requestAnimationFrame((now) => { S.lastNow = now; loop(now); });
    readyResolve(true);
  } catch (err) {
    fail(err);
  }
}

main();
