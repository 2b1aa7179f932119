// Pointer events on the AudioContext's clock (docs/web-audio.md, "Placement in the audio"). Pure: every
// clock is read by the caller and passed in as a `reading`:
//   nowMs            performance.now() when the reading was taken
//   currentTime      the context's currentTime then (the render position: it advances once per
//                    audio callback, by a whole callback's frames)
//   contextTime, performanceTime   getOutputTimestamp(): the sample at contextTime (s) is heard at
//                    performanceTime (ms, performance.now()'s clock); both 0 before the output runs
//   latencyS         the output latency the page assumes (baseLatency + outputLatency), the same the
//                    prediction horizon holds
// An event's timeStamp is on performance.now()'s clock. Its true time on the audio clock is the
// context time of the sample heard at that moment; it is stamped latencyS later, on the render side
// of the clock, where the renderer reckons each finger's age (the horizon adds latencyS back, so the
// felt position does not depend on latencyS).
'use strict';
var VimgAudioClock = (function () {
  // A pairing older than this (a context that stalled or has not started) is not extrapolated.
  var kStalePairingMs = 250;

  // A reading's pairing, judged by its age at nowMs.
  function pairingUsableAt(r, nowMs) {
    return r.contextTime > 0 && r.performanceTime > 0 && Math.abs(nowMs - r.performanceTime) <= kStalePairingMs;
  }
  function pairingUsable(r) { return pairingUsableAt(r, r.nowMs); }

  // The context time (s) of the sample heard at timeStampMs, from the output's pairing of the two
  // clocks; NaN without a usable pairing.
  function heardContextTimeS(timeStampMs, r) {
    return pairingUsable(r) ? r.contextTime + (timeStampMs - r.performanceTime) / 1000 : NaN;
  }

  // The time to stamp a pointer sample with on the context's clock (s): its heard time plus
  // latencyS. Without a usable pairing, the context's current time less the sample's age. Where the
  // render has stalled (an audio thread starved of CPU) the stamp lies beyond currentTime, at its
  // true place on the audio's timeline: the renderer holds the event until it gets there.
  function eventTimeS(timeStampMs, r) {
    var heard = heardContextTimeS(timeStampMs, r);
    return isNaN(heard) ? r.currentTime - Math.max(0, (r.nowMs - timeStampMs) / 1000) : heard + r.latencyS;
  }

  // When the sample at contextTimeS is heard, on performance.now()'s clock (ms); NaN without a
  // usable pairing.
  function heardAtMs(contextTimeS, r) {
    return pairingUsable(r) ? r.performanceTime + (contextTimeS - r.contextTime) * 1000 : NaN;
  }

  // One audio callback that runs late pairs its samples with a later performanceTime: that pairing
  // alone would place events a few ms early (up to 5 ms seen in headless Chromium on a loaded
  // machine). Of the readings kept (oldest first), those whose pairing lies within kLocalMs of
  // timeStampMs (each pairing once; else the one nearest to it), the one with the median offset
  // (contextTime - performanceTime): the newest reading with that pairing, or `newest` alone when
  // no reading has a usable pairing.
  var kLocalMs = 50;
  function steadyReading(readings, timeStampMs) {
    var newest = readings[readings.length - 1];
    // A pairing is judged by its age at the newest reading.
    var usable = readings.filter(function (r) { return pairingUsableAt(r, newest.nowMs); });
    if (usable.length === 0) return newest;
    // One pairing per audio callback: readings taken within one callback repeat it, and count once.
    var local = usable.filter(function (r, i) {
      return Math.abs(r.performanceTime - timeStampMs) <= kLocalMs &&
             (i === 0 || r.performanceTime !== usable[i - 1].performanceTime);
    });
    var nearest = usable.reduce(function (best, r) {
      return Math.abs(r.performanceTime - timeStampMs) < Math.abs(best.performanceTime - timeStampMs) ? r : best;
    });
    var pool = local.length > 0 ? local : [nearest];
    var offset = function (r) { return r.contextTime * 1000 - r.performanceTime; };
    var sorted = pool.slice().sort(function (x, y) { return offset(x) - offset(y); });
    var median = sorted[(sorted.length - 1) >> 1];
    return { nowMs: newest.nowMs, currentTime: newest.currentTime, latencyS: newest.latencyS,
             contextTime: median.contextTime, performanceTime: median.performanceTime };
  }

  return { eventTimeS: eventTimeS, heardContextTimeS: heardContextTimeS, heardAtMs: heardAtMs, steadyReading: steadyReading,
           kStalePairingMs: kStalePairingMs, kLocalMs: kLocalMs };
})();
if (typeof module !== 'undefined' && module.exports) module.exports = VimgAudioClock;
