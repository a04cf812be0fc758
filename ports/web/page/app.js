// ports/web/page/app.js — the explorer's plumbing: the panel registry, the worker that runs the
// WASM module, controls that show the library's Status beside them, drawing returned
// pictures, the figures' parameter tables, the self-test (#selftest), the interaction test
// (#interaction) and the bench (#bench). No algorithm here: every number comes from the C
// API (ports/web/api/), every picture is a buffer it returned.
'use strict';
(function () {
  const SK = (window.SK = { panels: [], version: '', lastMs: {} });

  // ---- errors: into the page (and the console), never silent ----
  function pageError(text) {
    const box = document.getElementById('sk-errors');
    if (box) {
      box.hidden = false;
      box.textContent += text + '\n';
    }
    document.body.dataset.errors = String(Number(document.body.dataset.errors || 0) + 1);
  }
  window.addEventListener('error', (e) => pageError('error: ' + e.message));
  window.addEventListener('unhandledrejection', (e) => pageError('error: ' + String(e.reason)));

  // ---- the worker ----
  function makeWorker() {
    const inline = document.getElementById('sk-worker-src');
    if (inline) {  // single-file build: the module and worker.js travel inside the page
      const url = URL.createObjectURL(new Blob([inline.textContent], { type: 'text/javascript' }));
      return new Worker(url);
    }
    return new Worker('worker.js');  // hosted build
  }
  let worker = null;  // started at DOMContentLoaded (the single file carries its source below the scripts)
  let nextId = 1;
  const waiting = new Map();
  let outstanding = 0;
  const idleWaiters = [];
  let progressSink = null;
  let workerStarted, workerFailed;
  SK.workerReady = new Promise((resolve, reject) => { workerStarted = resolve; workerFailed = reject; });
  SK.workerReady.catch(() => {});
  function startWorker() {
    worker = makeWorker();
    worker.addEventListener('message', (e) => {
      const d = e.data;
      if (d.ready === true) {
        SK.version = d.version;
        workerStarted();
      } else if (d.ready === false) {
        pageError('the WASM module did not start: ' + d.error);
        workerFailed(new Error(d.error));
      } else if (d.progress !== undefined) {
        if (progressSink) progressSink(d.progress);
      } else if (waiting.has(d.id)) {
        const done = waiting.get(d.id);
        waiting.delete(d.id);
        done(d);
      }
    });
    worker.addEventListener('error', (e) => pageError('worker: ' + e.message));
  }

  function settle() {
    if (outstanding === 0)
      requestAnimationFrame(() => {
        if (outstanding !== 0) return;
        while (idleWaiters.length) idleWaiters.shift()();
      });
  }
  // One C API call in the worker (calls run in the order made). Resolves with the reply.
  SK.call = function (fn, args, want) {
    outstanding++;
    return SK.workerReady.then(() => new Promise((resolve) => {
      const id = nextId++;
      waiting.set(id, (reply) => {
        outstanding--;
        if (reply.code === -1 || reply.code === -2) pageError(fn + ': ' + reply.message);
        SK.lastMs[fn] = reply.ms;
        resolve(reply);
        settle();
      });
      worker.postMessage({ id, fn, args, want });
    }));
  };
  // Resolves when no call and no panel update is pending (after the next frame is drawn).
  SK.idle = () => new Promise((resolve) => { idleWaiters.push(resolve); settle(); });
  // Wraps an async update so that a burst of control events runs it at most once at a time,
  // and once more at the end with the latest values (a slider dragged never queues up work).
  SK.coalesce = function (update) {
    let running = false, again = false, last = Promise.resolve();
    const run = () => {
      if (running) { again = true; return last; }
      running = true;
      outstanding++;
      last = Promise.resolve().then(update).catch((e) => pageError(String(e && e.stack || e))).then(() => {
        running = false;
        outstanding--;
        if (again) { again = false; return run(); }
        settle();
      });
      return last;
    };
    return run;
  };

  // ---- hashing: FNV-1a 64 (as ports/web/native_reference.cpp), in two 32-bit halves ----
  SK.fnv64 = function (bytes) {
    let lo = 0x84222325, hi = 0xcbf29ce4;
    for (let i = 0; i < bytes.length; i++) {
      lo = (lo ^ bytes[i]) >>> 0;
      // h * 0x100000001b3 mod 2^64 = h * 0x1b3 + (h << 40)
      const a = lo * 0x1b3;
      const carry = Math.floor(a / 4294967296);
      const newHi = (hi * 0x1b3 + carry + ((lo << 8) >>> 0)) % 4294967296;
      lo = a >>> 0;
      hi = newHi >>> 0;
    }
    return hi.toString(16).padStart(8, '0') + lo.toString(16).padStart(8, '0');
  };
  SK.canvasHash = (canvas) => {
    if (!canvas.width || !canvas.height) return 'empty';
    const img = canvas.getContext('2d').getImageData(0, 0, canvas.width, canvas.height);
    return SK.fnv64(img.data);
  };
  const utf8 = (s) => new TextEncoder().encode(s);

  // ---- drawing returned buffers ----
  SK.draw = function (canvas, picture) {
    if (!picture || !picture.width) return false;
    if (canvas.width !== picture.width) canvas.width = picture.width;
    if (canvas.height !== picture.height) canvas.height = picture.height;
    canvas.getContext('2d').putImageData(new ImageData(picture.data, picture.width, picture.height), 0, 0);
    canvas.dataset.hash = '';
    return true;
  };
  // A polyline of values (a profile, a curve) on a canvas: drawing only.
  SK.plot = function (canvas, values, opts) {
    const o = Object.assign({ min: 0, max: 1, color: '#1f5f99', label: '' }, opts || {});
    const g = canvas.getContext('2d'), w = canvas.width, h = canvas.height;
    g.fillStyle = '#fff';
    g.fillRect(0, 0, w, h);
    g.strokeStyle = '#ccc';
    g.strokeRect(0.5, 0.5, w - 1, h - 1);
    g.strokeStyle = o.color;
    g.lineWidth = 1.5;
    g.beginPath();
    for (let i = 0; i < values.length; i++) {
      const x = (i / (values.length - 1)) * (w - 8) + 4;
      const y = h - 4 - ((values[i] - o.min) / (o.max - o.min)) * (h - 8);
      if (i === 0) g.moveTo(x, y); else g.lineTo(x, y);
    }
    g.stroke();
    if (o.label) {
      g.fillStyle = '#333';
      g.font = '11px sans-serif';
      g.fillText(o.label, 6, 13);
    }
  };

  // ---- controls ----
  function el(tag, attrs, parent, text) {
    const e = document.createElement(tag);
    for (const k in attrs || {}) e.setAttribute(k, attrs[k]);
    if (text !== undefined) e.textContent = text;
    if (parent) parent.appendChild(e);
    return e;
  }
  SK.el = el;
  let controlId = 0;
  // A labelled slider with a number box (any value can be typed: the library judges it) and
  // the Status message of the last call it caused beside it.
  SK.slider = function (parent, o) {
    const row = el('div', { class: 'sk-control' }, parent);
    const id = 'sk-c' + (++controlId);
    el('label', { for: id }, row, o.label);
    const range = el('input', { type: 'range', min: o.min, max: o.max, step: o.step, value: o.value, 'aria-label': o.label }, row);
    const box = el('input', { type: 'number', id, step: o.step, value: o.value, class: 'sk-number' }, row);
    const status = el('span', { class: 'sk-status', role: 'status' }, row);
    if (o.key) { range.dataset.key = o.key; box.dataset.key = o.key + '-number'; }
    const c = {
      row, range, box, status,
      get value() { return Number(box.value); },
      set(v) { box.value = v; range.value = v; },
      onchange: null,
    };
    range.addEventListener('input', () => { box.value = range.value; if (c.onchange) c.onchange(); });
    box.addEventListener('input', () => { if (box.value !== '') { range.value = box.value; if (c.onchange) c.onchange(); } });
    return c;
  };
  SK.select = function (parent, o) {
    const row = el('div', { class: 'sk-control' }, parent);
    const id = 'sk-c' + (++controlId);
    el('label', { for: id }, row, o.label);
    const sel = el('select', { id }, row);
    o.options.forEach(([v, t]) => { const op = el('option', { value: v }, sel, t); if (String(v) === String(o.value)) op.selected = true; });
    const status = el('span', { class: 'sk-status', role: 'status' }, row);
    const c = { row, sel, status, get value() { return Number(sel.value); }, onchange: null };
    sel.addEventListener('change', () => { if (c.onchange) c.onchange(); });
    return c;
  };
  // A picture turned by the mouse (drag) and by two sliders (the keyboard's way: Tab to a
  // slider, arrow keys): dragging moves the sliders, and either calls update().
  SK.turnable = function (canvas, yaw, pitch, update) {
    let drag = null;
    canvas.addEventListener('pointerdown', (e) => { drag = { x: e.clientX, y: e.clientY, yaw: yaw.value, pitch: pitch.value }; canvas.setPointerCapture(e.pointerId); });
    canvas.addEventListener('pointermove', (e) => {
      if (!drag) return;
      yaw.set((drag.yaw + (e.clientX - drag.x) * 0.01).toFixed(2));
      pitch.set(Math.max(Number(pitch.range.min), Math.min(Number(pitch.range.max), drag.pitch + (e.clientY - drag.y) * 0.01)).toFixed(2));
      update();
    });
    canvas.addEventListener('pointerup', () => { drag = null; });
    canvas.style.cursor = 'grab';
  };
  // Shows a reply's Status beside the control that caused it; true when the call succeeded.
  SK.report = function (control, reply) {
    if (!reply) return false;
    const ok = reply.code === 0;
    control.status.textContent = ok ? '' : reply.codeName + ': ' + reply.message;
    control.row.classList.toggle('sk-bad', !ok);
    return ok;
  };
  SK.clearReport = (control) => { control.status.textContent = ''; control.row.classList.remove('sk-bad'); };
  // A canvas with a caption under it.
  SK.figure = function (parent, caption, w, h) {
    const fig = el('figure', { class: 'sk-figure' }, parent);
    const canvas = el('canvas', { width: w || 256, height: h || 256 }, fig);
    const cap = el('figcaption', {}, fig);
    cap.innerHTML = caption;
    return { fig, canvas, cap };
  };
  // The parameter tables the figures record (paper_figures, via params.js), merged.
  SK.params = function (parent, figureIds) {
    const all = window.SK_FIGURE_PARAMS || {};
    const box = el('details', { class: 'sk-params', open: '' }, parent);
    el('summary', {}, box, 'Parameters as the figures record them: given by the paper, or chosen here (' + figureIds.join(', ') + ')');
    const table = el('table', {}, box);
    const head = el('tr', {}, el('thead', {}, table));
    ['parameter', 'value', 'given / chosen', 'where / why'].forEach((t) => el('th', {}, head, t));
    const body = el('tbody', {}, table);
    const seen = new Set();
    figureIds.forEach((id) => {
      const f = all[id];
      if (!f) { pageError('no parameters recorded for figure ' + id); return; }
      f.rows.forEach((r) => {
        const key = r[0] + '|' + r[1];
        if (seen.has(key)) return;
        seen.add(key);
        const tr = el('tr', { class: r[2] === 'given' ? 'sk-given' : 'sk-chosen' }, body);
        r.forEach((c) => el('td', {}, tr, c));
      });
    });
    return box;
  };

  // ---- panels ----
  // SK.register({id, paper, order, title, cite, source, figures, open(el) -> Promise}):
  // `cite` names the paper's section / equations / figures, `source` the file and function of
  // the library that computes it; `open` builds the panel and resolves once it has drawn
  // (after warming its code up on a small input).
  SK.register = function (panel) { SK.panels.push(panel); };
  // The repository files a panel names: the paths in its `source` text (a bare file name is in
  // the folder of the path before it), its C API file and its page file. ports/web/bundle.py
  // reads the same text by the same rule and copies these files (as HTML) into sources/.
  SK.sourceFiles = function (panel) {
    const key = panel.id.split('-')[0];
    const out = [];
    let dir = '';
    (panel.source.match(/[\w./-]+\.(?:cpp|hpp|h)\b/g) || []).forEach((t) => {
      if (t.includes('/')) dir = t.slice(0, t.lastIndexOf('/') + 1);
      else t = dir + t;
      if (!out.includes(t)) out.push(t);
    });
    ['ports/web/api/api_' + key + '.cpp', 'ports/web/page/panels/' + key + '.js'].forEach((t) => { if (!out.includes(t)) out.push(t); });
    return out;
  };
  let current = null;
  SK.open = function (id) {
    const panel = SK.panels.find((p) => p.id === id);
    if (!panel) { pageError('no panel ' + id); return Promise.resolve(); }
    SK.panels.forEach((p) => { if (p.section) p.section.hidden = p !== panel; });
    document.querySelectorAll('#sk-nav a').forEach((a) => a.classList.toggle('sk-current', a.dataset.panel === id));
    current = panel;
    document.body.dataset.ready = '';
    if (!panel.section) {
      const s = (panel.section = el('section', { class: 'sk-panel', id: 'panel-' + panel.id }, document.getElementById('sk-main')));
      el('h2', {}, s, panel.title);
      const meta = el('p', { class: 'sk-cite' }, s);
      meta.innerHTML = '<b>' + panel.cite + '</b><br>Computed by <code>' + panel.source + '</code>';
      const src = el('p', { class: 'sk-sources' }, s, 'Source (repository path; the classroom bundle carries a copy): ');
      SK.sourceFiles(panel).forEach((f, i) => {
        if (i) src.appendChild(document.createTextNode(' · '));
        el('a', { href: 'sources/' + f + '.html', class: 'sk-source', target: '_blank' }, src, f);
      });
      const bar = (panel.progress = el('progress', { max: 1, value: 0, class: 'sk-progress' }, s));
      bar.hidden = true;
      const body = el('div', { class: 'sk-body' }, s);
      if (panel.figures && panel.figures.length) SK.params(s, panel.figures);
      panel.ready = Promise.resolve().then(() => panel.open(body, panel));
    }
    progressSink = (f) => { panel.progress.hidden = f >= 1; panel.progress.value = f; };
    return panel.ready.then(() => SK.idle()).then(() => {
      if (current === panel) document.body.dataset.ready = panel.id;
    });
  };

  function buildNav() {
    const nav = document.getElementById('sk-nav');
    SK.panels.sort((a, b) => (a.order || 0) - (b.order || 0));
    let paper = null, list = null;
    SK.panels.forEach((p) => {
      if (p.paper !== paper) {
        paper = p.paper;
        el('h3', {}, nav, paper);
        list = el('ul', {}, nav);
      }
      const a = el('a', { href: '#' + p.id, 'data-panel': p.id }, el('li', {}, list), p.title);
      a.addEventListener('click', (e) => { e.preventDefault(); history.replaceState(null, '', '#' + p.id); SK.open(p.id); });
    });
  }

  // ---- self-test (#selftest): the native reference's calls, the same hashes ----
  SK.selftest = async function () {
    const out = document.getElementById('sk-selftest');
    out.hidden = false;
    const spec = window.SK_SELFTEST;
    if (!spec) { out.textContent = 'FAIL: no selftest_expected.js beside the page (make test-web writes it)'; return; }
    const canvas = document.createElement('canvas');
    let pass = 0, fail = 0;
    const lines = [];
    for (const c of spec.cases) {
      const want = Object.keys(c.hashes).filter((k) => k !== 'status');
      const r = await SK.call(c.fn, c.args, want);
      const got = {};
      if (c.hashes.picture !== undefined) { SK.draw(canvas, r.picture); got.picture = r.picture && r.picture.width ? SK.canvasHash(canvas) : 'empty'; }
      if (c.hashes.floats !== undefined) got.floats = SK.fnv64(new Uint8Array(r.floats.data.buffer));
      if (c.hashes.text !== undefined) got.text = SK.fnv64(utf8(r.text));
      if (c.hashes.status !== undefined) got.status = SK.fnv64(utf8(r.message));
      for (const k in c.hashes) {
        const ok = got[k] === c.hashes[k] && r.code === c.code;
        ok ? pass++ : fail++;
        lines.push((ok ? 'ok   ' : 'FAIL ') + c.name + ' ' + k + ' ' + got[k] + (ok ? '' : ' (native ' + c.hashes[k] + ', code ' + r.code + ' vs ' + c.code + ')'));
      }
    }
    out.textContent = (fail ? 'FAIL' : 'PASS') + ' selftest: ' + pass + ' of ' + (pass + fail) + ' hashes equal the native build\'s\n' + lines.join('\n');
    document.body.dataset.selftest = fail ? 'FAIL' : 'PASS';
  };

  // ---- interaction test (#interaction): every panel opens, a slider changes the picture ----
  SK.interaction = async function () {
    const out = document.getElementById('sk-selftest');
    out.hidden = false;
    const lines = [];
    let ok = true;
    for (const p of SK.panels) {
      const t0 = performance.now();
      await SK.open(p.id);
      const canvases = p.section.querySelectorAll('canvas');
      const drawn = Array.from(canvases).filter((c) => SK.canvasHash(c) !== 'empty').length;
      lines.push('panel ' + p.id + ': ready in ' + (performance.now() - t0).toFixed(0) + ' ms, ' + canvases.length + ' canvases');
      if (!canvases.length || !drawn) { ok = false; lines.push('FAIL panel ' + p.id + ' drew nothing'); }
      // An animated panel's event count (its event slider's end): test_web.sh compares it with
      // the native run's at the same (default) settings.
      if (p.eventCount) lines.push('events ' + p.id + ' ' + p.eventCount());
    }
    for (const p of SK.panels.filter((q) => q.interaction)) {
      await SK.open(p.id);
      const t = p.interaction;  // {control: data-key of a range input, value, canvas: selector}
      const canvas = p.section.querySelector(t.canvas);
      const before = SK.canvasHash(canvas);
      const range = p.section.querySelector('input[data-key="' + t.control + '"]');
      range.value = t.value;
      range.dispatchEvent(new Event('input'));
      await SK.idle();
      const after = SK.canvasHash(canvas);
      const changed = before !== after && after !== 'empty';
      if (!changed) ok = false;
      lines.push((changed ? 'ok   ' : 'FAIL ') + p.id + ': slider ' + t.control + ' -> ' + t.value + ' changed the picture ' + before + ' -> ' + after);
    }
    const errors = Number(document.body.dataset.errors || 0);
    if (errors) { ok = false; lines.push('FAIL ' + errors + ' errors logged on the page'); }
    out.textContent = (ok ? 'PASS' : 'FAIL') + ' interaction\n' + lines.join('\n');
    document.body.dataset.interaction = ok ? 'PASS' : 'FAIL';
  };

  // ---- bench (#bench): first panel ready, slider -> new 512x512 marble frame ----
  SK.bench = async function () {
    const out = document.getElementById('sk-selftest');
    out.hidden = false;
    const b = SK.panels.find((p) => p.bench);
    await SK.open(b.id);
    const first = performance.now();  // since navigation start (the page opened from disk)
    const t = b.bench;
    const range = b.section.querySelector('input[data-key="' + t.control + '"]');
    const times = [], compute = [];
    for (let i = 0; i < t.values.length; i++) {
      const t0 = performance.now();
      range.value = t.values[i];
      range.dispatchEvent(new Event('input'));
      await SK.idle();
      times.push(performance.now() - t0);
      compute.push(SK.lastMs[t.fn]);
    }
    const sorted = times.slice().sort((x, y) => x - y);
    const inWorker = compute.slice().sort((x, y) => x - y);
    const lines = [
      'bench: first panel (' + b.id + ') ready ' + first.toFixed(0) + ' ms after navigation start (goal <= 1500 ms)',
      'bench: slider -> new ' + t.what + ' frame drawn: median ' + sorted[sorted.length >> 1].toFixed(1) + ' ms, best ' +
        sorted[0].toFixed(1) + ' ms over ' + times.length + ' moves (goal <= 33 ms)',
      'bench: of which ' + t.fn + ' in the worker (WASM): median ' + inWorker[inWorker.length >> 1].toFixed(1) + ' ms, best ' + inWorker[0].toFixed(1) + ' ms',
    ];
    // The panels' own benches (panel.benches, set by a panel's open()): {label, goal, prepare,
    // control, values, fns} moves a slider and times each move to the next drawn frame and the
    // named calls in the worker; {run} measures itself and returns its lines.
    for (const p of SK.panels) {
      await SK.open(p.id);
      for (const bb of p.benches || []) {
        if (bb.run) { lines.push(...(await bb.run())); continue; }
        if (bb.prepare) await bb.prepare();
        await SK.idle();
        const range = p.section.querySelector('input[data-key="' + bb.control + '"]');
        const wall = [], work = [];
        for (const v of bb.values) {
          const t0 = performance.now();
          range.value = v;
          range.dispatchEvent(new Event('input'));
          await SK.idle();
          wall.push(performance.now() - t0);
          work.push(bb.fns.reduce((sum, fn) => sum + (SK.lastMs[fn] || 0), 0));
        }
        const med = (a) => a.slice().sort((x, y) => x - y)[a.length >> 1], best = (a) => Math.min(...a);
        lines.push('bench: ' + bb.label + ': ' + bb.fns.join(' + ') + ' in the worker (WASM) median ' + med(work).toFixed(1) + ' ms, best ' +
          best(work).toFixed(1) + ' ms; to the next drawn frame median ' + med(wall).toFixed(1) + ' ms, best ' + best(wall).toFixed(1) +
          ' ms over ' + wall.length + ' moves (goal <= ' + bb.goal + ' ms)');
      }
      if (p.stop) p.stop();
    }
    out.textContent = lines.join('\n');
    document.body.dataset.bench = 'done';
  };

  // ---- start ----
  window.addEventListener('DOMContentLoaded', () => {
    startWorker();
    buildNav();
    const ver = document.getElementById('sk-version');
    SK.workerReady.then(() => { ver.textContent = 'shitsukan ' + SK.version + ' (WASM)'; });
    const hash = location.hash.slice(1);
    if (hash === 'selftest') {  // the expected hashes: a file make test-web writes beside the page
      const s = document.createElement('script');
      s.src = 'selftest_expected.js';
      s.onload = s.onerror = () => SK.selftest();
      document.head.appendChild(s);
    } else if (hash === 'interaction') {
      SK.interaction();
    } else if (hash === 'bench') {
      SK.bench();
    } else {
      const id = SK.panels.some((p) => p.id === hash) ? hash : SK.panels[0].id;
      SK.open(id);
    }
  });
})();
