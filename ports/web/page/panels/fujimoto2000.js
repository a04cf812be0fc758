// ports/web/page/panels/fujimoto2000.js — fujimoto2000 (wrinkly fractal surfaces), §2: the
// Iterated Shuffle Transformation live. The digit diagrams of figs. 3-9 for any N, K, B, kind
// and ends; a point u followed forward and back by the procedure (div, in-shf, ex-shf) beside
// the scale reverse formula (eqs. 7, 12); the IST's table; Table 1's ratio measured live.
// Wiring and drawing only (api_fujimoto2000.cpp).
/* global SK */
'use strict';
(function () {
  const P = 'fujimoto2000 — Fujimoto, Ohno et al.';
  const KINDS = [
    [0, 'unit-IST (§2.2.1, figs. 3, 4)'],
    [1, 'fully-connected (fig. 6a, fig. 8; eq. 12)'],
    [2, 'connected, fig. 6b shuffle'],
    [3, 'connected, fig. 7a (nearest neighbours)'],
    [4, 'connected, fig. 7b (no external shuffle)'],
    [5, 'connected, fig. 7c (crossed pairs)'],
  ];
  // Presets: the figures' own settings (paper_figures/fujimoto2000/fig0*_*.cpp).
  const PRESETS = [
    ['', 'choose a figure…'],
    ['fig. 3', { kind: 0, N: 5, K: 3, B: 1, ends: 0, half: 0, win: 0, u: 0.1 }],
    ['fig. 4(c)', { kind: 0, N: 3, K: 2, B: 1, ends: 0, half: 0, win: 0, u: 0.4 }],
    ['fig. 6(a)', { kind: 1, N: 5, K: 3, B: 13, ends: 0, half: 1, win: 5, u: 0.48 }],
    ['fig. 6(b)', { kind: 2, N: 5, K: 3, B: 13, ends: 0, half: 0, win: 5, u: 0.48 }],
    ['fig. 7(a)', { kind: 3, N: 5, K: 1, B: 13, ends: 0, half: 1, win: 5, u: 0.5 }],
    ['fig. 8(c)', { kind: 1, N: 7, K: 1, B: 13, ends: 0, half: 1, win: 5, u: 0.5 }],
    ['fig. 9', { kind: 1, N: 3, K: 3, B: 5, ends: 1, half: 1, win: 0, u: 0.05 }],
  ];

  SK.register({
    id: 'fujimoto2000-ist', paper: P, order: 100,
    title: 'The IST live: digit diagrams, a point followed, the formula beside the procedure',
    cite: 'fujimoto2000 §2.2.1 unit-IST (figs. 3, 4; eq. 7), §2.2.2 connected and fully-connected IST (figs. 6-8; eq. 12), translation-axis ends (fig. 9), §2.3 the scale reverse formulas on u (eqs. 9, 10, 14), Table 1 (procedure vs. formula)',
    source: 'lib/shitsukan/wrinkly/ist_axis.cpp ist_*_axis(), ist_procedure.cpp ist_divide_and_shuffle_internally() / ist_shuffle_externally(), ist_digits.cpp ist_scale_reverse_unit() / ist_scale_reverse_fully_connected(), ist_formula.cpp ist_forward(), ist_table.cpp ist_table(); diagrams by paper_figures/fujimoto2000/ist_diagram.cpp draw_ist_diagram()',
    figures: ['fujimoto2000/fig03', 'fujimoto2000/fig06a', 'fujimoto2000/fig09', 'fujimoto2000/table01'],
    interaction: { control: 'ist-u', value: 0.81, canvas: 'canvas.sk-ist' },
    async open(body, panel) {
      const box = SK.el('div', { class: 'sk-controls' }, body);
      const figs = SK.el('div', { class: 'sk-figs' }, body);
      const preset = SK.select(box, { label: 'figure', value: '', options: PRESETS.map(([n]) => [n, n || PRESETS[0][1]]) });
      const c = {
        kind: SK.select(box, { label: 'IST', value: 0, options: KINDS }),
        ends: SK.select(box, { label: 'ends', value: 0, options: [[0, 'cyclic axis'], [1, 'translation axis (fig. 9)']] }),
        N: SK.slider(box, { label: 'N (division)', min: 1, max: 9, step: 1, value: 5, key: 'ist-N' }),
        K: SK.slider(box, { label: 'K (iterations)', min: 0, max: 6, step: 1, value: 3, key: 'ist-K' }),
        B: SK.slider(box, { label: 'B (base intervals)', min: 1, max: 15, step: 1, value: 1, key: 'ist-B' }),
      };
      const v = {
        u: SK.slider(box, { label: 'u (followed)', min: 0, max: 1, step: 0.001, value: 0.1, key: 'ist-u' }),
        half: SK.select(box, { label: 'axes', value: 0, options: [[0, 'u*, u^0 .. u^K'], [1, 'with u^{k.5} (after div + in-shf)']] }),
        win: SK.slider(box, { label: 'window (bases)', min: 0, max: 15, step: 1, value: 0, key: 'ist-win' }),
      };
      const note = SK.el('p', { class: 'sk-note' }, box);
      note.textContent = 'The library judges every value: an even N for a connected IST, N^K too large, a shuffle that is not an exchange on a translation axis — its message appears beside the control. The thin dark line with arrowheads follows the sub-interval holding u from axis to axis.';
      const readout = SK.el('div', { class: 'sk-readout' }, box);
      SK.el('h4', {}, box, 'Table 1, measured live on this IST');
      const tbtn = SK.el('button', { type: 'button' }, box, 'time 100 000 coordinates');
      const ratio = SK.el('div', { class: 'sk-readout' }, box);
      const f = SK.figure(figs, 'the digit diagram', 1000, 400);
      f.canvas.classList.add('sk-ist');
      const steps = SK.el('table', { class: 'sk-table' }, figs);
      const table = SK.el('details', { class: 'sk-params' }, figs);
      SK.el('summary', {}, table, 'the IST\'s table: alpha^0 -> alpha^K (ist_table)');
      const tableText = SK.el('pre', { class: 'sk-readout' }, table);
      let axisOk = false;

      const drawAxis = SK.coalesce(async () => {
        const r = await SK.call('sk_fujimoto2000_axis', [c.kind.value, c.N.value, c.K.value, c.B.value, c.ends.value], ['text']);
        const bad = /\bK\b|iteration|N\^K/.test(r.message) ? c.K : /base interval|\bB\b/.test(r.message) ? c.B :
          /exchange|translation|ends/.test(r.message) ? c.ends : /kind|shuffle|fig/.test(r.message) ? c.kind : c.N;
        [c.N, c.K, c.B, c.kind, c.ends].forEach((x) => SK.clearReport(x));
        axisOk = SK.report(bad, r);
        if (!axisOk) return;
        const tb = await SK.call('sk_fujimoto2000_table', [0, 400], ['text']);
        tableText.textContent = tb.code === 0 ? tb.text : tb.codeName + ': ' + tb.message;
        await follow();
      });
      const follow = async () => {
        if (!axisOk) return;
        const d = await SK.call('sk_fujimoto2000_diagram', [v.half.value, v.u.value, 0, v.win.value, 1000], ['picture']);
        [v.u, v.win].forEach((x) => SK.clearReport(x));
        if (!SK.report(/\bu\b/.test(d.message) ? v.u : c.K, d)) return;
        SK.draw(f.canvas, d.picture);
        const r = await SK.call('sk_fujimoto2000_follow', [v.u.value], ['floats', 'text']);
        if (!SK.report(v.u, r)) return;
        const t = JSON.parse(r.text), s = r.floats.data;
        f.cap.textContent = KINDS[c.kind.value][1] + ', N = ' + c.N.value + ', K = ' + c.K.value + ', B = ' + c.B.value +
          (c.ends.value ? ', translation ends' : ', cyclic') + ': every box is a sub-interval, coloured by where it starts on u^0; the line follows u = ' + v.u.value;
        let html = '<tr><th>k</th><th>after div + in-shf (u^{k-0.5})</th><th>after ex-shf (u^k)</th><th>base</th></tr>';
        for (let i = 0; i < s.length; i += 4)
          html += '<tr><td>' + s[i] + '</td><td>' + (i ? s[i + 1].toFixed(6) : '—') + '</td><td>' + s[i + 2].toFixed(6) + '</td><td>' + s[i + 3] + '</td></tr>';
        steps.innerHTML = '<caption>u followed by the procedure, step by step</caption>' + html;
        readout.textContent =
          'alpha^0 (eq. 9)     ' + t.alpha0 + '  offset ' + t.offset.toFixed(4) + '\n' +
          'alpha^K iterations  ' + t.alphaK_steps + '\n' +
          'alpha^K formula     ' + t.alphaK_formula + '\n   ' + t.formula + '\n' +
          'back (inverse)      ' + t.alpha0_back + '\n' +
          'u^K procedure       ' + t.v_procedure + '\n' +
          'u^K formula eq. 14  ' + t.v_formula + (t.agree ? '  (same bits)' : '  (differs by ' + Math.abs(t.v_procedure - t.v_formula).toExponential(1) + ': rounding)') + '\n' +
          'back: procedure     ' + t.back_procedure + '\n' +
          '      formula       ' + t.back_formula;
      };
      const updateFollow = SK.coalesce(follow);
      // make bench-web: fig. 6(a)'s diagram (N = 5, K = 3, B = 13, 5 bases shown) redrawn as u moves.
      panel.benches = [{
        label: 'IST diagram redraw (fig. 6(a), 1000 px, u moved)', goal: 16, control: 'ist-u',
        values: Array.from({ length: 24 }, (_, i) => (0.02 + 0.04 * i).toFixed(3)), fns: ['sk_fujimoto2000_diagram'],
        prepare: async () => { preset.sel.value = 'fig. 6(a)'; preset.sel.dispatchEvent(new Event('change')); },
      }];
      Object.values(c).forEach((x) => { x.onchange = drawAxis; });
      Object.values(v).forEach((x) => { x.onchange = updateFollow; });
      preset.sel.addEventListener('change', () => {
        const p = PRESETS.find(([n]) => n === preset.sel.value);
        if (!p || !p[0]) return;
        const o = p[1];
        c.kind.sel.value = o.kind; c.ends.sel.value = o.ends; c.N.set(o.N); c.K.set(o.K); c.B.set(o.B);
        v.half.sel.value = o.half; v.win.set(o.win); v.u.set(o.u);
        drawAxis();
      });
      tbtn.addEventListener('click', async () => {
        ratio.textContent = 'timing…';
        const r = await SK.call('sk_fujimoto2000_ratio', [100000], ['text']);
        if (r.code !== 0) { ratio.textContent = r.codeName + ': ' + r.message; return; }
        const t = JSON.parse(r.text);
        ratio.textContent = 'procedure ' + t.procedure_us.toFixed(3) + ' µs, formula ' + t.formula_us.toFixed(4) +
          ' µs per coordinate: ratio ' + t.ratio.toFixed(1) + ' (largest difference ' + t.max_difference.toExponential(1) +
          ')\nthe paper, N = 5, K = 1 .. 6: ratio 84 .. 181 (R10000 250 MHz); wall clock in the browser, varies with load';
      });
      await drawAxis();
    },
  });

  SK.register({
    id: 'fujimoto2000-wr', paper: P, order: 110,
    title: 'WR surfaces: delta and K live, turned by the mouse',
    cite: 'fujimoto2000 §3 the WR surface R = P + H(F_U^-1(u), F_V^-1(v)) N, eq. (15) (IST-Bezier figs. 14, 17; IST-B-spline figs. 15, 18); §4.1 the superposed surface eq. (16) with the weights of eq. (19) (delta: smooth to rough); §4.2 hierarchical sampling, eq. (20); §5 "Gaussian random numbers are given to the sample values" (the jitter, superposed form only)',
    source: 'lib/shitsukan/wrinkly/wr_surface.cpp make_wr_surface(), wr_tessellation.cpp tessellate_wr_surface(), hierarchical_sampling.cpp sample_hierarchy(), superposition.cpp; lib/shitsukan/raster/rasterizer.cpp draw_mesh()',
    figures: ['fujimoto2000/fig14b', 'fujimoto2000/fig17a4', 'fujimoto2000/fig18a5'],
    interaction: { control: 'wr-delta', value: 0.7, canvas: 'canvas.sk-wr' },
    async open(body, panel) {
      const box = SK.el('div', { class: 'sk-controls' }, body);
      const figs = SK.el('div', { class: 'sk-figs' }, body);
      const c = {
        figure: SK.select(box, { label: 'surface', value: 0, options: [[0, 'IST-Bezier, unit-IST N = 3 (figs. 14, 17)'], [1, 'IST-B-spline, fully-connected N = 3 (figs. 15, 18)']] }),
        form: SK.select(box, { label: 'form', value: 2, options: [[0, 'conventional P + H N (the "(c)" panels)'], [1, 'WR surface, eq. (15): spiky'], [2, 'superposed, eqs. (16), (19), (20)']] }),
        delta: SK.slider(box, { label: 'delta (eq. 19)', min: 0.05, max: 0.95, step: 0.01, value: 0.35, key: 'wr-delta' }),
        K: SK.slider(box, { label: 'K (levels)', min: 0, max: 5, step: 1, value: 3, key: 'wr-K' }),
        seed: SK.slider(box, { label: 'heights seed', min: 0, max: 999, step: 1, value: 14, key: 'wr-seed' }),
        // §5's Gaussian jitter on the height samples, x(1 + jitter g): fig. 17's 0.5 by default
        // (fig. 18 takes 0.12), g drawn from the heights seed; the superposed form's alone.
        jitter: SK.slider(box, { label: 'jitter (§5)', min: 0, max: 1, step: 0.01, value: 0.5, key: 'wr-jitter' }),
      };
      const view = {
        yaw: SK.slider(box, { label: 'turn (yaw)', min: -3.14, max: 3.14, step: 0.01, value: 0, key: 'wr-yaw' }),
        pitch: SK.slider(box, { label: 'tilt (pitch)', min: -1.2, max: 1.2, step: 0.01, value: 0, key: 'wr-pitch' }),
      };
      const note = SK.el('p', { class: 'sk-note' }, box);
      note.textContent = 'Drag the picture (or use the turn / tilt sliders) to turn the surface (the tessellation is kept; only the view is redrawn). The control heights h_i are chosen here (a hashed field), not the paper\'s meshes. The jitter applies to the superposed form only (it is greyed out for the others): each hierarchical sample\'s height is multiplied by (1 + jitter g), g Gaussian drawn from the heights seed (§5; fig. 17 takes 0.5, fig. 18 0.12). Set it to 0 on the IST-Bezier surface: the unit-IST tiles the patch with small copies of the whole H, a regular quilt; the jitter breaks it.';
      const readout = SK.el('div', { class: 'sk-readout' }, box);
      const f = SK.figure(figs, 'the surface, Z-buffered and Lambert-lit by the library\'s rasterizer', 512, 512);
      f.canvas.classList.add('sk-wr');
      const update = SK.coalesce(async () => {
        const superposed = c.form.value === 2;
        c.jitter.range.disabled = c.jitter.box.disabled = !superposed;
        c.jitter.row.title = superposed ? '' : 'the jitter applies to the superposed form only';
        const r = await SK.call('sk_fujimoto2000_wr', [c.figure.value, c.form.value, c.delta.value, c.K.value, c.seed.value, c.jitter.value, view.yaw.value, view.pitch.value, 512], ['picture', 'text']);
        const bad = /jitter/.test(r.message) ? c.jitter : /delta/.test(r.message) ? c.delta : /\bK\b|level/.test(r.message) ? c.K : /form/.test(r.message) ? c.form : c.figure;
        [c.delta, c.K, c.form, c.figure, c.jitter].forEach((x) => SK.clearReport(x));
        if (!SK.report(bad, r)) return;
        SK.draw(f.canvas, r.picture);
        const t = JSON.parse(r.text);
        readout.textContent = t.vertices + ' vertices, ' + t.triangles + ' triangles (grid ' + t.grid.join(' x ') + ')' +
          (superposed ? ', deepest step used ' + t.levels_used + ', jitter ' + c.jitter.value : '') + '\ntessellated in ' + t.tessellate_ms.toFixed(0) +
          ' ms, drawn in ' + t.draw_ms.toFixed(0) + ' ms (WASM, wall clock)';
      });
      Object.values(c).forEach((x) => { x.onchange = update; });
      // make bench-web: fig. 14(b)'s surface (IST-Bezier, unit-IST N = 3, WR eq. (15) at K = 2,
      // 512 x 512; the WR form takes no jitter): each new heights seed re-tessellates and redraws it.
      panel.benches = [{
        label: 'WR surface, fig. 14(b) size (K = 2, 512 x 512) re-tessellated and drawn', goal: 100, control: 'wr-seed',
        values: Array.from({ length: 12 }, (_, i) => 100 + i), fns: ['sk_fujimoto2000_wr'],
        prepare: async () => { c.figure.sel.value = 0; c.form.sel.value = 1; c.K.set(2); c.jitter.set(0.5); await update(); },
      }];
      Object.values(view).forEach((x) => { x.onchange = update; });
      SK.turnable(f.canvas, view.yaw, view.pitch, update);
      await SK.call('sk_fujimoto2000_wr', [0, 2, 0.35, 1, 14, 0.5, 0, 0, 64], []);  // warm-up, the jitter's code too
      await update();
    },
  });

  SK.register({
    id: 'fujimoto2000-terrain', paper: P, order: 115,
    title: 'The superposed terrain of fig. 21, with its jitter',
    cite: 'fujimoto2000 §5 fig. 21: a terrain as a superposed IST-B-spline surface (eq. 20), the ratio delta of eq. (19) in the mountains and almost 0 in the green field (not superposed); "Gaussian random numbers are given to the sample values" (§5): the jitter on the hierarchical samples (§4.2); (c) conventional, (d) WR (spiky)',
    source: 'paper_figures/fujimoto2000/terrain_mesh.cpp terrain_control_mesh() (the figure\'s mesh); lib/shitsukan/wrinkly/hierarchical_sampling.cpp sample_hierarchy() (the jitter), wr_tessellation.cpp tessellate_wr_surface(), wr_surface.cpp make_wr_surface(); lib/shitsukan/raster/rasterizer.cpp draw_mesh(); ports/web/api/api_fujimoto2000_terrain.cpp',
    figures: ['fujimoto2000/fig21f'],
    interaction: { control: 'terrain-seed', value: 22, canvas: 'canvas.sk-terrain' },
    async open(body) {
      const box = SK.el('div', { class: 'sk-controls' }, body);
      const figs = SK.el('div', { class: 'sk-figs' }, body);
      // Defaults: fig. 21(f) as paper_figures/fujimoto2000/fig21_terrain.cpp draws it (delta 0.55,
      // jitter 0.12 on heights, 0.035 on colours, seed 21).
      const c = {
        form: SK.select(box, { label: 'form', value: 2, options: [[0, '(c) conventional B-spline'], [1, '(d) WR surface, eq. (15): spiky'], [2, '(e)-(g) superposed, eq. (20)']] }),
        delta: SK.slider(box, { label: 'delta (eq. 19)', min: 0.05, max: 0.95, step: 0.01, value: 0.55, key: 'terrain-delta' }),
        K: SK.slider(box, { label: 'K (levels)', min: 1, max: 4, step: 1, value: 3, key: 'terrain-K' }),
        jh: SK.slider(box, { label: 'jitter: height', min: 0, max: 0.6, step: 0.01, value: 0.12, key: 'terrain-jh' }),
        jc: SK.slider(box, { label: 'jitter: colour', min: 0, max: 0.2, step: 0.005, value: 0.035, key: 'terrain-jc' }),
        seed: SK.slider(box, { label: 'jitter seed', min: 0, max: 999, step: 1, value: 21, key: 'terrain-seed' }),
        yaw: SK.slider(box, { label: 'turn (yaw)', min: -3.14, max: 3.14, step: 0.01, value: 0, key: 'terrain-yaw' }),
        pitch: SK.slider(box, { label: 'tilt (pitch)', min: -0.6, max: 0.6, step: 0.01, value: 0, key: 'terrain-pitch' }),
      };
      const note = SK.el('p', { class: 'sk-note' }, box);
      note.textContent = 'The jitter multiplies each hierarchical sample\'s height by (1 + jitter g) and adds jitter g to its colour (g Gaussian, drawn from the seed): set it to 0 to see the IST alone. The green field at the front right carries delta 0.02: it is hardly superposed. Drag the picture (or use the turn / tilt sliders) to turn it.';
      const readout = SK.el('div', { class: 'sk-readout' }, box);
      const f = SK.figure(figs, 'fig. 21 drawn by the library\'s rasterizer from the figure\'s camera and light', 512, 512);
      f.canvas.classList.add('sk-terrain');
      const update = SK.coalesce(async () => {
        const r = await SK.call('sk_fujimoto2000_terrain', [c.form.value, c.delta.value, c.K.value, c.jh.value, c.jc.value, c.seed.value, c.yaw.value, c.pitch.value, 512], ['picture', 'text']);
        const bad = /jitter_height/.test(r.message) ? c.jh : /jitter_color|colour/.test(r.message) ? c.jc : /delta/.test(r.message) ? c.delta : /\bK\b|level/.test(r.message) ? c.K : c.form;
        Object.values(c).forEach((x) => SK.clearReport(x));
        if (!SK.report(bad, r)) return;
        SK.draw(f.canvas, r.picture);
        const t = JSON.parse(r.text);
        readout.textContent = t.vertices + ' vertices, ' + t.triangles + ' triangles (grid ' + t.grid.join(' x ') + ')' +
          (c.form.value === 2 ? ', deepest step used ' + t.levels_used : '') + '\ntessellated in ' + t.tessellate_ms.toFixed(0) +
          ' ms, drawn in ' + t.draw_ms.toFixed(0) + ' ms (WASM, wall clock)';
      });
      Object.values(c).forEach((x) => { x.onchange = update; });
      SK.turnable(f.canvas, c.yaw, c.pitch, update);
      await SK.call('sk_fujimoto2000_terrain', [2, 0.55, 1, 0.12, 0.035, 21, 0, 0, 64], []);  // warm-up
      await update();
    },
  });
})();
