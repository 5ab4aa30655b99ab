#!/usr/bin/env python3
"""Literal expected values of tests/test_sweep.cpp and tests/test_steady_state.cpp.

Computed here, with mpmath at 50 significant digits, from the closed forms of
docs/theory.md, independently of the C++ code (which computes them in double
and long double, by other formulas or by simulation). Each lambda is the
exact binary value of the double the tests pass (mpf(float) is exact).

    python3 tests/steady_state_values.py        # mpmath 1.3.0

Seed's model, m = B = w = 1 (theory.md 5):
  lambda* = 2 / sqrt(4 + pi^2);
  continuous (lambda < lambda*): tau1 = acos(lambda pi / 2), slide per period
    4 sin(tau1), stuck fraction 0;
  dead bands (lambda* <= lambda < 1): alpha = asin(lambda), stop tau_s = the
    root of f(t) = cos(alpha) - cos(t) - lambda (t - alpha) in
    [pi - alpha, pi + alpha] (bisection to 2^-170), stuck fraction
    1 - (tau_s - alpha) / pi, slide per period 2 D with
    D = cos(alpha) (tau_s - alpha) - (sin(tau_s) - lambda) - lambda (tau_s - alpha)^2 / 2,
    checked against mpmath.quad of f;
  stops (lambda >= 1): stuck fraction 1, slide 0.

Den Hartog's non-stop solution for k > 0, c = 0 (theory.md 8.2) at
beta = w / sqrt(k/m) = 2: nu = 1/2, U = nu tan(nu pi / 2) = 1/2,
V = 1 / (1 - beta^2) = -1/3, X = sqrt(V^2 - r^2 U^2) (in B/k). It exists for
r < |V / U| = 2/3 and the mass leaves at once at each reversal iff
beta^2 X > S r (Rs = S R): 16 (1/9 - r^2 / 4) > S^2 r^2, i.e.
r < (4/3) / sqrt(4 + S^2): 4 / (3 sqrt 5) for S = 1, 8/15 for S = 1.5.
"""
import mpmath as mp

mp.mp.dps = 50


def regime(lam):
    star = 2 / mp.sqrt(4 + mp.pi ** 2)
    return "continuous" if lam < star else "dead_bands" if lam < 1 else "stops"


def seed_steady(lam):
    """(regime, stuck fraction, slide per period) for m = B = w = 1."""
    r = regime(lam)
    if r == "continuous":
        tau1 = mp.acos(lam * mp.pi / 2)
        return r, mp.mpf(0), 4 * mp.sin(tau1)
    if r == "stops":
        return r, mp.mpf(1), mp.mpf(0)
    a = mp.asin(lam)
    f = lambda t: mp.cos(a) - mp.cos(t) - lam * (t - a)
    lo, hi = mp.pi - a, mp.pi + a  # f(lo) > 0 >= f(hi)
    for _ in range(400):
        mid = (lo + hi) / 2
        if f(mid) > 0:
            lo = mid
        else:
            hi = mid
    ts = (lo + hi) / 2
    d = mp.cos(a) * (ts - a) - (mp.sin(ts) - lam) - lam * (ts - a) ** 2 / 2
    assert abs(d - mp.quad(f, [a, ts])) < mp.mpf(10) ** -40
    return r, 1 - (ts - a) / mp.pi, 2 * d


def main():
    star = 2 / mp.sqrt(4 + mp.pi ** 2)
    print("lambda* =", mp.nstr(star, 30))
    print("4.1104 = (4 + pi^2)^(3/2) / (4 pi) =", mp.nstr((4 + mp.pi ** 2) ** 1.5 / (4 * mp.pi), 20))
    print()
    print("// test_sweep.cpp, kSeedTable: {lambda, regime, stuck fraction, slide per period}")
    for lam in [0.1, 0.2, 0.3, 0.4, 0.5, 0.53, 0.536, 0.5365, 0.54, 0.55, 0.6, 0.65, 0.7,
                0.7246, 0.75, 0.8, 0.9, 0.95, 0.99, 1.0, 1.01, 1.2]:
        r, stuck, slide = seed_steady(mp.mpf(lam))
        print("    {%r, Regime::%s, %sL, %sL}," % (lam, r, mp.nstr(stuck, 25, min_fixed=-5),
                                                 mp.nstr(slide, 25, min_fixed=-5)))
    print()
    # m = 2, B = 3, w = 0.5, R = fl(0.7 * 3): phases as for lambda = R / B
    # (exact ratio of the doubles), lengths times B / (m w^2) = 6.
    R = mp.mpf(0.7 * 3)
    r, stuck, slide = seed_steady(R / 3)
    print("units m=2 B=3 w=0.5 R=%r: stuck %s slide %s" % (0.7 * 3, mp.nstr(stuck, 25),
                                                          mp.nstr(6 * slide, 25)))
    print()
    for s in [1, 1.5]:
        print("Den Hartog boundary at beta = 2, S = %s: %s" % (s, mp.nstr(
            mp.mpf(4) / 3 / mp.sqrt(4 + mp.mpf(s) ** 2), 25)))
    print()
    # test_steady_state.cpp: the fuzz finding m = 1792, B = 65540,
    # R = 35196.89849646949: the reported lambda is the double R / B.
    lam = 35196.89849646949 / 65540
    print("fuzz lambda = %r: lambda - lambda* = %s, regime %s" % (
        lam, mp.nstr(mp.mpf(lam) - star, 5), regime(mp.mpf(lam))))
    print("exact R/B - lambda* = %s" % mp.nstr(mp.mpf(35196.89849646949) / 65540 - star, 5))


if __name__ == "__main__":
    main()
