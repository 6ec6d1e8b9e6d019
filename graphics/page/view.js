/* tarsim view: step through a construction and turn the mechanism, offline.
 *
 * Everything drawn comes from the page's JSON (exercises/view.py): the steps of each
 * figure at the exercise's position, and the frames of a revolution, each placed by
 * tarsim's constructions and checked against its analytic solver. The page draws those
 * numbers and nothing else: no frame is interpolated, no geometry is computed here.
 */
"use strict";

const D = JSON.parse(document.getElementById("data").textContent);
const NS = "http://www.w3.org/2000/svg";
const PANELS = ["space", "velocity", "acceleration"];
const TIP_MARK = {velocity: "", acceleration: "′"};
const S = {lang: "en", fig: 0, step: 0, frame: 0, playing: null, drag: null,
           layers: {kennedy: true, construction: true, labels: true, numbers: true},
           views: {}, times: []};

// ----- the steps of the chosen figure ------------------------------------------------------
function parts() { return D.figures.length ? D.figures[S.fig].parts : []; }

/* The numbered steps, in the order steps.md lists them: [part, number, words]. */
function numbered() {
  const out = [];
  parts().forEach((part, p) => part.steps.forEach(st => {
    if (st.said) out.push({part: p, n: st.n, said: st.said});
  }));
  return out;
}

/* How a drawn step stands against the current one: "done", "current" or "later". */
function stage(p, n) {
  const list = numbered();
  if (!list.length || S.step < 0) return "later";
  const cur = list[Math.min(S.step, list.length - 1)];
  if (p < cur.part || (p === cur.part && n < cur.n)) return "done";
  return p === cur.part && n === cur.n ? "current" : "later";
}

// ----- world to panel ----------------------------------------------------------------------
function pts(panel) {
  const out = [];
  const push = xy => { if (xy && isFinite(xy[0]) && isFinite(xy[1])) out.push(xy); };
  for (const f of D.frames) {
    if (!f.p) continue;
    if (panel === "space") for (let i = 0; i < f.p.length; i += 2) push([f.p[i], f.p[i + 1]]);
    const key = panel === "velocity" ? "v" : "a";
    if (panel !== "space") { push(f[key + "o"]); Object.values(f[key]).forEach(push); }
  }
  parts().forEach(part => {
    if (part.panel !== panel) return;
    part.steps.forEach(st => {
      const d = st.draw || {};
      if (d.pt) push(d.pt);
      if (d.seg) { push(d.seg.slice(0, 2)); push(d.seg.slice(2)); }
    });
  });
  return out;
}

function fit(panel) {
  const svg = svgOf(panel), box = svg.getBoundingClientRect();
  const w = box.width || 600, h = box.height || 400, all = pts(panel);
  if (!all.length) return {cx: 0, cy: 0, k: 1, w, h};
  let [x0, y0, x1, y1] = [Infinity, Infinity, -Infinity, -Infinity];
  for (const [x, y] of all) { x0 = Math.min(x0, x); x1 = Math.max(x1, x);
                              y0 = Math.min(y0, y); y1 = Math.max(y1, y); }
  const span = Math.max(x1 - x0, y1 - y0, 1e-9);
  const k = 0.86 * Math.min(w / Math.max(x1 - x0, span * 0.05), h / Math.max(y1 - y0, span * 0.05));
  return {cx: (x0 + x1) / 2, cy: (y0 + y1) / 2, k, w, h};
}

function svgOf(panel) { return document.querySelector(`#${panel} svg`); }
function px(v, xy) { return [v.w / 2 + (xy[0] - v.cx) * v.k, v.h / 2 - (xy[1] - v.cy) * v.k]; }
function world(panel, x, y) {
  const v = S.views[panel];
  return [v.cx + (x - v.w / 2) / v.k, v.cy - (y - v.h / 2) / v.k];
}
const f3 = x => x.toFixed(2);

// ----- drawing -----------------------------------------------------------------------------
function esc(t) { return String(t).replace(/[&<>"]/g, c => `&#${c.charCodeAt(0)};`); }

function label(v, xy, text, cls, dx = 6, dy = -6) {
  if (!S.layers.labels || !text) return "";
  const [x, y] = px(v, xy);
  return `<text class="${cls}" x="${f3(x + dx)}" y="${f3(y + dy)}">${esc(text)}</text>`;
}

function arrow(v, a, b, cls, attrs = "") {
  const [x0, y0] = px(v, a), [x1, y1] = px(v, b);
  const len = Math.hypot(x1 - x0, y1 - y0);
  if (len < 0.5)            // a nil vector: its tip is its tail, drawn as the point it is
    return `<circle class="${cls} dot" ${attrs} cx="${f3(x1)}" cy="${f3(y1)}" r="2.5"/>`;
  const ux = (x1 - x0) / len, uy = (y1 - y0) / len, h = Math.min(9, len / 2);
  const head = `${f3(x1)},${f3(y1)} ${f3(x1 - h * ux + h * 0.35 * uy)},${f3(y1 - h * uy - h * 0.35 * ux)}`
             + ` ${f3(x1 - h * ux - h * 0.35 * uy)},${f3(y1 - h * uy + h * 0.35 * ux)}`;
  return `<g class="${cls}" ${attrs}><line x1="${f3(x0)}" y1="${f3(y0)}" x2="${f3(x1)}" y2="${f3(y1)}"/>`
       + `<polygon points="${head}"/></g>`;
}

function farLine(v, a, d, cls, attrs = "") {
  const L = 4 * (v.w + v.h) / v.k;
  const p = px(v, [a[0] - L * d[0], a[1] - L * d[1]]), q = px(v, [a[0] + L * d[0], a[1] + L * d[1]]);
  return `<line class="${cls}" ${attrs} x1="${f3(p[0])}" y1="${f3(p[1])}" x2="${f3(q[0])}" y2="${f3(q[1])}"/>`;
}

/* One step's mark, in the stage it is at (done, current). */
function stepMark(v, st, where, panel) {
  const d = st.draw, cls = `step ${where} ${st.layer}`, at = `data-n="${st.n}"`;
  if (!S.layers[st.layer === "kennedy" ? "kennedy" : "construction"] && !d.pt) return "";
  let s = "";
  if (d.pt) s += `<circle class="${cls} dot" ${at} cx="${f3(px(v, d.pt)[0])}" cy="${f3(px(v, d.pt)[1])}" r="3"/>`
               + label(v, d.pt, st.label, "steplabel");
  if (d.seg) s += d.dim ? `<line class="${cls}" ${at} x1="${f3(px(v, d.seg)[0])}" y1="${f3(px(v, d.seg)[1])}" `
                          + `x2="${f3(px(v, d.seg.slice(2))[0])}" y2="${f3(px(v, d.seg.slice(2))[1])}"/>`
                        : arrow(v, d.seg.slice(0, 2), d.seg.slice(2), cls, at)
                          + (where === "current" ? label(v, d.seg.slice(2), st.label, "steplabel") : "");
  if (d.line) s += farLine(v, d.line.slice(0, 2), d.line.slice(2), cls, at);
  if (d.circle) { const [x, y] = px(v, d.circle);
                  s += `<circle class="${cls} ring" ${at} cx="${f3(x)}" cy="${f3(y)}" r="${f3(d.circle[2] * v.k)}"/>`; }
  if (d.angle) {
    const [vx, vy, a0, sw, reach] = d.angle, r = 0.35 * reach * v.k, n = 24;
    const path = [...Array(n + 1).keys()].map(i => {
      const a = a0 + sw * i / n; const [x, y] = px(v, [vx, vy]);
      return `${i ? "L" : "M"}${f3(x + r * Math.cos(a))},${f3(y - r * Math.sin(a))}`; }).join(" ");
    s += `<path class="${cls} ring" ${at} d="${path}"/>`;
  }
  if (S.layers.numbers && where === "current") {
    const xy = d.pt || d.seg?.slice(2) || d.line?.slice(0, 2) || d.circle || d.angle;
    if (xy) s += label(v, xy, String(st.n), "number", -14, 14);
  }
  return s;
}

function drawSpace(f) {
  const v = S.views.space, at = i => [f.p[2 * i], f.p[2 * i + 1]], idx = {};
  D.points.forEach((p, i) => { idx[p] = i; });
  let s = "";
  const here = S.frame === 0;
  if (here) parts().forEach((part, p) => {
    if (part.panel !== "space") return;
    part.steps.forEach(st => { const w = stage(p, st.n);
                               if (w !== "later" && st.draw) s += stepMark(v, st, w, "space"); });
  });
  if (!here || !parts().some(part => part.panel === "space")) s += drawCentres(f, v);
  for (const link of D.links) {
    if (link.number === 1) continue;
    const xy = link.points.map(p => px(v, at(idx[p])));
    s += xy.length > 2
      ? `<polygon class="link plate" points="${xy.map(q => q.map(f3).join(",")).join(" ")}"/>`
      : `<polyline class="link" points="${xy.map(q => q.map(f3).join(",")).join(" ")}"/>`;
  }
  for (const p of D.ground) {
    const [x, y] = px(v, at(idx[p]));
    s += `<path class="ground" d="M${f3(x)},${f3(y)} l-7,12 h14 z"/>`;
  }
  for (const p of D.slides) {
    const [x, y] = px(v, at(idx[p]));
    s += `<rect class="block" x="${f3(x - 7)}" y="${f3(y - 5)}" width="14" height="10"/>`;
  }
  D.points.forEach((p, i) => {
    const [x, y] = px(v, at(i));
    s += `<circle class="joint" data-point="${p}" cx="${f3(x)}" cy="${f3(y)}" r="3.5"/>`
       + label(v, at(i), p, "name");
  });
  return s;
}

function drawCentres(f, v) {
  let s = "";
  if (S.layers.kennedy) for (const c of D.centres) for (const [a, b] of c.lines) {
    const p = f.c[a], q = f.c[b];
    if (!p || !q) continue;
    const d = [q[0] - p[0], q[1] - p[1]], n = Math.hypot(...d);
    if (n > 0) s += farLine(v, p, [d[0] / n, d[1] / n], "kennedy");
  }
  for (const [name, xy] of Object.entries(f.c)) {
    if (!xy) continue;
    const [x, y] = px(v, xy);
    if (Math.abs(x) > 4 * v.w || Math.abs(y) > 4 * v.h) continue;
    s += `<circle class="centre" data-centre="${name}" cx="${f3(x)}" cy="${f3(y)}" r="2.5"/>`
       + label(v, xy, name, "centrelabel", 5, 12);
  }
  return s;
}

function drawPolygon(f, panel) {
  const v = S.views[panel], key = panel === "velocity" ? "v" : "a";
  let s = "";
  const stepped = S.frame === 0 && parts().some(part => part.panel === panel);
  if (stepped) parts().forEach((part, p) => {
    if (part.panel !== panel) return;
    part.steps.forEach(st => { const w = stage(p, st.n);
                               if (w !== "later" && st.draw) s += stepMark(v, st, w, panel); });
  });
  if (!f[key] || stepped) return s;   // the construction is the polygon at its own position
  const pole = f[key + "o"];
  for (const [name, tip] of Object.entries(f[key])) {
    if (D.ground.includes(name)) continue;          // a pivot's tip is the pole itself
    const attrs = `data-tip="${name}"`;
    s += arrow(v, pole, tip, `vector ${panel}`, attrs);
    const [x, y] = px(v, tip);
    s += `<circle class="tip" ${attrs} cx="${f3(x)}" cy="${f3(y)}" r="2"/>`
       + label(v, tip, name.toLowerCase() + TIP_MARK[panel], "tiplabel");
  }
  const [x, y] = px(v, pole);
  return s + `<circle class="pole" cx="${f3(x)}" cy="${f3(y)}" r="3"/>`
           + label(v, pole, panel === "velocity" ? "o" : "o′", "tiplabel", -12, 14);
}

const STYLE = `<style>
  .link{fill:none;stroke:#111;stroke-width:2.4;stroke-linejoin:round}
  .plate{fill:#eee}
  .ground{fill:#fff;stroke:#111;stroke-width:1.2}
  .block{fill:#fff;stroke:#111;stroke-width:1.4}
  .joint{fill:#fff;stroke:#111;stroke-width:1.4}
  .centre{fill:#111}
  .kennedy{stroke:#777;stroke-width:.8;stroke-dasharray:8 3 2 3}
  .step{fill:none;stroke:#444;stroke-width:1}
  .step.dot{fill:#444}
  .step polygon{fill:#444}
  .step.done{opacity:.35}
  .step.current{stroke:#c62828;stroke-width:2.2}
  .step.current.dot,.step.current polygon{fill:#c62828}
  g.step.current line{stroke:#c62828;stroke-width:2.2}
  g.step line{stroke:#444}
  .vector line{stroke-width:1.6}
  .vector.velocity line{stroke:#1f5fbf}.vector.velocity polygon{fill:#1f5fbf}
  .vector.acceleration line{stroke:#2e7d32}.vector.acceleration polygon{fill:#2e7d32}
  .tip{fill:#111}.pole{fill:#fff;stroke:#111}
  text{font:italic 13px "DejaVu Serif",serif;fill:#111}
  .number{font:bold 12px "DejaVu Sans",sans-serif;fill:#c62828}
  .centrelabel{font-size:11px;fill:#333}
</style>`;

function draw() {
  const t0 = performance.now();
  const f = D.frames[S.frame];
  for (const panel of PANELS) {
    const svg = svgOf(panel), v = S.views[panel];
    svg.setAttribute("viewBox", `0 0 ${v.w} ${v.h}`);
    if (!f.p) { svg.innerHTML = STYLE + `<text x="12" y="24">${esc(f.why || "")}</text>`; continue; }
    svg.innerHTML = STYLE + (panel === "space" ? drawSpace(f) : drawPolygon(f, panel));
  }
  drawSteps();
  drawReadout(f);
  drawCursor();
  S.times.push(performance.now() - t0);
}

// ----- the steps' list ---------------------------------------------------------------------
function drawSteps() {
  const ol = document.getElementById("steps"), list = numbered();
  ol.classList.toggle("rtl", S.lang === "fa");
  document.getElementById("readout").classList.toggle("rtl", S.lang === "fa");
  document.querySelectorAll("[data-ui]").forEach(el => {
    el.textContent = (D.ui[S.lang] || D.ui.en)[el.dataset.ui] || el.dataset.ui; });
  let html = "", last = -1;
  list.forEach((st, i) => {
    if (st.part !== last) { html += `<li class="part">${esc(parts()[st.part].title[S.lang])}</li>`; last = st.part; }
    const cls = i === S.step ? "current" : i < S.step ? "done" : "";
    html += `<li class="step ${cls}" data-i="${i}" data-n="${st.n}"><b>${st.n}.</b> ${esc(st.said[S.lang] || st.said.en)}</li>`;
  });
  ol.innerHTML = html || `<li>${S.lang === "fa" ? "این شکل مرحله‌ای ندارد." : "No construction steps in this figure."}</li>`;
  const stepper = document.getElementById("stepper");
  stepper.max = Math.max(0, list.length - 1);
  stepper.value = Math.max(0, S.step);
  ol.querySelector("li.current")?.scrollIntoView({block: "nearest"});
}

function drawReadout(f) {
  const deg = ((f.angle * 180 / Math.PI) % 360 + 360) % 360;
  const fa = S.lang === "fa";
  let state;
  if (!f.p) state = `<span class="bad">${fa ? "سرهم نمی‌شود" : "cannot be assembled"}: ${esc(f.why)}</span>`;
  else if (!f.ok) state = `<span class="bad">${fa ? "وارسی نادرست" : "check failed"}: ${esc(f.why)}</span>`;
  else state = fa ? "✓ با حل تحلیلی وارسی شد" : "✓ checked against the analytic solution";
  const steps = S.frame === 0 ? "" : (fa ? " — مراحل در وضعیت تمرین رسم شده‌اند" : " — the steps are drawn at the exercise's position (frame 1)");
  document.getElementById("readout").innerHTML =
    `θ${D.input.link} = ${deg.toFixed(1)}° (${fa ? "قاب" : "frame"} ${S.frame + 1}/${D.frames.length}) ${state}${steps}`;
  document.getElementById("angle").value = S.frame;
}

// ----- the output's curve ------------------------------------------------------------------
function drawPlot() {
  const svg = document.getElementById("plot"), box = svg.getBoundingClientRect();
  const w = box.width || 800, h = box.height || 100, vals = D.plot.values, n = vals.length;
  svg.setAttribute("viewBox", `0 0 ${w} ${h}`);
  const ok = vals.filter(x => x !== null), lo = Math.min(0, ...ok), hi = Math.max(0, ...ok);
  const y = x => h - 14 - (x - lo) / ((hi - lo) || 1) * (h - 28), x = k => 40 + k / (n - 1) * (w - 50);
  let d = "", pen = "M";
  vals.forEach((val, k) => { if (val === null) { pen = "M"; return; }
                             d += `${pen}${f3(x(k))},${f3(y(val))} `; pen = "L"; });
  const marks = D.marks.map(m => `<line x1="${f3(x(markFrame(m)))}" x2="${f3(x(markFrame(m)))}" y1="4" y2="${h - 10}" stroke="${m.kind === "dead" ? "#c62828" : "#999"}" stroke-dasharray="3 3"/>`).join("");
  svg.innerHTML = `<line x1="40" x2="${w - 10}" y1="${f3(y(0))}" y2="${f3(y(0))}" stroke="#ccc"/>${marks}`
    + `<path d="${d}" fill="none" stroke="#111" stroke-width="1.5"/>`
    + `<text x="4" y="14" style="font:italic 12px 'DejaVu Serif'">${esc(D.plot.symbol)} (${esc(D.plot.unit)})</text>`
    + `<line id="cursor" y1="4" y2="${h - 10}" stroke="#c62828" stroke-width="1.5"/>`;
  S.plotX = x;
  drawCursor();
}

function drawCursor() {
  const c = document.getElementById("cursor");
  if (c && S.plotX) { const x = S.plotX(S.frame); c.setAttribute("x1", x); c.setAttribute("x2", x); }
}

function markFrame(m) {
  const n = D.frames.length, t = (m.angle - D.input.angle) / D.input.step;
  return ((Math.round(t) % n) + n) % n;
}

// ----- input -------------------------------------------------------------------------------
function setFrame(k) {
  const n = D.frames.length;
  S.frame = ((Math.round(k) % n) + n) % n;
  draw();
}

function setStep(i) {
  S.step = Math.max(-1, Math.min(i, numbered().length - 1));
  if (S.frame !== 0) S.frame = 0;     // the steps belong to the exercise's position
  draw();
}

function crankPin() {
  const link = D.links.find(l => l.number === D.input.link);
  const pivot = link.points.find(p => D.ground.includes(p)) || link.points[0];
  const pin = link.points.find(p => p !== pivot);
  return [D.points.indexOf(pivot), D.points.indexOf(pin)];
}

function angleFrame(a) {
  const n = D.frames.length, tau = 2 * Math.PI;
  const t = (((a - D.input.angle) % tau) + tau) % tau;
  return D.input.step > 0 ? Math.round(t / D.input.step) % n
                          : Math.round((tau - t) / -D.input.step) % n;
}

function pointer(panel) {
  const svg = svgOf(panel);
  svg.addEventListener("pointerdown", e => {
    const r = svg.getBoundingClientRect(), x = e.clientX - r.left, y = e.clientY - r.top;
    const f = D.frames[S.frame];
    if (panel === "space" && f.p) {
      const [, pin] = crankPin(), [px0, py0] = px(S.views.space, [f.p[2 * pin], f.p[2 * pin + 1]]);
      if (Math.hypot(px0 - x, py0 - y) < 18) { S.drag = {crank: true}; svg.setPointerCapture(e.pointerId); return; }
    }
    S.drag = {panel, x, y, cx: S.views[panel].cx, cy: S.views[panel].cy};
    svg.setPointerCapture(e.pointerId);
  });
  svg.addEventListener("pointermove", e => {
    if (!S.drag) return;
    const r = svg.getBoundingClientRect(), x = e.clientX - r.left, y = e.clientY - r.top;
    if (S.drag.crank) {
      const [pivot] = crankPin(), f0 = D.frames[0];
      const [wx, wy] = world("space", x, y);
      setFrame(angleFrame(Math.atan2(wy - f0.p[2 * pivot + 1], wx - f0.p[2 * pivot])));
      return;
    }
    const v = S.views[S.drag.panel];
    v.cx = S.drag.cx - (x - S.drag.x) / v.k; v.cy = S.drag.cy + (y - S.drag.y) / v.k;
    draw();
  });
  svg.addEventListener("pointerup", () => { S.drag = null; });
  svg.addEventListener("wheel", e => {
    e.preventDefault();
    const r = svg.getBoundingClientRect(), x = e.clientX - r.left, y = e.clientY - r.top;
    const [wx, wy] = world(panel, x, y), v = S.views[panel], z = Math.exp(-e.deltaY / 500);
    v.k *= z; v.cx = wx - (wx - v.cx) / z; v.cy = wy - (wy - v.cy) / z;
    draw();
  }, {passive: false});
}

function download() {
  const parts = PANELS.map((p, i) => {
    const v = S.views[p];
    return `<g transform="translate(${i === 0 ? 0 : (i - 1) * (S.views.velocity.w + 10)},${i === 0 ? 0 : S.views.space.h + 10})">${svgOf(p).innerHTML}</g>`;
  });
  const w = Math.max(S.views.space.w, S.views.velocity.w + S.views.acceleration.w + 10);
  const h = S.views.space.h + Math.max(S.views.velocity.h, S.views.acceleration.h) + 10;
  const text = `<svg xmlns="${NS}" width="${f3(w)}" height="${f3(h)}" viewBox="0 0 ${f3(w)} ${f3(h)}">`
             + `<rect width="100%" height="100%" fill="#fff"/>${parts.join("")}</svg>`;
  const a = document.createElement("a");
  a.href = URL.createObjectURL(new Blob([text], {type: "image/svg+xml"}));
  const deg = ((D.frames[S.frame].angle * 180 / Math.PI) % 360 + 360) % 360;
  a.download = `frame-theta${D.input.link}-${deg.toFixed(1)}.svg`;
  document.body.appendChild(a); a.click(); a.remove();
  return text;
}

function start() {
  document.getElementById("title").textContent = D.title[S.lang] || D.title.en;
  const sel = document.getElementById("figure");
  sel.innerHTML = D.figures.map((f, i) => `<option value="${i}">${esc(f.stem)}</option>`).join("");
  sel.addEventListener("change", () => { S.fig = +sel.value; S.step = 0; refit(); draw(); });
  const hasFa = D.figures.some(f => f.parts.some(p => p.steps.some(s => s.said && s.said.fa)));
  const lang = document.getElementById("lang");
  lang.hidden = !hasFa;
  lang.addEventListener("click", () => {
    S.lang = S.lang === "en" ? "fa" : "en";
    lang.textContent = S.lang === "en" ? "فارسی" : "English";
    document.getElementById("title").textContent = D.title[S.lang] || D.title.en;
    draw();
  });
  document.getElementById("first").onclick = () => setStep(-1);
  document.getElementById("prev").onclick = () => setStep(S.step - 1);
  document.getElementById("next").onclick = () => setStep(S.step + 1);
  document.getElementById("stepper").oninput = e => setStep(+e.target.value);
  document.getElementById("steps").onclick = e => {
    const li = e.target.closest("li[data-i]"); if (li) setStep(+li.dataset.i); };
  document.getElementById("play").onclick = () => {
    if (S.playing) { clearInterval(S.playing); S.playing = null; return; }
    if (S.step >= numbered().length - 1) S.step = -1;
    S.playing = setInterval(() => {
      if (S.step >= numbered().length - 1) { clearInterval(S.playing); S.playing = null; return; }
      setStep(S.step + 1); }, 900);
  };
  document.querySelectorAll("[data-layer]").forEach(box => box.addEventListener("change", () => {
    S.layers[box.dataset.layer] = box.checked; draw(); }));
  const angle = document.getElementById("angle");
  angle.max = D.frames.length - 1;
  angle.addEventListener("input", () => setFrame(+angle.value));
  document.getElementById("marks").innerHTML = D.marks.map(m =>
    `<span class="${m.kind}" title="${m.kind === "dead" ? esc(m.why || "dead point") : "limit position"}"`
    + ` style="left:calc(${(100 * markFrame(m) / Math.max(1, D.frames.length - 1)).toFixed(3)}% - 1px)"></span>`).join("");
  document.getElementById("download").onclick = download;
  PANELS.forEach(pointer);
  window.addEventListener("resize", () => { refit(); draw(); drawPlot(); });
  refit();
  S.step = numbered().length - 1;
  draw();
  drawPlot();
}

function refit() { for (const p of PANELS) S.views[p] = fit(p); }

/* For tests and benchmarks: set a frame or a step, read a drawn point back in world
   units, and the time each redraw took. */
window.tarsimView = {setFrame, setStep, world, download, data: D, state: S,
                     frameTimes: () => S.times.slice()};
start();
