// ports/web/page/panels/tokai1994.js — tokai1994 (reptile leather) step by step: the two-stage
// Voronoi division and its perturbation (§3.1, figs. 4-7, 10), one scale's Bezier
// cross-section and relief (§3.2, figs. 12-15, Table 1), the bump-mapped patch under a light
// the user moves (§4-5, figs. 16-18). Wiring and drawing only (api_tokai1994.cpp).
/* global SK */
'use strict';
(function () {
  const P = 'tokai1994 — Tokai, Miyata';
  // The pattern and section the worker holds; `version` changes whenever either does, so the
  // maps of the patch panel are remade only when needed.
  const T = { pattern: '', version: 0, section: 0 };
  async function ensurePattern(c, report) {
    const args = c ? [c.D.value, c.d.value, c.a.value, c.p.value, c.seed.value] : [0.1, 1, 0.25, 0.015, 1];
    const key = args.join('/');
    if (!c && T.pattern) return null;  // another panel's pattern: keep it
    if (key === T.pattern) return null;
    const r = await SK.call('sk_tokai1994_pattern', args, ['text']);
    if (report) {
      const bad = /spacing D|D must|D </.test(r.message) ? c.D : /distance d|\bd\b/.test(r.message) ? c.d :
        /displacement|\ba\b/.test(r.message) ? c.a : /perturbation|\bp\b/.test(r.message) ? c.p : c.D;
      [c.D, c.d, c.a, c.p].forEach((x) => SK.clearReport(x));
      if (!SK.report(bad, r)) return r;
    }
    if (r.code === 0) { T.pattern = key; T.version++; }
    return r;
  }

  const STEPS = [
    [0, 'fig. 4: stage-1 seeds (processings 1-2) and their Voronoi division (3)'],
    [1, 'fig. 5: the stage-1 polygons, edges bent (processing 4)'],
    [2, 'fig. 6: stage-2 seed rows, narrowing toward the edges, and the stage-2 cells'],
    [3, 'fig. 7: the final scale pattern'],
    [4, 'fig. 10: the perturbation p alone (grey: the straight cells)'],
  ];

  SK.register({
    id: 'tokai1994-division', paper: P, order: 70,
    title: 'Two-stage Voronoi division, step by step',
    cite: 'tokai1994 §3.1: stage 1 (vertical) and stage 2 (horizontal) division, each by processings 1-4 — lattice seeds, the move of eq. (1) M = D·a·Rnd, the Voronoi division, the edge perturbation; figs. 4, 5, 6, 7 and fig. 10 (p)',
    source: 'lib/shitsukan/leather/scale_division.cpp generate_scale_pattern(), seed_layout.cpp stage1_seeds() / stage2_row_seeds(), edge_perturbation.cpp perturb_two_stage()',
    figures: ['tokai1994/fig04', 'tokai1994/fig06', 'tokai1994/fig07', 'tokai1994/fig10'],
    interaction: { control: 'p', value: 0.04, canvas: 'canvas.sk-division' },
    async open(body) {
      const box = SK.el('div', { class: 'sk-controls' }, body);
      const figs = SK.el('div', { class: 'sk-figs' }, body);
      const step = SK.select(box, { label: 'step', value: 3, options: STEPS.map(([v, t]) => [v, t.split(':')[0] + ': ' + t.split(': ')[1].split(' (')[0]]) });
      const c = {
        D: SK.slider(box, { label: 'D (spacing)', min: 0.02, max: 0.3, step: 0.005, value: 0.1, key: 'D' }),
        d: SK.slider(box, { label: 'd / D', min: 0, max: 3, step: 0.05, value: 1, key: 'd' }),
        a: SK.slider(box, { label: 'a (eq. 1)', min: 0, max: 1, step: 0.01, value: 0.25, key: 'a' }),
        p: SK.slider(box, { label: 'p (fig. 10)', min: 0, max: 0.06, step: 0.001, value: 0.015, key: 'p' }),
        seed: SK.slider(box, { label: 'seed', min: 0, max: 9999, step: 1, value: 1, key: 'seed' }),
      };
      const readout = SK.el('div', { class: 'sk-readout' }, box);
      const f = SK.figure(figs, STEPS[3][1], 512, 512);
      f.canvas.classList.add('sk-division');
      const update = SK.coalesce(async () => {
        const r = await ensurePattern(c, true);
        if (r && r.code !== 0) return;
        if (r) {
          const t = JSON.parse(r.text);
          readout.textContent = t.scales + ' scales from ' + t.stage1 + ' stage-1 polygons; ' + t.stage2_seeds + ' stage-2 seeds on ' +
            t.columns + ' columns\nperturbation: ' + t.edges + ' edges bent, RMS offset ' + t.realised_rms.toFixed(4) +
            ' of ' + t.requested_rms.toFixed(4) + ' requested (' + t.shrunk + ' edges scaled down to keep the tiling)\n' +
            'generated in ' + r.ms.toFixed(0) + ' ms (WASM, in the worker)';
        }
        const s = await SK.call('sk_tokai1994_step', [step.value, 512], ['picture']);
        if (!SK.report(step, s)) return;
        SK.draw(f.canvas, s.picture);
        f.cap.textContent = STEPS[step.value][1] + (step.value === 0 || step.value === 2 ? ' — open circles: seeds on the lattice; red dots: moved by eq. (1)' : '');
      });
      Object.values(c).forEach((x) => { x.onchange = update; });
      step.onchange = update;
      await SK.call('sk_tokai1994_pattern', [0.3, 1, 0.25, 0.015, 1], []);  // warm-up on a small pattern
      await update();
    },
  });

  SK.register({
    id: 'tokai1994-relief', paper: P, order: 80,
    title: 'One scale: the Bezier cross-section and its relief',
    cite: 'tokai1994 §3.2, fig. 12: the cross-section z(r), a cubic Bezier curve (eqs. (2), (3); Table 1), swept from the scale\'s centroid to its edge, and the normal of eq. (4); figs. 13-15 are Table 1\'s three sections. Drag the control points',
    source: 'lib/shitsukan/leather/relief.cpp scale_relief() / table1_section(), lib/shitsukan/geom/bezier_curve.cpp section_at_r() / validate_section()',
    figures: ['tokai1994/fig12', 'tokai1994/fig13a', 'tokai1994/fig15a'],
    async open(body) {
      const box = SK.el('div', { class: 'sk-controls' }, body);
      const figs = SK.el('div', { class: 'sk-figs' }, body);
      const c = {
        section: SK.select(box, { label: 'section', value: 0, options: [[0, 'Table 1 convex (fig. 13)'], [1, 'Table 1 concave (fig. 14)'], [2, 'Table 1 two segments (fig. 15)']] }),
        scale: SK.slider(box, { label: 'height scale', min: 0, max: 4, step: 0.05, value: 1, key: 'hscale' }),
        lx: SK.slider(box, { label: 'light x', min: -1, max: 1, step: 0.05, value: 0.3, key: 'lx' }),
        ly: SK.slider(box, { label: 'light y', min: -1, max: 1, step: 0.05, value: 0.5, key: 'ly' }),
        lz: SK.slider(box, { label: 'light z', min: 0, max: 1, step: 0.05, value: 0.8, key: 'lz' }),
      };
      const sec = SK.figure(figs, 'the cross-section z(r) (blue, section_at_r) and its control points (red: drag them); r = 0 the centroid, r = 1 the edge (z drawn 1.24x larger than r)', 420, 260);
      const dragStatus = SK.el('div', { class: 'sk-status', role: 'status' }, figs);
      const rel = SK.figure(figs, 'the scale nearest the middle of the pattern: height (left, white highest) and the eq. (4) normal lit by the light (right)', 392, 192);
      const info = SK.el('div', { class: 'sk-readout' }, box);
      const view = { r0: -0.05, r1: 1.05, z0: -0.05, z1: 0.5 };
      const W = 420, H = 260;
      const toPx = (r, z) => [((r - view.r0) / (view.r1 - view.r0)) * W, H - ((z - view.z0) / (view.z1 - view.z0)) * H];
      const fromPx = (x, y) => [view.r0 + (x / W) * (view.r1 - view.r0), view.z0 + ((H - y) / H) * (view.z1 - view.z0)];
      let points = [];
      async function drawSection() {
        const p = await SK.call('sk_tokai1994_section_points', [], ['floats']);
        const q = await SK.call('sk_tokai1994_section_curve', [200], ['floats']);
        points = Array.from(p.floats.data);
        const g = sec.canvas.getContext('2d');
        g.fillStyle = '#fff'; g.fillRect(0, 0, W, H);
        g.strokeStyle = '#ddd'; g.beginPath();
        [[0, 0, 1, 0], [0, 0, 0, 0.45], [1, 0, 1, 0.45]].forEach(([a, b, cc, d]) => { const u = toPx(a, b), v = toPx(cc, d); g.moveTo(u[0], u[1]); g.lineTo(v[0], v[1]); });
        g.stroke();
        g.strokeStyle = '#e0a0a0'; g.beginPath();
        for (let k = 0; k < points.length; k += 2) { const u = toPx(points[k], points[k + 1]); k % 8 === 0 ? g.moveTo(u[0], u[1]) : g.lineTo(u[0], u[1]); }
        g.stroke();
        g.strokeStyle = '#1f5f99'; g.lineWidth = 2; g.beginPath();
        const d = q.floats.data;
        for (let k = 0; k < d.length; k += 2) { const u = toPx(d[k], d[k + 1]); k ? g.lineTo(u[0], u[1]) : g.moveTo(u[0], u[1]); }
        g.stroke(); g.lineWidth = 1;
        g.fillStyle = '#c8281e';
        for (let k = 0; k < points.length; k += 2) { const u = toPx(points[k], points[k + 1]); g.beginPath(); g.arc(u[0], u[1], 5, 0, 7); g.fill(); }
        g.fillStyle = '#333'; g.font = '11px sans-serif'; g.fillText('r →', W - 30, H - 6); g.fillText('z', 6, 12);
      }
      const drawRelief = SK.coalesce(async () => {
        await ensurePattern(null, false);
        const r = await SK.call('sk_tokai1994_scale_relief', [192, c.scale.value, c.lx.value, c.ly.value, c.lz.value], ['picture', 'text']);
        const bad = /height/.test(r.message) ? c.scale : /light/.test(r.message) ? c.lx : c.scale;
        [c.scale, c.lx].forEach((x) => SK.clearReport(x));
        if (!SK.report(bad, r)) return;
        SK.draw(rel.canvas, r.picture);
        const t = JSON.parse(r.text);
        info.textContent = 'scale ' + t.scale + ': ' + t.vertices + ' vertices, S = 2·area/perimeter = ' + t.S.toFixed(4) +
          ' (one height unit), highest point ' + t.max_height.toFixed(4);
      });
      c.section.onchange = async () => {
        await SK.call('sk_tokai1994_section_load', [c.section.value], []);
        T.version++;
        await drawSection();
        await drawRelief();
      };
      [c.scale, c.lx, c.ly, c.lz].forEach((x) => { x.onchange = drawRelief; });
      let drag = null;
      sec.canvas.style.cursor = 'crosshair';
      sec.canvas.addEventListener('pointerdown', (e) => {
        const rect = sec.canvas.getBoundingClientRect();
        const x = ((e.clientX - rect.left) * W) / rect.width, y = ((e.clientY - rect.top) * H) / rect.height;
        let best = -1, bd = 12 * 12;
        for (let k = 0; k < points.length; k += 2) {
          const u = toPx(points[k], points[k + 1]), dd = (u[0] - x) ** 2 + (u[1] - y) ** 2;
          if (dd < bd) { bd = dd; best = k / 2; }
        }
        if (best >= 0) { drag = { segment: Math.floor(best / 4), index: best % 4 }; sec.canvas.setPointerCapture(e.pointerId); }
      });
      const move = SK.coalesce(async () => {
        if (!drag || !drag.to) return;
        const r = await SK.call('sk_tokai1994_section_move', [drag.segment, drag.index, drag.to[0], drag.to[1]], []);
        dragStatus.textContent = r.code === 0 ? '' : 'control point refused: ' + r.codeName + ': ' + r.message;
        if (r.code === 0) T.version++;
        await drawSection();
        await drawRelief();
      });
      sec.canvas.addEventListener('pointermove', (e) => {
        if (!drag) return;
        const rect = sec.canvas.getBoundingClientRect();
        drag.to = fromPx(((e.clientX - rect.left) * W) / rect.width, ((e.clientY - rect.top) * H) / rect.height);
        move();
      });
      sec.canvas.addEventListener('pointerup', () => { drag = null; });
      await SK.call('sk_tokai1994_section_load', [0], []);
      if (T.pattern) await SK.call('sk_tokai1994_scale_relief', [16, 1, 0.3, 0.5, 0.8], []);  // warm-up
      await drawSection();
      await drawRelief();
    },
  });

  SK.register({
    id: 'tokai1994-patch', paper: P, order: 90,
    title: 'The bump-mapped patch under a moving light',
    cite: 'tokai1994 §4-5, figs. 16-18: the leather maps (heights and eq. (4) normals of every scale) mapped onto a bicubic Bezier patch (eq. (5)) and bump-mapped, lit by two point lights; drag the picture (or the sliders) to move the key light',
    source: 'lib/shitsukan/leather/maps.cpp make_leather_maps(), lib/shitsukan/render/leather_mesh.cpp draw_leather_mesh(), lib/shitsukan/geom/bezier_patch_mesh.cpp tessellate_patch_strip()',
    figures: ['tokai1994/fig16', 'tokai1994/fig18'],
    async open(body) {
      const box = SK.el('div', { class: 'sk-controls' }, body);
      const figs = SK.el('div', { class: 'sk-figs' }, body);
      const c = {
        size: SK.select(box, { label: 'maps', value: 512, options: [[256, '256 x 256'], [512, '512 x 512 (the paper\'s)'], [1024, '1024 x 1024']] }),
        az: SK.slider(box, { label: 'light azimuth', min: -3.14, max: 3.14, step: 0.01, value: -0.8, key: 'az' }),
        el: SK.slider(box, { label: 'light elevation', min: 0.05, max: 1.55, step: 0.01, value: 0.6, key: 'el' }),
      };
      const note = SK.el('p', { class: 'sk-note' }, box);
      note.textContent = 'The maps follow the pattern and section of the two panels before this one (fig. 7 and Table 1\'s convex section until you change them). Low light shows the scales\' relief best.';
      const info = SK.el('div', { class: 'sk-readout' }, box);
      const fp = SK.figure(figs, 'the patch, bump-mapped, Blinn 1977 shading; key light where you drag', 448, 448);
      fp.canvas.style.cursor = 'grab';
      const fn = SK.figure(figs, 'the normal map (rgb = (n + 1)/2, +y up)', 256, 256);
      fn.canvas.style.width = '256px';
      let mapsFor = '';
      const update = SK.coalesce(async () => {
        await ensurePattern(null, false);
        const key = T.version + '/' + c.size.value;
        if (key !== mapsFor) {
          const m = await SK.call('sk_tokai1994_maps', [c.size.value], ['picture']);
          if (!SK.report(c.size, m)) return;
          SK.draw(fn.canvas, m.picture);
          info.textContent = 'maps ' + c.size.value + ' x ' + c.size.value + ' made in ' + m.ms.toFixed(0) + ' ms (WASM, in the worker)';
          mapsFor = key;
        }
        const r = await SK.call('sk_tokai1994_patch', [c.az.value, c.el.value, 448], ['picture']);
        if (!SK.report(c.az, r)) return;
        SK.draw(fp.canvas, r.picture);
      });
      Object.values(c).forEach((x) => { x.onchange = update; });
      let drag = null;
      fp.canvas.addEventListener('pointerdown', (e) => { drag = { x: e.clientX, y: e.clientY, az: c.az.value, el: c.el.value }; fp.canvas.setPointerCapture(e.pointerId); });
      fp.canvas.addEventListener('pointermove', (e) => {
        if (!drag) return;
        c.az.set((drag.az + (e.clientX - drag.x) * 0.01).toFixed(2));
        c.el.set(Math.max(0.05, Math.min(1.55, drag.el - (e.clientY - drag.y) * 0.01)).toFixed(2));
        update();
      });
      fp.canvas.addEventListener('pointerup', () => { drag = null; });
      await update();
    },
  });
})();
