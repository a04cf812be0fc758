// ports/web/page/worker.js — runs the shitsukan WASM module off the page's thread, so heavy
// work (lattices, scale patterns, maps) never freezes the page. Plumbing only: it calls the
// C API function it is asked for (ports/web/api/shitsukan_web.h) and copies the outputs.
//
// Request  {id, fn: 'sk_okada1987_marble_slice', args: [16, 32, 512], want: ['picture', 'floats', 'text']}
// Reply    {id, code, codeName, message, ms, picture: {width, height, data}, floats: {columns, data}, text}
//          code 0 = ok; otherwise the library's StatusCode and its own message. code -1: the
//          module aborted (message says why). Progress: {progress: 0..1} from the library's
//          Progress callback (api_common.cpp) while a call runs.
/* global createShitsukan */
'use strict';
if (typeof createShitsukan === 'undefined') importScripts('shitsukan_web.js');  // hosted build

let Module = null;
const ready = createShitsukan({
  print: (t) => console.log(t),
  printErr: (t) => console.warn(t),
}).then((m) => {
  Module = m;
  m._sk_init();
  postMessage({ ready: true, version: m.UTF8ToString(m._sk_version()) });
}).catch((e) => postMessage({ ready: false, error: String(e) }));

function run(req) {
  const m = Module;
  const fn = m['_' + req.fn];
  if (typeof fn !== 'function' || !/^sk_[a-z0-9_]+$/.test(req.fn))
    return { id: req.id, code: -2, codeName: 'no such function', message: 'no C API function ' + req.fn };
  m._sk_clear_outputs();
  const t0 = performance.now();
  let code;
  try {
    code = fn.apply(null, req.args);
  } catch (e) {
    return { id: req.id, code: -1, codeName: 'abort', message: 'the module stopped: ' + String(e) };
  }
  const reply = {
    id: req.id, code, ms: performance.now() - t0,
    codeName: m.UTF8ToString(m._sk_status_code_name()),
    message: m.UTF8ToString(m._sk_status_message()),
  };
  const transfer = [];
  const want = req.want || ['picture', 'floats', 'text'];
  if (want.includes('picture')) {
    const w = m._sk_picture_width(), h = m._sk_picture_height();
    const p = m._sk_picture_data();
    const data = new Uint8ClampedArray(m.HEAPU8.buffer.slice(p, p + w * h * 4));
    reply.picture = { width: w, height: h, data };
    transfer.push(data.buffer);
  }
  if (want.includes('floats')) {
    const n = m._sk_floats_count(), p = m._sk_floats_data();
    const data = new Float32Array(m.HEAPU8.buffer.slice(p, p + n * 4));
    reply.floats = { columns: m._sk_floats_columns(), data };
    transfer.push(data.buffer);
  }
  if (want.includes('text')) reply.text = m.UTF8ToString(m._sk_text());
  return [reply, transfer];
}

onmessage = (e) => {
  ready.then(() => {
    const r = run(e.data);
    if (Array.isArray(r)) postMessage(r[0], r[1]);
    else postMessage(r);
  });
};
