'use strict';
// The study page's sound output (docs/matching-test.md, "The matching test in the browser";
// docs/web-audio.md, "Outputs per platform"): the AudioWorklet (worklet.js, which instantiates vimg.wasm
// itself from the bytes posted to it) in a secure context, else a ScriptProcessorNode rendered by
// the page's own renderer; which image it plays, and the pointer samples it renders. Used by
// study.js (start, play) and study_touch.js (event).
const VimgStudyAudio = (function () {
  // renderer: the page's VimgRenderer; wasmBytes: vimg.wasm's bytes; onStarted(text): what runs
  // (rate, output, reported latency), said once the sound has started.
  function create(renderer, wasmBytes, onStarted) {
    let audio = null;         // {context, node, worklet}
    let playing = null;       // 'set/image' the output plays
    let playingBytes = null;  // its .vsc

    // Starts the output (a user activation must come first: a click or a touch); once only.
    async function start() {
      if (audio) return;
      const context = new AudioContext({ latencyHint: 'interactive' });
      audio = { context, worklet: Boolean(context.audioWorklet && window.isSecureContext) };
      if (audio.worklet) {
        await context.audioWorklet.addModule('worklet.js');
        audio.node = new AudioWorkletNode(context, 'vimg-processor', { numberOfInputs: 0, outputChannelCount: [2] });
        const ready = new Promise((resolve, reject) => {
          audio.node.port.onmessage = (e) => {
            if (e.data.type === 'ready') resolve();
            if (e.data.type === 'error') { console.error('vimg worklet: ' + e.data.text); reject(new Error(e.data.text)); }
          };
        });
        const first = playing ? playingBytes.slice().buffer : null;
        audio.node.port.postMessage({ type: 'init', wasm: wasmBytes.slice().buffer, vsc: first });
        audio.node.connect(context.destination);
        await ready;
      } else {
        audio.node = context.createScriptProcessor(256, 0, 1);
        renderer.liveStart(context.sampleRate);
        if (playing) renderer.loadVsc(playingBytes);
        audio.node.onaudioprocess = (e) => e.outputBuffer.getChannelData(0).set(renderer.liveRender(e.outputBuffer.length));
        audio.node.connect(context.destination);
      }
      await context.resume();
      const latency_ms = 1000 * ((context.baseLatency || 0) + (context.outputLatency || 0));
      onStarted('on: ' + context.sampleRate + ' Hz, ' + (audio.worklet ? 'AudioWorklet' : 'ScriptProcessor') +
        ', reported latency ' + latency_ms.toFixed(1) + ' ms');
    }
    // Plays image `id` ('set/image', its .vsc `bytes`) from now on, or from the start.
    function play(id, bytes) {
      if (playing === id) return;
      playing = id;
      playingBytes = bytes;
      if (audio && audio.worklet) audio.node.port.postMessage({ type: 'vsc', bytes: bytes.slice().buffer });
      if (audio && !audio.worklet) renderer.loadVsc(bytes);
    }
    // A pointer sample (phase 0 down, 1 move, 2 up; mm) to the renderer that plays, if one does.
    function event(finger, phase, x, y, pressure, timeStamp) {
      if (audio && audio.worklet) {
        const age = (performance.now() - timeStamp) / 1000;
        audio.node.port.postMessage({ type: 'event', finger, phase, x, y, pressure, age });
      } else if (audio) {
        renderer.liveEvent(finger, phase, x, y, pressure);
      }
    }
    return {
      start,
      play,
      event,
      started: () => audio !== null,
      context: () => (audio ? audio.context : null),  // the output's AudioContext, null before start()
    };
  }
  return { create };
})();
