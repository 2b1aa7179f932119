// web/site/audio_clock.js on given clock readings (node --test; ctest web_audio_clock): the stamps
// follow the output's pairing of the clocks, keep the events' own spacing, do not move with the
// context's current time (which advances a whole callback at once), nor with a stalled render.
import assert from 'node:assert/strict';
import { createRequire } from 'node:module';
import test from 'node:test';

const require = createRequire(import.meta.url);
const clock = require('../../web/site/audio_clock.js');

// The output is 11.6 ms behind the render position; the sample at context time 10 s is heard at
// performance.now() = 5000 ms; the page assumes 10.9 ms of output latency.
const reading = { nowMs: 5003, currentTime: 10.0146, contextTime: 10, performanceTime: 5000, latencyS: 0.0109 };
const near = (a, b, tol, what) => assert.ok(Math.abs(a - b) <= tol, `${what}: ${a} is not within ${tol} of ${b}`);

test('an event is heard at the pairing extrapolated to its own timeStamp', () => {
  near(clock.heardContextTimeS(4995, reading), 9.995, 1e-12, 'heard');
  near(clock.eventTimeS(4995, reading), 9.995 + 0.0109, 1e-12, 'stamp');
});

test('the stamps keep the events\' spacing and ignore when the page maps them', () => {
  let seed = 7;
  const random = () => ((seed = (seed * 1103515245 + 12345) % 2147483648) / 2147483648);
  for (let k = 0; k < 1000; ++k) {
    const pairMs = 1000 + random() * 1e6;
    const r = { nowMs: pairMs + random() * 20, contextTime: 1 + random() * 1000, performanceTime: pairMs, latencyS: random() * 0.05 };
    r.currentTime = r.contextTime + (r.nowMs - pairMs) / 1000 + r.latencyS + random() * 0.01;
    const a = r.nowMs - 40 * random(), b = a - 30 * random();
    near(clock.eventTimeS(a, r) - clock.eventTimeS(b, r), (a - b) / 1000, 1e-9, 'spacing');
    // One audio callback later (currentTime a block further, the pairing a block further): the same stamp.
    const later = { ...r, nowMs: r.nowMs + 2.9, currentTime: r.currentTime + 0.0029, contextTime: r.contextTime + 0.0029, performanceTime: pairMs + 2.9 };
    near(clock.eventTimeS(a, later), clock.eventTimeS(a, r), 1e-9, 'stamp one callback later');
    near(clock.heardAtMs(clock.heardContextTimeS(a, r), r), a, 1e-6, 'heardAtMs inverts heardContextTimeS');
  }
});

test('a stalled render does not move the stamp', () => {
  // currentTime held back 30 ms (the audio thread starved): the stamp stays at the event's true time.
  near(clock.eventTimeS(5002, { ...reading, currentTime: reading.currentTime - 0.03 }), 10.002 + 0.0109, 1e-12, 'stamp');
});

test('without a usable pairing: the current time less the age', () => {
  for (const r of [
    { ...reading, contextTime: 0, performanceTime: 0 },                                   // not started
    { ...reading, performanceTime: reading.nowMs - clock.kStalePairingMs - 1 },           // stale
  ]) {
    near(clock.eventTimeS(4995, r), r.currentTime - 0.008, 1e-12, 'fallback stamp');
    assert.ok(Number.isNaN(clock.heardAtMs(10, r)) && Number.isNaN(clock.heardContextTimeS(4995, r)));
  }
  // A timeStamp after the reading (no age): the current time.
  assert.equal(clock.eventTimeS(5010, { ...reading, contextTime: 0, performanceTime: 0 }), reading.currentTime);
});

// Readings every 3 ms of a clock whose output is 11.6 ms behind; `late` (ms) delays one callback's pairing.
function readingsOf(fromMs, toMs, { lateAtMs = -1, lateMs = 0, jumpAtMs = Infinity, jumpMs = 0 } = {}) {
  const out = [];
  for (let t = fromMs; t <= toMs; t += 3) {
    const shift = (t >= jumpAtMs ? jumpMs : 0) + (t === lateAtMs ? lateMs : 0);
    out.push({ nowMs: t + 0.5, currentTime: (t - 11.6) / 1000 + 0.0116, contextTime: (t - 11.6) / 1000,
               performanceTime: t + shift, latencyS: 0.0109 });
  }
  return out;
}

test('one late callback\'s pairing is outvoted', () => {
  const readings = readingsOf(1000, 1099, { lateAtMs: 1090, lateMs: 5 });
  const truth = clock.eventTimeS(1080, readingsOf(1000, 1099).at(-1));
  near(clock.eventTimeS(1080, clock.steadyReading(readings, 1080)), truth, 1e-9, 'steady stamp');
  // The late pairing on its own would stamp the event 5 ms early.
  near(clock.eventTimeS(1080, { ...readings.find((r) => r.performanceTime === 1095), nowMs: 1099.5 }), truth - 0.005, 1e-9, 'late pairing');
});

test('an event is mapped with the pairing in force at its time', () => {
  // The output skipped 5 ms at 1060 ms (its samples now heard 5 ms later): an event at 1030 ms keeps
  // the pairing before the skip, one at 1090 ms takes the one after.
  const readings = readingsOf(1000, 1120, { jumpAtMs: 1060, jumpMs: 5 });
  near(clock.heardContextTimeS(1030, clock.steadyReading(readings, 1030)), (1030 - 11.6) / 1000, 1e-9, 'before the skip');
  near(clock.heardContextTimeS(1090, clock.steadyReading(readings, 1090)), (1090 - 5 - 11.6) / 1000, 1e-9, 'after the skip');
});

test('without any usable pairing, the newest reading', () => {
  const readings = readingsOf(1000, 1030).map((r) => ({ ...r, contextTime: 0, performanceTime: 0 }));
  assert.deepEqual(clock.steadyReading(readings, 1020), readings.at(-1));
});

test('a pairing read many times counts once', () => {
  // Ten readings within one late callback repeat its pairing; four other callbacks outvote it.
  const steady = readingsOf(1000, 1012);
  const late = { ...steady.at(-1), contextTime: (1015 - 11.6) / 1000, performanceTime: 1015 + 5.8 };
  const readings = [...steady, ...Array.from({ length: 10 }, (_, k) => ({ ...late, nowMs: 1021 + k * 0.1 }))];
  near(clock.heardContextTimeS(1010, clock.steadyReading(readings, 1010)), (1010 - 11.6) / 1000, 1e-9, 'stamp');
});
