/* tarsim serve: the exact numbers, typed. The selected point's, link's, block's or wheel's
   properties; the list of the mechanism's parts (an error shown on the row it names); the
   input (link, θ, ω, α) and what to find, by which methods. A field commits on change
   (Enter or leaving it), so a number half typed is never sent. */
"use strict";
const Panel = (() => {
  let app, t;
  const esc = s => String(s).replace(/[&<>"]/g, c => ({ "&": "&amp;", "<": "&lt;", ">": "&gt;", '"': "&quot;" })[c]);
  const num = v => { const x = Number(String(v).trim().replace("−", "-")); return Number.isFinite(x) ? x : null; };
  const unit = () => app.model.ex.units?.length ?? "mm";
  const angleUnit = () => (app.model.ex.units?.angle === "rad" ? "rad" : "°");
  const field = (id, value, label, u = "", type = "number", extra = "") =>
    `<label class="row"><span>${label}</span><span class="pair" style="grid-template-columns:1fr auto">` +
    `<input type="${type}" step="any" id="${id}" value="${esc(value ?? "")}" ${extra}><span class="unit">${u}</span></span></label>`;
  const select = (id, options, value, label) =>
    `<label class="row"><span>${label}</span><select id="${id}">${options.map(([v, w]) =>
      `<option value="${esc(v)}"${String(v) === String(value) ? " selected" : ""}>${esc(w)}</option>`).join("")}</select></label>`;
  function on(id, fn) {
    const e = document.getElementById(id);
    if (e) e.addEventListener("change", () => { fn(e.type === "checkbox" ? e.checked : e.value); app.changed(); });
  }

  function init(a, words) { app = a; t = words; }

  function render() { props(); parts(); input(); ask(); }

  function errorFor(what) {
    const w = app.error?.where ?? {};
    const hitIt = Object.entries(what).every(([k, v]) => v instanceof RegExp ? v.test(w[k] ?? "") : w[k] === v) &&
      Object.keys(w).length;
    return hitIt ? `<div class="err" data-error>${esc(app.error.text)}</div>` : "";
  }

  // --- the selected part --------------------------------------------------------------------
  function props() {
    const box = document.getElementById("props"), sel = app.selected, m = app.model;
    let html = `<h2>${t("props")}</h2>`;
    if (sel?.point !== undefined && Model.points(m).includes(sel.point)) html += pointProps(sel.point);
    else if (sel?.link !== undefined && Model.link(m, sel.link)) html += linkProps(Model.link(m, sel.link));
    else if (sel?.slider !== undefined && m.ex.slider?.[sel.slider]) html += sliderProps(m.ex.slider[sel.slider], sel.slider);
    else if (sel?.contact !== undefined && m.ex.contact?.[sel.contact]) html += contactProps(m.ex.contact[sel.contact]);
    else html += `<p>${t("nothing")}</p>`;
    box.innerHTML = html;
    wire(sel);
  }

  function pointProps(p) {
    const m = app.model, frame = Model.isFrame(m, p), xy = Model.where(m, p) ?? [0, 0];
    let h = `<p>${t("point")} <b>${esc(p)}</b> — ${frame ? t("frame_point") : t("sketch_point")}</p>` +
      field("p-name", p, t("name"), "", "text") +
      field("p-x", Model.round(xy[0], 3), t("x"), unit()) + field("p-y", Model.round(xy[1], 3), t("y"), unit());
    const onInput = Model.link(m, m.ex.input.link)?.points.includes(p);
    if (!frame && !onInput) {
      const a = m.ex.assembly?.[p], cur = m.nearPoints.has(p) ? "near" : typeof a === "string" ? a : "near";
      h += select("p-asm", ["near", "left", "right", "forward", "backward"].map(k => [k, t(k)]), cur, t("assembly"));
    }
    return h + errorFor({ joint: p });
  }

  function linkProps(l) {
    const m = app.model, isInput = m.ex.input.link === l.number;
    let h = `<p><span style="color:${Editor.colour(l.number)}">■</span> ${t("number")} <b>${l.number}</b>` +
      ` (${l.points.map(esc).join(" – ")})${isInput ? " — " + t("is_input") : ""}</p>` +
      field("l-name", l.name ?? "", t("name"), "", "text");
    const pairs = [];
    for (let i = 0; i < l.points.length; i++) for (let j = i + 1; j < l.points.length; j++) {
      if (l.points.length > 2 && i > 1) continue;            // AB, AC, BC of a plate; D from A and B
      pairs.push([l.points[i], l.points[j]]);
    }
    pairs.forEach(([a, b], k) => {
      const key = Model.pairKey(m, l, a, b);
      h += field(`l-len-${k}`, key ? l.lengths[key] : "", `${t("length")} ${esc(a + b)}`, unit(), "number", `data-a="${esc(a)}" data-b="${esc(b)}"`);
    });
    for (const p of l.points.slice(2)) {
      h += select(`l-side-${p}`, [["left", t("left")], ["right", t("right")]], l.sides?.[p] ?? "left",
                  `${t("side")} ${esc(l.points[0] + "→" + l.points[1])}: ${esc(p)}`);
    }
    const others = Model.points(m).filter(p => !l.points.includes(p));
    if (l.points.length >= 2 && others.length) {
      h += select("l-add", [["", "—"], ...others.map(p => [p, p])], "", t("add_point"));
    }
    if (!isInput && Model.isFrame(m, l.points[0])) h += `<button type="button" id="l-input">${t("make_input")}</button>`;
    return h + errorFor({ link: l.number });
  }

  function sliderProps(s, i) {
    const m = app.model;
    let h = `<p>${s.on === 1 ? t("block") : t("slot")}: ${t("number")} ${s.link}, ${t("point")} ${esc(s.point)}</p>`;
    h += select("s-kind", [["block", t("kind_block")], ["pin", t("kind_pin")]], s.kind ?? "block", t("kind"));
    const links = [[1, "1"], ...m.ex.link.filter(l => l.number !== s.link).map(l => [l.number, String(l.number)])];
    h += select("s-on", links, s.on, t("on"));
    if (s.on === 1) {
      const th = typeof s.through === "string" ? Model.where(m, s.through) : s.through ?? [0, 0];
      h += field("s-tx", th[0], `${t("through")} x`, unit()) + field("s-ty", th[1], `${t("through")} y`, unit()) +
        field("s-angle", s.angle ?? 0, t("angle"), angleUnit());
    }
    h += field("s-offset", s.offset ?? 0, t("offset"), unit());
    return h + errorFor({ slider: i });
  }

  function contactProps(c) {
    return `<p>${t("wheel")}: ${t("number")} ${c.circle.link}, ${esc(c.circle.centre)}</p>` +
      field("c-r", c.circle.radius, t("radius"), unit()) +
      field("c-angle", c.face.angle ?? 0, `${t("face")} ${t("angle")}`, angleUnit()) +
      select("c-side", [["left", t("left")], ["right", t("right")]], c.side ?? "left", t("side")) +
      `<label class="row"><span></span><span><input type="checkbox" id="c-roll"${c.rolling ? " checked" : ""}> ${t("rolling")}</span></label>`;
  }

  function wire(sel) {
    const m = app.model;
    if (sel?.point !== undefined) {
      const p = sel.point;
      on("p-name", v => { if (Model.rename(m, p, v.trim())) app.selected = { point: v.trim() }; });
      const setXY = (k, v) => {
        const x = num(v); if (x === null) return;
        if (Model.isFrame(m, p)) m.ex.frame[p][k] = x;
        (m.sketch[p] ??= [...Model.where(m, p)])[k] = x;
        app.dropShown();
      };
      on("p-x", v => setXY(0, v)); on("p-y", v => setXY(1, v));
      on("p-asm", v => {
        if (v === "near") { m.nearPoints.add(p); if (m.ex.assembly) delete m.ex.assembly[p]; }
        else { m.nearPoints.delete(p); (m.ex.assembly ??= {})[p] = v; }
      });
    }
    if (sel?.link !== undefined) {
      const l = Model.link(m, sel.link);
      on("l-name", v => { if (v.trim()) l.name = v.trim(); else delete l.name; });
      document.querySelectorAll("#props [id^=l-len-]").forEach(e => e.addEventListener("change", () => {
        const x = num(e.value);
        if (x !== null) { Model.setLength(m, l, e.dataset.a, e.dataset.b, x); app.dropShown(); }
        app.changed();
      }));
      for (const p of l.points.slice(2)) on(`l-side-${p}`, v => { (l.sides ??= {})[p] = v; });
      on("l-add", p => {
        if (!p) return;
        l.points.push(p);
        const pos = app.positions();
        for (const q of l.points.slice(0, 2)) {
          const [a, b] = [pos[q], pos[p]];
          if (a && b) l.lengths[q + p] = Model.round(Math.hypot(b[0] - a[0], b[1] - a[1]), 1);
        }
        (l.sides ??= {})[p] = "left";
      });
      const b = document.getElementById("l-input");
      if (b) b.onclick = () => { m.ex.input.link = l.number; Model.autoFind(m); app.changed(); };
    }
    if (sel?.slider !== undefined) {
      const s = m.ex.slider[sel.slider];
      on("s-kind", v => { if (v === "pin") s.kind = "pin"; else delete s.kind; });
      on("s-on", v => {
        s.on = Number(v);
        if (s.on === 1) { s.through ??= Model.where(m, s.point).map(x => Model.round(x, 1)); s.angle ??= 0; }
        else { delete s.through; delete s.angle; }
      });
      const th = k => v => {
        const x = num(v); if (x === null) return;
        s.through = typeof s.through === "string" ? [...Model.where(m, s.through)] : s.through.slice();
        s.through[k] = x;
      };
      on("s-tx", th(0)); on("s-ty", th(1));
      on("s-angle", v => { const x = num(v); if (x !== null) s.angle = x; });
      on("s-offset", v => { const x = num(v); if (x === null || x === 0) delete s.offset; else s.offset = x; });
    }
    if (sel?.contact !== undefined) {
      const c = m.ex.contact[sel.contact];
      on("c-r", v => {
        const x = num(v); if (x === null) return;
        c.circle.radius = x;
        const l = Model.link(m, c.circle.link);
        if (l?.points.length === 2 && l.points[0] === c.circle.centre) Model.setLength(m, l, l.points[0], l.points[1], x);
      });
      on("c-angle", v => { const x = num(v); if (x !== null) c.face.angle = x; });
      on("c-side", v => { c.side = v; });
      on("c-roll", v => { c.rolling = v; });
    }
  }

  // --- the parts ----------------------------------------------------------------------------
  function parts() {
    const m = app.model, sel = app.selected ?? {}, w = app.error?.where ?? {};
    const row = (what, body, swatch) => {
      const [k, v] = Object.entries(what)[0];
      const cls = [sel[k] === v ? "sel" : "", w[k === "point" ? "joint" : k] === v ? "bad" : ""].join(" ");
      return `<li class="${cls}" data-${k}="${esc(v)}">${swatch ? `<span class="sw" style="background:${swatch}"></span>` : ""}<span>${body}</span></li>`;
    };
    const len = l => Object.entries(l.lengths ?? {}).map(([k, v]) => `${esc(k)} = ${v}`).join(", ");
    let h = `<h2>${t("parts")}</h2><h3>${t("links")}</h3><ul>` +
      m.ex.link.map(l => row({ link: l.number }, `<b>${l.number}</b> ${esc(l.name ?? "")} <bdi dir="ltr">${esc(l.points.join("–"))}` +
        `${len(l) ? " · " + len(l) + " " + unit() : ""}${m.ex.input.link === l.number ? " · ω" + l.number : ""}</bdi>` +
        (w.link === l.number ? `<div class="err" data-error>${esc(app.error.text)}</div>` : ""), Editor.colour(l.number))).join("") + "</ul>";
    if (m.ex.slider?.length) h += `<h3>${t("sliders")}</h3><ul>` + m.ex.slider.map((s, i) =>
      row({ slider: i }, `${esc(s.point)} · ${t("number")} ${s.link} ${t("on")} ${s.on}${s.kind === "pin" ? " (" + t("kind_pin") + ")" : ""}`)).join("") + "</ul>";
    if (m.ex.contact?.length) h += `<h3>${t("contacts")}</h3><ul>` + m.ex.contact.map((c, i) =>
      row({ contact: i }, `${esc(c.circle.centre)} · r = ${c.circle.radius} ${unit()}`)).join("") + "</ul>";
    const joint = w.joint && !w.link && !Object.keys(sel).includes("point") ? `<div class="err" data-error>${esc(w.joint)}: ${esc(app.error.text)}</div>` : "";
    h += joint;
    const box = document.getElementById("parts");
    box.innerHTML = h;
    box.querySelectorAll("li").forEach(li => li.onclick = () => {
      const d = li.dataset;
      app.select(d.link ? { link: Number(d.link) } : d.slider ? { slider: Number(d.slider) } : { contact: Number(d.contact) });
    });
  }

  // --- the input and the asks ---------------------------------------------------------------
  function input() {
    const m = app.model, i = m.ex.input;
    // Any link may be the input (a crank about a frame pivot, or a wheel rolling on the frame).
    const pivoted = m.ex.link.filter(l => l.points.length > 1);
    const u = m.ex.units ?? {};
    let h = `<h2>${t("input")}</h2>` +
      select("i-link", pivoted.length ? pivoted.map(l => [l.number, `${l.number} (${l.points.join("–")})`]) : [["", "—"]], i.link, t("input_link"));
    const omega = typeof i.omega === "number" ? i.omega : "";
    // The input's rates may be given by another member (speed = {point, value}, omega =
    // {link, value}): shown as the file gives them, and kept.
    const given = i.speed ?? (typeof i.omega === "object" ? i.omega : null);
    h += field("i-angle", i.angle ?? 0, `${t("theta")}${i.link}`, angleUnit()) +
      (given ? `<p class="given">${t("given")}: <bdi dir="ltr">${esc(i.speed ? "speed" : "omega")} = { ${
        esc(Object.entries(given).map(([k, v]) => `${k} = ${JSON.stringify(v)}`).join(", "))} }</bdi></p>`
             : field("i-omega", omega, `${t("omega")}${i.link}`, u.angular_velocity ?? "rad/s")) +
      field("i-alpha", typeof i.alpha === "number" ? i.alpha : 0, `${t("alpha")}${i.link}`, "rad/s²");
    h += select("u-length", ["mm", "cm", "m", "in"].map(k => [k, k]), u.length ?? "mm", `${t("units")}`);
    const box = document.getElementById("input-box");
    box.innerHTML = h + (app.error?.where?.link ? "" : errorFor({ field: /^input/ }));
    on("i-link", v => { if (v) { i.link = Number(v); Model.autoFind(m); } });
    on("i-angle", v => { const x = num(v); if (x !== null) { i.angle = x; app.setAngle(x); } });
    on("i-omega", v => { const x = num(v); if (x !== null) i.omega = x; });
    on("i-alpha", v => { const x = num(v); if (x !== null) i.alpha = x; });
    on("u-length", v => { (m.ex.units ??= {}).length = v; });
  }

  function ask() {
    const m = app.model, a = (m.ex.ask ??= {}), find = a.find ?? [], methods = a.methods ?? [];
    const turning = m.ex.link.map(l => l.number);
    const pts = Model.movingPoints(m).filter(p => m.ex.link.some(l => l.points.includes(p)));
    const offered = ["centres", ...turning.map(n => "omega" + n), ...turning.map(n => "alpha" + n),
                     ...pts.map(p => "V_" + p), ...pts.map(p => "A_" + p)];
    offered.push(...Model.FIND_WIDE);
    const extra = find.filter(f => !offered.includes(f));
    const label = f => f === "centres" ? t("centres") : f.replace(/^omega(\d+)$/, "ω$1").replace(/^alpha(\d+)$/, "α$1");
    let h = `<h2>${t("ask")}</h2><div class="checks" id="a-find">` + offered.map(f =>
      `<label><input type="checkbox" value="${esc(f)}"${find.includes(f) ? " checked" : ""}> ${esc(label(f))}</label>`).join("") + "</div>" +
      `<label class="row"><span>${t("more")}</span><input type="text" id="a-more" value="${esc(extra.join(", "))}"></label>` +
      `<h3>${t("methods")}</h3><div class="checks" id="a-methods">` + Model.METHODS.map(k =>
        `<label><input type="checkbox" value="${k}"${methods.includes(k) ? " checked" : ""}> ${t(k.replace(/-/g, "_"))}</label>`).join("") + "</div>";
    const box = document.getElementById("ask-box");
    box.innerHTML = h + errorFor({ field: /^ask/ });
    const collect = () => {
      m.autoFind = false;
      const picked = [...box.querySelectorAll("#a-find input:checked")].map(e => e.value);
      const more = document.getElementById("a-more").value.split(",").map(s => s.trim()).filter(Boolean);
      a.find = [...picked, ...more];
      a.methods = Model.METHODS.filter(k => box.querySelector(`#a-methods input[value="${k}"]`).checked);
      if (!a.methods.length) delete a.methods;
      app.changed();
    };
    box.querySelectorAll("input").forEach(e => e.addEventListener("change", collect));
  }

  return { init, render };
})();
