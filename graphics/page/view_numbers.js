/* tarsim view: what the page reads out under the figure, at the frame shown, and the
 * curve it plots under the slider, from the page's JSON (exercises/linkages/view_readout.py):
 * each moving body's ω and α and each asked rate, said as steps.md's results table says
 * them, and the output's signed rate against the input's angle. Its functions are called
 * by view.js, which the page sets after this file in the same script.
 */
"use strict";

// ----- the readout -------------------------------------------------------------------------
function drawReadout(f) {
  const deg = ((f.angle * 180 / Math.PI) % 360 + 360) % 360;
  const fa = S.lang === "fa";
  let state;
  if (!f.at) state = `<span class="bad">${fa ? "سرهم نمی‌شود" : "cannot be assembled"}: ${esc(f.why)}</span>`;
  else if (!f.ok) state = `<span class="bad">${fa ? "وارسی نادرست" : "check failed"}: ${esc(f.why)}</span>`;
  else state = fa ? "✓ با حل تحلیلی وارسی شد" : "✓ checked against the analytic solution";
  const steps = S.frame === 0 ? "" : (fa ? " — مراحل در وضعیت خود تمرین رسم می‌شوند: برای بازگشت روی یک مرحله کلیک کنید"
                                        : " — the steps are drawn at the exercise's own position: click a step to go back");
  const lost = f.lost ? ` — ${esc(ui().lost)}: ${esc(f.lost)}` : "";
  document.getElementById("readout").innerHTML =
    `<div>${esc(D.input.symbol)} = ${said(numeral(deg.toFixed(1)), S.lang)}° (${fa ? "قاب" : "frame"} ${numeral(S.frame + 1)}/${numeral(D.frames.length)}) ${state}${lost}${steps}</div>`
    + `<div class="rates">${rates(S.frame).map(([name, parts]) => `<bdi dir="${fa ? "rtl" : "ltr"}" data-q="${esc(name)}">`
      + parts.map(([text, formula]) => formula && fa ? `<bdi dir="ltr">${esc(text)}</bdi>` : esc(text)).join("") + "</bdi>").join("")}</div>`;
  document.getElementById("angle").value = S.frame;
}

function ui() { return D.ui[S.lang] || D.ui.en; }

/* A number as steps.md's tables set it: six significant figures, a true minus, never
   "−0", in the language's digits. */
function figures(x) {
  const t = String(Number(x.toPrecision(6)));
  return numeral(Number(t) === 0 ? "0" : t.replace("-", "−"));
}
function numeral(t) {
  return S.lang === "fa" ? String(t).replace(/[0-9]/g, c => "۰۱۲۳۴۵۶۷۸۹"[c]).replace(/\./g, "٫") : String(t);
}

/* Each moving link's ω and α and each asked point's velocity and acceleration at frame
   ``k``, as steps.md's results table says them: [results.json's name, its words as
   [text, whether a formula], a formula kept left to right among Persian words]. A rate
   is signed counter-clockwise positive and says its sense; a vector, its size and the
   angle it points at. */
function rates(k) {
  const R = D.readout, out = [], w = ui();
  if (!R) return out;
  const sense = v => [[v > 0 ? ` (${w.ccw})` : v < 0 ? ` (${w.cw})` : "", false]];
  for (const r of R.turning) {
    for (const [key, sym, unit] of [["omega", "ω", "rad/s"], ["alpha", "α", "rad/s²"]]) {
      const v = r[key][k];
      if (v !== null) out.push([`${key}${r.n}`, [[`${sym}${r.n} = ${figures(v)} ${unit}`, true], ...sense(v)]]);
    }
  }
  for (const q of R.asked) {
    const x = q.x[k], y = q.y[k];
    if (x === null) continue;
    const size = `${q.symbol} = ${figures(Math.hypot(x, y))} ${q.unit}`;
    let at = Math.atan2(y, x) * 180 / Math.PI;
    if (at <= -180 + 1e-9) at = 180;
    if (Math.abs(at) < 1e-9) at = 0;
    if (x === 0 && y === 0) { out.push([q.name, [[size, true]]]); continue; }
    const where = `${numeral(String(Number(at.toPrecision(4))).replace("-", "−"))}°`;
    // "{what} at {where}" as the language says it, each field a formula of its own
    const parts = w["{what} at {where}"].split(/(\{what\}|\{where\})/).filter(t => t)
      .map(t => t === "{what}" ? [size, true] : t === "{where}" ? [where, true] : [t, false]);
    out.push([q.name, parts]);
  }
  return out;
}

// ----- the output's curve ------------------------------------------------------------------
/* The output's signed rate against the input's angle (exercises/linkages/view_readout.py
   says which): an angle axis in degrees under it, ticked every 45° of the angle itself, and
   a value axis at its left, ticked at its least, 0 and its greatest, in the figures'
   units; the limit positions (grey) and dead points (red) as dashed lines. */
function drawPlot() {
  const svg = document.getElementById("plot"), box = svg.getBoundingClientRect();
  const w = box.width || 800, h = box.height || 120, vals = D.plot.values, n = vals.length;
  svg.setAttribute("viewBox", `0 0 ${w} ${h}`);
  const ok = vals.filter(x => x !== null), lo = Math.min(0, ...ok), hi = Math.max(0, ...ok);
  const top = 8, bottom = h - 30, left = 8;     // the axes meet where the curve starts
  // x as the slider's thumb stands (its track inset by half a thumb at each end)
  const y = v => bottom - (v - lo) / ((hi - lo) || 1) * (bottom - top), x = k => 8 + k / (n - 1) * (w - 16);
  let d = "", pen = "M";
  vals.forEach((val, k) => { if (val === null) { pen = "M"; return; }
                             d += `${pen}${num(x(k))},${num(y(val))} `; pen = "L"; });
  const marks = D.marks.map(m => `<line x1="${num(x(markFrame(m)))}" x2="${num(x(markFrame(m)))}" y1="${top}" y2="${bottom}" stroke="${m.kind === "dead" ? HOT : "#999"}" stroke-dasharray="3 3"/>`).join("");
  const small = "font:11px 'DejaVu Sans'", ticks = [];
  const deg = k => (D.input.angle + D.input.step * k) * 180 / Math.PI;
  for (let k = 0; k < n; k++) {           // a tick where the angle passes a multiple of 45°
    const a = deg(k), b = deg(k + 1), m = Math.ceil(Math.min(a, b) / 45 - 1e-9) * 45;
    if (m >= Math.max(a, b) - 1e-9) continue;
    const at = 8 + (k + (m - a) / (b - a)) / (n - 1) * (w - 16);
    if (at < left - 1e-9 || at > w - 8) continue;
    ticks.push(`<line class="tick" x1="${num(at)}" x2="${num(at)}" y1="${bottom}" y2="${bottom + 4}" stroke="#444"/>`
      + `<text x="${num(at)}" y="${bottom + 15}" text-anchor="middle" style="${small}">${numeral(((m % 360) + 360) % 360)}°</text>`);
  }
  const values = [...new Set([lo, 0, hi])].map(v => `<line x1="${left - 4}" x2="${left}" y1="${num(y(v))}" y2="${num(y(v))}" stroke="#444"/>`
    + `<text class="value" x="${left + 6}" y="${num(y(v) + 4)}" style="${small}" stroke="#fff" stroke-width="3" paint-order="stroke">${figures(v)}</text>`).join("");
  svg.innerHTML = `<line x1="${left}" x2="${w - 8}" y1="${num(y(0))}" y2="${num(y(0))}" stroke="#ccc"/>${marks}`
    + `<line x1="${left}" x2="${left}" y1="${top}" y2="${bottom}" stroke="#444"/>`
    + `<line x1="${left}" x2="${w - 8}" y1="${bottom}" y2="${bottom}" stroke="#444"/>${ticks.join("")}${values}`
    + `<path d="${d}" fill="none" stroke="#111" stroke-width="1.5"/>`
    + `<text id="value-axis" x="${left + 90}" y="${top + 10}" style="font:italic 12px 'DejaVu Serif'" stroke="#fff" stroke-width="3" paint-order="stroke">${esc(D.plot.symbol)} (${esc(D.plot.unit)})</text>`
    + `<text id="angle-axis" x="${w - 8}" y="${h - 2}" text-anchor="end" style="font:italic 12px 'DejaVu Serif'">${esc(D.input.symbol)} (°)</text>`
    + `<line id="cursor" y1="${top}" y2="${bottom}" stroke="${HOT}" stroke-width="1.5"/>`;
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
