"""Nested leave-one-participant-out for the touch predictors (scripts/train_touch_predictor.py).

Every choice is made inside each outer fold, on its three training participants alone:
- learned: the candidate (history length N, width W, synthetic share) with the least inner
  leave-one-participant-out error (each training participant held out from a model trained on
  the other two), then trained on the three and scored on the held-out participant;
- fitted: the ridge and the blend scale, the same way.
A model trained on a set of participants is trained once and serves every fold that needs that set
(its seed depends on the set), so the nested figures cost ten trainings per candidate: the four
sets of three and the six sets of two. The shipped model is the candidate with the least
(unnested) leave-one-participant-out error, trained on all four.
"""
import itertools
import multiprocessing
import time

import numpy as np

import fit_touch_predictor as fitted_fit
import touch_predictor_data as data
import touch_predictor_evaluation as evaluation
import touch_predictor_network as network
import touch_predictor_synthetic as synthetic

PARTICIPANTS = (1, 2, 3, 4)
SEED = 20170904
FITTED_RIDGES = (1e-4, 1e-3, 1e-2)
FITTED_BLENDS = (0.005, 0.01, 0.02, 0.05)


class Candidate:
    def __init__(self, n_points, width, synthetic_share, max_gain):
        self.n_points, self.width = n_points, width
        self.synthetic_share, self.max_gain = synthetic_share, max_gain

    def key(self):
        return (self.n_points, self.width, self.synthetic_share, self.max_gain)

    def name(self):
        return f"N={self.n_points} W={self.width} share={self.synthetic_share:g} gain={self.max_gain:g}"

    def settings(self):
        return network.Settings(max_gain=self.max_gain, synthetic_share=self.synthetic_share)


def seed_of(participants):
    return SEED + sum(10 ** (p - 1) for p in participants)


def training_rows(groups, paths, n_points, participants):
    rows = data.Samples()
    for (task, participant), strokes in groups.items():
        if participant not in participants:
            continue
        for stroke, states in strokes:
            moves = len(stroke) - 2
            for n in range(1, moves + 1):
                for s in data.TRAINING_STEPS:
                    target = stroke[min(n + s, moves)]
                    rows.add(states[n][0], stroke[n][1:], s * data.NOMINAL_S, target[1:], 10 * data.TASK_INDEX[task] + s)
    for task, task_paths in paths.items():
        synthetic.add_training_rows(rows, task_paths, n_points, task)
    return rows.arrays(n_points)


_WORK = {}  # what the forked trainers read: groups by N and the synthetic paths


def _train_one(job):
    candidate, participants = job
    started = time.time()
    x, meta = training_rows(_WORK["groups"][candidate.n_points], _WORK["paths"], candidate.n_points, participants)
    params = network.train(x, meta, candidate.width, seed_of(participants), candidate.settings())
    print(f"  {candidate.name()} on participants {sorted(participants)}: {len(x)} rows, {time.time() - started:.0f} s", flush=True)
    return params


def train_all(jobs, groups_by_n, paths, processes):
    """{(candidate key, participants): params} for jobs [(candidate, frozenset)]."""
    _WORK["groups"], _WORK["paths"] = groups_by_n, paths
    if processes > 1:
        with multiprocessing.get_context("fork").Pool(processes) as pool:
            results = pool.map(_train_one, jobs, chunksize=1)
    else:
        results = [_train_one(job) for job in jobs]
    return {(c.key(), frozenset(p)): r for (c, p), r in zip(jobs, results)}


def fitted_baselines(directory):
    """{(participants, ridge): (free, exact)} for every set of two, three and four participants."""
    per = {p: fitted_fit.samples(directory, (p,)) for p in PARTICIPANTS}
    out = {}
    for size in (2, 3, 4):
        for chosen in itertools.combinations(PARTICIPANTS, size):
            features = np.concatenate([per[p][0] for p in chosen])
            targets = np.concatenate([per[p][1] for p in chosen])
            for ridge in FITTED_RIDGES:
                free, exact, _ = fitted_fit.fit(features, targets, ridge)
                out[(frozenset(chosen), ridge)] = (free, exact)
    return out


def others(participants, held):
    return frozenset(p for p in participants if p != held)


def nested(sets, candidates, models, fits):
    """The outer folds: {held: (chosen candidate, chosen (ridge, blend), inner scores)}, and the
    models and baselines that predict each held-out participant."""
    folds, outer_models, outer_baselines = {}, {}, {}
    everyone = frozenset(PARTICIPANTS)
    for held in PARTICIPANTS:
        training = others(everyone, held)
        inner = {}
        for c in candidates:
            inner[c.key()] = evaluation.learned_score(
                sets, {q: (c.n_points, models[(c.key(), others(training, q))], c.max_gain) for q in training})
        chosen = min(candidates, key=lambda c: inner[c.key()])
        fitted_inner = {}
        for ridge in FITTED_RIDGES:
            for blend in FITTED_BLENDS:
                fitted_inner[(ridge, blend)] = evaluation.fitted_score(
                    sets, {q: (*fits[(others(training, q), ridge)], blend) for q in training})
        ridge, blend = min(fitted_inner, key=fitted_inner.get)
        folds[held] = (chosen, (ridge, blend), inner)
        outer_models[held] = (chosen.n_points, models[(chosen.key(), training)], chosen.max_gain)
        outer_baselines[held] = (*fits[(training, ridge)], blend)
    return folds, outer_models, outer_baselines


def unnested(sets, candidates, models):
    """Each candidate's leave-one-participant-out measure over the four participants."""
    everyone = frozenset(PARTICIPANTS)
    return {c.key(): evaluation.learned_score(
        sets, {p: (c.n_points, models[(c.key(), others(everyone, p))], c.max_gain) for p in PARTICIPANTS})
        for c in candidates}


def jobs_for(candidates):
    sets_needed = [frozenset(s) for size in (2, 3) for s in itertools.combinations(PARTICIPANTS, size)]
    return [(c, s) for c in candidates for s in sets_needed]
