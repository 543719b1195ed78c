(function () {
const D = JSON.parse(document.getElementById('sweep-data').textContent);
const $ = id => document.getElementById(id);
const card = $('sweep'), slider = $('sweep-slider'), play = $('sweep-play');
const f = v => (Math.round(v * 1000) / 1000).toString();
function P(name, i) {
  const p = D.pts[name][i];
  return p ? [D.ox + D.k * p[0], D.oy - D.k * p[1]] : null;
}
let cur = 0, timer = null;
function show(i) {
  cur = ((i % D.count) + D.count) % D.count;
  if (+slider.value !== cur) slider.value = cur;
  for (const l of D.links) {
    const el = $(l.id), ps = l.pts.map(n => P(n, cur)), on = ps.every(p => p);
    el.style.visibility = on ? '' : 'hidden';
    if (!on) continue;
    if (el.tagName === 'line') {
      el.setAttribute('x1', f(ps[0][0])); el.setAttribute('y1', f(ps[0][1]));
      el.setAttribute('x2', f(ps[1][0])); el.setAttribute('y2', f(ps[1][1]));
    } else el.setAttribute('points', ps.map(p => f(p[0]) + ',' + f(p[1])).join(' '));
  }
  for (const b of D.blocks) {
    const el = $(b.id), c = P(b.at, cur), a = b.dir[cur];
    el.style.visibility = (c && a !== null) ? '' : 'hidden';
    if (!c || a === null) continue;
    const u = [Math.cos(a), -Math.sin(a)], n = [-u[1], u[0]], pts = [];
    for (const [su, sn] of [[1, 1], [-1, 1], [-1, -1], [1, -1]])
      pts.push(f(c[0] + su * u[0] * b.l / 2 + sn * n[0] * b.h / 2) + ',' + f(c[1] + su * u[1] * b.l / 2 + sn * n[1] * b.h / 2));
    el.setAttribute('points', pts.join(' '));
  }
  for (const q of D.pins) {
    const el = $(q.id), c = P(q.at, cur);
    el.style.visibility = c ? '' : 'hidden';
    if (c) { el.setAttribute('cx', f(c[0])); el.setAttribute('cy', f(c[1])); }
  }
  for (const q of D.labels) {
    const el = $(q.id), c = P(q.at, cur);
    el.style.visibility = c ? '' : 'hidden';
    if (c) { el.setAttribute('x', f(c[0] + q.off[cur][0])); el.setAttribute('y', f(c[1] + q.off[cur][1])); }
  }
  for (const t of D.traces) {
    const pts = [];
    for (let j = t.from; j < t.to && j <= cur; j++) { const c = P(t.at, j); pts.push(f(c[0]) + ',' + f(c[1])); }
    $(t.id).setAttribute('points', pts.length > 1 ? pts.join(' ') : '');
  }
  for (const c of D.charts) {
    const el = $(c.id), x = c.x[cur];
    el.setAttribute('x1', f(x)); el.setAttribute('x2', f(x));
    for (const d of c.dots) {
      const dot = $(d.id), y = d.y[cur];
      dot.style.visibility = y === null ? 'hidden' : '';
      if (y !== null) { dot.setAttribute('cx', f(x)); dot.setAttribute('cy', f(y)); }
    }
  }
  D.readout[cur].forEach((v, j) => { $('sweep-v' + j).textContent = v; });
  $('sweep-angle').textContent = D.angle[cur];
  card.classList.toggle('gap', !D.ok[cur]);
  card.classList.toggle('event', D.ok[cur] && D.status[cur] !== '');
  $('sweep-status').textContent = D.status[cur];
}
slider.addEventListener('input', () => show(+slider.value));
slider.addEventListener('keydown', e => e.stopPropagation());   // the arrow keys move the crank, not the steps
function pause() { clearInterval(timer); timer = null; play.textContent = '\u25b6 play'; }
play.onclick = () => {
  if (timer) { pause(); return; }
  timer = setInterval(() => show(cur + 1), 40);
  play.textContent = '\u275a\u275a pause';
};
document.querySelectorAll('#sweep-events button').forEach(b => b.onclick = () => { pause(); show(+b.dataset.i); });
const hash = location.hash;
const m = hash.match(/angle=(-?[0-9.]+)/);
let start = 0;
if (m) {
  const want = parseFloat(m[1]);
  let best = Infinity;
  D.value.forEach((v, i) => {
    const d = Math.abs(((v - want) % D.turn + 1.5 * D.turn) % D.turn - D.turn / 2);
    if (d < best) { best = d; start = i; }
  });
}
show(start);
if (hash.includes('selftest-sweep')) window.addEventListener('load', () => {
  const problems = [];
  // an arrow key on the slider moves the crank, never the construction's steps
  const steps = document.getElementById('count'), before_steps = steps ? steps.textContent : '';
  slider.dispatchEvent(new KeyboardEvent('keydown', {key: 'ArrowRight', bubbles: true}));
  if (steps && steps.textContent !== before_steps) problems.push('keys');
  // at a gap only the crank stands, greyed, with the note
  const gap = D.ok.indexOf(false);
  let gaps = 'none';
  if (gap >= 0) {
    show(gap);
    const drawn = D.links.filter(l => $(l.id).style.visibility !== 'hidden').map(l => l.pts.join(''));
    gaps = card.classList.contains('gap') && $('sweep-status').textContent.includes('cannot be assembled')
      && D.links.every(l => ($(l.id).style.visibility === 'hidden') === l.pts.some(n => !D.pts[n][gap]))
      ? 'ok:' + drawn.join('+') : 'FAILED';
    if (gaps === 'FAILED') problems.push('gap');
    show(start);
  }
  // play turns the crank on, pause stops it
  play.click();
  const playing = timer !== null && play.textContent.includes('pause');
  play.click();
  if (!playing || timer !== null || !play.textContent.includes('play')) problems.push('play');
  show(start);
  const before = D.readout[cur].join('|'), shown0 = $('sweep-v0').textContent;
  const target = (cur + Math.round(D.count / 4)) % D.count;
  slider.value = target;
  slider.dispatchEvent(new Event('input'));
  const where = [];
  for (const q of D.pins) {
    const el = $(q.id), c = P(q.at, target);
    if (!c) continue;
    const x = +el.getAttribute('cx'), y = +el.getAttribute('cy');
    if (Math.abs(x - c[0]) > 1e-3 || Math.abs(y - c[1]) > 1e-3) problems.push(q.at);
    where.push(q.at + '=' + el.getAttribute('cx') + ',' + el.getAttribute('cy'));
  }
  const cx = D.charts.length ? +$(D.charts[0].id).getAttribute('x1') : null;
  if (D.charts.length && Math.abs(cx - D.charts[0].x[target]) > 1e-3) problems.push('cursor');
  if (D.readout[cur].join('|') === before || $('sweep-v0').textContent === shown0) problems.push('readout');
  if (cur !== target || +slider.value !== target) problems.push('slider');
  document.title = 'selftest-sweep ' + (problems.length ? 'FAILED ' + problems.join(',') : 'ok') + ' i=' + cur
    + ' gaps=' + gaps + ' ' + where.join(' ') + ' cursor=' + cx + ' readout=' + $('sweep-v0').textContent;
});
})();
