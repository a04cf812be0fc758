// ports/web/page/panels/okada1987.js — okada1987 (3D random fractal marble and wood) step by
// step: the lattice level by level (§2), D(P) and marble (§3-4.1), wood (§4.2), the forward
// and backward mappings, the objects of figs. 10a and 13. Wiring and drawing only: every
// number and picture comes from ports/web/api/api_okada1987.cpp.
/* global SK */
'use strict';
(function () {
  const P = 'okada1987 — Okada, Yokoi, Toriwaki';
  const fmt = (x, d) => Number(x).toFixed(d === undefined ? 3 : d);

  // The lattice the slices and objects share (sk_okada1987_build), rebuilt when R, beta or
  // seed change; its Status shows beside the R control of the panel that asked.
  let built = '';
  async function ensureLattice(c) {
    const key = [c.R.value, c.beta.value, c.seed.value].join('/');
    if (key === built) { SK.clearReport(c.R); return true; }
    const r = await SK.call('sk_okada1987_build', [c.R.value, c.beta.value, c.seed.value], []);
    if (!SK.report(c.R, r)) { built = ''; return false; }
    built = key;
    return true;
  }
  function latticeControls(box) {
    SK.el('h4', {}, box, 'Lattice (§2.2; the 65^3 of R = 6 is the papers\')');
    return {
      R: SK.slider(box, { label: 'R (depth)', min: 1, max: 8, step: 1, value: 6, key: 'R' }),
      beta: SK.slider(box, { label: 'beta (eq. 2)', min: 0, max: 2, step: 0.05, value: 0.9, key: 'beta' }),
      seed: SK.slider(box, { label: 'seed', min: 0, max: 9999, step: 1, value: 1987, key: 'seed' }),
    };
  }
  function wire(controls, update) {
    Object.values(controls).forEach((c) => { c.onchange = update; });
  }

  // ---- §2: the lattice level by level ----
  SK.register({
    id: 'okada1987-lattice', paper: P, order: 10,
    title: 'The random fractal lattice, level by level',
    cite: 'okada1987 §2.1 fig. 1 (2D, by quadtree) and §2.2 fig. 2 (3D, by octree): eqs. (1)-(4) add the nodes of a level, eq. (5) gives their random amplitude g·e^-(n-1)·beta',
    source: 'lib/shitsukan/solid/quadtree_lattice.cpp build_quadtree_lattice(), lib/shitsukan/solid/fractal_lattice.cpp build_fractal_lattice(), fractal_params.cpp level_amplitude()',
    figures: ['okada1987/fig01', 'okada1987/fig02'],
    async open(body) {
      const box = SK.el('div', { class: 'sk-controls' }, body);
      const figs = SK.el('div', { class: 'sk-figs' }, body);
      const c = {
        level: SK.slider(box, { label: 'level n', min: 0, max: 6, step: 1, value: 3, key: 'level' }),
        R: SK.slider(box, { label: 'R (depth)', min: 1, max: 8, step: 1, value: 6, key: 'R' }),
        beta: SK.slider(box, { label: 'beta (eq. 2)', min: 0, max: 2, step: 0.05, value: 0.9, key: 'beta' }),
        seed: SK.slider(box, { label: 'seed', min: 0, max: 9999, step: 1, value: 1987, key: 'seed' }),
        z: SK.slider(box, { label: '3D: plane z', min: 0, max: 64, step: 1, value: 32, key: 'z' }),
      };
      const legend = SK.el('p', { class: 'sk-legend sk-note' }, box);
      legend.innerHTML = 'Right halves: the nodes level n adds —' +
        '<span style="background:#3465a4"></span>eq. (1) edge midpoints' +
        '<span style="background:#f57900"></span>eq. (3) face centres (2D: square centres)' +
        '<span style="background:#cc0000"></span>eq. (4) cube centres' +
        '<span style="background:#c8c8c8"></span>set by earlier levels. Left halves: the values ' +
        '(blue −1.5 … white 0 … red +1.5), each node drawn as the square of its level; grey: not set yet.';
      const amp = SK.figure(box, 'eq. (5): amplitude e^-(n-1)·beta of the random term per level (current level dark)', 320, 110);
      const readout = SK.el('div', { class: 'sk-readout' }, box);
      const f1 = SK.figure(figs, 'fig. 1: the 2D height field after level n (left) and the points level n adds (right)', 520, 256);
      const f2 = SK.figure(figs, 'fig. 2: the plane z of the 3D lattice after level n (left) and the nodes each rule adds (right)', 520, 256);
      f1.canvas.classList.add('sk-quadtree');
      f2.canvas.classList.add('sk-octree');
      const update = SK.coalesce(async () => {
        const R = c.R.value, n = c.level.value;
        c.level.range.max = Math.max(0, Math.min(R, 12));
        c.z.range.max = Math.pow(2, Math.max(0, Math.min(R, 12)));
        const q = await SK.call('sk_okada1987_quadtree_level', [R, c.beta.value, c.seed.value, n, 256]);
        const ok2 = SK.report(c.R, q) && SK.draw(f1.canvas, q.picture);
        const r = await SK.call('sk_okada1987_lattice_level', [R, c.beta.value, c.seed.value, n, c.z.value, 256]);
        // level and plane errors beside their controls, the rest (R, beta) beside R
        const target = /level/.test(r.message) ? c.level : /plane/.test(r.message) ? c.z : /beta/.test(r.message) ? c.beta : c.R;
        [c.level, c.z, c.beta].forEach((x) => { if (x !== target) SK.clearReport(x); });
        if (!SK.report(target, r)) return;
        if (!ok2) SK.report(c.R, q);
        SK.draw(f2.canvas, r.picture);
        const t = JSON.parse(r.text);
        SK.plotBars(amp.canvas, t.amplitude, n);
        readout.textContent = 'level ' + n + ' of ' + R + ': lattice ' + t.side + '^3 nodes\n' +
          'added at this level: ' + t.edge + ' edge midpoints (eq. 1), ' + t.face + ' face centres (eq. 3), ' +
          t.centre + ' cube centres (eq. 4)\n' +
          'amplitude L^(n) = ' + (n > 0 ? fmt(t.amplitude[n - 1], 4) : '—') + '  (eq. 5: the random term is g·L^(n), g ~ N(0, 1))';
      });
      wire(c, update);
      // warm-up on a small input, then the real one
      await SK.call('sk_okada1987_lattice_level', [3, 0.9, 1987, 3, 4, 32], []);
      await update();
    },
  });
  // Bars of the per-level amplitudes (drawing only).
  SK.plotBars = function (canvas, values, current) {
    const g = canvas.getContext('2d'), w = canvas.width, h = canvas.height;
    g.fillStyle = '#fff';
    g.fillRect(0, 0, w, h);
    const bw = (w - 20) / values.length;
    g.font = '10px sans-serif';
    values.forEach((v, i) => {
      const bh = v * (h - 24);
      g.fillStyle = i + 1 === current ? '#1f5f99' : '#9fbcd8';
      g.fillRect(10 + i * bw + 2, h - 14 - bh, bw - 4, bh);
      g.fillStyle = '#333';
      g.fillText('n=' + (i + 1), 10 + i * bw + 2, h - 3);
    });
  };

  // ---- §3-4.1: D(P) and marble ----
  SK.register({
    id: 'okada1987-marble', paper: P, order: 20,
    title: 'Turbulence D(P) and marble',
    cite: 'okada1987 eq. (6) (D(P): trilinear interpolation of the lattice, fig. 6), §4.1 eq. (8) (the stripes: trapezoids with exponential skirts, fig. 9), eq. (9) (the shift k·D(P) along z), eq. (12) (the colours); fig. 12 varies k',
    source: 'lib/shitsukan/solid/turbulence.cpp turbulence_row(), lib/shitsukan/solid/marble.cpp marble_original() / marble_texture(), lib/shitsukan/render/solid_bake.cpp render_solid_slice()',
    figures: ['okada1987/fig07', 'okada1987/fig09', 'okada1987/fig12a'],
    bench: { control: 'k', values: [2, 4, 6, 8, 10, 12, 14, 16, 18, 20, 22, 24, 26, 28, 30, 32, 3, 5, 7, 9], what: '512x512 marble', fn: 'sk_okada1987_marble_slice' },
    interaction: { control: 'k', value: 24, canvas: 'canvas.sk-marble' },
    async open(body) {
      const box = SK.el('div', { class: 'sk-controls' }, body);
      const figs = SK.el('div', { class: 'sk-figs' }, body);
      const c = latticeControls(box);
      SK.el('h4', {}, box, 'Marble (§4.1)');
      const m = {
        k: SK.slider(box, { label: 'k (eq. 9)', min: 0, max: 48, step: 0.5, value: 16, key: 'k' }),
        y: SK.slider(box, { label: 'slice plane y', min: 0, max: 64, step: 0.25, value: 32, key: 'y' }),
      };
      SK.el('h4', {}, box, 'One stripe of eq. (8): c, w, alpha');
      const s = {
        i: SK.select(box, { label: 'stripe', value: 2, options: [0, 1, 2, 3, 4, 5].map((i) => [i, 'stripe ' + (i + 1)]) }),
        c: SK.slider(box, { label: 'c (centre)', min: 0, max: 64, step: 0.5, value: 26, key: 'c' }),
        w: SK.slider(box, { label: 'w (top width)', min: 0, max: 10, step: 0.1, value: 0.8, key: 'w' }),
        alpha: SK.slider(box, { label: 'alpha (skirt)', min: 0, max: 3, step: 0.05, value: 1.5, key: 'alpha' }),
      };
      const reset = SK.el('button', { type: 'button' }, box, 'the six stripes as the figures');
      const prof = SK.figure(box, 'eq. (8): G(z) = Σ g_j(z) over z in [0, 2^R] (before the shift)', 320, 100);
      const fm = SK.figure(figs, 'eqs. (8), (9), (12): the marble on the same plane, G(P + k·D(P)·(0, 0, 1)), 512 x 512', 512, 512);
      const fd = SK.figure(figs, 'eq. (6): D(P) on the plane y (x right, z up; blue −2.5 … red +2.5)', 256, 256);
      fm.canvas.classList.add('sk-marble');
      const timing = SK.el('div', { class: 'sk-readout' }, box);
      let stripeDirty = false, profileDirty = true, lastD = '';
      const update = SK.coalesce(async () => {
        if (!(await ensureLattice(c))) return;
        if (stripeDirty) {
          stripeDirty = false;
          const r = await SK.call('sk_okada1987_set_stripe', [s.i.value, s.c.value, s.w.value, s.alpha.value], []);
          profileDirty = true;
          const bad = /width/.test(r.message) ? s.w : /alpha|decay/.test(r.message) ? s.alpha : s.c;
          [s.c, s.w, s.alpha].forEach((x) => SK.clearReport(x));
          SK.report(bad, r);
        }
        // only what a control changed is recomputed: k alone redraws the marble alone
        const g = await SK.call('sk_okada1987_marble_slice', [m.k.value, m.y.value, 512], ['picture']);
        if (!SK.report(m.k, g)) return;
        SK.draw(fm.canvas, g.picture);
        timing.textContent = 'marble slice computed in ' + fmt(g.ms, 1) + ' ms (WASM, in the worker)';
        const dKey = built + '/' + m.y.value;
        if (dKey !== lastD) {
          const d = await SK.call('sk_okada1987_turbulence_slice', [m.y.value, 256, 2.5], ['picture']);
          if (!SK.report(m.y, d)) return;
          SK.draw(fd.canvas, d.picture);
          lastD = dKey;
        }
        if (profileDirty) {
          const p = await SK.call('sk_okada1987_marble_profile', [320], ['floats']);
          if (p.code === 0) SK.plot(prof.canvas, p.floats.data, { min: 0, max: 1.2, label: 'G(z)' });
          profileDirty = false;
        }
      });
      wire(c, update);
      wire(m, update);
      [s.c, s.w, s.alpha].forEach((x) => { x.onchange = () => { stripeDirty = true; update(); }; });
      s.i.onchange = async () => {  // the chosen stripe's current values (the library's presets until moved)
        const r = await SK.call('sk_okada1987_get_stripes', [], ['floats']);
        const i = s.i.value, v = r.floats.data;
        s.c.set(+v[3 * i].toFixed(3)); s.w.set(+v[3 * i + 1].toFixed(3)); s.alpha.set(+v[3 * i + 2].toFixed(3));
      };
      reset.addEventListener('click', async () => {
        await SK.call('sk_okada1987_set_stripe', [-1, 0, 0, 0], []);
        profileDirty = true;
        await s.i.onchange();
        update();
      });
      await SK.call('sk_okada1987_build', [3, 0.9, 1987], []);  // warm-up on a small lattice
      await SK.call('sk_okada1987_marble_slice', [16, 4, 32], []);
      built = '';
      await s.i.onchange();
      await update();
    },
  });

  // ---- §4.2: wood ----
  SK.register({
    id: 'okada1987-wood', paper: P, order: 30,
    title: 'Wood: rings bent by the turbulence',
    cite: 'okada1987 §4.2: eq. (10) G = sin(k2·r) about the axis (x0, y0), eq. (11) the radial shift k·D(P)·u, eq. (12) the colours; figs. 10b and 13b',
    source: 'lib/shitsukan/solid/wood.cpp wood_original() / wood_texture(), lib/shitsukan/render/solid_bake.cpp render_solid_slice()',
    figures: ['okada1987/fig10b', 'okada1989/fig07'],
    async open(body) {
      const box = SK.el('div', { class: 'sk-controls' }, body);
      const figs = SK.el('div', { class: 'sk-figs' }, body);
      const c = latticeControls(box);
      SK.el('h4', {}, box, 'Wood (§4.2)');
      const w = {
        k: SK.slider(box, { label: 'k (eq. 11)', min: 0, max: 8, step: 0.1, value: 1.6, key: 'k' }),
        k2: SK.slider(box, { label: 'k2 (eq. 10)', min: 0.1, max: 4, step: 0.05, value: 1.2, key: 'k2' }),
        x0: SK.slider(box, { label: 'axis x0', min: -32, max: 96, step: 1, value: 6, key: 'x0' }),
        y0: SK.slider(box, { label: 'axis y0', min: -32, max: 96, step: 1, value: 14, key: 'y0' }),
        z: SK.slider(box, { label: 'slice plane z', min: 0, max: 64, step: 0.25, value: 32, key: 'z' }),
      };
      const f = SK.figure(figs, 'the plane z across the trunk (x right, y up): rings every 2·pi/k2, bent by k·D(P)', 512, 512);
      const f0 = SK.figure(figs, 'the same with k = 0: eq. (10) alone', 256, 256);
      const update = SK.coalesce(async () => {
        if (!(await ensureLattice(c))) return;
        const r = await SK.call('sk_okada1987_wood_slice', [w.k.value, w.k2.value, w.x0.value, w.y0.value, w.z.value, 512], ['picture']);
        const bad = /k2|ring/.test(r.message) ? w.k2 : /axis|x0|y0/.test(r.message) ? w.x0 : /plane|z/.test(r.message) ? w.z : w.k;
        Object.values(w).forEach((x) => SK.clearReport(x));
        if (!SK.report(bad, r)) return;
        SK.draw(f.canvas, r.picture);
        const r0 = await SK.call('sk_okada1987_wood_slice', [0, w.k2.value, w.x0.value, w.y0.value, w.z.value, 256], ['picture']);
        SK.draw(f0.canvas, r0.picture);
      });
      wire(c, update);
      wire(w, update);
      await SK.call('sk_okada1987_build', [3, 0.9, 1987], []);  // warm-up on a small lattice
      await SK.call('sk_okada1987_wood_slice', [1.6, 1.2, 6, 14, 4, 32], []);
      built = '';
      await update();
    },
  });

  // ---- §3.2 forward vs okada1989 §4-1 backward ----
  SK.register({
    id: 'okada1987-mapping', paper: P, order: 40,
    title: 'Forward mapping (okada1987) and pixel shift (okada1989)',
    cite: 'okada1987 §3.2: the value G(P) "is observed at" P\' = F(P, D(P)) — a forward map; okada1989 §4-1 eq. (7): the pixel P shows G(P + k·D(P)·u) — the backward (gather) form a renderer evaluates',
    source: 'lib/shitsukan/solid/pixel_shift.hpp pixel_shift(); ports/web/api/api_okada1987.cpp sk_okada1987_mapping() scatters with it, lib/shitsukan/render/solid_bake.cpp render_solid_slice() gathers',
    figures: ['okada1987/fig07', 'okada1989/fig06'],
    async open(body) {
      const box = SK.el('div', { class: 'sk-controls' }, body);
      const figs = SK.el('div', { class: 'sk-figs' }, body);
      const c = latticeControls(box);
      SK.el('h4', {}, box, 'The shift');
      const m = {
        k: SK.slider(box, { label: 'k', min: 0, max: 48, step: 0.5, value: 16, key: 'k' }),
        y: SK.slider(box, { label: 'slice plane y', min: 0, max: 64, step: 0.25, value: 32, key: 'y' }),
      };
      const note = SK.el('p', { class: 'sk-note' }, box);
      note.textContent = 'Forward: every pixel sends its G(P) to where P\' lands; black pixels received nothing (holes), ' +
        'others several values (the last wins). Backward: every pixel asks for G at its own P\': no holes. ' +
        'For small k the two differ by the sign of the shift.';
      const readout = SK.el('div', { class: 'sk-readout' }, box);
      const ff = SK.figure(figs, 'forward (okada1987 §3.2): scatter G(P) to P\' = P + k·D(P)·(0, 0, 1)', 384, 384);
      const fb = SK.figure(figs, 'backward (okada1989 §4-1, eq. 7): pixel P shows G(P\')', 384, 384);
      const update = SK.coalesce(async () => {
        if (!(await ensureLattice(c))) return;
        const f = await SK.call('sk_okada1987_mapping', [m.k.value, m.y.value, 384, 1], ['picture', 'floats']);
        if (!SK.report(m.k, f)) return;
        SK.draw(ff.canvas, f.picture);
        const b = await SK.call('sk_okada1987_mapping', [m.k.value, m.y.value, 384, 0], ['picture']);
        SK.draw(fb.canvas, b.picture);
        let holes = 0, multi = 0;
        f.floats.data.forEach((h) => { if (h === 0) holes++; else if (h > 1) multi++; });
        readout.textContent = 'forward: ' + holes + ' of ' + f.floats.data.length + ' pixels got no value, ' + multi + ' got several';
      });
      wire(c, update);
      wire(m, update);
      await SK.call('sk_okada1987_build', [3, 0.9, 1987], []);  // warm-up on a small lattice
      await SK.call('sk_okada1987_mapping', [16, 4, 32, 1], []);
      built = '';
      await update();
    },
  });

  // ---- figs. 10a and 13: the library's rasterizer, turned with the mouse ----
  SK.register({
    id: 'okada1987-objects', paper: P, order: 50,
    title: 'Objects: the cube (fig. 10a) and the cut sphere (fig. 13)',
    cite: 'okada1987 §4.4 figs. 10a (cube, marble k = 16) and 13 (sphere with a part cut away): the solid texture inside the object shows on every cut face. Drag the picture to turn the object',
    source: 'lib/shitsukan/render/solid_mesh.cpp render_solid_texture() (the scanline rasterizer of lib/shitsukan/raster/), lib/shitsukan/geom/mesh_builders.cpp make_box() / make_sphere_without_octant()',
    figures: ['okada1987/fig10a', 'okada1987/fig13a'],
    async open(body) {
      const box = SK.el('div', { class: 'sk-controls' }, body);
      const figs = SK.el('div', { class: 'sk-figs' }, body);
      const c = latticeControls(box);
      SK.el('h4', {}, box, 'Object');
      const o = {
        scene: SK.select(box, { label: 'object', value: 0, options: [[0, 'cube (fig. 10a)'], [1, 'cut sphere (fig. 13)']] }),
        material: SK.select(box, { label: 'material', value: 0, options: [[0, 'marble (k = 16)'], [1, 'wood (k = 1.6)']] }),
        k: SK.slider(box, { label: 'k', min: 0, max: 48, step: 0.1, value: 16, key: 'k' }),
        yaw: SK.slider(box, { label: 'turn (yaw)', min: -3.14, max: 3.14, step: 0.01, value: 0, key: 'yaw' }),
        pitch: SK.slider(box, { label: 'tilt (pitch)', min: -1.5, max: 1.5, step: 0.01, value: 0, key: 'pitch' }),
      };
      o.material.onchange = () => { o.k.set(o.material.value === 0 ? 16 : 1.6); update(); };
      const fo = SK.figure(figs, 'drawn by the library\'s own rasterizer (Lambert light from the upper front); drag to turn', 448, 448);
      fo.canvas.classList.add('sk-object');
      fo.canvas.style.cursor = 'grab';
      const update = SK.coalesce(async () => {
        if (!(await ensureLattice(c))) return;
        const r = await SK.call('sk_okada1987_object', [o.scene.value, o.material.value, o.k.value, o.yaw.value, o.pitch.value, 448], ['picture']);
        if (!SK.report(o.k, r)) return;
        SK.draw(fo.canvas, r.picture);
      });
      wire(c, update);
      [o.scene, o.k, o.yaw, o.pitch].forEach((x) => { x.onchange = update; });
      let drag = null;
      fo.canvas.addEventListener('pointerdown', (e) => { drag = { x: e.clientX, y: e.clientY, yaw: o.yaw.value, pitch: o.pitch.value }; fo.canvas.setPointerCapture(e.pointerId); });
      fo.canvas.addEventListener('pointermove', (e) => {
        if (!drag) return;
        o.yaw.set((drag.yaw + (e.clientX - drag.x) * 0.01).toFixed(2));
        o.pitch.set(Math.max(-1.5, Math.min(1.5, drag.pitch + (e.clientY - drag.y) * 0.01)).toFixed(2));
        update();
      });
      fo.canvas.addEventListener('pointerup', () => { drag = null; });
      await SK.call('sk_okada1987_build', [3, 0.9, 1987], []);  // warm-up on a small lattice
      await SK.call('sk_okada1987_object', [1, 1, 1.6, 0, 0, 32], []);
      built = '';
      await update();
    },
  });
})();
