/* tarsim view: step through a construction and turn the mechanism, offline.
 *
 * Everything drawn comes from the page's JSON (exercises/linkages/view.py): each figure as
 * tarsim draws it, primitive by primitive (graphics/figure_data.py), and the frames of a
 * revolution, each the named points (joints, centres, polygon tips) tarsim's constructions
 * placed there. This script knows primitives, styles and tags, nothing of mechanisms: it
 * writes each primitive as the SVG writer does, shows a primitive from the step it is
 * tagged with, and moves it with the named points it stands on. Nothing is interpolated
 * and no geometry is computed here beyond that move.
 */
"use strict";

const D = JSON.parse(document.getElementById("data").textContent);
const HOT = "#c62828";
const HOME_REACH = 0.25;      // how far beyond the drawing, of its size, the opening view looks
const HOME_NAME = 8;          // paper mm round a point the frames take: its symbol and name
const S = {lang: "en", fig: 0, step: 0, frame: 0, playing: null, drag: null, shown: null,
           layers: {}, boxes: {}, homes: {}, fitted: {}, times: [], items: []};
// The layers a reader may hide, as the page's boxes name them (a primitive's ``l``).
document.querySelectorAll("[data-layer]").forEach(box => { S.layers[box.dataset.layer] = box.checked; });

// ----- the chosen figure and its steps -----------------------------------------------------
function figure() { return D.figures[S.fig]; }
/* The drawing shown: the figure at the exercise's position, or, while the input turns
   (any frame but the first), the same figure drawn farther on (its ``turning``), which
   stands apart where a construction collapses at the exercise's own position. */
function drawn() {
  const f = figure(), d = f.drawn[S.lang] || f.drawn.en;
  return S.frame !== 0 && d.turning ? d.turning : d;
}

/* The numbered steps, in the order steps.md lists them: {part, n, said}. */
function numbered() {
  const out = [];
  figure().parts.forEach((part, p) => part.steps.forEach(st => out.push({part: p, ...st})));
  return out;
}

/* How a primitive tagged [part, n, part, n, …] stands against the current step. */
function stage(tags) {
  const list = numbered();
  if (!tags) return "";
  if (!list.length || S.step < 0) return "later";
  const cur = list[Math.min(S.step, list.length - 1)];
  let first = null, hot = false;
  for (let i = 0; i < tags.length; i += 2) {
    const [p, n] = [tags[i], tags[i + 1]];
    if (p === cur.part && n === cur.n) hot = true;
    if (!first || p < first[0] || (p === first[0] && n < first[1])) first = [p, n];
  }
  if (hot) return "cur";
  return first[0] < cur.part || (first[0] === cur.part && first[1] < cur.n) ? "done" : "later";
}

// ----- writing primitives as the SVG writer does -------------------------------------------
function esc(t) { return String(t).replace(/[&<>"]/g, c => `&#${c.charCodeAt(0)};`); }
const num = v => String(+v.toFixed(3));
function attrs(a) { return Object.entries(a).map(([k, v]) => ` ${k}="${esc(v)}"`).join(""); }

function pathD(xy, closed) {
  const pairs = [];
  for (let i = 0; i < xy.length; i += 2) pairs.push(`${xy[i]},${xy[i + 1]}`);
  return "M" + pairs.join(" L") + (closed ? " Z" : "");
}

function run([x, y, size, anchor, face, text, spans]) {
  const a = {x, y, "font-size": size, "text-anchor": anchor};
  if (face.includes("r")) Object.assign(a, {direction: "rtl", "font-family": D.fonts.rtl});
  if (face.includes("i")) a["font-style"] = "italic";
  if (face.includes("b")) a["font-weight"] = "bold";
  return `<text${attrs(a)}>${esc(text)}`
    + spans.map(([t, s, dy]) => `<tspan dy="${dy}" font-size="${s}">${esc(t)}</tspan>`).join("")
    + "</text>";
}

/* One primitive as markup: a path, a circle, or a text (a group of runs). */
function markup(item, k) {
  const [kind, style, g, more = {}] = item;
  const cls = [`s-${style || "text"}`, more.l ? `L-${more.l}` : ""].join(" ").trim();
  const own = {"data-i": k, class: cls, ...(style ? D.styles[style] : D.styles.text)};
  if (kind === "c") return `<circle${attrs({cx: g[0], cy: g[1], r: g[2], ...own})}/>`;
  if (kind === "t") return `<g${attrs(own)}>${g.map(run).join("")}</g>`;
  return `<path${attrs({d: pathD(g, kind === "z"), ...own})}/>`;
}

function styleSheet() {
  let css = "";
  for (const [name, a] of Object.entries(D.styles)) {
    const hot = [];
    if (a.stroke && a.stroke !== "none") hot.push(`stroke:${HOT}`);
    if (name === "text" || (a.fill && a.fill !== "none" && a.fill !== "#fff")) hot.push(`fill:${HOT}`);
    css += `.s-${name}.cur{${hot.join(";")}}`;
  }
  for (const layer of Object.keys(S.layers)) css += `.hide-${layer} .L-${layer}{display:none}`;
  return `<style>${css}.later,.still,.lost{display:none}.done,svg.away{opacity:.35}</style>`;
}

/* Write the figure afresh (a figure or language chosen), keeping each primitive's element
   and what moves it. */
function build() {
  const svg = sheet(), d = drawn();
  svg.innerHTML = styleSheet() + d.items.map(markup).join("");
  const els = svg.querySelectorAll("[data-i]");
  S.items = d.items.map((item, k) => {
    const [kind, , g, more = {}] = item, el = els[k];
    const at = kind === "t" ? more.at : kind === "c" ? g.slice(0, 2) : g;
    return {el, kind, g, tags: more.s, move: more.m, at, arc: more.a, fixed: more.f, sc: more.sc,
            frame: more.fr, paper: more.p,
            base: kind === "p" || kind === "z" ? el.getAttribute("d") : null};
  });
  S.shown = {fig: S.fig, lang: S.lang, turning: S.frame !== 0};
  // The figure's home: all that each drawing of it (at the position, and turning) draws.
  const key = `${S.fig} ${S.lang}`, was = S.homes[key], mine = home(svg, d);
  S.homes[key] = was ? [Math.min(was[0], mine[0]), Math.min(was[1], mine[1]),
                        Math.max(was[0] + was[2], mine[0] + mine[2]) - Math.min(was[0], mine[0]),
                        Math.max(was[1] + was[3], mine[1] + mine[3]) - Math.min(was[1], mine[1])] : mine;
  // the figure's view, until the reader zooms or pans it: its home in the language shown
  // (kept as it is when the drawing turning takes over, so that the crank being dragged
  // stays under the pointer)
  if (!S.boxes[S.fig] || (S.fitted[S.fig] && !S.shown.turning)) {
    S.boxes[S.fig] = S.homes[key].slice(); S.fitted[S.fig] = true; }
}

/* The view a figure opens in and the reset button goes back to: all it draws at the
   exercise's position, as the browser sets its words (a Persian caption runs wider than
   the box the figure was laid out in), and where the frames take the points D.home names
   (the mechanism's joints) with room for their names, a little white round it all, so
   that no label is cut at the panel's edge. */
function home(svg, d) {
  let [x0, y0, x1, y1] = d.box;
  const grow = (a, b, c, e) => {
    x0 = Math.min(x0, a); y0 = Math.min(y0, b); x1 = Math.max(x1, c); y1 = Math.max(y1, e);
  };
  const all = svg.getBBox();
  if (all.width || all.height) grow(all.x, all.y, all.x + all.width, all.y + all.height);
  // A point a frame takes beyond a quarter of the drawing's size round it is left to the
  // reader to pan to.
  const reach = HOME_REACH * Math.max(x1 - x0, y1 - y0);
  const [r0, s0, r1, s1] = [x0 - reach, y0 - reach, x1 + reach, y1 + reach];
  const f0 = figure().drawn[S.lang] || figure().drawn.en;
  for (const drawing of [f0, f0.turning]) {
    const v = drawing && D.home && drawing.views[D.home.view];
    if (!v) continue;
    for (const f of D.frames) {
      const xy = f.at && f.at[D.home.view];
      for (const k of xy ? D.home.points : []) {
        if (xy[2 * k] === null) continue;
        const x = v[1] + v[0] * xy[2 * k], y = v[2] - v[0] * xy[2 * k + 1];
        if (x >= r0 && x <= r1 && y >= s0 && y <= s1)
          grow(x - HOME_NAME, y - HOME_NAME, x + HOME_NAME, y + HOME_NAME);
      }
    }
  }
  const m = 0.03 * Math.max(x1 - x0, y1 - y0);
  return [x0 - m, y0 - m, x1 - x0 + 2 * m, y1 - y0 + 2 * m];
}

// ----- turning: each primitive moved with the named points it stands on ----------------------
/* A frame's named points of a view on the paper of the drawing shown: a polygon the
   drawing turns with its panel at the frame's own scale (the figure's ``fit``, chosen
   by tarsim for that frame), its middle at the middle of its panel above the caption. */
function paperPoints(frame, view) {
  const d = drawn(), v = d.views[view], xy = frame.at && frame.at[view];
  if (!v || !xy) return null;
  let [s, ox, oy] = v;
  const fit = frameFit(frame, view);
  if (fit) {
    const [x0, y0, , , caption] = d.panels[view];
    s = fit[0]; ox = x0 + fit[4] / 2 - s * fit[1]; oy = y0 + (fit[5] - caption) / 2 + s * fit[2];
  }
  return onSheet(xy, [s, ox, oy]);
}

/* Where the drawing shown put its own named points (the first frame's, for a drawing at
   the exercise's position). */
function ownPoints(view) {
  const d = drawn(), v = d.views[view], xy = d.named ? d.named[view] : D.frames[0].at[view];
  return v && xy ? onSheet(xy, v) : null;
}

function onSheet(xy, [s, ox, oy]) {
  const out = [];
  for (let i = 0; i < xy.length; i += 2)
    out.push(xy[i] === null ? null : [ox + s * xy[i], oy - s * xy[i + 1]]);
  return out;
}

/* The frame's scale of a polygon panel of the turning drawing: [mm a world unit, the
   world point at the polygon's middle, its statement's index, the panel's width and
   height]; null if it has none. */
function frameFit(frame, view) {
  const d = drawn(), fit = figure().fit;
  if (!fit || !fit.at[view] || !d.panels || !d.panels[view] || d !== (figure().drawn[S.lang] || figure().drawn.en).turning) return null;
  const k = frame === D.frames[S.frame] ? S.frame : D.frames.indexOf(frame);
  const out = fit.at[view].slice(6 * k, 6 * k + 6);
  return out[0] === null ? null : out;
}

/* A polygon panel's frame and caption at the frame's scale: the frame grown or shrunk
   round the polygon, the caption at its foot, the scale statement said anew. */
function restate(it, frame) {
  const fit = frameFit(frame, it.fixed);
  if (!fit) return;
  const [x0, y0, , h0] = drawn().panels[it.fixed];
  if (it.frame) {
    const [x1, y1] = [x0 + fit[4], y0 + fit[5]];
    it.el.setAttribute("d", `M${num(x0)},${num(y0)} L${num(x1)},${num(y0)} L${num(x1)},${num(y1)} L${num(x0)},${num(y1)} Z`);
    return;
  }
  it.el.setAttribute("transform", `translate(0,${num(fit[5] - h0)})`);
  const text = it.el.querySelector("text");
  if (!it.sc || !text) return;
  const said = figure().fit.said[it.sc][fit[3]];
  text.textContent = said[S.lang] || said.en;
  it.el.querySelectorAll("text").forEach((t, i) => { if (i) t.remove(); });
}

/* An arc about C from S to E, the shorter way, in n chords (as the figure draws an arc
   swung from one point to another). */
function swing(C, S, E, n) {
  if (!C || !S || !E) return null;
  const r = Math.hypot(S[0] - C[0], S[1] - C[1]), a = Math.atan2(S[1] - C[1], S[0] - C[0]);
  let t = Math.atan2(E[1] - C[1], E[0] - C[0]) - a;
  t = Math.atan2(Math.sin(t), Math.cos(t));
  const out = [];
  for (let i = 0; i <= n; i++) out.push(C[0] + r * Math.cos(a + t * i / n), C[1] + r * Math.sin(a + t * i / n));
  return out;
}

function moveTo(frame) {
  const here = S.frame === 0, cache = {}, start = {};
  // A figure none of whose primitives moves stands as it is, dimmed.
  const still = !here && frame.at && !S.items.some(it => it.move || it.arc);
  sheet().classList.toggle("away", still);
  if (still) { S.items.forEach(restore); return; }
  const now = view => (view in cache ? cache[view] : (cache[view] = paperPoints(frame, view)));
  const own = view => (view in start ? start[view] : (start[view] = ownPoints(view)));
  for (const it of S.items) {
    it.el.classList.remove("still", "lost");
    if (here) { restore(it); continue; }
    if (it.fixed && frame.at) { restore(it); restate(it, frame); continue; }
    if (it.arc && frame.at) {
      const [view, [c, s, e]] = it.arc, at = now(view), xy = at && swing(at[c], at[s], at[e], it.g.length / 2 - 1);
      if (xy) place(it, xy); else it.el.classList.add("lost");
      continue;
    }
    if (!it.move || !frame.at) { it.el.classList.add(frame.at ? "still" : "lost"); continue; }
    const [view, b] = it.move, was = own(view);
    const moved = now(view) && was && carry(it.at, b, now(view), was);
    if (!moved) { it.el.classList.add("lost"); continue; }
    place(it, moved);
  }
}

/* The points ``at`` (x, y in turn) carried from the named points ``was`` the drawing
   stands on to the frame's ``now``: each by its [P, Q, R]; null if one of them is
   missing. */
function carry(at, b, now, was) {
  const out = [];
  for (let i = 0; i < at.length; i += 2) {
    const j = b.length === 3 ? 0 : 3 * i / 2;        // one triple for all, or one a point
    const a = b[j], q = b[j + 1], r = b[j + 2], P = now[a], P0 = was[a];
    if (!P || !P0) return null;
    let c = 1, s = 0;
    if (q >= 0) {
      if (!now[q] || !now[r] || !was[q] || !was[r]) return null;
      const t = Math.atan2(now[r][1] - now[q][1], now[r][0] - now[q][0])
              - Math.atan2(was[r][1] - was[q][1], was[r][0] - was[q][0]);
      c = Math.cos(t); s = Math.sin(t);
    }
    const dx = at[i] - P0[0], dy = at[i + 1] - P0[1];
    out.push(P[0] + c * dx - s * dy, P[1] + s * dx + c * dy);
  }
  return out;
}

function place(it, xy) {
  if (it.kind === "c") { it.el.setAttribute("cx", num(xy[0])); it.el.setAttribute("cy", num(xy[1])); }
  else if (it.kind === "t") it.el.setAttribute("transform", `translate(${num(xy[0] - it.at[0])},${num(xy[1] - it.at[1])})`);
  else it.el.setAttribute("d", pathD(xy.map(num), it.kind === "z"));
}

function restore(it) {
  if (it.kind === "c") { it.el.setAttribute("cx", it.g[0]); it.el.setAttribute("cy", it.g[1]); }
  else if (it.kind === "t") it.el.removeAttribute("transform");
  else it.el.setAttribute("d", it.base);
}

// ----- drawing ---------------------------------------------------------------------------
function sheet() { return document.querySelector("#sheet svg"); }

function draw() {
  const t0 = performance.now();
  if (!S.shown || S.shown.fig !== S.fig || S.shown.lang !== S.lang
      || S.shown.turning !== (S.frame !== 0)) build();
  const svg = sheet(), f = D.frames[S.frame], box = S.boxes[S.fig];
  svg.setAttribute("viewBox", box.map(num).join(" "));
  // Step numbers number the steps, which are drawn at the exercise's position: while the
  // input turns they are hidden, and never stand over a name carried another way.
  for (const layer of Object.keys(S.layers))
    svg.classList.toggle(`hide-${layer}`, !S.layers[layer] || (layer === "numbers" && S.frame !== 0));
  const turning = S.frame !== 0;
  for (const it of S.items) {
    it.el.classList.remove("later", "done", "cur");
    const where = turning ? "" : stage(it.tags);
    if (where) it.el.classList.add(where);
  }
  moveTo(f);
  drawSteps();
  drawReadout(f);
  drawCursor();
  S.times.push(performance.now() - t0);
}

// ----- the steps' list -------------------------------------------------------------------
/* Persian words with formulas among them: each formula (a run that opens with a Latin
   letter or a bracket and holds no Persian letter) is isolated left to right, so that
   "(۱ rad/s)² × ۱۸۰" keeps its order and its brackets inside a right-to-left line. */
const FORMULA = /([A-Za-zα-ωΑ-ΩΔ(][A-Za-zα-ωΑ-ΩΔ0-9۰-۹₀-₉_=+\-−×·÷/:()²³′″ᵗⁿᶜ.°٫≡⊥∥→ ]*[A-Za-zα-ωΑ-Ω0-9۰-۹₀-₉)²³′″°])/g;
function said(text, lang) {
  const safe = esc(text);
  return lang === "fa" ? safe.replace(FORMULA, '<bdi dir="ltr">$1</bdi>') : safe;
}

function drawSteps() {
  const key = [S.fig, S.lang, S.step, S.frame !== 0].join();
  if (S.listed === key) return;       // a frame turned: the list stands as it was
  S.listed = key;
  const ol = document.getElementById("steps"), list = numbered();
  ol.classList.toggle("rtl", S.lang === "fa");
  ol.classList.toggle("away", S.frame !== 0);
  document.getElementById("readout").classList.toggle("rtl", S.lang === "fa");
  document.querySelectorAll("[data-ui]").forEach(el => {
    el.textContent = (D.ui[S.lang] || D.ui.en)[el.dataset.ui] || el.dataset.ui; });
  let html = "", last = -1;
  list.forEach((st, i) => {
    if (st.part !== last) { html += `<li class="part">${esc(figure().parts[st.part].title[S.lang])}</li>`; last = st.part; }
    const cls = i === S.step ? "current" : i < S.step ? "done" : "";
    html += `<li class="step ${cls}" data-i="${i}" data-n="${st.n}"><b>${st.n}.</b> ${said(st.said[S.lang] || st.said.en, st.said[S.lang] ? S.lang : "en")}</li>`;
  });
  ol.innerHTML = html || `<li>${S.lang === "fa" ? "این شکل مرحله‌ای ندارد." : "No construction steps in this figure."}</li>`;
  const stepper = document.getElementById("stepper");
  stepper.max = Math.max(0, list.length - 1);
  stepper.value = Math.max(0, S.step);
  ol.querySelector("li.current")?.scrollIntoView({block: "nearest"});
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

function angleFrame(a) {
  const n = D.frames.length, tau = 2 * Math.PI;
  const t = (((a - D.input.angle) % tau) + tau) % tau;
  return D.input.step > 0 ? Math.round(t / D.input.step) % n
                          : Math.round((tau - t) / -D.input.step) % n;
}

/* A pointer's place on the figure's paper (mm). */
function onPaper(e) {
  const p = new DOMPoint(e.clientX, e.clientY).matrixTransform(sheet().getScreenCTM().inverse());
  return [p.x, p.y];
}

/* Where a named point of a view stands on the page (client pixels) in the frame shown,
   and a place on the page (client pixels) in that view's world: for dragging the input
   round, and for tests that read the drawing back. */
function screen(view, i) {
  const xy = paperPoints(D.frames[S.frame], view)?.[i];
  if (!xy) return null;
  const p = new DOMPoint(xy[0], xy[1]).matrixTransform(sheet().getScreenCTM());
  return [p.x, p.y];
}
function world(view, cx, cy) {
  const v = drawn().views[view], [x, y] = onPaper({clientX: cx, clientY: cy});
  return v ? [(x - v[1]) / v[0], -(y - v[2]) / v[0]] : null;
}

/* Drag the input's handle round its pivot (D.drag: a named point of a view, and the one
   it turns about) to turn it; drag elsewhere to pan, and zoom with the wheel. */
function pointer() {
  const svg = sheet(), drag = D.drag;
  svg.addEventListener("pointerdown", e => {
    const handle = screen(drag.view, drag.handle);
    if (handle && Math.hypot(handle[0] - e.clientX, handle[1] - e.clientY) < 25) {
      S.drag = {turn: true}; svg.setPointerCapture(e.pointerId); return;
    }
    S.drag = {x: e.clientX, y: e.clientY, box: S.boxes[S.fig].slice(),
              k: 1 / svg.getScreenCTM().a};          // paper mm a pixel
    svg.setPointerCapture(e.pointerId);
  });
  svg.addEventListener("pointermove", e => {
    if (!S.drag) return;
    if (S.drag.turn) {
      const at = D.frames[0].at[drag.view], [wx, wy] = world(drag.view, e.clientX, e.clientY);
      setFrame(angleFrame(Math.atan2(wy - at[2 * drag.about + 1], wx - at[2 * drag.about])));
      return;
    }
    const {x, y, box, k} = S.drag;
    S.fitted[S.fig] = false;
    S.boxes[S.fig] = [box[0] - (e.clientX - x) * k, box[1] - (e.clientY - y) * k, box[2], box[3]];
    draw();
  });
  svg.addEventListener("pointerup", () => { S.drag = null; });
  svg.addEventListener("wheel", e => {
    e.preventDefault();
    const [x, y] = onPaper(e), z = Math.exp(e.deltaY / 500), box = S.boxes[S.fig];
    S.fitted[S.fig] = false;
    S.boxes[S.fig] = [x - (x - box[0]) * z, y - (y - box[1]) * z, box[2] * z, box[3] * z];
    draw();
  }, {passive: false});
}

/* The figure as shown, as a file: what is hidden left out, each primitive as written.
   A turned frame keeps the figure's paper too (its title, caption, scale bars and
   legend, which the page shows at the exercise's position only), its caption saying the
   frame's angle. */
function download() {
  const d = drawn(), svg = sheet(), parts = [], turned = S.frame !== 0;
  for (const it of S.items) {
    const paper = turned && it.paper;
    if (!paper && getComputedStyle(it.el).display === "none") continue;
    const el = it.el.cloneNode(true);
    el.removeAttribute("class"); el.removeAttribute("data-i");
    if (it.el.classList.contains("done")) el.setAttribute("opacity", ".35");
    if (paper && it.paper === "angle") el.querySelectorAll("text, tspan").forEach(t => {
      for (const node of t.childNodes) if (node.nodeType === 3) node.data = atAngle(node.data); });
    parts.push(el.outerHTML);
  }
  const text = `<svg xmlns="http://www.w3.org/2000/svg" width="${d.w}mm" height="${d.h}mm" viewBox="0 0 ${d.w} ${d.h}">`
             + `<rect width="100%" height="100%" fill="#fff"/>${parts.join("")}</svg>`;
  const a = document.createElement("a");
  a.href = URL.createObjectURL(new Blob([text], {type: "image/svg+xml"}));
  const deg = ((D.frames[S.frame].angle * 180 / Math.PI) % 360 + 360) % 360;
  a.download = `${figure().stem}-${D.input.slug}-${deg.toFixed(1)}.svg`;
  document.body.appendChild(a); a.click(); a.remove();
  svg.dataset.downloaded = "1";
  return text;
}

/* ``text`` with the input's angle said at the frame shown: "θ₂ = 90°" at θ2 = 40° is
   "θ₂ = 40°", in the text's own digits (the pattern exercises/linkages/view_paper.py
   marks such a text by). */
const ANGLE = /(θ[₀-₉0-9]+ = )([−\-0-9.۰-۹٫]+)(°)/g;
function atAngle(text) {
  const plain = D.input.symbol, sub = plain.replace(/[0-9]/g, c => "₀₁₂₃₄₅₆₇₈₉"[c]);
  const deg = ((D.frames[S.frame].angle * 180 / Math.PI) % 360 + 360) % 360;
  const said = String(Number(deg.toFixed(2)));
  return text.replace(ANGLE, (all, head, value, tail) => {
    if (head !== `${sub} = ` && head !== `${plain} = `) return all;
    const fa = /[۰-۹]/.test(value);
    return head + (fa ? said.replace(/[0-9]/g, c => "۰۱۲۳۴۵۶۷۸۹"[c]).replace(".", "٫") : said) + tail;
  });
}

/* Back to the view the figure opened in: its zoom and pan undone. */
function resetView() {
  S.boxes[S.fig] = S.homes[`${S.fig} ${S.lang}`].slice();
  S.fitted[S.fig] = true;
  draw();
}

function start() {
  document.getElementById("title").textContent = D.title[S.lang] || D.title.en;
  const sel = document.getElementById("figure");
  const options = () => D.figures.map((f, i) =>
    `<option value="${i}"${i === S.fig ? " selected" : ""}>${esc(f.heading[S.lang] || f.heading.en)}</option>`).join("");
  sel.innerHTML = options();
  sel.addEventListener("change", () => { S.fig = +sel.value; S.step = 0; draw(); });
  const lang = document.getElementById("lang");
  lang.hidden = !D.figures.some(f => f.drawn.fa);
  lang.addEventListener("click", () => {
    S.lang = S.lang === "en" ? "fa" : "en";
    lang.textContent = S.lang === "en" ? "فارسی" : "English";
    document.getElementById("title").textContent = D.title[S.lang] || D.title.en;
    document.getElementById("title").dir = S.lang === "fa" ? "rtl" : "ltr";
    sel.innerHTML = options();
    draw();
    drawPlot();
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
  document.getElementById("reset").onclick = resetView;
  pointer();
  window.addEventListener("resize", () => { draw(); drawPlot(); });
  S.step = 0;                         // step 1: a construction is read from its start
  draw();
  drawPlot();
}

/* For tests and benchmarks: set a frame or a step, find a named point on the page and a
   place in a view's world, and the time each redraw took. */
window.tarsimView = {setFrame, setStep, screen, world, download, resetView, data: D, state: S,
                     frameTimes: () => S.times.slice()};
start();
