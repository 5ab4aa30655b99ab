#!/usr/bin/env python3
"""The seed's figure 10.2 (USNRC problem 7, lambda = R/B = 0.7, from rest),
redone with the Python module: the exact velocity with the stiff-spring
(K_f = 1e7) velocity overlaid, and the stiff spring checked by compare().

    python3 docs/examples/figure_10_2.py [OUTPUT_DIR]      # writes figure_10_2.png

Runs headless (MPLBACKEND=Agg); docs/python.md explains each call.
"""
import os
import sys

import matplotlib

matplotlib.use(os.environ.get("MPLBACKEND", "Agg"))
import matplotlib.pyplot as plt  # noqa: E402

import frictionref  # noqa: E402

out_dir = sys.argv[1] if len(sys.argv) > 1 else "."
model = frictionref.Model(mass=1, amplitude=1, omega=1, lambda_=0.7)  # m = B = w = 1, v0 = 0

# The exact solution on a 0.01 grid plus every stop and breakaway (the kinks).
exact = frictionref.curve(model, t_end=30, dt=0.01, include_events=True)
# The seed's DYNARACK-like model: a friction spring K_f = 1e7, archived every 0.01.
stiff = frictionref.stiff(model, 30, kf=1e7, output_dt=0.01)
report = frictionref.compare(model, stiff["t"], stiff["v"])
regime = frictionref.classify(model)

fig, ax = plt.subplots(figsize=(9, 5))
ax.plot(exact["t"], exact["v"], color="black", linewidth=2.5, label="exact (frictionref)")
ax.plot(stiff["t"], stiff["v"], color="tab:red", linewidth=1,
        label="stiff spring, K_f = 1e7 (central differences)")
for stop in frictionref.events(model, 30):
    if stop["phase"] == "stick":
        ax.axvspan(stop["t_begin"], stop["t_end"], color="0.92", zorder=0)
ax.set_title("Oscillating mass with friction R/F=.7 Dead Bands Present\n"
             "Velocity of mass vs time (initial velocity = 0.)")
ax.set_xlabel("t [time]")
ax.set_ylabel("v [length/time]")
ax.axhline(0, color="0.5", linewidth=0.5)
ax.legend(loc="upper right")
ax.text(0.01, 0.02,
        f"regime {regime['regime']}, stuck {100 * regime['stuck_fraction']:.2f} % of the time "
        f"(grey: dead bands); compare: {report['verdict']}, max |v error| = "
        f"{report['velocity_error']['max']:.2e}",
        transform=ax.transAxes, fontsize=8)
fig.tight_layout()
path = os.path.join(out_dir, "figure_10_2.png")
fig.savefig(path, dpi=120)
print(f"{path}: stiff spring vs exact, verdict {report['verdict']}")
