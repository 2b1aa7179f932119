'use strict';
// The study page's screens (docs/matching-test.md, "The matching test in the browser"): the section
// of the flow's phase shown, and in it the instructions and consent, the device check's touch
// screen, training (the set's pictures as thumbnails, the selected one at true size on the stage and
// played), a trial (a blank stage of the image's size to rub, then the set's pictures to choose
// from, at one common scale) and the pause. Pictures are drawn by picture.js. Used by study.js.
const VimgStudyScreens = (function () {
  const kPhaseSections = ['instructions', 'device-check', 'training', 'trial', 'pause', 'done'];
  const $ = (id) => document.getElementById(id);
  const drawPicture = VimgPicture.draw;
  const figure = VimgPicture.figure;

  // m: the wasm module; study: the participant's state (GET api/state); images: 'set/image' ->
  // {bytes, picture}; output: VimgStudyAudio's; pxPerMm(): the calibration; phase(), screen(): where
  // the flow is; choose(index): the choice of a picture (a promise).
  function create({ m, study, images, output, pxPerMm, phase, screen, choose }) {
    function play(set, index) {
      const id = set + '/' + index;
      if (images.has(id)) output.play(id, images.get(id).bytes);
    }
    // Pictures of a set at one common scale, the largest that fits two by two, at most true size.
    function thumbScale(set) {
      const pictures = study.sets[set].images.map((_, i) => images.get(set + '/' + i).picture);
      const w = Math.max(...pictures.map((p) => p.width_mm)), h = Math.max(...pictures.map((p) => p.height_mm));
      return Math.min(pxPerMm(), (window.innerWidth - 60) / (2 * w), (window.innerHeight - 200) / (2 * h));
    }
    function render() {
      const p = phase();
      for (const id of kPhaseSections) $(id).classList.toggle('shown', id === p);
      const set = m._vimg_study_set();
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
        drawPicture(stage, images.get(set + '/' + selected).picture, pxPerMm());
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
          drawPicture(stage, images.get(set + '/' + presented).picture, pxPerMm(), { blank: true });
          stage.hidden = false;
          play(set, presented);
        } else {
          study.sets[set].images.forEach((name, i) => {
            choices.appendChild(figure(images.get(set + '/' + i).picture, name, thumbScale(set), () => choose(i).catch(() => {})));
          });
        }
      } else if (p === 'pause') {
        $('next-set').textContent = study.sets[m._vimg_study_set()].name;
      }
    }
    return { render };
  }
  return { create };
})();
