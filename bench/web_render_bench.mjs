// node bench/web_render_bench.mjs SITE_DIR IMAGE.vsc GESTURE.csv [REPEATS]
// The wasm render cost per sample (renderGesture at 48 kHz, the page's path) for comparison with
// the native `vimg render` of the same gesture (docs/benchmarks/web-and-wasm.md, "WebAssembly render"), and the cost of
// one finger prediction per model on the workload touch_prediction_bench's BM_Predict measures
// natively (primitives/touch_prediction/circling_finger.hpp): the median of 5 runs of 2 000 000.
import { readFileSync } from 'node:fs';
import { createRequire } from 'node:module';
import path from 'node:path';

const [siteDir, vscPath, gesturePath, repeatsArg] = process.argv.slice(2);
const repeats = Number(repeatsArg || 10);
const require = createRequire(import.meta.url);
const createVimgModule = require(path.resolve(siteDir, 'vimg.js'));
const r = await createVimgModule.VimgRenderer.create({ wasmBinary: readFileSync(path.join(siteDir, 'vimg.wasm')) });
r.loadVsc(readFileSync(vscPath));
const csv = readFileSync(gesturePath, 'utf8');
r.renderGesture(csv, 48000);  // warm up (compile tiers)
// Five runs of REPEATS renders; the median per sample of the wall time and of this process's CPU
// time (as render_gesture_bench's ns_per_sample, which counts CPU time: on a loaded machine the two differ).
const walls = [];
const cpus = [];
let samples = 0;
for (let run = 0; run < 5; ++run) {
  samples = 0;
  const cpu0 = process.cpuUsage();
  const t0 = process.hrtime.bigint();
  for (let i = 0; i < repeats; ++i) samples += r.renderGesture(csv, 48000).length;
  walls.push(Number(process.hrtime.bigint() - t0) / samples);
  const cpu = process.cpuUsage(cpu0);
  cpus.push(((cpu.user + cpu.system) * 1000) / samples);
}
const median = (v) => [...v].sort((a, b) => a - b)[2];
console.log(`wasm: ${samples} samples per run; median of 5 runs: ${median(walls).toFixed(1)} ns per sample wall, ` +
            `${median(cpus).toFixed(1)} ns per sample CPU`);
for (const model of r.predictionModels()) {
  const n = 2000000;
  r.benchPredict(n / 10, model);  // warm up
  const runs = [];
  for (let i = 0; i < 5; ++i) runs.push(r.benchPredict(n, model));
  runs.sort((a, b) => a - b);
  console.log(`wasm: predict ${model}: ${((runs[2] * 1e9) / n).toFixed(1)} ns per prediction (median of 5 x ${n})`);
}
