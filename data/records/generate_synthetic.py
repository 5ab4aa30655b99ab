#!/usr/bin/env python3
"""Synthetic ground-motion records for tests and examples (data/records/synthetic/).

Deterministic and dependency-free (no numpy, no random module: a 64-bit LCG),
so the files are the same on every machine and Python version. Every value is
written with 7 significant digits in the E format of PEER .AT2 files, so any
correctly rounding reader (strtod, Python float) gets the same doubles.

  pulse-train.AT2    0.01 s, 2000 samples: 0.5 s of exact zeros (as many real
                     records start), then a decaying 2 Hz sine with a 0.7 Hz
                     beat; PGA about 0.45 g; exact zeros inside it too
  noise-burst.AT2    0.005 s, 4000 samples: band-limited noise (LCG, two-pole
                     filter) under a Saragoni-Hart-like envelope; PGA about 0.3 g
  nonuniform.csv     the first 2 s of pulse-train at non-uniform times (a table
                     of time and acceleration in g, with a header and comments)

Usage: python3 data/records/generate_synthetic.py [OUTPUT_DIR]
       (default: data/records/synthetic next to this script)
"""
import math
import os
import sys


def e7(value):
    """The value as an .AT2 field: 7 significant digits, E format."""
    return f"{value: .6E}"


def rounded(value):
    return float(e7(value))


def pulse_train():
    dt, n = 0.01, 2000
    a = []
    for i in range(n):
        t = i * dt
        if t < 0.5:
            a.append(0.0)
            continue
        s = t - 0.5
        value = 0.45 * math.exp(-s / 6.0) * math.sin(2 * math.pi * 2.0 * s) * math.cos(
            2 * math.pi * 0.35 * s)
        a.append(rounded(value))
    # Exact zeros inside the motion (SLAMMER skips those samples).
    for i in (700, 701, 1333):
        a[i] = 0.0
    return dt, a


def noise_burst():
    dt, n = 0.005, 4000
    state = 20261125
    y1 = y2 = 0.0
    a = []
    for i in range(n):
        state = (6364136223846793005 * state + 1442695040888963407) % 2**64
        white = (state >> 11) / 2**53 * 2 - 1
        # Two-pole resonator near 3 Hz, damping 0.4 (a crude soil filter).
        w = 2 * math.pi * 3.0
        c1 = 2 * math.exp(-0.4 * w * dt) * math.cos(w * dt * math.sqrt(1 - 0.16))
        c2 = -math.exp(-2 * 0.4 * w * dt)
        y = c1 * y1 + c2 * y2 + white
        y2, y1 = y1, y
        t = i * dt
        envelope = (t / 4.0) ** 2 * math.exp(2 * (1 - t / 4.0)) if t > 0 else 0.0
        a.append(rounded(0.01 * envelope * y))
    return dt, a


def write_at2(path, title, dt, a):
    with open(path, "w", newline="\n") as f:
        f.write("PEER NGA STRONG MOTION DATABASE RECORD\n")
        f.write(f"{title}, synthetic (frictionref data/records/generate_synthetic.py)\n")
        f.write("ACCELERATION TIME SERIES IN UNITS OF G\n")
        f.write(f"NPTS= {len(a):5d}, DT= {dt:.4f} SEC\n")
        for k in range(0, len(a), 5):
            f.write("".join(f" {e7(v)}" for v in a[k:k + 5]) + "\n")


def write_nonuniform(path, dt, a):
    with open(path, "w", newline="\n") as f:
        f.write("# The first 2 s of pulse-train.AT2 at non-uniform times: every\n")
        f.write("# sample up to 1 s, then every other one (frictionref\n")
        f.write("# data/records/generate_synthetic.py). Acceleration in g.\n")
        f.write("time_s,accel_g\n")
        for i in range(201):
            if i <= 100 or i % 2 == 0:
                f.write(f"{i * dt!r},{e7(a[i]).strip()}\n")


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else os.path.join(
        os.path.dirname(os.path.abspath(__file__)), "synthetic")
    os.makedirs(out, exist_ok=True)
    dt, a = pulse_train()
    write_at2(os.path.join(out, "pulse-train.AT2"), "Pulse train 2 Hz", dt, a)
    write_nonuniform(os.path.join(out, "nonuniform.csv"), dt, a)
    dt, a = noise_burst()
    write_at2(os.path.join(out, "noise-burst.AT2"), "Noise burst 3 Hz", dt, a)


if __name__ == "__main__":
    main()
