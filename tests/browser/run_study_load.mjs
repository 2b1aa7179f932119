// The matching test under load (docs/benchmarks/study-server.md, "Study server"): 30 participants' pages in one
// headless Chromium answer at once against one `vimg serve --study`, each TRIALS trials (rub,
// Answer, a picture), all pages in step, their sound suspended after the device check. Checks that no row is lost or doubled (every participant's
// file holds trials 1..TRIALS once, as the plan says) and prints the answer round trips the pages
// measured (request sent to confirmation): median, p99, max.
// usage: node run_study_load.mjs VIMG SOURCE_DIR ARTIFACT_DIR [PARTICIPANTS] [TRIALS]
import { execFileSync } from 'node:child_process';
import fs from 'node:fs';
import path from 'node:path';
import { launchBrowser } from './lib/browser.mjs';
import { readTrials, rub, startStudyServer, toNextTrial } from './lib/study_tools.mjs';

const [vimg, sourceDir, artDir, participantsArg, trialsArg] = process.argv.slice(2);
if (!artDir) {
  console.error('usage: node run_study_load.mjs VIMG SOURCE_DIR ARTIFACT_DIR [PARTICIPANTS] [TRIALS]');
  process.exit(2);
}
const participants = Number(participantsArg || 30);
const trials = Number(trialsArg || 5);
fs.rmSync(artDir, { recursive: true, force: true });
const results = path.join(artDir, 'results');
fs.mkdirSync(results, { recursive: true });
const study = path.join(sourceDir, 'assets/examples/matching/study.xml');
const gesture = [[10, 10], [20, 10], [20, 20], [10, 20]].map(([x, y]) => ({ x, y }));

const server = await startStudyServer(vimg, study, results);
const browser = await launchBrowser();
let failed = 0;
try {
  const pages = [];
  for (let p = 0; p < participants; ++p) {
    const id = `load${String(p).padStart(2, '0')}`;
    const link = execFileSync(vimg, ['study', 'link', results, '--participant', id], { encoding: 'utf8' }).trim();
    const page = await browser.newPage();
    await page.goto(link, { waitUntil: 'load', timeout: 120000 });
    await page.waitForFunction(() => window.vimg !== undefined && window.vimg.ready !== undefined, { timeout: 120000 });
    await page.evaluate(() => window.vimg.ready);
    // Past the device check, each page's sound is suspended: 30 renderers in one browser on one
    // machine would measure that machine, not the server (each participant has a device of their own).
    await toNextTrial(page);
    await page.evaluate(() => window.vimg.audioContext().suspend());
    pages.push({ id, page });
  }
  // Each round: every page rubs, then all answer at once.
  for (let k = 1; k <= trials; ++k) {
    for (const { page } of pages) {
      await toNextTrial(page);
      await page.bringToFront();
      await rub(page, gesture);
    }
    await Promise.all(pages.map(({ page }) => page.evaluate(() => window.vimg.study.answer(window.vimg.study.state().choices[0]))));
  }
  const times = [];
  for (const { id, page } of pages) {
    times.push(...(await page.evaluate(() => window.vimg.study.roundTripsMs())));
    const rows = readTrials(path.join(results, `${id}.trials.csv`));
    if (rows.length !== trials || rows.some((r, i) => Number(r.trial) !== i + 1 || r.participant !== id)) {
      console.log(`FAIL ${id}: the file holds trials ${rows.map((r) => r.trial).join(' ')}`);
      ++failed;
    }
  }
  times.sort((a, b) => a - b);
  const at = (q) => times[Math.min(times.length - 1, Math.ceil(q * times.length) - 1)];
  console.log(`${participants} participants x ${trials} trials: ${times.length} answers confirmed; round trip ` +
              `median ${at(0.5).toFixed(1)} ms, p99 ${at(0.99).toFixed(1)} ms, max ${times[times.length - 1].toFixed(1)} ms`);
  if (times.length !== participants * trials) { console.log('FAIL: not every answer was confirmed'); ++failed; }
} finally {
  await browser.close();
  await server.kill('SIGTERM');
}
console.log(failed ? `${failed} FAILED` : 'all passed');
process.exit(failed ? 1 : 0);
