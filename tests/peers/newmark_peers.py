#!/usr/bin/env python3
"""Newmark's rigid block on the synthetic records: the exact answer against two
numerical peers, as the record is resampled linearly (the same ground motion,
sampled more finely), for docs/validation.md.

Peers:
  - SLAMMER 1.1's algorithm (RigidBlock.SlammerRigorous), as `frictionref
    newmark --method slammer` runs it (bit-exact against a separate Python
    transliteration: tests/test_slammer_rigid_block.cpp);
  - the rigid block many scripts write with numpy/scipy: the relative velocity
    stepped with the trapezoidal rule while sliding (clipped at 0 one-way,
    stopped at a sign change two-way), the displacement by
    scipy.integrate.cumulative_trapezoid.

The exact answer is `frictionref newmark` (default method) on the original
record; it is also run on every resampled record, to show it does not move.

  python3 tests/peers/newmark_peers.py [path/to/frictionref] > table.md

Needs python3-numpy and python3-scipy (Debian packages; tests/peers/run.sh
installs them).
"""
import json
import os
import subprocess
import sys
import tempfile
import time

import numpy as np
from scipy.integrate import cumulative_trapezoid

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
BIN = sys.argv[1] if len(sys.argv) > 1 else os.path.join(ROOT, "build/release/frictionref")
G = 9.80665
KY = 0.1
FACTORS = [1, 4, 16, 64]


def read_at2(path):
    lines = open(path).read().splitlines()
    dt = float(lines[3].split("DT=")[1].split()[0])
    values = [float(x) for line in lines[4:] for x in line.split()]
    return dt, np.array(values)


def resample(a, factor):
    """The linear interpolant of `a` at `factor` times the sampling rate."""
    n = len(a)
    s = np.arange(factor) / factor
    fine = (a[:-1, None] + s[None, :] * (a[1:] - a[:-1])[:, None]).ravel()
    return np.append(fine, a[-1]) if n > 1 else a


def frictionref(path, dt, method, two_way):
    args = [BIN, "newmark", "--record", path, "--record-dt", repr(dt), "--yield-accel", str(KY),
            "--method", method, "--json"]
    if two_way:
        args.append("--two-way")
    start = time.perf_counter()
    out = subprocess.run(args, check=True, capture_output=True, text=True).stdout
    seconds = time.perf_counter() - start
    return json.loads(out)[0]["displacement_at_record_end"], seconds


def scipy_block(a_g, dt, two_way):
    """a_g in g; returns the displacement at the last sample [m] and seconds."""
    start = time.perf_counter()
    a = a_g * G
    ky = KY * G
    v = np.zeros(len(a))
    for i in range(1, len(a)):
        if v[i - 1] == 0:
            if a[i] > ky:
                s = 1.0
            elif two_way and a[i] < -ky:
                s = -1.0
            else:
                continue
        else:
            s = 1.0 if v[i - 1] > 0 else -1.0
        vi = v[i - 1] + 0.5 * dt * ((a[i - 1] - s * ky) + (a[i] - s * ky))
        if s * vi <= 0:  # the slide ends inside the step
            vi = 0.0
        v[i] = vi
    x = cumulative_trapezoid(v, dx=dt, initial=0)
    return x[-1], time.perf_counter() - start


def main():
    print("| record | sliding | resampling | dt [s] | exact [m] | SLAMMER [m] | SLAMMER error | "
          "numpy/scipy [m] | numpy/scipy error | time exact / SLAMMER / scipy [ms] |")
    print("|---|---|---:|---:|---:|---:|---:|---:|---:|---:|")
    with tempfile.TemporaryDirectory() as work:
        for name in ["noise-burst.AT2", "pulse-train.AT2"]:
            dt, a = read_at2(os.path.join(ROOT, "data/records/synthetic", name))
            for two_way in [False, True]:
                reference = None
                for factor in FACTORS:
                    fine = resample(a, factor)
                    path = os.path.join(work, f"{name}.{factor}.txt")
                    with open(path, "w") as f:
                        f.write("\n".join(repr(float(x)) for x in fine) + "\n")
                    step = dt / factor
                    exact, t_exact = frictionref(path, step, "exact", two_way)
                    if reference is None:
                        reference = exact
                    slammer, t_slammer = frictionref(path, step, "slammer", two_way)
                    scipy, t_scipy = scipy_block(fine, step, two_way)
                    rel = lambda d: f"{abs(d - reference) / abs(reference):.2e}"
                    print(f"| {name} | {'two-way' if two_way else 'one-way'} | x{factor} | "
                          f"{step:.6g} | {exact:.10f} | {slammer:.10f} | {rel(slammer)} | "
                          f"{scipy:.10f} | {rel(scipy)} | {1e3 * t_exact:.0f} / "
                          f"{1e3 * t_slammer:.0f} / {1e3 * t_scipy:.0f} |")


if __name__ == "__main__":
    main()
