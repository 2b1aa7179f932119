// node bench/web_latency_bench.mjs VIMG [MOVES]
// What the finger feels in the page, in Debian's headless Chromium: `vimg serve` serves the smiley,
// the sound starts, and MOVES pointer moves across the face are sent one per 128-frame block of
// audio time. For each event, the span from its own `timeStamp` (when the browser took it) to the
// moment its first affected sample is heard: the worklet reports that sample's time on the
// AudioContext's clock, and the page maps it to performance.now()'s clock with the output's pairing
// of the two (getOutputTimestamp(), web/site/audio_clock.js). Prints p50, p99, jitter (p99 - p50)
// and max in ms, the audio callback period (how far currentTime advances at once, the goal for the
// jitter), the block length, the span's two parts (timeStamp to the page's handler, handler to
// heard), and for comparison the older span from posting the event to the worklet's report
// arriving back on the page's thread.
import path from 'node:path';
import { fileURLToPath } from 'node:url';

const here = path.dirname(fileURLToPath(import.meta.url));
const { launchBrowser, openPage } = await import(path.join(here, '../tests/browser/lib/browser.mjs'));
const { startServe } = await import(path.join(here, '../tests/browser/lib/serve.mjs'));
const { callbackPeriodS, waitForAudioTime } = await import(path.join(here, '../tests/browser/lib/page_tools.mjs'));

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
await waitForAudioTime(page, 0.2);  // the output's pairing of the clocks is in place
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
const periodS = await callbackPeriodS(page);
const mine = await page.evaluate((from) => window.vimg.events.filter((e) => e.id >= from && e.firstBlockAt !== undefined)
  .map((e) => ({ felt: e.heardAtMs - e.timeStamp, handled: e.time - e.timeStamp, heard: e.heardAtMs - e.time,
                 reported: e.firstBlockAt - e.time })), firstId);
await browser.close();
await serve.stop();

const quantiles = (values) => {
  const v = values.filter(Number.isFinite).sort((a, b) => a - b);
  const q = (f) => v[Math.min(v.length - 1, Math.floor(f * v.length))];
  return { n: v.length, p50: q(0.5), p99: q(0.99), max: v.at(-1) };
};
const felt = quantiles(mine.map((e) => e.felt));
const reported = quantiles(mine.map((e) => e.reported));
const ms = (v) => `${v.toFixed(2)} ms`;
console.log(`events ${felt.n} of ${moves}; timeStamp -> first affected sample heard: p50 ${ms(felt.p50)}, ` +
            `p99 ${ms(felt.p99)}, jitter (p99 - p50) ${ms(felt.p99 - felt.p50)}, max ${ms(felt.max)}`);
console.log(`audio callback period ${ms(periodS * 1000)} (${Math.round(periodS * rate)} frames); ` +
            `one block is ${ms((128 / rate) * 1000)} at ${rate} Hz; jitter goal (<= one callback period) ` +
            `${felt.p99 - felt.p50 <= periodS * 1000 ? 'met' : 'not met'}`);
const handled = quantiles(mine.map((e) => e.handled));
const heard = quantiles(mine.map((e) => e.heard));
console.log(`of which timeStamp -> the page's handler: p50 ${ms(handled.p50)}, p99 ${ms(handled.p99)}; ` +
            `handler -> heard: p50 ${ms(heard.p50)}, p99 ${ms(heard.p99)}`);
console.log(`for comparison, posted -> first affected block reported back: p50 ${ms(reported.p50)}, ` +
            `p99 ${ms(reported.p99)}, max ${ms(reported.max)}`);
