#!/usr/bin/env python3
"""Fits the weights of the touch predictor's `fitted` model (primitives/touch_prediction/).

Data: tests/data/touch-latency-henze2017 only (Henze et al., MobileHCI 2017; participants 1-4 of
the writing, drawing and Fitts tasks; Apache-2.0, see the LICENSE there). Nothing else is read.

The model (docs/latency.md): from one finger's history, the displacements d_k = p(t_n - k*LAG) -
p(t_n), k = 1..K, at lags of LAG = 1/120 s back from the last event t_n (linear interpolation
between stored events, held at the first event before it), predict the displacement at t_n + h as
sum_k w_k(h) d_k, the same scalar weights for x and y. Two weight sets per horizon h_j = j*LAG,
j = 1..NH, are fitted by least squares over every move event of every stroke and every horizon
whose time is inside the stroke (target: the recorded path, linear between events):
  - unconstrained (W_FREE): the least-squares filter;
  - constant-velocity exact (W_EXACT): the same, constrained to sum_k w_k k*LAG = -h, so that a
    finger moving at constant velocity is predicted exactly.
Both are ridge-regularised (RIDGE times the mean diagonal of the normal matrix added to it): the
lag displacements are strongly correlated, and without it the weights swing to +-16 with a noise
gain of about 150; with RIDGE = 1e-3 the sum of |w_k| at 100 ms is about 7-14 and the error
ratios change by less than 0.01 (1e-4 and 1e-2 were tried).
The C++ code blends them by how straight the history is (BLEND_SCALE, chosen by a scan on the same
data: 0.005, 0.01, 0.02, 0.05 gave ratios within 0.01 of each other; 0.01 was best on drawing).

The history rule is the C++ rule (FingerHistory): an event earlier than the last stored one takes
the last one's time; an event replaces the newest stored point while that point is less than
MIN_SPACING after the one before it; at most CAPACITY points.

Usage: fit_touch_predictor.py [--data DIR] [--out HEADER] [--check]
  --check: fit, and compare with HEADER instead of writing it (exit 1 if they differ).
Deterministic: numpy's solve on the same inputs; weights are printed with 9 significant digits.
"""
import argparse
import os
import sys

import numpy as np

LAG_S = 1.0 / 120.0
K = 12
NH = 24
MIN_SPACING_S = 0.002
CAPACITY = 64
PX_PER_MM = 12.72
BLEND_SCALE = 0.01
RIDGE = 1e-3
BLEND_FLOOR_MM = 0.05
TASKS = (("writing", "WriteTasks"), ("drawing", "PaintTasks"), ("fitts", "FittsTasks"))
PARTICIPANTS = (1, 2, 3, 4)


def load(directory, prefix, participant):
    """Rows (time_s, x_mm, y_mm, action) of one file (epoch_ms;time_ms;x_px;y_px;size;action)."""
    rows = []
    with open(os.path.join(directory, f"{prefix}-participant{participant}.txt"), encoding="ascii") as f:
        for number, line in enumerate(f, 1):
            fields = line.strip().split(";")
            if len(fields) != 6:
                sys.exit(f"{f.name}:{number}: error: expected 6 fields separated by ';'")
            rows.append((float(fields[1]) / 1000.0, float(fields[2]) / PX_PER_MM,
                         float(fields[3]) / PX_PER_MM, int(fields[5])))
    return rows


def strokes(rows):
    """Index lists from a down (action 0) to its up (1)."""
    out, current = [], None
    for i, row in enumerate(rows):
        if row[3] == 0:
            current = [i]
        elif current is not None:
            current.append(i)
            if row[3] == 1:
                out.append(current)
                current = None
    return out


def push(history, t, x, y):
    if history and t < history[-1][0]:
        t = history[-1][0]
    if len(history) >= 2 and history[-1][0] - history[-2][0] < MIN_SPACING_S:
        history[-1] = (t, x, y)
    else:
        history.append((t, x, y))
        if len(history) > CAPACITY:
            history.pop(0)


def lag_displacements(history):
    tn, xn, yn = history[-1]
    d = np.zeros((2, K))
    j = len(history) - 1
    for k in range(1, K + 1):
        tq = tn - k * LAG_S
        while j > 0 and history[j - 1][0] > tq:
            j -= 1
        if j == 0:
            x, y = history[0][1], history[0][2]
        else:
            t0, x0, y0 = history[j - 1]
            t1, x1, y1 = history[j]
            a = (tq - t0) / (t1 - t0) if t1 > t0 else 1.0
            x, y = x0 + a * (x1 - x0), y0 + a * (y1 - y0)
        d[0, k - 1] = x - xn
        d[1, k - 1] = y - yn
    return d


def samples(directory, participants=PARTICIPANTS):
    features, targets = [], []
    for _, prefix in TASKS:
        for participant in participants:
            rows = load(directory, prefix, participant)
            table = np.array(rows)
            for stroke in strokes(rows):
                t, x, y = table[stroke, 0], table[stroke, 1], table[stroke, 2]
                keep = np.r_[t[1:] != t[:-1], True]  # the recorded path: the last row of equal times
                tu, xu, yu = t[keep], x[keep], y[keep]
                history = []
                for i in stroke:
                    push(history, *table[i, :3])
                    if rows[i][3] != 2:
                        continue
                    tn, xn, yn = history[-1]
                    query = tn + np.arange(1, NH + 1) * LAG_S
                    inside = query <= tu[-1]
                    if not inside.any():
                        continue
                    tx = np.where(inside, np.interp(query, tu, xu) - xn, np.nan)
                    ty = np.where(inside, np.interp(query, tu, yu) - yn, np.nan)
                    features.append(lag_displacements(history))
                    targets.append((tx, ty))
    return np.array(features), np.array(targets)


def fit(features, targets, ridge=RIDGE):
    lags = np.arange(1, K + 1) * LAG_S
    free, exact = [], []
    for j in range(NH):
        used = ~np.isnan(targets[:, 0, j])
        a = np.vstack([features[used, 0, :], features[used, 1, :]])
        b = np.concatenate([targets[used, 0, j], targets[used, 1, j]])
        gram, rhs = a.T @ a, a.T @ b
        gram = gram + ridge * np.trace(gram) / K * np.eye(K)
        free.append(np.linalg.solve(gram, rhs))
        kkt = np.zeros((K + 1, K + 1))
        kkt[:K, :K] = 2.0 * gram
        kkt[:K, K] = lags
        kkt[K, :K] = lags
        exact.append(np.linalg.solve(kkt, np.r_[2.0 * rhs, -(j + 1) * LAG_S])[:K])
    return np.array(free), np.array(exact), int(np.sum(~np.isnan(targets[:, 0, 0])))


def header(free, exact, count):
    def table(name, weights):
        lines = [f"inline constexpr double {name}[kFittedHorizons][kFittedLags] = {{"]
        for j, row in enumerate(weights):
            values = ", ".join(f"{v:.9g}" for v in row)
            lines.append(f"    {{{values}}},  // h = {j + 1}/120 s")
        lines.append("};")
        return "\n".join(lines)
    return f"""#pragma once
// Generated by scripts/fit_touch_predictor.py from tests/data/touch-latency-henze2017 (Henze et al.,
// MobileHCI 2017, participants 1-4, Apache-2.0): do not edit; run the script to reproduce it.
// {count} move events; weights w_k(h) of the displacements k/120 s back, for h = j/120 s.
namespace vimg::touch_prediction {{

inline constexpr int kFittedLags = {K};
inline constexpr int kFittedHorizons = {NH};
inline constexpr double kFittedLag_s = 1.0 / 120.0;
inline constexpr double kBlendScale = {BLEND_SCALE};
inline constexpr double kBlendFloor_mm = {BLEND_FLOOR_MM};

// Least squares.
{table("kFreeWeights", free)}

// Least squares, exact for constant velocity.
{table("kExactWeights", exact)}

}}  // namespace vimg::touch_prediction
"""


def main():
    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--data", default=os.path.join(root, "tests/data/touch-latency-henze2017"))
    parser.add_argument("--out", default=os.path.join(root, "primitives/touch_prediction/fitted_weights.hpp"))
    parser.add_argument("--check", action="store_true")
    args = parser.parse_args()
    features, targets = samples(args.data)
    text = header(*fit(features, targets))
    if args.check:
        with open(args.out, encoding="utf-8") as f:
            if f.read() != text:
                sys.exit(f"{args.out}: error: differs from the fit of {args.data}; run {sys.argv[0]}")
        print(f"{args.out}: reproduced exactly")
        return
    with open(args.out + ".tmp", "w", encoding="utf-8") as f:
        f.write(text)
    os.replace(args.out + ".tmp", args.out)
    print(f"wrote {args.out}")


if __name__ == "__main__":
    main()
