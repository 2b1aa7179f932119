#!/usr/bin/env python3
"""Draws docs/images/perception_conformance.png: the discrimination model of docs/perception.md
against the published figures of tests/data/psychophysics/published_figures.csv. The model's
numbers are the lines the conformance test prints (`conformance,QUANTITY,FREQUENCY_HZ,SL_DB,MODEL,
LOW,HIGH`), so the picture shows exactly what ctest holds the model to. Run by hand (not in CI);
it needs matplotlib (Debian: apt-get install python3-matplotlib):

  build/release/tests/perception_tests --gtest_filter='DiscriminationConformance.*' > conformance.txt
  python3 scripts/plot_perception_conformance.py conformance.txt \\
      tests/data/psychophysics/published_figures.csv docs/images/perception_conformance.png
"""
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def read_model(path):
    rows = {}
    with open(path, encoding="utf-8") as f:
        for line in f:
            if not line.startswith("conformance,"):
                continue
            cells = line.strip().split(",")
            if len(cells) != 7:
                sys.exit(f"{path}: error: a conformance line with {len(cells)} fields: {line.strip()}")
            rows.setdefault(cells[1], []).append((float(cells[2]), float(cells[3]) if cells[3] else None, float(cells[4])))
    if not rows:
        sys.exit(f"{path}: error: no conformance lines (the output of perception_tests --gtest_filter='DiscriminationConformance.*')")
    return rows


def read_published(path):
    rows = []
    with open(path, encoding="utf-8") as f:
        lines = [line for line in f if not line.startswith("#")]
    for row in csv.DictReader(lines):
        rows.append(row)
    return rows


def bands(ax, published, quantity, colours):
    for n, row in enumerate(r for r in published if r["quantity"] == quantity):
        low_hz, high_hz = float(row["frequency_low_hz"]), float(row["frequency_high_hz"])
        low, high = float(row["low"]), float(row["high"])
        sl = row["sensation_level_low_db"]
        source = row["source"].split(":")[0].split(",")[0]
        label = f"{source} ({sl} dB SL)" if sl else source
        ax.fill_between([low_hz, high_hz], [low, low], [high, high], alpha=0.18, color=colours[n % len(colours)],
                        label=label)


def main():
    if len(sys.argv) != 4:
        sys.exit("usage: plot_perception_conformance.py CONFORMANCE.txt PUBLISHED.csv OUT.png")
    model = read_model(sys.argv[1])
    published = read_published(sys.argv[2])
    colours = ("#1b9e77", "#d95f02", "#7570b3")
    fig, axes = plt.subplots(2, 2, figsize=(11, 8))

    for ax, quantity, ylabel, title in (
            (axes[0][0], "frequency_weber_fraction", "frequency JND (Weber fraction)", "Frequency discrimination"),
            (axes[0][1], "amplitude_jnd_db", "amplitude JND (dB)", "Amplitude discrimination")):
        bands(ax, published, quantity, colours)
        for sl, marker in ((20.0, "o"), (30.0, "s")):
            pts = sorted((f, v) for f, s, v in model.get(quantity, []) if s == sl)
            ax.plot([p[0] for p in pts], [p[1] for p in pts], marker=marker, color="black", label=f"model, {sl:g} dB SL")
        ax.set_xscale("log")
        ax.set_xlabel("frequency (Hz)")
        ax.set_ylabel(ylabel)
        ax.set_title(title)
        ax.legend(fontsize=7)

    ax = axes[1][0]
    for row in (r for r in published if r["quantity"] == "gap_detection_ms"):
        lo_sl, hi_sl = float(row["sensation_level_low_db"]), float(row["sensation_level_high_db"])
        ax.fill_between([lo_sl - 2, hi_sl + 2], [float(row["low"])] * 2, [float(row["high"])] * 2, alpha=0.18,
                        color=colours[0], label=row["source"].split(":")[0].split(",")[0] + " et al.")
    pts = sorted((s, v) for f, s, v in model.get("gap_detection_ms", []))
    ax.plot([p[0] for p in pts], [p[1] for p in pts], marker="o", color="black", label="model, 250 Hz tone")
    ax.set_xlabel("sensation level (dB)")
    ax.set_ylabel("gap detection threshold (ms)")
    ax.set_ylim(0, 15)
    ax.set_title("Gap detection")
    ax.legend(fontsize=7)

    ax = axes[1][1]
    for n, row in enumerate(r for r in published if r["quantity"] == "detection_threshold_peak_displacement_um"):
        ax.fill_between([float(row["frequency_low_hz"]), float(row["frequency_high_hz"])], [float(row["low"])] * 2,
                        [float(row["high"])] * 2, alpha=0.18, color=colours[n % len(colours)],
                        label=row["source"].split(":")[0].split(";")[0])
    pts = sorted((f, v) for f, s, v in model.get("threshold_peak_displacement_um", []))
    ax.plot([p[0] for p in pts], [p[1] for p in pts], color="black", label="model: min(Pacinian U, non-Pacinian floor)")
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("frequency (Hz)")
    ax.set_ylabel("detection threshold, peak displacement (µm)")
    ax.set_title("Detection threshold")
    ax.legend(fontsize=7)

    fig.suptitle("Discrimination model (black) against published ranges (shaded)")
    fig.tight_layout()
    fig.savefig(sys.argv[3], dpi=90)


if __name__ == "__main__":
    main()
