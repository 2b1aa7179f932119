'use strict';
// The study page (docs/matching-test.md, "The matching test in the browser"): the matching test of
// vimg-player --study on any device. The procedure is the C++ StudyFlow (study/study_flow.hpp)
// in vimg.wasm; this file shows its screens, moves pointer events and samples, and sends each
// answer to the server, keeping it in localStorage until the server confirms it. The link is
// study.html#participant=ID&key=KEY; the key goes in the X-Vimg-Key header, never in a URL.
// window.vimg.ready: a promise that resolves once the study is loaded (rejects when it cannot be);
// window.vimg.study: state(), proceed(), skipTraining(), answer(stem) (docs/web.md).
(function () {
  const $ = (id) => document.getElementById(id);
  const link = new URLSearchParams(location.hash.slice(1));
  const participant = link.get('participant') || '';
  const headers = { 'X-Vimg-Key': link.get('key') || '' };
  const pendingKey = 'vimg.study.pending.' + participant;  // answers the server has not confirmed
  const kScreens = ['welcome', 'training', 'rubbing', 'answering', 'pause', 'end'];
  const kPhaseSections = ['instructions', 'device-check', 'training', 'trial', 'pause', 'done'];
  let pxPerMm = Number(localStorage.getItem('vimg.pxPerMm')) || 96 / 25.4;
  let m = null;            // the wasm module (renderer.module)
  let renderer = null;
  let wasmBytes = null;
  let study = null;        // GET api/state
  let consented = false;
  let audio = null;        // {context, node, worklet}
  let playing = null;      // 'set/image' the output plays
  let shown = null;        // the picture on the stage (training), null: a blank stage (trials)
  const images = new Map();  // 'set/image' -> {bytes, picture}
  const fingers = new Map();
  const api = { study: {} };
  window.vimg = api;

  let loaded = false;       // the study has started in the flow (window.vimg.ready resolved)
  let loadError = null;    // why loading failed
  let refusal = '';        // what to do about an answer the server refused for good
  const now = () => performance.now() / 1000;
  // The line above the screens: a refused answer's message stays until the page is reloaded.
  const status = (text) => {
    $('status').textContent = refusal || text;
    $('status').classList.toggle('problem', refusal !== '');
  };
  const screen = () => kScreens[m._vimg_study_screen()];
  function phase() {
    const s = screen();
    if (s === 'welcome') return consented ? 'device-check' : 'instructions';
    if (s === 'rubbing' || s === 'answering') return 'trial';
    return { training: 'training', pause: 'pause', end: 'done' }[s];
  }
  const setIndex = () => m._vimg_study_set();

  // ---- the server ----
  async function fetchOk(url, options) {
    const r = await fetch(url, Object.assign({ cache: 'no-store' }, options));
    if (!r.ok && r.status !== 409) throw new Error(url + ': HTTP ' + r.status + ' ' + (await r.text()));
    return r;
  }
  const pending = () => JSON.parse(localStorage.getItem(pendingKey) || '[]');
  const keepPending = (list) => localStorage.setItem(pendingKey, JSON.stringify(list));
  let delivering = null;
  const confirmed = new Map();  // trial -> [{resolve, reject}] waiting for its confirmation
  const roundTripsMs = [];      // each confirmed answer's last request, sent to confirmed
  // Worth sending again: a lost network (no reply), too many answers at once (429), a server that
  // failed or cannot open the trial file now (5xx, 503). Any other refusal (400, 403, 404, 409
  // without the trial recorded, 413, ...) is for good: sending the same answer again cannot help.
  const transient = (code) => code === 429 || code >= 500;
  function refusalMessage(code, reply, why) {
    const lost = 'Your last answer (trial ' + reply.trial + ') was not saved: ';
    if (code === 403) return lost + 'the server no longer accepts this link (HTTP 403). Ask the researcher for a new link.';
    if (code === 409) {
      return lost + 'the server has ' + reply.completed + ' trials of yours, not the one before this (HTTP 409). ' +
        'Reload this page to go on from trial ' + (reply.completed + 1) + '.';
    }
    return lost + 'the server refused it (HTTP ' + code + (why ? ': ' + why : '') + '). Reload this page; ' +
      'if this message comes again, tell the researcher.';
  }
  // Settles a kept answer: confirmed (null) or refused for good (the message). A refused answer
  // leaves the list of kept answers for vimg.study.refused.ID, so that it is not lost without a trace.
  function settle(trial, message) {
    if (message) {
      const refusedKey = 'vimg.study.refused.' + participant;
      const kept = pending().filter((a) => a.trial === trial);
      localStorage.setItem(refusedKey, JSON.stringify(JSON.parse(localStorage.getItem(refusedKey) || '[]').concat(kept)));
    }
    keepPending(pending().filter((a) => a.trial !== trial));
    for (const waiter of confirmed.get(trial) || []) {
      if (message) waiter.reject(new Error(message));
      else waiter.resolve();
    }
    confirmed.delete(trial);
  }
  // Sends the kept answers in order until each is settled: confirmed (200, or 409 with the trial
  // recorded) or refused for good (the participant is told what to do). A lost network, a stopped
  // server, 429 and 5xx are tried again, at once, then at most every 2 s.
  function deliver() {
    if (!delivering) {
      delivering = sendKept().finally(() => {
        delivering = null;
        if (pending().length > 0) deliver();  // kept while the last round was ending
      });
    }
    return delivering;
  }
  async function sendKept() {
    let wait_ms = 100;
    for (let list = pending(); list.length > 0; list = pending()) {
      const first = list[0];
      let done = false;
      let refused = '';
      const sent_ms = performance.now();
      try {
        const r = await fetch('api/answer', { method: 'POST', cache: 'no-store', body: first.body,
          headers: Object.assign({ 'Content-Type': 'application/x-www-form-urlencoded' }, headers) });
        const text = await r.text();
        let reply = null;
        try { reply = JSON.parse(text); } catch (err) { reply = null; }
        done = (r.status === 200 || r.status === 409) && reply !== null && reply.completed >= first.trial;
        if (!done && !transient(r.status)) {
          refused = refusalMessage(r.status, { trial: first.trial, completed: reply ? reply.completed : 0 },
                                   reply ? reply.error : text.trim().slice(0, 200));
        } else if (!done) {
          status('saving… (the server answered HTTP ' + r.status + '; retrying)');
        }
      } catch (err) {
        status('saving… (the server is not reachable; retrying)');
      }
      if (done) {
        roundTripsMs.push(performance.now() - sent_ms);
        settle(first.trial, null);
        wait_ms = 100;
        status('');
      } else if (refused) {
        refusal = refused;
        status('');
        settle(first.trial, refused);
      } else {
        await new Promise((resolve) => setTimeout(resolve, wait_ms));
        wait_ms = Math.min(2000, wait_ms * 2);
      }
    }
  }
  window.addEventListener('online', () => deliver());

  function deviceFields() {
    const latency = audio ? (audio.context.baseLatency || 0) + (audio.context.outputLatency || 0) : 0;
    return '&device_user_agent=' + encodeURIComponent(navigator.userAgent.slice(0, 512).replace(/[^\x20-\x7e]/g, '?')) +
      '&device_screen_width_mm=' + screen_mm(screen_px().w) + '&device_screen_height_mm=' + screen_mm(screen_px().h) +
      '&device_audio_rate_hz=' + (audio ? audio.context.sampleRate : 0) + '&device_output_latency_s=' + latency;
  }
  const screen_px = () => ({ w: window.screen.width, h: window.screen.height });
  const screen_mm = (px) => Math.min(10000, Math.max(1, px / pxPerMm));

  // ---- images: fetched once, drawn by picture.js ----
  async function image(set, index) {
    const id = set + '/' + index;
    if (!images.has(id)) {
      const r = await fetchOk('images/' + encodeURIComponent(study.sets[set].files[index]) + '.vsc');
      const bytes = new Uint8Array(await r.arrayBuffer());
      renderer.loadVsc(bytes);
      images.set(id, { bytes, picture: renderer.picture() });
    }
    return images.get(id);
  }
  function play(set, index) {
    const id = set + '/' + index;
    if (playing === id || !images.has(id)) return;
    playing = id;
    const bytes = images.get(id).bytes;
    if (audio && audio.worklet) audio.node.port.postMessage({ type: 'vsc', bytes: bytes.slice().buffer });
    if (audio && !audio.worklet) renderer.loadVsc(bytes);
  }
  const drawPicture = VimgPicture.draw;
  const figure = VimgPicture.figure;

  // ---- the screens ----
  // Pictures of a set at one common scale, the largest that fits two by two, at most true size.
  function thumbScale(set) {
    const pictures = study.sets[set].images.map((_, i) => images.get(set + '/' + i).picture);
    const w = Math.max(...pictures.map((p) => p.width_mm)), h = Math.max(...pictures.map((p) => p.height_mm));
    return Math.min(pxPerMm, (window.innerWidth - 60) / (2 * w), (window.innerHeight - 200) / (2 * h));
  }
  function render() {
    const p = phase();
    for (const id of kPhaseSections) $(id).classList.toggle('shown', id === p);
    const set = setIndex();
    const stage = $('stage');
    stage.hidden = true;
    if (p === 'instructions') {
      $('instructions-text').textContent = study.instructions;
      $('consent-text').textContent = study.consent;
    } else if (p === 'device-check') {
      const n = navigator.maxTouchPoints;
      $('touch-state').textContent = n > 0 ? 'present (' + n + (n === 1 ? ' point)' : ' points)')
                                           : 'none found: use the device\'s touch screen';
    } else if (p === 'training') {
      $('training-set').textContent = study.sets[set].name;
      const selected = m._vimg_study_training_picture();
      const thumbs = $('thumbs');
      thumbs.textContent = '';
      study.sets[set].images.forEach((name, i) => {
        const f = figure(images.get(set + '/' + i).picture, name, thumbScale(set) / 2, () => {
          m._vimg_study_show_training_picture(i);
          render();
        });
        if (i === selected) f.classList.add('selected');
        thumbs.appendChild(f);
      });
      shown = images.get(set + '/' + selected).picture;
      drawPicture(stage, shown, pxPerMm);
      stage.hidden = false;
      play(set, selected);
    } else if (p === 'trial') {
      $('trial-number').textContent = m._vimg_study_trial();
      $('trial-total').textContent = m._vimg_study_total();
      const presented = m._vimg_study_presented();
      const rubbing = screen() === 'rubbing';
      $('answer').hidden = !rubbing;
      $('answer').disabled = !m._vimg_study_can_answer();
      $('trial-hint').textContent = rubbing ? 'Rub the grey area, then press Answer.' : 'Which picture did you feel?';
      const choices = $('choices');
      choices.textContent = '';
      if (rubbing) {
        shown = null;
        drawPicture(stage, images.get(set + '/' + presented).picture, pxPerMm, { blank: true });
        stage.hidden = false;
        play(set, presented);
      } else {
        study.sets[set].images.forEach((name, i) => {
          choices.appendChild(figure(images.get(set + '/' + i).picture, name, thumbScale(set), () => choose(i).catch(() => {})));
        });
      }
    } else if (p === 'pause') {
      $('next-set').textContent = study.sets[setIndex()].name;
    }
  }

  // ---- pointer events on the stage, in mm through the calibration ----
  function onPointer(e, ph) {
    const s = screen();
    if (s !== 'rubbing' && s !== 'training') return;
    const samples = ph === 1 && e.getCoalescedEvents ? e.getCoalescedEvents() : [];
    for (const sample of samples.length > 0 ? samples : [e]) onSample(sample, ph);
    e.preventDefault();
    if (s === 'rubbing') $('answer').disabled = !m._vimg_study_can_answer();
  }
  function onSample(e, ph) {
    const r = $('stage').getBoundingClientRect();
    const x = (e.clientX - r.left) / pxPerMm, y = (e.clientY - r.top) / pxPerMm;
    let f = fingers.get(e.pointerId);
    if (ph === 0) {
      if (!audio) startAudio().catch((err) => status(String(err)));  // a touch is a user activation
      const used = new Set([...fingers.values()].map((v) => v.finger));
      let finger = 0;
      while (used.has(finger)) ++finger;
      if (finger >= 10) return;
      f = { finger };
      fingers.set(e.pointerId, f);
      $('stage').setPointerCapture(e.pointerId);
    }
    if (!f) return;
    m._vimg_study_touch(e.timeStamp / 1000, f.finger, ph, x, y);
    const pressure = e.pointerType === 'mouse' || !(e.pressure > 0) ? 1 : e.pressure;
    if (audio && audio.worklet) {
      const age = (performance.now() - e.timeStamp) / 1000;
      audio.node.port.postMessage({ type: 'event', finger: f.finger, phase: ph, x, y, pressure, age });
    } else if (audio) {
      renderer.liveEvent(f.finger, ph, x, y, pressure);
    }
    if (ph === 2) fingers.delete(e.pointerId);
  }

  // ---- the output: the AudioWorklet in a secure context, else a ScriptProcessorNode (docs/web.md) ----
  async function startAudio() {
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
      const first = playing ? images.get(playing).bytes.slice().buffer : null;
      audio.node.port.postMessage({ type: 'init', wasm: wasmBytes.slice().buffer, vsc: first });
      audio.node.connect(context.destination);
      await ready;
    } else {
      audio.node = context.createScriptProcessor(256, 0, 1);
      renderer.liveStart(context.sampleRate);
      if (playing) renderer.loadVsc(images.get(playing).bytes);
      audio.node.onaudioprocess = (e) => e.outputBuffer.getChannelData(0).set(renderer.liveRender(e.outputBuffer.length));
      audio.node.connect(context.destination);
    }
    await context.resume();
    const latency_ms = 1000 * ((context.baseLatency || 0) + (context.outputLatency || 0));
    $('audio-state').textContent = 'on: ' + context.sampleRate + ' Hz, ' + (audio.worklet ? 'AudioWorklet' : 'ScriptProcessor') +
      ', reported latency ' + latency_ms.toFixed(1) + ' ms';
  }

  function setPxPerMm(v) {
    pxPerMm = v;
    localStorage.setItem('vimg.pxPerMm', String(v));
    $('ppmm').value = v;
    $('ppmm-value').textContent = v.toFixed(2) + ' CSS px per mm';
    $('ruler').style.width = 50 * v + 'px';
  }

  // ---- a person's actions, and window.vimg.study (each returns once the page has moved on) ----
  // The choice of picture `index`: the trial's row is kept until the server confirms it.
  function choose(index) {
    if (!m._vimg_study_choose(index, now())) return Promise.reject(new Error('no choice is asked for now'));
    const trial = m._vimg_study_result_trial();
    const set = m._vimg_study_result_set();
    const stems = study.sets[set].images;
    const body = 'participant=' + encodeURIComponent(participant) + '&trial=' + trial +
      '&presented=' + encodeURIComponent(stems[m._vimg_study_result_presented()]) +
      '&chosen=' + encodeURIComponent(stems[m._vimg_study_result_chosen()]) +
      '&rub_s=' + m._vimg_study_result_rub_s() + '&response_s=' + m._vimg_study_result_response_s() +
      '&path_mm=' + m._vimg_study_result_path_mm() + deviceFields();
    keepPending(pending().concat([{ trial, body }]));
    const done = new Promise((resolve, reject) => confirmed.set(trial, (confirmed.get(trial) || []).concat([{ resolve, reject }])));
    deliver();
    render();
    return done;
  }
  // The calls below need the study loaded: state() says 'loading' (or 'error') until then.
  const whenLoaded = () => {
    if (!loaded) throw new Error('the study is not loaded yet (await window.vimg.ready)');
  };
  api.study.state = () => {
    if (loadError) return { phase: 'error', error: loadError };
    if (!loaded) return { phase: 'loading' };
    const set = setIndex();
    return { phase: phase(), set: study.sets[set].name, trial: m._vimg_study_trial(), trials: m._vimg_study_total(),
             choices: study.sets[set].images.slice() };
  };
  api.study.proceed = async () => {
    whenLoaded();
    const p = phase();
    if (p === 'instructions') {
      consented = true;
    } else if (p === 'device-check') {
      await startAudio();
      m._vimg_study_begin(now());
    } else if (p === 'pause') {
      m._vimg_study_resume(now());
    } else if (p === 'training') {
      m._vimg_study_skip_training(now());
    } else {
      throw new Error('the ' + p + ' screen has no button to press');
    }
    render();
  };
  api.study.skipTraining = async () => {
    whenLoaded();
    if (phase() !== 'training') throw new Error('not training');
    m._vimg_study_skip_training(now());
    render();
  };
  api.study.answer = async (stem) => {
    whenLoaded();
    if (phase() !== 'trial') throw new Error('not in a trial');
    const index = study.sets[setIndex()].images.indexOf(stem);
    if (index < 0) throw new Error(stem + ' is not an image of set ' + study.sets[setIndex()].name);
    if (screen() === 'rubbing' && !m._vimg_study_answer(now())) throw new Error('rub the screen before answering');
    await choose(index);
  };
  // For tests: where a pointer must be to touch the stage at (x, y) mm, and the answers not yet confirmed.
  api.clientPointOfMm = (x, y) => {
    const r = $('stage').getBoundingClientRect();
    return { x: r.left + x * pxPerMm, y: r.top + y * pxPerMm };
  };
  api.study.unconfirmed = () => pending().length;
  api.study.delivering = () => delivering !== null;  // answers are being sent (or a retry waits)
  api.study.refusal = () => refusal;                  // the message of an answer refused for good, or ''

  api.study.roundTripsMs = () => roundTripsMs.slice();
  api.audioContext = () => (audio ? audio.context : null);  // for tools: the output's context

  // ---- start: the wasm, the participant's state (retried until the server answers), the flow ----
  async function loadState() {
    for (let wait_ms = 200; ; wait_ms = Math.min(2000, wait_ms * 2)) {
      let r = null;
      try {
        r = await fetch('api/state?participant=' + encodeURIComponent(participant), { headers, cache: 'no-store' });
      } catch (err) {
        status('the server is not reachable; retrying…');
      }
      if (r && r.ok) return r.json();
      if (r && r.status === 403) throw new Error('this link is not valid (ask the researcher for yours)');
      if (r) status('the server answered HTTP ' + r.status + '; retrying…');
      await new Promise((resolve) => setTimeout(resolve, wait_ms));
    }
  }
  function copyInts(values) {
    const at = m._malloc(4 * Math.max(1, values.length));
    m.HEAP32.set(values, at >> 2);
    return at;
  }
  api.ready = (async () => {
    setPxPerMm(pxPerMm);
    const r = await fetchOk('vimg.wasm');
    wasmBytes = new Uint8Array(await r.arrayBuffer());
    renderer = await VimgRenderer.create({ wasmBinary: wasmBytes.slice() });
    m = renderer.module;
    await loadState();
    await deliver();  // answers kept from an earlier visit go first
    study = await loadState();
    study.instructions = study.instructions || 'Each trial shows no picture. Rub the grey area to feel an image, ' +
      'press Answer, then tap the picture you felt. Each set begins with training: rub each picture to learn how it feels.';
    study.consent = study.consent || 'Your answers (the picture chosen, the times and the length of your rubbing) and a ' +
      'description of this device are stored by the researcher under your participant ID.';
    for (let s = 0; s < study.sets.length; ++s) {
      for (let i = 0; i < study.sets[s].files.length; ++i) await image(s, i);
    }
    const counts = copyInts(study.sets.map((s) => s.images.length));
    const plan = copyInts(study.plan.flat());
    const ok = m._vimg_study_start(counts, study.sets.length, plan, study.plan.length, study.completed, study.training_s, 1, now());
    m._free(counts);
    m._free(plan);
    if (!ok) throw new Error('the study\'s plan does not match its sets');
    $('consent').addEventListener('click', () => api.study.proceed());
    $('device-ok').addEventListener('click', () => api.study.proceed().catch((err) => status(String(err))));
    $('audio-start').addEventListener('click', () => startAudio().catch((err) => status(String(err))));
    $('ppmm').addEventListener('input', (e) => setPxPerMm(Number(e.target.value)));
    $('training-end').addEventListener('click', () => api.study.proceed());
    $('continue').addEventListener('click', () => api.study.proceed());
    $('answer').addEventListener('click', () => { if (m._vimg_study_answer(now())) render(); });
    const stage = $('stage');
    stage.addEventListener('pointerdown', (e) => onPointer(e, 0));
    stage.addEventListener('pointermove', (e) => onPointer(e, 1));
    stage.addEventListener('pointerup', (e) => onPointer(e, 2));
    stage.addEventListener('pointercancel', (e) => onPointer(e, 2));
    // The training countdown runs in the flow; the page only shows it and follows its end.
    const frame = () => {
      if (screen() === 'training') {
        m._vimg_study_tick(now());
        if (screen() !== 'training') render();
        else $('training-left').textContent = Math.ceil(m._vimg_study_training_left_s(now())) + ' s left';
      }
      requestAnimationFrame(frame);
    };
    requestAnimationFrame(frame);
    loaded = true;
    render();
    status(study.completed > 0 && !study.finished ? 'welcome back: the study goes on at trial ' + (study.completed + 1) : '');
  })();
  api.ready.catch((err) => {
    loadError = err.message;
    status('error: ' + err.message);
  });
})();
