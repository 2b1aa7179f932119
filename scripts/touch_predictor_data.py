"""The learned touch predictor's data: recorded strokes, the model's inputs, the authors' protocol
and the synthetic paths (scripts/train_touch_predictor.py trains on them; docs/latency.md).

Recorded strokes come from tests/data/touch-latency-henze2017 (Henze et al., MobileHCI 2017,
participants 1-4 of the writing, drawing and Fitts tasks, Apache-2.0), read by
fit_touch_predictor.py's reader with the C++ FingerHistory rule.
"""
import math

import numpy as np

import fit_touch_predictor as fitted_fit

MIN_STEP_S = 0.006
NOMINAL_S = 1.0 / 60.0
H_REF_S = 0.1
GATE_SCALE = 0.01
RECENT_S = 0.1
TASKS = fitted_fit.TASKS
TASK_INDEX = {task: i for i, (task, _) in enumerate(TASKS)}
SYNTHETIC_TASK = len(TASKS)  # the smooth synthetic paths' loss groups: 10 x this + s
ONSET_TASK = len(TASKS) + 1  # the synthetic stroke onsets' and ends'
STEPS_AHEAD = (2, 4, 6)  # the protocol's horizons: 33, 67, 100 ms
TRAINING_STEPS = range(1, 7)  # targets 1..6 events ahead in training


def task_strokes(directory, prefix, participant):
    """Strokes as lists of (t, x, y): the down, the moves, the up (as vimg's trace reader gives)."""
    rows = fitted_fit.load(directory, prefix, participant)
    return [[rows[i][:3] for i in stroke] for stroke in fitted_fit.strokes(rows)]


def push(history, t, x, y):
    fitted_fit.push(history, t, x, y)


def n_inputs(n_points):
    return 3 * (n_points - 1) + 2


def features(history, n_points):
    """(inputs, S, cos, sin, gate, v1x, v1y, reach) of the history's newest state, or None for a
    still finger (S = 0). The C++ twin: learned_predictor.cpp's prepare()."""
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
    """Rows of (features, now, horizon, target, loss group) and their arrays for the network."""

    def __init__(self):
        self.rows = []
        self.groups = []  # the loss's group of each row: 10 x task + s

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
    """Per event index n: (learned features, lag displacements, the history) of ev[0..n]."""
    history, out = [], []
    for t, x, y in stroke:
        push(history, t, x, y)
        out.append((features(history, n_points), fitted_fit.lag_displacements(history), list(history[-64:])))
    return out


def load_groups(directory, n_points, participants):
    """{(task, participant): [(stroke, states)]}."""
    groups = {}
    for task, prefix in TASKS:
        for participant in participants:
            groups[(task, participant)] = [(s, stroke_states(s, n_points)) for s in task_strokes(directory, prefix, participant)]
    return groups


def protocol_samples(stroke, s):
    """The authors' protocol (prediction_protocol.cpp): (history end index, target index, index
    before) per sample; the target index is the event s ahead or, past the stroke, the last move."""
    moves = len(stroke) - 2
    window = 11 + s
    if moves < 12:
        return []
    out = []
    for i in range(0, moves - 12 + 1):
        jump = i + window + 1 if i + window <= moves else moves

        def at(k):
            return 1 + min(k, jump - 1)
        same_time = False
        for a in range(1, window):
            k = i + a
            dt = stroke[at(jump - 1)][0] - stroke[at(jump - 2)][0] if k >= jump - 1 else stroke[at(k)][0] - stroke[at(k - 1)][0]
            if dt < 5e-4:
                same_time = True
                break
        if same_time:
            continue
        out.append((1 + i + 10, at(i + 10 + s), at(i + 9)))
    return out


def horizon(stroke, end, target, s, given_target_time):
    """The horizon a sample is predicted at: s / 60 s, or, given the target event's time (as the
    authors' LSTM was), that time less the newest event's; past a stroke's end the target is its
    last move, whose own time is given."""
    if given_target_time:
        return max(stroke[target][0] - stroke[end][0], 0.0)
    return s * NOMINAL_S


def linear_prediction(history, h):
    tn, xn, yn = history[-1]
    for t, x, y in reversed(history[:-1]):
        if tn - t >= 0.001:
            return xn + (xn - x) / (tn - t) * h, yn + (yn - y) / (tn - t) * h
    return xn, yn
