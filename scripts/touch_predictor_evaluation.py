"""Held-out evaluation of the touch predictors on the authors' protocol (scripts/train_touch_predictor.py).

Every (task, participant, horizon, horizon mode) is turned into arrays once (`EvaluationSet`), so
that scoring a model is a vectorised pass. Two horizon modes:
- "nominal": the model predicts s / 60 s ahead, as the protocol's figures are stated;
- "target time": the model is given the target event's time (the newest event's time plus the real
  gap to it), as the authors' LSTM was.
A table maps (task, s, participant) to sums of distances (mm): samples, none, the authors' linear,
linear, fitted, learned.
"""
import numpy as np

import fit_touch_predictor as fitted_fit
import touch_predictor_data as data
import touch_predictor_network as network

MODES = ("nominal", "target time")


class EvaluationSet:
    """One task, participant, horizon and mode: the inputs per history length, and the baselines."""

    def __init__(self, strokes_by_n, s, given_target_time):
        any_n = next(iter(strokes_by_n))
        rows = {n: data.Samples() for n in strokes_by_n}
        lags, nows, targets, linear, authors = [], [], [], [], []
        for k, (stroke, states) in enumerate(strokes_by_n[any_n]):
            for end, target, before in data.protocol_samples(stroke, s):
                h = data.horizon(stroke, end, target, s, given_target_time)
                now, goal = stroke[end][1:], stroke[target][1:]
                for n, strokes in strokes_by_n.items():
                    rows[n].add(strokes[k][1][end][0], now, h, goal)
                lags.append(states[end][1])
                nows.append(now)
                targets.append(goal)
                linear.append(data.linear_prediction(states[end][2], h))
                b = stroke[before]
                authors.append((now[0] + s * (now[0] - b[1]), now[1] + s * (now[1] - b[2])))
        self.inputs = {n: r.arrays(n) for n, r in rows.items()}
        self.horizons = self.inputs[any_n][1][:, 5].copy()
        self.lags, self.nows, self.targets = np.array(lags), np.array(nows), np.array(targets)
        self.fixed = (len(targets), self.distance(self.nows), self.distance(authors), self.distance(linear))

    def distance(self, predicted):
        if len(self.targets) == 0:
            return 0.0
        return float(np.sum(np.hypot(*(np.asarray(predicted) - self.targets).T)))

    def fitted(self, baseline):
        """baseline: (free, exact, blend scale)."""
        free, exact, blend = baseline
        if len(self.targets) == 0:
            return 0.0
        out = np.zeros_like(self.nows)
        for h in np.unique(self.horizons):
            rows = self.horizons == h
            out[rows] = fitted_offsets(free, exact, blend, self.lags[rows], h)
        return self.distance(self.nows + out)

    def learned(self, model):
        """model: (n_points, params, max gain)."""
        n_points, params, max_gain = model
        if len(self.targets) == 0:
            return 0.0
        x, meta = self.inputs[n_points]
        return self.distance(network.predict(params, x, meta, max_gain))


def fitted_offsets(free, exact, blend_scale, lags, h):
    """The C++ fitted model (finger_predictor.cpp) on lag displacements (n, 2, K) at horizon h."""
    j = int(np.floor(h / fitted_fit.LAG_S))
    a = h / fitted_fit.LAG_S - j

    def weights(table):
        if j >= fitted_fit.NH:
            return table[-1] * h / (fitted_fit.NH * fitted_fit.LAG_S)
        lower = np.zeros(fitted_fit.K) if j == 0 else table[j - 1]
        return (1 - a) * lower + a * table[j]
    wf, we = weights(free), weights(exact)
    k = np.arange(1, fitted_fit.K + 1)
    v = -(lags @ k) / (fitted_fit.LAG_S * np.sum(k * k))
    resid = lags + v[:, :, None] * k * fitted_fit.LAG_S
    rho = np.sqrt(np.sum(resid ** 2, axis=(1, 2)) / fitted_fit.K) / (
        np.hypot(v[:, 0], v[:, 1]) * fitted_fit.K * fitted_fit.LAG_S + fitted_fit.BLEND_FLOOR_MM)
    lam = np.exp(-rho / blend_scale)[:, None]
    return lam * (lags @ we) + (1 - lam) * (lags @ wf)


def evaluation_sets(directory, participants, history_lengths):
    """{(mode, task, s, participant): EvaluationSet}."""
    by_n = {n: data.load_groups(directory, n, participants) for n in history_lengths}
    sets = {}
    for (task, participant) in by_n[history_lengths[0]]:
        strokes_by_n = {n: by_n[n][(task, participant)] for n in history_lengths}
        for mode in MODES:
            for s in data.STEPS_AHEAD:
                sets[(mode, task, s, participant)] = EvaluationSet(strokes_by_n, s, mode == "target time")
    return sets


def table(sets, mode, baselines, models):
    """baselines, models: {participant: what predicts that participant}."""
    out = {}
    for (m, task, s, participant), e in sets.items():
        if m == mode and participant in models:
            out[(task, s, participant)] = (*e.fixed, e.fitted(baselines[participant]), e.learned(models[participant]))
    return out


def pooled(tab):
    """Means (mm) per (task, s) over the participants: samples, none, authors, linear, fitted, learned."""
    out = {}
    for task, _ in data.TASKS:
        for s in data.STEPS_AHEAD:
            rows = [v for (t, ss, _), v in tab.items() if t == task and ss == s]
            if rows:
                sums = np.sum(rows, axis=0)
                out[(task, s)] = (int(sums[0]), *(sums[1:] / sums[0]))
    return out


def mean_ratio(tab, column=5):
    """The selection's measure: the mean over tasks and horizons of the pooled error / none."""
    return float(np.mean([v[column] / v[1] for v in pooled(tab).values()]))


def learned_score(sets, models):
    """The measure on the participants in models (nominal horizons), each by its own model."""
    out = {}
    for (m, task, s, participant), e in sets.items():
        if m == "nominal" and participant in models:
            out[(task, s, participant)] = (e.fixed[0], e.fixed[1], 0.0, 0.0, 0.0, e.learned(models[participant]))
    return mean_ratio(out)


def fitted_score(sets, baselines):
    out = {}
    for (m, task, s, participant), e in sets.items():
        if m == "nominal" and participant in baselines:
            out[(task, s, participant)] = (e.fixed[0], e.fixed[1], 0.0, 0.0, e.fitted(baselines[participant]), 0.0)
    return mean_ratio(out, column=4)
