// The AudioWorklet: renders 128-frame blocks at the AudioContext's rate with the same wasm as the
// page (vimg.wasm, instantiated here from the bytes the page posts: Emscripten's loader does not run
// in a worklet). Messages in: {type:'init', wasm, vsc}, {type:'vsc', bytes},
// {type:'event', finger, phase, x, y, pressure, id, time}, {type:'prediction', horizonS}.
// An event's `time` is the pointer sample's own time on the AudioContext's clock (the page maps its
// timeStamp there with the output's pairing of the clocks, audio_clock.js); the renderer applies it at its sample (WebRenderer::live_event_at): inside a
// block when it falls there, at the next block's first sample when it is already past, stamped with
// its own time (at most WebRenderer::kOldestLiveEventS old) so the prediction knows its age. Without
// `time`, an event applies at the next block. The page's horizon adds the output's latency
// (docs/latency.md). Out: {type:'ready'}, {type:'scope', samples, contacts, applied, peak,
// time, horizonS (the prediction horizon in use)}, {type:'error', text} (once, when rendering throws);
// `applied` holds [id, time, first affected sample's time] (context clock, s) of each event applied
// by the blocks since the last report.
// The site's worklet.js is web/wasm/vimg_api.js followed by this file (web/wasm/CMakeLists.txt), so
// the worklet calls the wasm through the same VimgRenderer as the page: one copy-in of a .vsc.
'use strict';

// A NUL-terminated UTF-8 string of the wasm's memory (TextDecoder, where the worklet scope has it).
function utf8At(memory, at) {
  const heap = new Uint8Array(memory.buffer);
  let end = at;
  while (heap[end] !== 0) ++end;
  if (typeof TextDecoder === 'function') return new TextDecoder().decode(heap.subarray(at, end));
  return String.fromCharCode.apply(null, heap.subarray(at, end));
}

class VimgProcessor extends AudioWorkletProcessor {
  constructor() {
    super();
    this.exports = null;
    this.pending = [];           // {id, time, stampS}: events queued in the renderer (live time, context time)
    this.offsetS = null;         // the context's time minus the renderer's live time
    this.scope = new Float32Array(1024);
    this.scopeAt = 0;
    this.peak = 0;
    this.blocks = 0;
    this.applied = [];           // [id, stampS, firstSampleS] since the last report
    // The rendered block, a view of the wasm's memory made again only when the memory grows or the
    // renderer's block moves: a block allocates nothing here (tests/browser/worklet_allocation_test.mjs).
    this.view = null;
    // A message that fails (a wasm that does not instantiate, say) is reported, never swallowed.
    this.port.onmessage = (e) => {
      try {
        this.onMessage(e.data);
      } catch (err) {
        this.port.postMessage({ type: 'error', text: String((err && err.stack) || err) });
      }
    };
  }

  instantiate(bytes) {
    let memory = null;
    const env = {
      emscripten_memcpy_big: (dest, src, n) => new Uint8Array(memory.buffer).copyWithin(dest, src, src + n),
      emscripten_resize_heap: (size) => {
        const pages = Math.ceil((size - memory.buffer.byteLength) / 65536);
        try { memory.grow(pages); return 1; } catch (err) { return 0; }
      },
      abort: () => { throw new Error('vimg.wasm aborted'); },
      __cxa_allocate_exception: () => { throw new Error('vimg.wasm threw'); },
      __cxa_throw: () => { throw new Error('vimg.wasm threw'); },
    };
    const instance = new WebAssembly.Instance(new WebAssembly.Module(bytes), { env });
    memory = instance.exports.memory;
    instance.exports.__wasm_call_ctors();
    this.exports = instance.exports;
    this.memory = memory;
    // VimgRenderer over this instance, with the names Emscripten's loader gives the page (_name, HEAPU8).
    const module = {
      get HEAPU8() { return new Uint8Array(memory.buffer); },
      UTF8ToString: (at) => utf8At(memory, at),
    };
    for (const name of Object.keys(instance.exports)) module['_' + name] = instance.exports[name];
    this.renderer = new VimgRenderer(module);
  }

  onMessage(m) {
    if (m.type === 'init') {
      this.instantiate(m.wasm);
      this.exports.vimg_live_start(sampleRate);
      if (m.vsc) this.renderer.loadVsc(m.vsc);
      this.port.postMessage({ type: 'ready', sampleRate });
    } else if (m.type === 'vsc' && this.exports) {
      this.renderer.loadVsc(m.bytes);
    } else if (m.type === 'event' && this.exports) {
      const x = this.exports;
      const offset = this.offsetS === null ? currentTime - x.vimg_live_time_s() : this.offsetS;
      const t = typeof m.time === 'number' ? m.time - offset : x.vimg_live_time_s();
      x.vimg_live_event_at(t, m.finger, m.phase, m.x, m.y, m.pressure);
      if (m.id !== undefined) this.pending.push({ id: m.id, time: t, stampS: t + offset });
    } else if (m.type === 'prediction' && this.exports) {
      this.exports.vimg_live_set_prediction(m.horizonS);
    }
  }

  // An error here would otherwise stay inside the audio thread: the page reports it as a console error.
  process(inputs, outputs) {
    try {
      return this.render(outputs);
    } catch (err) {
      if (!this.failed) this.port.postMessage({ type: 'error', text: String((err && err.stack) || err) });
      this.failed = true;
      return true;
    }
  }

  // The block just rendered, as a Float32Array over the wasm's memory (the same one while it fits).
  blockAt(at, frames) {
    const v = this.view;
    if (v === null || v.buffer !== this.memory.buffer || v.byteOffset !== at || v.length !== frames) {
      this.view = new Float32Array(this.memory.buffer, at, frames);  // a byte offset
    }
    return this.view;
  }

  // The first sample at or after t (the block's first when already past), on the context's clock.
  firstSampleS(t, start) {
    return this.offsetS + start + Math.max(0, Math.ceil((t - start) * sampleRate - 1e-6)) / sampleRate;
  }

  render(outputs) {
    const out = outputs[0];
    if (!this.exports || out.length === 0) return true;
    const x = this.exports;
    const start = x.vimg_live_time_s();
    this.offsetS = currentTime - start;
    const frames = out[0].length;
    const block = this.blockAt(x.vimg_live_render(frames), frames);
    // The events this block applied (their time is before its end) are reported with it, with their
    // first affected sample; the others stay pending (compacted in place).
    const end = x.vimg_live_time_s();
    const pending = this.pending;
    let kept = 0;
    for (let i = 0; i < pending.length; ++i) {
      const e = pending[i];
      if (e.time < end) this.applied.push([e.id, e.stampS, this.firstSampleS(e.time, start)]);
      else pending[kept++] = e;
    }
    pending.length = kept;
    for (let c = 0; c < out.length; ++c) out[c].set(block);
    let peak = this.peak;
    for (let i = 0; i < frames; ++i) {
      this.scope[this.scopeAt] = block[i];
      this.scopeAt = (this.scopeAt + 1) % this.scope.length;
      // The peak of every block since the last report, so no block's output goes unseen.
      peak = Math.max(peak, Math.abs(block[i]));
    }
    this.peak = peak;
    // The first block that carries an event's effect reports it (the latency benchmark reads this);
    // otherwise every 8th block. postMessage copies the scope and the applied list at once, so both
    // are reused.
    if (this.applied.length > 0 || ++this.blocks % 8 === 0) {
      this.port.postMessage({ type: 'scope', samples: this.scope, at: this.scopeAt, peak: this.peak,
                              contacts: x.vimg_live_contacts(), applied: this.applied, time: currentTime,
                              horizonS: x.vimg_live_prediction_horizon_s() });
      this.applied.length = 0;
      this.peak = 0;
    }
    return true;
  }
}

registerProcessor('vimg-processor', VimgProcessor);
