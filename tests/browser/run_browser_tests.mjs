// The web player in a real browser (issue: feel it anywhere). Serves an image with the real
// `vimg serve`, opens it in Debian's headless Chromium through the DevTools protocol, and checks:
//   loads            the page loads and gets ready with no console error, failed request or exception
//   picture          a screenshot of the page shows the picture the PNG export draws
//   drag             silence at rest; a drag across a SURFACE sounds in the AudioWorklet and lights it
//   renderGesture    window.vimg.renderGesture equals `vimg render --out F.csv` within 1e-5 of full scale
//   prediction       touch-latency settings default from the wasm and persist across a reload; the
//                    worklet predicts the horizon the page asks; every pointer sample reaches the
//                    renderer; in the page's wasm, an approach that stops 6 mm short of a SURFACE is
//                    felt inside it with 400 ms predicted, and not without prediction
//   placement        an event queued inside a block takes effect at its own sample, not the block's first
//   timestamps       pointer events with known timeStamps land on the worklet's clock within one render
//                    quantum of their true time (audio_clock.js: the output's pairing of the clocks)
//   push             a save of the image reaches the open page, the audio still running (the time is reported)
//   refuses          traversal, other methods than GET/HEAD and listings are refused
//   noErrors         no console error, failed request or exception during all the checks, not only at load
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

// The page's own wasm, on the events' own clock (no machine's timing in it): a finger at 100 mm/s,
// an event every 10 ms, towards the SURFACE's roomiest free side, stopping `shortMm` before its edge
// and resting there 0.2 s. Returns the peak with each finger predicted `horizonS` ahead (0: off).
function predictedApproachPeak(primitive, shortMm, horizonS) {
  return page.evaluate(async (p, short, horizon) => {
    const info = window.vimg.imageInfo();
    const [x0, y0, x1, y1] = p.bbox_mm;
    const side = [
      { room: x0, from: [x0, (y0 + y1) / 2], dir: [-1, 0] },
      { room: info.width_mm - x1, from: [x1, (y0 + y1) / 2], dir: [1, 0] },
      { room: y0, from: [(x0 + x1) / 2, y0], dir: [0, -1] },
      { room: info.height_mm - y1, from: [(x0 + x1) / 2, y1], dir: [0, 1] },
    ].sort((a, b) => b.room - a.room)[0];
    const renderer = await VimgRenderer.create({ wasmBinary: new Uint8Array(await (await fetch('vimg.wasm')).arrayBuffer()) });
    renderer.loadVsc(new Uint8Array(await (await fetch('images/' + encodeURIComponent(info.name) + '.vsc')).arrayBuffer()));
    const rate = 48000;
    renderer.liveSetPrediction(horizon);
    renderer.liveStart(rate);
    let peak = 0;
    const render = (s) => { for (const v of renderer.liveRender(Math.round(s * rate))) peak = Math.max(peak, Math.abs(v)); };
    const at = (d) => [side.from[0] + side.dir[0] * d, side.from[1] + side.dir[1] * d];
    let t = renderer.liveTimeS();
    renderer.liveEventAt(t, 0, 0, ...at(side.room - 1), 1);
    for (let d = side.room - 2; d >= short; d -= 1) {
      t += 0.01;
      renderer.liveEventAt(t, 0, 1, ...at(d), 1);
    }
    render(t - renderer.liveTimeS() + 0.2);
    renderer.liveEventAt(renderer.liveTimeS(), 0, 2, ...at(short), 1);
    render(0.05);
    return peak;
  }, primitive, shortMm, horizonS);
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
  // The worklet's renderer predicts the horizon the page asks: off, then 400 ms + the output's latency.
  await page.evaluate(() => window.vimg.startAudio());
  const horizonOf = async () => {
    await waitForAudioTime(page, 0.05);  // a report of the worklet after the change
    return page.evaluate(() => ({ worklet: window.vimg.workletHorizonS, page: window.vimg.touchSettings().horizonS }));
  };
  const off = await horizonOf();
  await page.evaluate(() => window.vimg.setTouchPrediction(true));
  const on = await horizonOf();
  assert(off.worklet === 0, `with prediction off the worklet predicts ${off.worklet} s ahead`);
  assert(on.page >= 0.4 && Math.abs(on.worklet - on.page) < 1e-9, `with 400 ms on, the worklet predicts ${on.worklet} s ahead, the page asked ${on.page} s`);
  // Every pointer sample reaches the worklet's renderer (each reported by the block that applied it).
  const from = await page.evaluate(() => window.vimg.samplesSent);
  const surface = (await page.evaluate(() => window.vimg.imageInfo())).primitives.find((p) => p.kind === 'surface');
  await dragAcross(page, surface);
  await waitForAudioTime(page, 0.1);
  const samples = await page.evaluate((f) => {
    const mine = window.vimg.events.filter((e) => e.id > f);
    return { sent: mine.length, rendered: mine.filter((e) => e.firstBlockAt !== undefined).length };
  }, from);
  assert(samples.sent >= 10 && samples.rendered === samples.sent, `${samples.rendered} of ${samples.sent} pointer samples reached the renderer`);
  // What prediction does to the felt position, in the page's own wasm: 6 mm short of the SURFACE is
  // silent without it (the tracker reckons at most 30 ms ahead: 3 mm) and felt inside with 400 ms.
  const kShortMm = 6;
  const silent = await predictedApproachPeak(surface, kShortMm, 0);
  const felt = await predictedApproachPeak(surface, kShortMm, on.page);
  await page.evaluate((d) => { window.vimg.setTouchLatencyMs(d); }, s.defaults[s.kind]);
  assert(silent === 0, `without prediction, stopping ${kShortMm} mm short of ${surface.id} sounded (peak ${silent})`);
  assert(felt > 0.01, `with ${(on.page * 1000).toFixed(1)} ms predicted, stopping ${kShortMm} mm short of ${surface.id} stayed silent`);
  return `defaults ${s.defaults.touch}/${s.defaults.mouse} ms, kept across a reload; worklet horizon ${off.worklet} s off, ` +
    `${on.worklet.toFixed(4)} s on; ${samples.rendered} of ${samples.sent} samples rendered; ${kShortMm} mm short: ` +
    `peak ${silent} off, ${felt.toFixed(3)} predicted`;
});

// WebRenderer::live_event_at through the page's own wasm: a stroke across a SURFACE queued to start
// 200 samples into the next render leaves those samples silent and sounds within 10 ms (480 samples)
// of its start; applied at the block's first sample instead, it would sound before sample 200.
await check('placement', async () => {
  const surface = (await page.evaluate(() => window.vimg.imageInfo())).primitives.find((p) => p.kind === 'surface');
  const r = await page.evaluate(async (name, s) => {
    const renderer = await VimgRenderer.create({ wasmBinary: new Uint8Array(await (await fetch('vimg.wasm')).arrayBuffer()) });
    renderer.loadVsc(new Uint8Array(await (await fetch('images/' + encodeURIComponent(name) + '.vsc')).arrayBuffer()));
    const rate = 48000;
    renderer.liveStart(rate);
    renderer.liveRender(480);
    const t0 = renderer.liveTimeS() + 200 / rate;
    const [x, y] = [(s.bbox_mm[0] + s.bbox_mm[2]) / 2 - 2, (s.bbox_mm[1] + s.bbox_mm[3]) / 2];  // across its middle
    renderer.liveEventAt(t0, 0, 0, x, y, 1);
    for (let k = 1; k <= 40; ++k) renderer.liveEventAt(t0 + k * 0.001, 0, 1, x + k * 0.1, y, 1);
    const block = Array.from(renderer.liveRender(4800));
    return { first: block.findIndex((v) => Math.abs(v) > 1e-6), peak: Math.max(...block.map(Math.abs)) };
  }, (await page.evaluate(() => window.vimg.imageInfo())).name, surface);
  assert(r.peak > 0.01, `the queued stroke never sounded (peak ${r.peak})`);
  assert(r.first >= 200, `the output sounded at sample ${r.first}, before the stroke's first event at sample 200`);
  assert(r.first < 200 + 480, `the output first sounded at sample ${r.first}, more than 10 ms after the stroke's start at sample 200`);
  return `silent for ${r.first} samples, the stroke starting at sample 200; peak ${r.peak.toFixed(3)}`;
});

// web/site/audio_clock.js in the page: pointer events dispatched with known timeStamps (DevTools'
// input events carry their own time), 20 to 60 ms old when dispatched as a panel's events are, land
// on the worklet's clock within one render quantum (128 frames) of their true time: the context time
// heard at their timeStamp by the output's pairings of the clocks (getOutputTimestamp()) read every
// few ms while the check runs, those within 30 ms of the event. The stamp is that time plus the
// output latency the page assumes (the horizon adds the same), so the check subtracts it.
await check('timestamps', async () => {
  await page.evaluate(() => window.vimg.startAudio());
  await waitForAudioTime(page, 0.2);
  await page.evaluate(() => {
    window.clockReadings = [];
    window.clockSampler = setInterval(() => window.clockReadings.push(window.vimg.clockReading()), 2);
  });
  await waitForAudioTime(page, 0.1);  // pairings read before the oldest event's time
  const surface = (await page.evaluate(() => window.vimg.imageInfo())).primitives.find((p) => p.kind === 'surface');
  const [x0, y0, x1, y1] = surface.bbox_mm;
  const from = await page.evaluate(() => window.vimg.samplesSent);
  const cdp = await page.createCDPSession();
  const origin = await page.evaluate(() => performance.timeOrigin);
  const sent = [];
  const points = await page.evaluate((a, b, y) => Array.from({ length: 40 }, (_, i) => window.vimg.clientPointOfMm(a + (b - a) * i / 40, y)),
                                     x0 + 2, x1 - 2, (y0 + y1) / 2);
  for (let round = 0; round < 8; ++round) {
    for (let k = 0; k < 5; ++k) {
      // 60, 50, ... 20 ms old when dispatched (the clock read just before), in order.
      const now = await page.evaluate(() => performance.now());
      const timeStamp = Math.max(now - 60 + 10 * k + 3 * Math.random(), (sent.at(-1) ?? 0) + 0.5);
      const p = points[round * 5 + k];
      const type = round === 0 && k === 0 ? 'mousePressed' : 'mouseMoved';
      await cdp.send('Input.dispatchMouseEvent', { type, x: p.x, y: p.y, button: 'left', buttons: 1, clickCount: 1,
                                                   timestamp: (origin + timeStamp) / 1000 });
      sent.push(timeStamp);
    }
    await waitForAudioTime(page, 0.02);
  }
  const last = await page.evaluate((a, b) => window.vimg.clientPointOfMm(a, b), x1 - 2, (y0 + y1) / 2);
  await cdp.send('Input.dispatchMouseEvent', { type: 'mouseReleased', x: last.x, y: last.y, button: 'left', buttons: 0, clickCount: 1 });
  await waitForAudioTime(page, 0.1);
  const r = await page.evaluate((f) => {
    clearInterval(window.clockSampler);
    return { events: window.vimg.events.filter((e) => e.id > f).map((e) => ({ timeStamp: e.timeStamp, stampS: e.stampS })),
             readings: window.clockReadings, rate: window.vimg.audioSampleRate() };
  }, from);
  const events = r.events.slice(0, sent.length);
  assert(events.length === sent.length && events.every((e) => e.stampS !== undefined),
         `${events.filter((e) => e.stampS !== undefined).length} of ${sent.length} dispatched events were applied by the worklet`);
  const skewMs = Math.max(...events.map((e, i) => Math.abs(e.timeStamp - sent[i])));
  assert(skewMs < 0.5, `the page's timeStamps differ from the dispatched ones by up to ${skewMs} ms`);
  // The true time of each event: the context time heard at its timeStamp by the pairings the page
  // read every few ms, within 30 ms of it (their median offset, so one late callback is outvoted).
  const pairs = r.readings.filter((q) => q.contextTime > 0);
  assert(pairs.length >= 20, `only ${pairs.length} pairings of the clocks were read`);
  const latencyS = pairs.at(-1).latencyS;
  const errorsS = events.map((e) => {
    // Within 30 ms, else (the audio thread stalled) the three nearest.
    const byDistance = [...pairs].sort((x, y) => Math.abs(x.performanceTime - e.timeStamp) - Math.abs(y.performanceTime - e.timeStamp));
    const within = byDistance.filter((q) => Math.abs(q.performanceTime - e.timeStamp) <= 30);
    const near = (within.length >= 3 ? within : byDistance.slice(0, 3)).map((q) => q.contextTime * 1000 - q.performanceTime)
      .sort((x, y) => x - y);
    return e.stampS - latencyS - (e.timeStamp + near[(near.length - 1) >> 1]) / 1000;
  });
  const worst = Math.max(...errorsS.map(Math.abs));
  const quantumS = 128 / r.rate;
  assert(worst <= quantumS, `an event landed ${(worst * 1000).toFixed(2)} ms from its true time (bound: one render quantum, ` +
         `${(quantumS * 1000).toFixed(2)} ms); errors ${errorsS.map((v) => (v * 1000).toFixed(2)).join(', ')} ms`);
  return `${events.length} events, worst ${(worst * 1000).toFixed(3)} ms from their true time (bound ${(quantumS * 1000).toFixed(2)} ms) ` +
    `over ${pairs.length} pairings read; timeStamps kept within ${skewMs.toFixed(3)} ms`;
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

await check('noErrors', async () => {
  assert(problems.length === 0, problems.join('; '));
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
