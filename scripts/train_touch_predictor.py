#!/usr/bin/env python3
"""Trains the touch predictor's `learned` model (primitives/touch_prediction/learned_predictor.hpp).

Data: tests/data/touch-latency-henze2017 only (Henze et al., MobileHCI 2017; participants 1-4 of
the writing, drawing and Fitts tasks; Apache-2.0, see the LICENSE there), plus synthetic smooth
paths generated here (constant acceleration and gentle curves at 50-250 mm/s).

The model (docs/latency.md, "The learned model"): from one finger's history (the C++ FingerHistory
rule, see fit_touch_predictor.py), the newest N points at least MIN_STEP_S apart (the newest point,
then walking back), padded with the oldest point at NOMINAL_S gaps (the finger was put down there).
Their N - 1 steps are expressed in the stroke's frame: rotated so that the last three steps point
along +x, divided by their mean length S. The inputs are, per step (newest first), its two
coordinates in that frame and its time gap in units of NOMINAL_S (minus 1, clipped to [-1, 3]),
then the horizon min(h, H_REF_S) / H_REF_S and ln(S / 1 mm) / 2 clipped to [-3, 2]. Two ReLU layers
of WIDTH units and a tanh output of two units f give the offset, in the stroke's frame,
    S * (h / H_REF_S) * F_MAX * tanh(...),
rotated back, and blended with the newest step's velocity v_1: offset = g v_1 h + (1 - g) o_net,
g = exp(-rho / GATE_SCALE), rho the rms of |v_j - v_1| / |v_1| over the older steps. So by
construction: S = 0 (a still finger) gives no offset; h = 0 gives none; a constant velocity
(rho = 0) is continued exactly; the network's offset is at most sqrt(2) F_MAX S h / H_REF_S (a
fixed multiple of the recent steps' mean length); and the offset is clamped to h * REACH_PER_S
times the largest distance from the newest point to the points back to the newest one at least
RECENT_S old, so a finger that has rested RECENT_S is predicted exactly where it is.

Training: mini-batch Adam on the weighted mean Euclidean distance (mm) between the predicted and the
recorded position s events later (s = 1..6 at h = s / 60 s; past the last move of a stroke its
last move, as the authors' protocol pads), each event mirrored across the direction of motion,
and the synthetic paths' exact positions at h. Seeds are pinned. The weights make the loss the
selection's own measure: each (task, s) group of rows weighs the same, and within it a row counts
1 / (rows x the group's mean displacement), so the loss is the mean over tasks and horizons of
error / no extrapolation; the synthetic paths form a fourth task weighing SYNTHETIC_SHARE of one.

Selection: the form (N, WIDTH) with the least leave-one-participant-out (LOPO) error, the mean over
tasks and horizons of (held-out error / no extrapolation), measured with the authors' protocol
(primitives/touch_prediction/prediction_protocol.hpp, ported below) on the held-out participant
of each fold. The LOPO table (none, linear, the fitted filter refitted per fold, learned) goes to
stdout and to tests/data/touch_prediction/learned_lopo.csv. The shipped weights are trained on all
of participants 1-4 with the chosen form.

Usage: train_touch_predictor.py [--data DIR] [--forms N:W,...] [--check | --check-forward]
  (default) select, report LOPO, train on all, write the header, probes and the LOPO CSV;
  --check          retrain everything and compare the LOPO figures with learned_lopo.csv and the
                   in-sample figures with the header's (tolerance CHECK_TOLERANCE, ratios), not bytes;
  --check-forward  recompute the header's probe predictions from the header's weights (seconds).
"""
import argparse
import math
import os
import re
import sys
import time

os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")
os.environ.setdefault("OMP_NUM_THREADS", "1")
import numpy as np  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import fit_touch_predictor as fitted_fit  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
HEADER = os.path.join(ROOT, "primitives/touch_prediction/learned_weights.hpp")
PROBES = os.path.join(ROOT, "tests/touch_prediction/learned_probes.hpp")
LOPO_CSV = os.path.join(ROOT, "tests/data/touch_prediction/learned_lopo.csv")

MIN_STEP_S = 0.006
NOMINAL_S = 1.0 / 60.0
H_REF_S = 0.1
F_MAX = 12.0
GATE_SCALE = 0.01
RECENT_S = 0.1
REACH_PER_S = 1000.0
FORMS = ((10, 32), (14, 32), (18, 24))
PARTICIPANTS = (1, 2, 3, 4)
TASKS = fitted_fit.TASKS
STEPS_AHEAD = (2, 4, 6)  # the protocol's horizons: 33, 67, 100 ms
EPOCHS = 10
BATCH = 512
LEARNING_RATE = 3e-3
SYNTHETIC_STROKES = 400
SYNTHETIC_SHARE = 0.3  # of one task's weight in the loss (1.0 gave a LOPO mean of 0.480, 0.3 0.472)
SEED = 20170904
CHECK_TOLERANCE = 0.02  # ratios to no extrapolation


# ---- data ----------------------------------------------------------------------------------------

def task_strokes(directory, prefix, participant):
    """Strokes as lists of (t, x, y): the down, the moves, the up (as vimg's trace reader gives)."""
    rows = fitted_fit.load(directory, prefix, participant)
    return [[rows[i][:3] for i in stroke] for stroke in fitted_fit.strokes(rows)]


def push(history, t, x, y):
    fitted_fit.push(history, t, x, y)


def n_inputs(n_points):
    return 3 * (n_points - 1) + 2


def features(history, n_points):
    """(inputs, S, cos, sin, gate, v1x, v1y) of the history's newest state, or None for a still
    finger (S = 0)."""
    t0, x0, y0 = history[-1]
    pts = [history[-1]]
    for age in range(2, len(history) + 1):
        if len(pts) == n_points:
            break
        p = history[-age]
        if pts[-1][0] - p[0] >= MIN_STEP_S:
            pts.append(p)
    while len(pts) < n_points:
        oldest = pts[-1]
        pts.append((oldest[0] - NOMINAL_S, oldest[1], oldest[2]))
    steps = [(pts[j - 1][1] - pts[j][1], pts[j - 1][2] - pts[j][2], pts[j - 1][0] - pts[j][0]) for j in range(1, n_points)]
    length = 0.0
    for sx, sy, _ in steps:
        length += math.sqrt(sx * sx + sy * sy)
    if length == 0.0:
        return None
    scale = length / (n_points - 1)
    ux, uy = x0 - pts[3][1], y0 - pts[3][2]
    norm = math.sqrt(ux * ux + uy * uy)
    c, s = (ux / norm, uy / norm) if norm > 0.0 else (1.0, 0.0)
    inputs = []
    for sx, sy, gap in steps:
        inputs += [(c * sx + s * sy) / scale, (-s * sx + c * sy) / scale, min(max(gap / NOMINAL_S - 1.0, -1.0), 3.0)]
    inputs += [0.0, min(max(math.log(scale) / 2.0, -3.0), 2.0)]  # the horizon goes in at [-2]
    # The gate: how far the steps' velocities depart from the newest step's (rms, relative).
    v1x, v1y = steps[0][0] / steps[0][2], steps[0][1] / steps[0][2]
    speed2 = v1x * v1x + v1y * v1y
    gate = 0.0
    if speed2 > 0.0:
        departure = 0.0
        for sx, sy, gap in steps[1:]:
            dx, dy = sx / gap - v1x, sy / gap - v1y
            departure += dx * dx + dy * dy
        gate = math.exp(-math.sqrt(departure / (n_points - 2) / speed2) / GATE_SCALE)
    return np.array(inputs), scale, c, s, gate, v1x, v1y, reach(history)


def reach(history):
    """The largest distance from the newest point to the points back to the newest one at least
    RECENT_S old (all points when none is): the offset is clamped to h * REACH_PER_S times it."""
    t0, x0, y0 = history[-1]
    largest2 = 0.0
    for age in range(2, len(history) + 1):
        t, x, y = history[-age]
        largest2 = max(largest2, (x - x0) * (x - x0) + (y - y0) * (y - y0))
        if t0 - t >= RECENT_S:
            break
    return math.sqrt(largest2)


class Samples:
    """Rows: inputs (horizon filled in), scale, rotation, now, target, weight."""

    def __init__(self):
        self.rows = []  # (inputs or None, scale, c, s, x0, y0, h, tx, ty)
        self.groups = []  # the loss's group of each row: 10 x task + s (task 3: synthetic)

    def add(self, feat, now, h, target, group=0):
        self.rows.append((feat, now, h, target))
        self.groups.append(group)

    def arrays(self, n_points):
        n = len(self.rows)
        x = np.zeros((n, n_inputs(n_points)))
        meta = np.zeros((n, 14))  # scale, c, s, x0, y0, h, tx, ty, moving, gate, v1x, v1y, reach, group
        for i, (feat, now, h, target) in enumerate(self.rows):
            meta[i, 3:5] = now
            meta[i, 5] = h
            meta[i, 6:8] = target
            meta[i, 13] = self.groups[i]
            if feat is None:
                continue
            inputs, scale, c, s, gate, v1x, v1y, reach_mm = feat
            x[i] = inputs
            x[i, -2] = min(h, H_REF_S) / H_REF_S
            meta[i, 0:3] = (scale, c, s)
            meta[i, 8] = 1.0
            meta[i, 9:13] = (gate, v1x, v1y, reach_mm)
        return x, meta


def stroke_states(stroke, n_points):
    """Per event index n: (learned features, lag displacements, linear prediction data) of ev[0..n]."""
    history, out = [], []
    for t, x, y in stroke:
        push(history, t, x, y)
        out.append((features(history, n_points), fitted_fit.lag_displacements(history), list(history[-64:])))
    return out


def protocol_samples(stroke, s):
    """The authors' protocol (prediction_protocol.cpp): (history end index, target) per sample."""
    moves = len(stroke) - 2
    window = 11 + s
    if moves < 12:
        return []
    out = []
    for i in range(0, moves - 12 + 1):
        jump = i + window + 1 if i + window <= moves else moves

        def at(k):
            return stroke[1 + min(k, jump - 1)]
        same_time = False
        for a in range(1, window):
            k = i + a
            dt = at(jump - 1)[0] - at(jump - 2)[0] if k >= jump - 1 else at(k)[0] - at(k - 1)[0]
            if dt < 5e-4:
                same_time = True
                break
        if same_time:
            continue
        out.append((1 + i + 10, at(i + 10 + s)[1:], at(i + 9)[1:]))
    return out


def linear_prediction(history, h):
    tn, xn, yn = history[-1]
    for t, x, y in reversed(history[:-1]):
        if tn - t >= 0.001:
            return xn + (xn - x) / (tn - t) * h, yn + (yn - y) / (tn - t) * h
    return xn, yn


def synthetic_strokes(rng, count):
    """Smooth paths at 50-250 mm/s, events at 60 or 120 Hz: constant acceleration along a line, or
    gentle curves (radius >= 30 mm) with a speed that swells and ebbs. (event times, fine time, x, y)"""
    out = []
    for k in range(count):
        rate = 60.0 if k % 3 else 120.0
        duration = rng.uniform(0.4, 1.2)
        fine_t = np.arange(0.0, duration + 0.25, 2.5e-4)
        if k % 2 == 0:
            v0, a = rng.uniform(50.0, 250.0), rng.uniform(-400.0, 400.0)
            speed = np.clip(v0 + a * fine_t, 50.0, 250.0)
            curvature = 0.0
        else:
            mean = rng.uniform(80.0, 200.0)
            speed = mean * (1.0 + rng.uniform(0.0, 0.5) * np.sin(rng.uniform(2.0, 8.0) * fine_t + rng.uniform(0.0, 6.3)))
            curvature = rng.uniform(-1.0, 1.0) / 30.0
        along = np.concatenate([[0.0], np.cumsum(0.5 * (speed[1:] + speed[:-1]) * np.diff(fine_t))])
        heading = rng.uniform(0.0, 2.0 * np.pi) + curvature * along
        px = np.concatenate([[0.0], np.cumsum(np.cos(heading[:-1]) * np.diff(along))])
        py = np.concatenate([[0.0], np.cumsum(np.sin(heading[:-1]) * np.diff(along))])
        out.append((np.arange(0.0, duration, 1.0 / rate), fine_t, px, py))
    return out


def build(strokes_by_group, synthetic, n_points, fit_groups):
    """Training samples from the groups in fit_groups (plus the synthetic paths)."""
    train = Samples()
    for key, strokes in strokes_by_group.items():
        if key[1] not in fit_groups:
            continue
        for stroke, states in strokes:
            moves = len(stroke) - 2
            for n in range(1, moves + 1):
                for s in range(1, 7):
                    target = stroke[min(n + s, moves)]
                    train.add(states[n][0], stroke[n][1:], s * NOMINAL_S, target[1:], 10 * TASK_INDEX[key[0]] + s)
    for t, fine_t, px, py in synthetic:
        history = []
        for i, ti in enumerate(t):
            xi, yi = np.interp(ti, fine_t, px), np.interp(ti, fine_t, py)
            push(history, ti, xi, yi)
            if i == 0:
                continue
            feat = features(history, n_points)
            for s in range(1, 7):
                h = s * NOMINAL_S
                train.add(feat, (xi, yi), h, (np.interp(ti + h, fine_t, px), np.interp(ti + h, fine_t, py)), 10 * SYNTHETIC_TASK + s)
    return train


# ---- the network ---------------------------------------------------------------------------------

def init(n_in, width, rng):
    return [rng.normal(0, np.sqrt(2.0 / n_in), (n_in, width)), np.zeros(width),
            rng.normal(0, np.sqrt(2.0 / width), (width, width)), np.zeros(width),
            rng.normal(0, 0.1 / np.sqrt(width), (width, 2)), np.zeros(2)]


def forward(params, x):
    w1, b1, w2, b2, w3, b3 = params
    z1 = x @ w1 + b1
    a1 = np.maximum(z1, 0.0)
    z2 = a1 @ w2 + b2
    a2 = np.maximum(z2, 0.0)
    f = np.tanh(a2 @ w3 + b3)
    return F_MAX * f, (a1, a2, f)


def local_offsets(meta):
    """The target offsets in the stroke frame (mm)."""
    dx, dy = meta[:, 6] - meta[:, 3], meta[:, 7] - meta[:, 4]
    c, s = meta[:, 1], meta[:, 2]
    return np.stack([c * dx + s * dy, -s * dx + c * dy], axis=1)


TASK_INDEX = {task: i for i, (task, _) in enumerate(TASKS)}
SYNTHETIC_TASK = len(TASKS)


def row_weights(meta):
    """Each row's weight in the loss (mean 1): 1 / (rows of its group x the group's mean distance
    to its target), times SYNTHETIC_SHARE for the synthetic paths' groups."""
    groups = meta[:, 13].astype(int)
    displacement = np.hypot(meta[:, 6] - meta[:, 3], meta[:, 7] - meta[:, 4])
    weights = np.zeros(len(meta))
    for group in np.unique(groups):
        rows = groups == group
        share = SYNTHETIC_SHARE if group // 10 == SYNTHETIC_TASK else 1.0
        weights[rows] = share / (rows.sum() * max(displacement[rows].mean(), 1e-3))
    return weights / weights.mean()


def train(x, meta, width, seed, epochs=None):
    epochs = epochs or EPOCHS
    rng = np.random.default_rng(seed)
    moving = meta[:, 8] > 0
    x, meta = x[moving], meta[moving]
    target = local_offsets(meta)
    c, s, h = meta[:, 1], meta[:, 2], meta[:, 5]
    linear = np.stack([(c * meta[:, 10] + s * meta[:, 11]) * h, (-s * meta[:, 10] + c * meta[:, 11]) * h], axis=1)
    gate = np.tile(meta[:, 9], 2)[:, None]
    linear = np.vstack([linear, linear * [1.0, -1.0]])
    # Mirror across the direction of motion: b -> -b for every step and for the target.
    mirror_x = x.copy()
    mirror_x[:, 1:-2:3] *= -1.0
    x = np.vstack([x, mirror_x])
    target = np.vstack([target, target * [1.0, -1.0]])
    gain = np.tile(meta[:, 0] * meta[:, 5] / H_REF_S, 2)[:, None]
    weights = np.tile(row_weights(meta), 2)[:, None]
    params = init(x.shape[1], width, rng)
    m = [np.zeros_like(p) for p in params]
    v = [np.zeros_like(p) for p in params]
    step = 0
    batches = int(np.ceil(len(x) / BATCH))
    for epoch in range(epochs):
        order = rng.permutation(len(x))
        lr = LEARNING_RATE * 0.5 * (1.0 + np.cos(np.pi * epoch / epochs))
        for b in range(batches):
            idx = order[b * BATCH:(b + 1) * BATCH]
            xb, gb, tb = x[idx], gain[idx] * (1.0 - gate[idx]), target[idx] - gate[idx] * linear[idx]
            out, (a1, a2, f) = forward(params, xb)
            diff = out * gb - tb
            dist = np.sqrt(np.sum(diff * diff, axis=1) + 1e-4)
            grad_out = diff / dist[:, None] * gb * weights[idx] / len(idx)
            gz3 = grad_out * F_MAX * (1.0 - f * f)
            w1, b1, w2, b2, w3, b3 = params
            ga2 = gz3 @ w3.T
            gz2 = ga2 * (a2 > 0)
            ga1 = gz2 @ w2.T
            gz1 = ga1 * (a1 > 0)
            grads = [xb.T @ gz1, gz1.sum(0), a1.T @ gz2, gz2.sum(0), a2.T @ gz3, gz3.sum(0)]
            step += 1
            for i, g in enumerate(grads):
                m[i] = 0.9 * m[i] + 0.1 * g
                v[i] = 0.999 * v[i] + 0.001 * g * g
                params[i] = params[i] - lr * (m[i] / (1 - 0.9 ** step)) / (np.sqrt(v[i] / (1 - 0.999 ** step)) + 1e-8)
    return params


def predict(params, x, meta):
    """Predicted positions (n, 2) in mm: the still rows at their position."""
    out, _ = forward(params, x)
    gain = (meta[:, 0] * meta[:, 5] / H_REF_S)[:, None]
    local = out * gain * meta[:, 8:9]
    c, s, gate, h = meta[:, 1], meta[:, 2], meta[:, 9], meta[:, 5]
    ox = gate * meta[:, 10] * h + (1.0 - gate) * (c * local[:, 0] - s * local[:, 1])
    oy = gate * meta[:, 11] * h + (1.0 - gate) * (s * local[:, 0] + c * local[:, 1])
    size = np.sqrt(ox * ox + oy * oy)
    limit = h * REACH_PER_S * meta[:, 12]
    shrink = np.where(size > limit, limit / np.where(size > 0.0, size, 1.0), 1.0)
    return np.stack([meta[:, 3] + ox * shrink, meta[:, 4] + oy * shrink], axis=1)


# ---- evaluation ----------------------------------------------------------------------------------

def fitted_predictions(free, exact, lags, h):
    """The C++ fitted model (finger_predictor.cpp) on lag displacements (n, 2, K) at horizon h."""
    j = int(np.floor(h / fitted_fit.LAG_S))
    a = h / fitted_fit.LAG_S - j
    def weights(table):
        lower = np.zeros(fitted_fit.K) if j == 0 else table[j - 1]
        return (1 - a) * lower + a * table[j] if j < fitted_fit.NH else table[-1] * h / (fitted_fit.NH * fitted_fit.LAG_S)
    wf, we = weights(free), weights(exact)
    k = np.arange(1, fitted_fit.K + 1)
    v = -(lags @ k) / (fitted_fit.LAG_S * np.sum(k * k))  # (n, 2)
    resid = lags + v[:, :, None] * k * fitted_fit.LAG_S
    rho = np.sqrt(np.sum(resid ** 2, axis=(1, 2)) / fitted_fit.K) / (np.hypot(v[:, 0], v[:, 1]) * fitted_fit.K * fitted_fit.LAG_S + fitted_fit.BLEND_FLOOR_MM)
    lam = np.exp(-rho / fitted_fit.BLEND_SCALE)[:, None]
    return lam * (lags @ we) + (1 - lam) * (lags @ wf)


def evaluate(groups, models, n_points):
    """Sums of distances (mm) per (task, s, participant): samples, none, authors' linear, linear,
    fitted, learned; the participant's predictions come from models[participant]."""
    table = {}
    for (task, participant), strokes in groups.items():
        free, exact, params = models[participant]
        for s in STEPS_AHEAD:
            h = s * NOMINAL_S
            rows = Samples()
            lags, nows, targets, lin, authors = [], [], [], [], []
            for stroke, states in strokes:
                for end, target, before in protocol_samples(stroke, s):
                    now = stroke[end][1:]
                    rows.add(states[end][0], now, h, target)
                    lags.append(states[end][1])
                    targets.append(target)
                    nows.append(now)
                    lin.append(linear_prediction(states[end][2], h))
                    authors.append((now[0] + s * (now[0] - before[0]), now[1] + s * (now[1] - before[1])))
            x, meta = rows.arrays(n_points)
            targets, nows = np.array(targets), np.array(nows)
            learned = predict(params, x, meta)
            fitted = nows + fitted_predictions(free, exact, np.array(lags), h)
            def total(p):
                return float(np.sum(np.hypot(*(np.asarray(p) - targets).T)))
            table[(task, s, participant)] = (len(targets), total(nows), total(authors), total(lin), total(fitted), total(learned))
    return table


def pooled(table):
    """Means (mm) per (task, s) over the participants: samples, none, authors, linear, fitted, learned."""
    out = {}
    for task, _ in TASKS:
        for s in STEPS_AHEAD:
            sums = np.sum([v for (t, ss, _), v in table.items() if t == task and ss == s], axis=0)
            out[(task, s)] = (int(sums[0]), *(sums[1:] / sums[0]))
    return out


def print_table(table, title):
    print(f"\n{title}")
    print("| task | horizon | samples | none | linear (authors) | linear | fitted | learned | learned / none |")
    print("|---|---|---:|---:|---:|---:|---:|---:|---:|")
    for (task, s), (n, none, authors, lin, fit, learned) in pooled(table).items():
        px = fitted_fit.PX_PER_MM
        print(f"| {task} | {s * 1000 / 60:.0f} ms | {n} | {none * px:.1f} px | {authors * px:.1f} px | {lin * px:.1f} px | "
              f"{fit * px:.1f} px ({fit / none:.2f}) | {learned * px:.1f} px | {learned / none:.2f} |")


def mean_ratio(table):
    return float(np.mean([v[5] / v[1] for v in pooled(table).values()]))


def load_groups(directory, n_points):
    groups = {}
    for task, prefix in TASKS:
        for participant in PARTICIPANTS:
            groups[(task, participant)] = [(s, stroke_states(s, n_points)) for s in task_strokes(directory, prefix, participant)]
    return groups


def refit_fitted(directory, participants):
    fitted_fit.PARTICIPANTS = participants
    free, exact, _ = fitted_fit.fit(*fitted_fit.samples(directory))
    fitted_fit.PARTICIPANTS = PARTICIPANTS
    return free, exact


def lopo(directory, n_points, width, synthetic, fitted_by_fold, groups):
    models = {}
    for held in PARTICIPANTS:
        fit_on = tuple(p for p in PARTICIPANTS if p != held)
        x, meta = build(groups, synthetic, n_points, fit_on).arrays(n_points)
        started = time.time()
        params = train(x, meta, width, SEED + held)
        print(f"  N={n_points} W={width}: fold without participant {held}: {len(x)} samples, {time.time() - started:.0f} s", flush=True)
        models[held] = (*fitted_by_fold[held], params)
    return evaluate(groups, models, n_points)


# ---- outputs -------------------------------------------------------------------------------------

def write(path, text):
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path + ".tmp", "w", encoding="utf-8") as f:
        f.write(text)
    os.replace(path + ".tmp", path)
    print(f"wrote {path}")


def c_array(name, values):
    values = np.atleast_2d(values)
    dims = "".join(f"[{d}]" for d in np.shape(values)) if values.shape[0] > 1 else f"[{values.shape[1]}]"
    rows = [", ".join(f"{v:.17g}" for v in row) for row in values]
    body = "\n".join(f"    {{{r}}}," for r in rows) if values.shape[0] > 1 else f"    {rows[0]},"
    return f"inline constexpr double {name}{dims} = {{\n{body}\n}};"


def ratio_lines(table):
    lines = []
    for (task, s), v in pooled(table).items():
        lines.append(f"//   {task} {s * 1000 / 60:.0f} ms: none {v[1] * fitted_fit.PX_PER_MM:.1f} px, fitted {v[4] / v[1]:.3f}, learned {v[5] / v[1]:.3f}")
    return "\n".join(lines)


def header_text(params, n_points, width, lopo_table, in_sample, form_ratios):
    w1, b1, w2, b2, w3, b3 = params
    forms = ", ".join(f"N={n} W={w}: {r:.4f}" for (n, w), r in form_ratios.items())
    return f"""#pragma once
// Generated by scripts/train_touch_predictor.py from tests/data/touch-latency-henze2017 (Henze et al.,
// MobileHCI 2017, participants 1-4, Apache-2.0) and synthetic smooth paths: do not edit. Regenerate with
//   /usr/bin/python3 scripts/train_touch_predictor.py          (about 10 minutes on 2 cores)
// and check a regeneration with --check (the figures below within {CHECK_TOLERANCE} as ratios, not bytes).
// The model: primitives/touch_prediction/learned_predictor.hpp. Forms by leave-one-participant-out
// mean ratio to no extrapolation: {forms}.
// Out of sample (leave-one-participant-out, ratios to no extrapolation, the authors' protocol):
{ratio_lines(lopo_table)}
// In sample (these weights, trained on all of participants 1-4):
{ratio_lines(in_sample)}
namespace vimg::touch_prediction {{

inline constexpr int kLearnedPoints = {n_points};
inline constexpr int kLearnedInputs = {n_inputs(n_points)};
inline constexpr int kLearnedWidth = {width};
inline constexpr double kLearnedMinStep_s = {MIN_STEP_S};
inline constexpr double kLearnedNominalGap_s = 1.0 / 60.0;
inline constexpr double kLearnedHorizonRef_s = {H_REF_S};
inline constexpr double kLearnedMaxGain = {F_MAX};
inline constexpr double kLearnedGateScale = {GATE_SCALE};
inline constexpr double kLearnedRecent_s = {RECENT_S};
inline constexpr double kLearnedReachPerSecond = {REACH_PER_S};

{c_array("kLearnedW1", w1)}
{c_array("kLearnedB1", b1)}
{c_array("kLearnedW2", w2)}
{c_array("kLearnedB2", b2)}
{c_array("kLearnedW3", w3)}
{c_array("kLearnedB3", b3)}

}}  // namespace vimg::touch_prediction
"""


def read_header():
    """(params, n_points, width, in-sample ratios) from the committed header."""
    with open(HEADER, encoding="utf-8") as f:
        text = f.read()
    def const(name):
        return float(re.search(rf"{name} = ([-0-9.e]+)", text).group(1))
    n_points, width = int(const("kLearnedPoints")), int(const("kLearnedWidth"))
    def array(name, shape):
        body = re.search(rf"{name}\[[^=]*= {{(.*?)\n}};", text, re.S).group(1)
        return np.array([float(v) for v in re.findall(r"[-0-9.e+]+", body.replace("{", " ").replace("}", " ")) if v not in ("+", "-")]).reshape(shape)
    n_in = n_inputs(n_points)
    params = [array("kLearnedW1", (n_in, width)), array("kLearnedB1", (width,)), array("kLearnedW2", (width, width)),
              array("kLearnedB2", (width,)), array("kLearnedW3", (width, 2)), array("kLearnedB3", (2,))]
    in_sample = text.split("// In sample")[1].split("namespace")[0]
    return params, n_points, width, re.findall(r"//   (\w+) (\d+) ms: .*learned ([0-9.]+)", in_sample)


def probe_histories():
    """Histories the C++ test replays (tests/touch_prediction/learned_probe_test.cpp): (events, horizons)."""
    rng = np.random.default_rng(SEED + 7)
    out = []
    curve = [(i / 60.0, 20.0 + 30.0 * np.cos(0.3 * i), 40.0 + 25.0 * np.sin(0.2 * i)) for i in range(20)]
    jitter = [(0.5 + i * 0.0167 + rng.uniform(-0.006, 0.006), 3.0 * i + rng.normal(0, 0.3), 0.5 * i * i / 10.0) for i in range(16)]
    start = [(2.0, 10.0, 10.0), (2.017, 11.5, 10.2), (2.033, 13.4, 10.9)]
    fast = [(i / 240.0, 150.0 * i / 240.0 + 2.0 * np.sin(i / 10.0), 40.0 * (i / 240.0) ** 2) for i in range(80)]
    stop_go = [(i / 60.0, 5.0 * min(i, 8) + 5.0 * max(0, i - 14), 1.0) for i in range(20)]
    for events in (curve, jitter, start, fast, stop_go):
        out.append((events, (0.0, 0.01, 0.025, 0.0333, 0.0667, 0.1, 0.15)))
    return out


def probe_predictions(params, n_points):
    rows = []
    for k, (events, horizons) in enumerate(probe_histories()):
        history = []
        for t, x, y in events:
            push(history, t, x, y)
        feat = features(history, n_points)
        s = Samples()
        for h in horizons:
            s.add(feat, history[-1][1:], h, (0.0, 0.0))
        x, meta = s.arrays(n_points)
        for h, p in zip(horizons, predict(params, x, meta)):
            rows.append((k, h, p[0], p[1]))
    return rows


def probes_text(params, n_points):
    histories = probe_histories()
    events = [(k, t, x, y) for k, (ev, _) in enumerate(histories) for t, x, y in ev]
    expected = probe_predictions(params, n_points)
    ev_rows = "\n".join(f"    {{{k}, {t:.17g}, {x:.17g}, {y:.17g}}}," for k, t, x, y in events)
    ex_rows = "\n".join(f"    {{{k}, {h:.17g}, {x:.17g}, {y:.17g}}}," for k, h, x, y in expected)
    return f"""#pragma once
// Generated by scripts/train_touch_predictor.py with primitives/touch_prediction/learned_weights.hpp:
// probe histories and the predictions the script's own forward pass gives for them, so that
// tests/touch_prediction/learned_probe_test.cpp checks the C++ forward pass against numpy's
// (`train_touch_predictor.py --check-forward` recomputes them from the committed weights).
namespace vimg::learned_probes {{

struct ProbeEvent {{
  int history;
  double time_s, x_mm, y_mm;
}};
struct ProbePrediction {{
  int history;
  double horizon_s, x_mm, y_mm;
}};

inline constexpr int kHistories = {len(histories)};
inline constexpr ProbeEvent kEvents[] = {{
{ev_rows}
}};
inline constexpr ProbePrediction kPredictions[] = {{
{ex_rows}
}};

}}  // namespace vimg::learned_probes
"""


def check_forward():
    params, n_points, _, _ = read_header()
    with open(PROBES, encoding="utf-8") as f:
        text = f.read().split("kPredictions[] = {")[1]
    committed = [tuple(float(v) for v in row.split(",")) for row in re.findall(r"\{([^{}]*)\},", text)]
    computed = probe_predictions(params, n_points)
    worst = max(max(abs(a[2] - b[2]), abs(a[3] - b[3])) for a, b in zip(committed, computed))
    if len(committed) != len(computed) or worst > 1e-9:
        sys.exit(f"{PROBES}: error: the probes differ from the forward pass of {HEADER} by {worst:g} mm; run {sys.argv[0]}")
    print(f"{PROBES}: {len(computed)} predictions reproduced from {HEADER} within {worst:.1e} mm")
    return 0


def lopo_csv_text(table):
    lines = ["held_out_participant,task,horizon_ms,samples,none_mm,authors_linear_mm,linear_mm,fitted_mm,learned_mm"]
    for (task, s, participant), v in sorted(table.items(), key=lambda kv: (kv[0][2], kv[0][0], kv[0][1])):
        n = v[0]
        lines.append(f"{participant},{task},{s * 1000 / 60:.0f},{n}," + ",".join(f"{x / n:.6f}" for x in v[1:]))
    return "\n".join(lines) + "\n"


def check(lopo_csv, in_sample):
    """Compares a retraining's figures with the committed ones (ratios within CHECK_TOLERANCE)."""
    def ratios(text):
        out = {}
        for line in text.strip().splitlines()[1:]:
            f = line.split(",")
            out[(f[0], f[1], f[2])] = float(f[8]) / float(f[4])
        return out
    with open(LOPO_CSV, encoding="utf-8") as f:
        committed, fresh = ratios(f.read()), ratios(lopo_csv)
    worst = max(abs(committed[k] - fresh[k]) for k in fresh)
    _, _, _, header_in_sample = read_header()
    now = {(t, f"{s * 1000 / 60:.0f}"): v[5] / v[1] for (t, s), v in pooled(in_sample).items()}
    worst_in = max(abs(float(r) - now[(t, ms)]) for t, ms, r in header_in_sample)
    print(f"largest difference: {worst:.4f} (LOPO per fold), {worst_in:.4f} (in sample); tolerance {CHECK_TOLERANCE}")
    if worst > CHECK_TOLERANCE or worst_in > CHECK_TOLERANCE:
        sys.exit(f"{LOPO_CSV}: error: a retraining differs by more than {CHECK_TOLERANCE}; run {sys.argv[0]}")
    return 0


def smooth_paths_report(params, n_points, count=60):
    """Mean error (mm) of learned and linear on held-out synthetic smooth paths, per horizon."""
    paths = synthetic_strokes(np.random.default_rng(SEED + 99), count)
    out = {}
    for s in STEPS_AHEAD:
        h = s * NOMINAL_S
        rows, lin = Samples(), []
        for t, fine_t, px, py in paths:
            history = []
            for i, ti in enumerate(t):
                xi, yi = np.interp(ti, fine_t, px), np.interp(ti, fine_t, py)
                push(history, ti, xi, yi)
                if ti < 0.15:
                    continue
                rows.add(features(history, n_points), (xi, yi), h, (np.interp(ti + h, fine_t, px), np.interp(ti + h, fine_t, py)))
                lin.append(linear_prediction(history, h))
        x, meta = rows.arrays(n_points)
        target = meta[:, 6:8]
        out[s] = (float(np.mean(np.hypot(*(predict(params, x, meta) - target).T))),
                  float(np.mean(np.hypot(*(np.array(lin) - target).T))))
    return out


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--data", default=os.path.join(ROOT, "tests/data/touch-latency-henze2017"))
    parser.add_argument("--forms", default=",".join(f"{n}:{w}" for n, w in FORMS))
    parser.add_argument("--check", action="store_true")
    parser.add_argument("--check-forward", action="store_true")
    args = parser.parse_args()
    if args.check_forward:
        return check_forward()
    started = time.time()
    forms = [tuple(int(v) for v in f.split(":")) for f in args.forms.split(",")]
    synthetic = synthetic_strokes(np.random.default_rng(SEED), SYNTHETIC_STROKES)
    fitted_by_fold = {held: refit_fitted(args.data, tuple(p for p in PARTICIPANTS if p != held)) for held in PARTICIPANTS}
    results = {}
    for n_points, width in forms:
        groups = load_groups(args.data, n_points)
        table = lopo(args.data, n_points, width, synthetic, fitted_by_fold, groups)
        results[(n_points, width)] = (mean_ratio(table), table, groups)
        print(f"form N={n_points} W={width}: LOPO mean learned / none {results[(n_points, width)][0]:.4f}", flush=True)
    n_points, width = min(results, key=lambda f: results[f][0])
    _, table, groups = results[(n_points, width)]
    print_table(table, f"Leave-one-participant-out (chosen form N={n_points} W={width}):")
    x, meta = build(groups, synthetic, n_points, PARTICIPANTS).arrays(n_points)
    params = train(x, meta, width, SEED)
    free, exact, _ = fitted_fit.fit(*fitted_fit.samples(args.data))
    in_sample = evaluate(groups, {p: (free, exact, params) for p in PARTICIPANTS}, n_points)
    print_table(in_sample, "In sample (the shipped weights, trained on participants 1-4):")
    smooth = smooth_paths_report(params, n_points)
    for s, (learned, lin) in smooth.items():
        print(f"smooth synthetic paths, {s * 1000 / 60:.0f} ms: learned {learned:.3f} mm, linear {lin:.3f} mm, ratio {learned / lin:.2f}")
    print(f"total {time.time() - started:.0f} s")
    header = header_text(params, n_points, width, table, in_sample, {f: r[0] for f, r in results.items()})
    lopo_csv = lopo_csv_text(table)
    if args.check:
        return check(lopo_csv, in_sample)
    write(HEADER, header)
    write(LOPO_CSV, lopo_csv)
    write(PROBES, probes_text(params, n_points))


if __name__ == "__main__":
    sys.exit(main())
