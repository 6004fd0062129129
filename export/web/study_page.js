// The page logic of a study's study_report.html (a classic script, no build step; the C++ writer
// inlines it). It reads #cg-study (study name, parameters, metrics, status counts and one row per
// variant: id, parameter values, status, refused field, error, metrics, link) and draws: the status
// counts, the refusals by field, one scatter plot per swept parameter and metric coloured by status
// (variants without the metric, e.g. refused ones, in a band below the axis, so their parameters show),
// and parallel coordinates over parameters and metrics. Every point links to its variant's
// report.html (when the study's outputs include html) or report.json. The verdict in #cg-verdict
// (data-state, data-variants, data-points, data-plots) is for a headless browser's --dump-dom.
(function () {
  'use strict';
  const $ = (id) => document.getElementById(id);
  const SVG = 'http://www.w3.org/2000/svg';
  const COLOURS = { built: '#1f77b4', refused: '#d62728', failed: '#ff7f0e', timeout: '#9467bd', pending: '#7f7f7f' };
  const el = (tag, attrs, ...children) => {
    const e = document.createElement(tag);
    for (const [k, v] of Object.entries(attrs || {})) e.setAttribute(k, v);
    for (const c of children) e.append(c instanceof Node ? c : document.createTextNode(String(c)));
    return e;
  };
  const svg = (tag, attrs, ...children) => {
    const e = document.createElementNS(SVG, tag);
    for (const [k, v] of Object.entries(attrs || {})) e.setAttribute(k, v);
    for (const c of children) e.append(c instanceof Node ? c : document.createTextNode(String(c)));
    return e;
  };
  const fmt = (v) => (typeof v === 'number' ? String(Number(v.toPrecision(4))) : v === null || v === undefined ? '' : String(v));

  function table(head, rows, id) {
    const t = el('table', id ? { id } : {});
    t.append(el('thead', {}, el('tr', {}, ...head.map((h) => el('th', {}, h)))));
    const b = el('tbody');
    for (const r of rows) b.append(el('tr', {}, ...r.map((c) => el('td', {}, c))));
    t.append(b);
    return el('div', { class: 'scroll' }, t);
  }

  // A numeric axis of the values of one column (strings: their distinct values, in order of appearance).
  function axis(values) {
    const nums = values.filter((v) => typeof v === 'number');
    if (nums.length === values.filter((v) => v !== null && v !== undefined).length && nums.length) {
      let lo = Math.min(...nums), hi = Math.max(...nums);
      if (lo === hi) { lo -= 0.5 * Math.abs(lo || 1); hi += 0.5 * Math.abs(hi || 1); }
      return { at: (v) => (typeof v === 'number' ? (v - lo) / (hi - lo) : null), ticks: [[0, fmt(lo)], [1, fmt(hi)]] };
    }
    const names = [...new Set(values.filter((v) => v !== null && v !== undefined).map(String))];
    const at = (v) => (v === null || v === undefined ? null : names.length > 1 ? names.indexOf(String(v)) / (names.length - 1) : 0.5);
    return { at, ticks: names.map((n) => [at(n), n]) };
  }

  function point(row, x, y, title) {
    const a = svg('a', { href: row.link || '#', target: '_blank' });
    const c = svg('circle', { cx: x.toFixed(1), cy: y.toFixed(1), r: 4, fill: COLOURS[row.status] || '#000', 'fill-opacity': 0.8,
                              'data-id': row.id, class: 'point' }, svg('title', {}, title));
    a.append(c);
    return a;
  }

  let points = 0;
  function scatter(rows, xName, xs, yName, ys) {
    const W = 260, H = 200, L = 48, R = 10, T = 10, B = 46, band = 14;
    const ax = axis(xs), ay = axis(ys);
    const s = svg('svg', { width: W, height: H, viewBox: `0 0 ${W} ${H}`, class: 'scatter' });
    const px = (u) => L + u * (W - L - R), py = (v) => H - B - v * (H - B - T);
    s.append(svg('rect', { x: L, y: T, width: W - L - R, height: H - B - T, fill: 'none', stroke: '#99a' }));
    for (const [u, label] of ax.ticks) s.append(svg('text', { x: px(u), y: H - B + band + 14, 'font-size': 10, 'text-anchor': 'middle' }, label));
    for (const [v, label] of ay.ticks) s.append(svg('text', { x: L - 4, y: py(v) + 3, 'font-size': 10, 'text-anchor': 'end' }, label));
    s.append(svg('text', { x: (L + W - R) / 2, y: H - 4, 'font-size': 11, 'text-anchor': 'middle' }, xName));
    s.append(svg('text', { x: 11, y: (T + H - B) / 2, 'font-size': 11, 'text-anchor': 'middle',
                           transform: `rotate(-90 11 ${(T + H - B) / 2})` }, yName));
    rows.forEach((r, i) => {
      const u = ax.at(xs[i]);
      if (u === null) return;
      const v = ay.at(ys[i]);
      const y = v === null ? H - B + band / 2 + 2 : py(v);  // no value: the band below the axis
      s.append(point(r, px(u), y, `${r.id} (${r.status}): ${xName} ${fmt(xs[i])}, ${yName} ${v === null ? 'none' : fmt(ys[i])}${r.error ? ` - ${r.error}` : ''}`));
      ++points;
    });
    return el('div', { class: 'plot' }, s);
  }

  function parallel(rows, columns) {
    const W = Math.max(420, 130 * columns.length), H = 300, T = 20, B = 40, L = 60, R = 60;
    const s = svg('svg', { width: W, height: H, viewBox: `0 0 ${W} ${H}`, id: 'parallel' });
    const xs = (k) => L + (columns.length > 1 ? (k * (W - L - R)) / (columns.length - 1) : 0);
    const axes = columns.map((c) => axis(c.values));
    const py = (v) => H - B - v * (H - B - T);
    columns.forEach((c, k) => {
      s.append(svg('line', { x1: xs(k), x2: xs(k), y1: T, y2: H - B, stroke: '#99a' }));
      s.append(svg('text', { x: xs(k), y: H - 8, 'font-size': 11, 'text-anchor': 'middle' }, c.name));
      for (const [v, label] of axes[k].ticks) s.append(svg('text', { x: xs(k) + 4, y: py(v) + 3, 'font-size': 9 }, label));
    });
    rows.forEach((r, i) => {
      const pts = columns.map((c, k) => [xs(k), axes[k].at(c.values[i])]).filter(([, v]) => v !== null);
      if (pts.length < 2) return;
      const a = svg('a', { href: r.link || '#', target: '_blank' });
      a.append(svg('polyline', { points: pts.map(([x, v]) => `${x.toFixed(1)},${py(v).toFixed(1)}`).join(' '), fill: 'none',
                                 stroke: COLOURS[r.status] || '#000', 'stroke-opacity': 0.7, 'stroke-width': 1.5 },
                   svg('title', {}, `${r.id} (${r.status})`)));
      s.append(a);
    });
    return el('div', { class: 'scroll' }, s);
  }

  function render(d) {
    $('cg-summary').textContent = `${d.rows.length} variants; parameters: ${d.parameters.join(', ')}`;
    const content = $('cg-content');
    content.append(el('h2', {}, 'Status'), table(['status', 'variants'], Object.entries(d.status_counts).map(([s, n]) => [
      el('span', {}, el('span', { class: 'swatch', style: `background:${COLOURS[s] || '#000'}` }), s), n]), 'status-table'));
    const refused = {};
    for (const r of d.rows) if (r.status === 'refused') (refused[r.refused_field] = refused[r.refused_field] || []).push(r);
    if (Object.keys(refused).length) {
      content.append(el('h2', {}, 'Refusals by field'), table(['field', 'variants', 'ids', 'first message'],
        Object.entries(refused).map(([f, rs]) => [f, rs.length, rs.map((r) => r.id).join(', '), rs[0].error]), 'refusal-table'));
    }
    const metrics = d.metrics.filter((m) => d.rows.some((r) => typeof r.metrics[m] === 'number'));
    const plots = el('div', { id: 'plots' });
    let count = 0;
    d.parameters.forEach((p, k) => {
      for (const m of metrics) {
        plots.append(scatter(d.rows, p, d.rows.map((r) => r.values[k]), m, d.rows.map((r) => r.metrics[m])));
        ++count;
      }
    });
    content.append(el('h2', {}, 'Each parameter against each metric'),
                   el('p', {}, 'Colour: status. Variants without the metric (refused, failed) sit in the band below the axis. Click a point for its variant\'s report.'),
                   plots);
    const columns = d.parameters.map((p, k) => ({ name: p, values: d.rows.map((r) => r.values[k]) }))
      .concat(metrics.map((m) => ({ name: m, values: d.rows.map((r) => r.metrics[m]) })));
    content.append(el('h2', {}, 'Parallel coordinates'), parallel(d.rows, columns));
    content.append(el('h2', {}, 'Variants'), table(['id', ...d.parameters, 'status', ...metrics, 'error'], d.rows.map((r) => [
      el('a', { href: r.link || '#' }, r.id), ...r.values.map(fmt), r.status, ...metrics.map((m) => fmt(r.metrics[m])), r.error || '']),
      'variant-table'));
    return count;
  }

  const v = $('cg-verdict');
  try {
    const d = JSON.parse($('cg-study').textContent);
    const plots = render(d);
    v.dataset.state = 'rendered';
    v.dataset.variants = String(d.rows.length);
    v.dataset.points = String(points);
    v.dataset.plots = String(plots);
    v.textContent = `rendered: ${d.rows.length} variants, ${plots} plots, ${points} points`;
    v.className = 'ok';
  } catch (e) {
    v.dataset.state = 'broken';
    v.textContent = `broken: ${e.message}`;
    v.className = 'bad';
  }
})();
