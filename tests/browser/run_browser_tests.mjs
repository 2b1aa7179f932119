// The web player in a real browser (issue: feel it anywhere). Serves an image with the real
// `vimg serve`, opens it in Debian's headless Chromium through the DevTools protocol, and checks:
//   loads            the page loads and gets ready with no console error, failed request or exception
//   picture          a screenshot of the page shows the picture the PNG export draws
//   drag             silence at rest; a drag across a SURFACE sounds in the AudioWorklet and lights it
//   renderGesture    window.vimg.renderGesture equals `vimg render --out F.csv` within 1e-5 of full scale
//   prediction       touch-latency settings default from the wasm and persist across a reload; every
//                    pointer sample reaches the renderer; a drag that stops 6 mm short of a SURFACE is
//                    felt inside it with a 200 ms panel latency predicted, and not without prediction
//   push             a save of the image reaches the open page within 1 s, the audio still running
//   refuses          traversal, other methods than GET/HEAD and listings are refused
// Waits are on states (a line printed, a value changed), each bounded only against a hang.
// usage: node run_browser_tests.mjs VIMG SOURCE_DIR ARTIFACT_DIR [TEST...]
import { execFileSync } from 'node:child_process';
import fs from 'node:fs';
import path from 'node:path';
import { launchBrowser, openPage } from './lib/browser.mjs';
import { startServe } from './lib/serve.mjs';
import { comparePicture, dragAcross, rawRequest, waitForAudioTime } from './lib/page_tools.mjs';

const [vimg, sourceDir, artDir, ...only] = process.argv.slice(2);
if (!artDir) {
  console.error('usage: node run_browser_tests.mjs VIMG SOURCE_DIR ARTIFACT_DIR [TEST...]');
  process.exit(2);
}
fs.rmSync(artDir, { recursive: true, force: true });
fs.mkdirSync(artDir, { recursive: true });
const art = (name) => path.join(artDir, name);
const run = (args) => execFileSync(vimg, args, { encoding: 'utf8' });

// The served image is a copy, so the push test can save over it.
const imagePath = art('smiley.vimg');
fs.copyFileSync(path.join(sourceDir, 'assets/examples/smiley.vimg'), imagePath);
const serve = await startServe(vimg, [imagePath]);
const browser = await launchBrowser();
const { page, problems } = await openPage(browser, serve.url);

const results = [];
async function check(name, body) {
  if (only.length && !only.includes(name)) return;
  const started = Date.now();
  try {
    const note = await body();
    results.push({ name, ok: true, note });
    console.log(`PASS ${name}${note ? `: ${note}` : ''} (${Date.now() - started} ms)`);
  } catch (e) {
    results.push({ name, ok: false, note: e.message });
    console.log(`FAIL ${name}: ${e.message}`);
    await page.screenshot({ path: art(`failed-${name}.png`) }).catch(() => {});
  }
}
const assert = (condition, message) => { if (!condition) throw new Error(message); };

await check('loads', async () => {
  assert(problems.length === 0, problems.join('; '));
  const info = await page.evaluate(() => window.vimg.imageInfo());
  assert(info.primitives.length > 0, 'the page shows no primitives');
  return `${info.name}: ${info.width_mm} x ${info.height_mm} mm, ${info.primitives.length} primitives`;
});

await check('picture', async () => {
  run(['convert', imagePath, art('export.png')]);
  const shot = await page.screenshot({ path: art('page.png') });
  const r = await comparePicture(page, shot, fs.readFileSync(art('export.png')));
  assert(r.correlation > 0.9, `the screenshot's picture correlates ${r.correlation.toFixed(3)} with the PNG export (want > 0.9)`);
  return `correlation ${r.correlation.toFixed(3)} over ${r.cells} cells`;
});

await check('drag', async () => {
  await page.evaluate(() => window.vimg.startAudio());
  await page.evaluate(() => window.vimg.workletPeak());  // resets the peak
  await waitForAudioTime(page, 0.25);
  const restPeak = await page.evaluate(() => window.vimg.workletPeak());
  assert(restPeak === 0, `the worklet is not silent at rest (peak ${restPeak})`);
  const info = await page.evaluate(() => window.vimg.imageInfo());
  const surface = info.primitives.find((p) => p.kind === 'surface');
  assert(surface, 'the image has no SURFACE');
  const { peak, lit } = await dragAcross(page, surface);
  await page.screenshot({ path: art('dragging.png') });
  assert(peak > 0.01, `a drag across SURFACE ${surface.id} gave a worklet peak of ${peak}`);
  assert(lit.includes(surface.id), `SURFACE ${surface.id} was not lit while touched (lit: ${lit.join(', ')})`);
  return `rest peak 0, drag peak ${peak.toFixed(3)}, lit ${lit.join(', ')}`;
});

await check('renderGesture', async () => {
  let worst = 0;
  for (const gesture of ['smiley_eyes.csv', 'smiley_mouth.csv']) {
    const csvPath = path.join(sourceDir, 'assets/gestures', gesture);
    const rate = await page.evaluate(() => window.vimg.renderRateHz ?? 8000);
    const web = await page.evaluate(async (csv) => Array.from(await window.vimg.renderGesture(csv)),
                                     fs.readFileSync(csvPath, 'utf8'));
    run(['render', imagePath, '--gesture', csvPath, '--rate', String(rate), '--out', art(`${gesture}.native.csv`)]);
    const native = fs.readFileSync(art(`${gesture}.native.csv`), 'utf8').trim().split('\n').slice(1)
      .map((row) => Number(row.split(',')[1]));
    assert(web.length === native.length, `${gesture}: ${web.length} samples in the page, ${native.length} from vimg render`);
    for (let i = 0; i < web.length; ++i) worst = Math.max(worst, Math.abs(web[i] - native[i]));
    assert(native.some((v) => Math.abs(v) > 0.01), `${gesture}: the native render is silent`);
  }
  assert(worst <= 1e-5, `largest difference ${worst} of full scale (limit 1e-5)`);
  return `largest difference ${worst.toExponential(2)} of full scale`;
});

// Moves at 100 mm/s (1 mm per 10 ms of audio time) towards the SURFACE's nearest free side, stops
// `short_mm` before its edge, waits 0.2 s of audio and lifts. Returns the worklet's peak meanwhile.
async function approach(primitive, shortMm) {
  const info = await page.evaluate(() => window.vimg.imageInfo());
  const [x0, y0, x1, y1] = primitive.bbox_mm;
  const sides = [
    { room: x0, from: (d) => [x0 - d, (y0 + y1) / 2] },
    { room: info.width_mm - x1, from: (d) => [x1 + d, (y0 + y1) / 2] },
    { room: y0, from: (d) => [(x0 + x1) / 2, y0 - d] },
    { room: info.height_mm - y1, from: (d) => [(x0 + x1) / 2, y1 + d] },
  ].sort((a, b) => b.room - a.room);
  const side = sides[0];
  assert(side.room >= shortMm + 10, `no side of ${primitive.id} has ${shortMm + 10} mm of room`);
  const at = (d) => page.evaluate((p) => window.vimg.clientPointOfMm(p[0], p[1]), side.from(d));
  const start = await at(side.room - 1);
  await page.mouse.move(start.x, start.y);
  await page.evaluate(() => window.vimg.workletPeak());  // resets the peak
  await page.mouse.down();
  for (let d = side.room - 2; d >= shortMm; d -= 1) {
    const p = await at(d);
    await page.mouse.move(p.x, p.y);
    await waitForAudioTime(page, 0.01);
  }
  await waitForAudioTime(page, 0.2);
  const peak = await page.evaluate(() => window.vimg.workletPeak());
  await page.mouse.up();
  await waitForAudioTime(page, 0.2);
  return peak;
}

await check('prediction', async () => {
  const s = await page.evaluate(() => window.vimg.touchSettings());
  // docs/latency.md: 25 ms for a touchscreen, 8 ms for a mouse or pen (the C++ constants).
  assert(s.defaults.touch === 25 && s.defaults.mouse === 8, `defaults ${JSON.stringify(s.defaults)}`);
  assert(s.latencyMs === s.defaults[s.kind] && s.prediction, `a new device starts at ${JSON.stringify(s)}`);
  assert(!(await page.evaluate(() => window.vimg.setTouchLatencyMs(-1))), 'a negative latency was accepted');
  await page.evaluate(() => { window.vimg.setTouchLatencyMs(400); window.vimg.setTouchPrediction(false); });
  await page.reload({ waitUntil: 'load' });  // the page's script defines window.vimg before 'load'
  await page.evaluate(() => window.vimg.ready);
  const kept = await page.evaluate(() => window.vimg.touchSettings());
  assert(kept.latencyMs === 400 && !kept.prediction, `after a reload: ${JSON.stringify(kept)}`);
  await page.evaluate(() => window.vimg.startAudio());
  await waitForAudioTime(page, 0.1);
  const surface = (await page.evaluate(() => window.vimg.imageInfo())).primitives.find((p) => p.kind === 'surface');
  const sentBefore = await page.evaluate(() => window.vimg.samplesSent);
  const off = await approach(surface, 3);
  const sent = (await page.evaluate(() => window.vimg.samplesSent)) - sentBefore;
  await page.evaluate(() => window.vimg.setTouchPrediction(true));
  const on = await approach(surface, 3);
  await page.evaluate((d) => { window.vimg.setTouchLatencyMs(d); }, s.defaults[s.kind]);
  assert(sent >= 10, `only ${sent} pointer samples reached the renderer`);
  assert(off === 0, `without prediction, stopping 3 mm short of ${surface.id} sounded (peak ${off})`);
  assert(on > 0.01, `with 400 ms predicted, stopping 3 mm short of ${surface.id} stayed silent (peak ${on})`);
  return `defaults ${s.defaults.touch}/${s.defaults.mouse} ms, kept across a reload; ${sent} samples; 3 mm short: peak ${off} off, ${on.toFixed(3)} predicted`;
});

await check('push', async () => {
  const before = await page.evaluate(() => ({ version: window.vimg.sceneVersion, info: window.vimg.imageInfo() }));
  // An editor's save: a new file renamed over the old one. The new image is 10 mm wider.
  const text = fs.readFileSync(imagePath, 'utf8').replace(/width="(\d+(\.\d+)?)"/, (m, w) => `width="${Number(w) + 10}"`);
  fs.writeFileSync(`${imagePath}.tmp`, text);
  const saved = Date.now();
  fs.renameSync(`${imagePath}.tmp`, imagePath);
  await page.waitForFunction((v) => window.vimg.sceneVersion > v, { timeout: 10000, polling: 'raf' }, before.version);
  const latencyMs = Date.now() - saved;
  const after = await page.evaluate(() => ({ info: window.vimg.imageInfo(), audio: window.vimg.audioState() }));
  assert(after.info.width_mm === before.info.width_mm + 10, `the page shows width ${after.info.width_mm} mm after the save`);
  assert(after.audio === 'running', `the audio is ${after.audio} after the swap`);
  assert(latencyMs < 1000, `the save reached the page after ${latencyMs} ms (limit 1 s)`);
  return `reached the page ${latencyMs} ms after the save, audio ${after.audio}`;
});

await check('refuses', async () => {
  const origin = new URL(serve.url);
  const cases = [
    ['GET /../../../../etc/passwd', [400, 403, 404]],
    ['GET /%2e%2e/%2e%2e/%2e%2e/etc/passwd', [400, 403, 404]],
    ['GET /images/', [403, 404]],
    ['POST /', [405]],
    ['PUT /index.html', [405]],
    ['DELETE /index.html', [405]],
  ];
  const seen = [];
  for (const [request, allowed] of cases) {
    const r = await rawRequest(origin.hostname, Number(origin.port), request);
    seen.push(`${request} -> ${r.status}`);
    assert(allowed.includes(r.status), `${request} gave ${r.status}, want one of ${allowed.join('/')}`);
    assert(!r.body.includes('root:'), `${request} leaked a file outside the site`);
  }
  const head = await rawRequest(origin.hostname, Number(origin.port), 'HEAD /');
  assert(head.status === 200 && head.body === '', `HEAD / gave ${head.status} with ${head.body.length} bytes of body`);
  return seen.join(', ');
});

await browser.close();
const code = await serve.stop();
fs.writeFileSync(art('serve.log'), serve.stderr());
if (!only.length || only.includes('stop')) {
  const ok = code === 143;
  results.push({ name: 'stop', ok });
  console.log(`${ok ? 'PASS' : 'FAIL'} stop: vimg serve exited ${code} on SIGTERM (want 143)`);
}
fs.writeFileSync(art('results.json'), JSON.stringify(results, null, 2));
const failed = results.filter((r) => !r.ok);
console.log(`${results.length - failed.length} of ${results.length} browser checks passed; artifacts in ${artDir}`);
process.exit(failed.length ? 1 : 0);
