#!/usr/bin/python3
"""Reference ST-SIM values for tests/primitives/perception_stsim_reference_test.cpp.

Builds the test signals of signals.csv (the same recipe the C++ test follows, sample for sample:
plain float arithmetic and the C library's sin/exp, no NumPy in the signal generation), runs the
reference implementation (the `vibromaf` package, not part of this repository) on every pair of
cases.csv's first four columns, and rewrites cases.csv with its outputs and threshold.csv with the
reference's threshold curve. See README.md.

usage: /usr/bin/python3 make_fixtures.py VIBROMAF_SOURCE_DIR
"""

import csv
import math
import pathlib
import sys
import warnings

FS = 8000.0
HERE = pathlib.Path(__file__).resolve().parent
MASK64 = (1 << 64) - 1


def splitmix64(state):
    state = (state + 0x9E3779B97F4A7C15) & MASK64
    z = state
    z = ((z ^ (z >> 30)) * 0xBF58476D1CE4E5B9) & MASK64
    z = ((z ^ (z >> 27)) * 0x94D049BB133111EB) & MASK64
    return state, z ^ (z >> 31)


def component(kind, length, p):
    """One component over `length` samples; p: start, end, then the kind's parameters."""
    start, end = int(p[0]), int(p[1])
    out = [0.0] * length
    if kind == "noise":  # seed, amplitude: uniform in [-a, a)
        state = int(p[2])
        a = float(p[3])
        for n in range(start, min(end, length)):
            state, z = splitmix64(state)
            u = float(z >> 11) * (1.0 / 9007199254740992.0)
            out[n] = a * (2.0 * u - 1.0)
        return out
    for n in range(start, min(end, length)):
        t = float(n - start) / FS
        if kind == "sine":  # f, a, phase
            w = 2.0 * math.pi * float(p[2])
            out[n] = float(p[3]) * math.sin(w * t + float(p[4]))
        elif kind == "chirp":  # f0, f1, a: frequency from f0 to f1 linearly over [start, end)
            f0, f1, a = float(p[2]), float(p[3]), float(p[4])
            duration = float(end - start) / FS
            out[n] = a * math.sin(2.0 * math.pi * (f0 * t + (f1 - f0) * t * t / (2.0 * duration)))
        elif kind == "pulses":  # period (samples), width (samples), f, a: bursts, phase 0 at each start
            period, width = int(p[2]), int(p[3])
            k = (n - start) % period
            if k < width:
                out[n] = float(p[5]) * math.sin(2.0 * math.pi * float(p[4]) * (float(k) / FS))
        elif kind == "ring":  # period (samples), f, a, decay (s): a decaying ring restarted every period
            k = (n - start) % int(p[2])
            tk = float(k) / FS
            out[n] = float(p[4]) * math.exp(-tk / float(p[5])) * math.sin(2.0 * math.pi * float(p[3]) * tk)
        elif kind == "const":  # a
            out[n] = float(p[2])
        else:
            raise ValueError(f"unknown component {kind}")
    return out


def make_signal(length, recipe):
    signal = [0.0] * length
    for item in recipe.split():
        kind, *p = item.split(":")
        if kind == "gain":
            g = float(p[0])
            signal = [g * x for x in signal]
        elif kind == "delay":
            d = int(p[0])
            signal = ([0.0] * d + signal)[:length]
        elif kind == "clip":
            c = float(p[0])
            signal = [min(max(x, -c), c) for x in signal]
        else:
            values = component(kind, length, p)
            signal = [x + v for x, v in zip(signal, values)]
    return signal


def main():
    sys.path.insert(0, sys.argv[1])
    import numpy as np  # pylint: disable=import-outside-toplevel
    from vibromaf.metrics.stsim import STSIM, st_sim  # pylint: disable=import-outside-toplevel
    from vibromaf.signal.perception import PerceptualThreshold  # pylint: disable=import-outside-toplevel
    from vibromaf.signal.spectrum import compute_spectral_support  # pylint: disable=import-outside-toplevel
    from vibromaf.signal.transform import preprocess_input_signal  # pylint: disable=import-outside-toplevel

    with open(HERE / "signals.csv", newline="") as f:
        signals = {row["name"]: np.array(make_signal(int(row["samples"]), row["recipe"]))
                   for row in csv.DictReader(l for l in f if not l.startswith("#"))}
    with open(HERE / "cases.csv", newline="") as f:
        lines = [l for l in f]
    header_comments = [l for l in lines if l.startswith("#")]
    cases = list(csv.DictReader(l for l in lines if not l.startswith("#")))

    builder = STSIM(2 / 3).perceptual_spectrum_builder
    for case in cases:
        distorted, reference = signals[case["distorted"]], signals[case["reference"]]
        eta = float(case["eta"])
        case.update(result="", temporal="", spectral="", stsim="")
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            try:
                value = st_sim(distorted, reference, eta)
            except ValueError:
                case["result"] = "error"
                continue
            cut = preprocess_input_signal(distorted, reference)
            if np.array_equal(cut, reference):
                case.update(result="identical", temporal="1", spectral="1", stsim=repr(float(value)))
                continue
            spectral = STSIM.compute_sim(
                compute_spectral_support(builder.compute_perceptual_spectrum(reference)),
                compute_spectral_support(builder.compute_perceptual_spectrum(cut)))
            temporal = STSIM.compute_sim(builder.block_builder.divide_and_normalize(reference),
                                         builder.block_builder.divide_and_normalize(cut))
        case.update(temporal=repr(float(temporal)), spectral=repr(float(spectral)))
        if isinstance(value, complex):
            # Python's pow of a negative float: the reference returns a complex number; ST-SIM is 0.
            case.update(result="complex", stsim=repr(value))
        else:
            case.update(result="value", stsim=repr(float(value)))

    with open(HERE / "threshold.csv", "w", newline="") as f:
        f.write("# The reference's perceptual threshold for 512-sample blocks at 8 kHz, dB per DCT bin (README.md).\n")
        f.write("bin,threshold_db\n")
        for k, value in enumerate(PerceptualThreshold(8000).calculate(512)):
            f.write(f"{k},{float(value)!r}\n")

    with open(HERE / "cases.csv", "w", newline="") as f:
        f.writelines(header_comments)
        writer = csv.DictWriter(f, fieldnames=list(cases[0].keys()), lineterminator="\n")
        writer.writeheader()
        writer.writerows(cases)


if __name__ == "__main__":
    main()
