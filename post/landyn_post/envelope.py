"""landyn-envelope: landing-stability envelope of a LANDYN grid campaign.

Reads the summary file of a grid campaign (landyn_batch, docs/campaign.md) that varies a
horizontal touchdown velocity and a terrain slope, and draws over (horizontal velocity x slope):

  * filled contours of the smallest stroke margin of all struts (or another metric, --metric),
  * the bottoming-out boundary (margin = the campaign's min_stroke_margin criterion),
  * the tip-over boundary and the tipped-over cases, and the boundary of successful landings,
  * failed or invalid cases (crosses), and the successful / unsuccessful cases.

It also prints the envelope as a table: for each slope, the largest horizontal velocity up to
which every case of the grid landed successfully. Further grid parameters (e.g. yaw) are reduced
by their worst case (smallest margin, any tip-over) unless fixed with --fix LABEL=VALUE.

Axes carry engineering labels (e.g. "horizontal velocity along global +x, uphill [m/s]").
Exit status 0, 1 on a usage error, 2 when the file is not a grid campaign summary with the two
parameters, 4 when the figure cannot be written.
"""
import os
import sys

import numpy as np

import h5py
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from . import cli  # noqa: E402
from .campaign import input_label  # noqa: E402
from .schema import CAMPAIGN_SCHEMA  # noqa: E402

SCHEMA = CAMPAIGN_SCHEMA.encode()
METRICS = {  # dataset under /cases: (label, scale to the plotted unit, unit)
    "min_stroke_margin": ("smallest stroke margin", 1000.0, "mm"),
    "peak_overload": ("peak overload", 1.0, "g"),
    "final_tilt": ("final tilt", 1.0, "deg"),
    "max_tilt": ("largest tilt", 1.0, "deg"),
    "peak_penetration": ("largest footpad penetration", 1000.0, "mm"),
    "max_slide_distance": ("largest footpad slide", 1.0, "m"),
    "min_body_clearance": ("body clearance", 1.0, "m"),
}


class Error(Exception):
    pass


def text(x):
    s = x.decode() if isinstance(x, bytes) else str(x)
    return "" if s == "(none)" else s


def load(path):
    try:
        f = h5py.File(path, "r")
    except OSError as exc:
        raise Error(f"{path}: cannot open ({exc})") from None
    with f:
        if f.attrs.get("schema_version") != SCHEMA:
            raise Error(f"{path}: not a LANDYN campaign summary ({SCHEMA.decode()})")
        d = {
            "mode": text(f.attrs["mode"]),
            "title": text(f.attrs.get("title", b"")),
            "labels": [text(x) for x in f["parameters/label"][()]],
            "names": [text(x) for x in f["parameters/name"][()]],
            "units": [text(x) for x in f["parameters/units"][()]],
            "base_deck_text": text(f["campaign/base_deck_text"][()]) if "campaign/base_deck_text" in f else "",
            "status": f["cases/status"][()],
            "success": f["cases/success"][()],
            "tipped": f["cases/tipped_over"][()],
            "min_margin_crit": float(f["criteria/min_stroke_margin"][()]),
            "cases": {k: f["cases/" + k][()] for k in METRICS},
        }
        d["inputs"] = {lab: f["cases/inputs/" + lab][()] for lab in d["labels"]}
    return d


def pick(d, want, keys):
    if want:
        if want not in d["labels"]:
            raise Error(f"no parameter labelled '{want}'; the campaign varies: {', '.join(d['labels'])}")
        return want
    for lab, name in zip(d["labels"], d["names"]):
        if any(k in name for k in keys):
            return lab
    raise Error(f"cannot tell which parameter is {keys[0]}; give it (--x/--y), one of: {', '.join(d['labels'])}")


def grid(d, xl, yl, metric, fixed):
    """2-D arrays over the unique x and y values, other parameters worst-cased."""
    x = d["inputs"][xl]
    y = d["inputs"][yl]
    keep = np.ones(len(x), bool)
    for lab, val in fixed.items():
        if lab not in d["inputs"]:
            raise Error(f"--fix {lab}: no such parameter")
        keep &= np.isclose(d["inputs"][lab], val)
    if not keep.any():
        raise Error("--fix selects no case")
    xs = np.unique(x[keep])
    ys = np.unique(y[keep])
    shape = (len(ys), len(xs))
    m = np.full(shape, np.nan)
    tip = np.zeros(shape)
    ok = np.ones(shape, bool)
    bad = np.zeros(shape, bool)
    seen = np.zeros(shape, bool)
    vals = d["cases"][metric]
    worst = np.nanmax if metric in ("peak_overload", "final_tilt", "max_tilt", "peak_penetration",
                                    "max_slide_distance") else np.nanmin
    for k in np.nonzero(keep)[0]:
        i = np.searchsorted(ys, y[k])
        j = np.searchsorted(xs, x[k])
        seen[i, j] = True
        if d["status"][k] != 0:
            bad[i, j] = True
            ok[i, j] = False
            continue
        m[i, j] = vals[k] if np.isnan(m[i, j]) else worst([m[i, j], vals[k]])
        tip[i, j] = max(tip[i, j], d["tipped"][k])
        ok[i, j] &= d["success"][k] == 1
    ok &= seen
    return xs, ys, m, tip, ok, bad, seen


def envelope(xs, ys, ok):
    """For each slope: the largest x such that every grid point with x' <= x succeeded."""
    out = []
    for i, yv in enumerate(ys):
        best = None
        for j in range(len(xs)):
            if not ok[i, j]:
                break
            best = xs[j]
        out.append((yv, best))
    return out


def _main(argv=None):
    ap = cli.make_parser("landyn-envelope", __doc__)
    ap.add_argument("summary", help="summary file of a grid campaign (landyn_batch)")
    ap.add_argument("-o", "--output", help="figure file (default <summary stem>_stability.png)")
    ap.add_argument("--x", help="label of the horizontal-velocity parameter (default: the one varying velocity(1|2))")
    ap.add_argument("--y", help="label of the slope parameter (default: the one varying terrain%%slope)")
    ap.add_argument("--metric", default="min_stroke_margin", choices=sorted(METRICS),
                    help="contoured metric (default min_stroke_margin)")
    ap.add_argument("--fix", action="append", default=[], metavar="LABEL=VALUE",
                    help="hold another grid parameter at a value instead of taking its worst case")
    ap.add_argument("--dpi", type=cli.positive_int, default=150)
    ap.add_argument("--title")
    a = ap.parse_args(argv)
    if a.output:                      # before the work: never an input, and a format matplotlib writes
        cli.refuse_overwrite(a.output, [a.summary])
        cli.figure_format(a.output)
    try:
        d = load(a.summary)
        if d["mode"] != "grid":
            raise Error(f"{a.summary}: a {d['mode']} campaign; the envelope needs a grid campaign")
        xl = pick(d, a.x, ("velocity(1)", "velocity(2)", "velocity"))
        yl = pick(d, a.y, ("terrain%slope(",))
        if xl == yl:
            raise Error("--x and --y name the same parameter")
        fixed = {}
        for spec in a.fix:
            lab, _, val = spec.partition("=")
            try:
                fixed[lab] = float(val)
            except ValueError:
                raise Error(f"--fix {spec}: expected LABEL=VALUE")
        xs, ys, m, tip, ok, bad, seen = grid(d, xl, yl, a.metric, fixed)
    except Error as exc:
        print(f"landyn-envelope: error: {exc}", file=sys.stderr)
        return 2
    if len(xs) < 2 or len(ys) < 2:
        print("landyn-envelope: error: the grid needs at least 2 values of each parameter", file=sys.stderr)
        return 2
    xu = d["units"][d["labels"].index(xl)]
    yu = d["units"][d["labels"].index(yl)]
    mlabel, scale, munit = METRICS[a.metric]
    X, Y = np.meshgrid(xs, ys)
    fig, ax = plt.subplots(figsize=(8, 6.8))
    z = m * scale
    if np.isfinite(z).sum() >= 3:
        cf = ax.contourf(X, Y, np.ma.masked_invalid(z), levels=14, cmap="viridis")
        fig.colorbar(cf, ax=ax, label=f"{mlabel} [{munit}]")
        if a.metric == "min_stroke_margin":
            lim = d["min_margin_crit"] * scale
            if np.nanmin(z) < lim < np.nanmax(z):
                cs = ax.contour(X, Y, np.ma.masked_invalid(z), levels=[lim], colors="red", linewidths=2)
                ax.clabel(cs, fmt={lim: f"margin {lim:g} mm"}, fontsize=8)
    if tip.max() > 0 and tip.min() < 1:
        ct = ax.contour(X, Y, tip, levels=[0.5], colors="white", linewidths=2.5, linestyles="--")
        ax.clabel(ct, fmt={0.5: "tip-over"}, fontsize=8)
    good = seen & ok
    ax.plot(X[good], Y[good], "o", mfc="white", mec="black", ms=6, label="successful landing")
    fail = seen & ~ok & ~bad & (tip < 0.5)
    ax.plot(X[fail], Y[fail], "s", mfc="none", mec="orange", ms=7, label="criteria not met")
    ax.plot(X[tip >= 0.5], Y[tip >= 0.5], "v", color="red", ms=7, label="tipped over")
    ax.plot(X[bad], Y[bad], "x", color="black", ms=8, mew=2, label="no result (invalid/failed run)")
    env = envelope(xs, ys, ok)
    if ok.any() and not ok[seen].all():
        ax.contour(X, Y, ok.astype(float), levels=[0.5], colors="black", linewidths=1.8)
        ax.plot([], [], color="black", lw=1.8, label="success boundary")
    ex = [e[1] for e in env if e[1] is not None]
    ey = [e[0] for e in env if e[1] is not None]
    if ex:
        ax.plot(ex, ey, "D", color="black", ms=5, label="envelope: largest velocity, all successful")
    dx = 0.03 * (xs[-1] - xs[0])
    dy = 0.03 * (ys[-1] - ys[0])
    ax.set_xlim(xs[0] - dx, xs[-1] + dx)
    ax.set_ylim(ys[0] - dy, ys[-1] + dy)
    names = dict(zip(d["labels"], d["names"]))
    ax.set_xlabel(input_label(names[xl], xu, d["base_deck_text"], d["names"]))
    ax.set_ylabel(input_label(names[yl], yu, d["base_deck_text"], d["names"]))
    ttl = a.title or (d["title"] or os.path.basename(a.summary)) + " - landing stability envelope"
    if fixed:
        ttl += "\n" + ", ".join(f"{k} = {v:g}" for k, v in fixed.items())
    elif len(d["labels"]) > 2:
        ttl += "\n(worst case over " + ", ".join(lab for lab in d["labels"] if lab not in (xl, yl)) + ")"
    ax.set_title(ttl, fontsize=10)
    ax.legend(loc="upper center", bbox_to_anchor=(0.5, -0.13), ncol=3, fontsize=8, frameon=False)
    # <stem>_stability.png: the example campaign envelope.h5 gave envelope_envelope.png
    out = a.output or os.path.splitext(os.path.basename(a.summary))[0] + "_stability.png"
    try:
        cli.refuse_overwrite(out, [a.summary])
    except cli.LandynWriteError as exc:
        print(f"landyn-envelope: error: {exc}", file=sys.stderr)
        return cli.EXIT_WRITE
    fig.tight_layout()
    try:
        cli.savefig(fig, out, dpi=a.dpi)
    except cli.LandynWriteError as exc:
        print(f"landyn-envelope: error: {exc}", file=sys.stderr)
        return cli.EXIT_WRITE
    plt.close(fig)
    print(f"Stability envelope of {a.summary}: largest {xl} [{xu}] with every case successful up to it")
    print(f"  {yl + ' [' + yu + ']':>28}  {xl + ' [' + xu + ']':>28}")
    for yv, xv in env:
        print(f"  {yv:28.4g}  {('none' if xv is None else f'{xv:.4g}'):>28}")
    print(f"Figure written to {out}")
    return 0


if __name__ == "__main__":
    sys.exit(main())


def main(argv=None):
    """landyn-envelope: one error line and exit status 2 for any input it cannot process."""
    return cli.run("landyn-envelope", _main, argv)
