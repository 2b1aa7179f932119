#!/usr/bin/env python3
"""Draws docs/images/perception_conformance.png: the perception model of docs/perception.md against
the published figures of tests/data/psychophysics/published_figures.csv. The model's numbers are
the lines the conformance tests print (`conformance,QUANTITY,FREQUENCY_HZ,SL_DB,MODEL,LOW,HIGH` and
`identification,SET,MEMBERS,MODEL,LOW,HIGH`), so the picture shows exactly what ctest holds the
model to. Run by hand (not in CI); it needs matplotlib (Debian: apt-get install python3-matplotlib):

  build/release/tests/perception_tests \\
      --gtest_filter='DiscriminationConformance.*:IdentificationConformance.*' > conformance.txt
  python3 scripts/plot_perception_conformance.py conformance.txt \\
      tests/data/psychophysics/published_figures.csv docs/images/perception_conformance.png
"""
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def label(ax, xlabel, ylabel, title, ylim=None, **legend):
    """A panel's axes, title and legend."""
    ax.set_xlabel(xlabel)
    ax.set_ylabel(ylabel)
    if ylim is not None:
        ax.set_ylim(*ylim)
    ax.set_title(title)
    ax.legend(fontsize=6, **legend)


def read_model(path):
    rows, identification = {}, []
    with open(path, encoding="utf-8") as f:
        for line in f:
            cells = line.strip().split(",")
            if line.startswith("identification,"):
                if len(cells) != 6:
                    sys.exit(f"{path}: error: an identification line with {len(cells)} fields: {line.strip()}")
                identification.append((cells[1], int(cells[2]), float(cells[3]), float(cells[4]), float(cells[5])))
            elif line.startswith("conformance,"):
                if len(cells) != 7:
                    sys.exit(f"{path}: error: a conformance line with {len(cells)} fields: {line.strip()}")
                rows.setdefault(cells[1], []).append(
                    (float(cells[2]), float(cells[3]) if cells[3] else None, float(cells[4]), float(cells[5]), float(cells[6])))
    if not rows or not identification:
        sys.exit(f"{path}: error: no conformance or identification lines (the output of perception_tests "
                 "--gtest_filter='DiscriminationConformance.*:IdentificationConformance.*')")
    return rows, identification


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


def jnd_panel(ax, published, model, quantity, ylabel, title, colours):
    bands(ax, published, quantity, colours)
    for sl, marker, size in ((20.0, "o", 9), (35.0, "s", 4)):
        pts = sorted((r[0], r[2]) for r in model.get(quantity, []) if r[1] == sl)
        ax.plot([p[0] for p in pts], [p[1] for p in pts], marker=marker, markersize=size, markerfacecolor="none",
                color="black", label=f"model, {sl:g} dB SL")
    ax.set_xscale("log")
    label(ax, "frequency (Hz)", ylabel, title)


def main():
    if len(sys.argv) != 4:
        sys.exit("usage: plot_perception_conformance.py CONFORMANCE.txt PUBLISHED.csv OUT.png")
    model, identification = read_model(sys.argv[1])
    published = read_published(sys.argv[2])
    colours = ("#1b9e77", "#d95f02", "#7570b3")
    fig, axes = plt.subplots(2, 3, figsize=(15, 8))
    jnd_panel(axes[0][0], published, model, "frequency_weber_fraction", "frequency JND (Weber fraction)",
              "Frequency discrimination", colours)
    jnd_panel(axes[0][1], published, model, "amplitude_jnd_db", "amplitude JND (dB)", "Amplitude discrimination", colours)

    ax = axes[0][2]
    for row in (r for r in published if r["quantity"] == "gap_detection_ms"):
        lo_sl, hi_sl = float(row["sensation_level_low_db"]), float(row["sensation_level_high_db"])
        ax.fill_between([lo_sl - 2, hi_sl + 2], [float(row["low"])] * 2, [float(row["high"])] * 2, alpha=0.18,
                        color=colours[0], label=row["source"].split(":")[0].split(",")[0] + " et al.")
    pts = sorted((r[1], r[2]) for r in model.get("gap_detection_ms", []))
    ax.plot([p[0] for p in pts], [p[1] for p in pts], marker="o", color="black", label="model, 250 Hz tone")
    label(ax, "sensation level (dB)", "gap detection threshold (ms)", "Gap detection", (0, 15))

    ax = axes[1][0]
    pts = sorted((r[0], r[2], r[3], r[4]) for r in model.get("threshold_peak_displacement_um", []))
    ax.fill_between([p[0] for p in pts], [p[2] for p in pts], [p[3] for p in pts], alpha=0.18, color=colours[0],
                    label="published: floor to 40 Hz, minimum from 250 Hz, 10-14 dB/octave between")
    ax.plot([p[0] for p in pts], [p[1] for p in pts], color="black", marker=".",
            label="model: min(Pacinian U, non-Pacinian floor)")
    ax.set_xscale("log")
    ax.set_yscale("log")
    label(ax, "frequency (Hz)", "detection threshold, peak displacement (µm)", "Detection threshold", loc="lower left")

    ax = axes[1][1]
    one = [r for r in identification if r[0].startswith(("frequency", "level"))]
    low, high = one[0][3], one[0][4]
    ax.axhspan(low, high, alpha=0.18, color=colours[0], label="Rabinowitz et al. 1987: one dimension")
    for n, name in enumerate(dict.fromkeys(r[0] for r in one)):
        pts = sorted((r[1], r[2]) for r in one if r[0] == name)
        ax.plot([p[0] for p in pts], [p[1] for p in pts], marker="os^vD"[n % 5], color="black", alpha=0.4 + 0.12 * n,
                label=f"model: {name}")
    label(ax, "members of the set", "information transfer (bits)", "Identification along one dimension (rendered sets)", (0, 2.5))

    ax = axes[1][2]
    many = [r for r in identification if not r[0].startswith(("frequency", "level"))]
    for y, (name, _, value, lo, hi) in enumerate(many):
        ax.fill_between([lo, hi], [y - 0.3] * 2, [y + 0.3] * 2, alpha=0.18, color=colours[0])
        ax.plot([value], [y], marker="o", color="black")
        ax.annotate(f"model {value:.3g} (published {lo:g}-{hi:g})", (value, y + 0.32), fontsize=7, ha="center")
    ax.set_yticks(range(len(many)), [r[0].replace(": ", ":\n") for r in many], fontsize=7)
    ax.set_xscale("log")
    ax.set_ylim(-0.7, len(many) - 0.2)
    ax.set_xlabel("bits, or percent correct (log scale)")
    ax.set_title("Several dimensions (the tactons a pinned deviation)")

    fig.suptitle("Perception model (black) against published ranges (shaded)")
    fig.tight_layout()
    fig.savefig(sys.argv[3], dpi=90)


if __name__ == "__main__":
    main()
