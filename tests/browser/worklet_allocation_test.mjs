// The AudioWorklet's per-block path (web/site/worklet.js, render()) makes no typed array and no
// array per block: in Node alone (node --test), the worklet's file runs in a context of its own
// whose Float32Array and whose array and typed-array methods that return new arrays count their
// calls, over a fake wasm renderer (a Memory and the exports render() calls). 2000 blocks of 10
// fingers' worth of events, none reported between the 8-block reports, and events applied in
// blocks: the only arrays are one [id, stamp, first sample] per applied event; the only typed array
// is the view made once (again only when the wasm's memory grows).
import assert from 'node:assert/strict';
import fs from 'node:fs';
import path from 'node:path';
import test from 'node:test';
import vm from 'node:vm';
import { fileURLToPath } from 'node:url';

const here = path.dirname(fileURLToPath(import.meta.url));
const source = fs.readFileSync(path.join(here, '../../web/site/worklet.js'), 'utf8');

function load() {
  const counts = { float32: 0, arrays: 0 };
  const posted = [];
  const context = vm.createContext({ sampleRate: 48000, currentTime: 0 });
  // The context's own intrinsics, counted: every way render() could make an array or a typed array.
  vm.runInContext(`
    globalThis.__counts = { float32: 0, arrays: 0 };
    const F = Float32Array;
    globalThis.Float32Array = new Proxy(F, { construct(target, args) { ++__counts.float32; return Reflect.construct(target, args); } });
    for (const name of ['slice', 'filter', 'map', 'concat', 'splice', 'flat', 'flatMap', 'toSorted', 'toReversed']) {
      const f = Array.prototype[name];
      if (f) Array.prototype[name] = function (...a) { ++__counts.arrays; return f.apply(this, a); };
    }
    const T = Object.getPrototypeOf(Int8Array.prototype);
    for (const name of ['slice', 'subarray', 'map', 'filter']) {
      const f = T[name];
      T[name] = function (...a) { ++__counts.arrays; return f.apply(this, a); };
    }
    const from = Array.from; Array.from = function (...a) { ++__counts.arrays; return from.apply(this, a); };
    class AudioWorkletProcessor { constructor() { this.port = { postMessage: (m) => globalThis.__post(m) }; } }
    globalThis.AudioWorkletProcessor = AudioWorkletProcessor;
    globalThis.registerProcessor = (name, cls) => { globalThis.__processor = cls; };
  `, context);
  context.__post = (m) => posted.push(structuredClone(m));  // postMessage copies, as a port does
  vm.runInContext(source, context);
  const processor = vm.runInContext('new __processor()', context);
  // A fake renderer: 128-frame blocks of a sine in the wasm's memory, live time advancing.
  const memory = new WebAssembly.Memory({ initial: 1, maximum: 4 });
  let live = 0;
  const at = 1024;
  processor.memory = memory;
  processor.exports = {
    vimg_live_time_s: () => live,
    vimg_live_render: (frames) => {
      const samples = new Float32Array(memory.buffer, at, frames);
      for (let i = 0; i < frames; ++i) samples[i] = Math.sin(live * 1000 + i);
      live += frames / 48000;
      return at;
    },
    vimg_live_contacts: () => 10,
    vimg_live_prediction_horizon_s: () => 0.03,
    vimg_live_event_at: () => {},
  };
  const outputs = [[new Float32Array(128), new Float32Array(128)]];
  return { context, processor, memory, outputs, posted, counts: () => vm.runInContext('__counts', context), live: () => live };
}

test('a block of the worklet makes no typed array and no array', () => {
  const w = load();
  const made = w.counts().float32;  // the processor's own (its scope)
  w.processor.process([], w.outputs);  // the first block makes the view
  const before = { ...w.counts() };
  assert.equal(before.float32 - made, 1, 'the first block makes its view of the memory');
  let applied = 0;
  for (let block = 0; block < 2000; ++block) {
    if (block % 3 === 0) {  // ten fingers' events, due within the next block
      for (let f = 0; f < 10; ++f) {
        w.processor.onMessage({ type: 'event', finger: f, phase: 1, x: 10, y: 10, pressure: 1, id: block * 10 + f,
                                time: w.live() + 64 / 48000 });
      }
      applied += 10;
    }
    w.context.currentTime = w.live();
    w.processor.process([], w.outputs);
  }
  const after = w.counts();
  assert.equal(after.float32 - before.float32, 0, 'no Float32Array per block');
  assert.equal(after.arrays - before.arrays, 0, 'no array made by a method per block');
  const reported = w.posted.filter((m) => m.type === 'scope').reduce((n, m) => n + m.applied.length, 0);
  assert.equal(w.processor.pending.length, 0);
  assert.ok(reported <= applied && reported > 0, `every applied event is reported once (${reported} of ${applied})`);
  assert.equal(w.outputs[0][1][5], w.outputs[0][0][5], 'every channel gets the block');
});

test('the view follows the memory when it grows', () => {
  const w = load();
  w.processor.process([], w.outputs);
  const before = w.counts().float32;
  w.processor.process([], w.outputs);
  assert.equal(w.counts().float32, before, 'the same memory: the same view');
  w.memory.grow(1);  // detaches the old buffer
  w.processor.process([], w.outputs);
  assert.equal(w.counts().float32, before + 1, 'a grown memory: one new view');
  assert.equal(w.outputs[0][0].length, 128);
});
