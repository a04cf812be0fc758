// ports/web/page/panels/okada1989.js — okada1989 (the pixel shift method): lattice Types I, II
// and III give the same D(P), with very different memory and time. The pixel shift itself is
// the okada1987 "forward / backward" panel. Wiring and drawing only (api_okada1989.cpp).
/* global SK */
'use strict';
(function () {
  SK.register({
    id: 'okada1989-types', paper: 'okada1989 — the pixel shift method', order: 60,
    title: 'Lattice Types I, II and III: the same values',
    cite: 'okada1989 §2-1 Type I (the whole lattice, O(2^3R) memory), §3-2 Type II (each queried node\'s ancestors kept in a list), §3-3 Type III (no table: every node recomputed from its coordinates, O(R) memory); D(P) by eq. (6) from each',
    source: 'lib/shitsukan/solid/lattice_store.cpp FractalLattice::build(), lattice_type2.cpp TypeIILattice::turbulence(), lattice_type3.cpp TypeIIILattice::turbulence()',
    figures: ['okada1989/table-types'],
    async open(body) {
      const box = SK.el('div', { class: 'sk-controls' }, body);
      const figs = SK.el('div', { class: 'sk-figs' }, body);
      const c = {
        R: SK.slider(box, { label: 'R (depth)', min: 1, max: 24, step: 1, value: 6, key: 'R' }),
        beta: SK.slider(box, { label: 'beta', min: 0, max: 2, step: 0.05, value: 0.9, key: 'beta' }),
        seed: SK.slider(box, { label: 'seed', min: 0, max: 9999, step: 1, value: 1987, key: 'seed' }),
        n: SK.slider(box, { label: 'points', min: 1, max: 20000, step: 1, value: 2000, key: 'n' }),
        pattern: SK.select(box, { label: 'points', value: 0, options: [[0, 'a raster row (coherent)'], [1, 'scattered (Pcg32)']] }),
      };
      const note = SK.el('p', { class: 'sk-note' }, box);
      note.textContent = 'Type I refuses R > 10 (and anything over its 512 MiB budget): watch its status; ' +
        'Types II and III go on to R = 20 and 24. With hash noise all three give the same float at every point.';
      const table = SK.el('table', { class: 'sk-table' }, figs);
      const values = SK.el('div', { class: 'sk-readout' }, figs);
      const plot = SK.figure(figs, 'D(P) at the points: Type I (blue), II (orange, dashed), III (red, dotted) — one curve when they agree', 512, 160);
      const update = SK.coalesce(async () => {
        const r = await SK.call('sk_okada1989_types', [c.R.value, c.beta.value, c.seed.value, c.n.value, c.pattern.value], ['floats', 'text']);
        const bad = /points/.test(r.message) ? c.n : /beta/.test(r.message) ? c.beta : c.R;
        [c.R, c.n, c.beta].forEach((x) => SK.clearReport(x));
        if (!SK.report(bad, r)) return;
        const t = JSON.parse(r.text);
        if (t.I_status !== 'ok') SK.report(c.R, { code: 1, codeName: 'Type I', message: t.I_status });
        const n = t.n, d = r.floats.data;
        const kb = (b) => b === undefined ? '—' : (b / 1024).toFixed(1) + ' KiB';
        const us = (ms) => ms === undefined ? '—' : ms * n < 0.2 ? '< ' + (200 / n).toFixed(2) + ' µs (under the browser\'s 0.1 ms timer step: add points)' : (ms * 1000).toPrecision(3) + ' µs';
        table.innerHTML = '<tr><th></th><th>memory held</th><th>time per point</th><th>status</th></tr>' +
          '<tr><th>Type I</th><td>' + kb(t.I_bytes) + '</td><td>' + us(t.I_ms_per_point) + ' (+ build ' + (t.I_build_ms === undefined ? '—' : t.I_build_ms.toFixed(1) + ' ms') + ')</td><td>' + t.I_status + '</td></tr>' +
          '<tr><th>Type II</th><td>' + kb(t.II_bytes) + ' payload, ' + kb(t.II_container_bytes) + ' as held (' + t.II_nodes + ' nodes)</td><td>' + us(t.II_ms_per_point) + '</td><td>' + t.II_status + '</td></tr>' +
          '<tr><th>Type III</th><td>' + kb(t.III_bytes) + ' object (' + kb(t.III_ancestry_bytes) + ' ancestry)</td><td>' + us(t.III_ms_per_point) + ' reusing the ancestry; ' + us(t.III_noreuse_ms_per_point) + ' from the top every time (okada1989\'s own)</td><td>' + t.III_status + '</td></tr>';
        values.textContent = t.agree + ' of ' + n + ' points give the same bits in every type that ran.\nfirst points:  I            II           III\n' +
          Array.from({ length: Math.min(6, n) }, (_, i) => '  ' + [d[i], d[n + i], d[2 * n + i]].map((v) => (isNaN(v) ? 'refused' : v.toFixed(7)).padStart(12)).join(' ')).join('\n') +
          '\n(time per point is measured live: it varies with the machine\'s load)';
        const g = plot.canvas.getContext('2d');
        g.fillStyle = '#fff'; g.fillRect(0, 0, 512, 160);
        let lo = Infinity, hi = -Infinity;
        for (const v of d) if (!isNaN(v)) { lo = Math.min(lo, v); hi = Math.max(hi, v); }
        const m = Math.min(n, 512), at = (i) => Math.floor((i * (n - 1)) / (m - 1 || 1));  // 512 samples over all n
        [['#1f5f99', 0, []], ['#f57900', n, [6, 4]], ['#cc0000', 2 * n, [2, 3]]].forEach(([col, off, dash]) => {
          g.strokeStyle = col; g.setLineDash(dash); g.beginPath();
          for (let i = 0; i < m; i++) {
            const v = d[off + at(i)];
            if (isNaN(v)) continue;
            const x = (i / (m - 1 || 1)) * 504 + 4, y = 156 - ((v - lo) / (hi - lo || 1)) * 152;
            i ? g.lineTo(x, y) : g.moveTo(x, y);
          }
          g.stroke();
        });
        g.setLineDash([]);
      });
      Object.values(c).forEach((x) => { x.onchange = update; });
      await SK.call('sk_okada1989_types', [3, 0.9, 1987, 16, 0], []);  // warm-up
      await update();
    },
  });
})();
