"""scipy.integrate.solve_ivp peer (tests/peers/README.md).

The mass with Coulomb friction under sin t (m = B = w = 1), integrated phase by phase
with solve_ivp and terminal event functions, switching between stick and slip:

  slip, direction s: y = (x, v), x' = v, v' = sin t - s lambda;
                     terminal event s v = 0, direction -1 (v reaching 0 from the slip side)
  stick:             y' = 0; terminal event |sin t| - lambda = 0, direction +1

At v = 0: |sin t| <= lambda -> stick (a stop); else slip in the direction of the force
(a reversal if that is the other way, a "touch" if it is the same way). At the end of a
stick: slip in the direction of the force (a breakaway). The slip starts from the first
double past the crossing |sin t| = lambda: scipy's root may be a rounding short of it,
and then the slip can stop at once and the stop/breakaway pair repeats for ever at the
same t (CVODE puts its roots past the crossing by itself). The breakaway time reported is
scipy's root. Each phase is a new solve_ivp
call from the event state, with v set to 0 exactly. During a stick the step is capped at
0.5 (max_step): the right-hand side is zero, so the error control would let the step grow
past a whole window |sin t| > lambda (1.59 wide at lambda = 0.7) and the event would be
missed. Implicit methods (Radau, LSODA) get the analytic Jacobian.

The general model (docs/theory.md section 7; the cases of peer_common.GENERAL_CASES) is
integrated the same way with the model's own rules, N = F0 + sin t - k x:

  slip, direction s: x' = v, v' = F0 + sin t - c v - k x - s R; terminal event s v = 0
  stick:             y' = 0; terminal event |N| - Rs = 0, direction +1
  at v = 0:          |N| <= Rs -> stick (a stop); else slip in the direction of N

and a breakaway slips in the direction of N, from the first double past |N| = Rs. The
seed's cases keep the code above (the same numbers, the same cost).

A slip from rest whose v = 0 event fires at its own start time (the first step was below
the resolution of t, so v never left 0) is retried once with first_step = 1e-4. A run
that produces 10 events in a row at the same t stops and reports it (a Zeno loop).

Counted: nfev (right-hand side), njev, nlu (summed over all solve_ivp calls), the
event-function evaluations, the slip starts moved past the crossing ("nudges") and
the retried slips ("retries"), and the largest step taken in a slip. A run stops at its deadline (wall clock) and says how far
it got.

Usage: /usr/bin/python3 scipy_peer.py --out DIR [--cases 10.1,10.2,...,spring-damper,...]
       [--methods RK45,...] [--tols loose,tight] [--deadline-1000p S] [--min-time S]
Writes DIR/scipy-<method>-<tol>-<case>.json.
"""

import argparse
import math
import os
import sys
import time
import warnings

import numpy as np
import scipy
from scipy.integrate import solve_ivp

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import peer_common  # noqa: E402

TOLERANCES = {
    "loose": (1e-6, 1e-9),
    "tight": (1e-12, 1e-14),
}
METHODS = ["RK45", "DOP853", "Radau", "LSODA"]
IMPLICIT = {"Radau", "LSODA", "BDF"}


def sign_of(value):
    return 1 if value > 0 else -1 if value < 0 else 0


def run(lam, v0, t_end, method, rtol, atol, deadline, general=None):
    """One run. general: None for the seed's model, else a dict with the general model's
    static (Rs), stiffness (k), damping (c) and force_offset (F0); lam is R."""
    start = time.perf_counter()
    if general is None:
        rs = lam

        def net(tt, xx):  # the force that decides at rest
            return math.sin(tt)
    else:
        rs, k, c, f0 = (float(general["static"]), float(general["stiffness"]),
                        float(general["damping"]), float(general["force_offset"]))

        def net(tt, xx):  # N = F(t) - k x
            return f0 + math.sin(tt) - k * xx
    counts = {"nfev": 0, "njev": 0, "nlu": 0, "gev": 0, "calls": 0, "nudges": 0,
              "retries": 0, "max_slip_step": 0.0}
    events = []
    t, x, v = 0.0, 0.0, float(v0)
    sign = sign_of(v) if v != 0 else (0 if abs(net(t, x)) <= rs else sign_of(net(t, x)))
    zero2 = np.zeros(2)
    if general is None:
        jac_slip = np.array([[0.0, 1.0], [0.0, 0.0]])
    else:
        jac_slip = np.array([[0.0, 1.0], [-k, -c]])
    jac_stick = np.zeros((2, 2))
    failure = ""
    finished = False
    stuck = 0
    while True:
        if sign == 0:
            def fun(tt, y):
                return zero2

            if general is None:
                def event(tt, y):
                    counts["gev"] += 1
                    return abs(math.sin(tt)) - lam
            else:
                def event(tt, y):  # y[0] stays x during the stick
                    counts["gev"] += 1
                    return abs(f0 + math.sin(tt) - k * y[0]) - rs

            event.terminal = True
            event.direction = 1
            options = {"max_step": 0.5}
            jac = jac_stick
            y0 = [x, 0.0]
        else:
            s = sign

            if general is None:
                def fun(tt, y, s=s):
                    return np.array([y[1], math.sin(tt) - s * lam])
            else:
                def fun(tt, y, s=s):
                    return np.array([y[1], f0 + math.sin(tt) - c * y[1] - k * y[0] - s * lam])

            def event(tt, y, s=s):
                counts["gev"] += 1
                return s * y[1]

            event.terminal = True
            event.direction = -1
            options = {}
            jac = jac_slip
            y0 = [x, v]
        if method in IMPLICIT:  # a callable: scipy's LSODA wrapper rejects a matrix here
            options["jac"] = lambda tt, y, jac=jac: jac
        for attempt in (0, 1):
            try:
                sol = solve_ivp(fun, (t, t_end), y0, method=method, rtol=rtol, atol=atol,
                                events=event, **options)
            except Exception as error:  # scipy's own event handling can raise
                sol = None
                failure = "solve_ivp raised %s (%s) in a %s phase from t = %.17g" % (
                    type(error).__name__, error, "stick" if sign == 0 else "slip", t)
                break
            counts["calls"] += 1
            counts["nfev"] += int(sol.nfev)
            counts["njev"] += int(sol.njev)
            counts["nlu"] += int(sol.nlu)
            # A slip from rest whose v = 0 event fires at its own start: the solver's first
            # step was below the resolution of t (the initial-step heuristic sees a zero
            # right-hand side; LSODA, loose, 1000-period case), so v never left 0. Retry
            # once with an explicit first step.
            if (sign != 0 and attempt == 0 and sol.status == 1
                    and float(sol.t_events[0][0]) <= t):
                options["first_step"] = 1e-4
                counts["retries"] += 1
                continue
            break
        if sol is None:
            break
        if sign != 0 and len(sol.t) > 1:
            counts["max_slip_step"] = max(counts["max_slip_step"], float(np.max(np.diff(sol.t))))
        if sol.status == -1:
            failure = "solve_ivp failed at t = %.6g: %s" % (sol.t[-1], sol.message)
            t = float(sol.t[-1])
            break
        if sol.status == 0:  # reached t_end
            t = float(sol.t[-1])
            finished = True
            break
        te = float(sol.t_events[0][0])
        te_root = te  # the event time reported: scipy's own root
        ye = sol.y_events[0][0]
        if sign == 0:
            # scipy's root (brentq) may land on either side of |sin t| = lambda. On the
            # near side the slip would start with the force a rounding below friction, and
            # its v = 0 event could fire at once: stop, stick, the same breakaway again, for
            # ever (seen with LSODA, loose, on the 1000-period case). Start the slip from
            # the first double past the crossing, which is where CVODE puts its roots (the
            # event time reported stays scipy's root).
            while abs(net(te, float(ye[0]))) - rs <= 0 and counts["nudges"] < 10**6:
                te = math.nextafter(te, math.inf)
                counts["nudges"] += 1
        force = net(te, float(ye[0]))
        if sign != 0:
            if abs(force) <= rs:
                kind, sign = "stop", 0
            elif sign_of(force) != sign:
                kind, sign = "reversal", sign_of(force)
            else:
                kind = "touch"
        else:
            kind, sign = "breakaway", sign_of(force)
        events.append((kind, te_root))
        stuck = stuck + 1 if te <= t else 0
        t, x, v = te, float(ye[0]), 0.0
        if stuck >= 10:
            failure = "stuck: 10 events in a row at t = %.17g (%s)" % (t, kind)
            break
        if time.perf_counter() - start > deadline:
            failure = "deadline"
            break
    return {"events": events, "counts": counts, "t_reached": t, "finished": finished,
            "failure": failure}


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--out", required=True)
    parser.add_argument("--cases", default=",".join(peer_common.ALL_CASE_IDS),
                        help="case ids of peer_common.CASES and GENERAL_CASES")
    parser.add_argument("--methods", default=",".join(METHODS))
    parser.add_argument("--tols", default="loose,tight")
    parser.add_argument("--deadline", type=float, default=60.0,
                        help="wall-clock limit of one run on a 30-unit case [s]")
    parser.add_argument("--deadline-1000p", type=float, default=60.0,
                        help="wall-clock limit of one run on the 1000-period case [s]")
    parser.add_argument("--min-time", type=float, default=0.2)
    args = parser.parse_args()
    warnings.simplefilter("ignore")
    os.makedirs(args.out, exist_ok=True)
    for case_id in args.cases.split(","):
        params = peer_common.case_params(case_id)
        cid, lam, v0, t_end = params["id"], params["lambda"], params["v0"], params["t_end"]
        general = params if params["general"] else None
        deadline = args.deadline_1000p if cid == "1000p" else args.deadline
        for method in args.methods.split(","):
            for tol in args.tols.split(","):
                rtol, atol = TOLERANCES[tol]
                times = []
                while True:
                    t0 = time.perf_counter()
                    result = run(lam, v0, t_end, method, rtol, atol, deadline, general)
                    times.append(time.perf_counter() - t0)
                    # Repeat short runs (median of >= 3, >= min_time in all); a run that
                    # alone takes over 1 s is not repeated.
                    if (not result["finished"] or times[0] > 1.0
                            or (sum(times) >= args.min_time and len(times) >= 3)):
                        break
                record = {
                    "peer": "scipy", "method": method, "tol": tol, "rtol": rtol, "atol": atol,
                    "scipy": scipy.__version__, "case": cid, "lambda": lam, "v0": v0,
                    "t_end": t_end, "time_s": float(np.median(times)), "reps": len(times),
                    "deadline_s": deadline,
                }
                if general is not None:
                    record.update({key: params[key] for key in
                                   ("static", "stiffness", "damping", "force_offset")})
                record.update(result["counts"])
                record.update({k: result[k] for k in ("t_reached", "finished", "failure")})
                record["events"] = result["events"]
                name = "scipy-%s-%s-%s.json" % (method, tol, cid)
                peer_common.write_json(os.path.join(args.out, name), record)
                print("%-7s %-5s %-6s %8.3f s  nfev %8d  events %5d  %s" % (
                    method, tol, cid, record["time_s"], record["nfev"], len(result["events"]),
                    "finished" if result["finished"] else "STOPPED: " + result["failure"]),
                    flush=True)


if __name__ == "__main__":
    main()
