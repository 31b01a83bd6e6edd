"""landyn_study files (docs/study.md): the crush length of every measure option for every variant,
as the paper's Figs. 10, 12 and 13 show them (``landyn-plot STUDY.h5``)."""
from __future__ import annotations

import os
import textwrap

import numpy as np

from . import cli
from .schema import LandynFileError

MM = 1.0e3
_STRUT_SHORT = {"primary": "P", "secondary left": "L", "secondary_left": "L", "secondary right": "R",
                "secondary_right": "R", "1": "P", "2": "L", "3": "R"}


def read_study(path: str) -> dict:
    import h5py

    def txt(x):
        return x.decode() if isinstance(x, bytes) else str(x)

    try:
        with h5py.File(path, "r") as f:
            return {
                "title": txt(f.attrs.get("title", b"")),
                "variants": [txt(x) for x in f["study/variant_label"][()]],
                "cases": [txt(x) for x in f["study/case_label"][()]],
                "crush": np.asarray(f["table/crush_length"][()], dtype=float),     # (options, variants) m
                "load_case": [txt(x) for x in f["table/load_case"][()]],
                "gear": np.asarray(f["table/gear"][()], dtype=int),
                "strut": [txt(x) for x in f["table/strut"][()]],
                "status": np.asarray(f["summary/status"][()], dtype=int),          # (cases, variants)
            }
    except KeyError as exc:
        raise LandynFileError(f"{path}: not a complete landyn_study file (missing {exc})") from None


PCT_BASE_MM = 10.0   #: a % deviation is quoted only where the first variant's crush is at least this [mm]


def relative_deviation(crush: np.ndarray, min_base: float = PCT_BASE_MM / MM) -> np.ndarray:
    """(n_options, n_variants - 1) deviation of every further variant from the first in % of the
    first's |crush|, NaN where that is below `min_base` (m): 2.2 mm -> 32.7 mm is +1385 %, a number
    that says nothing and dwarfs every other."""
    base = crush[:, :1]
    with np.errstate(invalid="ignore", divide="ignore"):
        pct = (crush[:, 1:] - base) / np.abs(base) * 100.0
    return np.where(np.abs(base) >= min_base, pct, np.nan)


def fig_study(st: dict):
    """Grouped bars: crush length of each measure option (x) for each variant, and below the
    deviation of every further variant from the first in mm (readable whatever the baseline; the
    largest deviation in % over the options with a base of at least PCT_BASE_MM in the title)."""
    cli.use_agg()
    import matplotlib.pyplot as plt
    crush = st["crush"] * MM
    n_opt, n_var = crush.shape
    fig, (ax, ax2) = plt.subplots(2, 1, figsize=(max(8.0, 0.9 * n_opt + 3), 7.5), sharex=True,
                                  gridspec_kw={"height_ratios": [2, 1]})
    x = np.arange(1, n_opt + 1)
    w = 0.8 / n_var
    hatches = ("", "//", "..", "xx", "\\\\", "--", "++", "oo")
    for j, lab in enumerate(st["variants"]):
        xs = x - 0.4 + w * (j + 0.5)
        ax.bar(xs, crush[:, j], w, label=lab, color=f"C{j % 10}", edgecolor="k", lw=0.4, hatch=hatches[j // 10 % 8])
        bad = ~np.isfinite(crush[:, j])
        if np.any(bad):
            ax.plot(xs[bad], np.zeros(bad.sum()), "x", color="red", ms=8, mew=2)
    ax.axhline(0, color="k", lw=0.6)
    ax.set_ylabel("crush length [mm]\n(primary shortening, secondary lengthening +)")
    ax.legend(fontsize=7, ncol=min(n_var, 4), loc="lower left", bbox_to_anchor=(0.0, 1.0), frameon=False)
    ax.grid(True, axis="y", alpha=0.3)
    dev = crush[:, 1:] - crush[:, :1]      # mm: readable whatever the baseline (a % explodes near 0)
    for j in range(1, n_var):
        ax2.bar(x - 0.4 + w * (j + 0.5), dev[:, j - 1], w, color=f"C{j % 10}", edgecolor="k", lw=0.4,
                hatch=hatches[j // 10 % 8])
    pct = relative_deviation(st["crush"])
    big = np.nanmax(np.abs(pct)) if np.isfinite(pct).any() else 0.0
    if n_var > 1:
        ax2.set_title(f"deviation from '{textwrap.shorten(st['variants'][0], 30)}' in mm (a % explodes where the base "
                      f"is near 0); in %, where the base is at least {PCT_BASE_MM:g} mm: largest {big:.1f} %",
                      fontsize=8, loc="left")
    ax2.axhline(0, color="k", lw=0.6)
    ax2.set_ylabel(f"deviation from\n'{textwrap.shorten(st['variants'][0], 24)}' [mm]")
    ax2.grid(True, axis="y", alpha=0.3)
    ax2.set_xticks(x)
    ax2.set_xticklabels([f"{k}\n{lc}\nG{g}{_STRUT_SHORT.get(s, '?')}" for k, lc, g, s in
                         zip(x, st["load_case"], st["gear"], st["strut"])], fontsize=7)
    ax2.set_xlabel("measure option: load case, G = gear, P primary, L / R secondary left / right")
    failed = int(np.sum(st["status"] != 0))
    note = f"; {failed} run(s) failed (x)" if failed else ""
    fig.suptitle("\n".join(textwrap.wrap(f"Study: {st['title']}", 100)
                           + [f"crush length per measure option and variant (as the paper's Figs. 10, 12, 13){note}"]),
                 fontsize=9)
    fig.tight_layout()
    return fig


def write_study_figures(path: str, outdir: str, formats=("png",), dpi: int = 120) -> list[str]:
    cli.use_agg()
    import matplotlib.pyplot as plt
    st = read_study(path)
    fig = fig_study(st)
    out = [cli.savefig(fig, os.path.join(outdir, f"{cli.stem(path)}_study.{fmt}"), dpi=dpi) for fmt in formats]
    plt.close(fig)
    return out
