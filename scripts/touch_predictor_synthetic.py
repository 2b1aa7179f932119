"""Synthetic strokes for the learned touch predictor (scripts/train_touch_predictor.py).

Two families, each path given as (event times, fine time, x, y, quantised, window), the window
being the span of time a test of the family looks at:
- smooth paths at 50-250 mm/s: constant acceleration along a line, or gentle curves (radius >= 30 mm)
  with a speed that swells and ebbs (events at 60 or 120 Hz);
- stroke onsets and ends: a straight stroke from rest at a constant acceleration (accelerating), or
  one that accelerates from rest and then decelerates to rest (decelerating); events at 60, 90 or
  120 Hz with +-2 ms of timing jitter, half of them with positions rounded to the panel's pixel
  (1 / 12.72 mm). tests/touch_prediction/stroke_onset_test.cpp holds the model to these
  on its own seeded strokes.
The targets are the exact path at the horizon.
"""
import math

import numpy as np

import fit_touch_predictor as fitted_fit
import touch_predictor_data as data


def smooth_paths(rng, count):
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
        out.append((np.arange(0.0, duration, 1.0 / rate), fine_t, px, py, False, (0.0, duration)))
    return out


def onset_and_end_strokes(rng, count):
    """Straight strokes from rest: even k accelerate at 300-2000 mm/s^2 for 0.5 s; odd k accelerate
    for 0.15-0.3 s to a peak of 100-400 mm/s, then decelerate at 300-1500 mm/s^2 to rest."""
    out = []
    for k in range(count):
        rate = (60.0, 90.0, 120.0)[k % 3]
        heading = rng.uniform(0.0, 2.0 * np.pi)
        fine_t = np.arange(0.0, 1.6, 2.5e-4)
        if k % 2 == 0:
            along = 0.5 * rng.uniform(300.0, 2000.0) * fine_t * fine_t
            duration = 0.5
            window = (0.0, duration)
        else:
            rise_s, peak = rng.uniform(0.15, 0.3), rng.uniform(100.0, 400.0)
            stop_s = peak / rng.uniform(300.0, 1500.0)
            up = np.minimum(fine_t, rise_s)
            down = np.clip(fine_t - rise_s, 0.0, stop_s)
            along = 0.5 * peak / rise_s * up * up + peak * down - 0.5 * peak / stop_s * down * down
            duration = rise_s + stop_s + 0.05
            window = (rise_s, rise_s + stop_s)
        n = int(duration * rate)
        t = np.arange(n) / rate + np.concatenate([[0.0], rng.uniform(-0.002, 0.002, n - 1)])
        out.append((np.maximum.accumulate(t), fine_t, along * math.cos(heading), along * math.sin(heading), k % 4 < 2, window))
    return out


def panel_position(x, y, quantised):
    if not quantised:
        return x, y
    return round(x * fitted_fit.PX_PER_MM) / fitted_fit.PX_PER_MM, round(y * fitted_fit.PX_PER_MM) / fitted_fit.PX_PER_MM


def add_training_rows(samples, paths, n_points, task):
    """Every event but the first, targets at s / 60 s for s = 1..6, in the loss groups of `task`."""
    for t, fine_t, px, py, quantised, _ in paths:
        history = []
        for i, ti in enumerate(t):
            xi, yi = panel_position(np.interp(ti, fine_t, px), np.interp(ti, fine_t, py), quantised)
            data.push(history, ti, xi, yi)
            if i == 0:
                continue
            feat = data.features(history, n_points)
            for s in data.TRAINING_STEPS:
                h = s * data.NOMINAL_S
                target = (np.interp(ti + h, fine_t, px), np.interp(ti + h, fine_t, py))
                samples.add(feat, (xi, yi), h, target, 10 * task + s)


def training_paths(seed, smooth_count, onset_count):
    """{loss task: paths}: the smooth paths and the onsets and ends, each its own task in the loss."""
    return {data.SYNTHETIC_TASK: smooth_paths(np.random.default_rng(seed), smooth_count),
            data.ONSET_TASK: onset_and_end_strokes(np.random.default_rng(seed + 5), onset_count)}
