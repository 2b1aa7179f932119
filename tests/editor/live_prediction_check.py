#!/usr/bin/env python3
"""Check of the editor's live path with touch prediction on (live_prediction_gui_test.sh).

usage: live_prediction_check.py WAV GESTURE.csv POINTER.csv X Y R HORIZON_S

The pointer (steady_pointer's log) sent one move per period at known times. The editor stamps each
event when its event loop handles it: a loaded GUI thread drawing a frame handles the events queued
meanwhile together, so the recorded history is stop-and-go even though the pointer is steady. Each
recorded move k is sent move k; its handling delay is its stamp minus its send time, up to a
constant (the clocks' offset), taken as the smallest of them. So the true path on the output's time
axis is move k at (send time + offset), and the crossings of the disc of radius R around (X, Y) are
read from it.

A predictor that continues the recorded motion from the newest event n by the horizon H puts the
finger at the true position of t + H - delay_n, delay_n >= 0: the drive may lead the true path by
at most H (plus MARGIN_S: the render block, the waveform's first sample above threshold, the
velocity's error on a steady line). It never lags the events the editor has: the drive starts no
later than the first recorded move inside the disc and stops no later than the first one past it
(plus MARGIN_S).
"""
import statistics
import sys

from gui_check import driven_samples, fail, read_gesture, read_wav

MARGIN_S = 0.006


def read_pointer(path):
    rows = []
    for line in open(path):
        if line.startswith("deadline_s"):
            continue
        deadline, sent, x, y, event = line.strip().split(",")
        rows.append((float(deadline), float(sent), int(x), int(y), event))
    return rows


def main(argv):
    if len(argv) != 8:
        fail(__doc__)
    wav, gesture, pointer = argv[1:4]
    cx, cy, r, horizon_s = (float(v) for v in argv[4:8])

    sent = read_pointer(pointer)
    moves_sent = [row for row in sent if row[4] == "move"][1:]  # the first move is before the press
    gaps_ms = [1e3 * (b[1] - a[1]) for a, b in zip(moves_sent, moves_sent[1:])]
    period_ms = 1e3 * (moves_sent[1][0] - moves_sent[0][0])
    late_ms = sorted(1e3 * (row[1] - row[0]) for row in sent)
    print(f"pointer: {len(moves_sent)} moves every {period_ms:.1f} ms; sent intervals median "
          f"{statistics.median(gaps_ms):.2f} ms, late by p50 {late_ms[len(late_ms) // 2]:.2f} ms, "
          f"max {late_ms[-1]:.2f} ms")
    if abs(statistics.median(gaps_ms) - period_ms) > 1.0:
        fail("the pointer itself was not steady")

    rows = [row for row in read_gesture(gesture) if row[1] == 0]
    moves = [row for row in rows if row[4] == "move"]
    if any(abs(row[3] - cy) > 0.6 for row in moves):
        fail(f"{gesture}: the finger left the line y = {cy} mm")
    if len(moves) != len(moves_sent):
        fail(f"{gesture}: {len(moves)} moves recorded of {len(moves_sent)} sent")
    stamps = [row[0] for row in moves]
    xs = [row[2] for row in moves]
    delays = [t - s[1] for t, s in zip(stamps, moves_sent)]
    offset = min(delays)
    delay_ms = sorted(1e3 * (d - offset) for d in delays)
    print(f"recorded: {len(moves)} moves; handling delay median {delay_ms[len(delay_ms) // 2]:.1f} ms, "
          f"max {delay_ms[-1]:.1f} ms")
    true_t = [s[1] + offset for s in moves_sent]

    def true_crossing(x_edge):
        for (t0, x0), (t1, x1) in zip(zip(true_t, xs), zip(true_t[1:], xs[1:])):
            if x0 < x_edge <= x1:
                return t0 + (t1 - t0) * (x_edge - x0) / (x1 - x0)
        fail(f"{gesture}: the finger never reached x = {x_edge} mm")

    def first_recorded(x_edge):
        return next(t for t, x in zip(stamps, xs) if x >= x_edge)

    rate, d = read_wav(wav)
    on = driven_samples(wav, d)
    t_on, t_off = on[0] / rate, on[-1] / rate
    print(f"the finger is on the dot {true_crossing(cx - r):.4f}..{true_crossing(cx + r):.4f} s; the drive "
          f"is on {t_on:.4f}..{t_off:.4f} s; horizon {1e3 * horizon_s:.1f} ms")
    bad = []
    for name, x_edge, t_drive in (("onset", cx - r, t_on), ("offset", cx + r, t_off)):
        lead = true_crossing(x_edge) - t_drive
        late = t_drive - first_recorded(x_edge)
        print(f"{name}: {1e3 * lead:.1f} ms before the finger (at most {1e3 * (horizon_s + MARGIN_S):.1f}), "
              f"{1e3 * late:.1f} ms after the editor had it (at most {1e3 * MARGIN_S:.1f})")
        if lead > horizon_s + MARGIN_S:
            bad.append(f"the {name} leads the finger by {1e3 * lead:.1f} ms, more than the horizon")
        if late > MARGIN_S:
            bad.append(f"the {name} comes {1e3 * late:.1f} ms after the editor had the event")
    gaps = [b - a for a, b in zip(on, on[1:]) if b - a > 0.005 * rate]
    if gaps:
        bad.append(f"the drive stops {len(gaps)} times inside the pulse")
    if bad:
        fail("; ".join(bad))
    print("ok: the pulse is felt where the finger crosses the dot, ahead of it by the horizon")


if __name__ == "__main__":
    main(sys.argv)
