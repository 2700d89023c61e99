// The page's input and drawing. Everything computed comes from the module (web/wasm), the
// library the `bounce-table` command runs: nothing of the model is written here.
'use strict';

let wasm = null;

// Runs a command of the module `instance` (a command name and a JSON input; the JSON answer).
// The same function runs in the worker (its text is sent there).
function callOn(instance, command, input) {
  const x = instance.exports, enc = new TextEncoder(), dec = new TextDecoder();
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

function call(command, input) {
  return callOn(wasm, command, input);
}

// A capture is analysed in a worker (a page of its own thread: a 10 MB capture takes seconds,
// and the page stays responsive). Built from a Blob, so that it also starts from file://.
// Each message: one command; the answer comes back with the message's id.
let worker = null;
const pending = new Map();
function startWorker(bytes) {
  const source = `'use strict';
${callOn.toString()}
let instance = null;
onmessage = async (e) => {
  const m = e.data;
  if (m.bytes) { instance = (await WebAssembly.instantiate(m.bytes, {})).instance; return; }
  let answer;
  try { answer = callOn(instance, m.command, m.input); } catch (err) { answer = { error: String(err) }; }
  postMessage({ id: m.id, answer });
};`;
  worker = new Worker(URL.createObjectURL(new Blob([source], { type: 'text/javascript' })));
  worker.onmessage = (e) => { pending.get(e.data.id)(e.data.answer); pending.delete(e.data.id); };
  worker.postMessage({ bytes });
}
let nextId = 0;
function ask(command, input) {
  return new Promise((resolve) => {
    const id = nextId++;
    pending.set(id, resolve);
    worker.postMessage({ id, command, input });
  });
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
  design(line);
}

// The table mode on the scene: its window in ticks of the period, the firmware constants,
// and the envelope J(t) with the exact impacts (the CLI's --plot SVG).
function design(line) {
  const error = document.getElementById('window-error');
  const period = document.getElementById('period').value.trim();
  const margin = document.getElementById('margin').value.trim();
  const format = document.getElementById('constants-format').value;
  const args = ['--sample-period', period, '--margin', margin];
  error.textContent = '';
  for (const id of ['window', 'constants', 'envelope']) document.getElementById(id).innerHTML = '';
  const table = call('table', { text: line, args });
  if (table.error) { error.textContent = table.error; return; }
  document.getElementById('window').textContent = table.ok.text;
  const constants = call('table', { text: line, args: [...args, '--format', format] });
  document.getElementById('constants').textContent = constants.ok ? constants.ok.text : constants.error;
  const plot = table.ok.plots[0];
  if (plot) document.getElementById('envelope').innerHTML = plot.envelope;
}

// Round steps for an axis: 1, 2 or 5 times a power of ten, about `n` of them.
function ticks(lo, hi, n) {
  const raw = (hi - lo) / n, p = Math.pow(10, Math.floor(Math.log10(raw)));
  const step = [1, 2, 5, 10].map((m) => m * p).find((s) => s >= raw);
  const out = [];
  for (let v = Math.ceil(lo / step) * step; v <= hi + step * 1e-9; v += step) out.push(v);
  return out;
}

// The capture's tests, six at a time (the pager's buttons move through them).
const PAGE = 6;
let shown = { trace: null, start: 0 };
function plot(trace) {
  shown = { trace, start: 0 };
  page();
}
function page() {
  const { trace, start } = shown, n = trace.acquisitions.length;
  const div = document.getElementById('plot');
  div.innerHTML = '';
  const pager = document.createElement('div');
  const label = document.createElement('span');
  label.id = 'pager';
  label.textContent = ` tests ${start + 1}-${Math.min(start + PAGE, n)} of ${n} `;
  for (const [text, to] of [['previous', start - PAGE], ['next', start + PAGE]]) {
    const b = document.createElement('button');
    b.textContent = text; b.id = 'pager-' + text;
    b.disabled = to < 0 || to >= n;
    b.onclick = () => { shown.start = to; page(); };
    if (text === 'next') pager.appendChild(label);
    pager.appendChild(b);
  }
  div.appendChild(pager);
  for (let k = start; k < Math.min(start + PAGE, n); k++) {
    const box = document.createElement('div');
    div.appendChild(box);
    drawTest(box, trace, trace.acquisitions[k], k);
  }
}

// A time axis's unit for a span (s): microseconds or milliseconds.
function unit(span) {
  return span < 2e-3 ? [1e6, 'us'] : [1e3, 'ms'];
}

// One test: an analog acquisition (volts, the two thresholds dashed) or a capture of levels'
// event (the contact's state, a step at each change), against time; each level change a tick on
// the time axis, and the window calibrate recommends for its switch and kind shaded from the
// first change. Drag across the plot to zoom in on a span, double-click to zoom out.
function drawTest(box, trace, a, k) {
  const analog = a.t !== undefined;
  const w = 900, h = 240, left = 60, right = 70, top = 24, bottom = 40;
  const window = trace.windows[a.switch + '/' + a.kind];
  let t0full, t1full, points;
  if (analog) {
    t0full = a.t[0]; t1full = a.t[a.t.length - 1];
    points = a.t.map((t, i) => [t, a.v[i]]);
  } else {
    // Levels: 0 open, 1 closed; a press starts open. Relative to the first change.
    const c = a.changes.map((t) => t - a.changes[0]);
    const end = Math.max(c[c.length - 1], window ?? 0);
    const pad = Math.max(end, 1e-6) * 0.15;
    t0full = -pad; t1full = end + pad;
    let level = a.kind === 'press' ? 0 : 1;
    points = [[t0full, level]];
    for (const t of c) { points.push([t, level]); level = 1 - level; points.push([t, level]); }
    points.push([t1full, level]);
  }
  const changes = analog ? a.changes : a.changes.map((t) => t - a.changes[0]);
  const draw = (t0, t1) => {
    const [scale, name] = unit(t1 - t0);
    const vmin = analog ? Math.min(...a.v, a.low) : -0.1, vmax = analog ? Math.max(...a.v, a.high) : 1.1;
    const x = (t) => left + (w - left - right) * (t - t0) / (t1 - t0);
    const y = (v) => h - bottom - (h - top - bottom) * (v - vmin) / (vmax - vmin);
    let d = '';
    for (const [t, v] of points) if (t >= t0 && t <= t1) d += (d ? 'L' : 'M') + x(t).toFixed(1) + ',' + y(v).toFixed(1);
    const yName = analog ? 'volts (V)' : 'contact';
    let axes = `<line x1="${left}" x2="${w - right}" y1="${h - bottom}" y2="${h - bottom}" stroke="#000"/>
      <line x1="${left}" x2="${left}" y1="${top}" y2="${h - bottom}" stroke="#000"/>
      <text x="${(w - right + left) / 2}" y="${h - 6}" text-anchor="middle" font-size="12">time (${name})${analog ? '' : ', from the first change'}</text>
      <text x="14" y="${(h - bottom + top) / 2}" font-size="12" transform="rotate(-90 14 ${(h - bottom + top) / 2})" text-anchor="middle">${yName}</text>`;
    for (const t of ticks(t0 * scale, t1 * scale, 8)) {
      const px = x(t / scale);
      axes += `<line x1="${px}" x2="${px}" y1="${h - bottom}" y2="${h - bottom + 4}" stroke="#000"/>
        <text x="${px}" y="${h - bottom + 16}" font-size="11" text-anchor="middle">${+t.toPrecision(6)}</text>`;
    }
    const levels = analog ? ticks(vmin, vmax, 4).map((v) => [v, +v.toPrecision(4)]) : [[0, 'open'], [1, 'closed']];
    for (const [v, text] of levels) {
      axes += `<line x1="${left - 4}" x2="${left}" y1="${y(v)}" y2="${y(v)}" stroke="#000"/>
        <text x="${left - 6}" y="${y(v) + 4}" font-size="11" text-anchor="end">${text}</text>`;
    }
    let marks = '';
    if (changes.length && window !== undefined) {
      const from = changes[0], to = Math.min(from + window, t1);
      if (to > t0 && from < t1) {
        const x0 = x(Math.max(from, t0)), x1 = x(to);
        marks += `<rect x="${x0}" y="${top}" width="${Math.max(x1 - x0, 1)}" height="${h - top - bottom}" fill="#2a2" fill-opacity="0.12"/>
          <text x="${x0 + 4}" y="${top + 12}" font-size="11" fill="#161">${a.kind} window ${seconds(window)}</text>`;
      }
    }
    for (const c of changes) {
      if (c >= t0 && c <= t1) marks += `<line x1="${x(c)}" x2="${x(c)}" y1="${h - bottom - 6}" y2="${h - bottom}" stroke="#c00"/>`;
    }
    const thresholds = analog ? `
      <line x1="${left}" x2="${w - right}" y1="${y(a.low)}" y2="${y(a.low)}" stroke="#07c" stroke-dasharray="4"/>
      <line x1="${left}" x2="${w - right}" y1="${y(a.high)}" y2="${y(a.high)}" stroke="#c70" stroke-dasharray="4"/>
      <text x="${w - right + 4}" y="${y(a.low) + 4}" font-size="11">low ${a.low.toFixed(2)} V</text>
      <text x="${w - right + 4}" y="${y(a.high) + 4}" font-size="11">high ${a.high.toFixed(2)} V</text>` : '';
    const title = analog ? `acquisition ${k + 1} (${a.kind}), ${a.file}, ${a.channel}` : `${a.origin} (${a.kind}), ${a.switch}${a.section ? ', ' + a.section : ''}`;
    box.innerHTML = `<svg width="${w}" height="${h}" xmlns="http://www.w3.org/2000/svg" style="user-select:none">
      <text x="${left}" y="14" font-size="12">${escape(title)}: ${a.changes.length} level changes</text>
      ${marks}${axes}${thresholds}
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
    svg.ondblclick = () => draw(t0full, t1full);
  };
  draw(t0full, t1full);
}

// Text from a capture, safe inside SVG markup.
function escape(text) {
  return String(text).replace(/[&<>"]/g, (c) => ({ '&': '&amp;', '<': '&lt;', '>': '&gt;', '"': '&quot;' })[c]);
}

// The capture's steps, each one command in the worker: the trace (analog captures), calibrate,
// replay on isolated presses, and replay on taps with human timing.
// `files`: one capture file, or a folder's files (several acquisitions, one a file), each
// [name, text]; `switch` names a folder.
async function analyse(files, folder) {
  const args = document.getElementById('options').value.split(/\s+/).filter((s) => s);
  const error = document.getElementById('capture-error');
  error.textContent = '';
  const bar = document.getElementById('progress-bar'), label = document.getElementById('progress');
  const common = folder ? { files, switch: folder } : { files };
  const steps = [
    ['trace', { ...common, args }, 'reading the trace'],
    ['calibrate', { ...common, args }, 'calibrate'],
    ['replay', { ...common, args }, 'replay (isolated presses)'],
    ['replay', { ...common, args: [...args, '--taps'] }, 'replay (taps with human timing)'],
  ];
  const size = files.reduce((sum, [, text]) => sum + text.length, 0);
  const name = folder ? `${folder} (${files.length} files)` : files[0][0];
  for (const id of ['plot', 'calibrate', 'replay', 'taps', 'replay-plots', 'taps-plots']) document.getElementById(id).innerHTML = '';
  bar.max = steps.length; bar.hidden = false;
  const errors = [];
  for (const [k, [command, input, what]] of steps.entries()) {
    bar.value = k;
    label.textContent = `${name} (${(size / 1e6).toFixed(1)} MB): ${what}, step ${k + 1} of ${steps.length}`;
    const r = await ask(command, input);
    if (k === 0) {
      if (r.ok) plot(r.ok);
      continue; // a capture of levels has no trace: calibrate says what is wrong, if anything
    }
    if (r.error) { errors.push(r.error); continue; }
    if (command === 'calibrate') document.getElementById('calibrate').textContent = r.ok;
    else {
      const which = k === 2 ? 'replay' : 'taps';
      document.getElementById(which).textContent = r.ok.text;
      document.getElementById(which + '-plots').innerHTML = r.ok.plots.map((p) => p.svg).join('');
    }
  }
  error.textContent = [...new Set(errors)].join('\n');
  bar.value = steps.length; bar.hidden = true;
  label.textContent = '';
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
  startWorker(bytes);
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
  for (const id of ['period', 'margin', 'constants-format']) document.getElementById(id).onchange = evaluate;
  evaluate();
  document.getElementById('tab-calc').onclick = () => tab('calc');
  document.getElementById('tab-capture').onclick = () => tab('capture');
  // Several files are a folder's (sorted by name and hidden files left out, as the CLI reads a
  // folder), named by their folder where the browser says it (else "capture").
  const read = async (list) => {
    const chosen = [...list].filter((f) => !f.name.startsWith('.')).sort((a, b) => (a.name < b.name ? -1 : a.name > b.name ? 1 : 0));
    if (!chosen.length) return;
    const files = await Promise.all(chosen.map(async (f) => [f.name, await f.text()]));
    const path = chosen[0].webkitRelativePath || '';
    const folder = files.length > 1 ? (path.includes('/') ? path.split('/')[0] : 'capture') : null;
    analyse(files, folder);
  };
  document.getElementById('file').onchange = (e) => read(e.target.files);
  const drop = document.getElementById('drop');
  drop.ondragover = (e) => e.preventDefault();
  drop.ondrop = (e) => { e.preventDefault(); read(e.dataTransfer.files); };
}

main();
