// The matching test in a real browser (vimg serve --study; docs/studies.md, "The matching test in
// the browser"). One participant's whole study through the page in Debian's headless Chromium,
// synthetic pointer rubbing and the answers of the shipped responses_demo.csv, with:
//   resume     the server is killed after trial 20; trial 21 is answered while it is down (the page
//              keeps it), the server is restarted and the page reloaded: the study goes on at trial 22
//   offline    a network drop (DevTools' offline mode) during trial 30 loses nothing
//   file       every trial exactly once, and the trial file equals vimg-player's scripted run of
//              the same responses and rubbing except for the time columns (rub_s, response_s,
//              time_utc; path_mm within 1e-3 mm: the browser quantizes pointer positions in CSS px)
//   file       ... and every row is the plan's presented image and set, with the response chosen
//   dashboard  the dashboard's report is `vimg study report` of the same file, byte for byte, and
//              the link its form makes is the one `vimg study link` prints
//   dashboard  ... and its numbers are the ones the test's own trials give (the plan's presented
//              image, the answer the test chose): per set the comparison matrix, the participant's
//              trials, correct and accuracy, and the accuracy's 95 % Wilson interval computed here
//   loading    before the study is loaded, window.vimg.study.state() is {phase: 'loading'}
//   phone      at 412 px wide the grey stage shows only where one rubs; the device check says "1 point"
//   refused    an answer refused for good (403) is sent once and the page says what to do
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
// The 40 trials as this test planned and answered them: the participant's plan (the server's state)
// and the responses this test gave, independent of the trial file and of the report's code.
async function plannedTrials() {
  const key = new URLSearchParams(link.split('#')[1]).get('key');
  const state = await (await fetch(`${server.url}api/state?participant=demo`, { headers: { 'X-Vimg-Key': key } })).json();
  return state.plan.slice(0, 40).map(([set, image], i) => ({ set: state.sets[set].name, images: state.sets[set].images,
    presented: state.sets[set].images[image], chosen: responses.get(i + 1) }));
}
// The dashboard's report against the trials this test planned and answered, with nothing taken from
// the report's code: per set the sentence (trials, accuracy, its 95 % Wilson score interval
// (p + z^2/2n +- z sqrt(p(1-p)/n + z^2/4n^2)) / (1 + z^2/n), chance 1/images), every cell of the
// comparison matrix (read by the names in its header) and the participant's row.
const escapeHtml = (text) => text.replace(/&/g, '&amp;').replace(/</g, '&lt;').replace(/>/g, '&gt;')
  .replace(/"/g, '&quot;').replace(/'/g, '&#39;');
const percent = (fraction) => `${(100 * fraction).toFixed(1)} %`;
function wilson95(correct, n) {
  const z = 1.959963984540054;  // the standard normal's 0.975 quantile
  const p = correct / n;
  const centre = (p + z * z / (2 * n)) / (1 + z * z / n);
  const half = (z / (1 + z * z / n)) * Math.sqrt(p * (1 - p) / n + z * z / (4 * n * n));
  return [centre - half, centre + half];
}
const cells = (row) => [...row.matchAll(/<t[hd]>(.*?)<\/t[hd]>/g)].map((m) => m[1]);
function checkReportAgainstTrials(report, planned) {
  const names = [...new Set(planned.map((t) => t.set))];
  for (const name of names) {
    const trials = planned.filter((t) => t.set === name);
    const images = trials[0].images;
    const n = trials.length;
    const correct = trials.filter((t) => t.presented === t.chosen).length;
    const start = report.indexOf(`<h3>Set ${escapeHtml(name)}</h3>`);
    assert(start >= 0, `the report has no section for set ${name}`);
    const end = report.indexOf('<h3>', start + 4);
    const section = report.slice(start, end < 0 ? report.length : end);
    const [lower, upper] = wilson95(correct, n);
    const sentence = `<p>${n} trials by 1 participant; accuracy ${percent(correct / n)} (95 % Wilson interval ` +
      `${(100 * lower).toFixed(1)}\u2013${(100 * upper).toFixed(1)} %) against chance ${percent(1 / images.length)} (${images.length} images).</p>`;
    assert(section.includes(sentence), `set ${name}: the report does not say ${sentence}`);
    const participantRow = `<tr><td>demo</td><td>${n}</td><td>${correct}</td><td>${percent(correct / n)}</td></tr>`;
    assert(section.includes(participantRow), `set ${name}: the report has no participant row ${participantRow}`);
    const table = section.match(/<table>\s*<caption>Comparison matrix[^]*?<\/table>/);
    assert(table, `set ${name}: the report has no comparison matrix`);
    const [header, ...body] = [...table[0].matchAll(/<tr>.*?<\/tr>/g)].map((m) => cells(m[0]));
    const chosenNames = header.slice(1, -1);
    assert(JSON.stringify([...chosenNames].sort()) === JSON.stringify(images.map(escapeHtml).sort()),
           `set ${name}: the matrix's columns ${chosenNames} are not the set's images ${images}`);
    const count = (presented, chosen) => trials.filter((t) => (presented === null || escapeHtml(t.presented) === presented) &&
                                                              (chosen === null || escapeHtml(t.chosen) === chosen)).length;
    assert(body.length === images.length + 1, `set ${name}: the matrix has ${body.length} rows`);
    for (const row of body) {
      const presented = row[0] === 'total' ? null : row[0];
      const want = [...chosenNames.map((chosen) => count(presented, chosen)), count(presented, null)].map(String);
      assert(JSON.stringify(row.slice(1)) === JSON.stringify(want),
             `set ${name}, presented ${row[0]}: the matrix says ${row.slice(1)}, the test's trials ${want}`);
    }
  }
  return names.map((name) => {
    const trials = planned.filter((t) => t.set === name);
    return `${name} ${trials.filter((t) => t.presented === t.chosen).length}/${trials.length}`;
  }).join(', ');
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
  // Every row against the participant's plan (the server's state) and the responses given.
  const planned = await plannedTrials();
  for (let i = 0; i < 40; ++i) {
    const { set, presented, chosen } = planned[i];
    const want = { participant: 'demo', set, presented, chosen };
    want.correct = want.presented === want.chosen ? '1' : '0';
    for (const column of Object.keys(want)) {
      assert(got[i][column] === want[column], `trial ${i + 1} ${column}: file ${got[i][column]}, plan and responses ${want[column]}`);
    }
  }
  const expected = await playerRun;
  if (!expected) return 'compared with the plan and the responses; vimg-player not built, so not with its scripted run';
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
  const sets = checkReportAgainstTrials(report, await plannedTrials());
  // The dashboard's form makes a participant's link: the one `vimg study link` prints.
  await dashboard.type('#participant', 'tablet-7');
  await dashboard.click('#make-link button');
  await dashboard.waitForFunction(() => document.getElementById('link').textContent.length > 0, { timeout: 30000 });
  const made = await dashboard.evaluate(() => document.getElementById('link').textContent);
  const printed = execFileSync(vimg, ['study', 'link', art('results'), '--participant', 'tablet-7'], { encoding: 'utf8' }).trim();
  assert(made === printed, `the dashboard made the link ${made}, vimg study link prints ${printed}`);
  return `the same HTML as vimg study report, whose numbers are the test's own trials' (${sets}); the same link as vimg study link`;
});

// Before the study is loaded (its state request held back), window.vimg.study.state() says so
// instead of throwing; window.vimg.ready is a promise that resolves once it is loaded.
await check('loading', async () => {
  const p = await browser.newPage();
  p.on('pageerror', (e) => problems.push(`uncaught (loading): ${e.message}`));
  await p.setRequestInterception(true);
  let release = null;
  const held = new Promise((resolve) => { release = resolve; });
  let requested = null;
  const stateRequested = new Promise((resolve) => { requested = resolve; });
  p.on('request', async (request) => {
    if (request.url().includes('/api/state')) {
      requested();
      await held;
    }
    request.continue();
  });
  const linkOf = execFileSync(vimg, ['study', 'link', art('results'), '--participant', 'loading-1'], { encoding: 'utf8' }).trim();
  await p.goto(linkOf, { waitUntil: 'load' });
  await stateRequested;
  const before = await p.evaluate(async () => ({ state: window.vimg.study.state(), ready: window.vimg.ready instanceof Promise,
    proceed: await window.vimg.study.proceed().then(() => 'moved on', (e) => e.message) }));
  assert(JSON.stringify(before.state) === '{"phase":"loading"}', `before loading: ${JSON.stringify(before.state)}`);
  assert(before.ready, 'window.vimg.ready is not a promise');
  assert(before.proceed.includes('not loaded yet'), `proceed() before loading: ${before.proceed}`);
  release();
  await p.evaluate(() => window.vimg.ready);
  const after = await p.evaluate(() => window.vimg.study.state());
  assert(after.phase === 'instructions' && after.trial === 1, `after loading: ${JSON.stringify(after)}`);
  await p.close();
  return `${JSON.stringify(before.state)}, then ${after.phase}`;
});

// The screens on a 412 px wide phone with one touch point: the grey stage is shown only where the
// participant rubs (training, a trial before Answer), not under the instructions, the device check
// or the choices; the device check says "1 point". Screenshots: phone-*.png. Nothing is answered.
await check('phone', async () => {
  const p = await browser.newPage();
  p.on('pageerror', (e) => problems.push(`uncaught (phone): ${e.message}`));
  await p.setViewport({ width: 412, height: 915, deviceScaleFactor: 1, isMobile: true, hasTouch: true });
  const client = await p.target().createCDPSession();
  await client.send('Emulation.setTouchEmulationEnabled', { enabled: true, maxTouchPoints: 1 });
  const linkOf = execFileSync(vimg, ['study', 'link', art('results'), '--participant', 'phone-1'], { encoding: 'utf8' }).trim();
  await p.goto(linkOf, { waitUntil: 'load' });
  await p.waitForFunction(() => window.vimg !== undefined && window.vimg.ready !== undefined, { timeout: 60000 });
  await p.evaluate(() => window.vimg.ready);
  const stageShown = () => p.evaluate(() => {
    const stage = document.getElementById('stage');
    return getComputedStyle(stage).display !== 'none' && stage.getBoundingClientRect().height > 0;
  });
  const seen = [];
  const expect = async (phase, shown) => {
    const state = await p.evaluate(() => window.vimg.study.state());
    assert(state.phase === phase, `the page is at ${state.phase}, expected ${phase}`);
    await p.screenshot({ path: art(`phone-${seen.length + 1}-${phase}.png`), fullPage: true });
    const got = await stageShown();
    assert(got === shown, `${phase}: the stage is ${got ? 'shown' : 'hidden'}`);
    seen.push(`${phase} ${got ? 'shown' : 'hidden'}`);
  };
  await expect('instructions', false);
  await p.evaluate(() => window.vimg.study.proceed());
  await expect('device-check', false);
  const touch = await p.evaluate(() => document.getElementById('touch-state').textContent);
  assert(touch === 'present (1 point)', `the device check says: ${touch}`);
  await p.evaluate(() => window.vimg.study.proceed());
  await expect('training', true);
  await p.evaluate(() => window.vimg.study.proceed());
  await expect('trial', true);  // rubbing
  await rub(p, gesture);
  await p.click('#answer');
  assert(await p.evaluate(() => document.querySelectorAll('#choices figure').length) > 0, 'no choices after Answer');
  await expect('trial', false);  // choosing
  await p.close();
  return `${seen.join(', ')}; touch: ${touch}`;
});

// An answer the server refuses for good (403: the server was restarted on another results folder,
// whose secret makes other keys) is sent once, settles as refused and tells the participant what
// to do; nothing is written.
await check('refused', async () => {
  const p = await browser.newPage();
  p.on('pageerror', (e) => problems.push(`uncaught (refused): ${e.message}`));
  const linkOf = execFileSync(vimg, ['study', 'link', art('results'), '--participant', 'refused-1'], { encoding: 'utf8' }).trim();
  await p.goto(linkOf, { waitUntil: 'load' });
  await p.waitForFunction(() => window.vimg !== undefined && window.vimg.ready !== undefined, { timeout: 60000 });
  await p.evaluate(() => window.vimg.ready);
  const state = await toNextTrial(p);
  await rub(p, gesture);
  await server.kill('SIGTERM');
  fs.mkdirSync(art('other-results'), { recursive: true });
  server = await startStudyServer(vimg, study, art('other-results'), server.port);
  const posts = [];
  p.on('request', (r) => { if (r.method() === 'POST' && r.url().endsWith('/api/answer')) posts.push(r.url()); });
  const settled = p.evaluate((stem) => window.vimg.study.answer(stem).then(() => 'confirmed', (e) => e.message), state.choices[0]);
  settled.catch(() => {});
  // Settled: refused, and nothing is being sent or waits to be sent again (a page that retries
  // never gets there: the bound ends the wait).
  await p.waitForFunction(() => window.vimg.study.refusal() !== '' && !window.vimg.study.delivering(), { timeout: 30000 })
    .catch(() => { throw new Error(`the answer never settled as refused (${posts.length} POSTs)`); });
  const outcome = await settled;
  assert(outcome.includes('HTTP 403') && outcome.includes('Ask the researcher for a new link'), `the answer settled as: ${outcome}`);
  assert(posts.length === 1, `${posts.length} POSTs of the refused answer`);
  assert(await p.evaluate(() => window.vimg.study.unconfirmed()) === 0, 'the refused answer is still kept for sending');
  const shown = await p.evaluate(() => {
    const e = document.getElementById('status');
    const box = e.getBoundingClientRect();
    return { text: e.textContent, visible: getComputedStyle(e).display !== 'none' && box.height > 0 && box.bottom > 0,
             problem: e.classList.contains('problem') };
  });
  assert(shown.visible && shown.problem && shown.text === outcome, `the page shows: ${JSON.stringify(shown)}`);
  await p.screenshot({ path: art('refused.png') });
  for (const dir of ['results', 'other-results']) {
    assert(!fs.readdirSync(art(dir)).some((name) => name.startsWith('refused-1.')), `a file of refused-1 in ${dir}`);
  }
  await p.close();
  return 'one POST, then: ' + shown.text;
});

if (problems.length) console.log(`page problems: ${problems.join('; ')}`);
await browser.close();
await server.kill('SIGTERM');
const failed = results.filter((r) => !r.ok).length + (problems.length ? 1 : 0);
console.log(failed ? `${failed} FAILED` : 'all passed');
process.exit(failed ? 1 : 0);
