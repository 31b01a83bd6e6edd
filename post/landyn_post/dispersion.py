"""landyn-dispersion: histograms, failure causes, sensitivities and success probability of a
LANDYN Monte Carlo campaign.

Reads the summary file of a campaign (landyn_batch, docs/campaign.md; meant for Monte Carlo,
works for any mode) and writes one figure, <stem>_statistics.png, with

  * histograms of the summary metrics of the cases that ran (smallest stroke margin, peak
    overload, peak footpad penetration, largest slide, final tilt, body clearance, largest
    primary-strut crush), with the campaign's criteria as red lines;
  * the running estimate of the probability of a successful landing over the cases (in case-id
    order) with its 95 % Wilson score band;
  * the failure-cause breakdown: how many cases failed each success criterion (a case may fail
    several), from /cases/failed_criteria;

and prints a statistics table (mean, standard deviation, 5 / 50 / 95 % quantiles, range) and
the success probability with its 95 % Wilson interval, as stored in the file, and the failures
per criterion. --inputs adds histograms of the sampled inputs. --sensitivity writes
<stem>_sensitivity.png: every varied input against the smallest stroke margin and the peak
overload (scatter, successful and failed cases marked, criteria as lines), and the Spearman rank
correlation of every input with every metric (scipy.stats.spearmanr), also printed as a table.
Axes carry engineering labels derived from what was sampled (e.g. "horizontal velocity along
global +x, uphill [m/s]"; "... (slope direction sampled)" when the campaign varies it too).

Exit status 0, 1 on a usage error, 2 when the file is not a campaign summary, 4 when a figure
cannot be written.
"""
import math
import os
import sys

import numpy as np

import h5py
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from . import cli  # noqa: E402
from .campaign import METRICS as SENS_METRICS, failure_breakdown, input_label, spearman  # noqa: E402
from .schema import CAMPAIGN_SCHEMA  # noqa: E402

SCHEMA = CAMPAIGN_SCHEMA.encode()
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


def _print_extremes(ids, data) -> None:
    """The cases at the extremes (smallest margin, largest overload), with the command that re-runs
    one of them with its full time history."""
    parts = []
    for name, pick, scale, unit, what in (("min_stroke_margin", np.nanargmin, 1000.0, "mm", "smallest stroke margin"),
                                          ("peak_overload", np.nanargmax, 1.0, "g", "largest peak overload")):
        v = data[name]
        if len(v) and np.isfinite(v).any():
            k = int(pick(v))
            parts.append(f"{what}: case {int(ids[k])} ({v[k] * scale:.4g} {unit})")
    if parts:
        print("  extreme cases: " + "; ".join(parts))
        print("  (re-run one with its full time history: landyn_batch DECK --case K --history)")


def default_figure_name(summary: str) -> str:
    """<stem>_statistics.png beside the working directory: the histograms, the success probability
    and the failure causes (not <stem>_dispersion.png, which read dispersion_dispersion.png for the
    example campaign dispersion.h5)."""
    return cli.stem(summary) + "_statistics.png"


def sensitivity_name(out: str) -> str:
    """The sensitivity figure's name next to the main figure: x_statistics.png -> x_sensitivity.png,
    other names x.png -> x_sensitivity.png."""
    root, ext = os.path.splitext(out)
    for suffix in ("_statistics", "_dispersion"):
        root = root.removesuffix(suffix)
    return root + "_sensitivity" + (ext or ".png")


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


def _main(argv=None):
    ap = cli.make_parser("landyn-dispersion", __doc__)
    ap.add_argument("summary", help="summary file of a campaign (landyn_batch)")
    ap.add_argument("-o", "--output", help="figure file (default <summary stem>_statistics.png)")
    ap.add_argument("--inputs", action="store_true", help="also histogram the sampled inputs")
    ap.add_argument("--sensitivity", action="store_true",
                    help="also write <stem>_sensitivity.png: inputs vs margin and overload, rank correlations")
    ap.add_argument("--bins", type=cli.nonnegative_int, default=0, help="histogram bins (default: about sqrt(cases))")
    ap.add_argument("--dpi", type=cli.positive_int, default=150)
    ap.add_argument("--title")
    a = ap.parse_args(argv)
    if a.output:                      # before the work: never an input, and a format matplotlib writes
        cli.refuse_overwrite(a.output, [a.summary])
        cli.figure_format(a.output)
    try:
        f = h5py.File(a.summary, "r")
    except OSError as exc:
        print(f"landyn-dispersion: error: {a.summary}: cannot open ({exc})", file=sys.stderr)
        return 2
    with f:
        if f.attrs.get("schema_version") != SCHEMA:
            print(f"landyn-dispersion: error: {a.summary}: not a LANDYN campaign summary", file=sys.stderr)
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
        par_names = [text(x) for x in f["parameters/name"][()]]
        base_text = text(f["campaign/base_deck_text"][()])
        failed_criteria = f["cases/failed_criteria"][()]
        sens = {m[0]: f["cases/" + m[0]][()] for m in SENS_METRICS}
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
        print(f"landyn-dispersion: note: a {mode} campaign; the histograms show its grid/list, not a distribution")
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
    _print_extremes(ids[ran], {m: data[m][ran] for m in ("min_stroke_margin", "peak_overload")})
    k, ne, p, lo, hi = stored
    print(f"  P(successful landing) = {k}/{ne} = {p:.4f}, 95 % Wilson score interval [{lo:.4f}, {hi:.4f}]"
          f" (failed runs: {failed_runs})")
    breakdown = failure_breakdown(failed_criteria)
    n_failed = int(np.sum(failed_criteria != 0))
    print(f"  failure causes ({n_failed} case(s) failed; a case may fail several criteria):")
    for _, lab, cnt in breakdown:
        print(f"    {lab:40s} {cnt:6d}")
    eng = {lab: input_label(nm, u, base_text, par_names) for lab, nm, u in zip(labels, par_names, units)}

    # ---- figure
    panels = [m for m in METRICS if np.isfinite(data[m[0]][ran]).any()]
    extra = labels if a.inputs else []
    npan = len(panels) + 2 + len(extra)
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
    if panels:       # one legend for every histogram, above them: none covers a bar or a criterion
        h, lab = axes[0].get_legend_handles_labels()
        fig.legend(h, lab, loc="upper center", bbox_to_anchor=(0.5, 0.965), ncol=3, fontsize=8, frameon=False)
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
    ax = axes[len(panels) + 1]
    ypos = np.arange(len(breakdown))
    ax.barh(ypos, [c for _, _, c in breakdown], color=["tab:red" if c else "0.8" for _, _, c in breakdown])
    ax.set_yticks(ypos)
    ax.set_yticklabels([lab for _, lab, _ in breakdown], fontsize=7)
    ax.invert_yaxis()
    for yv, (_, _, c) in zip(ypos, breakdown):
        ax.annotate(f" {c}", (c, yv), va="center", fontsize=7)
    ax.set_xlabel("failed cases")
    ax.set_title(f"failure causes: {n_failed} of {n} cases failed", fontsize=9)
    for ax, lab in zip(axes[len(panels) + 2:], extra):
        ax.hist(inputs[lab][np.isfinite(inputs[lab])], bins=nb, color="tab:gray")
        ax.set_xlabel(eng[lab], fontsize=8)
        ax.set_ylabel("cases")
    for ax in axes[npan:]:
        ax.axis("off")
    fig.suptitle(f"{title} - {n} cases", fontsize=11)
    fig.tight_layout(rect=(0, 0, 1, 0.94))
    out = a.output or default_figure_name(a.summary)
    try:
        cli.refuse_overwrite(out, [a.summary])
        cli.savefig(fig, out, dpi=a.dpi)
        plt.close(fig)
        print(f"Figure written to {out}")
        if a.sensitivity:
            out2 = sensitivity_name(out)
            cli.refuse_overwrite(out2, [a.summary])
            sensitivity_figure(out2, title, labels, eng, inputs, sens, success, ran, crit, a.dpi)
            print(f"Figure written to {out2}")
    except cli.LandynWriteError as exc:
        print(f"landyn-dispersion: error: {exc}", file=sys.stderr)
        return cli.EXIT_WRITE
    except cli.LandynPostError as exc:
        print(f"landyn-dispersion: error: {exc}", file=sys.stderr)
        return cli.EXIT_ERROR
    return 0


def sensitivity_figure(out, title, labels, eng, inputs, sens, success, ran, crit, dpi):
    """Inputs vs smallest stroke margin and peak overload (scatter), and the Spearman rank
    correlation of every input with every metric; prints the correlation table."""
    metrics = [m for m in SENS_METRICS if np.isfinite(sens[m[0]][ran]).sum() >= 3 and np.ptp(sens[m[0]][ran]) > 0]
    rho = np.full((len(labels), len(metrics)), np.nan)
    print("  Spearman rank correlation (input vs metric; p-value in parentheses):")
    w = max([len(eng[lab]) for lab in labels] + [5]) + 2
    print("    " + f"{'input':{w}s}" + "".join(f"{m[1][:22]:>24s}" for m in metrics))
    for i, lab in enumerate(labels):
        cells = []
        for j, m in enumerate(metrics):
            r, pv, _ = spearman(inputs[lab][ran], sens[m[0]][ran])
            rho[i, j] = r
            cells.append(f"{r:+.3f} ({pv:.2g})" if np.isfinite(r) else "-")
        print("    " + f"{eng[lab]:{w}s}" + "".join(f"{c:>24s}" for c in cells))
    scat = [m for m in metrics if m[0] in ("min_stroke_margin", "peak_overload")]
    fig = _sensitivity_panels(labels, eng, inputs, sens, success, ran, crit, scat, metrics, rho)
    fig.suptitle(f"{title}: sensitivity of the margins to the inputs", fontsize=10)
    cli.savefig(fig, out, dpi=dpi)
    plt.close(fig)


SENS_COLUMNS = 4   #: scatter panels per row of the sensitivity figure (a grid, not one row per metric)


def _sensitivity_panels(labels, eng, inputs, sens, success, ran, crit, scat, metrics, rho):
    """The sensitivity figure's panels: for each of the scatter metrics a block of rows of at most
    SENS_COLUMNS inputs, then the rank-correlation matrix across the full width; one legend for the
    figure, above the panels, so none covers a failure marker."""
    from matplotlib.lines import Line2D
    from matplotlib.ticker import FormatStrFormatter, MaxNLocator
    ncol = min(SENS_COLUMNS, max(len(labels), 1))
    rows_per = max(1, math.ceil(len(labels) / ncol))
    n_rows = rows_per * len(scat)
    heat_h = 1.6 + 0.3 * len(labels)
    fig = plt.figure(figsize=(3.4 * ncol + 0.4, 2.7 * n_rows + heat_h + 0.8), layout="constrained")
    top, bottom = fig.subfigures(2, 1, height_ratios=[2.7 * n_rows + 0.5, heat_h])
    axs = top.subplots(max(n_rows, 1), ncol, squeeze=False)
    good = success[ran] == 1
    for ax in axs.ravel()[len(scat) * rows_per * ncol:]:
        ax.axis("off")
    for j, m in enumerate(scat):
        y = sens[m[0]][ran] * m[2]
        for i in range(rows_per * ncol):
            ax = axs[j * rows_per + i // ncol, i % ncol]
            if i >= len(labels):
                ax.axis("off")
                continue
            lab = labels[i]
            x = inputs[lab][ran]
            ax.plot(x[good], y[good], "o", ms=3.5, color="tab:blue", alpha=0.7)
            ax.plot(x[~good], y[~good], "x", ms=4.5, color="tab:red")
            if m[0] in crit:
                ax.axhline(crit[m[0]] * m[2], color="red", lw=1.0, ls="--")
            r = rho[i, [mm[0] for mm in metrics].index(m[0])]
            ax.set_title(f"Spearman rho = {r:+.2f}" if np.isfinite(r) else "constant", fontsize=8)
            ax.set_xlabel(_wrap(eng[lab], 40), fontsize=7)
            ax.set_ylabel(f"{m[1]} [{m[3]}]", fontsize=7)
            ax.xaxis.set_major_locator(MaxNLocator(4))
            if np.nanmax(np.abs(x)) >= 1e4 if np.isfinite(x).any() else False:
                ax.xaxis.set_major_formatter(FormatStrFormatter("%.3g"))   # no offset text under the label
            ax.tick_params(labelsize=7)
            ax.grid(True, alpha=0.3)
    handles = [Line2D([], [], ls="none", marker="o", color="tab:blue", label="successful"),
               Line2D([], [], ls="none", marker="x", color="tab:red", label="not successful"),
               Line2D([], [], ls="--", color="red", label="criterion")]
    top.legend(handles=handles, loc="outside upper center", ncol=3, fontsize=8, frameon=False)
    if metrics:
        ax = bottom.subplots()
        im = ax.imshow(rho, vmin=-1, vmax=1, cmap="RdBu_r", aspect="auto")
        ax.set_xticks(range(len(metrics)))
        ax.set_xticklabels([f"{m[1]}" for m in metrics], rotation=20, ha="right", fontsize=7)
        ax.set_yticks(range(len(labels)))
        ax.set_yticklabels([eng[lab] for lab in labels], fontsize=7)
        for i in range(len(labels)):
            for j in range(len(metrics)):
                if np.isfinite(rho[i, j]):
                    ax.annotate(f"{rho[i, j]:+.2f}", (j, i), ha="center", va="center", fontsize=7)
        bottom.colorbar(im, ax=ax, label="Spearman rank correlation", fraction=0.04)
        ax.set_title("rank correlation input vs metric", fontsize=8)
    return fig


def _wrap(label: str, width: int) -> str:
    import textwrap
    return "\n".join(textwrap.wrap(label, width)) or label


if __name__ == "__main__":
    sys.exit(main())


def main(argv=None):
    """landyn-dispersion: one error line and exit status 2 for any input it cannot process."""
    return cli.run("landyn-dispersion", _main, argv)
