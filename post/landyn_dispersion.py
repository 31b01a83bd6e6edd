#!/usr/bin/env python3
"""landyn_dispersion: histograms and success probability of a LANDYN Monte Carlo campaign.

Reads the summary file of a campaign (landyn_batch, docs/campaign.md; meant for Monte Carlo,
works for any mode) and writes one figure with

  * histograms of the summary metrics of the cases that ran (smallest stroke margin, peak
    overload, peak footpad penetration, largest slide, final tilt, body clearance, largest
    primary-strut crush), with the campaign's criteria as red lines;
  * the running estimate of the probability of a successful landing over the cases (in case-id
    order) with its 95 % Wilson score band;

and prints a statistics table (mean, standard deviation, 5 / 50 / 95 % quantiles, range) and
the success probability with its 95 % Wilson interval, as stored in the file.
--inputs adds histograms of the sampled inputs.

Self-contained (numpy, h5py, matplotlib with the Agg backend); exit status 0, or 2 when the file
is not a campaign summary.
"""
import argparse
import math
import os
import sys

import numpy as np

try:
    import h5py
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
except ImportError as exc:  # pragma: no cover
    sys.exit(f"landyn_dispersion: needs numpy, h5py and matplotlib ({exc})")

SCHEMA = b"landyn-campaign-1.0"
Z95 = 1.959963984540054
# name: (dataset or None, label, scale, unit, criterion dataset, "applied" dataset)
METRICS = [
    ("min_stroke_margin", "smallest stroke margin", 1000.0, "mm", "criteria/min_stroke_margin", None),
    ("peak_overload", "peak overload", 1.0, "g", "criteria/max_overload", "criteria/max_overload_applied"),
    ("peak_penetration", "largest footpad penetration", 1000.0, "mm", None, None),
    ("max_slide_distance", "largest footpad slide", 1.0, "m", None, None),
    ("final_tilt", "final tilt", 1.0, "deg", None, None),
    ("min_body_clearance", "body clearance", 1.0, "m", "criteria/min_body_clearance",
     "criteria/min_body_clearance_applied"),
    ("max_primary_crush", "largest primary-strut crush", 1000.0, "mm", None, None),
]


def wilson(k, n, z=Z95):
    if n == 0:
        return 0.0, 1.0
    p = k / n
    den = 1 + z * z / n
    c = (p + z * z / (2 * n)) / den
    h = z / den * math.sqrt(p * (1 - p) / n + z * z / (4 * n * n))
    return (0.0 if k == 0 else max(0.0, c - h)), (1.0 if k == n else min(1.0, c + h))


def text(x):
    s = x.decode() if isinstance(x, bytes) else str(x)
    return "" if s == "(none)" else s


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("summary", help="summary file of a campaign (landyn_batch)")
    ap.add_argument("-o", "--output", help="figure file (default <summary stem>_dispersion.png)")
    ap.add_argument("--inputs", action="store_true", help="also histogram the sampled inputs")
    ap.add_argument("--bins", type=int, default=0, help="histogram bins (default: about sqrt(cases))")
    ap.add_argument("--dpi", type=int, default=150)
    ap.add_argument("--title")
    a = ap.parse_args(argv)
    try:
        f = h5py.File(a.summary, "r")
    except OSError as exc:
        print(f"landyn_dispersion: {a.summary}: cannot open ({exc})", file=sys.stderr)
        return 2
    with f:
        if f.attrs.get("schema_version") != SCHEMA:
            print(f"landyn_dispersion: {a.summary}: not a LANDYN campaign summary", file=sys.stderr)
            return 2
        mode = text(f.attrs["mode"])
        title = a.title or text(f.attrs.get("title", b"")) or os.path.basename(a.summary)
        status = f["cases/status"][()]
        success = f["cases/success"][()]
        ids = f["cases/case_id"][()]
        failed_runs = text(f["criteria/failed_runs"][()])
        data = {}
        for name, *_ in METRICS:
            if name == "max_primary_crush":
                c = f["cases/crush_length"][()]
                data[name] = c[:, :, 0].max(axis=1) if len(c) else np.zeros(0)
            else:
                data[name] = f["cases/" + name][()]
        crit = {}
        for name, _, _, _, cds, app in METRICS:
            if cds and (app is None or int(f[app][()]) == 1):
                crit[name] = float(f[cds][()])
        labels = [text(x) for x in f["parameters/label"][()]]
        units = [text(x) for x in f["parameters/units"][()]]
        inputs = {lab: f["cases/inputs/" + lab][()] for lab in labels}
        stored = (int(f["probability/n_success"][()]), int(f["probability/n_evaluated"][()]),
                  float(f["probability/p_success"][()]), float(f["probability/ci95_low"][()]),
                  float(f["probability/ci95_high"][()]))
        complete = int(f.attrs["complete"])
        n_cases = int(f.attrs["n_cases"])
    ran = status == 0
    n = len(status)
    if mode != "monte_carlo":
        print(f"landyn_dispersion: note: a {mode} campaign; the histograms show its grid/list, not a distribution")
    nb = a.bins or max(5, min(40, int(round(math.sqrt(max(ran.sum(), 1))))))

    # ---- statistics table
    print(f"Campaign {a.summary}: {n} of {n_cases} cases{'' if complete else ' (INCOMPLETE)'}, "
          f"{ran.sum()} ran, {(status == 2).sum()} invalid input, {(status == 3).sum()} failed runs")
    print(f"  {'metric':34} {'mean':>10} {'sd':>10} {'p5':>10} {'p50':>10} {'p95':>10} {'min':>10} {'max':>10}")
    for name, label, scale, unit, _, _ in METRICS:
        v = data[name][ran] * scale
        v = v[np.isfinite(v)]
        if len(v) == 0:
            continue
        q = np.percentile(v, [5, 50, 95])
        print(f"  {label + ' [' + unit + ']':34} {v.mean():10.4g} {v.std(ddof=1) if len(v) > 1 else 0:10.4g} "
              f"{q[0]:10.4g} {q[1]:10.4g} {q[2]:10.4g} {v.min():10.4g} {v.max():10.4g}")
    k, ne, p, lo, hi = stored
    print(f"  P(successful landing) = {k}/{ne} = {p:.4f}, 95 % Wilson score interval [{lo:.4f}, {hi:.4f}]"
          f" (failed runs: {failed_runs})")

    # ---- figure
    panels = [m for m in METRICS if np.isfinite(data[m[0]][ran]).any()]
    extra = labels if a.inputs else []
    npan = len(panels) + 1 + len(extra)
    ncol = 3
    nrow = math.ceil(npan / ncol)
    fig, axes = plt.subplots(nrow, ncol, figsize=(4.2 * ncol, 3.2 * nrow), squeeze=False)
    axes = axes.ravel()
    for ax, (name, label, scale, unit, _, _) in zip(axes, panels):
        v = data[name][ran] * scale
        good = success[ran] == 1
        ax.hist([v[good], v[~good]], bins=nb, stacked=True, color=["tab:blue", "tab:orange"],
                label=["successful", "not successful"])
        if name in crit:
            ax.axvline(crit[name] * scale, color="red", lw=1.5, label="criterion")
        ax.set_xlabel(f"{label} [{unit}]")
        ax.set_ylabel("cases")
    if panels:
        axes[0].legend(fontsize=7)
    # running probability with its Wilson band
    ax = axes[len(panels)]
    order = np.argsort(ids)
    counted = np.ones(n, bool) if failed_runs != "exclude" else ran
    s = (success[order] == 1) & counted[order]
    c = counted[order]
    ks = np.cumsum(s)
    ns = np.cumsum(c)
    band = np.array([wilson(int(kk), int(nn)) for kk, nn in zip(ks, ns)]) if n else np.zeros((0, 2))
    x = np.arange(1, n + 1)
    with np.errstate(invalid="ignore", divide="ignore"):
        ax.plot(x, np.where(ns > 0, ks / np.maximum(ns, 1), np.nan), color="tab:blue", label="P(success)")
    if n:
        ax.fill_between(x, band[:, 0], band[:, 1], color="tab:blue", alpha=0.25, label="95 % Wilson")
    ax.set_ylim(-0.02, 1.02)
    ax.set_xlabel("cases (by case id)")
    ax.set_ylabel("probability of success")
    ax.set_title(f"P = {p:.3f}  [{lo:.3f}, {hi:.3f}]", fontsize=9)
    ax.legend(fontsize=7, loc="lower right")
    for ax, lab in zip(axes[len(panels) + 1:], extra):
        ax.hist(inputs[lab][np.isfinite(inputs[lab])], bins=nb, color="tab:gray")
        ax.set_xlabel(f"{lab} [{units[labels.index(lab)]}]")
        ax.set_ylabel("cases")
    for ax in axes[npan:]:
        ax.axis("off")
    fig.suptitle(f"{title} - {n} cases", fontsize=11)
    fig.tight_layout(rect=(0, 0, 1, 0.97))
    out = a.output or os.path.splitext(os.path.basename(a.summary))[0] + "_dispersion.png"
    fig.savefig(out, dpi=a.dpi)
    plt.close(fig)
    print(f"Figure written to {out}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
