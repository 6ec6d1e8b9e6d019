/* tarsim serve: the exercise file's TOML, read into a plain object and written back.
   Only what exercise files use: tables, arrays of tables, inline tables, arrays, strings
   (basic, literal, multi-line), numbers and booleans. The server is the judge of the
   file: a text this reader cannot read is still sent as it is. */
"use strict";
const TOML = (() => {
  function parse(text) {
    let i = 0;
    const root = {};
    let table = root;
    const err = msg => { throw new Error(`TOML line ${text.slice(0, i).split("\n").length}: ${msg}`); };
    const ws = () => { while (i < text.length && " \t\r".includes(text[i])) i++; };
    const comment = () => { ws(); if (text[i] === "#") while (i < text.length && text[i] !== "\n") i++; };
    const blank = () => { for (;;) { comment(); if (text[i] === "\n") i++; else return; } };
    function key() {
      ws();
      const parts = [];
      for (;;) {
        ws();
        if (text[i] === '"' || text[i] === "'") parts.push(string());
        else {
          const m = /^[A-Za-z0-9_-]+/.exec(text.slice(i));
          if (!m) err("a key was expected");
          parts.push(m[0]); i += m[0].length;
        }
        ws();
        if (text[i] === ".") { i++; continue; }
        return parts;
      }
    }
    function string() {
      const q = text[i];
      const triple = text.startsWith(q.repeat(3), i);
      i += triple ? 3 : 1;
      if (triple && text[i] === "\n") i++;
      let out = "";
      for (;;) {
        if (i >= text.length) err("a string is not closed");
        if (triple ? text.startsWith(q.repeat(3), i) : text[i] === q) { i += triple ? 3 : 1; return out; }
        if (text[i] === "\\" && q === '"') {
          const c = text[i + 1];
          if (c === "\n" || (c === "\r" && text[i + 2] === "\n")) {     // line continuation
            i += 1; while (" \t\r\n".includes(text[i])) i++; continue;
          }
          const simple = { n: "\n", t: "\t", r: "\r", '"': '"', "\\": "\\", b: "\b", f: "\f" };
          if (c in simple) { out += simple[c]; i += 2; continue; }
          if (c === "u" || c === "U") {
            const n = c === "u" ? 4 : 8;
            out += String.fromCodePoint(parseInt(text.substr(i + 2, n), 16)); i += 2 + n; continue;
          }
          err("an unknown escape");
        }
        out += text[i++];
      }
    }
    function value() {
      ws();
      const c = text[i];
      if (c === '"' || c === "'") return string();
      if (c === "[") {
        i++; const arr = [];
        for (;;) {
          blank();
          if (text[i] === "]") { i++; return arr; }
          arr.push(value()); blank();
          if (text[i] === ",") i++;
          else if (text[i] !== "]") err("a ',' or ']' was expected");
        }
      }
      if (c === "{") {
        i++; const obj = {};
        for (;;) {
          ws();
          if (text[i] === "}") { i++; return obj; }
          const k = key();
          if (text[i] !== "=") err("'=' was expected");
          i++; put(obj, k, value()); ws();
          if (text[i] === ",") i++;
        }
      }
      const m = /^(true|false|[+-]?(inf|nan)|[+-]?[0-9_]+(\.[0-9_]+)?([eE][+-]?[0-9_]+)?)/.exec(text.slice(i));
      if (!m) err("a value was expected");
      i += m[0].length;
      if (m[0] === "true" || m[0] === "false") return m[0] === "true";
      return Number(m[0].replace(/_/g, "").replace("inf", "Infinity"));
    }
    function put(obj, parts, v) {
      let o = obj;
      for (const p of parts.slice(0, -1)) o = (o[p] ??= {});
      o[parts[parts.length - 1]] = v;
    }
    for (;;) {
      blank();
      if (i >= text.length) return root;
      if (text[i] === "[") {
        const arrayOf = text[i + 1] === "[";
        i += arrayOf ? 2 : 1;
        const parts = key();
        i += arrayOf ? 2 : 1;
        let o = root;
        for (const p of parts.slice(0, -1)) { o = (o[p] ??= {}); if (Array.isArray(o)) o = o[o.length - 1]; }
        const last = parts[parts.length - 1];
        if (arrayOf) { (o[last] ??= []).push(table = {}); } else table = (o[last] ??= {});
      } else {
        const k = key();
        if (text[i] !== "=") err("'=' was expected");
        i++; put(table, k, value());
      }
      comment();
      if (i < text.length && text[i] !== "\n") err("the line goes on after its value");
    }
  }

  const bare = k => /^[A-Za-z0-9_-]+$/.test(k) ? k : JSON.stringify(k);
  const isTable = v => v !== null && typeof v === "object" && !Array.isArray(v);
  const isTables = v => Array.isArray(v) && v.length > 0 && v.every(isTable);
  function inline(v) {
    if (typeof v === "string") return v.includes("\n") && !/["\\]/.test(v)
      ? `"""\n${v}"""` : JSON.stringify(v);
    if (typeof v === "number") {
      if (!Number.isFinite(v)) return v > 0 ? "inf" : v < 0 ? "-inf" : "nan";
      return String(v);
    }
    if (typeof v === "boolean") return String(v);
    if (Array.isArray(v)) return `[${v.map(inline).join(", ")}]`;
    return `{ ${Object.entries(v).map(([k, x]) => `${bare(k)} = ${inline(x)}`).join(", ")} }`;
  }
  function body(obj) {
    return Object.entries(obj).filter(([, v]) => v !== undefined)
      .map(([k, v]) => `${bare(k)} = ${inline(v)}\n`).join("");
  }
  /** The object as TOML: its plain values first, then each table ([name]) and each array
      of tables ([[name]]); tables inside those are written inline. */
  function write(obj) {
    const flat = {}, out = [];
    for (const [k, v] of Object.entries(obj)) if (!isTable(v) && !isTables(v)) flat[k] = v;
    out.push(body(flat));
    for (const [k, v] of Object.entries(obj)) {
      if (isTable(v)) out.push(`[${bare(k)}]\n${body(v)}`);
      else if (isTables(v)) for (const t of v) out.push(`[[${bare(k)}]]\n${body(t)}`);
    }
    return out.filter(Boolean).join("\n");
  }
  return { parse, write };
})();
