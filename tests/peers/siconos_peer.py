"""Siconos peer (tests/peers/README.md): Debian python3-siconos (Siconos 4.4).

Time stepping (Moreau-Jean type). The 1-DOF problem as a first-order linear system with a
relay:

  state x = (position, velocity), x' = A x + b(t) + r,  A = [[0, 1], [0, 0]],
  b(t) = (0, sin t),  r = (0, lambda) * mu,  y = velocity (FirstOrderLinearTIR, C = [0 1]),
  RelayNSL(1, -1, 1): mu in [-1, 1], mu = -sign(y) while y != 0, y = 0 with |mu| <= 1,

so the friction force is lambda * mu = -lambda sign(v) while sliding and anything in
[-lambda, lambda] at rest: the Coulomb law with R = lambda (m = B = w = 1). Integrator:
EulerMoreauOSI(theta), the theta-method for the smooth part with the relay multiplier
implicit; one-step problem: Relay (a relay problem solved by Siconos/Numerics at every
step). b(t) is a plain vector (no plugin): before each step it is set to
(1 - theta) b(t_k) + theta b(t_k+1), which is what the theta-method takes from a b that
varies in time. The velocity after each step is recorded; events are extracted from the
record by peer_common.events_from_record (at rest |v| < 1e-9; sticks at least 0.01 of a
period).

Event-driven: EventDriven + LsodarOSI is tried in three formulations (first-order relay;
Lagrangian 1-DOF with a relay; a 2-DOF Lagrangian with a permanent unilateral contact and
2-D Coulomb friction, NewtonImpactFrictionNSL + FrictionContact), after a control run of
the case it is written for (a frictionless bouncing ball, NewtonImpactNSL). What happens is
recorded in siconos-event-driven.json (Siconos 4.4 throws from
LsodarOSI::initializeWorkVectorsForInteraction for each of them; the Python binding only
shows "std::exception", so the messages of that function in libsiconos_kernel are quoted).

Usage: /usr/bin/python3 siconos_peer.py --out DIR [--cases ...] [--steps 1e-2,1e-3,1e-4]
       [--steps-1000p 1e-2,1e-3] [--theta 0.5] [--deadline S] [--deadline-1000p S]
Writes DIR/siconos-mj-h<h>-<case>.json and DIR/siconos-event-driven.json.
"""

import argparse
import glob
import math
import os
import re
import sys
import time

import numpy as np
import siconos
import siconos.kernel as sk

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import peer_common  # noqa: E402

REST_THRESHOLD = 1e-9
MIN_STICK = 0.01 * peer_common.TWO_PI


def build_time_stepping(lam, v0, t_end, h, theta):
    A = np.array([[0.0, 1.0], [0.0, 0.0]])
    ds = sk.FirstOrderLinearTIDS(np.array([0.0, v0]), A, np.array([0.0, 0.0]))
    rel = sk.FirstOrderLinearTIR(np.array([[0.0, 1.0]]), np.array([[0.0], [lam]]))
    inter = sk.Interaction(sk.RelayNSL(1, -1.0, 1.0), rel)
    nsds = sk.NonSmoothDynamicalSystem(0.0, t_end)
    nsds.insertDynamicalSystem(ds)
    nsds.link(inter, ds)
    sim = sk.TimeStepping(nsds, sk.TimeDiscretisation(0.0, h))
    sim.insertIntegrator(sk.EulerMoreauOSI(theta))
    sim.insertNonSmoothProblem(sk.Relay())
    return ds, sim


def run_time_stepping(lam, v0, t_end, h, theta, deadline):
    start = time.perf_counter()
    ds, sim = build_time_stepping(lam, v0, t_end, h, theta)
    n_max = int(math.ceil(t_end / h)) + 2
    ts = np.empty(n_max + 1)
    vs = np.empty(n_max + 1)
    ts[0], vs[0] = 0.0, v0
    state = ds.x()  # views on the system's vectors (updated in place by Siconos)
    b = ds.b()
    n = 1
    finished = True
    while sim.hasNextEvent():
        tk = sim.startingTime()
        tk1 = sim.nextTime()
        b[1] = (1.0 - theta) * math.sin(tk) + theta * math.sin(tk1)
        sim.computeOneStep()
        ts[n] = tk1
        vs[n] = state[1]
        n += 1
        sim.nextStep()
        if (n & 1023) == 0 and time.perf_counter() - start > deadline:
            finished = False
            break
    elapsed = time.perf_counter() - start
    return ts[:n], vs[:n], elapsed, n - 1, finished


def try_event_driven(lam):
    """Tries Siconos' event-driven scheme in three formulations; returns what happened."""
    attempts = []

    def first_order():
        A = np.array([[0.0, 1.0], [0.0, 0.0]])
        ds = sk.FirstOrderLinearTIDS(np.array([0.0, 0.0]), A, np.array([0.0, 0.0]))
        rel = sk.FirstOrderLinearTIR(np.array([[0.0, 1.0]]), np.array([[0.0], [lam]]))
        return ds, sk.Interaction(sk.RelayNSL(1, -1.0, 1.0), rel), sk.Relay

    def lagrangian_relay():
        ds = sk.LagrangianLinearTIDS(np.array([0.0]), np.array([0.0]), np.array([[1.0]]))
        ds.setFExtPtr(np.array([0.0]))
        rel = sk.LagrangianLinearTIR(np.array([[1.0]]))
        return ds, sk.Interaction(sk.RelayNSL(1, -lam, lam), rel), sk.LCP

    def lagrangian_contact_friction():
        # q = (x, z): z >= 0 unilateral with a unit normal load, tangential Coulomb
        # friction with coefficient lambda (so the friction force is lambda).
        ds = sk.LagrangianLinearTIDS(np.zeros(2), np.zeros(2), np.eye(2))
        ds.setFExtPtr(np.array([0.0, -1.0]))
        rel = sk.LagrangianLinearTIR(np.array([[0.0, 1.0], [1.0, 0.0]]))
        nsl = sk.NewtonImpactFrictionNSL(0.0, 0.0, lam, 2)
        return ds, sk.Interaction(nsl, rel), lambda: sk.FrictionContact(2)

    def control_bouncing_ball():
        # Not our problem: a frictionless ball dropped on the ground (NewtonImpactNSL), the
        # case EventDriven + LsodarOSI is written for, to show that the scheme itself runs.
        ds = sk.LagrangianLinearTIDS(np.array([1.0]), np.array([0.0]), np.array([[1.0]]))
        ds.setFExtPtr(np.array([-9.81]))
        rel = sk.LagrangianLinearTIR(np.array([[1.0]]))
        return ds, sk.Interaction(sk.NewtonImpactNSL(0.9), rel), sk.LCP

    for name, make in [
        ("control (not friction): bouncing ball, LagrangianLinearTIDS + NewtonImpactNSL, "
         "OSNS LCP", control_bouncing_ball),
        ("FirstOrderLinearTIDS + FirstOrderLinearTIR + RelayNSL, OSNS Relay", first_order),
        ("LagrangianLinearTIDS + LagrangianLinearTIR + RelayNSL, OSNS LCP", lagrangian_relay),
        ("LagrangianLinearTIDS (x, z) + unilateral contact + NewtonImpactFrictionNSL, "
         "OSNS FrictionContact(2)", lagrangian_contact_friction),
    ]:
        stage = "building the model"
        try:
            ds, inter, problem = make()
            nsds = sk.NonSmoothDynamicalSystem(0.0, 30.0)
            nsds.insertDynamicalSystem(ds)
            nsds.link(inter, ds)
            stage = "EventDriven + LsodarOSI"
            sim = sk.EventDriven(nsds, sk.TimeDiscretisation(0.0, 0.01))
            sim.insertIntegrator(sk.LsodarOSI())
            sim.insertNonSmoothProblem(problem(), sk.SICONOS_OSNSP_ED_IMPACT)
            sim.insertNonSmoothProblem(problem(), sk.SICONOS_OSNSP_ED_SMOOTH_ACC)
            stage = "EventDriven.initialize()"
            sim.initialize()
            stage = "EventDriven.advanceToEvent()"
            steps = 0
            while sim.hasNextEvent() and steps < 20:
                sim.advanceToEvent()
                sim.processEvents()
                steps += 1
            attempts.append({"formulation": name, "ok": True, "stage": "ran %d events" % steps})
        except Exception as error:  # the binding turns Siconos exceptions into Exception
            attempts.append({"formulation": name, "ok": False, "stage": stage,
                             "error": "%s: %s" % (type(error).__name__, error)})
    # The messages the kernel library has for these cases (the binding drops them).
    messages = []
    for lib in sorted(glob.glob("/usr/lib/*/libsiconos_kernel.so.*")):
        with open(lib, "rb") as f:
            data = f.read()
        for m in re.findall(rb"(?:LsodarOSI|EventDriven)::[ -~]*not yet implemented[ -~]*", data):
            text = m.decode().strip()
            if text not in messages:
                messages.append(text)
        break
    return {"attempts": attempts, "library_messages": messages}


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--out", required=True)
    parser.add_argument("--cases", default=",".join(c[0] for c in peer_common.CASES))
    parser.add_argument("--steps", default="1e-2,1e-3,1e-4")
    parser.add_argument("--steps-1000p", default="1e-2,1e-3")
    parser.add_argument("--theta", type=float, default=0.5)
    parser.add_argument("--deadline", type=float, default=60.0)
    parser.add_argument("--deadline-1000p", type=float, default=60.0)
    args = parser.parse_args()
    os.makedirs(args.out, exist_ok=True)
    version = getattr(siconos, "__version__", "")

    ed = try_event_driven(0.7)
    ed["siconos"] = version
    peer_common.write_json(os.path.join(args.out, "siconos-event-driven.json"), ed)
    for a in ed["attempts"]:
        print("event-driven: %s: %s" % (a["formulation"], "ok" if a["ok"] else
                                        "FAILED at %s (%s)" % (a["stage"], a["error"])),
              flush=True)

    for case_id in args.cases.split(","):
        cid, lam, v0, t_end, _ = peer_common.CASE_BY_ID[case_id]
        steps = args.steps_1000p if cid == "1000p" else args.steps
        deadline = args.deadline_1000p if cid == "1000p" else args.deadline
        for h_text in steps.split(","):
            h = float(h_text)
            ts, vs, elapsed, n_steps, finished = run_time_stepping(lam, v0, t_end, h, args.theta,
                                                                   deadline)
            events = peer_common.events_from_record(ts, vs, REST_THRESHOLD, MIN_STICK)
            record = {
                "peer": "siconos", "method": "Moreau-Jean (EulerMoreauOSI theta=%g)" % args.theta,
                "h": h, "theta": args.theta, "siconos": version, "case": cid, "lambda": lam,
                "v0": v0, "t_end": t_end, "time_s": elapsed, "reps": 1, "steps": n_steps,
                "finished": finished, "t_reached": float(ts[-1]),
                "failure": "" if finished else "deadline", "deadline_s": deadline,
                "rest_threshold": REST_THRESHOLD, "min_stick": MIN_STICK, "events": events,
            }
            name = "siconos-mj-h%s-%s.json" % (h_text, cid)
            peer_common.write_json(os.path.join(args.out, name), record)
            print("MJ h=%-6s %-6s %8.3f s  steps %9d  events %5d  %s" % (
                h_text, cid, elapsed, n_steps, len(events),
                "finished" if finished else "STOPPED at t = %.1f (deadline)" % ts[-1]), flush=True)


if __name__ == "__main__":
    main()
