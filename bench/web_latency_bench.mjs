// node bench/web_latency_bench.mjs VIMG [MOVES]
// Pointer-event-to-first-affected-block latency inside the page, in Debian's headless Chromium:
// `vimg serve` serves the smiley, the sound starts, and MOVES pointer moves across the face are sent
// one per 128-frame block of audio time. For each event the page records when it posted it to the
// AudioWorklet (performance.now()) and when the worklet's report of the first block that applied it
// arrived back on the page's thread. That span is an upper bound of the event-to-first-sample
// latency: it includes the message back from the audio thread. Prints p50, p99 and max in ms, and the
// block length for comparison (the goal: no buffering beyond the browser's own block).
import path from 'node:path';
import { fileURLToPath } from 'node:url';

const here = path.dirname(fileURLToPath(import.meta.url));
const { launchBrowser, openPage } = await import(path.join(here, '../tests/browser/lib/browser.mjs'));
const { startServe } = await import(path.join(here, '../tests/browser/lib/serve.mjs'));
const { waitForAudioTime } = await import(path.join(here, '../tests/browser/lib/page_tools.mjs'));

const [vimg, movesArg] = process.argv.slice(2);
if (!vimg) {
  console.error('usage: node bench/web_latency_bench.mjs VIMG [MOVES]');
  process.exit(2);
}
const moves = Number(movesArg || 400);
const serve = await startServe(vimg, [path.join(here, '../assets/examples/smiley.vimg')]);
const browser = await launchBrowser();
const { page } = await openPage(browser, serve.url);
await page.evaluate(() => window.vimg.startAudio());
const rate = await page.evaluate(() => window.vimg.audioSampleRate());
const at = (x, y) => page.evaluate((a, b) => window.vimg.clientPointOfMm(a, b), x, y);
let p = await at(10, 70);
await page.mouse.move(p.x, p.y);
await page.mouse.down();
const firstId = await page.evaluate(() => window.vimg.events.length ? window.vimg.events.at(-1).id + 1 : 1);
for (let i = 0; i < moves; ++i) {
  p = await at(10 + (50 * (i % 100)) / 100, 70 + Math.floor(i / 100));
  await page.mouse.move(p.x, p.y);
  await waitForAudioTime(page, 128 / rate);
}
await page.mouse.up();
await waitForAudioTime(page, 0.1);
const spans = await page.evaluate((from) => window.vimg.events.filter((e) => e.id >= from && e.firstBlockAt)
  .map((e) => e.firstBlockAt - e.time), firstId);
const blockMs = (128 / rate) * 1000;
spans.sort((a, b) => a - b);
const q = (f) => spans[Math.min(spans.length - 1, Math.floor(f * spans.length))];
console.log(`events ${spans.length} of ${moves}; event -> first affected block reported: ` +
            `p50 ${q(0.5).toFixed(2)} ms, p99 ${q(0.99).toFixed(2)} ms, max ${spans.at(-1).toFixed(2)} ms; ` +
            `one block is ${blockMs.toFixed(2)} ms at ${rate} Hz`);
await browser.close();
await serve.stop();
