'use strict';
// A picture as web/wasm/picture_json.hpp gives it (geometry in mm, the PNG palette), drawn on a
// canvas at `scale` CSS px per mm: the player page (index.html) and the study page (study.js).
// Options: `blank` draws only the canvas's area (a trial's unseen image), `lit` (a Set of item
// indices) draws those items in the highlight colour.
const VimgPicture = (function () {
  const css = (c, a) => 'rgba(' + c[0] + ',' + c[1] + ',' + c[2] + ',' + a + ')';
  function drawPicture(canvas, picture, scale, { blank = false, lit = null } = {}) {
    const dpr = window.devicePixelRatio || 1;
    canvas.style.width = picture.width_mm * scale + 'px';
    canvas.style.height = picture.height_mm * scale + 'px';
    canvas.width = Math.round(picture.width_mm * scale * dpr);
    canvas.height = Math.round(picture.height_mm * scale * dpr);
    const ctx = canvas.getContext('2d');
    ctx.setTransform(scale * dpr, 0, 0, scale * dpr, 0, 0);
    ctx.fillStyle = blank ? '#e8e8e8' : css(picture.background, 1);
    ctx.fillRect(0, 0, picture.width_mm, picture.height_mm);
    if (blank) return;
    picture.items.forEach((it, i) => {
      const color = lit && lit.has(i) ? picture.highlight : it.color;
      ctx.beginPath();
      if (it.kind === 'surface') {
        ctx.save();
        if (it.shape === 'rect') ctx.rect(it.x, it.y, it.w, it.h);
        else if (it.shape === 'ellipse') ctx.ellipse(it.cx, it.cy, it.rx, it.ry, 0, 0, 2 * Math.PI);
        else { ctx.moveTo(it.points[0], it.points[1]); for (let i = 2; i < it.points.length; i += 2) ctx.lineTo(it.points[i], it.points[i + 1]); ctx.closePath(); }
        ctx.clip();
        it.stripes.forEach((a, k) => {
          ctx.fillStyle = css(color, a);
          ctx.fillRect(it.stripe_x0 + k * it.stripe_step, 0, it.stripe_step * 1.02, picture.height_mm);
        });
        ctx.restore();
      } else if (it.kind === 'line') {
        ctx.strokeStyle = css(color, it.opacity); ctx.lineWidth = it.width; ctx.lineCap = 'round';
        ctx.moveTo(it.x1, it.y1); ctx.lineTo(it.x2, it.y2); ctx.stroke();
      } else {
        ctx.fillStyle = css(color, it.opacity); ctx.arc(it.x, it.y, it.r, 0, 2 * Math.PI); ctx.fill();
      }
    });
    ctx.strokeStyle = css(picture.border, 1); ctx.lineWidth = 1 / scale;
    ctx.strokeRect(0, 0, picture.width_mm, picture.height_mm);
  }
  function figure(picture, name, scale, onTap) {
    const f = document.createElement('figure');
    const c = document.createElement('canvas');
    drawPicture(c, picture, scale);
    const caption = document.createElement('figcaption');
    caption.textContent = name;
    f.append(c, caption);
    f.addEventListener('click', onTap);
    return f;
  }

  return { draw: drawPicture, figure };
})();
