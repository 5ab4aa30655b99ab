"""Shared pieces of the peer comparison (tests/peers/README.md).

- CASES: the seed's four cases every peer runs (m = B = w = 1, x0 = 0, t0 = 0);
  GENERAL_CASES: the general model's cases (spring, damper, static friction, offset), run
  by the exact engine, scipy and CVODE; case_params() gives any case's parameters.
- Event lists: [(kind, t), ...] with kind "stop" (a slip ends in a stick), "breakaway"
  (a stick ends), "reversal" (v = 0 and the slip goes on the other way at once); a peer
  may also report "touch" (v = 0 and the slip goes on the same way), which the exact
  engine never emits and which is counted as an extra event.
- events_from_record(): events from a sampled velocity record (time-stepping codes).
- match_events(): a peer's events against the exact ones.

Uses only the standard library and numpy.
"""

import decimal
import json
import math
import os

TWO_PI = 2.0 * math.pi

# (id, lambda, v0, t_end, label)
CASES = [
    ("10.1", 0.3, 0.0, 30.0, "seed 10.1: lambda 0.3, 30 time units"),
    ("10.2", 0.7, 0.0, 30.0, "seed 10.2: lambda 0.7, 30 time units"),
    ("10.3", 1.01, -1.0, 30.0, "seed 10.3: lambda 1.01, v0 -1, 30 time units"),
    ("1000p", 0.7, 0.0, 2000.0 * math.pi, "lambda 0.7, 1000 periods (t_end = 2000 pi)"),
]
CASE_BY_ID = {c[0]: c for c in CASES}

# The general model's cases (docs/theory.md section 7), m = B = w = 1, x0 = t0 = 0:
#   x'' + c x' + k x = F0 + sin t - f,
#   slipping f = R sign(v); at rest N = F0 + sin t - k x, stuck while |N| <= Rs,
#   breaks away in the direction of N when |N| > Rs; a slip reaching v = 0 sticks if
#   |N| <= Rs there, else goes on at once in the direction of N.
# "lambda" is R (= R/B with B = 1), "static" is Rs. Siconos and the stiff spring (a model
# of the seed's problem only) do not run these.
GENERAL_CASES = [
    {"id": "spring-damper", "lambda": 0.05, "static": 0.05, "stiffness": 9.0, "damping": 0.1,
     "force_offset": 0.0, "v0": 0.0, "t_end": 60.0 * math.pi,
     "label": "spring + damper + Coulomb: k 9 (natural frequency 3 w), c 0.1, R 0.05, "
              "30 periods (t_end = 60 pi)",
     "title": "spring + damper + Coulomb (k 9, c 0.1, R 0.05)",
     "why": "The natural frequency sqrt(k/m) = 3 is three times the forcing frequency, so "
            "the free oscillation rings inside each forcing period: after a start-up of a "
            "few periods, every half period has a long slip, a reversal, a short slip back "
            "(0.09 time units, the mass moves by 2e-5), a stop and a stick of about 0.74 "
            "time units that ends in a breakaway. The slips back are shortest early on "
            "(0.0125 time units and 6e-8 length units at t = 16.86) and grow to their "
            "steady length; an integrator must resolve them to keep the sequence."},
    {"id": "static-kinetic", "lambda": 0.4, "static": 0.8, "stiffness": 0.0, "damping": 0.0,
     "force_offset": 0.1, "v0": 0.0, "t_end": 60.0 * math.pi,
     "label": "static > kinetic: R 0.4, Rs 0.8, F0 0.1, 30 periods (t_end = 60 pi)",
     "title": "static > kinetic friction (R 0.4, Rs 0.8, F0 0.1)",
     "why": "Each stick ends in a breakaway where |N| = |F0 + sin t| reaches Rs = 0.8 "
            "(not R). Each period has one forward slip that ends at v = 0 with N = -0.834, "
            "beyond Rs, so the mass reverses at once, and one backward slip that ends with "
            "N = 0.594, between R and Rs, so the mass sticks: with Rs = R it would have "
            "gone on. The offset F0 = 0.1 breaks the symmetry between the two half periods "
            "(with F0 = 0 every stop would be of one kind); no spring (k = 0), so N does "
            "not depend on x and the mass drifts forward."},
]
GENERAL_CASE_BY_ID = {c["id"]: c for c in GENERAL_CASES}
ALL_CASE_IDS = [c[0] for c in CASES] + [c["id"] for c in GENERAL_CASES]


def case_params(case_id):
    """Every parameter of a case as a dict (the seed's cases with Rs = R and k = c = F0 = 0):
    id, lambda (R), static (Rs), stiffness, damping, force_offset, v0, t_end, label, and
    general (False for the seed's model, where the drivers keep their original code)."""
    if case_id in GENERAL_CASE_BY_ID:
        params = dict(GENERAL_CASE_BY_ID[case_id])
        params["general"] = True
        return params
    cid, lam, v0, t_end, label = CASE_BY_ID[case_id]
    return {"id": cid, "lambda": lam, "static": lam, "stiffness": 0.0, "damping": 0.0,
            "force_offset": 0.0, "v0": v0, "t_end": t_end, "label": label, "general": False}


def general_model_options(params):
    """The drivers' command-line options for the general model's terms (empty for the
    seed's cases)."""
    if not params.get("general"):
        return []
    return ["--static-friction", repr(params["static"]), "--stiffness", repr(params["stiffness"]),
            "--damping", repr(params["damping"]), "--force-offset", repr(params["force_offset"])]


def write_json(path, obj):
    """Writes obj to path atomically (temp file + rename)."""
    tmp = path + ".tmp"
    with open(tmp, "w") as f:
        json.dump(obj, f, indent=1)
        f.write("\n")
    os.replace(tmp, path)


def events_from_record(t, v, threshold, min_stick, t_end_is_record_end=True):
    """Events from a sampled velocity record (numpy arrays t, v).

    Each sample is moving forward (v >= threshold), backward (v <= -threshold) or at rest.
    A run of resting samples that lasts at least min_stick (from the last moving sample
    before it to the first moving sample after it) is a stick: it starts with a stop and
    ends with a breakaway. A shorter run between opposite directions, or a direct sign
    change, is a reversal; a shorter run between the same direction is ignored.

    Event times, to undo the sampling and the threshold to first order:
      stop:      v extrapolated linearly to 0 from the last two moving samples, kept between
                 the last moving and the first resting sample (as frictionref compare does);
      breakaway: after a breakaway v grows like c (t - t_b)^2, so sqrt|v| is extrapolated
                 linearly to 0 from the first two moving samples, kept between the first
                 resting sample of the run and the first moving one;
      reversal:  the mean of the two one-sided linear extrapolations to 0 (from the two
                 moving samples before and the two after; the acceleration jumps there).
    A rest at the start of the record gives only a breakaway; one that reaches the end,
    only a stop.
    """
    import numpy as np

    t = np.asarray(t, dtype=float)
    v = np.asarray(v, dtype=float)
    n = len(t)
    state = np.where(v >= threshold, 1, np.where(v <= -threshold, -1, 0))
    events = []
    # Boundaries between runs of equal state.
    change = np.flatnonzero(state[1:] != state[:-1]) + 1
    starts = np.concatenate(([0], change))
    ends = np.concatenate((change, [n]))  # exclusive
    runs = [(int(s), int(e), int(state[s])) for s, e in zip(starts, ends)]

    def stop_time(i_moving):  # i_moving: last moving sample; i_moving + 1 is at rest
        t1, v1 = t[i_moving], v[i_moving]
        t_lo, t_hi = t1, t[i_moving + 1]
        if i_moving >= 1 and state[i_moving - 1] == state[i_moving]:
            t0, v0 = t[i_moving - 1], v[i_moving - 1]
            if v1 != v0:
                ts = t1 - v1 * (t1 - t0) / (v1 - v0)
                return min(max(ts, t_lo), t_hi)
        return t_hi

    def breakaway_time(i_rest_first, i_moving):  # first moving sample after the rest run
        t1, v1 = t[i_moving], abs(v[i_moving])
        t_lo, t_hi = t[i_rest_first], t1
        if i_moving + 1 < n and state[i_moving + 1] == state[i_moving]:
            t2, v2 = t[i_moving + 1], abs(v[i_moving + 1])
            s1, s2 = math.sqrt(v1), math.sqrt(v2)
            if s2 != s1:
                tb = t1 - s1 * (t2 - t1) / (s2 - s1)
                return min(max(tb, t_lo), t_hi)
        return t_lo

    def line_zero(a, b, lo, hi):  # zero of the line through samples a, b, kept in [lo, hi]
        if v[b] == v[a]:
            return None
        return min(max(t[a] - v[a] * (t[b] - t[a]) / (v[b] - v[a]), lo), hi)

    def crossing(i, j):  # v changes sign between moving samples i < j (opposite signs)
        # The acceleration jumps by 2R/m at a reversal (a kink in v), so a line through
        # i and j is off by O(h). Extrapolate each side's own line to zero (the kink is at
        # the zero) and take the mean; the chord if a side has a single sample.
        lo, hi = t[i], t[j]
        zeros = []
        if i >= 1 and state[i - 1] == state[i]:
            zeros.append(line_zero(i - 1, i, lo, hi))
        if j + 1 < n and state[j + 1] == state[j]:
            zeros.append(line_zero(j, j + 1, lo, hi))
        zeros = [z for z in zeros if z is not None]
        if zeros:
            return sum(zeros) / len(zeros)
        chord = line_zero(i, j, lo, hi)
        return chord if chord is not None else 0.5 * (lo + hi)

    for k, (s, e, st) in enumerate(runs):
        if st == 0:
            first = k == 0
            last = k == len(runs) - 1
            t_begin = t[s - 1] if s > 0 else t[s]
            t_finish = t[e] if e < n else t[e - 1]
            if first and last:
                continue
            if first:
                events.append(("breakaway", breakaway_time(s, e)))
                continue
            if last:
                events.append(("stop", stop_time(s - 1)))
                continue
            before, after = runs[k - 1][2], runs[k + 1][2]
            if t_finish - t_begin >= min_stick:
                events.append(("stop", stop_time(s - 1)))
                events.append(("breakaway", breakaway_time(s, e)))
            elif before != after:
                events.append(("reversal", crossing(s - 1, e)))
        else:
            if k > 0 and runs[k - 1][2] == -st:  # direct sign change
                events.append(("reversal", crossing(s - 1, s)))
    return events


def match_events(exact, peer, window=0.5):
    """Matches a peer's events to the exact ones.

    exact: [(kind, t)] or [(kind, t, t_reference)] with t_reference a decimal string (the
    50-digit engine's time); the error is then measured against t_reference, exactly.

    Returns a dict: same_sequence (the kinds agree one to one), max_abs_error over the
    matched events (and where), matched count, missed (exact events without a peer event
    of the same kind within `window` time units) and extra (peer events without an exact
    one), each counted by kind, and a one-line verdict.
    """
    kinds_exact = [e[0] for e in exact]
    kinds_peer = [e[0] for e in peer]
    result = {"exact_count": len(exact), "peer_count": len(peer)}
    pairs = []
    missed, extra = [], []
    if kinds_exact == kinds_peer:
        pairs = list(zip(exact, peer))
    else:
        i = j = 0
        while i < len(exact) and j < len(peer):
            ke, te = exact[i][0], exact[i][1]
            kp, tp = peer[j][0], peer[j][1]
            if ke == kp and abs(te - tp) <= window:
                pairs.append((exact[i], peer[j]))
                i += 1
                j += 1
            elif te <= tp:
                missed.append(exact[i])
                i += 1
            else:
                extra.append(peer[j])
                j += 1
        missed.extend(exact[i:])
        extra.extend(peer[j:])
    max_err, max_at, max_kind = 0.0, None, None
    for e, (kp, tp) in pairs:
        ke, te = e[0], e[1]
        if len(e) > 2:  # a high-precision reference time (a decimal string): exact difference
            err = float(abs(decimal.Decimal(tp) - decimal.Decimal(e[2])))
        else:
            err = abs(tp - te)
        if err > max_err or max_at is None:
            max_err, max_at, max_kind = err, te, ke
    result["same_sequence"] = kinds_exact == kinds_peer
    result["matched"] = len(pairs)
    result["max_abs_error"] = max_err if pairs else None
    result["max_error_at"] = max_at
    result["max_error_kind"] = max_kind
    result["missed"] = count_kinds(missed)
    result["extra"] = count_kinds(extra)
    result["first_missed"] = list(missed[0][:2]) if missed else None
    result["first_extra"] = list(extra[0][:2]) if extra else None
    result["verdict"] = sequence_verdict(exact, peer, result)
    return result


def count_kinds(events):
    counts = {}
    for e in events:
        k = e[0]
        counts[k] = counts.get(k, 0) + 1
    return counts


def describe_counts(counts):
    order = ["stop", "breakaway", "reversal", "touch"]
    parts = []
    for k in order + sorted(set(counts) - set(order)):
        if counts.get(k):
            parts.append("%d %s%s" % (counts[k], k, "" if counts[k] == 1 else "s"))
    return ", ".join(parts) if parts else "none"


def sequence_verdict(exact, peer, result):
    if result["same_sequence"]:
        return "yes (%s)" % describe_counts(count_kinds(exact))
    ce, cp = count_kinds(exact), count_kinds(peer)
    parts = []
    for k in ["stop", "breakaway", "reversal", "touch"]:
        if ce.get(k, 0) != cp.get(k, 0):
            parts.append("%d of %d %ss" % (cp.get(k, 0), ce.get(k, 0), k))
    text = "no: " + (", ".join(parts) if parts else "same counts, different order")
    if result["missed"]:
        text += "; missed " + describe_counts(result["missed"])
    if result["extra"]:
        text += "; extra " + describe_counts(result["extra"])
    if result.get("first_missed"):
        text += "; first missed %s at t = %.4f" % tuple(result["first_missed"][:2])
    elif result.get("first_extra"):
        text += "; first extra %s at t = %.4f" % tuple(result["first_extra"][:2])
    return text


def load_exact_events(results_dir, case_id):
    """The reference events of a case: (kind, t_double, t_50digit_string) when the 50-digit
    engine gave the same sequence as the double engine, else (kind, t_double)."""
    with open(os.path.join(results_dir, "ours-%s.json" % case_id)) as f:
        ours = json.load(f)
    events = [tuple(e) for e in ours["events"]]
    hp = ours.get("hp_event_times")
    if ours.get("hp_same_sequence") and hp and len(hp) == len(events):
        return [(k, t, h[1]) for (k, t), h in zip(events, hp)]
    return events
