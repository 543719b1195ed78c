const sheets = document.getElementById('sheets');
let DATA, STEPS, LAST, first, END, groups, items, cur = 0;
function setup() {
  // the step at which each entity (by its id) first shows; the results and notes show with the last step
  DATA = JSON.parse(document.getElementById('steps-data').textContent);
  STEPS = DATA.steps;
  LAST = STEPS.length - 1;
  first = {};
  STEPS.forEach((s, i) => s.ids.forEach(id => { if (!(id in first)) first[id] = i; }));
  END = new Set(DATA.end);
  END.forEach(id => { first[id] = LAST; });
  groups = Array.from(sheets.querySelectorAll('.sheet g[data-entity]'))
    .filter(g => first[g.getAttribute('data-entity')] !== undefined);
  items = Array.from(document.querySelectorAll('#steps li'));
  items.forEach((li, j) => { li.onclick = () => show(j); });
}
setup();
// drafting serve: a new drawing of the same scene put in place of this one, at the same step and zoom
// (the parts are the server's, built as this page was: the sheets' SVG, the step list and its data)
window.replaceDrawing = parts => {
  sheets.querySelectorAll('.sheet').forEach(s => s.remove());
  sheets.insertAdjacentHTML('beforeend', parts.sheets);
  document.getElementById('steps').innerHTML = parts.items;
  document.getElementById('steps-data').textContent = parts.data;
  const h = document.querySelector('#panel h3');
  h.innerHTML = parts.title;                             // escaped in Python
  document.title = h.textContent;
  setup();
  show(cur);
};
function show(i) {
  cur = Math.max(0, Math.min(LAST, i));
  for (const g of groups) {
    const id = g.getAttribute('data-entity'), k = first[id];
    g.classList.toggle('todo', k > cur);
    g.classList.toggle('current', k === cur && !END.has(id));       // in colour: what this step adds
  }
  items.forEach((li, j) => {
    li.hidden = j > cur;                               // a later step's words stay unread
    li.classList.toggle('current', j === cur);
    li.classList.toggle('done', j < cur);
    if (j === cur) li.setAttribute('aria-current', 'step'); else li.removeAttribute('aria-current');
  });
  document.getElementById('caption').innerHTML = (cur + 1) + '. ' + STEPS[cur].caption;   // escaped in Python
  document.getElementById('equation').innerHTML = STEPS[cur].equation || '';
  document.getElementById('count').textContent = (cur + 1) + ' / ' + STEPS.length;
  document.getElementById('prev').disabled = cur === 0;
  document.getElementById('next').disabled = cur === LAST;
  if (!location.hash.includes('selftest')) history.replaceState(null, '', '#step=' + (cur + 1));
}
function next() { show(cur + 1); }
function prev() { show(cur - 1); }

// zoom: 1 = the sheets fit the window's width; the point under the pointer (or the middle) stays put
let zoom = 1;
function setZoom(z, px, py) {
  z = Math.max(0.5, Math.min(8, z));
  const r = sheets.getBoundingClientRect();
  px = px === undefined ? r.width / 2 : px;
  py = py === undefined ? r.height / 2 : py;
  const fx = (sheets.scrollLeft + px) / zoom, fy = (sheets.scrollTop + py) / zoom;
  zoom = z;
  sheets.style.setProperty('--zoom', z);
  sheets.scrollLeft = fx * z - px;
  sheets.scrollTop = fy * z - py;
  document.getElementById('zoom-level').textContent = Math.round(z * 100) + ' %';
}
sheets.addEventListener('wheel', e => {
  if (!e.ctrlKey) return;
  e.preventDefault();
  const r = sheets.getBoundingClientRect();
  setZoom(zoom * Math.exp(-e.deltaY * 0.002), e.clientX - r.left, e.clientY - r.top);
}, { passive: false });
document.getElementById('zoom-in').onclick = () => setZoom(zoom * 1.25);
document.getElementById('zoom-out').onclick = () => setZoom(zoom / 1.25);
document.getElementById('zoom-fit').onclick = () => setZoom(1);

document.getElementById('next').onclick = next;
document.getElementById('prev').onclick = prev;
document.addEventListener('keydown', e => {
  if (e.target.closest && e.target.closest('input, select, textarea') || e.ctrlKey || e.altKey || e.metaKey) return;
  if (e.key === 'ArrowRight') next();
  else if (e.key === 'ArrowLeft') prev();
  else if (e.key === '+' || e.key === '=') { e.preventDefault(); setZoom(zoom * 1.25); }
  else if (e.key === '-') { e.preventDefault(); setZoom(zoom / 1.25); }
  else if (e.key === '0') { e.preventDefault(); setZoom(1); }
});
const m = location.hash.match(/step=(\d+)/);
show(m ? parseInt(m[1], 10) - 1 : 0);
if (location.hash.includes('selftest')) {
  const target = m ? parseInt(m[1], 10) - 1 : 0;
  next(); next(); prev();
  const lit = sheets.querySelectorAll('g.current').length;
  const hidden = sheets.querySelectorAll('g.todo').length;
  const ok = cur === Math.min(target + 1, LAST);
  document.title = 'selftest ' + (ok ? 'ok' : 'FAILED') + ' step=' + (cur + 1) + ' lit=' + lit + ' hidden=' + hidden;
}
