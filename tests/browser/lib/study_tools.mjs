// Helpers of the study checks (run_study_tests.mjs): `vimg serve --study` on a fixed port (so a
// restarted server is the same address for the open page), the participant's link, a page that
// goes through the study's screens, rubbing a gesture with synthetic pointer events, trial files.
import { spawn } from 'node:child_process';
import fs from 'node:fs';

// Starts `vimg serve --study STUDY --results DIR --port PORT` (0: any free port) and waits for the
// dashboard URL it prints. Returns {port, url, researcherKey, child, kill(signal)}.
export async function startStudyServer(vimg, study, results, port = 0) {
  const child = spawn(vimg, ['serve', '--study', study, '--results', results, '--port', String(port)],
                      { stdio: ['ignore', 'pipe', 'pipe'] });
  let out = '';
  let err = '';
  child.stderr.on('data', (d) => { err += d; });
  const m = await new Promise((resolve, reject) => {
    const hang = setTimeout(() => reject(new Error(`vimg serve --study printed no dashboard within 60 s:\n${out}\n${err}`)), 60000);
    child.stdout.on('data', (d) => {
      out += d;
      const found = out.match(/dashboard (http:\/\/127\.0\.0\.1:(\d+)\/)dashboard\.html#key=([0-9a-f]{32})/);
      if (found) { clearTimeout(hang); resolve(found); }
    });
    child.on('exit', (code) => { clearTimeout(hang); reject(new Error(`vimg serve exited ${code}:\n${out}\n${err}`)); });
  });
  return {
    url: m[1], port: Number(m[2]), researcherKey: m[3], child, log: () => err,
    kill(signal = 'SIGKILL') {
      if (child.exitCode !== null || child.signalCode !== null) return Promise.resolve();
      const exited = new Promise((resolve) => child.on('exit', () => resolve()));
      child.kill(signal);
      return exited;
    },
  };
}

// A gesture file's rows (time_s,finger,x_mm,y_mm,pressure,phase) of finger 0.
export function readGesture(file) {
  return fs.readFileSync(file, 'utf8').trim().split('\n').slice(1).map((line) => {
    const [t, finger, x, y, , phase] = line.split(',');
    return { t: Number(t), finger: Number(finger), x: Number(x), y: Number(y), phase };
  });
}

// Rubs the stage along the gesture with the mouse (synthetic pointer events through DevTools).
export async function rub(page, gesture) {
  const points = await page.evaluate((g) => g.map((p) => window.vimg.clientPointOfMm(p.x, p.y)), gesture);
  await page.mouse.move(points[0].x, points[0].y);
  await page.mouse.down();
  for (const p of points.slice(1)) await page.mouse.move(p.x, p.y);
  await page.mouse.up();
}

// Moves the page on until it is in a trial (or done): instructions, device check, pauses and
// training are passed with proceed() as a person presses their buttons.
export async function toNextTrial(page) {
  for (;;) {
    const state = await page.evaluate(() => window.vimg.study.state());
    if (state.phase === 'trial' || state.phase === 'done') return state;
    await page.evaluate(() => window.vimg.study.proceed());
  }
}

// One trial: rub, then answer `stem`; resolves once the server has confirmed the row.
export async function answerTrial(page, gesture, stem) {
  await rub(page, gesture);
  await page.evaluate((s) => window.vimg.study.answer(s), stem);
}

// `trial,chosen` rows as a map trial -> stem.
export function readResponses(file) {
  const map = new Map();
  for (const line of fs.readFileSync(file, 'utf8').trim().split('\n').slice(1)) {
    const [trial, chosen] = line.split(',');
    map.set(Number(trial), chosen);
  }
  return map;
}

// A trial file's rows as objects (header names as keys).
export function readTrials(file) {
  const [header, ...rows] = fs.readFileSync(file, 'utf8').trim().split('\n');
  const names = header.split(',');
  return rows.map((row) => Object.fromEntries(row.split(',').map((v, i) => [names[i], v])));
}
