'use strict';
// The study page's answers on their way to the server (docs/matching-test.md, "The matching test in
// the browser"; docs/web-study.md, "The page's retries"). Each answer is kept in localStorage
// (vimg.study.pending.ID) until the server confirms it, sent again while sending again can help,
// and, when the server refuses it for good, kept aside (vimg.study.refused.ID) with a message that
// says what to do. Answers kept by a closed tab go first when the link is opened again (study.js
// waits for deliver() before it loads the participant's state). Used by study.js.
const VimgStudyAnswers = (function () {
  // Worth sending again: a lost network (no reply), too many answers at once (429), a server that
  // failed or cannot open the trial file now (5xx, 503). Any other refusal (400, 403, 404, 409
  // without the trial recorded, 413, ...) is for good: sending the same answer again cannot help.
  const transient = (code) => code === 429 || code >= 500;
  function refusalMessage(code, reply, why) {
    const lost = 'Your last answer (trial ' + reply.trial + ') was not saved: ';
    if (code === 403) return lost + 'the server no longer accepts this link (HTTP 403). Ask the researcher for a new link.';
    if (code === 409) {
      return lost + 'the server has ' + reply.completed + ' trials of yours, not the one before this (HTTP 409). ' +
        'Reload this page to go on from trial ' + (reply.completed + 1) + '.';
    }
    return lost + 'the server refused it (HTTP ' + code + (why ? ': ' + why : '') + '). Reload this page; ' +
      'if this message comes again, tell the researcher.';
  }

  // participant: the ID; headers: the requests' headers (the key); status(text): the line above the
  // screens, which shows refusal() instead of `text` once an answer has been refused for good.
  function create(participant, headers, status) {
    const pendingKey = 'vimg.study.pending.' + participant;  // answers the server has not confirmed
    const pending = () => JSON.parse(localStorage.getItem(pendingKey) || '[]');
    const keepPending = (list) => localStorage.setItem(pendingKey, JSON.stringify(list));
    let delivering = null;
    let refusal = '';             // what to do about an answer the server refused for good
    const confirmed = new Map();  // trial -> [{resolve, reject}] waiting for its confirmation
    const roundTripsMs = [];      // each confirmed answer's last request, sent to confirmed

    // Settles a kept answer: confirmed (null) or refused for good (the message). A refused answer
    // leaves the list of kept answers for vimg.study.refused.ID, so that it is not lost without a trace.
    function settle(trial, message) {
      if (message) {
        const refusedKey = 'vimg.study.refused.' + participant;
        const kept = pending().filter((a) => a.trial === trial);
        localStorage.setItem(refusedKey, JSON.stringify(JSON.parse(localStorage.getItem(refusedKey) || '[]').concat(kept)));
      }
      keepPending(pending().filter((a) => a.trial !== trial));
      for (const waiter of confirmed.get(trial) || []) {
        if (message) waiter.reject(new Error(message));
        else waiter.resolve();
      }
      confirmed.delete(trial);
    }
    // Sends the kept answers in order until each is settled: confirmed (200, or 409 with the trial
    // recorded) or refused for good (the participant is told what to do). A lost network, a stopped
    // server, 429 and 5xx are tried again, at once, then at most every 2 s.
    function deliver() {
      if (!delivering) {
        delivering = sendKept().finally(() => {
          delivering = null;
          if (pending().length > 0) deliver();  // kept while the last round was ending
        });
      }
      return delivering;
    }
    async function sendKept() {
      let wait_ms = 100;
      for (let list = pending(); list.length > 0; list = pending()) {
        const first = list[0];
        let done = false;
        let refused = '';
        const sent_ms = performance.now();
        try {
          const r = await fetch('api/answer', { method: 'POST', cache: 'no-store', body: first.body,
            headers: Object.assign({ 'Content-Type': 'application/x-www-form-urlencoded' }, headers) });
          const text = await r.text();
          let reply = null;
          try { reply = JSON.parse(text); } catch (err) { reply = null; }
          done = (r.status === 200 || r.status === 409) && reply !== null && reply.completed >= first.trial;
          if (!done && !transient(r.status)) {
            refused = refusalMessage(r.status, { trial: first.trial, completed: reply ? reply.completed : 0 },
                                     reply ? reply.error : text.trim().slice(0, 200));
          } else if (!done) {
            status('saving… (the server answered HTTP ' + r.status + '; retrying)');
          }
        } catch (err) {
          status('saving… (the server is not reachable; retrying)');
        }
        if (done) {
          roundTripsMs.push(performance.now() - sent_ms);
          settle(first.trial, null);
          wait_ms = 100;
          status('');
        } else if (refused) {
          refusal = refused;
          status('');
          settle(first.trial, refused);
        } else {
          await new Promise((resolve) => setTimeout(resolve, wait_ms));
          wait_ms = Math.min(2000, wait_ms * 2);
        }
      }
    }
    window.addEventListener('online', () => deliver());

    // Keeps the answer of `trial` (its form text) and sends it: resolves once the server has
    // confirmed it, rejects with the message shown when the server refuses it for good.
    function keep(trial, body) {
      keepPending(pending().concat([{ trial, body }]));
      const done = new Promise((resolve, reject) => confirmed.set(trial, (confirmed.get(trial) || []).concat([{ resolve, reject }])));
      deliver();
      return done;
    }
    return {
      keep,
      deliver,
      unconfirmed: () => pending().length,
      delivering: () => delivering !== null,  // answers are being sent (or a retry waits)
      refusal: () => refusal,                 // the message of an answer refused for good, or ''
      roundTripsMs: () => roundTripsMs.slice(),
    };
  }
  return { create };
})();
