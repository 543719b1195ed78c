// drafting serve: the scene's text beside its sheets, redrawn 150 ms after the last keystroke and on
// every save of the file on disk (server-sent events) -- in place in the shown page when it can; an error at the line it names, the last good
// sheets kept; saves checked against the version the text was loaded from (409: changed meanwhile).
'use strict';
const DATA = JSON.parse(document.getElementById('serve-data').textContent);
const $ = id => document.getElementById(id);
const text = $('text'), gutter = $('gutter'), view = $('view'), status = $('status');
const DEBOUNCE = 150;
const state = { name: null, version: null, saved: '', seq: 0, shown: 0, timer: null, error: null,
                drawn: 0, id: null, ms: null, server: null, page: null };
window.serveState = state;              // read by the tests and the benchmark

function api(url, body) {
  const opts = body === undefined ? {} : { method: 'POST', headers: { 'Content-Type': 'application/json' },
                                           body: JSON.stringify(body) };
  return fetch(url, opts).then(r => r.json().then(j => ({ status: r.status, body: j })));
}
function dirty() { return text.value !== state.saved; }
function setStatus(s) { status.textContent = s; status.classList.toggle('dirty', dirty()); }
function notice(message, buttons) {
  const n = $('notice');
  n.textContent = message;
  for (const [label, act] of buttons || []) {
    const b = document.createElement('button');
    b.textContent = label;
    b.onclick = () => { n.hidden = true; act(); };
    n.appendChild(b);
  }
  n.hidden = !message;
}

function lineHeight() { return parseFloat(getComputedStyle($('editor')).getPropertyValue('--line')) || 18; }
function gutterLines() {
  const n = text.value.split('\n').length;
  let out = '';
  for (let i = 1; i <= n; i++) out += (state.error && state.error.line === i ? '<span class="bad">' + i + '</span>' : i) + '\n';
  gutter.innerHTML = out;
  gutter.scrollTop = text.scrollTop;
}
function placeError() {
  const box = $('error'), mark = $('mark'), e = state.error;
  if (!e) { box.hidden = true; mark.hidden = true; return; }
  const h = lineHeight(), top = 6 + ((e.line || 1) - 1) * h - text.scrollTop;
  mark.hidden = !e.line;
  mark.style.top = top + 'px';
  box.hidden = false;
  box.style.top = Math.max(0, Math.min(top + h + 2, text.clientHeight - box.offsetHeight)) + 'px';
}
function showError(e) {
  state.error = e;
  const box = $('error');
  box.textContent = '';
  if (e) {
    const where = document.createElement('span');
    where.className = 'where';
    where.textContent = [e.line ? 'line ' + e.line : '', e.key].filter(Boolean).join(' \u00b7 ');
    if (where.textContent) { box.appendChild(where); box.appendChild(document.createTextNode(': ')); }
    box.appendChild(document.createTextNode(e.error));
  }
  gutterLines();
  placeError();
}

function currentStep() {
  // the step the reader is at in the shown page; at the last step (or none yet): the last step again
  try {
    const count = view.contentDocument.getElementById('count').textContent.split('/').map(s => parseInt(s, 10));
    return count[0] < count[1] ? count[0] : 9999;
  } catch (err) { return 9999; }
}

function draw() {
  clearTimeout(state.timer);
  const seq = ++state.seq, name = state.name, t0 = performance.now();
  return api('/api/draw', { name: name, text: text.value }).then(r => {
    if (seq < state.shown || name !== state.name) return;      // a later edit is already shown
    state.shown = seq;
    const b = r.body;
    if (r.status !== 200 || !b.ok) { showError({ error: b.error, key: b.key || '', line: b.line || null }); return; }
    showError(null);
    const done = () => { state.drawn = seq; state.id = b.id; state.ms = performance.now() - t0; state.server = b.ms; };
    const win = view.contentWindow;
    if (b.parts && state.page === name && win && win.replaceDrawing) {
      // the shown page takes the new drawing in place (same step, same zoom): no page to load
      const t1 = performance.now();
      win.replaceDrawing(b.parts);
      state.reply = t1 - t0; state.swap = performance.now() - t1;     // (for the benchmark's split)
      requestAnimationFrame(() => { const c = new MessageChannel(); c.port1.onmessage = done; c.port2.postMessage(0); });
      // (done: the task after the next frame's rendering -- once the new sheet is painted)
    } else {
      const step = currentStep();
      state.page = b.parts ? name : null;
      view.onload = done;
      view.src = '/view/' + b.id + '#step=' + step;
    }
    results(b);
  });
}
function schedule() {
  clearTimeout(state.timer);
  state.timer = setTimeout(draw, DEBOUNCE);
}

function results(b) {
  const stem = state.name.replace(/\.toml$/, ''), d = $('downloads');
  d.textContent = 'Download: ';
  const link = (file, label) => {
    const a = document.createElement('a');
    a.href = '/download/' + b.id + '/' + file; a.download = file; a.textContent = label;
    d.appendChild(a);
  };
  for (const f of ['svg', 'png']) {
    if (b.sheets === 1) link(stem + '.' + f, f.toUpperCase());
    else for (let k = 1; k <= b.sheets; k++) link(stem + '-' + k + '.' + f, f.toUpperCase() + ' ' + k);
  }
  link(stem + '.pdf', 'PDF');
  const w = $('warnings');
  w.textContent = '';
  for (const s of b.warnings) { const li = document.createElement('li'); li.textContent = s; w.appendChild(li); }
  const t = $('results');
  t.textContent = '';
  if (b.results.length) {
    const head = t.insertRow();
    for (const s of ['quantity', 'graphical', 'analytic', 'difference']) { const th = document.createElement('th'); th.textContent = s; head.appendChild(th); }
    for (const row of b.results) { const tr = t.insertRow(); for (const s of row) tr.insertCell().textContent = s; }
  }
}

function load(name) {
  return api('/api/scene?name=' + encodeURIComponent(name)).then(r => {
    if (r.status !== 200) { notice(r.body.error); return; }
    state.name = r.body.name; state.version = r.body.version; state.saved = r.body.text;
    text.value = r.body.text;
    $('name').textContent = r.body.name;
    document.title = r.body.name + ' - drafting serve';
    $('scenes').value = r.body.name;
    notice('');
    setStatus('');
    gutterLines();
    return draw();
  });
}

function save(over) {
  const body = { name: state.name, text: text.value, version: over || state.version };
  return api('/api/save', body).then(r => {
    if (r.status === 200) {
      state.version = r.body.version; state.saved = body.text;
      notice('');
      setStatus('saved (the previous version kept as ' + state.name + '~)');
    } else if (r.status === 409) {
      notice(r.body.error, [['Load that version', () => load(state.name)], ['Save mine over it', () => save(r.body.version)]]);
    } else notice(r.body.error || 'not saved');
  });
}

function listScenes(names) {
  const sel = $('scenes');
  sel.textContent = '';
  for (const n of names) { const o = document.createElement('option'); o.value = n; o.textContent = n; sel.appendChild(o); }
  if (state.name) sel.value = state.name;
}

function watch() {
  const events = new EventSource('/api/events');
  events.addEventListener('changed', ev => {
    const c = JSON.parse(ev.data);
    if (DATA.folder) api('/api/scenes').then(r => { if (r.status === 200) listScenes(r.body.scenes); });
    if (c.name !== state.name || c.version === state.version) return;
    if (!dirty()) { load(c.name).then(() => setStatus('reloaded: saved elsewhere')); return; }
    notice(c.name + ' was saved elsewhere (another tab or an editor) while you have unsaved edits here.',
           [['Load that version', () => load(c.name)], ['Keep mine', () => {}]]);
  });
}

text.addEventListener('input', () => { setStatus(dirty() ? 'unsaved' : ''); gutterLines(); schedule(); });
text.addEventListener('scroll', () => { gutter.scrollTop = text.scrollTop; placeError(); });
text.addEventListener('keydown', e => {
  if ((e.ctrlKey || e.metaKey) && e.key === 's') { e.preventDefault(); save(); }
});
$('save').onclick = () => save();
$('scenes').onchange = e => {
  if (dirty() && !confirm(state.name + ' has unsaved edits; open ' + e.target.value + ' without them?')) { e.target.value = state.name; return; }
  load(e.target.value);
};
window.addEventListener('beforeunload', e => { if (dirty()) e.preventDefault(); });
listScenes(DATA.scenes);
if (DATA.scenes.length) load(DATA.scenes[0]); else notice('This folder holds no scene (*.toml).');
watch();
