"""Independent reference values for the seed's model m x'' = B sin(w t) -+ R,
with m = B = w = 1, from the closed forms of docs/theory.md (3 and 5),
computed with mpmath at 50 digits. Nothing here calls frictionref.

A forward slip from rest at tb (v = 0, a = sin t - lam):
    v(t) = cos(tb) - cos(t) - lam (t - tb)
    x(t) = x(tb) + cos(tb) (t - tb) - (sin t - sin tb) - lam (t - tb)^2 / 2
and a backward one is its mirror image half a period later. From rest at
x = 0, t = 0 with lam* <= lam < 1 the motion is periodic from the first
breakaway at asin(lam) (theory.md 5.6): forward slide to the stop ts (the
zero of v in [pi - a, pi + a]), rest until pi + a, backward slide to ts + pi,
rest until 2 pi + a, and so on.
"""
import functools

import mpmath as mp

mp.mp.dps = 50

LAMBDA_STAR = 2 / mp.sqrt(4 + mp.pi ** 2)


def stop_time(lam):
    """The stop of the forward slip from rest at asin(lam), by bisection."""
    a = mp.asin(lam)
    lo, hi = mp.pi - a, mp.pi + a  # v(lo) > 0 >= v(hi)
    for _ in range(400):
        mid = (lo + hi) / 2
        if mp.cos(a) - mp.cos(mid) - lam * (mid - a) > 0:
            lo = mid
        else:
            hi = mid
    return (lo + hi) / 2


@functools.lru_cache(maxsize=None)  # 400 bisection steps at 50 digits: once per lambda
def dead_band_motion(lam):
    """(breakaway a, stop ts, slide D) of the periodic dead-band motion."""
    lam = mp.mpf(lam)
    a = mp.asin(lam)
    ts = stop_time(lam)
    slide = mp.cos(a) * (ts - a) - (mp.sin(ts) - mp.sin(a)) - lam * (ts - a) ** 2 / 2
    return a, ts, slide


def dead_band_phases(lam, t_end):
    """The exact phase table from rest at 0 up to t_end: (kind, t0, t1, x0, x1)."""
    a, ts, d = dead_band_motion(lam)
    phases = [("stick", mp.mpf(0), a, mp.mpf(0), mp.mpf(0))]
    k = 0
    while True:
        shift = k * mp.pi
        forward = k % 2 == 0
        x_begin = mp.mpf(0) if forward else d
        x_end = d if forward else mp.mpf(0)
        phases.append(("slip+" if forward else "slip-", a + shift, ts + shift, x_begin, x_end))
        phases.append(("stick", ts + shift, a + shift + mp.pi, x_end, x_end))
        if a + shift + mp.pi >= t_end:
            break
        k += 1
    table = []
    for kind, t0, t1, x0, x1 in phases:
        if t0 >= t_end:
            break
        table.append((kind, t0, min(t1, mp.mpf(t_end)), x0, x1))
    return table


def dead_band_state(lam, t):
    """(x, v, phase) of the same motion at time t."""
    t = mp.mpf(t)
    lam = mp.mpf(lam)
    for kind, t0, t1, x0, x1 in dead_band_phases(lam, t + 10):
        if t0 <= t < t1:
            if kind == "stick":
                return x0, mp.mpf(0), kind
            sign = 1 if kind == "slip+" else -1
            tb = t0 - (0 if sign > 0 else mp.pi)  # the forward slip it mirrors
            s = t - t0
            v = mp.cos(tb) - mp.cos(tb + s) - lam * s
            x = mp.cos(tb) * s - (mp.sin(tb + s) - mp.sin(tb)) - lam * s ** 2 / 2
            return x0 + sign * x, sign * v, kind
    raise AssertionError("t beyond the table")


def case_10_3(t):
    """lam = 1.01 from v0 = -1: one backward slide (v = R t - cos t,
    x = R t^2 / 2 - sin t) to the stop where cos t = R t, then rest."""
    r = mp.mpf("1.01")
    stop = case_10_3_stop()
    t = mp.mpf(t)
    if t < stop:
        return r * t ** 2 / 2 - mp.sin(t), r * t - mp.cos(t), "slip-"
    return r * stop ** 2 / 2 - mp.sin(stop), mp.mpf(0), "stick"


@functools.lru_cache(maxsize=None)
def case_10_3_stop():
    r = mp.mpf("1.01")
    return mp.findroot(lambda s: mp.cos(s) - r * s, 0.73)


def steady_state(lam):
    """(regime, stuck fraction, slide per period) of the seed's steady state."""
    lam = mp.mpf(lam)
    if lam < LAMBDA_STAR:
        tau1 = mp.acos(lam * mp.pi / 2)
        return "continuous", mp.mpf(0), 4 * mp.sin(tau1)
    if lam >= 1:
        return "stops", mp.mpf(1), mp.mpf(0)
    a, ts, d = dead_band_motion(lam)
    return "dead-bands", 1 - (ts - a) / mp.pi, 2 * d


def close(value, reference, ulps=4, scale=1.0):
    """|value - reference| within `ulps` units in the last place of
    max(|reference|, scale) (an absolute floor near zero)."""
    reference = float(reference)
    size = max(abs(reference), scale)
    return abs(value - reference) <= ulps * size * 2.0 ** -52
