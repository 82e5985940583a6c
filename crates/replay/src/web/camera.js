// camera.js: the view of the world (x right, y up, metres relative to the model's origin) on
// the canvas (CSS pixels, y down): centre, scale in pixels per metre, an entity to follow;
// pan by dragging, zoom with the wheel about the pointer.

const Cam = { cx: 0, cy: 0, scale: 4, follow: -1, width: 1, height: 1, dpr: 1 };

function worldToScreen(x, y) {
  return [(x - Cam.cx) * Cam.scale + Cam.width / 2, Cam.height / 2 - (y - Cam.cy) * Cam.scale];
}

function screenToWorld(px, py) {
  return [(px - Cam.width / 2) / Cam.scale + Cam.cx, Cam.cy - (py - Cam.height / 2) / Cam.scale];
}

// Sets ctx to draw in world metres.
function worldTransform(ctx) {
  const s = Cam.scale * Cam.dpr;
  ctx.setTransform(s, 0, 0, -s, Cam.dpr * (Cam.width / 2) - s * Cam.cx, Cam.dpr * (Cam.height / 2) + s * Cam.cy);
}

function screenTransform(ctx) {
  ctx.setTransform(Cam.dpr, 0, 0, Cam.dpr, 0, 0);
}

// Fits the box [x0, y0, x1, y1] (world, relative to the origin) with a margin.
function fitBox(box) {
  const w = Math.max(box[2] - box[0], 10), h = Math.max(box[3] - box[1], 10);
  Cam.cx = (box[0] + box[2]) / 2;
  Cam.cy = (box[1] + box[3]) / 2;
  Cam.scale = Math.min(Cam.width / (w * 1.1), Cam.height / (h * 1.1));
}

function zoomAbout(px, py, factor) {
  const [wx, wy] = screenToWorld(px, py);
  Cam.scale = Math.min(Math.max(Cam.scale * factor, 0.005), 500);
  if (Cam.follow < 0) {
    // Keep the world point under the pointer where it is.
    Cam.cx = wx - (px - Cam.width / 2) / Cam.scale;
    Cam.cy = wy + (py - Cam.height / 2) / Cam.scale;
  }
}

// Mouse handling on `canvas`: drag pans (and ends following), wheel zooms; `onChange` redraws,
// `onClick(px, py)`, `onDouble(px, py)` and `onHover(px, py)` for picking.
function attachCamera(canvas, hooks) {
  let drag = null;
  canvas.addEventListener("mousedown", (ev) => {
    drag = { x: ev.offsetX, y: ev.offsetY, moved: false };
  });
  window.addEventListener("mouseup", (ev) => {
    if (drag && !drag.moved && ev.target === canvas) hooks.onClick(ev.offsetX, ev.offsetY);
    drag = null;
    canvas.classList.remove("dragging");
  });
  canvas.addEventListener("mousemove", (ev) => {
    if (drag) {
      const dx = ev.offsetX - drag.x, dy = ev.offsetY - drag.y;
      if (!drag.moved && Math.hypot(dx, dy) < 3) return;
      drag.moved = true;
      canvas.classList.add("dragging");
      if (Cam.follow >= 0) hooks.onUnfollow();
      Cam.cx -= dx / Cam.scale;
      Cam.cy += dy / Cam.scale;
      drag.x = ev.offsetX;
      drag.y = ev.offsetY;
      hooks.onChange();
    } else {
      hooks.onHover(ev.offsetX, ev.offsetY);
    }
  });
  canvas.addEventListener("mouseleave", () => hooks.onHover(-1, -1));
  canvas.addEventListener("dblclick", (ev) => hooks.onDouble(ev.offsetX, ev.offsetY));
  canvas.addEventListener("wheel", (ev) => {
    ev.preventDefault();
    zoomAbout(ev.offsetX, ev.offsetY, Math.exp(-ev.deltaY * 0.0015));
    hooks.onChange();
  }, { passive: false });
}
