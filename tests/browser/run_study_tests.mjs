// The matching test in a real browser (vimg serve --study; docs/studies.md, "The matching test in
// the browser"). One participant's whole study through the page in Debian's headless Chromium,
// synthetic pointer rubbing and the answers of the shipped responses_demo.csv, with:
//   resume     the server is killed after trial 20; trial 21 is answered while it is down (the page
//              keeps it), the server is restarted and the page reloaded: the study goes on at trial 22
//   offline    a network drop (DevTools' offline mode) during trial 30 loses nothing
//   file       every trial exactly once, and the trial file equals vimg-player's scripted run of
//              the same responses and rubbing except for the time columns (rub_s, response_s,
//              time_utc; path_mm within 1e-3 mm: the browser quantizes pointer positions in CSS px)
//   dashboard  the dashboard's report is `vimg study report` of the same file, byte for byte, and
//              the link its form makes is the one `vimg study link` prints
// Waits are on states (a printed URL, a row in the file, a promise), each bounded only against a hang.
// usage: node run_study_tests.mjs VIMG VIMG_PLAYER|none SOURCE_DIR ARTIFACT_DIR
import { execFileSync, spawn } from 'node:child_process';
import fs from 'node:fs';
import path from 'node:path';
import { launchBrowser } from './lib/browser.mjs';
import { answerTrial, readResponses, readTrials, rub, startStudyServer, toNextTrial } from './lib/study_tools.mjs';

const [vimg, player, sourceDir, artDir] = process.argv.slice(2);
if (!artDir) {
  console.error('usage: node run_study_tests.mjs VIMG VIMG_PLAYER|none SOURCE_DIR ARTIFACT_DIR');
  process.exit(2);
}
fs.rmSync(artDir, { recursive: true, force: true });
const art = (name) => path.join(artDir, name);
fs.mkdirSync(art('results'), { recursive: true });
fs.mkdirSync(art('player'), { recursive: true });
const example = path.join(sourceDir, 'assets/examples/matching');
const study = path.join(example, 'study.xml');
const responses = readResponses(path.join(example, 'responses_demo.csv'));
// A short rubbing (90 ms, 40 mm of path) keeps vimg-player's scripted run, paced by the gesture, short.
const gesture = [[0, 10, 10], [0.01, 20, 10], [0.02, 20, 20], [0.03, 10, 20], [0.04, 10, 30], [0.05, 20, 30],
                 [0.06, 20, 40], [0.07, 10, 40], [0.09, 10, 50]].map(([t, x, y]) => ({ t, x, y }));
fs.writeFileSync(art('rubbing.csv'), 'time_s,finger,x_mm,y_mm,pressure,phase\n' + gesture.map((p, i) =>
  `${p.t},0,${p.x},${p.y},1,${i === 0 ? 'down' : i === gesture.length - 1 ? 'up' : 'move'}`).join('\n') + '\n');

// vimg-player's scripted run of the same responses and rubbing, alongside the browser's.
const playerRun = player === 'none' ? Promise.resolve(null) : new Promise((resolve, reject) => {
  const child = spawn(player, ['--study', study, '--participant', 'demo', '--results', art('player'),
    '--responses', path.join(example, 'responses_demo.csv'), '--gesture', art('rubbing.csv'),
    '--output', `wav:${art('player/demo.wav')}`], { stdio: ['ignore', 'ignore', 'pipe'],
    env: Object.assign({}, process.env, { SDL_VIDEODRIVER: 'dummy', SDL_AUDIODRIVER: 'dummy' }) });
  let err = '';
  child.stderr.on('data', (d) => { err += d; });
  child.on('exit', (code) => (code === 0 ? resolve(art('player/demo.trials.csv')) : reject(new Error(`vimg-player exited ${code}: ${err}`))));
});

const results = [];
const assert = (condition, message) => { if (!condition) throw new Error(message); };
async function check(name, body) {
  const started = Date.now();
  try {
    const note = await body();
    results.push({ name, ok: true });
    console.log(`PASS ${name}${note ? `: ${note}` : ''} (${Date.now() - started} ms)`);
  } catch (e) {
    results.push({ name, ok: false });
    console.log(`FAIL ${name}: ${e.stack || e.message}`);
  }
}
const rows = () => (fs.existsSync(art('results/demo.trials.csv')) ? readTrials(art('results/demo.trials.csv')) : []);

let server = await startStudyServer(vimg, study, art('results'));
const link = execFileSync(vimg, ['study', 'link', art('results'), '--participant', 'demo'], { encoding: 'utf8' }).trim();
const browser = await launchBrowser();
const page = await browser.newPage();
const problems = [];
page.on('pageerror', (e) => problems.push(`uncaught: ${e.message}`));
const open = async () => {
  await page.waitForFunction(() => window.vimg !== undefined && window.vimg.ready !== undefined, { timeout: 60000 });
  await page.evaluate(() => window.vimg.ready);
};
await page.goto(link, { waitUntil: 'load' });
await open();

// Trials `from`..`to` as a person: rub, Answer, the chosen picture.
async function trials(from, to) {
  for (let k = from; k <= to; ++k) {
    const state = await toNextTrial(page);
    assert(state.trial === k, `the page is at trial ${state.trial}, expected ${k}`);
    assert(state.choices.includes(responses.get(k)), `trial ${k}: ${responses.get(k)} is not among ${state.choices}`);
    await answerTrial(page, gesture, responses.get(k));
  }
}

await check('resume', async () => {
  await trials(1, 20);
  assert(rows().length === 20, `the file holds ${rows().length} rows after trial 20`);
  await server.kill('SIGKILL');
  // Trial 21 while the server is down: answered, kept, not confirmed.
  await toNextTrial(page);
  await rub(page, gesture);
  page.evaluate((stem) => window.vimg.study.answer(stem), responses.get(21)).catch(() => {});  // never confirmed here
  await page.waitForFunction(() => window.vimg.study.unconfirmed() === 1, { timeout: 30000 });
  server = await startStudyServer(vimg, study, art('results'), server.port);
  await page.reload({ waitUntil: 'load' });
  await open();
  const state = await page.evaluate(() => window.vimg.study.state());
  assert(state.phase === 'instructions' && state.trial === 22, `after the reload: ${JSON.stringify(state)}`);
  assert(rows().length === 21, `the file holds ${rows().length} rows after the kept trial 21 was delivered`);
  return `trial 21 kept across a reload and a restart; resumed at ${state.trial}`;
});

await check('offline', async () => {
  await trials(22, 29);
  await toNextTrial(page);
  const client = await page.target().createCDPSession();
  await client.send('Network.emulateNetworkConditions', { offline: true, latency: 0, downloadThroughput: -1, uploadThroughput: -1 });
  const answered = answerTrial(page, gesture, responses.get(30));
  await page.waitForFunction(() => window.vimg.study.unconfirmed() === 1, { timeout: 30000 });
  assert(rows().length === 29, `an answer reached the server while offline (${rows().length} rows)`);
  await client.send('Network.emulateNetworkConditions', { offline: false, latency: 0, downloadThroughput: -1, uploadThroughput: -1 });
  await answered;
  assert(rows().length === 30, `after the network came back the file holds ${rows().length} rows`);
  await trials(31, 40);
  const done = await page.evaluate(() => window.vimg.study.state());
  assert(done.phase === 'done', `after trial 40 the page is at ${done.phase}`);
});

await check('file', async () => {
  const got = rows();
  assert(got.length === 40 && got.every((r, i) => Number(r.trial) === i + 1), 'the file does not hold trials 1..40 once each');
  const expected = await playerRun;
  if (!expected) return 'vimg-player not built: compared with the plan only';
  const want = readTrials(expected);
  for (let i = 0; i < 40; ++i) {
    for (const column of ['participant', 'set', 'trial', 'presented', 'chosen', 'correct']) {
      assert(got[i][column] === want[i][column], `trial ${i + 1} ${column}: page ${got[i][column]}, vimg-player ${want[i][column]}`);
    }
    assert(Math.abs(Number(got[i].path_mm) - Number(want[i].path_mm)) < 1e-3,
           `trial ${i + 1} path_mm: page ${got[i].path_mm}, vimg-player ${want[i].path_mm}`);
  }
  return 'equal to vimg-player\'s scripted run except rub_s, response_s and time_utc';
});

await check('dashboard', async () => {
  execFileSync(vimg, ['study', 'report', art('results/demo.trials.csv'), '--out', art('report.html')]);
  const dashboard = await browser.newPage();
  await dashboard.goto(`${server.url}dashboard.html#key=${server.researcherKey}`, { waitUntil: 'load' });
  await dashboard.waitForFunction(() => document.getElementById('report').srcdoc.includes('</html>'), { timeout: 30000 });
  const report = await dashboard.evaluate(() => document.getElementById('report').srcdoc);
  assert(report === fs.readFileSync(art('report.html'), 'utf8') || false, 'the dashboard\'s report differs from vimg study report');
  // The dashboard's form makes a participant's link: the one `vimg study link` prints.
  await dashboard.type('#participant', 'tablet-7');
  await dashboard.click('#make-link button');
  await dashboard.waitForFunction(() => document.getElementById('link').textContent.length > 0, { timeout: 30000 });
  const made = await dashboard.evaluate(() => document.getElementById('link').textContent);
  const printed = execFileSync(vimg, ['study', 'link', art('results'), '--participant', 'tablet-7'], { encoding: 'utf8' }).trim();
  assert(made === printed, `the dashboard made the link ${made}, vimg study link prints ${printed}`);
  return 'the same HTML as vimg study report; the same link as vimg study link';
});

if (problems.length) console.log(`page problems: ${problems.join('; ')}`);
await browser.close();
await server.kill('SIGTERM');
const failed = results.filter((r) => !r.ok).length + (problems.length ? 1 : 0);
console.log(failed ? `${failed} FAILED` : 'all passed');
process.exit(failed ? 1 : 0);
