/* tarsim serve: the mechanism drawn on paper, and the tools that build it by clicking.
   World coordinates are the file's (its length unit, y up); the view maps them to the
   screen. A click is snapped to a tenth of the grid's step; exact numbers are typed in the
   property panel (app_panel.js). */
"use strict";
const Editor = (() => {
  const NS = "http://www.w3.org/2000/svg";
  const COLOURS = ["#1f5fa8", "#2e7d32", "#b45309", "#7b1fa2", "#00838f", "#ad1457", "#5d4037", "#455a64"];
  const colour = n => COLOURS[(n - 2) % COLOURS.length];
  const TOOLS = ["select", "ground", "pin", "link", "block", "slot", "wheel", "delete"];
  const ICONS = {
    select: '<path d="M4 2l11 8-5 1 3 6-2 1-3-6-4 4z" fill="currentColor"/>',
    ground: '<circle cx="9" cy="7" r="3" fill="none" stroke="currentColor" stroke-width="1.6"/><path d="M4 15l5-6 5 6z M2 15h14 M4 15l-2 3 M8 15l-2 3 M12 15l-2 3 M16 15l-2 3" fill="none" stroke="currentColor" stroke-width="1.4"/>',
    pin: '<circle cx="9" cy="9" r="4" fill="none" stroke="currentColor" stroke-width="2"/>',
    link: '<path d="M3 14L15 4" stroke="currentColor" stroke-width="4" stroke-linecap="round"/><circle cx="3" cy="14" r="2" fill="#fff"/><circle cx="15" cy="4" r="2" fill="#fff"/>',
    block: '<rect x="5" y="5" width="8" height="6" fill="none" stroke="currentColor" stroke-width="1.8"/><path d="M1 13h16 M3 13l-2 3 M7 13l-2 3 M11 13l-2 3 M15 13l-2 3" stroke="currentColor" stroke-width="1.4"/>',
    slot: '<path d="M2 6h14M2 12h14" stroke="currentColor" stroke-width="1.5"/><rect x="6" y="7" width="6" height="4" fill="currentColor"/>',
    wheel: '<circle cx="9" cy="8" r="6" fill="none" stroke="currentColor" stroke-width="1.8"/><circle cx="9" cy="8" r="1.3" fill="currentColor"/><path d="M1 15h16" stroke="currentColor" stroke-width="1.6"/>',
    delete: '<path d="M4 4l10 10M14 4L4 14" stroke="currentColor" stroke-width="2.2" stroke-linecap="round"/>',
  };
  let app, svg, view = { s: 1.1, cx: 150, cy: 90 }, pending = null, drag = null;

  function init(a) {
    app = a; svg = document.getElementById("editor");
    svg.addEventListener("pointerdown", down);
    svg.addEventListener("pointermove", move);
    svg.addEventListener("pointerup", up);
    svg.addEventListener("wheel", e => {
      e.preventDefault();
      const [x, y] = world(e), k = e.deltaY < 0 ? 1.15 : 1 / 1.15;
      view.s *= k; view.cx = x - (x - view.cx) / k; view.cy = y - (y - view.cy) / k; draw();
    }, { passive: false });
    new ResizeObserver(() => draw()).observe(svg);
    window.addEventListener("keydown", e => {
      if (e.key === "Escape") { pending = null; setTool("select"); }
      if ((e.key === "Delete" || e.key === "Backspace") && app.selected && e.target === document.body) {
        Model.remove(app.model, app.selected); app.selected = null; app.changed();
      }
    });
  }

  function toolbar(t) {
    const nav = document.getElementById("tools");
    nav.innerHTML = TOOLS.map(k => `<button type="button" data-tool="${k}" title="${t(k + "_t")}">` +
      `<svg viewBox="0 0 18 18" aria-hidden="true">${ICONS[k]}</svg><span>${t(k)}</span></button>`).join("") +
      `<button type="button" id="fit" title="${t("fit_t")}">${t("fit")}</button>` +
      `<label><input type="checkbox" id="snap" checked> ${t("snap")}</label>`;
    nav.querySelectorAll("[data-tool]").forEach(b => b.onclick = () => setTool(b.dataset.tool));
    document.getElementById("fit").onclick = () => { fit(); draw(); };
    setTool(app.tool);
  }

  function setTool(k) {
    app.tool = k; pending = null;
    document.querySelectorAll("#tools [data-tool]").forEach(b => b.classList.toggle("on", b.dataset.tool === k));
    svg.setAttribute("class", "tool-" + k);
    draw();
  }

  // --- the view ---------------------------------------------------------------------------
  const size = () => [svg.clientWidth || 600, svg.clientHeight || 400];
  function screen([x, y]) {
    const [w, h] = size();
    return [w / 2 + (x - view.cx) * view.s, h / 2 - (y - view.cy) * view.s];
  }
  function world(e) {
    const r = svg.getBoundingClientRect(), [w, h] = size();
    return [view.cx + (e.clientX - r.left - w / 2) / view.s, view.cy - (e.clientY - r.top - h / 2) / view.s];
  }
  /** Where on the page a point of the mechanism is drawn (client pixels): for clicking it. */
  function pageXY(xy) {
    const r = svg.getBoundingClientRect(), [x, y] = screen(xy);
    return [r.left + x, r.top + y];
  }
  function gridStep() {
    const raw = 60 / view.s, p = 10 ** Math.floor(Math.log10(raw));
    return [1, 2, 5, 10].map(k => k * p).find(v => v >= raw);
  }
  const minor = () => gridStep() / 10;
  function snap(xy) {
    if (!document.getElementById("snap")?.checked) return xy;
    const g = minor();
    return xy.map(v => Math.round(v / g) * g);
  }
  function fit() {
    const pos = app.positions(), pts = Object.values(pos);
    for (const c of app.model.ex.contact ?? []) {          // a wheel's whole circle
      const [x, y] = pos[c.circle.centre] ?? [NaN, NaN], r = c.circle.radius;
      if (Number.isFinite(x)) pts.push([x - r, y - r], [x + r, y + r]);
    }
    if (!pts.length) { view = { s: 1.1, cx: 150, cy: 90 }; return; }
    const xs = pts.map(p => p[0]), ys = pts.map(p => p[1]);
    const [w, h] = size();
    const bw = Math.max(...xs) - Math.min(...xs) || 100, bh = Math.max(...ys) - Math.min(...ys) || 100;
    view.s = Math.min((w - 120) / bw, (h - 120) / bh);
    view.cx = (Math.max(...xs) + Math.min(...xs)) / 2; view.cy = (Math.max(...ys) + Math.min(...ys)) / 2;
  }

  // --- hits -------------------------------------------------------------------------------
  function hit(e) {
    const r = svg.getBoundingClientRect(), at = [e.clientX - r.left, e.clientY - r.top];
    const pos = app.positions();
    let best = null, bd = 11;
    for (const [p, xy] of Object.entries(pos)) {
      const [x, y] = screen(xy), d = Math.hypot(x - at[0], y - at[1]);
      if (d < bd) { bd = d; best = { point: p }; }
    }
    if (best) return best;
    bd = 8;
    for (const l of app.model.ex.link) {
      const xy = l.points.map(p => pos[p]).filter(Boolean).map(screen);
      for (let i = 0; i < xy.length; i++) for (let j = i + 1; j < xy.length; j++) {
        const d = segDist(at, xy[i], xy[j]);
        if (d < bd) { bd = d; best = { link: l.number }; }
      }
    }
    if (best) return best;
    (app.model.ex.contact ?? []).forEach((c, i) => {
      const ctr = pos[c.circle.centre]; if (!ctr) return;
      const [x, y] = screen(ctr), d = Math.abs(Math.hypot(x - at[0], y - at[1]) - c.circle.radius * view.s);
      if (d < 7) best = { contact: i };
    });
    return best;
  }
  function segDist(p, a, b) {
    const [dx, dy] = [b[0] - a[0], b[1] - a[1]], L = dx * dx + dy * dy;
    const t = L ? Math.max(0, Math.min(1, ((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / L)) : 0;
    return Math.hypot(p[0] - a[0] - t * dx, p[1] - a[1] - t * dy);
  }

  // --- the tools --------------------------------------------------------------------------
  function down(e) {
    const m = app.model, h = hit(e), xy = snap(world(e));
    const moving = h?.point && !Model.isFrame(m, h.point);
    switch (app.tool) {
      case "select":
        app.select(h);
        if (h?.point) { drag = { point: h.point, moved: false }; svg.setPointerCapture(e.pointerId); }
        else if (!h) { drag = { pan: [e.clientX, e.clientY, view.cx, view.cy] }; svg.setPointerCapture(e.pointerId); }
        return;
      case "ground":
        if (h?.point) return app.select(h);
        return app.select({ point: Model.addGround(m, xy) }, true);
      case "pin":
        if (h?.point) return app.select(h);
        return app.select({ point: Model.addPin(m, xy) }, true);
      case "link": {
        const p = h?.point ?? Model.addPin(m, xy);
        if (!pending) { pending = p; app.select({ point: p }, !h?.point); return; }
        if (p === pending) return;
        const l = Model.addLink(m, pending, p);
        pending = null;
        app.select({ link: l.number }, true);
        const len = document.getElementById("l-len-0");     // the length, ready to be typed
        len?.focus(); len?.select();
        return;
      }
      case "block":
        if (moving) { Model.addBlock(m, h.point); return app.select({ slider: m.ex.slider.length - 1 }, true); }
        return;
      case "slot":
        if (moving && !pending) { pending = h.point; app.select(h); return; }
        if (pending && h?.link) {
          Model.addBlock(m, pending, h.link); pending = null;
          return app.select({ slider: m.ex.slider.length - 1 }, true);
        }
        return;
      case "wheel":
        if (moving) { Model.addWheel(m, h.point, Model.round(gridStep() / 2, 3)); return app.select({ contact: m.ex.contact.length - 1 }, true); }
        return;
      case "delete":
        if (h) { Model.remove(m, h); app.selected = null; app.changed(); }
    }
  }
  function move(e) {
    if (!drag) return;
    if (drag.pan) {
      const [x0, y0, cx, cy] = drag.pan;
      view.cx = cx - (e.clientX - x0) / view.s; view.cy = cy + (e.clientY - y0) / view.s; draw(); return;
    }
    const m = app.model, xy = snap(world(e)).map(v => Model.round(v, 3));
    const crank = Model.link(m, m.ex.input?.link);
    if (app.solution && !app.error && !m.ex.input.from && crank?.points[1] === drag.point &&
        Model.isFrame(m, crank.points[0])) {
      // The input's moving end, once solved, turns the input as the slider does.
      const [px, py] = m.ex.frame[crank.points[0]], [x, y] = world(e);
      app.turn(Math.round(Math.atan2(y - py, x - px) * 180 / Math.PI));
      return;
    }
    if (Model.isFrame(m, drag.point)) m.ex.frame[drag.point] = xy;
    m.sketch[drag.point] = xy; drag.moved = true;
    app.dragging(drag.point); draw();
  }
  function up() {
    if (drag?.moved) app.changed();
    drag = null;
  }

  // --- drawing ----------------------------------------------------------------------------
  const el = (tag, attrs, parent) => {
    const n = document.createElementNS(NS, tag);
    for (const [k, v] of Object.entries(attrs)) n.setAttribute(k, v);
    parent?.appendChild(n); return n;
  };

  function draw() {
    if (!svg) return;
    const m = app.model, pos = app.positions(), sel = app.selected ?? {}, bad = app.error?.where ?? {};
    const [w, h] = size();
    svg.setAttribute("viewBox", `0 0 ${w} ${h}`);
    svg.setAttribute("direction", "ltr");
    svg.replaceChildren();
    grid(w, h);
    const g = el("g", {}, svg);
    (m.ex.slider ?? []).forEach((s, i) => guide(g, s, i, pos, sel));
    (m.ex.contact ?? []).forEach((c, i) => wheel(g, c, i, pos, sel));
    for (const l of m.ex.link) {
      const xy = l.points.map(p => pos[p]).filter(Boolean).map(screen);
      const isSel = sel.link === l.number, isBad = bad.link === l.number;
      const stroke = isBad ? "var(--hot)" : colour(l.number);
      if (xy.length >= 3) {
        el("polygon", { points: xy.map(p => p.join(",")).join(" "), fill: stroke, "fill-opacity": .15,
                        stroke, "stroke-width": isSel ? 5 : 3, "stroke-linejoin": "round",
                        "data-link": l.number }, g);
      } else if (xy.length === 2) {
        if (isSel) el("line", { x1: xy[0][0], y1: xy[0][1], x2: xy[1][0], y2: xy[1][1], stroke: "var(--sel)",
                                "stroke-width": 12, "stroke-linecap": "round", opacity: .5 }, g);
        el("line", { x1: xy[0][0], y1: xy[0][1], x2: xy[1][0], y2: xy[1][1], stroke,
                     "stroke-width": isBad ? 6 : 5, "stroke-linecap": "round", "data-link": l.number,
                     "stroke-dasharray": isBad ? "10 5" : "none" }, g);
      }
      if (xy.length >= 2) {
        const c = [xy.reduce((a, p) => a + p[0], 0) / xy.length, xy.reduce((a, p) => a + p[1], 0) / xy.length];
        const [dx, dy] = [xy[1][0] - xy[0][0], xy[1][1] - xy[0][1]], L = Math.hypot(dx, dy) || 1;
        const at = [c[0] - dy / L * 14, c[1] + dx / L * 14];
        el("circle", { cx: at[0], cy: at[1], r: 9, fill: "#fff", stroke, "stroke-width": 1.5 }, g);
        const t = el("text", { x: at[0], y: at[1] + 4, "text-anchor": "middle", "font-size": 11, fill: stroke,
                               "data-link-label": l.number }, g);
        t.textContent = l.number;
      }
    }
    inputArrow(g, pos);
    for (const [p, xy] of Object.entries(pos)) point(g, p, screen(xy), sel.point === p || pending === p, bad.joint === p);
    placeBubble();
  }

  function grid(w, h) {
    const step = gridStep(), g = el("g", { stroke: "#eef0f3" }, svg);
    const [x0, y1] = [view.cx - w / 2 / view.s, view.cy + h / 2 / view.s];
    const [x1, y0] = [view.cx + w / 2 / view.s, view.cy - h / 2 / view.s];
    for (let x = Math.ceil(x0 / step) * step; x <= x1; x += step) {
      const [sx] = screen([x, 0]); el("line", { x1: sx, y1: 0, x2: sx, y2: h, stroke: Math.abs(x) < 1e-9 ? "#cfd5dc" : undefined }, g);
    }
    for (let y = Math.ceil(y0 / step) * step; y <= y1; y += step) {
      const [, sy] = screen([0, y]); el("line", { x1: 0, y1: sy, x2: w, y2: sy, stroke: Math.abs(y) < 1e-9 ? "#cfd5dc" : undefined }, g);
    }
    const t = el("text", { x: w - 8, y: h - 8, "text-anchor": "end", "font-size": 11, fill: "#8a939e" }, svg);
    t.textContent = `${t.textContent}□ ${+step.toPrecision(3)} ${app.model.ex.units?.length ?? "mm"}`;
  }

  function point(g, p, [x, y], isSel, isBad) {
    const m = app.model, frame = Model.isFrame(m, p);
    const ring = isBad ? "var(--hot)" : isSel ? "var(--sel)" : "#1b1f24";
    if (frame && m.ex.link.some(l => l.points.includes(p)) || frame && !Object.values(m.ex.contact ?? []).some(c => c.face.through === p)) {
      el("path", { d: `M${x},${y} l-9,14 h18 z`, fill: "#fff", stroke: ring, "stroke-width": 1.5 }, g);
      el("path", { d: `M${x - 13},${y + 14} h26` + [-12, -6, 0, 6].map(k => ` M${x + k + 6},${y + 14} l-5,6`).join(""),
                   stroke: ring, "stroke-width": 1.2 }, g);
    }
    el("circle", { cx: x, cy: y, r: isSel ? 6.5 : 5, fill: "#fff", stroke: ring, "stroke-width": isSel || isBad ? 3 : 2,
                   "data-point": p }, g);
    const t = el("text", { x: x + 9, y: y - 8, "font-size": 13, "font-weight": "bold", fill: isBad ? "var(--hot)" : "#1b1f24",
                           "paint-order": "stroke", stroke: "#fff", "stroke-width": 3, "data-point-label": p }, g);
    t.textContent = p;
  }

  function guide(g, s, i, pos, sel) {
    const p = pos[s.point]; if (!p) return;
    const isSel = sel.slider === i, c = isSel ? "var(--sel)" : "#555";
    let ang;
    if (s.on === 1) {
      ang = (s.angle ?? 0) * (app.model.ex.units?.angle === "rad" ? 1 : Math.PI / 180);
      const th = typeof s.through === "string" ? pos[s.through] : s.through;
      if (th) {
        const off = s.offset ?? 0, n = [-Math.sin(ang), Math.cos(ang)];
        const base = [th[0] + n[0] * off, th[1] + n[1] * off];
        const [a, b] = [[base[0] - Math.cos(ang) * 1e4, base[1] - Math.sin(ang) * 1e4], [base[0] + Math.cos(ang) * 1e4, base[1] + Math.sin(ang) * 1e4]].map(screen);
        el("line", { x1: a[0], y1: a[1], x2: b[0], y2: b[1], stroke: c, "stroke-width": 1.3, "stroke-dasharray": "8 4", "data-slider": i }, g);
      }
    } else {
      const l = Model.link(app.model, s.on), q = l && pos[l.points[0]];
      ang = q ? Math.atan2(p[1] - q[1], p[0] - q[0]) : 0;
      if (q) { const [a, b] = [screen(q), screen(p)];
        el("line", { x1: a[0], y1: a[1], x2: b[0], y2: b[1], stroke: colour(s.on), "stroke-width": 9, opacity: .25 }, g); }
    }
    if (s.kind === "pin") return;
    const [x, y] = screen(p), deg = -ang * 180 / Math.PI;
    el("rect", { x: x - 15, y: y - 9, width: 30, height: 18, rx: 2, fill: "#fff", stroke: c,
                 "stroke-width": isSel ? 3 : 1.8, transform: `rotate(${deg} ${x} ${y})`, "data-slider": i }, g);
  }

  function wheel(g, c, i, pos, sel) {
    const p = pos[c.circle.centre]; if (!p) return;
    const [x, y] = screen(p), r = c.circle.radius * view.s, isSel = sel.contact === i;
    el("circle", { cx: x, cy: y, r, fill: "#f7f9fb", stroke: isSel ? "var(--sel)" : colour(c.circle.link),
                   "stroke-width": isSel ? 3.5 : 2, "data-contact": i }, g);
    const f = c.face, th = typeof f.through === "string" ? pos[f.through] : f.through;
    if (f.link === 1 && th) {
      const ang = (f.angle ?? 0) * Math.PI / 180;
      const [a, b] = [[th[0] - Math.cos(ang) * 1e4, th[1] - Math.sin(ang) * 1e4], [th[0] + Math.cos(ang) * 1e4, th[1] + Math.sin(ang) * 1e4]].map(screen);
      el("line", { x1: a[0], y1: a[1], x2: b[0], y2: b[1], stroke: "#555", "stroke-width": 1.6 }, g);
    }
  }

  function inputArrow(g, pos) {
    const m = app.model, l = Model.link(m, m.ex.input?.link);
    if (!l || !pos[l.points[0]] || !Model.isFrame(m, l.points[0])) return;
    const [x, y] = screen(pos[l.points[0]]), r = 24, ccw = (Number(m.ex.input.omega) || 1) >= 0;
    const a0 = 0.3, a1 = 1.9, pt = a => [x + r * Math.cos(a), y - r * Math.sin(a)];
    const [s, e] = ccw ? [pt(a0), pt(a1)] : [pt(a1), pt(a0)];
    el("path", { d: `M${s[0]},${s[1]} A${r},${r} 0 0 ${ccw ? 0 : 1} ${e[0]},${e[1]}`, fill: "none",
                 stroke: colour(l.number), "stroke-width": 1.8, "marker-end": "url(#arrow)" }, g);
    const defs = el("defs", {}, svg);
    const mk = el("marker", { id: "arrow", viewBox: "0 0 10 10", refX: 8, refY: 5, markerWidth: 7, markerHeight: 7, orient: "auto-start-reverse" }, defs);
    el("path", { d: "M0,0 L10,5 L0,10 z", fill: colour(l.number) }, mk);
    const tip = pt(ccw ? a1 + 0.45 : a0 - 0.45);
    const t = el("text", { x: tip[0], y: tip[1] + 4, "font-size": 12, fill: colour(l.number),
                           "text-anchor": ccw ? "end" : "start" }, g);
    t.textContent = "ω" + l.number;
  }

  /** The server's one line, beside the link or point it names (or at the top if none). */
  function placeBubble() {
    const b = document.getElementById("bubble"), err = app.error;
    if (!err) { b.hidden = true; return; }
    b.hidden = false; b.textContent = "⚠ " + err.text;
    const pos = app.positions(), w = err.where ?? {};
    let at = null;
    if (w.link) {
      const l = Model.link(app.model, w.link), xy = l?.points.map(p => pos[p]).filter(Boolean) ?? [];
      if (xy.length) at = screen([xy.reduce((a, p) => a + p[0], 0) / xy.length, xy.reduce((a, p) => a + p[1], 0) / xy.length]);
    } else if (w.joint && pos[w.joint]) at = screen(pos[w.joint]);
    const [W, H] = size();
    if (!at) { b.style.left = "8px"; b.style.top = "2.2em"; return; }
    // Near the part, where it hides the least of the drawing: below, above, right or left
    // of it, nearest first; a point hidden counts as much as 10 px of a link.
    const [bw, bh] = [Math.min(b.offsetWidth || 300, W - 16), b.offsetHeight || 40];
    const clampX = x => Math.max(8, Math.min(W - bw - 8, x)), clampY = y => Math.max(4, Math.min(H - bh - 4, y));
    const places = [];
    for (const d of [22, 60, 110]) {
      places.push([clampX(at[0] - bw / 2), clampY(at[1] + d)], [clampX(at[0] - bw / 2), clampY(at[1] - d - bh)],
                  [clampX(at[0] + d), clampY(at[1] - bh / 2)], [clampX(at[0] - d - bw), clampY(at[1] - bh / 2)]);
    }
    const marks = Object.values(pos).flatMap(p => { const [x, y] = screen(p); return [[x, y, 10], [x + 14, y - 12, 10]]; });
    for (const l of app.model.ex.link) {
      const xy = l.points.map(p => pos[p]).filter(Boolean).map(screen);
      for (let i = 1; i < xy.length; i++) {
        const n = Math.ceil(Math.hypot(xy[i][0] - xy[0][0], xy[i][1] - xy[0][1]) / 10);
        for (let k = 0; k <= n; k++) marks.push([xy[0][0] + (xy[i][0] - xy[0][0]) * k / n, xy[0][1] + (xy[i][1] - xy[0][1]) * k / n, 1]);
      }
    }
    const hidden = ([x, y]) => marks.reduce((sum, [px, py, w]) =>
      sum + (px > x - 8 && px < x + bw + 8 && py > y - 8 && py < y + bh + 8 ? w : 0), 0);
    let best = places[0], least = Infinity;
    for (const p of places) { const h = hidden(p); if (h < least) { least = h; best = p; } }
    b.style.left = best[0] + "px"; b.style.top = best[1] + "px";
  }

  return { init, toolbar, setTool, draw, fit, pageXY, colour };
})();
