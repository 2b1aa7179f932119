'use strict';
// The study page's touch input (docs/matching-test.md, "The matching test in the browser"): pointer
// events on the stage, with the samples the browser coalesced, in mm through the ruler calibration,
// each finger numbered 0..9, to the flow (StudyFlow's touches: the rubbing that allows Answer and
// its path) and to the sound output (study_audio.js). Only while training or rubbing. Used by study.js.
const VimgStudyTouch = (function () {
  // stage: the canvas; m: the wasm module; output: VimgStudyAudio's; pxPerMm(): the calibration;
  // screen(): the flow's screen; status(text): the line above the screens.
  function attach(stage, { m, output, pxPerMm, screen, status }) {
    const fingers = new Map();  // pointerId -> {finger}
    const answer = document.getElementById('answer');
    function onPointer(e, ph) {
      const s = screen();
      if (s !== 'rubbing' && s !== 'training') return;
      const samples = ph === 1 && e.getCoalescedEvents ? e.getCoalescedEvents() : [];
      for (const sample of samples.length > 0 ? samples : [e]) onSample(sample, ph);
      e.preventDefault();
      if (s === 'rubbing') answer.disabled = !m._vimg_study_can_answer();
    }
    function onSample(e, ph) {
      const r = stage.getBoundingClientRect();
      const x = (e.clientX - r.left) / pxPerMm(), y = (e.clientY - r.top) / pxPerMm();
      let f = fingers.get(e.pointerId);
      if (ph === 0) {
        if (!output.started()) output.start().catch((err) => status(String(err)));  // a touch is a user activation
        const used = new Set([...fingers.values()].map((v) => v.finger));
        let finger = 0;
        while (used.has(finger)) ++finger;
        if (finger >= 10) return;
        f = { finger };
        fingers.set(e.pointerId, f);
        stage.setPointerCapture(e.pointerId);
      }
      if (!f) return;
      m._vimg_study_touch(e.timeStamp / 1000, f.finger, ph, x, y);
      const pressure = e.pointerType === 'mouse' || !(e.pressure > 0) ? 1 : e.pressure;
      output.event(f.finger, ph, x, y, pressure, e.timeStamp);
      if (ph === 2) fingers.delete(e.pointerId);
    }
    stage.addEventListener('pointerdown', (e) => onPointer(e, 0));
    stage.addEventListener('pointermove', (e) => onPointer(e, 1));
    stage.addEventListener('pointerup', (e) => onPointer(e, 2));
    stage.addEventListener('pointercancel', (e) => onPointer(e, 2));
  }
  return { attach };
})();
