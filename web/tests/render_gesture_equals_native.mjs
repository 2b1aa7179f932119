// node render_gesture_equals_native.mjs SITE_DIR IMAGE.vsc GESTURE.csv NATIVE.csv [RATE_HZ]
// Renders the gesture with the site's vimg.js/vimg.wasm (the page's renderGesture path) and compares
// it with the CSV `vimg render IMAGE --gesture G --out NATIVE.csv` wrote: the same number of samples,
// the same first time, every drive within 1e-5 of full scale. Exit 0 when equal, 1 when not, 2 on
// a usage or load problem. Prints one line with the figures.
import { readFileSync } from 'node:fs';
import { createRequire } from 'node:module';
import path from 'node:path';

const [siteDir, vscPath, gesturePath, nativeCsvPath, rateArg] = process.argv.slice(2);
if (!nativeCsvPath) {
  console.error('usage: node render_gesture_equals_native.mjs SITE_DIR IMAGE.vsc GESTURE.csv NATIVE.csv [RATE_HZ]');
  process.exit(2);
}
const kTolerance = 1e-5;  // of full scale (a drive of 1)
// Without RATE_HZ both sides use their default rate: the wasm's is the C++ one `vimg render` uses.
const rateHz = rateArg ? Number(rateArg) : undefined;

const require = createRequire(import.meta.url);
const createVimgModule = require(path.resolve(siteDir, 'vimg.js'));
const renderer = await createVimgModule.VimgRenderer.create({
  wasmBinary: readFileSync(path.join(siteDir, 'vimg.wasm')),
});
renderer.loadVsc(readFileSync(vscPath));
const web = renderer.renderGesture(readFileSync(gesturePath, 'utf8'), rateHz);

const rows = readFileSync(nativeCsvPath, 'utf8').trim().split('\n').slice(1);
const nativeTimes = rows.map((r) => Number(r.split(',')[0]));
const native = rows.map((r) => Number(r.split(',')[1]));
let maxDiff = 0;
let at = -1;
const n = Math.min(web.length, native.length);
for (let i = 0; i < n; ++i) {
  const d = Math.abs(web[i] - native[i]);
  if (!(d <= maxDiff)) {
    maxDiff = d;
    at = i;
  }
}
let peak = 0;
for (const v of native) peak = Math.max(peak, Math.abs(v));
const startDiff = Math.abs(renderer.renderedStartS() - nativeTimes[0]);
console.log(`samples web ${web.length} native ${native.length}; max |web - native| ${maxDiff} at sample ${at}; ` +
            `native peak |drive| ${peak}; first time web ${renderer.renderedStartS()} native ${nativeTimes[0]}`);
const equal = web.length === native.length && maxDiff <= kTolerance && startDiff < 0.5 / (rateHz ?? renderer.defaultRenderRateHz());
process.exit(equal ? 0 : 1);
