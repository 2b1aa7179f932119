#!/usr/bin/env python3
"""A 20 s, ten-finger gesture over assets/examples/smiley.vimg (70 x 140 mm), for timing
`vimg render --touch-latency-ms` with prediction on and off (docs/benchmarks/touch-prediction.md, "Touch prediction
in the render loop"; issue 44):

    python3 bench/ten_finger_gesture.py > ten_fingers_20s.csv
    vimg render assets/examples/smiley.vimg --gesture ten_fingers_20s.csv --rate 48000 \
        --touch-latency-ms 60 --out /tmp/out.wav

Ten fingers on a 2 x 5 grid inside the face, each circling its own centre (radius 8 mm) at 120 mm/s, one event per
finger every 1/120 s (a 120 Hz panel), down at 0 s and up at 20 s. Deterministic (no noise)."""
import math
import sys

DURATION_S = 20.0
EVENT_RATE_HZ = 120.0
RADIUS_MM = 8.0
SPEED_MM_PER_S = 120.0


def main() -> None:
    out = sys.stdout
    out.write("time_s,finger,x_mm,y_mm,pressure,phase\n")
    events = int(round(DURATION_S * EVENT_RATE_HZ))
    omega_rad_per_s = SPEED_MM_PER_S / RADIUS_MM
    for k in range(events + 1):
        t = k / EVENT_RATE_HZ
        phase = "down" if k == 0 else "up" if k == events else "move"
        for finger in range(10):
            cx = 25.0 + 20.0 * (finger % 2)
            cy = 46.0 + 12.0 * (finger // 2)
            a = omega_rad_per_s * t + finger * 0.7
            out.write(f"{t:.9g},{finger},{cx + RADIUS_MM * math.cos(a):.6f},{cy + RADIUS_MM * math.sin(a):.6f},1,{phase}\n")


if __name__ == "__main__":
    main()
