#!/usr/bin/env python3
"""Which of two builds' dense curves of the seed's model is correctly rounded.

The command of a reference curve (data/reference/*.csv) is run with two
binaries, OLD and NEW. For every numeric field where their curves differ,
the closed form of the seed's slip
(docs/theory.md 2, phase_law.hpp) is evaluated in 50 digits (mpmath) at exact
w t, from the phase's start as `frictionref events` prints it, and each value
is compared with the double nearest the exact one. (Every number read is
converted to its double first: the files hold shortest round-trip forms,
whose decimal value is not the double's.) Used for docs/benchmarks.md
("Dense samples in double-double"): the fast path's values must be the
correctly rounded ones wherever the two differ.

    python3 tests/reference/dense_rounding_check.py OLD NEW data/reference/seed-10.2-exact-curve.csv
"""
import csv
import io
import struct
import subprocess
import sys

import mpmath

mpmath.mp.dps = 50


def nearest_double(x):
    d = float(x)
    best = d
    for n in (next_after(d, -1), next_after(d, 1)):
        if abs(mpmath.mpf(n) - x) < abs(mpmath.mpf(best) - x):
            best = n
    return best


def next_after(d, direction):
    bits = struct.unpack("<q", struct.pack("<d", d))[0]
    if d == 0:
        return 5e-324 * direction
    step = 1 if (d > 0) == (direction > 0) else -1
    return struct.unpack("<d", struct.pack("<q", bits + step))[0]


def table(text):
    rows = [line for line in text.splitlines() if line and not line.startswith("#")]
    return list(csv.reader(io.StringIO("\n".join(rows))))


def main(old_binary, binary, path):
    with open(path) as f:
        committed_text = f.read()
    command = next(l for l in committed_text.splitlines() if l.startswith("# command:"))
    model = next(l for l in committed_text.splitlines() if l.startswith("# model:"))
    args = command.split(":", 1)[1].split()[1:]
    fresh = table(subprocess.run([binary] + args, check=True, capture_output=True, text=True).stdout)
    committed = table(subprocess.run([old_binary] + args, check=True, capture_output=True,
                                     text=True).stdout)
    fields = dict(kv.split("=") for kv in model.split(":", 1)[1].split())
    m, B, w, R = (mpmath.mpf(float(fields[k])) for k in ("mass", "amplitude", "omega", "friction"))
    event_args = ["events"] + [a for a in args[1:] if a not in ("--include-events",)]
    # --dt takes a value: drop it with its value.
    cleaned = []
    skip = False
    for a in event_args:
        if skip:
            skip = False
            continue
        if a == "--dt":
            skip = True
            continue
        cleaned.append(a)
    events = table(subprocess.run([binary] + cleaned, check=True, capture_output=True, text=True).stdout)
    phases = [dict(zip(events[0], r)) for r in events[1:]]
    header = committed[0]
    differing = fresh_right = committed_right = 0
    for row_new, row_old in zip(fresh[1:], committed[1:]):
        for j, name in enumerate(header):
            if name == "phase" or row_new[j] == row_old[j]:
                continue
            differing += 1
            t = float(row_new[0])
            kind = row_new[-1]
            # The sampler's rule: a time at a boundary belongs to the next phase.
            phase = [p for p in phases if float(p["t_begin"]) <= t < float(p["t_end"])
                     or (t == float(p["t_end"]) and p is phases[-1])][-1]
            assert phase["phase"] == kind, (t, kind, phase)
            s = 1 if kind == "slip+" else -1
            a0 = w * mpmath.mpf(float(phase["t_begin"]))
            tau = w * mpmath.mpf(t)
            h = tau - a0
            b = B / (m * w)
            r = R / (m * w)
            xa, va = mpmath.mpf(float(phase["x_begin"])), mpmath.mpf(float(phase["v_begin"]))
            exact = {
                "v": va + b * (mpmath.cos(a0) - mpmath.cos(tau)) - s * r * h,
                "x": xa + ((va + b * mpmath.cos(a0)) * h - b * (mpmath.sin(tau) - mpmath.sin(a0))
                           - s * r * h * h / 2) / w,
                "a": w * (b * mpmath.sin(tau) - s * r),
            }[name]
            rounded = nearest_double(exact)
            fresh_right += float(row_new[j]) == rounded
            committed_right += float(row_old[j]) == rounded
    print(f"{path}: {differing} fields differ between OLD and NEW; correctly rounded: "
          f"NEW {fresh_right}, OLD {committed_right}")
    return 0 if fresh_right == differing else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv[1], sys.argv[2], sys.argv[3]))
