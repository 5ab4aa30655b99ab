#!/usr/bin/python3
"""Write candidate time histories the way third-party friction codes write them.

These files feed `frictionref compare` in tests/cli/test_compare_candidates.cpp. They
are produced by an integrator written here from scratch (event-driven RK4 with
bisection), deliberately NOT by frictionref: a candidate computed by the code it is
checked against would prove nothing.

Model (the "seed" problem): m x'' = B sin(w t) - f, Coulomb friction R = lambda B,
static friction equal to sliding friction, x0 = v0 = 0, t0 = 0, recorded on [0, 30].

Run from the repository root (rewrites the files next to this script, deterministic):

    /usr/bin/python3 tests/data/candidates/make_candidates.py
"""
import math
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
M, B, W = 1.0, 1.0, 1.0
T_END = 30.0
SLIP_STEP = 1e-3        # RK4 step during slips
STICK_STEP = 1e-3       # scan step for breakaways while stuck
EVENT_TOL = 1e-13       # bisection width for stops and breakaways


def force(t):
    return B * math.sin(W * t)


def rk4_slip(t, x, v, h, s, friction):
    """One RK4 step of x' = v, m v' = F(t) - s R (sign of the slip frozen)."""
    def acc(tt):
        return (force(tt) - s * friction) / M
    a1 = acc(t)
    a2 = acc(t + 0.5 * h)
    a4 = acc(t + h)
    # The right-hand side does not depend on v, so k2 == k3 for v; x still needs all four.
    v1, v2, v3 = v, v + 0.5 * h * a1, v + 0.5 * h * a2
    v4 = v + h * a2
    x_new = x + h / 6.0 * (v1 + 2 * v2 + 2 * v3 + v4)
    v_new = v + h / 6.0 * (a1 + 4 * a2 + a4)
    return x_new, v_new


def accurate_breakaway(friction):
    """Breakaway finder of a careful code: scan in small steps, bisect |F| - R to ~1e-13.

    A grazing excursion of |F| above R shorter than STICK_STEP would be missed; the
    models here (lambda = 0.7, and 1.01 where |F| never exceeds R) have none.
    """
    def excess(t):
        return abs(force(t)) - friction

    def find(t_start, t_end):
        if excess(t_start) > 0:
            return t_start
        k = 0
        while True:
            a = t_start + k * STICK_STEP
            if a >= t_end:
                return None
            b = min(t_start + (k + 1) * STICK_STEP, t_end)
            if excess(b) > 0:
                while b - a > EVENT_TOL:
                    mid = 0.5 * (a + b)
                    a, b = (a, mid) if excess(mid) > 0 else (mid, b)
                # The upper end has |F| > R, so the slip starts accelerating away from rest.
                return b
            k += 1
    return find


def archive_only_breakaway(friction, archive_times):
    """Breakaway finder of a code that tests for breakaway only at its archive times
    (like CVODE with no maximum step while the mass rests: it jumps archive to archive)."""
    def find(t_start, t_end):
        for ta in archive_times:
            if t_start <= ta <= t_end and abs(force(ta)) > friction:
                return ta
        return None
    return find


def simulate(friction, out_times, find_breakaway, t_end=T_END):
    """Event-driven stick-slip run from rest at t = 0.

    Returns (x, v) at the sorted out_times (dense output: a partial RK4 step from the
    last step state, so the outputs never perturb the trajectory) and the event list
    [(kind, t, x, slip sign after the event)].
    """
    out = np.zeros((len(out_times), 2))
    i_out = 0
    events = []
    t, x, v = 0.0, 0.0, 0.0
    while t < t_end:
        # --- stuck at x until the next breakaway
        t_b = find_breakaway(t, t_end)
        t_next = t_end if t_b is None else t_b
        while i_out < len(out_times) and out_times[i_out] <= t_next:
            out[i_out] = (x, 0.0)
            i_out += 1
        if t_b is None:
            break
        t = t_b
        s = 1.0 if force(t) > 0 else -1.0
        events.append(("breakaway", t, x, s))
        # --- slipping with sign s until the velocity reaches zero (then stick or reverse)
        while t < t_end:
            h = min(SLIP_STEP, t_end - t)
            x1, v1 = rk4_slip(t, x, v, h, s, friction)
            if s * v1 > 0:
                while i_out < len(out_times) and out_times[i_out] <= t + h:
                    tau = out_times[i_out] - t
                    out[i_out] = rk4_slip(t, x, v, tau, s, friction)
                    i_out += 1
                t, x, v = t + h, x1, v1
                continue
            # The stop lies inside this step: bisect the RK4 sub-step length.
            lo, hi = 0.0, h
            while hi - lo > EVENT_TOL:
                mid = 0.5 * (lo + hi)
                if s * rk4_slip(t, x, v, mid, s, friction)[1] > 0:
                    lo = mid
                else:
                    hi = mid
            t_stop = t + hi
            while i_out < len(out_times) and out_times[i_out] < t_stop:
                out[i_out] = rk4_slip(t, x, v, out_times[i_out] - t, s, friction)
                i_out += 1
            x = rk4_slip(t, x, v, hi, s, friction)[0]
            t, v = t_stop, 0.0
            if abs(force(t)) > friction:   # static friction cannot hold it: reverse
                s = 1.0 if force(t) > 0 else -1.0
                events.append(("reversal", t, x, s))
                continue
            events.append(("stop", t, x, 0.0))
            break
    while i_out < len(out_times):   # a slip that ran to t_end
        out[i_out] = (x, v)
        i_out += 1
    return out, events


def closed_form_slip(t, t_s, x_s, s, friction):
    """Exact slip from rest at t_s with sign s (seed model: every slip starts at rest)."""
    dt = t - t_s
    c = B / (M * W)
    v = c * (math.cos(W * t_s) - math.cos(W * t)) - s * friction * dt / M
    x = (x_s + c * math.cos(W * t_s) * dt - c / W * (math.sin(W * t) - math.sin(W * t_s))
         - 0.5 * s * friction * dt * dt / M)
    return x, v


def slips_of(events):
    """(t_start, x_start, sign, t_end) of every slip, from the event list."""
    slips = []
    for i, (kind, t_s, x_s, s) in enumerate(events):
        if kind in ("breakaway", "reversal"):
            t_e = events[i + 1][1] if i + 1 < len(events) else T_END
            slips.append((t_s, x_s, s, t_e))
    return slips


def self_check(friction, times, states, events):
    """Fail loudly unless the integrator matches the closed forms to < 1e-8.

    Every sample inside a slip is compared with the closed form from that slip's start;
    every breakaway must satisfy |F| = R and every stop v_closed = 0; samples outside
    the slips must be at rest.
    """
    worst = 0.0
    slips = slips_of(events)
    for kind, t_e, _, _ in events:
        if kind == "breakaway":
            worst = max(worst, abs(abs(force(t_e)) - friction))
    for t_s, x_s, s, t_e in slips:
        if t_e < T_END:
            worst = max(worst, abs(closed_form_slip(t_e, t_s, x_s, s, friction)[1]))
    for t, (x, v) in zip(times, states):
        slip = [sl for sl in slips if sl[0] < t <= sl[3]]
        if slip:
            xc, vc = closed_form_slip(t, *slip[0][:3], friction)
            worst = max(worst, abs(x - xc), abs(v - vc))
        else:
            assert v == 0.0, f"moving at t = {t} outside every slip"
    assert any(e[0] == "stop" for e in events), "lambda = 0.7 must have sticks"
    assert worst < 1e-8, f"integrator self-check failed: max error {worst:g}"
    return worst


def tanh_run(friction, eps, out_step=0.02, h=1e-4):
    """Regularised friction m v' = F - R tanh(v/eps), plain RK4 with a fixed step.

    The friction slope R/(m eps) ~ 1e3 needs h < 2.78 m eps / R for RK4 stability;
    h = 1e-4 is well inside. Returns t, v at every out_step and the max |v| reached.
    """
    def acc(t, v):
        return (force(t) - friction * math.tanh(v / eps)) / M
    n_sub = int(round(out_step / h))
    n_out = int(round(T_END / out_step))
    t_out, v_out = [0.0], [0.0]
    v, vmax = 0.0, 0.0
    for k in range(n_out):
        t0 = k * out_step
        for j in range(n_sub):
            t = t0 + j * h
            k1 = acc(t, v)
            k2 = acc(t + 0.5 * h, v + 0.5 * h * k1)
            k3 = acc(t + 0.5 * h, v + 0.5 * h * k2)
            k4 = acc(t + h, v + h * k3)
            v += h / 6.0 * (k1 + 2 * k2 + 2 * k3 + k4)
            vmax = max(vmax, abs(v))
        t_out.append(round((k + 1) * out_step, 12))
        v_out.append(v)
    return np.array(t_out), np.array(v_out), vmax


def fmt(value):
    # + 0.0 turns -0.0 into 0.0 so a resting mass never prints as "-0".
    return "%.10g" % (value + 0.0)


def write_rows(name, header_lines, rows, sep=",", decimal_comma=False):
    lines = list(header_lines)
    for row in rows:
        cells = [fmt(c) for c in row]
        if decimal_comma:
            cells = [c.replace(".", ",") for c in cells]
        lines.append(sep.join(cells))
    (HERE / name).write_text("\n".join(lines) + "\n")
    return len(rows)


def main():
    lam = 0.7
    friction = lam * B
    summary = []

    # The accurate run on the 0.02 grid; k / 50 is the double nearest to the printed time.
    t_grid = np.arange(1501) / 50.0
    states, events = simulate(friction, t_grid, accurate_breakaway(friction))
    err = self_check(friction, t_grid, states, events)
    print(f"self-check: max |integrator - closed form| = {err:.3g} "
          f"over {len(events)} events (< 1e-8 required)")
    rows = [(t, x, v) for t, (x, v) in zip(t_grid, states)]

    summary.append(("accurate.csv", write_rows("accurate.csv", ["t,x,v"], rows),
                    "independent RK4 stick-slip run, lambda 0.7: PASS"))
    summary.append(("shape_semicolon_decimal_comma.csv",
                    write_rows("shape_semicolon_decimal_comma.csv", ["t;x;v"], rows,
                               sep=";", decimal_comma=True),
                    "same run, ';' and decimal commas"))
    summary.append(("shape_unit_suffixes.csv",
                    write_rows("shape_unit_suffixes.csv", ["time_s,x_m,v_mps"], rows),
                    "same run, header with unit suffixes"))
    summary.append(("shape_title_lines.csv",
                    write_rows("shape_title_lines.csv",
                               ["FRICTION MODEL RUN 42", "generated by make_candidates.py",
                                "t,x,v"], rows),
                    "same run, two title lines before the header"))
    # A restart from a checkpoint at t = 15 writes 15..20 again (same values).
    overlap = rows[:1001] + rows[750:]
    summary.append(("shape_restart_overlap.csv",
                    write_rows("shape_restart_overlap.csv", ["t,x,v"], overlap),
                    "same run, 0..20 then restart 15..30: needs --on-overlap keep-last"))

    # Late by 0.03: the candidate at t shows the accurate state at t - 0.03.
    t_shift = (5 + np.arange(1496)) / 50.0
    shifted, _ = simulate(friction, t_shift - 0.03, accurate_breakaway(friction))
    summary.append(("shifted.csv",
                    write_rows("shifted.csv", ["t,v"],
                               [(t, v) for t, (_, v) in zip(t_shift, shifted)]),
                    "accurate run late by +0.03: FAIL, time_shift"))

    # Regularised friction above the force amplitude: the exact mass never moves.
    t_tanh, v_tanh, vmax = tanh_run(1.01 * B, 1e-3)
    summary.append(("tanh.csv", write_rows("tanh.csv", ["t,v"], list(zip(t_tanh, v_tanh))),
                    f"tanh friction eps 1e-3, lambda 1.01, max |v| {vmax:.4g}: FAIL, creep"))

    # Breakaway tested only at the archive times 0, 5, ..., 30.
    archive = [5.0 * k for k in range(7)]
    arch_states, arch_events = simulate(friction, archive,
                                        archive_only_breakaway(friction, archive))
    coarse = {t: v for t, (_, v) in zip(archive, arch_states)}
    for kind, t, _, _ in arch_events:
        coarse.setdefault(t, 0.0)   # every event is at rest (v = 0)
    summary.append(("coarse_missed_breakaways.csv",
                    write_rows("coarse_missed_breakaways.csv", ["t,v"],
                               sorted(coarse.items())),
                    f"breakaway tested at archive times only ({len(arch_events)} events)"
                    ": not PASS"))

    print(f"\n{'file':36s} {'rows':>5s}  what it is")
    for name, n, what in summary:
        print(f"{name:36s} {n:5d}  {what}")


if __name__ == "__main__":
    main()
