/* tarsim serve: the mechanism being built, kept as the exercise file itself (the object
   TOML.parse gives), with a sketch of where each moving point stands. The page knows no
   kinematics: the sketch only says which assembly the user drew (written as a near point,
   B = [x, y]) and where to draw a point before the server has placed it. */
"use strict";
const Model = (() => {
  const ORDER = ["name", "source", "description", "units", "frame", "link", "slider", "contact",
                 "input", "assembly", "ask", "names"];
  const FIND_WIDE = ["dof", "grashof", "time_ratio", "stroke", "mu"];
  const METHODS = ["radius-rotation", "parallel-line", "components", "polygon",
                   "line-of-transmission", "klein"];

  /** An empty mechanism: the frame alone, in mm and degrees, asking the centres. */
  function empty() {
    return {
      ex: { name: "My linkage", units: { length: "mm", angle: "deg", angular_velocity: "rad/s" },
            frame: {}, link: [], input: { link: 2, angle: 60, omega: 10, alpha: 0 },
            ask: { find: ["centres"], methods: ["radius-rotation"] } },
      sketch: {}, autoFind: true, autoNames: new Set(), nearPoints: new Set(),
    };
  }

  /** A model from a file's text; null if it is not a linkage the editor can draw. */
  function fromToml(text) {
    const ex = TOML.parse(text);
    if (!ex.frame || !Array.isArray(ex.link)) return null;
    ex.slider ??= []; ex.contact ??= [];
    const sketch = {};
    for (const [p, xy] of Object.entries(ex.frame)) sketch[p] = xy.slice();
    return { ex, sketch, autoFind: false, autoNames: new Set(), nearPoints: new Set() };
  }

  /** The exercise file, its tables in the usual order, the near points from the sketch. */
  function toToml(m) {
    const ex = structuredClone(m.ex);
    for (const k of ["slider", "contact"]) if (!ex[k]?.length) delete ex[k];
    const inputPoints = new Set(link(m, ex.input?.link)?.points ?? []);
    for (const p of m.nearPoints) {
      if (!isFrame(m, p) && !inputPoints.has(p) && m.sketch[p] && m.ex.link.some(l => l.points.includes(p))) {
        (ex.assembly ??= {})[p] = m.sketch[p].map(v => round(v, 2));
      }
    }
    if (ex.assembly && !Object.keys(ex.assembly).length) delete ex.assembly;
    const ordered = {};
    for (const k of ORDER) if (k in ex) ordered[k] = ex[k];
    for (const k of Object.keys(ex)) if (!(k in ordered)) ordered[k] = ex[k];
    return TOML.write(ordered);
  }

  const round = (v, d) => Math.round(v * 10 ** d) / 10 ** d;
  const isFrame = (m, p) => Object.hasOwn(m.ex.frame, p);
  const link = (m, n) => m.ex.link.find(l => l.number === n);
  const points = m => [...Object.keys(m.ex.frame), ...movingPoints(m)];
  function movingPoints(m) {
    const seen = new Set();
    for (const l of m.ex.link) for (const p of l.points) if (!isFrame(m, p)) seen.add(p);
    for (const p of Object.keys(m.sketch)) if (!isFrame(m, p)) seen.add(p);
    return [...seen];
  }
  const where = (m, p) => m.ex.frame[p] ?? m.sketch[p];
  const pairKey = (m, l, a, b) => Object.keys(l.lengths ?? {}).find(k => k === a + b || k === b + a);

  function freshName(m, first) {
    const used = new Set(points(m));
    if (first === "O") { for (let k = 2; ; k++) if (!used.has("O" + k)) return "O" + k; }
    for (const c of "ABCDEFGHJKLMNPQRSTUVWXYZ") if (!used.has(c)) return c;
    for (let k = 1; ; k++) if (!used.has("P" + k)) return "P" + k;
  }

  function addGround(m, xy) {
    const p = freshName(m, "O");
    m.ex.frame[p] = xy.map(v => round(v, 3)); m.sketch[p] = m.ex.frame[p].slice();
    m.autoNames.add(p); return p;
  }
  function addPin(m, xy) {
    const p = freshName(m, "A");
    m.sketch[p] = xy.slice(); m.nearPoints.add(p); return p;
  }
  const nextNumber = m => Math.max(1, ...m.ex.link.map(l => l.number)) + 1;

  /** A binary link joining a and b (a frame point first: a link turns about its first
      point), its length measured off the sketch to the nearest 0.1. */
  function addLink(m, a, b) {
    if (isFrame(m, b) && !isFrame(m, a)) [a, b] = [b, a];
    const n = nextNumber(m);
    const [pa, pb] = [where(m, a), where(m, b)];
    const l = { number: n, points: [a, b], lengths: { [a + b]: round(Math.hypot(pb[0] - pa[0], pb[1] - pa[1]), 1) } };
    m.ex.link.push(l);
    for (const p of [a, b]) {                 // O? on link n becomes O_n, as the books name it
      if (m.autoNames.has(p) && isFrame(m, p) && !points(m).includes("O" + n) &&
          m.ex.link.filter(k => k.points.includes(p)).length === 1) rename(m, p, "O" + n);
    }
    if (!m.ex.link.some(k => k.number === m.ex.input.link) && isFrame(m, l.points[0])) m.ex.input.link = n;
    autoFind(m); return l;
  }

  /** A block carrying point p, on a frame guide through it (angle 0), or in link on's slot. */
  function addBlock(m, p, on) {
    const n = nextNumber(m);
    m.ex.link.push({ number: n, name: "block", points: [p] });
    const xy = where(m, p).map(v => round(v, 1));
    const s = on ? { link: n, point: p, on } : { link: n, point: p, on: 1, through: xy, angle: 0 };
    (m.ex.slider ??= []).push(s);
    if (!on) m.nearPoints.delete(p), ((m.ex.assembly ??= {})[p] ??= "forward");
    autoFind(m); return s;
  }

  /** A wheel about p rolling on a straight frame face under it. */
  function addWheel(m, p, r = 30) {
    const n = nextNumber(m);
    const [x, y] = where(m, p);
    const mark = freshName(m, "A");
    m.sketch[mark] = [x + r, y]; m.nearPoints.add(mark);
    m.ex.link.push({ number: n, name: "wheel", points: [p, mark], lengths: { [p + mark]: r } });
    const g = points(m).includes("G") ? freshName(m, "O") : "G";
    m.ex.frame[g] = [round(x, 1), round(y - r, 1)]; m.sketch[g] = m.ex.frame[g].slice();
    const c = { circle: { link: n, centre: p, radius: r }, face: { link: 1, through: g, angle: 0 },
                side: "left", rolling: true };
    (m.ex.contact ??= []).push(c);
    autoFind(m); return c;
  }

  function rename(m, from, to) {
    if (from === to || points(m).includes(to) || !/^[A-Za-z][A-Za-z0-9_']*$/.test(to)) return false;
    const swap = p => (p === from ? to : p);
    const ex = m.ex;
    if (isFrame(m, from)) {
      ex.frame = Object.fromEntries(Object.entries(ex.frame).map(([k, v]) => [swap(k), v]));
    }
    for (const l of ex.link) {
      if (l.lengths) {
        const keys = {};
        for (const [k, v] of Object.entries(l.lengths)) {
          let nk = k;
          for (const a of l.points) for (const b of l.points) if (a !== b && k === a + b) nk = swap(a) + swap(b);
          keys[nk] = v;
        }
        l.lengths = keys;
      }
      if (l.sides) l.sides = Object.fromEntries(Object.entries(l.sides).map(([k, v]) => [swap(k), v]));
      l.points = l.points.map(swap);
    }
    for (const s of ex.slider ?? []) { s.point = swap(s.point); if (typeof s.through === "string") s.through = swap(s.through); }
    for (const c of ex.contact ?? []) {
      for (const part of [c.circle, c.face]) for (const k of ["centre", "through"]) if (part?.[k]) part[k] = swap(part[k]);
    }
    if (ex.assembly) ex.assembly = Object.fromEntries(Object.entries(ex.assembly).map(([k, v]) => [swap(k), v]));
    if (ex.ask?.find) ex.ask.find = ex.ask.find.map(f => f.replace(new RegExp(`(?<=^[VA]_)${from}$`), to));
    m.sketch = Object.fromEntries(Object.entries(m.sketch).map(([k, v]) => [swap(k), v]));
    for (const set of [m.autoNames, m.nearPoints]) if (set.delete(from)) set.add(to);
    m.autoNames.delete(to);
    return true;
  }

  /** Sets link l's length between a and b, moving the sketch's free end along the link. */
  function setLength(m, l, a, b, value) {
    const key = pairKey(m, l, a, b) ?? a + b;
    (l.lengths ??= {})[key] = value;
    const [fixed, free] = isFrame(m, b) ? [b, a] : [a, b];
    const [p, q] = [where(m, fixed), where(m, free)];
    const d = Math.hypot(q[0] - p[0], q[1] - p[1]);
    if (!isFrame(m, free) && d > 0 && Number.isFinite(value) && value > 0) {
      m.sketch[free] = [p[0] + (q[0] - p[0]) * value / d, p[1] + (q[1] - p[1]) * value / d];
    }
  }

  /** Deletes a point (and every link, block and contact that needs it) or a link. */
  function remove(m, what) {
    const ex = m.ex;
    if (what.point) {
      const p = what.point;
      delete ex.frame[p]; delete m.sketch[p]; if (ex.assembly) delete ex.assembly[p];
      m.nearPoints.delete(p);
      for (const l of ex.link.filter(l => l.points.includes(p))) remove(m, { link: l.number });
      ex.slider = (ex.slider ?? []).filter(s => s.point !== p && s.through !== p);
      ex.contact = (ex.contact ?? []).filter(c => c.circle.centre !== p && c.face.through !== p);
    } else if (what.link) {
      const n = what.link;
      ex.link = ex.link.filter(l => l.number !== n);
      ex.slider = (ex.slider ?? []).filter(s => s.link !== n && s.on !== n);
      ex.contact = (ex.contact ?? []).filter(c => c.circle.link !== n && c.face.link !== n);
      renumber(m);
    } else if (what.slider !== undefined) {
      ex.slider.splice(what.slider, 1);
    } else if (what.contact !== undefined) {
      ex.contact.splice(what.contact, 1);
    }
    autoFind(m);
  }

  /** Numbers the links 2, 3, … again after a deletion, and every reference to them. */
  function renumber(m) {
    const ex = m.ex, map = { 1: 1 };
    ex.link.sort((a, b) => a.number - b.number).forEach((l, k) => { map[l.number] = k + 2; l.number = k + 2; });
    for (const s of ex.slider ?? []) { s.link = map[s.link]; s.on = map[s.on]; }
    for (const c of ex.contact ?? []) { c.circle.link = map[c.circle.link]; c.face.link = map[c.face.link]; }
    ex.input.link = map[ex.input.link] ?? ex.link.find(l => isFrame(m, l.points[0]))?.number ?? 2;
    if (ex.ask?.find) ex.ask.find = ex.ask.find.filter(f => {
      const k = /^(omega|alpha)(\d+)$/.exec(f); return !k || map[k[2]] !== undefined;
    }).map(f => f.replace(/^(omega|alpha)(\d+)$/, (_, w, n) => w + map[n]));
  }

  /** While the user has not chosen what to ask: the centres, the ω of each link but the
      input, and the velocity of each moving point off the input link. */
  function autoFind(m) {
    if (!m.autoFind) return;
    const input = link(m, m.ex.input.link);
    const find = ["centres"];
    for (const l of m.ex.link) if (l !== input && l.points.length > 1) find.push("omega" + l.number);
    for (const p of movingPoints(m)) if (!input?.points.includes(p) && m.ex.link.some(l => l.points.includes(p))) find.push("V_" + p);
    m.ex.ask.find = find;
  }

  /** Can it be sent to the server yet? Not before the input names a link; until then the
      page says what is missing rather than asking (the server judges all the rest). */
  function ready(m) {
    return link(m, m.ex.input?.link) ? null : "hint_input";
  }

  return { empty, fromToml, toToml, addGround, addPin, addLink, addBlock, addWheel, rename,
           setLength, remove, autoFind, ready, link, isFrame, points, movingPoints, where,
           pairKey, round, FIND_WIDE, METHODS };
})();
