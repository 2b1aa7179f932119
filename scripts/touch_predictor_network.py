"""The learned touch predictor's network, its training and its prediction (numpy only).

The C++ twin is primitives/touch_prediction/learned_predictor.cpp: the same forward pass, gate and
clamp. Two ReLU layers of `width` units and a tanh output f give the offset, in the stroke's
frame, S * (h / H_REF_S) * max_gain * f, rotated back, blended with the newest step's velocity by
the gate, and clamped to h * REACH_PER_S times the recent reach (docs/touch-prediction.md, "The
learned model").
"""
import numpy as np

import touch_predictor_data as data

REACH_PER_S = 1000.0


class Settings:
    """What a training is given besides its rows: the output cap, the loss's synthetic share and the
    optimiser's schedule (seeds are passed per training)."""

    def __init__(self, max_gain=12.0, synthetic_share=0.3, onset_share=0.5, epochs=10, batch=512, learning_rate=3e-3):
        self.max_gain = max_gain
        self.synthetic_share = synthetic_share
        self.onset_share = onset_share
        self.epochs = epochs
        self.batch = batch
        self.learning_rate = learning_rate


def init(n_in, width, rng):
    return [rng.normal(0, np.sqrt(2.0 / n_in), (n_in, width)), np.zeros(width),
            rng.normal(0, np.sqrt(2.0 / width), (width, width)), np.zeros(width),
            rng.normal(0, 0.1 / np.sqrt(width), (width, 2)), np.zeros(2)]


def forward(params, x, max_gain):
    w1, b1, w2, b2, w3, b3 = params
    a1 = np.maximum(x @ w1 + b1, 0.0)
    a2 = np.maximum(a1 @ w2 + b2, 0.0)
    f = np.tanh(a2 @ w3 + b3)
    return max_gain * f, (a1, a2, f)


def local_offsets(meta):
    """The target offsets in the stroke frame (mm)."""
    dx, dy = meta[:, 6] - meta[:, 3], meta[:, 7] - meta[:, 4]
    c, s = meta[:, 1], meta[:, 2]
    return np.stack([c * dx + s * dy, -s * dx + c * dy], axis=1)


def row_weights(meta, settings):
    """Each row's weight in the loss (mean 1): 1 / (rows of its group x the group's mean distance
    to its target), times the synthetic share for the smooth synthetic paths' groups and the onset
    share for the synthetic onsets' and ends'. So the loss is the selection's measure, the mean over
    tasks and horizons of error / no extrapolation, plus the synthetic tasks at their shares."""
    groups = meta[:, 13].astype(int)
    displacement = np.hypot(meta[:, 6] - meta[:, 3], meta[:, 7] - meta[:, 4])
    weights = np.zeros(len(meta))
    for group in np.unique(groups):
        rows = groups == group
        share = {data.SYNTHETIC_TASK: settings.synthetic_share, data.ONSET_TASK: settings.onset_share}.get(group // 10, 1.0)
        weights[rows] = share / (rows.sum() * max(displacement[rows].mean(), 1e-3))
    return weights / weights.mean()


def train(x, meta, width, seed, settings):
    """Mini-batch Adam on the weighted mean Euclidean distance, every row mirrored across the
    direction of motion, a cosine learning rate."""
    rng = np.random.default_rng(seed)
    moving = meta[:, 8] > 0
    x, meta = x[moving], meta[moving]
    target = local_offsets(meta)
    c, s, h = meta[:, 1], meta[:, 2], meta[:, 5]
    linear = np.stack([(c * meta[:, 10] + s * meta[:, 11]) * h, (-s * meta[:, 10] + c * meta[:, 11]) * h], axis=1)
    gate = np.tile(meta[:, 9], 2)[:, None]
    linear = np.vstack([linear, linear * [1.0, -1.0]])
    mirror_x = x.copy()
    mirror_x[:, 1:-2:3] *= -1.0
    x = np.vstack([x, mirror_x])
    target = np.vstack([target, target * [1.0, -1.0]])
    gain = np.tile(meta[:, 0] * meta[:, 5] / data.H_REF_S, 2)[:, None]
    weights = np.tile(row_weights(meta, settings), 2)[:, None]
    params = init(x.shape[1], width, rng)
    m = [np.zeros_like(p) for p in params]
    v = [np.zeros_like(p) for p in params]
    step = 0
    batches = int(np.ceil(len(x) / settings.batch))
    for epoch in range(settings.epochs):
        order = rng.permutation(len(x))
        lr = settings.learning_rate * 0.5 * (1.0 + np.cos(np.pi * epoch / settings.epochs))
        for b in range(batches):
            idx = order[b * settings.batch:(b + 1) * settings.batch]
            xb, gb, tb = x[idx], gain[idx] * (1.0 - gate[idx]), target[idx] - gate[idx] * linear[idx]
            out, (a1, a2, f) = forward(params, xb, settings.max_gain)
            diff = out * gb - tb
            dist = np.sqrt(np.sum(diff * diff, axis=1) + 1e-4)
            grad_out = diff / dist[:, None] * gb * weights[idx] / len(idx)
            gz3 = grad_out * settings.max_gain * (1.0 - f * f)
            w1, b1, w2, b2, w3, b3 = params
            gz2 = (gz3 @ w3.T) * (a2 > 0)
            gz1 = (gz2 @ w2.T) * (a1 > 0)
            grads = [xb.T @ gz1, gz1.sum(0), a1.T @ gz2, gz2.sum(0), a2.T @ gz3, gz3.sum(0)]
            step += 1
            for i, g in enumerate(grads):
                m[i] = 0.9 * m[i] + 0.1 * g
                v[i] = 0.999 * v[i] + 0.001 * g * g
                params[i] = params[i] - lr * (m[i] / (1 - 0.9 ** step)) / (np.sqrt(v[i] / (1 - 0.999 ** step)) + 1e-8)
    return params


def predict(params, x, meta, max_gain):
    """Predicted positions (n, 2) in mm: the still rows at their position."""
    out, _ = forward(params, x, max_gain)
    gain = (meta[:, 0] * meta[:, 5] / data.H_REF_S)[:, None]
    local = out * gain * meta[:, 8:9]
    c, s, gate, h = meta[:, 1], meta[:, 2], meta[:, 9], meta[:, 5]
    ox = gate * meta[:, 10] * h + (1.0 - gate) * (c * local[:, 0] - s * local[:, 1])
    oy = gate * meta[:, 11] * h + (1.0 - gate) * (s * local[:, 0] + c * local[:, 1])
    size = np.sqrt(ox * ox + oy * oy)
    limit = h * REACH_PER_S * meta[:, 12]
    shrink = np.where(size > limit, limit / np.where(size > 0.0, size, 1.0), 1.0)
    return np.stack([meta[:, 3] + ox * shrink, meta[:, 4] + oy * shrink], axis=1)
