#!/usr/bin/env python3
"""Writes a valid .vimg with N primitives (dots, lines, rects, ellipses, polygons in equal
shares) spread evenly over a 200 x 200 mm canvas: the editor's frame-time benchmark input.
usage: make_many_primitives.py N OUT.vimg"""
import math
import sys

n, out = int(sys.argv[1]), sys.argv[2]
side = math.ceil(math.sqrt(n))
cell = 200.0 / side
rows = ['<?xml version="1.0" encoding="UTF-8"?>',
        '<vibroimage version="1.0" width="200" height="200">']
for i in range(n):
    x = (i % side) * cell + cell / 2
    y = (i // side) * cell + cell / 2
    r = cell * 0.35
    kind = i % 5
    if kind == 0:
        rows.append(f'  <dot id="d{i}" x="{x:.3f}" y="{y:.3f}" radius="{r:.3f}" gain="1"/>')
    elif kind == 1:
        rows.append(f'  <line id="l{i}" x1="{x - r:.3f}" y1="{y:.3f}" x2="{x + r:.3f}" y2="{y:.3f}" width="{r / 3:.3f}" '
                    f'frequency="175" damping="0.05" gain="1"/>')
    elif kind == 2:
        rows.append(f'  <surface id="s{i}" shape="rect" x="{x - r:.3f}" y="{y - r:.3f}" width="{2 * r:.3f}" '
                    f'height="{2 * r:.3f}" period="0.5" relief="0.5" pattern="sine" gain="1"/>')
    elif kind == 3:
        rows.append(f'  <surface id="s{i}" shape="ellipse" cx="{x:.3f}" cy="{y:.3f}" rx="{r:.3f}" ry="{r * 0.7:.3f}" '
                    f'period="0.5" relief="0.5" pattern="square" gain="1"/>')
    else:
        pts = " ".join(f"{x + r * math.cos(a):.3f},{y + r * math.sin(a):.3f}" for a in (0, 2.1, 4.2))
        rows.append(f'  <surface id="s{i}" shape="polygon" points="{pts}" period="0.5" relief="0.5" '
                    f'pattern="triangle" gain="1"/>')
rows.append('</vibroimage>')
open(out, "w").write("\n".join(rows) + "\n")
