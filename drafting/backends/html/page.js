const STEPS = JSON.parse(document.getElementById('steps-data').textContent);
const first = {};
STEPS.forEach((s, i) => s.entities.forEach(e => { if (!(e in first)) first[e] = i; }));
const tagged = Array.from(document.querySelectorAll('[data-e]'));
let cur = 0;
function show(i) {
  cur = Math.max(0, Math.min(STEPS.length - 1, i));
  for (const el of tagged) {
    const k = first[el.getAttribute('data-e')];
    el.classList.toggle('todo', k !== undefined && k > cur);
    el.classList.toggle('current', k === cur);
  }
  document.querySelectorAll('#steps li').forEach((li, j) => {
    li.classList.toggle('current', j === cur);
    li.classList.toggle('done', j < cur);
  });
  document.getElementById('caption').innerHTML = (cur + 1) + '. ' + STEPS[cur].caption;   // escaped in Python
  document.getElementById('equation').innerHTML = STEPS[cur].equation || '';
  document.getElementById('count').textContent = (cur + 1) + ' / ' + STEPS.length;
  if (!location.hash.includes('selftest')) history.replaceState(null, '', '#step=' + (cur + 1));
}
function next() { show(cur + 1); }
function prev() { show(cur - 1); }
document.getElementById('next').onclick = next;
document.getElementById('prev').onclick = prev;
document.addEventListener('keydown', e => { if (e.key === 'ArrowRight') next(); if (e.key === 'ArrowLeft') prev(); });
document.querySelectorAll('#steps li').forEach((li, j) => li.onclick = () => show(j));
const m = location.hash.match(/step=(\d+)/);
show(m ? parseInt(m[1], 10) - 1 : 0);
if (location.hash.includes('selftest')) {
  const target = m ? parseInt(m[1], 10) - 1 : 0;
  next(); next(); prev();
  const lit = document.querySelectorAll('[data-e].current').length;
  const hidden = document.querySelectorAll('[data-e].todo').length;
  const ok = cur === Math.min(target + 1, STEPS.length - 1);
  document.title = 'selftest ' + (ok ? 'ok' : 'FAILED') + ' step=' + (cur + 1) + ' lit=' + lit + ' hidden=' + hidden;
}
