// Opens tidepath's 3-D viewer pages (`tidepath view ... -o view.html`, `--view view.html`) in
// headless Chromium with software WebGL (SwiftShader) and checks, for each page:
//   - it makes no request other than for the file itself (data:, blob:, about: allowed);
//   - no console error and no uncaught exception, from loading to the end of the checks;
//   - it signals `document.documentElement.dataset.tidepathState = "rendered"` within the
//     timeout (a page that signals "error" fails with its `tidepathError`);
//   - a screenshot of #tp-plot at the start time is not blank;
//   - moving the time slider #tp-time halfway and to its end is handled (the page sets
//     `dataset.tidepathTime` to the slider's value, to within 1e-9 relative); the screenshots
//     then are not blank and, when the time range is not a single instant, differ from the
//     first (the vehicles moved). Screenshots: SHOTS/<stem>-start.png, -mid.png, -end.png;
//   - the play button and the vertical exaggeration slider raise no error.
//
//   node scripts/view_test/check_views.mjs [--shots DIR] [--timeout SECONDS] VIEW.html ...
//   node scripts/view_test/check_views.mjs --self-test   # the checks fail on broken pages
//
// Prints one line per page; exits 1 when any page fails, 2 on bad usage. Environment:
// TIDEPATH_CHROMIUM (browser binary, default /usr/bin/chromium), VIEW_TEST_VERBOSE=1 (print
// each self-test page's verdict, not only the summary).
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { pathToFileURL } from 'node:url';
import { chromium } from 'playwright-core';
import { PNG } from 'pngjs';

const CHROMIUM = process.env.TIDEPATH_CHROMIUM || '/usr/bin/chromium';
// Software WebGL: ANGLE on SwiftShader (Vulkan). Verified on Debian's chromium 156, where
// WebGL 1 and 2 contexts are created and plotly's gl3d scenes draw.
const CHROMIUM_ARGS = [
  '--headless=new', '--no-sandbox', '--disable-gpu', '--use-angle=swiftshader',
  '--enable-unsafe-swiftshader', '--disable-quic', '--no-first-run',
  '--disable-background-networking', '--disable-component-update', '--disable-sync',
];
const VIEWPORT = { width: 1280, height: 800 };
// A screenshot is blank unless more than MIN_CONTENT_FRACTION of its pixels differ from its
// most common colour and it holds more than MIN_COLOURS distinct colours (a shaded surface
// has thousands; an empty page or a filled box has one or two).
const MIN_CONTENT_FRACTION = 0.03;
const MIN_COLOURS = 20;
const PLAY_MS = 1500; // how long the play button runs

class CheckError extends Error {}

function usage(msg) {
  if (msg) console.error(`check_views: ${msg}`);
  console.error('usage: node check_views.mjs [--shots DIR] [--timeout SECONDS] VIEW.html ...\n'
    + '       node check_views.mjs --self-test');
  process.exit(2);
}

function parseArgs(argv) {
  const opts = { shots: 'target/view-test/shots', timeoutMs: 60_000, files: [], selfTest: false };
  for (let i = 0; i < argv.length; i++) {
    const a = argv[i];
    if (a === '--shots') opts.shots = argv[++i] ?? usage('--shots needs a folder');
    else if (a === '--timeout') {
      const s = Number(argv[++i]);
      if (!(s > 0)) usage('--timeout needs a positive number of seconds');
      opts.timeoutMs = s * 1000;
    } else if (a === '--self-test') opts.selfTest = true;
    else if (a.startsWith('-')) usage(`unknown option ${a}`);
    else opts.files.push(a);
  }
  if (!opts.selfTest && opts.files.length === 0) usage('no HTML file given');
  return opts;
}

/** Share of pixels unlike the most common colour, and the number of distinct colours. */
export function pixelStats(png) {
  const counts = new Map();
  const d = png.data;
  for (let i = 0; i < d.length; i += 4) {
    const key = ((d[i] << 24) | (d[i + 1] << 16) | (d[i + 2] << 8) | d[i + 3]) >>> 0;
    counts.set(key, (counts.get(key) ?? 0) + 1);
  }
  let mode = 0;
  for (const n of counts.values()) mode = Math.max(mode, n);
  const pixels = d.length / 4;
  return { contentFraction: pixels ? (pixels - mode) / pixels : 0, colours: counts.size };
}

function checkNotBlank(buf, label) {
  const st = pixelStats(PNG.sync.read(buf));
  if (st.contentFraction <= MIN_CONTENT_FRACTION || st.colours <= MIN_COLOURS) {
    throw new CheckError(`${label} screenshot is blank: ${(100 * st.contentFraction).toFixed(2)}% of `
      + `pixels differ from the most common colour (need > ${100 * MIN_CONTENT_FRACTION}%), `
      + `${st.colours} colours (need > ${MIN_COLOURS})`);
  }
  return st;
}

/** Number of pixels that differ between two screenshots of the same size. */
function changedPixels(a, b) {
  const pa = PNG.sync.read(a);
  const pb = PNG.sync.read(b);
  if (pa.width !== pb.width || pa.height !== pb.height) return pa.width * pa.height;
  let n = 0;
  for (let i = 0; i < pa.data.length; i += 4) {
    if (pa.data[i] !== pb.data[i] || pa.data[i + 1] !== pb.data[i + 1]
      || pa.data[i + 2] !== pb.data[i + 2] || pa.data[i + 3] !== pb.data[i + 3]) n++;
  }
  return n;
}

function allowedUrl(url, self) {
  if (/^(data|blob|about):/i.test(url)) return true;
  return url.split('#')[0] === self;
}

/** Two animation frames, so what the page drew last is on screen. */
const settle = (page) => page.evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r))));

/**
 * Sets #tp-time to `t` (null: its max) and dispatches `input`; waits until the page signals
 * that time in `dataset.tidepathTime` (failing first on any error meanwhile). Returns the
 * slider's value as set.
 */
async function moveTimeSlider(page, t, opts, failIfErrors) {
  const value = await page.$eval('#tp-time', (el, t) => {
    el.value = t === null ? el.max : String(t);
    el.dispatchEvent(new Event('input', { bubbles: true }));
    return String(Number(el.value));
  }, t);
  try {
    // Numerically: the page may clamp the slider's value (a decimal string) to its range.
    await page.waitForFunction((v) => {
      const got = Number(document.documentElement.dataset.tidepathTime ?? NaN);
      return Math.abs(got - Number(v)) <= 1e-9 * Math.max(1, Math.abs(Number(v)));
    }, value, { timeout: opts.timeoutMs, polling: 50 });
  } catch (e) {
    failIfErrors('after moving the time slider');
    const got = await page.locator('html').getAttribute('data-tidepath-time');
    throw new CheckError(`moving #tp-time to ${value}: dataset.tidepathTime is ${JSON.stringify(got)}, not ${JSON.stringify(value)}`
      + ` after ${opts.timeoutMs / 1000} s`);
  }
  await settle(page);
  return value;
}

async function checkPage(browser, file, opts) {
  const abs = path.resolve(file);
  const url = pathToFileURL(abs).href;
  const stem = path.basename(abs).replace(/\.html?$/i, '');
  const sizeMb = fs.statSync(abs).size / 1e6;
  const context = await browser.newContext({ viewport: VIEWPORT, serviceWorkers: 'block' });
  const requests = [];
  const errors = [];
  // Nothing leaves the machine: every request is recorded, any but the file itself fails the
  // page, and those going to the network are aborted.
  await context.route(/^(https?|wss?|ftp):/i, (route) => route.abort('blockedbyclient'));
  context.on('request', (r) => { if (!allowedUrl(r.url(), url)) requests.push(r.url()); });
  const page = await context.newPage();
  page.on('websocket', (ws) => requests.push(ws.url()));
  page.on('console', (m) => { if (m.type() === 'error') errors.push(`console error: ${m.text()}`); });
  page.on('pageerror', (e) => errors.push(`uncaught exception: ${e.message}`));
  page.on('crash', () => errors.push('the page crashed'));
  const failIfErrors = (when) => {
    if (requests.length) throw new CheckError(`${requests.length} request(s) other than the file itself ${when}:\n    ${requests.join('\n    ')}`);
    if (errors.length) throw new CheckError(`${errors.length} JavaScript error(s) ${when}:\n    ${errors.join('\n    ')}`);
  };
  try {
    await page.goto(url, { waitUntil: 'load', timeout: opts.timeoutMs });
    const html = page.locator('html');
    try {
      await page.waitForFunction(() => ['rendered', 'error'].includes(document.documentElement.dataset.tidepathState),
        null, { timeout: opts.timeoutMs, polling: 100 });
    } catch (e) {
      failIfErrors('while waiting for the first render');
      const state = await html.getAttribute('data-tidepath-state');
      throw new CheckError(`no render signal within ${opts.timeoutMs / 1000} s (dataset.tidepathState = ${JSON.stringify(state)})`);
    }
    if ((await html.getAttribute('data-tidepath-state')) === 'error') {
      const msg = await html.getAttribute('data-tidepath-error');
      failIfErrors('while building the scene');
      throw new CheckError(`the page reports an error while building the scene: ${msg}`);
    }
    const view = await page.evaluate(() => {
      const v = window.tidepathView;
      return v ? { timeRange: v.timeRange, renderMs: v.renderMs, setTime: typeof v.setTime } : null;
    });
    if (!view || !Array.isArray(view.timeRange) || view.timeRange.length !== 2
      || !view.timeRange.every(Number.isFinite) || view.timeRange[1] < view.timeRange[0]
      || !Number.isFinite(view.renderMs) || view.setTime !== 'function') {
      throw new CheckError(`window.tidepathView is not {timeRange: [t0, t1], renderMs, setTime}: ${JSON.stringify(view)}`);
    }
    for (const id of ['tp-plot', 'tp-time', 'tp-play', 'tp-clock', 'tp-exaggeration']) {
      if ((await page.locator(`#${id}`).count()) !== 1) throw new CheckError(`the page has no #${id}`);
    }
    const [t0, t1] = view.timeRange;
    const range = await page.$eval('#tp-time', (el) => [Number(el.min), Number(el.max), el.type]);
    const tol = 1e-6 * Math.max(1, Math.abs(t0), Math.abs(t1));
    if (range[2] !== 'range' || Math.abs(range[0] - t0) > tol || Math.abs(range[1] - t1) > tol) {
      throw new CheckError(`#tp-time is not a range input from ${t0} to ${t1}: type ${range[2]}, min ${range[0]}, max ${range[1]}`);
    }
    await settle(page);
    failIfErrors('up to the first render');
    // Without WebGL plotly's gl3d resolves newPlot all the same, showing only this notice.
    if (await page.evaluate(() => document.body.innerText.includes('WebGL is not supported'))) {
      throw new CheckError('the page says "WebGL is not supported by your browser": no WebGL context (check the Chromium flags)');
    }

    fs.mkdirSync(opts.shots, { recursive: true });
    const plot = page.locator('#tp-plot');
    const shotA = await plot.screenshot({ path: path.join(opts.shots, `${stem}-start.png`) });
    checkNotBlank(shotA, 'start');

    // The time slider halfway (when there is a range), then to its end, as a user's drag
    // ends: value set, `input` dispatched; the page redraws and signals the time.
    const shots = [];
    let motion = 'single instant';
    if (t1 > t0) {
      const mid = await moveTimeSlider(page, (t0 + t1) / 2, opts, failIfErrors);
      shots.push(['mid', mid, await plot.screenshot({ path: path.join(opts.shots, `${stem}-mid.png`) })]);
    }
    const tEnd = await moveTimeSlider(page, null, opts, failIfErrors);
    shots.push(['end', tEnd, await plot.screenshot({ path: path.join(opts.shots, `${stem}-end.png`) })]);
    failIfErrors('after moving the time slider');
    for (const [label, , shot] of shots) checkNotBlank(shot, label);
    if (t1 > t0) {
      // Both must differ from the start: halfway the vehicles are under way, at the end they
      // have arrived (or the moving obstacles, currents or waves have changed).
      const changed = shots.map(([label, t, shot]) => {
        const n = changedPixels(shotA, shot);
        if (n === 0) throw new CheckError(`the screenshots at t = ${t0} s and t = ${t} s (${label}) are identical: nothing moved`);
        return `${label} ${n}`;
      });
      motion = `px changed from start: ${changed.join(', ')}`;
    }

    // The vertical exaggeration slider to its end (unless disabled: a flat 2-D world), then
    // play for a while (a single instant may disable the play button; a time range may not).
    const moved = await page.$eval('#tp-exaggeration', (el) => {
      if (el.disabled) return false;
      el.value = el.max;
      el.dispatchEvent(new Event('input', { bubbles: true }));
      el.dispatchEvent(new Event('change', { bubbles: true }));
      return true;
    });
    await settle(page);
    failIfErrors('after moving the exaggeration slider');
    const notes = [motion, moved ? null : 'exaggeration disabled'];
    if (await page.$eval('#tp-play', (el) => el.disabled)) {
      if (t1 > t0) throw new CheckError(`#tp-play is disabled although the time range is ${t0}..${t1} s`);
      notes.push('play disabled');
    } else {
      // A script click: Playwright's own waits for the page after a click, which can take
      // seconds while software WebGL redraws every frame.
      await page.$eval('#tp-play', (el) => el.click());
      await page.waitForTimeout(opts.playMs ?? PLAY_MS);
      failIfErrors('while playing');
    }
    return { sizeMb, renderMs: view.renderMs, notes: notes.filter(Boolean).join(', ') };
  } finally {
    await context.close();
  }
}

async function launch() {
  if (!fs.existsSync(CHROMIUM)) {
    console.error(`check_views: no browser at ${CHROMIUM} (apt-get install chromium, or set TIDEPATH_CHROMIUM)`);
    process.exit(2);
  }
  return chromium.launch({ executablePath: CHROMIUM, headless: true, args: CHROMIUM_ARGS });
}

/** Checks each file; returns the number of failures. `expectFail` inverts the verdict. */
async function run(browser, files, opts, expectFail = false, log = console.log) {
  let failures = 0;
  for (const file of files) {
    const name = path.basename(file);
    const started = Date.now();
    try {
      const r = await checkPage(browser, file, opts);
      const secs = ((Date.now() - started) / 1000).toFixed(1);
      if (expectFail) {
        failures++;
        log(`FAIL self-test ${name}: a broken page passed the checks`);
      } else {
        log(`view ${name}: ${r.sizeMb.toFixed(2)} MB, first render ${Math.round(r.renderMs)} ms, `
          + `shots ok (${r.notes}), 0 errors, 0 requests (${secs} s)`);
      }
    } catch (e) {
      const msg = e instanceof CheckError ? e.message : `${e.name}: ${e.message}`;
      if (expectFail) log(`self-test ${name} (${((Date.now() - started) / 1000).toFixed(1)} s): fails as it should: ${msg.split('\n').slice(0, 2).map((l) => l.trim()).join(' ')}`);
      else {
        failures++;
        log(`FAIL view ${name}: ${msg}`);
      }
    }
  }
  return failures;
}

async function main() {
  const opts = parseArgs(process.argv.slice(2));
  const browser = await launch();
  let failures = 0;
  try {
    if (opts.selfTest) {
      const { writeMockPages } = await import('./mock_pages.mjs');
      const dir = fs.mkdtempSync(path.join(os.tmpdir(), 'tidepath-view-self-test-'));
      const mocks = writeMockPages(dir);
      const shots = path.join(dir, 'shots');
      const lines = [];
      const log = (l) => lines.push(l);
      const started = Date.now();
      let selfFailures = await run(browser, mocks.good, { ...opts, shots, timeoutMs: 10_000, playMs: 500 }, false, log);
      selfFailures += await run(browser, mocks.bad, { ...opts, shots, timeoutMs: 1_500, playMs: 300 }, true, log);
      fs.rmSync(dir, { recursive: true, force: true });
      if (selfFailures || process.env.VIEW_TEST_VERBOSE) console.log(lines.join('\n'));
      console.log(`self-test: ${mocks.good.length} good mock pages pass, ${mocks.bad.length} broken ones fail`
        + `${selfFailures ? ` -- BUT ${selfFailures} did not` : ''} (${((Date.now() - started) / 1000).toFixed(1)} s)`);
      failures += selfFailures;
    }
    failures += await run(browser, opts.files, opts);
  } finally {
    await browser.close();
  }
  if (failures) {
    console.error(`check_views: ${failures} page(s) failed`);
    process.exit(1);
  }
}

await main();
