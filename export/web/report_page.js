// The page logic of a build's report.html (a classic script, no build step; the C++ writer inlines it
// after viewer.bundle.js). It reads the data the writer embedded: #cg-report (the content of
// report.json), #cg-faces (the .glb's face table: primitive i -> body, name, kind, area; the kinds'
// colours; the blade's up direction) and #cg-model (the .glb, base64), renders the tables from the report and opens the model.
// Every report section is read generically, so a section the pipeline adds (e.g. "network") shows up
// without changes here.
//
// When the model is drawn the page writes its verdict into #cg-verdict (for a person and for a
// headless browser's --dump-dom): data-state "rendered" or "broken", data-faces (primitives loaded),
// data-pixels (pixels off the clear colour), data-hole-rows. The test hook report.html#pick=<face
// name> picks at a point of that face on screen and writes the face found there into data-pick.
(function () {
  'use strict';
  const $ = (id) => document.getElementById(id);
  const el = (tag, attrs, ...children) => {
    const e = document.createElement(tag);
    for (const [k, v] of Object.entries(attrs || {})) e.setAttribute(k, v);
    for (const c of children) e.append(c instanceof Node ? c : document.createTextNode(String(c)));
    return e;
  };
  const json = (id) => {
    const node = $(id);
    return node ? JSON.parse(node.textContent) : null;
  };

  function fmt(v) {
    if (v === null || v === undefined) return '';
    if (typeof v === 'number') {
      if (Number.isInteger(v)) return String(v);
      const a = Math.abs(v);
      return a !== 0 && (a < 1e-3 || a >= 1e6) ? v.toExponential(3) : String(Number(v.toPrecision(5)));
    }
    if (typeof v === 'boolean') return v ? 'yes' : 'no';
    if (Array.isArray(v)) return v.map(fmt).join(', ');
    if (typeof v === 'object') return JSON.stringify(v);
    return String(v);
  }
  const scalar = (v) => v === null || typeof v !== 'object' || (Array.isArray(v) && v.every((x) => typeof x !== 'object'));

  // A table of an array of objects: one column per key whose values are scalars (or lists of them).
  function table(rows, id) {
    const keys = [];
    for (const r of rows) for (const [k, v] of Object.entries(r)) if (scalar(v) && !keys.includes(k)) keys.push(k);
    const t = el('table', id ? { id } : {});
    t.append(el('thead', {}, el('tr', {}, ...keys.map((k) => el('th', {}, k.replace(/_/g, ' '))))));
    const body = el('tbody');
    for (const r of rows) {
      const tr = el('tr', {}, ...keys.map((k) => el('td', {}, fmt(r[k]))));
      if (r.passed === false || r.valid === false || r.volume_passed === false) tr.className = 'failed';
      body.append(tr);
    }
    t.append(body);
    return el('div', { class: 'scroll' }, t);
  }

  // Any JSON value as headings and tables: arrays of objects as tables, objects of scalars as
  // key/value tables, nested objects recursively.
  function generic(value, title, level, idPrefix) {
    const box = el('div', { class: 'block' });
    if (title) box.append(el(`h${Math.min(level, 4)}`, {}, title.replace(/_/g, ' ')));
    if (Array.isArray(value) && value.length && value.every((x) => x && typeof x === 'object' && !Array.isArray(x))) {
      box.append(table(value, idPrefix));
    } else if (value && typeof value === 'object' && !Array.isArray(value)) {
      const flat = Object.entries(value).filter(([, v]) => scalar(v));
      if (flat.length) box.append(table(flat.map(([k, v]) => ({ quantity: k, value: v }))));
      for (const [k, v] of Object.entries(value))
        if (!scalar(v)) box.append(generic(v, k, level + 1, idPrefix ? `${idPrefix}-${k}` : undefined));
    } else {
      box.append(el('p', {}, fmt(value)));
    }
    return box;
  }

  function section(id, title, ...content) {
    const s = el('section', { id }, el('h2', {}, title), ...content);
    $('cg-content').append(s);
    return s;
  }

  function renderReport(r) {
    const solid = r.solid || {};
    const failed = Object.entries(r.checks || {}).filter(([, c]) => !c.passed).map(([n]) => n);
    $('cg-summary').textContent = `${r.valid ? 'valid' : 'NOT valid'}; volume ${fmt(solid.volume_mm3)} mm³, ` +
      `area ${fmt(solid.surface_area_mm2)} mm², ${fmt(solid.face_count)} faces` +
      (failed.length ? `; failed checks: ${failed.join(', ')}` : '');
    $('cg-summary').className = r.valid ? 'ok' : 'bad';

    if (Array.isArray(r.sections) && r.sections.length) {
      const rows = [];
      for (const s of r.sections)
        for (const p of s.passages || [])
          rows.push({ span: s.span, passage: p.name, area_mm2: p.area_mm2, wetted_perimeter_mm: p.wetted_perimeter_mm,
                      hydraulic_diameter_mm: p.hydraulic_diameter_mm, loops: p.loops });
      $('cg-sections').append(el('h3', {}, 'Coolant passages along span'), table(rows, 'passages'));
    }
    section('checks', 'Checks', table(Object.entries(r.checks || {}).map(([name, c]) =>
      ({ check: name, passed: c.passed, message: c.message })), 'checks-table'));
    const cooling = (r.model && r.model.cooling) || {};
    const film = cooling.film;
    if (film && Array.isArray(film.holes)) {
      section('holes', `Film holes (${film.holes.length})`, table(film.holes, 'hole-table'),
              ...(film.rows && film.rows.length ? [el('h3', {}, 'Rows'), table(film.rows, 'row-table')] : []));
    }
    if (r.network) section('network', 'Coolant flow network', generic(r.network, '', 3, 'network'));
    if (r.bodies) section('bodies', 'Bodies', table(r.bodies.map((b) => ({ ...b, faces: undefined }))));
    if (r.timings_s) section('timings', 'Timings (s)', table(Object.entries(r.timings_s).map(([stage, s]) => ({ stage, seconds: s }))));
    return film && Array.isArray(film.holes) ? film.holes.length : 0;
  }

  function verdict(state, fields, text) {
    const v = $('cg-verdict');
    v.dataset.state = state;
    for (const [k, x] of Object.entries(fields)) v.dataset[k] = String(x);
    v.textContent = text;
    v.className = state === 'rendered' ? 'ok' : 'bad';
  }

  function controls(viewer, faces, kinds) {
    const box = $('cg-controls');
    const toggle = (label, colour, test) => {
      const input = el('input', { type: 'checkbox', checked: '' });
      input.addEventListener('change', () => viewer.setVisible(test, input.checked));
      const swatch = colour ? el('span', { class: 'swatch', style: `background:${colour}` }) : '';
      box.append(el('label', {}, input, swatch, label));
    };
    box.append(el('h3', {}, 'Bodies'));
    for (const b of [...new Set(faces.map((f) => f.body))]) toggle(b, '', (f) => f.body === b);
    box.append(el('h3', {}, 'Faces by kind'));
    for (const k of kinds) {
      const n = faces.filter((f) => f.kind === k.kind).length;
      toggle(`${k.kind} (${n})`, k.colour, (f) => f.kind === k.kind);
    }
  }

  function describe(face) {
    return face ? `${face.name} (kind ${face.kind}, body ${face.body}, area ${fmt(face.area_mm2)} mm²)` : 'nothing';
  }

  function hook(viewer, faces) {
    const m = /#pick=(.+)$/.exec(location.hash);
    if (!m) return;
    const name = decodeURIComponent(m[1]);
    const v = $('cg-verdict');
    v.dataset.pickExpected = name;
    const i = faces.findIndex((f) => f.name === name);
    const p = i < 0 ? null : viewer.facePoint(i);
    const j = p ? viewer.pick(p.x, p.y) : -1;
    v.dataset.pick = j < 0 ? '' : faces[j].name;
    $('cg-picked').textContent = `picked at ${p ? `(${p.x.toFixed(0)}, ${p.y.toFixed(0)})` : '-'}: ${describe(faces[j])}`;
  }

  function openModel(holeRows) {
    const data = json('cg-faces');
    const model = $('cg-model');
    if (!data || !model) {
      verdict('no-model', { holeRows }, 'no model in this report');
      return;
    }
    const canvas = $('cg-canvas');
    window.CoolingGenViewer.open(canvas, model.textContent.trim(), data.faces, data.up).then((viewer) => {
      const pixels = viewer.drawnPixels();
      verdict(pixels > 0 ? 'rendered' : 'broken', { faces: viewer.meshes.length, pixels, holeRows },
              `${pixels > 0 ? 'rendered' : 'broken: nothing drawn'}: ${viewer.meshes.length} faces, ${pixels} pixels drawn, ${holeRows} hole rows`);
      controls(viewer, data.faces, data.kinds);
      let down = null;
      canvas.addEventListener('pointerdown', (e) => { down = [e.offsetX, e.offsetY]; });
      canvas.addEventListener('pointerup', (e) => {
        if (!down || Math.hypot(e.offsetX - down[0], e.offsetY - down[1]) > 4) return;
        $('cg-picked').textContent = describe(data.faces[viewer.pick(e.offsetX, e.offsetY)]);
      });
      window.addEventListener('resize', () => { viewer.resize(); viewer.render(); });
      hook(viewer, data.faces);
    }).catch((e) => {
      verdict('broken', { faces: 0, pixels: 0, holeRows }, `broken: the model could not be shown (${e && e.message ? e.message : e})`);
    });
  }

  let holeRows = 0;
  try {
    holeRows = renderReport(json('cg-report'));
  } catch (e) {
    verdict('broken', { faces: 0, pixels: 0, holeRows: 0 }, `broken: the report data could not be read (${e.message})`);
    return;
  }
  openModel(holeRows);
})();
