'use strict';
// The study page (docs/matching-test.md, "The matching test in the browser"): the matching test of
// vimg-player --study on any device. The procedure is the C++ StudyFlow (study/study_flow.hpp)
// in vimg.wasm; this file loads the study and drives the flow: the person's actions and
// window.vimg.study, each trial's answer, the training countdown. The link is
// study.html#participant=ID&key=KEY; the key goes in the X-Vimg-Key header, never in a URL.
// window.vimg.ready: a promise that resolves once the study is loaded (rejects when it cannot be);
// window.vimg.study: state(), proceed(), skipTraining(), answer(stem) (docs/web-study.md).
// Beside it (study.html loads them first): study_answers.js (each answer kept until the server
// confirms it, and the retries), study_screens.js (the screens and the pictures to choose from),
// study_touch.js (pointer events to the flow and the output), study_audio.js (the sound output).
(function () {
  const $ = (id) => document.getElementById(id);
  const link = new URLSearchParams(location.hash.slice(1));
  const participant = link.get('participant') || '';
  const headers = { 'X-Vimg-Key': link.get('key') || '' };
  const kScreens = ['welcome', 'training', 'rubbing', 'answering', 'pause', 'end'];
  let pxPerMm = Number(localStorage.getItem('vimg.pxPerMm')) || 96 / 25.4;
  let m = null;            // the wasm module (renderer.module)
  let renderer = null;
  let study = null;        // GET api/state
  let consented = false;
  let output = null;       // the sound output (study_audio.js)
  let screens = null;      // the screens (study_screens.js)
  const images = new Map();  // 'set/image' -> {bytes, picture}
  const api = { study: {} };
  window.vimg = api;

  let loaded = false;       // the study has started in the flow (window.vimg.ready resolved)
  let loadError = null;    // why loading failed
  const now = () => performance.now() / 1000;
  // The line above the screens: a refused answer's message stays until the page is reloaded.
  const status = (text) => {
    const refusal = answers.refusal();
    $('status').textContent = refusal || text;
    $('status').classList.toggle('problem', refusal !== '');
  };
  const answers = VimgStudyAnswers.create(participant, headers, status);
  const screen = () => kScreens[m._vimg_study_screen()];
  function phase() {
    const s = screen();
    if (s === 'welcome') return consented ? 'device-check' : 'instructions';
    if (s === 'rubbing' || s === 'answering') return 'trial';
    return { training: 'training', pause: 'pause', end: 'done' }[s];
  }
  const setIndex = () => m._vimg_study_set();
  const render = () => screens.render();
  const startAudio = () => output.start();

  async function fetchOk(url, options) {
    const r = await fetch(url, Object.assign({ cache: 'no-store' }, options));
    if (!r.ok && r.status !== 409) throw new Error(url + ': HTTP ' + r.status + ' ' + (await r.text()));
    return r;
  }

  function deviceFields() {
    const context = output ? output.context() : null;
    const latency = context ? (context.baseLatency || 0) + (context.outputLatency || 0) : 0;
    return '&device_user_agent=' + encodeURIComponent(navigator.userAgent.slice(0, 512).replace(/[^\x20-\x7e]/g, '?')) +
      '&device_screen_width_mm=' + screen_mm(screen_px().w) + '&device_screen_height_mm=' + screen_mm(screen_px().h) +
      '&device_audio_rate_hz=' + (context ? context.sampleRate : 0) + '&device_output_latency_s=' + latency;
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
    const done = answers.keep(trial, body);
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
  api.study.unconfirmed = () => answers.unconfirmed();
  api.study.delivering = () => answers.delivering();  // answers are being sent (or a retry waits)
  api.study.refusal = () => answers.refusal();        // the message of an answer refused for good, or ''

  api.study.roundTripsMs = () => answers.roundTripsMs();
  api.audioContext = () => (output ? output.context() : null);  // for tools: the output's context

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
    const wasmBytes = new Uint8Array(await r.arrayBuffer());
    renderer = await VimgRenderer.create({ wasmBinary: wasmBytes.slice() });
    m = renderer.module;
    output = VimgStudyAudio.create(renderer, wasmBytes, (text) => { $('audio-state').textContent = text; });
    await loadState();
    await answers.deliver();  // answers kept from an earlier visit go first
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
    screens = VimgStudyScreens.create({ m, study, images, output, pxPerMm: () => pxPerMm, phase, screen, choose });
    $('consent').addEventListener('click', () => api.study.proceed());
    $('device-ok').addEventListener('click', () => api.study.proceed().catch((err) => status(String(err))));
    $('audio-start').addEventListener('click', () => startAudio().catch((err) => status(String(err))));
    $('ppmm').addEventListener('input', (e) => setPxPerMm(Number(e.target.value)));
    $('training-end').addEventListener('click', () => api.study.proceed());
    $('continue').addEventListener('click', () => api.study.proceed());
    $('answer').addEventListener('click', () => { if (m._vimg_study_answer(now())) render(); });
    VimgStudyTouch.attach($('stage'), { m, output, pxPerMm: () => pxPerMm, screen, status });
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
