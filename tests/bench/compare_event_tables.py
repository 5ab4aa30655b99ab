#!/usr/bin/env python3
"""Phase tables of two frictionref binaries on the same random general models.

For a change to the engine that should move results by rounding only (the
general engine's predictions, docs/theory.md 7.4): both binaries run
`frictionref events` on N random models (static friction, spring, damper, a
second harmonic, force offset, frequency), and the tables are compared. The
phase kinds must agree row by row; values are compared relative to their
column's largest value in the table.

    python3 tests/bench/compare_event_tables.py OLD_BINARY NEW_BINARY [SEED] [N]

(OLD_BINARY built from an earlier commit in a git worktree, e.g.
`git worktree add /tmp/wt REV && cmake -S /tmp/wt -B /tmp/wt/build
-DCMAKE_BUILD_TYPE=Release && cmake --build /tmp/wt/build --target frictionref_cli`.)
Exit status 1 if any model differs in exit status, number of phases or kinds.
"""
import random
import subprocess
import sys


def run(binary, args):
    p = subprocess.run([binary, 'events'] + args, capture_output=True, text=True)
    return p.returncode, p.stdout


def random_model(rng):
    lam = rng.uniform(0, 1.2)
    ls = lam * rng.choice([1, 1, rng.uniform(1, 1.6)])
    args = ['--lambda', repr(lam), '--static-lambda', repr(ls),
            '--t-end', repr(rng.uniform(20, 400))]
    if rng.random() < 0.7:
        args += ['--stiffness', repr(rng.choice([0, rng.uniform(0, 4)]))]
    if rng.random() < 0.6:
        args += ['--damping', repr(rng.choice([0, rng.uniform(0, 0.5), rng.uniform(0, 5)]))]
    if rng.random() < 0.4:
        args += ['--harmonic', '%r,%r,%r' % (rng.uniform(0, 1), rng.uniform(0.2, 4),
                                             rng.uniform(-3, 3))]
    if rng.random() < 0.3:
        args += ['--force-offset', repr(rng.uniform(-0.5, 0.5))]
    if rng.random() < 0.3:
        args += ['--omega', repr(rng.uniform(0.3, 3))]
    return args


def rows(text):
    lines = [l for l in text.splitlines() if not l.startswith('#')]
    return [l.split(',') for l in lines[1:]]


def main():
    old, new = sys.argv[1], sys.argv[2]
    seed = int(sys.argv[3]) if len(sys.argv) > 3 else 1
    n = int(sys.argv[4]) if len(sys.argv) > 4 else 300
    rng = random.Random(seed)
    identical = differing = structural = 0
    worst, worst_model = 0.0, None
    for _ in range(n):
        args = random_model(rng)
        (status_old, out_old), (status_new, out_new) = run(old, args), run(new, args)
        if status_old != status_new:
            structural += 1
            print('exit status', status_old, status_new, ' '.join(args))
            continue
        if out_old == out_new:
            identical += 1
            continue
        differing += 1
        a, b = rows(out_old), rows(out_new)
        if len(a) != len(b) or any(x[0] != y[0] for x, y in zip(a, b)):
            structural += 1
            print('phases differ', len(a), len(b), ' '.join(args))
            continue
        for c in range(1, len(a[0])):
            scale = max(abs(float(r[c])) for r in a) or 1e-300
            for x, y in zip(a, b):
                d = abs(float(x[c]) - float(y[c])) / scale
                if d > worst:
                    worst, worst_model = d, args
    print(f'{n} models: {identical} tables identical, {differing} differing in values, '
          f'{structural} in exit status, phase count or kinds; largest difference '
          f'{worst:.3g} of its column\'s largest value'
          + (f' ({" ".join(worst_model)})' if worst_model else ''))
    return 1 if structural else 0


if __name__ == '__main__':
    sys.exit(main())
