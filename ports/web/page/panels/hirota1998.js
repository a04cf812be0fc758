// ports/web/page/panels/hirota1998.js — hirota1998 (growing tree bark), §3: the two-layer
// model animated in time. The worker grows and cracks the trunk once (the library's
// event-driven run); the page then replays exactly that run's breaks, one event at a time, in
// order: play / pause, step one event, scrub. Wiring and drawing only (api_hirota1998.cpp).
/* global SK */
'use strict';
(function () {
  const P = 'hirota1998 — Hirota, Tanoue, Kaneko';
  const SPECIES = [[0, 'camphor (Table 2, col. 1)'], [1, 'Chinese tallow (col. 2)'], [2, 'pine (col. 3)']];
  const GRIDS = [[0, '32 x 24 nodes (the figures\' quick size)'], [1, '64 x 48 nodes'], [2, '128 x 64 nodes (the paper\'s size)']];
  const GRID = [[32, 24, 40], [64, 48, 20], [128, 64, 12]];  // N_R, N_H, px per cm
  // hirota1998 Table 3 (given): region width x height in cm, observed and the paper's simulated
  // mean and max; -1 = "(>20)".
  const TABLE3 = [
    { observed: [1.5, -1], mean: [1.58, 11.6], max: [2.06, -1] },
    { observed: [1.5, 3.0], mean: [1.70, 3.02], max: [2.08, 3.96] },
    { observed: [3.0, 7.0], mean: [2.34, 4.28], max: [3.24, 6.48] },
  ];
  const cm = (p) => p.map((x) => (x < 0 ? '(>20)' : x.toFixed(2))).join(' x ');

  SK.register({
    id: 'hirota1998-growth', paper: P, order: 120,
    title: 'The two-layer model: the trunk grows, springs break one event at a time',
    cite: 'hirota1998 §3.1 the two-layer model (Fig. 3): the inner layer grows (delta_r, delta_h), a spring of the surface layer breaks when its elongation passes kappa (spread sigma), a broken spring stays broken; Fig. 4 a crack drawn at the middle of the broken spring, width l - l0; Table 2 the species',
    source: 'lib/shitsukan/bark/crack_events.cpp grow_and_crack() / run_cracking(), cylinder_lattice.cpp build_cylinder(), bark_params.cpp species_preset(); lib/shitsukan/render/bark_crack_map.cpp draw_crack_map()',
    figures: ['hirota1998/fig04', 'hirota1998/fig05'],
    interaction: { control: 'bark-event', value: 200, canvas: 'canvas.sk-bark' },
    async open(body, panel) {
      const box = SK.el('div', { class: 'sk-controls' }, body);
      const figs = SK.el('div', { class: 'sk-figs' }, body);
      const c = {
        species: SK.select(box, { label: 'species', value: 0, options: SPECIES }),
        grid: SK.select(box, { label: 'lattice', value: 0, options: GRIDS }),
        sigma: SK.slider(box, { label: 'sigma', min: 0, max: 0.1, step: 0.0005, value: 0.0175, key: 'bark-sigma' }),
        kappa1: SK.slider(box, { label: 'kappa1 (axial)', min: 1.001, max: 1.1, step: 0.001, value: 1.04, key: 'bark-kappa1' }),
        kappa2: SK.slider(box, { label: 'kappa2 (around)', min: 1.001, max: 1.1, step: 0.001, value: 1.015, key: 'bark-kappa2' }),
      };
      const runInfo = SK.el('div', { class: 'sk-readout' }, box);
      SK.el('h4', {}, box, 'Replay of the run\'s breaks');
      const ev = SK.slider(box, { label: 'event', min: 0, max: 1, step: 1, value: 0, key: 'bark-event' });
      const speed = SK.slider(box, { label: 'events / frame', min: 1, max: 50, step: 1, value: 2, key: 'bark-speed' });
      const bar = SK.el('div', { class: 'sk-control' }, box);
      const play = SK.el('button', { type: 'button' }, bar, 'play');
      const step = SK.el('button', { type: 'button' }, bar, 'step one event');
      const back = SK.el('button', { type: 'button' }, bar, 'back one');
      const frameInfo = SK.el('div', { class: 'sk-readout' }, box);
      const table3 = SK.el('table', { class: 'sk-table' }, box);
      const f = SK.figure(figs, 'the unrolled bark', 480, 300);
      f.canvas.classList.add('sk-bark');
      const timeline = SK.figure(figs, 'breaks over time: cumulative count (blue) against t / T; the red line is the event shown', 480, 120);
      let run = null, playing = false, timer = 0;

      const drawTimeline = (event) => {
        const g = timeline.canvas.getContext('2d'), w = 480, h = 120;
        g.fillStyle = '#fff'; g.fillRect(0, 0, w, h);
        g.strokeStyle = '#ccc'; g.strokeRect(0.5, 0.5, w - 1, h - 1);
        if (!run || !run.times.length) return;
        const n = run.times.length;
        g.strokeStyle = '#1f5f99'; g.beginPath();
        for (let i = 0; i < n; i++) {
          const x = 4 + (run.times[i] / run.T) * (w - 8), y = h - 4 - ((i + 1) / n) * (h - 8);
          i ? g.lineTo(x, y) : g.moveTo(x, y);
        }
        g.stroke();
        const t = event ? run.times[event - 1] : 0;
        g.strokeStyle = '#cc0000'; g.beginPath();
        g.moveTo(4 + (t / run.T) * (w - 8), 2); g.lineTo(4 + (t / run.T) * (w - 8), h - 2); g.stroke();
      };
      const showFrame = SK.coalesce(async () => {
        if (!run) return;
        const e = Math.max(0, Math.min(run.events, Math.round(ev.value)));
        const r = await SK.call('sk_hirota1998_frame', [e, GRID[c.grid.value][2]], ['picture', 'text']);
        if (!SK.report(ev, r)) return;
        SK.draw(f.canvas, r.picture);
        const t = JSON.parse(r.text);
        frameInfo.textContent = 'event ' + e + ' of ' + run.events + ' at t = ' + t.t.toFixed(3) + ' s (' + (100 * t.t / run.T).toFixed(1) + '% of T)\n' +
          t.drawn + ' springs broken by then (a cascade breaks several at one t)\n' +
          'trunk unrolled: ' + t.C.toFixed(2) + ' x ' + t.H.toFixed(2) + ' cm' + (t.exact ? '' : '\n(widths from the latest kept field before t)');
        f.cap.textContent = 'The unrolled surface layer at t: plates (lattice triangles) and each broken spring as Fig. 4\'s crack, width l - l0; red square: the spring of this event. The canvas is the trunk at T: watch it fill as the trunk grows.';
        drawTimeline(e);
      });
      const rerun = SK.coalesce(async () => {
        stop();
        const g = GRID[c.grid.value];
        const r = await SK.call('sk_hirota1998_run', [c.species.value, c.sigma.value, c.kappa1.value, c.kappa2.value, g[0], g[1]], ['floats', 'text']);
        const bad = /sigma/.test(r.message) ? c.sigma : /kappa1|kappa_1/.test(r.message) ? c.kappa1 : /kappa/.test(r.message) ? c.kappa2 : /N_R|N_H|node/.test(r.message) ? c.grid : c.species;
        [c.sigma, c.kappa1, c.kappa2, c.grid, c.species].forEach((x) => SK.clearReport(x));
        if (!SK.report(bad, r)) { run = null; return; }
        const t = JSON.parse(r.text);
        run = { events: t.events, T: t.T, times: r.floats.data };
        runInfo.textContent = 'native-identical run: ' + t.events + ' breaks (' + t.cascade + ' in cascades), event-sequence hash ' + t.hash +
          '\n' + t.frames + ' frames kept; trunk at T: ' + t.C_T.toFixed(2) + ' x ' + t.H_T.toFixed(2) + ' cm\ngrown in ' + r.ms.toFixed(0) + ' ms (WASM, in the worker)';
        const p3 = TABLE3[c.species.value];
        table3.innerHTML = '<caption>Table 3 at T: regions bounded by cracks (cm, width x height)</caption>' +
          '<tr><th></th><th>mean</th><th>max</th></tr>' +
          '<tr><th>paper, observed</th><td colspan="2">' + cm(p3.observed) + '</td></tr>' +
          '<tr><th>paper, simulated</th><td>' + cm(p3.mean) + '</td><td>' + cm(p3.max) + '</td></tr>' +
          '<tr><th>this run (' + t.regions + ' regions, ' + t.full_height + ' full height)</th><td>' + cm([t.mean_w, t.mean_h]) + '</td><td>' + cm([t.max_w, t.max_h]) + '</td></tr>' +
          (c.grid.value === 2 ? '' : '<tr><td colspan="3">the trunk is ' + t.H_T.toFixed(1) + ' cm high at this lattice: choose 128 x 64 (the paper\'s size) to compare</td></tr>');
        ev.range.max = t.events;
        ev.box.max = t.events;
        ev.set(Math.min(Number(ev.value), t.events));
        await showFrame();
      });
      const speciesDefaults = async () => {
        const r = await SK.call('sk_hirota1998_species', [c.species.value], ['text']);
        if (!SK.report(c.species, r)) return;
        const t = JSON.parse(r.text);
        c.sigma.set(t.sigma); c.kappa1.set(t.kappa1.toFixed(3)); c.kappa2.set(t.kappa2.toFixed(3));
        await rerun();
      };
      function stop() { playing = false; play.textContent = 'play'; if (timer) cancelAnimationFrame(timer); timer = 0; }
      const tick = async () => {
        if (!playing || !run) return;
        const next = Math.min(run.events, Number(ev.value) + speed.value);
        ev.set(next);
        await showFrame();
        if (next >= run.events) { stop(); return; }
        if (playing) timer = requestAnimationFrame(tick);
      };
      play.addEventListener('click', () => {
        if (playing) { stop(); return; }
        if (run && Number(ev.value) >= run.events) ev.set(0);
        playing = true; play.textContent = 'pause';
        timer = requestAnimationFrame(tick);
      });
      step.addEventListener('click', () => { stop(); if (run) { ev.set(Math.min(run.events, Number(ev.value) + 1)); showFrame(); } });
      back.addEventListener('click', () => { stop(); if (run) { ev.set(Math.max(0, Number(ev.value) - 1)); showFrame(); } });
      // make bench-web: the camphor run at the paper's 128 x 64 nodes, then its replay at the
      // panel's pace (2 events a frame): frames per second drawn, and whether the run (computed
      // once, before the replay starts) keeps up with the replay.
      panel.benches = [{
        run: async () => {
          c.species.sel.value = 0; c.grid.sel.value = 2;
          await speciesDefaults();
          await SK.idle();
          const runMs = SK.lastMs.sk_hirota1998_run, per = Number(speed.value);
          const frame = [];
          ev.set(0);
          for (let i = 0; i < 60; i++) {
            const t0 = performance.now();
            ev.set(Math.min(run.events, (i + 1) * per));
            await showFrame();
            await new Promise((r) => requestAnimationFrame(r));
            frame.push(performance.now() - t0);
          }
          const sorted = frame.slice().sort((x, y) => x - y), med = sorted[sorted.length >> 1];
          const fps = 1000 / med, playS = run.events / per / Math.min(fps, 60);
          return ['bench: camphor at 128 x 64 nodes: ' + run.events + ' events, grown and cracked in ' + runMs.toFixed(0) + ' ms (WASM, in the worker, once)',
            'bench: camphor replay, ' + per + ' events a frame: median ' + med.toFixed(1) + ' ms a frame (best ' + sorted[0].toFixed(1) + ') = ' + fps.toFixed(1) +
              ' frames per second (goal >= 30); the replay of all events lasts ' + playS.toFixed(1) + ' s against the run\'s ' + (runMs / 1000).toFixed(1) + ' s: ' +
              (runMs / 1000 < playS ? 'the simulation keeps up' : 'the simulation does NOT keep up')];
        },
      }];
      c.species.onchange = speciesDefaults;
      [c.grid, c.sigma, c.kappa1, c.kappa2].forEach((x) => { x.onchange = rerun; });
      ev.onchange = () => { stop(); showFrame(); };
      panel.stop = stop;
      panel.eventCount = () => Number(ev.range.max);
      await speciesDefaults();
    },
  });

  SK.register({
    id: 'hirota1998-branch', paper: P, order: 140,
    title: 'The branch of fig. 11 in 3D: cracks on a branching trunk',
    cite: 'hirota1998 §5.1-5.2: an irregular mesh of a branching trunk, spring and shear-spring constants from the connection areas of Fig. 9, growth = isotropic enlargement (r_h) + offset along the normal (r_n); §5.3, Fig. 11: the cracks run around the trunk, denser on the thinner branch, and connect across the crotch',
    source: 'lib/shitsukan/bark/branch_bark.cpp build_branch_bark() / grow_branch_bark(), branch_shape.cpp, connection_area.cpp; paper_figures/hirota1998/branch_scene.cpp branch_scene() / draw_branch_view() (fig. 11\'s scene); lib/shitsukan/raster/rasterizer.cpp draw_mesh(); ports/web/api/api_hirota1998_branch.cpp',
    figures: ['hirota1998/fig11'],
    interaction: { control: 'branch-yaw', value: 1.2, canvas: 'canvas.sk-branch' },
    async open(body, panel) {
      const box = SK.el('div', { class: 'sk-controls' }, body);
      const figs = SK.el('div', { class: 'sk-figs' }, body);
      const c = {
        L0: SK.select(box, { label: 'mesh L0', value: 0.6, options: [[0.6, '0.6 cm (the figures\' quick size)'], [0.45, '0.45 cm'], [0.33, '0.33 cm (Table 2\'s L0)']] }),
        r_h: SK.slider(box, { label: 'r_h (length)', min: 0, max: 0.04, step: 0.001, value: 0.01, key: 'branch-rh' }),
        r_n: SK.slider(box, { label: 'r_n (normal, cm)', min: -0.05, max: 0.15, step: 0.005, value: 0.05, key: 'branch-rn' }),
        kappa: SK.slider(box, { label: 'kappa', min: 1.001, max: 1.05, step: 0.001, value: 1.015, key: 'branch-kappa' }),
        sigma: SK.slider(box, { label: 'sigma', min: 0, max: 0.1, step: 0.0005, value: 0.0175, key: 'branch-sigma' }),
      };
      const runInfo = SK.el('div', { class: 'sk-readout' }, box);
      const v = {
        frame: SK.slider(box, { label: 'time t (T/20)', min: 0, max: 20, step: 1, value: 20, key: 'branch-frame' }),
        view: SK.select(box, { label: 'camera', value: 0, options: [[0, 'front (fig. 11 left)'], [1, 'above the crotch (fig. 11 right)']] }),
        yaw: SK.slider(box, { label: 'turn (yaw)', min: -3.14, max: 3.14, step: 0.01, value: 0, key: 'branch-yaw' }),
        pitch: SK.slider(box, { label: 'tilt (pitch)', min: -1.2, max: 1.2, step: 0.01, value: 0, key: 'branch-pitch' }),
      };
      const bar = SK.el('div', { class: 'sk-control' }, box);
      const play = SK.el('button', { type: 'button' }, bar, 'play the growth');
      const frameInfo = SK.el('div', { class: 'sk-readout' }, box);
      const f = SK.figure(figs, 'the grown branch at t with its cracks (dark ribbons, Fig. 4\'s width l - l0), drawn by the library\'s rasterizer; drag to turn', 512, 512);
      f.canvas.classList.add('sk-branch');
      let run = null, timer = 0;
      const draw = SK.coalesce(async () => {
        if (!run) return;
        const r = await SK.call('sk_hirota1998_branch_view', [v.frame.value, v.view.value, v.yaw.value, v.pitch.value, 512], ['picture', 'text']);
        if (!SK.report(v.frame, r)) return;
        SK.draw(f.canvas, r.picture);
        const t = JSON.parse(r.text);
        frameInfo.textContent = 't = ' + t.t.toFixed(0) + ' of T = ' + run.T + ': ' + t.broken + ' springs broken, ' + t.ribbons + ' crack ribbons drawn';
      });
      const rerun = SK.coalesce(async () => {
        stop();
        const r = await SK.call('sk_hirota1998_branch_run', [c.L0.value, c.r_h.value, c.r_n.value, c.kappa.value, c.sigma.value], ['text']);
        const bad = /r_h/.test(r.message) ? c.r_h : /r_n/.test(r.message) ? c.r_n : /kappa/.test(r.message) ? c.kappa : /sigma/.test(r.message) ? c.sigma : c.L0;
        Object.values(c).forEach((x) => SK.clearReport(x));
        if (!SK.report(bad, r)) { run = null; return; }
        run = JSON.parse(r.text);
        runInfo.textContent = 'native-identical run: ' + run.nodes + ' nodes, ' + run.springs + ' springs, ' + run.events +
          ' breaks, event-sequence hash ' + run.hash + '\nmeshed, grown and cracked in ' + r.ms.toFixed(0) + ' ms (WASM, in the worker)';
        await draw();
      });
      function stop() { if (timer) clearTimeout(timer); timer = 0; play.textContent = 'play the growth'; }
      const tick = async () => {
        if (!timer) return;
        const next = Number(v.frame.value) + 1;
        v.frame.set(next);
        await draw();
        if (next >= 20) { stop(); return; }
        if (timer) timer = setTimeout(tick, 120);
      };
      play.addEventListener('click', () => {
        if (timer) { stop(); return; }
        if (Number(v.frame.value) >= 20) v.frame.set(0);
        play.textContent = 'pause';
        timer = setTimeout(tick, 0);
      });
      Object.values(c).forEach((x) => { x.onchange = rerun; });
      v.frame.onchange = () => { stop(); draw(); };
      [v.view, v.yaw, v.pitch].forEach((x) => { x.onchange = draw; });
      SK.turnable(f.canvas, v.yaw, v.pitch, draw);
      panel.stop = stop;
      panel.eventCount = () => (run ? run.events : -1);
      await rerun();
    },
  });

  SK.register({
    id: 'hirota1998-layers', paper: P, order: 130,
    title: 'The four-layer model: roles change cycle by cycle, plates peel',
    cite: 'hirota1998 §4.1-4.2, figs. 6-8: surface, middle (1), middle (2), inner; middle (2) grows to middle (1)\'s thickness in one cycle T, then the roles shift outward (Fig. 7); the surface cracks, dries near its cracks and peels when the interlayer shear strain passes kappa_h (Table 4); a plate falls when its lifted area is large enough',
    source: 'lib/shitsukan/bark/layered_bark.cpp LayeredBark::build() / run(), layer_schedule.cpp; paper_figures/hirota1998/layer_frame_draw.cpp draw_layer_frame() (fig. 8\'s frames); ports/web/api/api_hirota1998_layers.cpp',
    figures: ['hirota1998/fig08'],
    interaction: { control: 'layers-event', value: 300, canvas: 'canvas.sk-layers' },
    async open(body, panel) {
      const box = SK.el('div', { class: 'sk-controls' }, body);
      const figs = SK.el('div', { class: 'sk-figs' }, body);
      const SIZES = [[24, 16, 4, 40], [64, 48, 5, 16]];  // N_R, N_H, cycles, px per cm
      const c = {
        size: SK.select(box, { label: 'patch', value: 0, options: [[0, '24 x 16 nodes, 4 cycles (the figures\' quick run)'], [1, '64 x 48 nodes, 5 cycles (fig. 8\'s run)']] }),
        kappa_h: SK.slider(box, { label: 'kappa_h (Table 4)', min: 0.01, max: 0.2, step: 0.005, value: 0.08, key: 'layers-kappa-h' }),
      };
      const runInfo = SK.el('div', { class: 'sk-readout' }, box);
      SK.el('h4', {}, box, 'The run: by time (T / 50 a step) or event by event');
      const fr = SK.slider(box, { label: 'time (step)', min: 0, max: 1, step: 1, value: 0, key: 'layers-frame' });
      const evs = SK.slider(box, { label: 'event', min: 0, max: 1, step: 1, value: 0, key: 'layers-event' });
      const speed = SK.slider(box, { label: 'events / frame', min: 1, max: 40, step: 1, value: 3, key: 'layers-speed' });
      const bar = SK.el('div', { class: 'sk-control' }, box);
      const play = SK.el('button', { type: 'button' }, bar, 'play');
      const step = SK.el('button', { type: 'button' }, bar, 'step one event');
      const back = SK.el('button', { type: 'button' }, bar, 'back one');
      const frameInfo = SK.el('div', { class: 'sk-readout' }, box);
      const f = SK.figure(figs, 'the unrolled bark patch: surface bonded (dark brown), lifted (pale), middle (1) exposed where the surface fell off (orange); black: cracks of each layer', 480, 300);
      f.canvas.classList.add('sk-layers');
      const timeline = SK.figure(figs, 'over the run: surface still on the trunk (brown), of it still bonded (blue); grey lines: role changes; red: the step shown', 480, 110);
      let run = null, timer = 0;
      const row = (i) => Array.from(run.rec.slice(8 * i, 8 * i + 8));
      const drawTimeline = (i) => {
        const g = timeline.canvas.getContext('2d'), w = 480, h = 110;
        g.fillStyle = '#fff'; g.fillRect(0, 0, w, h);
        g.strokeStyle = '#ccc'; g.strokeRect(0.5, 0.5, w - 1, h - 1);
        if (!run) return;
        const tEnd = run.T * run.cycles, x = (t) => 4 + (t / tEnd) * (w - 8), y = (v) => h - 4 - v * (h - 8);
        [[1, '#8b5a2b'], [2, '#1f5f99']].forEach(([col, color]) => {
          g.strokeStyle = color; g.beginPath();
          for (let k = 0; k < run.frames; k++) { const r = row(k); k ? g.lineTo(x(r[0]), y(r[col])) : g.moveTo(x(r[0]), y(r[col])); }
          g.stroke();
        });
        g.strokeStyle = '#999';
        for (let k = 0; k < run.frames; k++) if (row(k)[7]) { g.beginPath(); g.moveTo(x(row(k)[0]), 2); g.lineTo(x(row(k)[0]), h - 2); g.stroke(); }
        g.strokeStyle = '#cc0000'; g.beginPath(); g.moveTo(x(row(i)[0]), 2); g.lineTo(x(row(i)[0]), h - 2); g.stroke();
      };
      const KIND = ['a spring of the surface broke', 'a spring of middle (1) broke', 'surface nodes debonded (peeling starts)'];
      const eventsUpTo = (i) => { let k = 0; while (k < run.events && run.ev[4 * k + 3] <= i) k++; return k; };
      const roles = (t) => 'surface = layer born in cycle ' + t.generation_surface + ', middle (1) = layer born in cycle ' + t.generation_middle1;
      const recordText = (i) => {
        const q = row(i);
        return 'surface on the trunk ' + (100 * q[1]).toFixed(1) + ' %, of it bonded ' + (100 * q[2]).toFixed(1) + ' %\n' +
          'broken springs: surface ' + q[3] + ', middle (1) ' + q[4] + '\nthis step: ' + q[5] + ' plates fell, ' + q[6] + ' shear springs debonded';
      };
      const cycleOf = (t) => Math.min(run.cycles, Math.floor(t / run.T - 1e-6) + 1);
      let mode = 'step';
      const show = SK.coalesce(async () => {
        if (!run) return;
        if (mode === 'event') {
          const e = Math.max(0, Math.min(run.events, Math.round(evs.value)));
          const r = await SK.call('sk_hirota1998_layers_event', [e, SIZES[c.size.value][3]], ['picture', 'text']);
          if (!SK.report(evs, r)) return;
          SK.draw(f.canvas, r.picture);
          const t = JSON.parse(r.text);
          fr.set(Math.max(0, t.frame - (e ? 0 : 1)));
          frameInfo.textContent = 'event ' + e + ' of ' + run.events + (e ? ' at t = ' + t.t.toFixed(1) + ' (cycle ' + cycleOf(t.t) + '): ' + KIND[t.kind] + (t.kind < 2 ? ' (red square)' : '') : ': the patch before any growth') + '\n' +
            roles(t) + '\ncracks and debonds of this step so far on the step\'s start; plates fall and roles change at the step\'s end\n' +
            (e ? 'at the end of this step: ' + recordText(t.frame) : '');
          drawTimeline(Math.max(0, t.frame));
          return;
        }
        const i = Math.max(0, Math.min(run.frames - 1, Math.round(fr.value)));
        const r = await SK.call('sk_hirota1998_layers_frame', [i, SIZES[c.size.value][3]], ['picture', 'text']);
        if (!SK.report(fr, r)) return;
        SK.draw(f.canvas, r.picture);
        const t = JSON.parse(r.text), q = row(i);
        evs.set(eventsUpTo(i));
        frameInfo.textContent = 'step ' + (i + 1) + ' of ' + run.frames + ': t = ' + q[0].toFixed(1) + ' (cycle ' + cycleOf(q[0]) + ' of ' + run.cycles + ')' +
          (t.before_role_change ? ', just before the role change' : q[7] ? ', the roles have just shifted outward' : '') + ', after ' + evs.value + ' events\n' +
          roles(t) + '\n' + recordText(i);
        drawTimeline(i);
      });
      const rerun = SK.coalesce(async () => {
        stop();
        const z = SIZES[c.size.value];
        const r = await SK.call('sk_hirota1998_layers_run', [z[0], z[1], z[2], c.kappa_h.value], ['floats', 'text']);
        Object.values(c).forEach((x) => SK.clearReport(x));
        if (!SK.report(/kappa_h/.test(r.message) ? c.kappa_h : c.size, r)) { run = null; return; }
        run = Object.assign(JSON.parse(r.text), { rec: r.floats.data });
        runInfo.textContent = 'native-identical run: ' + run.frames + ' steps kept (' + run.cycles + ' cycles of ' + run.steps + ', ' + run.role_changes +
          ' role changes), ' + run.peeled + ' plates fell\nrun in ' + r.ms.toFixed(0) + ' ms (WASM, in the worker)';
        const ev = await SK.call('sk_hirota1998_layers_events', [], ['floats']);
        if (!SK.report(c.size, ev)) { run = null; return; }
        run.ev = ev.floats.data;
        runInfo.textContent += '\n' + run.events + ' events of the break loop (as the native run: count and order), seen by the library\'s observer';
        fr.range.max = run.frames - 1; fr.box.max = run.frames - 1;
        evs.range.max = run.events; evs.box.max = run.events;
        fr.set(Math.min(Number(fr.value), run.frames - 1));
        mode = 'step';
        await show();
      });
      function stop() { if (timer) clearTimeout(timer); timer = 0; play.textContent = 'play'; }
      const tick = async () => {
        if (!timer || !run) return;
        const next = Math.min(run.events, Number(evs.value) + Number(speed.value));
        evs.set(next);
        mode = 'event';
        await show();
        if (next >= run.events) { stop(); return; }
        if (timer) timer = setTimeout(tick, 30);
      };
      play.addEventListener('click', () => {
        if (timer) { stop(); return; }
        if (run && Number(evs.value) >= run.events) evs.set(0);
        play.textContent = 'pause';
        timer = setTimeout(tick, 0);
      });
      const move = (d) => { stop(); if (run) { evs.set(Math.max(0, Math.min(run.events, Number(evs.value) + d))); mode = 'event'; show(); } };
      step.addEventListener('click', () => move(1));
      back.addEventListener('click', () => move(-1));
      Object.values(c).forEach((x) => { x.onchange = rerun; });
      fr.onchange = () => { stop(); mode = 'step'; show(); };
      evs.onchange = () => { stop(); mode = 'event'; show(); };
      panel.stop = stop;
      panel.eventCount = () => Number(evs.range.max);
      fr.set(124);
      await rerun();
    },
  });
})();
