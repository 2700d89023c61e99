const fs = require('fs');
const bytes = fs.readFileSync(process.argv[2]);
(async () => {
  const { instance } = await WebAssembly.instantiate(bytes, {});
  const x = instance.exports;
  const enc = new TextEncoder(), dec = new TextDecoder();
  function put(s) { const b = enc.encode(s); const p = x.cb_alloc(b.length); new Uint8Array(x.memory.buffer, p, b.length).set(b); return [p, b.length]; }
  function call(cmd, input) {
    const [cp, cl] = put(cmd), [ip, il] = put(JSON.stringify(input));
    const h = x.cb_call(cp, cl, ip, il);
    const hv = new DataView(x.memory.buffer, h, 8);
    const p = hv.getUint32(0, true), n = hv.getUint32(4, true);
    const out = dec.decode(new Uint8Array(x.memory.buffer, p, n));
    x.cb_free(p, n); x.cb_free(h, 8); x.cb_free(cp, cl); x.cb_free(ip, il);
    return JSON.parse(out);
  }
  const line = fs.readFileSync('bounce-table/scenes/catalogue.jsonl', 'utf8').split('\n')[2];
  console.log(JSON.stringify(call('eval', { line, method: 'auto' })).slice(0, 300));
  console.log(JSON.stringify(call('eval', { line: '{"omega": -1}' })));
  const rigol = fs.readFileSync('bounce-table/tests/fixtures/scope/rigol.csv', 'utf8');
  const r = call('calibrate', { args: ['--format', 'c'], files: [['rigol.csv', rigol]] });
  console.log(JSON.stringify(r).slice(0, 400));
  const t = call('trace', { files: [['rigol.csv', rigol]], args: [] });
  console.log(t.ok ? [t.ok.acquisitions.length, t.ok.acquisitions[0].low, t.ok.acquisitions[0].high] : t);
  const table = call('table', { text: line, args: ['--period', '0.001', '--format', 'rust'] });
  console.log(table.ok ? [table.ok.text.slice(0, 300), table.ok.plots.length, table.ok.plots[0].envelope.length] : table);
  const taps = call('replay', { args: ['--taps'], files: [['rigol.csv', rigol]] });
  console.log(taps.ok ? [taps.ok.text.slice(0, 200), taps.ok.plots.map((p) => p.name)] : taps);
})();
