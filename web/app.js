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

function plot(trace) {
  const div = document.getElementById('plot');
  div.innerHTML = '';
  const w = 900, h = 220, pad = 40;
  for (const [k, a] of trace.acquisitions.slice(0, 6).entries()) {
    const t0 = a.t[0], t1 = a.t[a.t.length - 1];
    const vmin = Math.min(...a.v, trace.low), vmax = Math.max(...a.v, trace.high);
    const x = (t) => pad + (w - 2 * pad) * (t - t0) / (t1 - t0);
    const y = (v) => h - pad - (h - 2 * pad) * (v - vmin) / (vmax - vmin);
    let d = '';
    a.t.forEach((t, i) => { d += (i ? 'L' : 'M') + x(t).toFixed(1) + ',' + y(a.v[i]).toFixed(1); });
    const svg = `<svg width="${w}" height="${h}" xmlns="http://www.w3.org/2000/svg">
      <text x="${pad}" y="14">acquisition ${k + 1}, ${a.channel}: ${seconds(t0)} to ${seconds(t1)}</text>
      <line x1="${pad}" x2="${w - pad}" y1="${y(trace.low)}" y2="${y(trace.low)}" stroke="#07c" stroke-dasharray="4"/>
      <line x1="${pad}" x2="${w - pad}" y1="${y(trace.high)}" y2="${y(trace.high)}" stroke="#c70" stroke-dasharray="4"/>
      <text x="${w - pad + 2}" y="${y(trace.low)}" font-size="11">${trace.low.toFixed(2)} V</text>
      <text x="${w - pad + 2}" y="${y(trace.high)}" font-size="11">${trace.high.toFixed(2)} V</text>
      <path d="${d}" fill="none" stroke="#222"/></svg>`;
    div.insertAdjacentHTML('beforeend', svg);
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
