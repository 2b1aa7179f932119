// Helpers of the browser checks: picture comparison, a drag paced by the audio clock, raw HTTP.
import net from 'node:net';

// Waits until the page's audio clock has advanced by `seconds` (a state, not a fixed sleep).
export async function waitForAudioTime(page, seconds) {
  const from = await page.evaluate(() => window.vimg.audioTime());
  await page.waitForFunction((t) => window.vimg.audioTime() >= t, { timeout: 30000, polling: 'raf' }, from + seconds);
}

// The audio callback's period (s): how far the context's currentTime advances at once, the median
// of 40 advances seen by reading it in a loop on the page's thread (bounded by 5 s against a stall).
export async function callbackPeriodS(page) {
  return page.evaluate(() => {
    const steps = [];
    let last = window.vimg.audioTime();
    const until = performance.now() + 5000;
    while (steps.length < 40 && performance.now() < until) {
      const t = window.vimg.audioTime();
      if (t !== last) { steps.push(t - last); last = t; }
    }
    steps.sort((x, y) => x - y);
    return steps[steps.length >> 1];
  });
}

// Presses at the left of the primitive's box, moves right 1 mm per 10 ms of audio time (100 mm/s)
// along its middle, and lifts. Returns the worklet's peak during the drag and the ids lit midway.
export async function dragAcross(page, primitive) {
  const [x0, y0, x1, y1] = primitive.bbox_mm;
  const y = (y0 + y1) / 2;
  const at = (x) => page.evaluate((a, b) => window.vimg.clientPointOfMm(a, b), x, y);
  const start = await at(x0 + 2);
  await page.mouse.move(start.x, start.y);
  await page.mouse.down();
  let lit = [];
  const steps = Math.max(4, Math.floor(x1 - x0 - 4));
  for (let i = 1; i <= steps; ++i) {
    const p = await at(x0 + 2 + ((x1 - x0 - 4) * i) / steps);
    await page.mouse.move(p.x, p.y);
    await waitForAudioTime(page, 0.01);
    if (i === Math.floor(steps / 2)) lit = await page.evaluate(() => window.vimg.litPrimitives());
  }
  const peak = await page.evaluate(() => window.vimg.workletPeak());
  await page.mouse.up();
  return { peak, lit };
}

// Correlation of luminance between the screenshot's picture area and the PNG export, both averaged
// over cells of about 2 mm, computed in the page with canvas 2D.
export async function comparePicture(page, screenshotPng, exportPng) {
  return page.evaluate(async (shotB64, exportB64) => {
    const load = (b64) => new Promise((resolve, reject) => {
      const img = new Image();
      img.onload = () => resolve(img);
      img.onerror = () => reject(new Error('an image did not decode'));
      img.src = `data:image/png;base64,${b64}`;
    });
    const [shot, exported] = await Promise.all([load(shotB64), load(exportB64)]);
    const info = window.vimg.imageInfo();
    const a = window.vimg.clientPointOfMm(0, 0);
    const b = window.vimg.clientPointOfMm(info.width_mm, info.height_mm);
    const cols = Math.max(8, Math.round(info.width_mm / 2));
    const rows = Math.max(8, Math.round(info.height_mm / 2));
    const cells = (img, sx, sy, sw, sh) => {
      const c = document.createElement('canvas');
      c.width = cols; c.height = rows;
      const g = c.getContext('2d');
      g.imageSmoothingQuality = 'high';
      g.drawImage(img, sx, sy, sw, sh, 0, 0, cols, rows);
      const d = g.getImageData(0, 0, cols, rows).data;
      const out = [];
      for (let i = 0; i < d.length; i += 4) out.push(0.2126 * d[i] + 0.7152 * d[i + 1] + 0.0722 * d[i + 2]);
      return out;
    };
    const scale = window.devicePixelRatio || 1;
    const p = cells(shot, a.x * scale, a.y * scale, (b.x - a.x) * scale, (b.y - a.y) * scale);
    const q = cells(exported, 0, 0, exported.naturalWidth, exported.naturalHeight);
    const mean = (v) => v.reduce((s, x) => s + x, 0) / v.length;
    const mp = mean(p); const mq = mean(q);
    let sxy = 0; let sxx = 0; let syy = 0;
    for (let i = 0; i < p.length; ++i) {
      sxy += (p[i] - mp) * (q[i] - mq); sxx += (p[i] - mp) ** 2; syy += (q[i] - mq) ** 2;
    }
    return { correlation: sxy / Math.sqrt(sxx * syy || 1), cells: p.length };
  }, Buffer.from(screenshotPng).toString('base64'), exportPng.toString('base64'));
}

// One request written as raw bytes (so `..` reaches the server as sent), the answer parsed.
export function rawRequest(host, port, requestLine) {
  return new Promise((resolve, reject) => {
    const socket = net.connect(port, host);
    let data = '';
    socket.setTimeout(30000, () => { socket.destroy(); reject(new Error(`no answer to ${requestLine}`)); });
    socket.on('connect', () => socket.write(`${requestLine} HTTP/1.1\r\nHost: ${host}:${port}\r\nConnection: close\r\nContent-Length: 0\r\n\r\n`));
    socket.on('data', (d) => { data += d; });
    socket.on('error', reject);
    socket.on('end', () => {
      const status = Number((data.match(/^HTTP\/1\.[01] (\d{3})/) || [])[1] || 0);
      const split = data.indexOf('\r\n\r\n');
      resolve({ status, body: split < 0 ? '' : data.slice(split + 4), raw: data });
    });
  });
}
