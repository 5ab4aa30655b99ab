#!/usr/bin/env python3
"""Seed inputs of the general model for fuzz_engine (tests/fuzz/corpus/engine/general-*,
record-*: with a ground record), and of the seed's model with its steady cycle replayed
(replay-*: flag bit 7; with dead bands and sliding continuously).

Each seed is a model of the general family written in fuzz_engine's input
layout (see the comment at the top of tests/fuzz/fuzz_engine.cpp) with every
field as a decimal m * 10^e. Run from the repository root:

    python3 tests/fuzz/tools/make_engine_seeds.py

It rewrites the general-*, record-* and replay-* files; the other seeds are untouched.
"""
import pathlib
import struct


def decimal(value_mantissa, exponent):
    """A field m * 10^e: int24 mantissa (little endian), int8 exponent."""
    m = value_mantissa & 0xFFFFFF
    return struct.pack("<I", m)[:3] + struct.pack("<b", exponent)


def seed(mass, amplitude, omega, friction, x0, v0, t0, periods,
         static_extra, stiffness, damping, offset, harmonics, record=None, one_way=False):
    """Fields as (mantissa, exponent) pairs; t_end as a number of forcing periods.
    record: [(t0, a0), (dt1, a1), ...] as (mantissa, exponent) pairs, or None."""
    flags = (2 << 1) | 32 | (64 if record else 0)
    out = bytes([0x00, flags])  # decimals; t_end in periods; general block; record
    for field in (mass, amplitude, omega, friction, x0, v0, t0, periods):
        out += decimal(*field)
    out += bytes([0x00])  # general fields as decimals
    for field in (static_extra, stiffness, damping, offset):
        out += decimal(*field)
    out += bytes([len(harmonics)])
    for b, w, phi in harmonics:
        out += decimal(*b) + decimal(*w) + decimal(*phi)
    if record:
        # samples - 2; times and values as decimals, bit 2: one-way
        out += bytes([len(record) - 2, 0x04 if one_way else 0x00])
        for time, accel in record:
            out += decimal(*time) + decimal(*accel)
    return out


one, zero = (1, 0), (0, 0)
SEEDS = {
    # name: (mass, B, w, R, x0, v0, t0, periods, Rs - R, k, c, F0, harmonics)
    "general-static": (one, one, one, (7, -1), zero, zero, zero, (20, 0), (1, -1), zero, zero, zero, []),
    "general-spring": (one, one, (2, 0), (2, -1), zero, zero, zero, (20, 0), zero, one, zero, zero, []),
    "general-damped": (one, one, one, (3, -1), zero, zero, zero, (20, 0), zero, one, (1, -1), zero, []),
    "general-overdamped": (one, one, one, (3, -1), zero, zero, zero, (10, 0), zero, one, (5, 0), zero, []),
    "general-critical": (one, one, one, (3, -1), zero, zero, zero, (10, 0), zero, one, (2, 0), zero, []),
    "general-resonant": (one, one, (2, 0), (2, -1), zero, zero, zero, (10, 0), zero, (4, 0), zero, zero, []),
    "general-offset": (one, one, one, (5, -1), zero, zero, zero, (10, 0), (2, -1), zero, zero, (3, -1), []),
    "general-harmonics": (one, one, one, (4, -1), zero, zero, zero, (10, 0), (2, -1), one, (1, -1), zero,
                          [((3, -1), (3, 0), zero), ((2, -1), (25, -1), (1, 0))]),
    "general-free-coulomb": (one, zero, one, (1, -1), (1, 0), zero, zero, (5, 0), zero, one, zero, zero, []),
    "general-drift": (one, zero, one, (2, -1), zero, zero, zero, (5, 0), zero, zero, (1, -1), (3, -1), []),
}

# A short record (t_0 = 0.5, dt = 0.25, a in units of 0.1) with each structure.
RECORD = [((5, -1), (8, -1)), ((25, -2), (-12, -1)), ((25, -2), (15, -1)), ((25, -2), (-3, -1)),
          ((25, -2), (-9, -1)), ((25, -2), (11, -1)), ((25, -2), (2, -1)), ((25, -2), (-6, -1))]
RECORD_SEEDS = {
    "record-rigid": (one, zero, one, (3, -1), zero, zero, zero, (1, 0), (1, -1), zero, zero, zero, []),
    "record-spring": (one, zero, one, (2, -1), zero, zero, zero, (1, 0), (1, -1), (4, 0), zero, zero, []),
    "record-damped-harmonic": (one, (2, -1), (3, 0), (2, -1), zero, zero, zero, (2, 0), (1, -1), (4, 0),
                               (3, -1), zero, [((1, -1), (7, 0), zero)]),
    "record-overdamped": (one, zero, one, (1, -1), zero, zero, zero, (1, 0), (1, -1), one, (5, 0), zero, []),
    "record-damper-only": (one, zero, one, (2, -1), zero, (5, -1), zero, (1, 0), zero, zero, (1, 0), zero, []),
}

def replay_seed(mass, amplitude, omega, friction, x0, v0, t0, periods):
    """The seed's model (no general block), t_end in periods, the cycle replayed (bit 7)."""
    out = bytes([0x00, (2 << 1) | 128])
    for field in (mass, amplitude, omega, friction, x0, v0, t0, periods):
        out += decimal(*field)
    return out


REPLAY_SEEDS = {
    # name: (mass, B, w, R, x0, v0, t0, periods)
    "replay-dead-bands": (one, one, one, (7, -1), zero, zero, zero, (20, 0)),
    "replay-moving-start": (one, one, (3, 0), (8, -1), (3, -1), (-1, 0), (2, -1), (30, 0)),
    "replay-near-one": (one, one, one, (999, -3), (5, 0), zero, zero, (40, 0)),
    "replay-far-phase": (one, one, one, (6, -1), zero, zero, (1, 8), (25, 0)),
    # continuous sliding, replayed from a reversal near the fixed point (theory.md 3.10)
    "replay-sliding": (one, one, one, (3, -1), zero, zero, zero, (60, 0)),
    "replay-sliding-offset": ((2, 0), one, (3, 0), (45, -2), (1, 6), (5, -1), (7, -1), (50, 0)),
    "replay-sliding-slow": (one, one, one, (1, -1), zero, zero, zero, (190, 0)),
}


def main():
    corpus = pathlib.Path("tests/fuzz/corpus/engine")
    for name, fields in SEEDS.items():
        (corpus / name).write_bytes(seed(*fields))
    for name, fields in RECORD_SEEDS.items():
        (corpus / name).write_bytes(seed(*fields, record=RECORD))
    for name in ("record-rigid", "record-spring"):
        (corpus / (name + "-one-way")).write_bytes(seed(*RECORD_SEEDS[name], record=RECORD, one_way=True))
    for name, fields in REPLAY_SEEDS.items():
        (corpus / name).write_bytes(replay_seed(*fields))
    print(f"wrote {len(SEEDS) + len(RECORD_SEEDS) + 2 + len(REPLAY_SEEDS)} seeds to {corpus}")


if __name__ == "__main__":
    main()
