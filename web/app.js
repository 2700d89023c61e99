// The page's input and drawing. Everything computed comes from the module (web/wasm), the
// library the `bounce-table` command runs: nothing of the model is written here.
'use strict';

let wasm = null;

function call(command, input) {
  const x = wasm.exports, enc = new TextEncoder(), dec = new TextDecoder();
  const put = (s) => {
    const b = enc.encode(s), p = x.cb_alloc(b.length);
    new Uint8Array(x.memory.buffer, p, b.length).set(b);
    return [p, b.length];
  };
  const [cp, cl] = put(command), [ip, il] = put(JSON.stringify(input));
  const h = x.cb_call(cp, cl, ip, il);
  const view = new DataView(x.memory.buffer, h, 8);
  const p = view.getUint32(0, true), n = view.getUint32(4, true);
  const out = dec.decode(new Uint8Array(x.memory.buffer, p, n).slice());
  x.cb_free(p, n); x.cb_free(h, 8); x.cb_free(cp, cl); x.cb_free(ip, il);
  return JSON.parse(out);
}

function seconds(t) {
  if (t === null || t === undefined) return 'endless';
  if (t < 1e-3) return (t * 1e6).toFixed(2) + ' us';
  return (t * 1e3).toFixed(3) + ' ms';
}

function evaluate() {
  const line = document.getElementById('scene').value.trim();
  const body = document.querySelector('#tiers tbody');
  const error = document.getElementById('scene-error');
  body.innerHTML = ''; error.textContent = '';
  for (const method of ['exact-tier', 'auto', 'map', 'averaged', 'closed']) {
    const r = call('eval', { line, method });
    if (r.error) {
      error.textContent = (r.field ? r.field + ': ' : '') + r.error;
      return;
    }
    const o = r.ok, row = document.createElement('tr');
    const err = o.expected_error === null ? 'none stated' : (o.expected_error * 100).toPrecision(2) + ' %';
    for (const cell of [method, seconds(o.end_time ?? o.last_above_time), err, (o.approximations || []).join(', ') || '-']) {
      const td = document.createElement('td'); td.textContent = cell; row.appendChild(td);
    }
    body.appendChild(row);
  }
}

// Round steps for an axis: 1, 2 or 5 times a power of ten, about `n` of them.
function ticks(lo, hi, n) {
  const raw = (hi - lo) / n, p = Math.pow(10, Math.floor(Math.log10(raw)));
  const step = [1, 2, 5, 10].map((m) => m * p).find((s) => s >= raw);
  const out = [];
  for (let v = Math.ceil(lo / step) * step; v <= hi + step * 1e-9; v += step) out.push(v);
  return out;
}

// One acquisition: volts against microseconds, the two thresholds dashed, each level change a
// tick on the time axis, and the window calibrate recommends for its kind shaded from the
// first change. Drag across the plot to zoom in on a span, double-click to zoom out.
function plot(trace) {
  const div = document.getElementById('plot');
  div.innerHTML = '';
  const w = 900, h = 240, left = 60, right = 70, top = 24, bottom = 40;
  for (const [k, a] of trace.acquisitions.slice(0, 6).entries()) {
    const box = document.createElement('div');
    div.appendChild(box);
    const draw = (t0, t1) => {
      const vmin = Math.min(...a.v, trace.low), vmax = Math.max(...a.v, trace.high);
      const x = (t) => left + (w - left - right) * (t - t0) / (t1 - t0);
      const y = (v) => h - bottom - (h - top - bottom) * (v - vmin) / (vmax - vmin);
      let d = '';
      a.t.forEach((t, i) => {
        if (t >= t0 && t <= t1) d += (d ? 'L' : 'M') + x(t).toFixed(1) + ',' + y(a.v[i]).toFixed(1);
      });
      let axes = `<line x1="${left}" x2="${w - right}" y1="${h - bottom}" y2="${h - bottom}" stroke="#000"/>
        <line x1="${left}" x2="${left}" y1="${top}" y2="${h - bottom}" stroke="#000"/>
        <text x="${(w - right + left) / 2}" y="${h - 6}" text-anchor="middle" font-size="12">time (us)</text>
        <text x="14" y="${(h - bottom + top) / 2}" font-size="12" transform="rotate(-90 14 ${(h - bottom + top) / 2})" text-anchor="middle">volts (V)</text>`;
      for (const t of ticks(t0 * 1e6, t1 * 1e6, 8)) {
        const px = x(t / 1e6);
        axes += `<line x1="${px}" x2="${px}" y1="${h - bottom}" y2="${h - bottom + 4}" stroke="#000"/>
          <text x="${px}" y="${h - bottom + 16}" font-size="11" text-anchor="middle">${+t.toPrecision(6)}</text>`;
      }
      for (const v of ticks(vmin, vmax, 4)) {
        axes += `<line x1="${left - 4}" x2="${left}" y1="${y(v)}" y2="${y(v)}" stroke="#000"/>
          <text x="${left - 6}" y="${y(v) + 4}" font-size="11" text-anchor="end">${+v.toPrecision(4)}</text>`;
      }
      let marks = '';
      const window = trace.windows[a.kind];
      if (a.changes.length && window !== undefined) {
        const from = a.changes[0], to = Math.min(from + window, t1);
        if (to > t0 && from < t1) {
          const x0 = x(Math.max(from, t0)), x1 = x(to);
          marks += `<rect x="${x0}" y="${top}" width="${Math.max(x1 - x0, 1)}" height="${h - top - bottom}" fill="#2a2" fill-opacity="0.12"/>
            <text x="${x0 + 4}" y="${top + 12}" font-size="11" fill="#161">${a.kind} window ${seconds(window)}</text>`;
        }
      }
      for (const c of a.changes) {
        if (c >= t0 && c <= t1) marks += `<line x1="${x(c)}" x2="${x(c)}" y1="${h - bottom - 6}" y2="${h - bottom}" stroke="#c00"/>`;
      }
      box.innerHTML = `<svg width="${w}" height="${h}" xmlns="http://www.w3.org/2000/svg" style="user-select:none">
        <text x="${left}" y="14" font-size="12">acquisition ${k + 1} (${a.kind}), ${a.channel}: ${a.changes.length} level changes</text>
        ${marks}${axes}
        <line x1="${left}" x2="${w - right}" y1="${y(trace.low)}" y2="${y(trace.low)}" stroke="#07c" stroke-dasharray="4"/>
        <line x1="${left}" x2="${w - right}" y1="${y(trace.high)}" y2="${y(trace.high)}" stroke="#c70" stroke-dasharray="4"/>
        <text x="${w - right + 4}" y="${y(trace.low) + 4}" font-size="11">low ${trace.low.toFixed(2)} V</text>
        <text x="${w - right + 4}" y="${y(trace.high) + 4}" font-size="11">high ${trace.high.toFixed(2)} V</text>
        <path d="${d}" fill="none" stroke="#222"/></svg>`;
      const svg = box.firstChild;
      const toTime = (e) => t0 + (t1 - t0) * (e.offsetX - left) / (w - left - right);
      let start = null;
      svg.onmousedown = (e) => { start = toTime(e); };
      svg.onmouseup = (e) => {
        const end = toTime(e);
        if (start !== null && Math.abs(end - start) > (t1 - t0) / 200) draw(Math.min(start, end), Math.max(start, end));
        start = null;
      };
      svg.ondblclick = () => draw(a.t[0], a.t[a.t.length - 1]);
    };
    draw(a.t[0], a.t[a.t.length - 1]);
  }
}

function analyse(name, text) {
  const args = document.getElementById('options').value.split(/\s+/).filter((s) => s);
  const error = document.getElementById('capture-error');
  error.textContent = '';
  const progress = document.getElementById('progress');
  progress.textContent = `reading ${name} (${(text.length / 1e6).toFixed(1)} MB)...`;
  setTimeout(() => {
    const trace = call('trace', { name, text, args });
    if (trace.ok) plot(trace.ok); else document.getElementById('plot').innerHTML = '';
    for (const command of ['calibrate', 'replay']) {
      const r = call(command, { args, files: [[name, text]] });
      document.getElementById(command).textContent = r.ok ?? '';
      if (r.error) error.textContent = r.error;
    }
    progress.textContent = '';
  }, 0);
}

function tab(on) {
  for (const id of ['calc', 'capture']) {
    document.getElementById(id).classList.toggle('on', id === on);
    document.getElementById('tab-' + id).classList.toggle('on', id === on);
  }
}

async function main() {
  const bytes = Uint8Array.from(atob(CONTACT_BOUNCE_WASM), (c) => c.charCodeAt(0));
  wasm = (await WebAssembly.instantiate(bytes, {})).instance;
  const select = document.getElementById('switch');
  for (const line of call('catalogue', {}).ok) {
    const o = document.createElement('option');
    o.value = line; o.textContent = JSON.parse(line).name; select.appendChild(o);
  }
  select.value = select.options[2].value; // the tactile dome
  const scene = document.getElementById('scene');
  scene.value = select.value;
  select.onchange = () => { scene.value = select.value; evaluate(); };
  scene.oninput = evaluate;
  evaluate();
  document.getElementById('tab-calc').onclick = () => tab('calc');
  document.getElementById('tab-capture').onclick = () => tab('capture');
  const read = (file) => file.text().then((text) => analyse(file.name, text));
  document.getElementById('file').onchange = (e) => read(e.target.files[0]);
  const drop = document.getElementById('drop');
  drop.ondragover = (e) => e.preventDefault();
  drop.ondrop = (e) => { e.preventDefault(); read(e.dataTransfer.files[0]); };
}

main();
