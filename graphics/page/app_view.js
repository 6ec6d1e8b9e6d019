/* tarsim serve: the page's state, its talk with the server, and the worked solution shown
   as the server sends it (figures, readout, results beside the analytic check, steps).
   Every edit writes the exercise file from the model and asks /api/solve; the page itself
   computes nothing of the mechanism's motion. */
"use strict";
const App = (() => {
  const app = {
    model: Model.empty(), raw: null, tool: "select", selected: null, error: null, lang: "en",
    shown: null, solution: null, figure: null, angle: null, seq: 0, timer: null, ctrl: null,
  };
  const t = k => WORDS[app.lang][k] ?? WORDS.en[k] ?? k;
  const $ = id => document.getElementById(id);
  const esc = s => String(s).replace(/[&<>"]/g, c => ({ "&": "&amp;", "<": "&lt;", ">": "&gt;", '"': "&quot;" })[c]);
  const minus = s => s.replace(/^-/, "−").replace(/e\+?(-?)(\d+)$/, (_, s, d) => `×10^${s}${d}`);
  // Rounding's leftovers (α = −3e−18 rad/s² of a link that does not turn) read as 0.
  const sig = (x, n = 4) => minus(String(Math.abs(x) < 1e-9 ? 0 : Number(Number(x).toPrecision(n))));

  /** Every point's place to draw: the frame's, then where the server last put each moving
      point (at the angle shown), else where the user drew it. */
  app.positions = () => {
    const m = app.model, out = {};
    for (const p of Model.points(m)) {
      const xy = Model.isFrame(m, p) ? m.ex.frame[p] : app.shown?.[p] ?? m.sketch[p];
      if (xy) out[p] = xy;
    }
    return out;
  };
  app.select = (what, changed = false) => {
    app.selected = what ?? null;
    if (changed) app.changed(); else { Editor.draw(); Panel.render(); }
  };
  app.changed = () => { app.error = null; Editor.draw(); Panel.render(); schedule(150); };
  app.dragging = () => { app.shown = null; };
  app.dropShown = () => { app.shown = null; };
  app.setAngle = x => { app.angle = x; showAngle(); };
  /** Turns the input to ``deg`` (the slider, the play button, the crank dragged). */
  app.turn = deg => { app.angle = deg; showAngle(); schedule(30, true); };

  function fileAngle() { return Number(app.model.ex.input?.angle ?? 0); }
  function showAngle() {
    const a = app.angle ?? fileAngle();
    const wrapped = ((a + 180) % 360 + 360) % 360 - 180;
    $("angle").value = wrapped; $("angle-out").value = `${sig(a, 5)}°`;
  }

  // --- solving ------------------------------------------------------------------------------
  /** Asks the server ``ms`` after the last edit. Turning the input asks twice: at once
      without figures (the readout and the drawing follow the slider), then with them once
      the slider rests, so the chosen construction is redrawn at that angle. */
  function schedule(ms, quickFirst = false) {
    clearTimeout(app.timer); clearTimeout(app.quick);
    app.unasked = true;                              // an edit not yet sent
    document.body.dataset.state = "pending";
    if (quickFirst) app.quick = setTimeout(() => solve(false), ms);
    app.timer = setTimeout(() => solve(true), quickFirst ? ms + 220 : ms);
  }
  function text() { return app.raw ?? Model.toToml(app.model); }

  async function solve(figures = true) {
    if (figures) app.unasked = false;
    if (!app.raw) {
      const why = !app.model.ex.link.length ? "hint_empty" : Model.ready(app.model);
      $("hint").textContent = why ? t(why) : "";
      $("hint").classList.toggle("big", why === "hint_empty");
      if (why) {
        state("idle");
        if (!app.solution) $("figure").innerHTML = `<p class="placeholder">${esc(t("no_solution"))}</p>`;
        return;
      }
    }
    const seq = ++app.seq;
    app.ctrl?.abort(); app.ctrl = new AbortController();
    const body = { toml: text(), lang: app.lang, figures, ...app.source };
    const override = app.angle !== null && Math.abs(app.angle - fileAngle()) > 1e-9;
    // At another angle: that position alone, without what belongs to no one position (the
    // time ratio, the stroke), which turning the input does not change.
    if (override) Object.assign(body, { angle: app.angle, whole: false });
    // The quick answer to an edit is the position's alone, in a few milliseconds; what is
    // asked of the mechanism as a whole comes with the figures' answer that follows.
    else if (!figures) body.whole = false;
    if (figures) state("solving");
    const t0 = performance.now();
    let res, data;
    try {
      res = await fetch("api/solve", { method: "POST", headers: { "Content-Type": "application/json" },
                                       body: JSON.stringify(body), signal: app.ctrl.signal });
      data = await res.json();
    } catch (e) {
      if (e.name === "AbortError") return;
      if (seq === app.seq) { app.error = { text: t("offline"), where: {} }; state("error"); redraw(); }
      return;
    }
    if (seq !== app.seq) return;
    if (!figures) {                    // the quick answer: the figures' answer follows
      if (res.ok) { place(data.points, override); Editor.draw(); readout(data); }
      return;
    }
    if (!res.ok) {
      app.error = { text: data.error ?? res.statusText, where: whereOf(data) };
      state("error"); redraw(); return;
    }
    app.error = null; app.solution = data;
    const ms = performance.now() - t0, first = !app.shown;
    place(data.points, override);
    if (first && offPaper()) Editor.fit();
    state("solved", ms);
    redraw(); showSolution();
  }

  /** The moving points where the server put them: the sketch follows at the file's own
      angle (so a near point stays on its branch), the drawing at any angle. */
  function place(points, override) {
    if (!points || app.raw) return;
    app.shown = points;
    if (!override) for (const [p, xy] of Object.entries(points)) if (!Model.isFrame(app.model, p)) app.model.sketch[p] = xy;
  }

  function offPaper() {
    const svg = $("editor"), r = svg.getBoundingClientRect(), pos = app.positions();
    const pts = Object.values(pos);
    for (const c of app.model.ex.contact ?? []) {
      const xy = pos[c.circle.centre];
      if (xy) pts.push([xy[0] - c.circle.radius, xy[1]], [xy[0] + c.circle.radius, xy[1]]);
    }
    return pts.some(xy => {
      const [x, y] = Editor.pageXY(xy);
      return x < r.left + 20 || x > r.right - 20 || y < r.top + 40 || y > r.bottom - 20;
    });
  }

  /** Where the error is: the server's "where", else the link or point its line names. */
  function whereOf(data) {
    if (data.where && Object.keys(data.where).length) return data.where;
    const l = /\blink (\d+)/.exec(data.error ?? ""), p = /\bpoint ([A-Za-z][A-Za-z0-9_']*)/.exec(data.error ?? "");
    return l ? { link: Number(l[1]) } : p ? { joint: p[1] } : {};
  }

  function state(s, ms) {
    // An answer that comes while a newer edit waits to be sent is shown, but the page is
    // not "solved" until that edit is answered too.
    document.body.dataset.state = app.unasked ? "pending" : s;
    const st = $("status");
    st.className = s === "error" ? "bad" : "";
    st.textContent = s === "solving" ? t("solving") : s === "solved" ? `✓ ${t("solved")}` : s === "error" ? "⚠" : "";
    st.title = s === "solved" ? `${Math.round(ms)} ms` : "";
    $("solution").classList.toggle("stale", s === "error");
    if (s === "error" && app.solution) $("solution").title = t("stale");
  }

  function redraw() {
    Editor.draw(); Panel.render();
    const note = $("raw-note");                // another chapter's file: its error over it
    note.textContent = app.error ? `⚠ ${app.error.text}` : t("raw_note");
    note.classList.toggle("err", !!app.error);
  }

  // --- the solution -------------------------------------------------------------------------
  function showSolution() {
    const s = app.solution; if (!s) return;
    const figs = s.figures ?? [];
    if (!figs.some(f => f.name === app.figure)) {       // the same figure at the new position
      app.figure = (figs.find(f => base(f.name) === base(app.figure ?? "")) ??
                    figs.find(f => /components|radius|polygon/.test(f.name)) ?? figs[0])?.name;
    }
    const titles = figs.map(f => f.title || f.name);
    const label = (f, k) => titles.indexOf(titles[k]) === titles.lastIndexOf(titles[k]) ? titles[k]
      : `${titles[k]} · ${position(f.name) ?? f.name}`;
    $("fig-tabs").innerHTML = figs.map((f, k) => `<button type="button" data-fig="${esc(f.name)}" title="${esc(f.name)}" class="${f.name === app.figure ? "on" : ""}">${esc(label(f, k))}</button>`).join("");
    $("fig-tabs").querySelectorAll("button").forEach(b => b.onclick = () => { app.figure = b.dataset.fig; showSolution(); });
    const fig = figs.find(f => f.name === app.figure);
    if (fig) { $("figure").innerHTML = fig.svg; inked($("figure").querySelector("svg")); }
    readout(s);
    $("table").innerHTML = `<tr><th>${t("quantity")}</th><th>${t("construction")}</th><th>${t("analytic")}</th><th>${t("rel_error")}</th></tr>` +
      (s.table ?? []).map(r => {
        const e = r.error === null || r.error === undefined ? NaN : Number(r.error);
        const ok = typeof r.passed === "boolean" ? r.passed : !(e > 1e-6);
        return `<tr><td>${esc(symbol(r.quantity))}${r.position ? ` <small>${esc(r.position)}</small>` : ""}</td>` +
          `<td>${cell(r.construction)}</td><td>${cell(r.analytic)}</td>` +
          `<td class="${ok ? "ok" : "off"}">${Number.isFinite(e) ? e.toExponential(1) : ""} ${ok ? "✓" : "✗"}</td></tr>`;
      }).join("");
    $("steps").innerHTML = s.steps ?? "";
  }
  /** The figure shown by its ink: the sheet's margins and empty paper cut off, so the
      drawing fills the column (a download keeps the whole sheet, true to scale). */
  function inked(svg) {
    const box = svg?.viewBox?.baseVal;
    if (!box || !box.width) return;
    let [x0, y0, x1, y1] = [Infinity, Infinity, -Infinity, -Infinity];
    for (const c of svg.children) {
      if (typeof c.getBBox !== "function") continue;
      const b = c.getBBox();
      if (!b.width && !b.height || b.width >= .95 * box.width && b.height >= .95 * box.height) continue;
      x0 = Math.min(x0, b.x); y0 = Math.min(y0, b.y); x1 = Math.max(x1, b.x + b.width); y1 = Math.max(y1, b.y + b.height);
    }
    if (!(x1 > x0 && y1 > y0)) return;
    const pad = 0.02 * Math.max(x1 - x0, y1 - y0);
    svg.setAttribute("viewBox", `${x0 - pad} ${y0 - pad} ${x1 - x0 + 2 * pad} ${y1 - y0 + 2 * pad}`);
    svg.removeAttribute("width"); svg.removeAttribute("height");
  }

  // A figure of one of several positions is named for it: V_B-radius-rotation-theta2-90.
  const AT = /-(?:theta(\d+)-(-?[\d.]+)|t-(-?[\d.]+)s)$/;
  const base = name => name.replace(AT, "");
  const position = name => {
    const m = AT.exec(name);
    return m && (m[1] ? `θ${m[1]} = ${minus(m[2])}°` : `t = ${m[3]} s`);
  };
  const symbol = q => q.replace(/\bomega(\d)/g, "ω$1").replace(/\balpha(\d)/g, "α$1");
  const cell = v => Array.isArray(v) ? `(${v.map(x => cell(x)).join(", ")})` : typeof v === "number" ? sig(v, 6) : esc(v ?? "");

  function readout(s) {
    const items = [];
    for (const [n, w] of Object.entries(s.omega ?? {})) {
      items.push(`<span data-q="omega${n}">ω${n} = ${sig(w)} rad/s${w ? ` <b>(${t(w > 0 ? "ccw" : "cw")})</b>` : ""}</span>`);
    }
    for (const [n, a] of Object.entries(s.alpha ?? {})) items.push(`<span data-q="alpha${n}">α${n} = ${sig(a)} rad/s²</span>`);
    const asked = (app.raw ? [] : app.model.ex.ask?.find ?? []).filter(f => /^V_[^/]+$/.test(f)).map(f => f.slice(2));
    const pts = asked.length ? asked : Object.keys(s.velocities ?? {}).filter(p => !Model.isFrame(app.model, p));
    for (const p of pts) {
      const v = s.velocities?.[p]; if (!v) continue;
      items.push(`<span data-q="V_${esc(p)}">V_${esc(p)} = ${sig(v.magnitude)} ${esc(v.unit ?? "mm/s")}` +
        (v.angle_deg !== undefined ? ` <b>∠ ${sig(v.angle_deg, 4)}°</b>` : "") + "</span>");
    }
    if (s.angle === null || s.angle === undefined) { $("readout").innerHTML = ""; return; }
    $("readout").innerHTML = `<span><b>${esc(t("readout"))} θ = ${sig(s.angle ?? fileAngle(), 5)}°</b></span>` + items.join("");
  }

  // --- files --------------------------------------------------------------------------------
  async function exercises() {
    let list;
    try { list = await (await fetch("api/exercises")).json(); } catch { return; }
    const groups = {};
    for (const b of list.bundled ?? []) (groups[b.chapter ?? ""] ??= []).push(b);
    $("open").innerHTML = `<option value="">${t("open")}…</option>` +
      Object.entries(groups).map(([ch, xs]) => `<optgroup label="${esc(t("bundled"))}: ${esc(ch)}">` +
        xs.map(b => `<option value="id:${esc(b.id)}">${esc(b.title || b.id)}</option>`).join("") + "</optgroup>").join("") +
      (list.files?.length ? `<optgroup label="${esc(t("folder"))}">` + list.files.map(f => `<option value="file:${esc(f)}">${esc(f)}</option>`).join("") + "</optgroup>" : "");
  }

  async function open(value) {
    app.unasked = true; document.body.dataset.state = "pending";
    const [kind, ref] = [value.slice(0, value.indexOf(":")), value.slice(value.indexOf(":") + 1)];
    const res = await fetch(`api/exercise?${kind}=${encodeURIComponent(ref)}`);
    const data = await res.json();
    if (!res.ok) { app.unasked = false; app.error = { text: data.error, where: {} }; state("error"); redraw(); return; }
    load(data.toml, kind === "id" ? { id: ref } : { file: ref });
  }

  function load(toml, source = {}) {
    app.source = source;
    let m = null;
    try { m = Model.fromToml(toml); } catch { m = null; }
    app.raw = m ? null : toml;
    document.body.classList.toggle("raw", !!app.raw);
    $("source").value = app.raw ?? "";
    app.model = m ?? Model.empty();
    app.selected = null; app.shown = null; app.error = null; app.solution = null; app.angle = null;
    $("name").value = app.raw ? (/^name\s*=\s*"(.*)"/m.exec(toml)?.[1] ?? "") : app.model.ex.name ?? "";
    $("name").disabled = !!app.raw;
    $("hint").textContent = "";
    showAngle();
    ["fig-tabs", "figure", "table", "steps", "readout"].forEach(id => { $(id).innerHTML = ""; });
    $("figure").innerHTML = `<p class="placeholder">${esc(t("solving"))}</p>`;
    Editor.fit(); redraw();
    schedule(0);
  }

  async function download(what) {
    const body = { toml: text(), lang: app.lang, what, ...app.source };
    if (app.angle !== null && Math.abs(app.angle - fileAngle()) > 1e-9 && what !== "toml") body.angle = app.angle;
    if (["svg", "pdf", "png"].includes(what)) body.figure = app.figure;
    const res = await fetch("api/download", { method: "POST", headers: { "Content-Type": "application/json" }, body: JSON.stringify(body) });
    if (!res.ok) {
      const d = await res.json().catch(() => ({}));
      app.error = { text: d.error ?? res.statusText, where: whereOf(d) }; state("error"); redraw(); return;
    }
    const name = /filename\*?=(?:UTF-8'')?"?([^";]+)"?/.exec(res.headers.get("Content-Disposition") ?? "")?.[1] ?? `tarsim.${what}`;
    const url = URL.createObjectURL(await res.blob());
    const a = document.createElement("a");
    a.href = url; a.download = decodeURIComponent(name); document.body.appendChild(a); a.click(); a.remove();
    setTimeout(() => URL.revokeObjectURL(url), 5000);
    $("downloads").open = false;
  }

  /** Saves the exercise in the served folder (the server writes nowhere else), asking
      before it replaces a file the app did not write. */
  async function save() {
    $("downloads").open = false;
    const name = prompt(t("save_as"), app.source.file ?? `${(app.source.id ?? "my-linkage")}.toml`);
    if (!name) return;
    const send = overwrite => fetch("api/save", { method: "POST", headers: { "Content-Type": "application/json" },
      body: JSON.stringify({ file: name, toml: text(), overwrite }) });
    let res = await send(false);
    if (res.status === 409 && confirm(`${name} ${t("overwrite")}`)) res = await send(true);
    const d = await res.json().catch(() => ({}));
    if (!res.ok) { app.error = { text: d.error ?? res.statusText, where: {} }; state("error"); redraw(); return; }
    app.source = { file: d.file ?? name };
    $("status").textContent = `${t("saved")}: ${d.file ?? name}`;
    exercises();
  }

  // --- language -----------------------------------------------------------------------------
  function words() {
    document.documentElement.lang = app.lang;
    document.documentElement.dir = app.lang === "fa" ? "rtl" : "ltr";
    document.title = t("app");
    document.querySelectorAll("[data-w]").forEach(e => { e.textContent = t(e.dataset.w); });
    document.querySelectorAll("[data-t]").forEach(e => { e.title = t(e.dataset.t); });
    Editor.toolbar(t);
    $("play").title = t("play");
    const first = $("open").options[0];
    if (first) first.textContent = `${t("open")}…`; else $("open").innerHTML = `<option value="">${esc(t("open"))}…</option>`;
    exercises();
  }

  function start() {
    Editor.init(app); Panel.init(app, t);
    words();
    $("lang").onclick = () => { app.lang = app.lang === "en" ? "fa" : "en"; words(); redraw(); schedule(0); };
    $("new").onclick = fresh;
    $("open").onchange = e => { if (e.target.value) open(e.target.value); e.target.value = ""; };
    $("name").onchange = e => { if (!app.raw) { app.model.ex.name = e.target.value; app.changed(); } };
    $("angle").oninput = e => app.turn(Number(e.target.value));
    $("play").onclick = () => {            // the input turning on its own, 3° a step
      if (app.playing) { clearInterval(app.playing); app.playing = null; }
      else app.playing = setInterval(() => app.turn(((app.angle ?? fileAngle()) + 3 + 180) % 360 - 180), 150);
      $("play").textContent = app.playing ? "⏸" : "▶";
    };
    $("reset-angle").onclick = () => { app.angle = null; showAngle(); schedule(0); };
    document.querySelectorAll("#downloads [data-what]").forEach(b => b.onclick = () => download(b.dataset.what));
    $("save").onclick = save;
    $("source").oninput = e => { app.raw = e.target.value; schedule(400); };
    $("figure").onclick = e => {            // a closer look at the figure, and back
      const f = $("figure"), r = f.getBoundingClientRect();
      const at = [(e.clientX - r.left) / r.width, (e.clientY - r.top) / r.height];
      f.classList.toggle("zoomed");
      if (f.classList.contains("zoomed")) {
        f.scrollLeft = at[0] * f.scrollWidth - r.width / 2; f.scrollTop = at[1] * f.scrollHeight - f.clientHeight / 2;
      }
    };
    const q = new URLSearchParams(location.search);
    if (q.get("id")) open("id:" + q.get("id")); else if (q.get("file")) open("file:" + q.get("file")); else fresh();
  }
  function fresh() {
    app.source = {}; app.raw = null; document.body.classList.remove("raw"); app.model = Model.empty(); app.selected = null; app.shown = null; app.error = null;
    app.solution = null; app.angle = null;
    $("name").value = app.model.ex.name; $("name").disabled = false;
    ["fig-tabs", "figure", "table", "steps", "readout"].forEach(id => { $(id).innerHTML = ""; });
    showAngle(); Editor.fit(); redraw(); solve();
  }

  return { app, start, toml: text, pageXY: xy => Editor.pageXY(xy) };
})();
window.tarsimApp = App;
document.addEventListener("DOMContentLoaded", App.start);
