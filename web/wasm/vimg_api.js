// The renderer's JavaScript face, appended to vimg.js after Emscripten's loader (--extern-post-js)
// and put in front of the site's worklet.js, so the page, its AudioWorklet, the Node tests and the
// benchmark all call the wasm through these same few lines.
// Nothing here models anything: every value comes from the C++ (web/wasm/exports.cpp).
var VimgRenderer = (function () {
  'use strict';

  function VimgRenderer(module) {
    this.module = module;
  }

  // Creates the module. `options.wasmBinary` (bytes) skips fetching vimg.wasm (Node, workers).
  VimgRenderer.create = function (options) {
    return createVimgModule(options || {}).then(function (module) {
      return new VimgRenderer(module);
    });
  };

  VimgRenderer.prototype.copyIn = function (bytes) {
    var m = this.module;
    var at = m._malloc(Math.max(1, bytes.length));
    m.HEAPU8.set(bytes, at);
    return at;
  };

  VimgRenderer.prototype.lastError = function () {
    return this.module.UTF8ToString(this.module._vimg_last_error());
  };

  // Loads a compiled image (.vsc bytes); throws with the reader's message when it is not valid.
  VimgRenderer.prototype.loadVsc = function (bytes) {
    var m = this.module;
    var at = this.copyIn(bytes instanceof Uint8Array ? bytes : new Uint8Array(bytes));
    var ok = m._vimg_load_vsc(at, bytes.byteLength);
    m._free(at);
    if (!ok) throw new Error(this.lastError());
    return { widthMm: m._vimg_canvas_width_mm(), heightMm: m._vimg_canvas_height_mm() };
  };

  // The drive of a gesture CSV as `vimg render IMAGE --gesture G --out F.csv` writes it: one sample
  // per 1/rate s from min(0, the gesture's start). Throws with the parser's message.
  VimgRenderer.prototype.renderGesture = function (csvText, rateHz) {
    var m = this.module;
    var bytes = new TextEncoder().encode(csvText);
    var at = this.copyIn(bytes);
    var n = m._vimg_render_gesture(at, bytes.length, rateHz || m._vimg_default_render_rate_hz());
    m._free(at);
    if (n < 0) throw new Error(this.lastError());
    var from = m._vimg_rendered_samples() >> 2;
    return m.HEAPF32.slice(from, from + n);
  };

  // The picture to draw (web/wasm/picture_json.hpp).
  VimgRenderer.prototype.picture = function () {
    return JSON.parse(this.module.UTF8ToString(this.module._vimg_picture_json()));
  };

  // Live rendering on this thread (the fallback without AudioWorklet, and the vibrate mode).
  VimgRenderer.prototype.liveStart = function (rateHz) { this.module._vimg_live_start(rateHz); };
  VimgRenderer.prototype.liveEvent = function (finger, phase, xMm, yMm, pressure) {
    var m = this.module;
    m._vimg_live_event(m._vimg_live_time_s(), finger, phase, xMm, yMm, pressure);
  };
  // The same event at its time on the live stream's clock (s): the next liveRender applies it at its
  // sample, or at its first sample when the time is already past (WebRenderer::live_event_at).
  VimgRenderer.prototype.liveEventAt = function (timeS, finger, phase, xMm, yMm, pressure) {
    this.module._vimg_live_event_at(timeS, finger, phase, xMm, yMm, pressure);
  };
  VimgRenderer.prototype.liveTimeS = function () { return this.module._vimg_live_time_s(); };
  // Touch-latency compensation (docs/latency.md): the defaults and the bound come from the C++.
  VimgRenderer.prototype.touchLatencyDefaultMs = function (pointerType) {
    return this.module._vimg_touch_latency_default_ms(pointerType === 'touch' ? 0 : 1);
  };
  VimgRenderer.prototype.touchLatencyMaxMs = function () { return this.module._vimg_touch_latency_max_ms(); };
  VimgRenderer.prototype.liveSetPrediction = function (horizonS) { this.module._vimg_live_set_prediction(horizonS); };
  // The rate renderGesture uses when none is given: `vimg render`'s (player/render_defaults.hpp).
  VimgRenderer.prototype.defaultRenderRateHz = function () { return this.module._vimg_default_render_rate_hz(); };
  // How many fingers the live renderer follows at once (player/render_defaults.hpp).
  VimgRenderer.prototype.maxLiveFingers = function () { return this.module._vimg_max_live_fingers(); };
  VimgRenderer.prototype.predictionModels = function () {
    var m = this.module, names = [];
    for (var i = 0; i < m._vimg_prediction_model_count(); ++i) names.push(m.UTF8ToString(m._vimg_prediction_model_name(i)));
    return names;
  };
  // The seconds `repeats` finger predictions take with `model` ('none', 'linear' or 'fitted'), as
  // touch_prediction_bench's BM_Predict measures them natively (bench/web_render_bench.mjs).
  VimgRenderer.prototype.benchPredict = function (repeats, model) {
    var index = this.predictionModels().indexOf(model);
    if (index < 0) throw new Error('unknown prediction model: ' + model);
    var t0 = (typeof performance !== 'undefined' ? performance : Date).now();
    this.module._vimg_bench_predict(repeats, index);
    return ((typeof performance !== 'undefined' ? performance : Date).now() - t0) / 1000;
  };
  VimgRenderer.prototype.liveRender = function (frames) {
    var at = this.module._vimg_live_render(frames) >> 2;
    return this.module.HEAPF32.subarray(at, at + frames);
  };

  VimgRenderer.prototype.renderedStartS = function () {
    return this.module._vimg_rendered_start_s();
  };

  return VimgRenderer;
})();
// On the loader (vimg.js) for Node and the page; the worklet (worklet.js) has no loader.
if (typeof createVimgModule !== 'undefined') createVimgModule.VimgRenderer = VimgRenderer;
