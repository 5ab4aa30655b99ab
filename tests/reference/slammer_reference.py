#!/usr/bin/env python3
"""Reference values for SLAMMER's rigid-block algorithm (tests/test_slammer_rigid_block.cpp).

A second, independent transliteration of RigidBlock.SlammerRigorous from USGS
SLAMMER 1.1 (Java, public domain; Jibson 1993), in plain Python floats (IEEE
double, same operation order as the Java), run on the synthetic records of
data/records/synthetic. The C++ implementation (src/newmark) must agree to
the last bit. How SLAMMER gets its samples, reproduced here:
  - DoubleList reads each value in g and multiplies it by scale * Gcmss
    (980.665): cm/s^2;
  - SlammerRigorous multiplies again by mult * unitMult (mult = the scale,
    negative for the inverse polarity; unitMult = 1 for metric output), and
    compares with t = KY * Gcmss * unitMult;
  - a sample exactly 0 with mult > 0 is skipped.
frictionref reads the record in g with --gravity 980.665 (centimetres), so its
sample is the value times 980.665, the same product; the inverse polarity
negates it (exact).

Also checks SLAMMER's own unit test when the Cape Mendocino 1992 Petrolia
record (PET-000, CGS; not redistributed here) is given:
  python3 tests/reference/slammer_reference.py --pet000 PATH
prints the one-way displacement at KY = 0.1 g, dt = 0.02 s (SlammerTest
asserts 35.40371 +- 1e-4 cm).

Usage: python3 tests/reference/slammer_reference.py > tests/data/records/slammer_reference.csv
"""
import os
import sys

GCMSS = 980.665
HERE = os.path.dirname(os.path.abspath(__file__))
RECORDS = os.path.join(HERE, "..", "..", "data", "records", "synthetic")


def sign(x):
    return 1.0 if x >= 0 else -1.0


def slammer_rigorous(data, d, ky, dual, mult):
    """data: samples after DoubleList (cm/s^2); mult: SLAMMER's multiplier."""
    t = ky * GCMSS * 1.0
    q = r = s = u = v = y = 0.0
    episodes = 0
    vmax = 0.0
    skipped = 0
    for val in data:
        a = val * mult * 1.0
        if a == 0.0 and mult > 0.0:
            skipped += 1
            continue
        if abs(v) < 1e-15:
            n = sign(a) if abs(a) > t else a / t
        else:
            n = sign(v)
        y = a - n * t
        v = r + d / 2.0 * (y + s)
        if (not dual and v <= 0.0) or (dual and not (abs(r) < 1e-15 or (v / r) > 0.0)):
            v = 0.0
            y = 0.0
        u = q + d / 2.0 * (v + r)
        if abs(r) < 1e-15 and not abs(v) < 1e-15:
            episodes += 1
        vmax = max(vmax, abs(v))
        q = u
        r = v
        s = y
    return u, episodes, vmax, skipped


def read_at2(path):
    lines = open(path).read().splitlines()
    header = lines[3].replace(",", " ").split()
    dt = float(header[header.index("DT=") + 1])
    values = [float(x) for line in lines[4:] for x in line.split()]
    return dt, values


def main():
    if len(sys.argv) == 3 and sys.argv[1] == "--pet000":
        values = [float(x) for x in open(sys.argv[2]).read().split()]
        data = [x * (1.0 * GCMSS) for x in values]
        print(repr(slammer_rigorous(data, 0.02, 0.1, False, 1.0)[0]))
        return
    print("# SLAMMER's rigid-block algorithm on data/records/synthetic, in cm (gravity 980.665):")
    print("# tests/reference/slammer_reference.py (a Python transliteration of")
    print("# RigidBlock.SlammerRigorous, SLAMMER 1.1). Values are Python repr: exact doubles.")
    print("record,yield_accel_g,mode,polarity,displacement_cm,slip_episodes,"
          "max_relative_velocity_cm_s,skipped_zero_samples")
    for name in ("pulse-train.AT2", "noise-burst.AT2"):
        dt, values = read_at2(os.path.join(RECORDS, name))
        data = [x * (1.0 * GCMSS) for x in values]
        for ky in (0.02, 0.05, 0.1, 0.2, 0.5):
            for dual in (False, True):
                for mult in (1.0, -1.0):
                    u, episodes, vmax, skipped = slammer_rigorous(data, dt, ky, dual, mult)
                    print(f"{name},{ky!r},{'two-way' if dual else 'one-way'},"
                          f"{'normal' if mult > 0 else 'inverse'},{u!r},{episodes},{vmax!r},{skipped}")


if __name__ == "__main__":
    main()
