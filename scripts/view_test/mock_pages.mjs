// Small pages that follow the viewer's page contract (see check_views.mjs), drawn on a 2-D
// canvas instead of plotly, for `check_views.mjs --self-test`: the good ones must pass, and
// each broken one must fail, so the checks are shown to catch what they claim to catch.
import fs from 'node:fs';
import path from 'node:path';

const CONTROLS = '<input type="range" id="tp-time" step="any"><button id="tp-play">play</button>'
  + '<span id="tp-clock"></span><input type="range" id="tp-exaggeration" min="1" max="10" value="1">';

/**
 * A page whose #tp-plot canvas shows a shaded "sea floor" and a vehicle that moves with time.
 * Options change one thing each: `t1` (end time), `draw` (false: nothing drawn), `fill` (one
 * colour), `move` (false: the vehicle stays), `after` (script run after the render signal),
 * `before` (script run while building), `signal` (false: never "rendered"), `timeHandled`
 * (false: the slider's input is ignored), `view` (false: no window.tidepathView), `disable`
 * (true: play and exaggeration disabled, and time too for a single instant), `extraHtml`.
 */
function page(o = {}) {
  const opt = { t1: 600, draw: true, fill: null, move: true, after: '', before: '', signal: true,
    timeHandled: true, view: true, disable: false, extraHtml: '', ...o };
  return `<!doctype html><html><head><meta charset="utf-8"><title>mock view</title>
<style>body{margin:0}#tp-plot{display:block;width:1280px;height:680px}</style></head><body>
<canvas id="tp-plot" width="1280" height="680"></canvas>${CONTROLS}${opt.extraHtml}
<script>
const root = document.documentElement;
const t0 = 0, t1 = ${opt.t1};
const cv = document.getElementById('tp-plot');
const ctx = cv.getContext('2d');
function draw(t) {
  ctx.fillStyle = ${JSON.stringify(opt.fill ?? '#ffffff')};
  ctx.fillRect(0, 0, cv.width, cv.height);
  if (!${opt.draw} || ${JSON.stringify(opt.fill)} !== null) return;
  const g = ctx.createLinearGradient(0, 0, cv.width, cv.height);
  g.addColorStop(0, '#08306b'); g.addColorStop(0.5, '#41b6c4'); g.addColorStop(1, '#ffffcc');
  ctx.fillStyle = g;
  ctx.fillRect(100, 100, 1000, 480);
  const f = ${opt.move} && t1 > t0 ? (t - t0) / (t1 - t0) : 0;
  ctx.fillStyle = '#ff7f0e';
  ctx.beginPath(); ctx.arc(200 + 800 * f, 340, 20, 0, 2 * Math.PI); ctx.fill();
}
async function setTime(t) {
  document.getElementById('tp-clock').textContent = t.toFixed(0) + ' s';
  draw(t);
  await new Promise((r) => requestAnimationFrame(r));
  root.dataset.tidepathTime = String(t);
}
try {
  ${opt.before}
  const slider = document.getElementById('tp-time');
  slider.min = t0; slider.max = t1; slider.value = t0;
  if (${opt.timeHandled}) slider.addEventListener('input', () => setTime(Number(slider.value)));
  let timer = null;
  document.getElementById('tp-play').addEventListener('click', () => {
    if (timer) { clearInterval(timer); timer = null; return; }
    timer = setInterval(() => { const t = Number(slider.value) + 10; slider.value = t > t1 ? t0 : t; setTime(Number(slider.value)); }, 100);
  });
  draw(t0);
  if (${opt.disable}) { slider.disabled = !(t1 > t0); document.getElementById('tp-play').disabled = true; document.getElementById('tp-exaggeration').disabled = true; }
  if (${opt.view}) window.tidepathView = { timeRange: [t0, t1], renderMs: performance.now(), setTime };
  if (${opt.signal}) root.dataset.tidepathState = 'rendered';
  ${opt.after}
} catch (e) {
  root.dataset.tidepathState = 'error';
  root.dataset.tidepathError = String(e.message);
}
</script></body></html>
`;
}

const GOOD = {
  'good': {},
  'good-single-instant': { t1: 0, disable: true },
};

const BAD = {
  'bad-blank': { draw: false },
  'bad-one-colour': { fill: '#1f77b4' },
  'bad-nothing-moves': { move: false },
  'bad-uncaught-exception': { after: 'setTimeout(() => undefinedFunction(), 0);' },
  'bad-exception-on-play': { after: "document.getElementById('tp-play').addEventListener('click', () => { null.x; });" },
  'bad-console-error': { after: "console.error('boom');" },
  'bad-fetch': { after: "fetch('http://example.com/tiles.json').catch(() => {});" },
  'bad-image-from-network': { extraHtml: '<img src="https://cdn.plot.ly/logo.png">' },
  'bad-sibling-file': { extraHtml: '<script src="plotly.min.js"></script>' },
  'bad-build-error': { before: "throw new Error('scene has no bathymetry');" },
  'bad-no-render-signal': { signal: false },
  'bad-slider-ignored': { timeHandled: false },
  'bad-no-view-object': { view: false },
  'bad-play-disabled': { disable: true },
};

/** Writes the pages into `dir`; returns their paths as {good: [...], bad: [...]}. */
export function writeMockPages(dir) {
  const write = (set) => Object.entries(set).map(([name, o]) => {
    const file = path.join(dir, `${name}.html`);
    fs.writeFileSync(file, page(o));
    return file;
  });
  return { good: write(GOOD), bad: write(BAD) };
}
