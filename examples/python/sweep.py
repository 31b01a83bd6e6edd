# %% [markdown]
# # Touchdown velocity sweep with the LANDYN Python API
#
# Load case LC-3 of the paper (`input/lc3.nml`: 1 m/s horizontal, yaw 45 deg, 8 deg slope) at five
# vertical touchdown velocities, `&initial_state velocity(3)` from 3 to 5 m/s (4 m/s is the paper's).
# Each run is one `landyn.Simulation`, sampled every millisecond with `history`; the figure shows the
# largest primary-strut stroke of each gear against the velocity.
#
#     .venv/bin/python examples/python/sweep.py               # writes sweep_primary_stroke.png
#     .venv/bin/python examples/python/sweep.py -o my.png
#
# Run it from the repository root after `bash scripts/setup.sh` (a few seconds). In a notebook or an
# editor with `# %%` cells, run the cells one by one.

# %%
import argparse
import os
import sys
import time

import matplotlib
import numpy as np

import landyn

if "ipykernel" not in sys.modules:
    matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

ap = argparse.ArgumentParser(description="LC-3 at five vertical touchdown velocities: largest primary stroke")
ap.add_argument("--deck", default="input/lc3.nml", help="base deck (default: %(default)s)")
ap.add_argument("-o", "--output", default="sweep_primary_stroke.png", help="figure file (default: %(default)s)")
args = ap.parse_args([] if "ipykernel" in sys.modules else None)

velocities = np.linspace(3.0, 5.0, 5)    # vertical touchdown velocity, global z down [m/s]
times = np.linspace(0.0, 1.0, 1001)      # samples up to the deck's t_end = 1 s [s]

# %% The sweep: one Simulation per velocity; the deck is the file, the swept variable an override
peak = {}            # gear number -> largest primary stroke per velocity [m]
outcomes = []
t0 = time.perf_counter()
for v in velocities:
    with landyn.Simulation(args.deck, overrides={"initial_state%velocity(3)": v}) as sim:
        primaries = [n for n in sim.output_names if n.endswith(".strut1.stroke")]   # strut 1: the primary
        hist = sim.history(times)
        for name in primaries:
            gear = int(name.split(".")[0][len("gear"):])
            peak.setdefault(gear, []).append(hist[name].max())
        outcomes.append(sim.outcome)
        unit = sim.units[primaries[0]]
print(f"{len(velocities)} runs in {time.perf_counter() - t0:.1f} s")
print("velocity [m/s]  " + "  ".join(f"gear {g} [{unit}]" for g in sorted(peak)) + "  outcome")
for i, v in enumerate(velocities):
    print(f"{v:14.2f}  " + "  ".join(f"{peak[g][i]:12.4f}" for g in sorted(peak)) + f"  {outcomes[i]}")

# %% The figure: gears that share a stroke by symmetry coincide; wide pale lines under narrow ones show both
gears = sorted(peak)
same = [(a, b) for i, a in enumerate(gears) for b in gears[i + 1:]
        if np.max(np.abs(np.subtract(peak[a], peak[b]))) < 0.5e-3]          # within 0.5 mm
fig, ax = plt.subplots(figsize=(7.0, 4.5), dpi=120)
markers = ["o", "s", "^", "x", "D", "v", "P", "*"]
for k, g in enumerate(gears):
    wide = any(g == a for a, _ in same)            # the first of a coinciding pair: drawn wide, underneath
    ax.plot(velocities, 1000.0 * np.asarray(peak[g]), marker=markers[k % len(markers)],
            markersize=13 if wide else 6, markerfacecolor="none" if wide else None, linewidth=6 if wide else 1.8,
            alpha=0.45 if wide else 1.0, zorder=2 if wide else 3, label=f"gear {g}")
ax.set_xlabel("vertical touchdown velocity  [m/s]", fontsize=12)
ax.set_ylabel("largest primary stroke  [mm]", fontsize=12)
ax.set_title(f"{os.path.basename(args.deck)}: largest primary stroke per gear", fontsize=12)
ax.tick_params(labelsize=11)
ax.grid(True, alpha=0.4)
title = ("coinciding (within 0.5 mm): " + ", ".join(f"{a} & {b}" for a, b in same)) if same else None
ax.legend(fontsize=11, title=title, title_fontsize=9)
fig.tight_layout()
fig.savefig(args.output)
print(f"figure: {args.output}")
