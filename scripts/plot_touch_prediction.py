#!/usr/bin/env python3
"""Draws docs/images/touch_prediction.svg from the table of bench/touch_prediction_bench --table:
the mean prediction error (px) against the horizon (ms), one panel per task, one line per approach.

  build/release/bench/touch_prediction_bench --table tests/data/touch-latency-henze2017 > table.md
  python3 scripts/plot_touch_prediction.py table.md docs/images/touch_prediction.svg
"""
import sys

APPROACHES = ("no extrapolation", "linear (authors)", "fitted", "learned")
COLOURS = ("#888888", "#d95f02", "#1b9e77", "#7570b3")


def read_table(path):
    rows = {}
    with open(path, encoding="utf-8") as f:
        for number, line in enumerate(f, 1):
            cells = [c.strip() for c in line.strip().strip("|").split("|")]
            if len(cells) != 10 or not cells[1].endswith(" ms"):
                continue
            try:
                horizon = float(cells[1][:-3])
                values = [float(c.split()[0]) for c in (cells[3], cells[4], cells[6], cells[7])]
            except ValueError:
                sys.exit(f"{path}:{number}: error: a table row whose numbers do not read: {line.strip()}")
            rows.setdefault(cells[0], []).append((horizon, values))
    if not rows:
        sys.exit(f"{path}: error: no table rows (the output of touch_prediction_bench --table)")
    return rows


def svg(rows):
    width, height, pad = 260, 220, 40
    tasks = list(rows)
    top = max(v for task in tasks for _, values in rows[task] for v in values)
    out = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{width * len(tasks)}" height="{height + 60}" '
           'font-family="DejaVu Sans, sans-serif" font-size="11">',
           f'<rect width="100%" height="100%" fill="white"/>']
    for i, task in enumerate(tasks):
        x0 = i * width + pad
        plot_w, plot_h = width - pad - 10, height - 2 * pad
        sx = lambda h: x0 + h / 100.0 * plot_w
        sy = lambda v: pad + plot_h - v / top * plot_h
        out.append(f'<text x="{x0 + plot_w / 2}" y="{pad - 14}" text-anchor="middle" font-weight="bold">{task}</text>')
        out.append(f'<line x1="{x0}" y1="{pad + plot_h}" x2="{x0 + plot_w}" y2="{pad + plot_h}" stroke="black"/>')
        out.append(f'<line x1="{x0}" y1="{pad}" x2="{x0}" y2="{pad + plot_h}" stroke="black"/>')
        for h in (0, 33, 67, 100):
            out.append(f'<text x="{sx(h)}" y="{pad + plot_h + 14}" text-anchor="middle">{h}</text>')
        for v in range(0, int(top) + 1, 20):
            out.append(f'<text x="{x0 - 4}" y="{sy(v) + 4}" text-anchor="end">{v}</text>')
        for a, colour in enumerate(COLOURS):
            points = [(0.0, 0.0)] + [(h, values[a]) for h, values in rows[task]]
            path = " ".join(f"{sx(h):.1f},{sy(v):.1f}" for h, v in points)
            out.append(f'<polyline points="{path}" fill="none" stroke="{colour}" stroke-width="2"/>')
        out.append(f'<text x="{x0 + plot_w / 2}" y="{pad + plot_h + 28}" text-anchor="middle">horizon, ms</text>')
    for a, (name, colour) in enumerate(zip(APPROACHES, COLOURS)):
        x = pad + a * 130
        out.append(f'<line x1="{x}" y1="{height + 25}" x2="{x + 20}" y2="{height + 25}" stroke="{colour}" stroke-width="2"/>')
        out.append(f'<text x="{x + 25}" y="{height + 29}">{name}</text>')
    out.append(f'<text x="{pad}" y="{height + 49}">mean error, px (12.72 px/mm; in sample)</text>')
    out.append("</svg>")
    return "\n".join(out) + "\n"


def main():
    if len(sys.argv) != 3:
        sys.exit("usage: plot_touch_prediction.py TABLE.md OUT.svg")
    text = svg(read_table(sys.argv[1]))
    with open(sys.argv[2] + ".tmp", "w", encoding="utf-8") as f:
        f.write(text)
    import os
    os.replace(sys.argv[2] + ".tmp", sys.argv[2])


if __name__ == "__main__":
    main()
