#!/usr/bin/env python3
"""Trains the touch predictor's `learned` model (primitives/touch_prediction/learned_predictor.hpp)
and reports it out of sample by nested leave-one-participant-out.

Data: tests/data/touch-latency-henze2017 only (participants 1-4 of Henze et al., MobileHCI 2017,
Apache-2.0), plus synthetic paths (touch_predictor_synthetic.py). The model and its inputs:
touch_predictor_data.py and touch_predictor_network.py; the selection: touch_predictor_selection.py;
the evaluation, with the authors' protocol: touch_predictor_evaluation.py (docs/latency.md).

Usage: train_touch_predictor.py [--data DIR] [--jobs J] [--check | --check-short | --check-forward]
  (default)       nested leave-one-participant-out over the candidates, then the shipped model (the
                  candidate with the least unnested error) trained on participants 1-4; writes the
                  header, the probes and tests/data/touch_prediction/learned_nested_lopo.csv;
  --check         all of it again, compared with the committed figures within CHECK_TOLERANCE;
  --check-short   one outer fold (participant 4 held out) retrained with the candidate it chose
                  and compared with the committed figures within CHECK_TOLERANCE (about a minute);
  --check-forward the probes from the committed header's weights (seconds).
"""
import argparse
import os
import sys
import time

os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")
os.environ.setdefault("OMP_NUM_THREADS", "1")
import numpy as np  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import fit_touch_predictor as fitted_fit  # noqa: E402
import touch_predictor_data as data  # noqa: E402
import touch_predictor_evaluation as evaluation  # noqa: E402
import touch_predictor_network as network  # noqa: E402
import touch_predictor_outputs as outputs  # noqa: E402
import touch_predictor_selection as selection  # noqa: E402
import touch_predictor_synthetic as synthetic  # noqa: E402

# The candidates every fold chooses among: the history length and width, and the smooth synthetic
# paths' share of the loss. Fixed: the output cap (kLearnedMaxGain, in mean recent steps per 100 ms:
# at 12 a stroke's onset stays 1.7-2.7 times linear extrapolation's error; at 24 a still finger's
# jitter exceeds the stated 20 sigma; docs/touch-prediction.md) and the onsets' and ends' share.
FORMS = ((10, 32), (14, 32), (18, 24))
SYNTHETIC_SHARES = (0.3, 1.0)
MAX_GAINS = (18.0,)
SMOOTH_PATHS = 400
ONSET_STROKES = 200
# Ratios to no extrapolation. Candidates' measures differ by 0.003-0.02, so a reproduction must agree
# to better than that; on one machine a retraining agrees to 1e-4.
CHECK_TOLERANCE = 0.002
SHORT_CHECK_HELD_OUT = 4


def candidates():
    return [selection.Candidate(n, w, share, gain) for n, w in FORMS for share in SYNTHETIC_SHARES for gain in MAX_GAINS]


def print_table(tab, title):
    print(f"\n{title}")
    print("| task | horizon | samples | none | linear (authors) | linear | fitted | learned | learned / fitted |")
    print("|---|---|---:|---:|---:|---:|---:|---:|---:|")
    px = fitted_fit.PX_PER_MM
    for (task, s), (n, none, authors, lin, fit, learned) in evaluation.pooled(tab).items():
        print(f"| {task} | {s * 1000 / 60:.0f} ms | {n} | {none * px:.1f} px | {authors * px:.1f} px ({authors / none:.2f}) | "
              f"{lin * px:.1f} px ({lin / none:.2f}) | {fit * px:.1f} px ({fit / none:.2f}) | "
              f"{learned * px:.1f} px ({learned / none:.2f}) | {learned / fit:.2f} |")


def onset_report(model, seed=20170904 + 99, count=60):
    """Mean error (mm) of learned and linear on held-out stroke onsets and ends, per horizon, from
    each stroke's tenth event (the decelerating ones while they decelerate)."""
    n_points, params, max_gain = model
    paths = synthetic.onset_and_end_strokes(np.random.default_rng(seed), count)
    out = {}
    for kind in ("accelerating", "decelerating"):
        for s in data.STEPS_AHEAD:
            h = s * data.NOMINAL_S
            rows, lin = data.Samples(), []
            for k, (t, fine_t, px, py, quantised, window) in enumerate(paths):
                if (k % 2 == 0) != (kind == "accelerating"):
                    continue
                history = []
                for i, ti in enumerate(t):
                    xi, yi = synthetic.panel_position(np.interp(ti, fine_t, px), np.interp(ti, fine_t, py), quantised)
                    data.push(history, ti, xi, yi)
                    if i >= 9 and window[0] <= ti < window[1]:
                        rows.add(data.features(history, n_points), (xi, yi), h, (np.interp(ti + h, fine_t, px), np.interp(ti + h, fine_t, py)))
                        lin.append(data.linear_prediction(history, h))
            x, meta = rows.arrays(n_points)
            target = meta[:, 6:8]
            out[(kind, s)] = (float(np.mean(np.hypot(*(network.predict(params, x, meta, max_gain) - target).T))),
                              float(np.mean(np.hypot(*(np.array(lin) - target).T))))
    return out


def run(directory, jobs):
    """The nested run. Returns what main writes."""
    started = time.time()
    cands = candidates()
    lengths = sorted({c.n_points for c in cands})
    sets = evaluation.evaluation_sets(directory, selection.PARTICIPANTS, lengths)
    groups_by_n = {n: data.load_groups(directory, n, selection.PARTICIPANTS) for n in lengths}
    paths = synthetic.training_paths(selection.SEED, SMOOTH_PATHS, ONSET_STROKES)
    print(f"data ready: {time.time() - started:.0f} s", flush=True)
    models = selection.train_all(selection.jobs_for(cands), groups_by_n, paths, jobs)
    fits = selection.fitted_baselines(directory)
    folds, outer_models, outer_baselines = selection.nested(sets, cands, models, fits)
    scores = selection.unnested(sets, cands, models)
    ship = min(cands, key=lambda c: scores[c.key()])
    everyone = frozenset(selection.PARTICIPANTS)
    final = selection.train_all([(ship, everyone)], groups_by_n, paths, 1)[(ship.key(), everyone)]
    shipped_fitted = (*fits[(everyone, fitted_fit.RIDGE)], fitted_fit.BLEND_SCALE)
    nested_tables = {mode: evaluation.table(sets, mode, outer_baselines, outer_models) for mode in evaluation.MODES}
    in_sample = evaluation.table(sets, "nominal", {p: shipped_fitted for p in selection.PARTICIPANTS},
                                 {p: (ship.n_points, final, ship.max_gain) for p in selection.PARTICIPANTS})
    print(f"total {time.time() - started:.0f} s")
    return folds, scores, ship, final, nested_tables, in_sample


def report(folds, scores, ship, final, nested_tables, in_sample):
    cands = {c.key(): c for c in candidates()}
    print("\nCandidates, unnested leave-one-participant-out (mean learned / none):")
    for key, score in sorted(scores.items(), key=lambda kv: kv[1]):
        print(f"  {cands[key].name()}: {score:.4f}")
    print("\nOuter folds (chosen on the three training participants alone):")
    for held, (chosen, (ridge, blend), inner) in folds.items():
        best = sorted(inner.values())
        print(f"  participant {held} held out: {chosen.name()} (inner {best[0]:.4f}, next {best[1]:.4f}); fitted ridge {ridge:g}, blend {blend:g}")
    for mode, tab in nested_tables.items():
        print_table(tab, f"Nested leave-one-participant-out, horizons {mode}: mean learned / none {evaluation.mean_ratio(tab):.4f}, "
                         f"fitted / none {evaluation.mean_ratio(tab, 4):.4f}")
    print_table(in_sample, f"In sample (the shipped weights, {ship.name()}, trained on participants 1-4):")
    for (kind, s), (learned, lin) in onset_report((ship.n_points, final, ship.max_gain)).items():
        print(f"{kind} strokes, {s * 1000 / 60:.0f} ms: learned {learned:.3f} mm, linear {lin:.3f} mm, ratio {learned / lin:.2f}")


def ratios_of(rows, mode=None, held=None):
    return {(r[0], r[1], r[2], r[3]): float(r[9]) / float(r[5]) for r in rows
            if (mode is None or r[1] == mode) and (held is None or r[0] == str(held))}


def short_check(directory):
    rows = outputs.read_nested_csv()
    fold = [r for r in rows if r[0] == str(SHORT_CHECK_HELD_OUT) and r[1] == "nominal"]
    n, w, share, gain = fold[0][10].split(":")
    candidate = selection.Candidate(int(n), int(w), float(share), float(gain))
    training = frozenset(p for p in selection.PARTICIPANTS if p != SHORT_CHECK_HELD_OUT)
    groups = {candidate.n_points: data.load_groups(directory, candidate.n_points, training)}
    paths = synthetic.training_paths(selection.SEED, SMOOTH_PATHS, ONSET_STROKES)
    params = selection.train_all([(candidate, training)], groups, paths, 1)[(candidate.key(), training)]
    model = (candidate.n_points, params, candidate.max_gain)
    fresh = {}
    for (mode, task, s, held), e in evaluation.evaluation_sets(directory, (SHORT_CHECK_HELD_OUT,), [candidate.n_points]).items():
        if mode == "nominal":
            fresh[(str(held), mode, task, f"{s * 1000 / 60:.0f}")] = e.learned(model) / e.fixed[1]
    return compare(ratios_of(rows, "nominal", SHORT_CHECK_HELD_OUT), fresh, f"participant {SHORT_CHECK_HELD_OUT}'s fold")


def compare(committed, fresh, what):
    if set(committed) != set(fresh):
        sys.exit(f"{outputs.NESTED_CSV}: error: the committed rows are not those a retraining gives; run {sys.argv[0]}")
    worst = max(abs(committed[k] - fresh[k]) for k in fresh)
    print(f"{what}: largest difference of a learned / none ratio {worst:.5f} over {len(fresh)} rows (tolerance {CHECK_TOLERANCE})")
    if worst > CHECK_TOLERANCE:
        sys.exit(f"{outputs.NESTED_CSV}: error: a retraining differs by {worst:.5f} > {CHECK_TOLERANCE}; run {sys.argv[0]}")
    return 0


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--data", default=os.path.join(outputs.ROOT, "tests/data/touch-latency-henze2017"))
    parser.add_argument("--jobs", type=int, default=2, help="trainings run at once (default 2)")
    group = parser.add_mutually_exclusive_group()
    group.add_argument("--check", action="store_true")
    group.add_argument("--check-short", action="store_true")
    group.add_argument("--check-forward", action="store_true")
    args = parser.parse_args()
    if args.jobs < 1:
        parser.error("--jobs must be at least 1")
    if args.check_forward:
        return outputs.check_forward()
    if args.check_short:
        return short_check(args.data)
    folds, scores, ship, final, nested_tables, in_sample = run(args.data, args.jobs)
    report(folds, scores, ship, final, nested_tables, in_sample)
    csv = outputs.nested_csv_text(nested_tables, folds)
    if args.check:
        fresh = ratios_of([line.split(",") for line in csv.strip().splitlines()[1:]])
        return compare(ratios_of(outputs.read_nested_csv()), fresh, "every outer fold")
    cands = {c.key(): c for c in candidates()}
    ranked = [(cands[k].name(), v) for k, v in sorted(scores.items(), key=lambda kv: kv[1])]
    outputs.write(outputs.HEADER, outputs.header_text(final, ship, nested_tables["nominal"], in_sample, ranked))
    outputs.write(outputs.NESTED_CSV, csv)
    outputs.write(outputs.PROBES, outputs.probes_text(final, ship.n_points, ship.max_gain))
    return 0


if __name__ == "__main__":
    sys.exit(main())
