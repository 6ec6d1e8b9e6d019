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
const S = {lang: "en", fig: 0, step: 0, frame: 0, playing: null, drag: null, labels: [],
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
/* What a panel must hold: in the steps' mode, the figure's own construction and the
   mechanism where it is drawn; turning, every frame's mechanism or polygon. */
function pts(panel, mode) {
  const out = [];
  const push = xy => { if (xy && isFinite(xy[0]) && isFinite(xy[1])) out.push(xy); };
  const key = panel === "velocity" ? "v" : "a";
  // The space panel keeps one view, so that the crank stays under the pointer that drags
  // it: every frame's mechanism, and the steps' marks near it (a far centre is left off).
  const space = panel === "space";
  const stepped = (space || mode === "steps") && parts().some(part => part.panel === panel);
  for (const f of mode === "steps" && !space ? [D.frames[0]] : D.frames) {
    if (!f.p) continue;
    if (space) for (let i = 0; i < f.p.length; i += 2) push([f.p[i], f.p[i + 1]]);
    else { push(f[key + "o"]); Object.values(f[key]).forEach(push); }
  }
  const near = space ? reach(out) : null, marks = [];
  const mark = xy => { if (!near || Math.hypot(xy[0] - near[0], xy[1] - near[1]) <= near[2]) marks.push(xy); };
  if (stepped) parts().forEach(part => {
    if (part.panel !== panel) return;
    part.steps.forEach(st => {
      const d = st.draw || {};
      if (d.pt) mark(d.pt);
      if (d.seg) { mark(d.seg.slice(0, 2)); mark(d.seg.slice(2)); }
      if (d.circle) { const [x, y, r] = d.circle; mark([x - r, y - r]); mark([x + r, y + r]); }
    });
  });
  marks.forEach(push);
  return out;
}

/* The centre of ``pts`` and three times their reach from it: how far a mark may stand
   from the mechanism and still be framed with it. */
function reach(pts) {
  if (!pts.length) return null;
  const cx = pts.reduce((s, p) => s + p[0], 0) / pts.length;
  const cy = pts.reduce((s, p) => s + p[1], 0) / pts.length;
  const r = Math.max(...pts.map(p => Math.hypot(p[0] - cx, p[1] - cy)), 1e-9);
  return [cx, cy, 3 * r];
}

/* The view of a panel now: the steps' own (at the exercise's position) or the turn's. */
function view(panel) {
  return S.views[panel === "space" || S.frame !== 0 ? "turn" : "steps"][panel];
}

function fit(panel, mode) {
  const svg = svgOf(panel), box = svg.getBoundingClientRect();
  const w = box.width || 600, h = box.height || 400, all = pts(panel, mode);
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
  const v = view(panel);
  return [v.cx + (x - v.w / 2) / v.k, v.cy - (y - v.h / 2) / v.k];
}
const f3 = x => x.toFixed(2);

// ----- drawing -----------------------------------------------------------------------------
function esc(t) { return String(t).replace(/[&<>"]/g, c => `&#${c.charCodeAt(0)};`); }

/* A name is kept, not drawn at once: names of points that stand together (O2 and I12)
   are set as one, "O2 ≡ I12", as the figures set them. */
function label(v, xy, text, cls, dx = 6, dy = -6) {
  if (!S.layers.labels || !text) return "";
  const [x, y] = px(v, xy);
  const same = S.labels.find(l => Math.hypot(l.x - x, l.y - y) < 1.5);
  if (same) { if (!same.text.split(" ≡ ").includes(text)) same.text += ` ≡ ${text}`; }
  else S.labels.push({x, y, dx, dy, text, cls});
  return "";
}

function names() {
  const out = S.labels.map(l => `<text class="${l.cls}" x="${f3(l.x + l.dx)}" y="${f3(l.y + l.dy)}">${esc(l.text)}</text>`).join("");
  S.labels = [];
  return out;
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
    if (xy) { const [x, y] = px(v, xy);
              s += `<text class="number" x="${f3(x - 14)}" y="${f3(y + 14)}">${st.n}</text>`; }
  }
  return s;
}

function drawSpace(f) {
  const v = view('space'), at = i => [f.p[2 * i], f.p[2 * i + 1]], idx = {};
  D.points.forEach((p, i) => { idx[p] = i; });
  let s = "";
  for (const g of D.guides) s += farLine(v, g.through, g.direction, "guide");
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
  for (const w of D.wheels) {
    const [x, y] = px(v, at(idx[w.point]));
    s += `<circle class="wheel" cx="${f3(x)}" cy="${f3(y)}" r="${f3(w.radius * v.k)}"/>`;
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
  // The construction over the mechanism, so that the current step is never hidden.
  const here = S.frame === 0;
  if (here) parts().forEach((part, p) => {
    if (part.panel !== "space") return;
    part.steps.forEach(st => { const w = stage(p, st.n);
                               if (w !== "later" && st.draw) s += stepMark(v, st, w, "space"); });
  });
  if (!here || !parts().some(part => part.panel === "space")) s += drawCentres(f, v);
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
  const v = view(panel), key = panel === "velocity" ? "v" : "a";
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
  .plate{fill:#eee;fill-opacity:.6}
  .guide{stroke:#111;stroke-width:.8}
  .wheel{fill:#eee;fill-opacity:.6;stroke:#111;stroke-width:2}
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
    const svg = svgOf(panel), v = view(panel);
    svg.setAttribute("viewBox", `0 0 ${v.w} ${v.h}`);
    if (!f.p) { svg.innerHTML = STYLE + `<text x="12" y="24">${esc(f.why || "")}</text>`; continue; }
    S.labels = [];
    svg.innerHTML = STYLE + (panel === "space" ? drawSpace(f) : drawPolygon(f, panel)) + names();
  }
  drawSteps();
  drawReadout(f);
  drawCursor();
  S.times.push(performance.now() - t0);
}

// ----- the steps' list ---------------------------------------------------------------------
/* Persian words with formulas among them: each formula (a run that opens with a Latin
   letter or a bracket and holds no Persian letter) is isolated left to right, so that
   "(۱ rad/s)² × ۱۸۰" keeps its order and its brackets inside a right-to-left line. */
const FORMULA = /([A-Za-zα-ωΑ-ΩΔ(][A-Za-zα-ωΑ-ΩΔ0-9۰-۹₀-₉_=+\-−×·÷/:()²³′″ᵗⁿᶜ.°٫≡⊥∥→ ]*[A-Za-zα-ωΑ-Ω0-9۰-۹₀-₉)²³′″°])/g;
function said(text, lang) {
  const safe = esc(text);
  return lang === "fa" ? safe.replace(FORMULA, '<bdi dir="ltr">$1</bdi>') : safe;
}

function drawSteps() {
  const ol = document.getElementById("steps"), list = numbered();
  ol.classList.toggle("rtl", S.lang === "fa");
  ol.classList.toggle("away", S.frame !== 0);
  document.getElementById("readout").classList.toggle("rtl", S.lang === "fa");
  document.querySelectorAll("[data-ui]").forEach(el => {
    el.textContent = (D.ui[S.lang] || D.ui.en)[el.dataset.ui] || el.dataset.ui; });
  let html = "", last = -1;
  list.forEach((st, i) => {
    if (st.part !== last) { html += `<li class="part">${esc(parts()[st.part].title[S.lang])}</li>`; last = st.part; }
    const cls = i === S.step ? "current" : i < S.step ? "done" : "";
    html += `<li class="step ${cls}" data-i="${i}" data-n="${st.n}"><b>${st.n}.</b> ${said(st.said[S.lang] || st.said.en, st.said[S.lang] ? S.lang : "en")}</li>`;
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
  const steps = S.frame === 0 ? "" : (fa ? " — مراحل در وضعیت خود تمرین رسم می‌شوند: برای بازگشت روی یک مرحله کلیک کنید"
                                        : " — the steps are drawn at the exercise's own position: click a step to go back");
  const lost = f.centres ? ` — ${fa ? "مراکز آنی" : "instant centres"}: ${esc(f.centres)}` : "";
  const value = f.p && D.plot.values[S.frame] !== null
    ? ` — ${esc(D.plot.symbol)} = ${D.plot.values[S.frame].toPrecision(4)} ${esc(D.plot.unit)}` : "";
  document.getElementById("readout").innerHTML =
    `θ${D.input.link} = ${deg.toFixed(1)}° (${fa ? "قاب" : "frame"} ${S.frame + 1}/${D.frames.length})${value} ${state}${lost}${steps}`;
  document.getElementById("angle").value = S.frame;
}

// ----- the output's curve ------------------------------------------------------------------
function drawPlot() {
  const svg = document.getElementById("plot"), box = svg.getBoundingClientRect();
  const w = box.width || 800, h = box.height || 100, vals = D.plot.values, n = vals.length;
  svg.setAttribute("viewBox", `0 0 ${w} ${h}`);
  const ok = vals.filter(x => x !== null), lo = Math.min(0, ...ok), hi = Math.max(0, ...ok);
  // x as the slider's thumb stands (its track inset by half a thumb at each end)
  const y = x => h - 14 - (x - lo) / ((hi - lo) || 1) * (h - 28), x = k => 8 + k / (n - 1) * (w - 16);
  let d = "", pen = "M";
  vals.forEach((val, k) => { if (val === null) { pen = "M"; return; }
                             d += `${pen}${f3(x(k))},${f3(y(val))} `; pen = "L"; });
  const marks = D.marks.map(m => `<line x1="${f3(x(markFrame(m)))}" x2="${f3(x(markFrame(m)))}" y1="4" y2="${h - 10}" stroke="${m.kind === "dead" ? "#c62828" : "#999"}" stroke-dasharray="3 3"/>`).join("");
  svg.innerHTML = `<line x1="40" x2="${w - 10}" y1="${f3(y(0))}" y2="${f3(y(0))}" stroke="#ccc"/>${marks}`
    + `<path d="${d}" fill="none" stroke="#111" stroke-width="1.5"/>`
    + `<text x="${w - 6}" y="14" text-anchor="end" style="font:italic 12px 'DejaVu Serif'">${esc(D.plot.symbol)} (${esc(D.plot.unit)})</text>`
    + `<text x="12" y="${f3(y(hi) + 4)}" style="font:11px 'DejaVu Sans'">${hi.toPrecision(3)}</text>`
    + `<text x="12" y="${f3(y(lo))}" style="font:11px 'DejaVu Sans'">${lo.toPrecision(3)}</text>`
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
      const [, pin] = crankPin(), [px0, py0] = px(view('space'), [f.p[2 * pin], f.p[2 * pin + 1]]);
      if (Math.hypot(px0 - x, py0 - y) < 25) { S.drag = {crank: true}; svg.setPointerCapture(e.pointerId); return; }
    }
    S.drag = {panel, x, y, cx: view(panel).cx, cy: view(panel).cy};
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
    const v = view(S.drag.panel);
    v.cx = S.drag.cx - (x - S.drag.x) / v.k; v.cy = S.drag.cy + (y - S.drag.y) / v.k;
    draw();
  });
  svg.addEventListener("pointerup", () => { S.drag = null; });
  svg.addEventListener("wheel", e => {
    e.preventDefault();
    const r = svg.getBoundingClientRect(), x = e.clientX - r.left, y = e.clientY - r.top;
    const [wx, wy] = world(panel, x, y), v = view(panel), z = Math.exp(-e.deltaY / 500);
    v.k *= z; v.cx = wx - (wx - v.cx) / z; v.cy = wy - (wy - v.cy) / z;
    draw();
  }, {passive: false});
}

function download() {
  const parts = PANELS.map((p, i) => {
    const v = view(p);
    return `<g transform="translate(${i === 0 ? 0 : (i - 1) * (view('velocity').w + 10)},${i === 0 ? 0 : view('space').h + 10})">${svgOf(p).innerHTML}</g>`;
  });
  const w = Math.max(view('space').w, view('velocity').w + view('acceleration').w + 10);
  const h = view('space').h + Math.max(view('velocity').h, view('acceleration').h) + 10;
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
  const options = () => D.figures.map((f, i) => f.parts.some(p => p.steps.length)
    ? `<option value="${i}"${i === S.fig ? " selected" : ""}>${esc(f.heading[S.lang] || f.heading.en)}</option>` : "").join("");
  sel.innerHTML = options();
  S.fig = +(sel.value || 0);
  sel.addEventListener("change", () => { S.fig = +sel.value; S.step = 0; refit(); draw(); });
  const hasFa = D.figures.some(f => f.parts.some(p => p.steps.some(s => s.said && s.said.fa)));
  const lang = document.getElementById("lang");
  lang.hidden = !hasFa;
  lang.addEventListener("click", () => {
    S.lang = S.lang === "en" ? "fa" : "en";
    lang.textContent = S.lang === "en" ? "فارسی" : "English";
    document.getElementById("title").textContent = D.title[S.lang] || D.title.en;
    document.getElementById("title").dir = S.lang === "fa" ? "rtl" : "ltr";
    sel.innerHTML = options();
    draw();
  });
  document.getElementById("first").onclick = () => setStep(-1);
  document.getElementById("prev").onclick = () => setStep(S.step - 1);
  document.getElementById("next").onclick = () => setStep(S.step + 1);
  document.getElementById("stepper").oninput = e => setStep(+e.target.value);
  document.getElementById("steps").onclick = e => {
    const li = e.target.closest("li[data-i]"); if (li) setStep(+li.dataset.i); };
  const play = document.getElementById("play");
  const stop = () => { clearInterval(S.playing); S.playing = null; play.firstChild.textContent = "▶︎ "; };
  play.onclick = () => {
    if (S.playing) { stop(); return; }
    if (S.step >= numbered().length - 1) S.step = -1;
    play.firstChild.textContent = "⏸ ";
    S.playing = setInterval(() => {
      if (S.step >= numbered().length - 1) { stop(); return; }
      setStep(S.step + 1); }, 900);
  };
  document.addEventListener("keydown", e => {
    if (e.target.tagName === "SELECT" || e.target.tagName === "INPUT") return;
    if (e.key === "ArrowRight" || e.key === "ArrowDown") setStep(S.step + 1);
    if (e.key === "ArrowLeft" || e.key === "ArrowUp") setStep(S.step - 1);
  });
  document.querySelectorAll("[data-layer]").forEach(box => box.addEventListener("change", () => {
    S.layers[box.dataset.layer] = box.checked; draw(); }));
  const angle = document.getElementById("angle");
  angle.max = D.frames.length - 1;
  angle.addEventListener("input", () => setFrame(+angle.value));
  document.getElementById("marks").innerHTML = D.marks.map(m =>
    `<span class="${m.kind}" title="${m.kind === "dead" ? esc(m.why || "dead point") : "limit position"}"`
    + ` style="left:calc(7px + ${(markFrame(m) / Math.max(1, D.frames.length - 1)).toFixed(5)} * (100% - 16px))"></span>`).join("");
  document.getElementById("download").onclick = download;
  PANELS.forEach(pointer);
  window.addEventListener("resize", () => { refit(); draw(); drawPlot(); });
  refit();
  S.step = numbered().length - 1;
  draw();
  drawPlot();
}

function refit() {
  S.views = {steps: {}, turn: {}};
  for (const mode of ["steps", "turn"]) for (const p of PANELS) S.views[mode][p] = fit(p, mode);
}

/* For tests and benchmarks: set a frame or a step, read a drawn point back in world
   units, and the time each redraw took. */
window.tarsimView = {setFrame, setStep, world, download, data: D, state: S,
                     frameTimes: () => S.times.slice()};
start();
