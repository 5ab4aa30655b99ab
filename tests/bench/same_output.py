#!/usr/bin/env python3
"""Byte-identical output of two frictionref binaries on random general models.

For a change that must not move a single bit (a faster evaluation of the same
closed form): both binaries run `frictionref curve --include-events` (997 rows)
and `frictionref events` on N random models (spring, damper, harmonics, force
offset, static friction, initial state; a fifth of them driven by a synthetic
record of data/records/synthetic, some one-way), from the same directory
name so the files' `# command:` lines match, and the files and messages are
compared byte for byte.

    python3 tests/bench/same_output.py OLD_BINARY NEW_BINARY [N] [SEED]

(OLD_BINARY from an earlier commit: see compare_event_tables.py.) Prints each
model that differs and a count; exit status 1 if any differs.
"""
import glob
import os
import random
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
RECORDS = sorted(f for f in glob.glob(os.path.join(ROOT, 'data/records/synthetic/*'))
                 if f.endswith(('.AT2', '.csv')))


def random_model(rng):
    def log_uniform(a, b):
        return 10 ** rng.uniform(a, b)
    b = rng.choice([1.0, log_uniform(-2, 2)])
    w = rng.choice([1.0, log_uniform(-1, 1)])
    m = rng.choice([1.0, log_uniform(-1, 1)])
    r = b * rng.uniform(0, 1.2)
    k = rng.choice([0, 0, log_uniform(-2, 2) * m * w * w])
    c = rng.choice([0, log_uniform(-3, 1) * m * w, 2 * (k * m) ** 0.5 * rng.uniform(0.5, 3)])
    args = ['--mass', repr(m), '--friction', repr(r), '--stiffness', repr(k), '--damping', repr(c)]
    if rng.random() < 0.2 and RECORDS:
        args += ['--ground-accel', rng.choice(RECORDS)]
        if rng.random() < 0.3:
            args += ['--one-way']
        return args, 20.0
    args += ['--amplitude', repr(b), '--omega', repr(w)]
    if rng.random() < 0.5:
        args += ['--static-friction', repr(r * (1 + rng.uniform(0, 0.5)))]
    if rng.random() < 0.4:
        args += ['--force-offset', repr(b * rng.uniform(-1, 1))]
    for _ in range(rng.choice([0, 0, 1, 2])):
        args += ['--harmonic', '%r,%r,%r' % (b * rng.uniform(0, 1), w * log_uniform(-1, 1),
                                             rng.uniform(-3, 3))]
    if rng.random() < 0.3:
        args += ['--v0', repr(rng.uniform(-1, 1) * b / (m * w))]
    if rng.random() < 0.3:
        args += ['--x0', repr(rng.uniform(-1, 1) * b / (m * w * w))]
    return args, 2 * 3.141592653589793 / w * rng.uniform(2, 6)


def run(binary, directory, command):
    out = os.path.join(directory, 'out.csv')
    if os.path.exists(out):
        os.remove(out)
    p = subprocess.run([binary] + command + ['-o', 'out.csv'], capture_output=True, text=True,
                       cwd=directory)
    text = open(out).read() if os.path.exists(out) else None
    return p.returncode, p.stderr, text


def main():
    old, new = os.path.abspath(sys.argv[1]), os.path.abspath(sys.argv[2])
    n = int(sys.argv[3]) if len(sys.argv) > 3 else 200
    rng = random.Random(int(sys.argv[4]) if len(sys.argv) > 4 else 1)
    runs = refused = differ = 0
    with tempfile.TemporaryDirectory() as a, tempfile.TemporaryDirectory() as b:
        # The same directory name for both, so that `# command:` lines match.
        da, db = os.path.join(a, 'run'), os.path.join(b, 'run')
        os.mkdir(da)
        os.mkdir(db)
        for _ in range(n):
            args, t_end = random_model(rng)
            for command in (['curve', '--dt', repr(t_end / 997), '--include-events'], ['events']):
                full = command + args + ['--t-end', repr(t_end)]
                first, second = run(old, da, full), run(new, db, full)
                runs += 1
                refused += first[0] != 0
                if first != second:
                    differ += 1
                    print('differs: frictionref ' + ' '.join(full), flush=True)
    print('%d runs (%d of them refused as input by OLD_BINARY), %d differ' % (runs, refused, differ))
    return 1 if differ else 0


if __name__ == '__main__':
    sys.exit(main())
