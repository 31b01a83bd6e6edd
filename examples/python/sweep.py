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

# %% The figure: gears that share a stroke by symmetry are drawn with different markers and lines
fig, ax = plt.subplots(figsize=(7.0, 4.5), dpi=120)
styles = [("o", "-", 9), ("s", "--", 7), ("^", "-.", 7), ("x", ":", 9), ("D", "-", 5), ("v", "--", 7)]
for k, g in enumerate(sorted(peak)):
    marker, line, size = styles[k % len(styles)]
    ax.plot(velocities, 1000.0 * np.asarray(peak[g]), marker=marker, linestyle=line, markersize=size,
            markerfacecolor="none" if k % 2 == 0 else None, linewidth=1.6, label=f"gear {g}")
ax.set_xlabel("vertical touchdown velocity  [m/s]", fontsize=12)
ax.set_ylabel("largest primary stroke  [mm]", fontsize=12)
ax.set_title(f"LC-3 ({args.deck}): largest primary stroke per gear", fontsize=12)
ax.tick_params(labelsize=11)
ax.grid(True, alpha=0.4)
ax.legend(fontsize=11, title="overlapping curves: symmetric gears", title_fontsize=9)
fig.tight_layout()
fig.savefig(args.output)
print(f"figure: {args.output}")
