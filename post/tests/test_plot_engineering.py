"""The figures an engineer expects: strut forces and force-stroke hysteresis, coincident symmetric
curves kept visible, Table 3 reference values, the report's touchdown conditions and verdict, and
the SAE J211 / ISO 6487 CFC filters."""
from __future__ import annotations

import matplotlib

matplotlib.use("Agg")

import numpy as np  # noqa: E402
import pytest  # noqa: E402

from landyn_post import load  # noqa: E402
from landyn_post import plot as lp  # noqa: E402
from landyn_post.filters import cfc_filter  # noqa: E402
from landyn_post.paper import load_case_of, table3  # noqa: E402
from landyn_post.report import touchdown_lines, verdict  # noqa: E402


def _lines(ax):
    return [ln for ln in ax.get_lines() if ln.get_label() and not ln.get_label().startswith("_")]


def test_symmetric_pairs_found_and_drawn_visibly(lc1_short, lc3_short):
    res1, res3 = load(lc1_short), load(lc3_short)
    assert lp.coincident_groups([res1.stroke[:, i, 0] for i in range(4)]) == [[0, 1, 2, 3]]
    assert lp.coincident_groups([res3.stroke[:, i, 0] for i in range(4)]) == [[0, 3], [1, 2]]
    fig = lp.fig_strokes(res3)
    ax = fig.axes[0]
    lines = _lines(ax)
    assert [ln.get_label() for ln in lines] == ["gear 1", "gear 2", "gear 3", "gear 4"]
    styles = [(ln.get_linestyle(), ln.get_marker(), ln.get_linewidth()) for ln in lines]
    # gear 4 lies on gear 1 and gear 3 on gear 2: the later curve of each pair looks different
    assert styles[3] != styles[0] and styles[2] != styles[1]
    assert lines[3].get_marker() not in ("None", "", None) and lines[2].get_marker() not in ("None", "", None)
    notes = " ".join(t.get_text() for t in fig.texts)
    assert "gear 1 = gear 4" in notes and "gear 2 = gear 3" in notes
    matplotlib.pyplot.close(fig)
    # in LC-1 all four coincide: four different looks
    fig = lp.fig_footpad_forces(res1)
    looks = {(ln.get_linestyle(), ln.get_marker(), ln.get_linewidth()) for ln in _lines(fig.axes[0])}
    assert len(looks) == 4
    assert "footpad 1 = footpad 2 = footpad 3 = footpad 4" in " ".join(t.get_text() for t in fig.texts)
    matplotlib.pyplot.close(fig)


def test_strut_force_and_hysteresis_figures(lc3_short):
    res = load(lc3_short)
    fig = lp.fig_strut_forces(res)
    y = _lines(fig.axes[0])[0].get_ydata()
    np.testing.assert_allclose(y, res.strut_force[:, 0, 0] / 1e3)
    assert "compression +" in fig.axes[0].get_ylabel() and "[kN]" in fig.axes[0].get_ylabel()
    matplotlib.pyplot.close(fig)
    fig = lp.fig_force_stroke(res)
    assert len(fig.axes) == 3 * res.n_gears
    ax = fig.axes[1]                       # gear 1 secondary left
    np.testing.assert_allclose(ax.get_lines()[0].get_xdata(), res.stroke[:, 0, 1] * 1e3)
    np.testing.assert_allclose(ax.get_lines()[0].get_ydata(), res.strut_force[:, 0, 1] / 1e3)
    matplotlib.pyplot.close(fig)


def test_crush_figure_shows_table3_for_a_paper_load_case(lc1_full, lc1_short, table3_csv, tmp_path, run_tool):
    res = load(lc1_full)
    assert load_case_of(res) == "LC-1"
    out = tmp_path / "p"
    r = run_tool("plot", lc1_full, "-o", out, "--only", "crush_lengths")
    assert r.returncode == 0, r

    class A:
        cfc = None
        reference = None
        ref_column = None
        load_case = None
        min_stroke_margin = 0.0
        max_overload = None

    opts = lp.plot_options(A(), res)
    assert opts.crush_ref == table3("LC-1", "theory") and opts.crush_ref[1] == pytest.approx(0.287)
    fig = lp.fig_crush_lengths(res, opts)
    labels = [t.get_text() for t in fig.axes[0].get_legend().get_texts()]
    assert "paper Table 3, LC-1, theory" in labels and "paper Table 3, LC-1, MSC Adams" in labels
    matplotlib.pyplot.close(fig)
    # a reference CSV instead
    A.reference, A.ref_column, A.load_case = str(table3_csv), "adams", "LC-1"
    opts = lp.plot_options(A(), load(lc1_short))
    assert opts.crush_ref[1] == pytest.approx(0.2888) and "adams" in opts.crush_ref_label


def test_report_touchdown_conditions_and_verdict(lc3_short, tmp_path, run_tool):
    res = load(lc3_short)
    lines = "\n".join(touchdown_lines(res))
    assert "LC-3 of the paper" in lines and "vertical 4.000 m/s" in lines and "horizontal 1.000 m/s" in lines
    assert "slope 8.00 deg" in lines and "mu_static 0.4" in lines and "mass 16000 kg" in lines
    # cut at 0.4 s the lander is still moving: inconclusive, never a success (issue 28)
    ok, v = verdict(res)
    assert not ok and v[0].startswith("INCONCLUSIVE")
    assert sum("[FAILED]" in ln for ln in v) == 1 and any("[FAILED] came to rest" in ln for ln in v)
    ok, v = verdict(res, min_stroke_margin=0.2, max_overload=1.0)
    assert not ok and v[0].startswith("NOT A SUCCESSFUL LANDING")
    assert sum("[FAILED]" in ln for ln in v) == 3
    out = tmp_path / "r"
    r = run_tool("plot", lc3_short, "-o", out, "--report", "--min-stroke-margin", "200", "--only", "strokes")
    assert r.returncode == 0, r
    assert (out / "lc3_short_report.pdf").read_bytes()[:5] == b"%PDF-"


def test_cfc_filter_response():
    """Flat to CFC (+0.5/-1 dB, SAE J211 corridor), about -3 dB at 1.65 CFC, strong attenuation a
    decade higher, and phaseless (a smooth pulse keeps its peak time)."""
    fs = 20000.0
    t = np.arange(0.0, 1.0, 1.0 / fs)
    mid = slice(4000, 16000)
    for cfc in (60, 180, 600):
        def gain_db(f):
            y = cfc_filter(t, np.sin(2 * np.pi * f * t), cfc)
            return 20 * np.log10(np.ptp(y[mid]) / 2)
        assert -1.0 <= gain_db(0.1 * cfc) <= 0.5
        assert -1.0 <= gain_db(cfc) <= 0.5
        assert gain_db(1.65 * cfc) == pytest.approx(-3.0, abs=0.6)
        assert gain_db(10 * cfc) < -40
    pulse = np.exp(-((t - 0.5) / 0.01) ** 2)
    f = cfc_filter(t, pulse, 60)
    assert abs(t[np.argmax(f)] - 0.5) < 1.0 / fs


def test_cfc_option_on_a_result(lc1_short, tmp_path, run_tool):
    out = tmp_path / "c"
    r = run_tool("plot", lc1_short, "-o", out, "--only", "body", "--cfc", "60")
    assert r.returncode == 0, r
    res = load(lc1_short)
    opts = lp.PlotOptions(cfc=60)
    fig = lp.fig_body(res, opts)
    assert "CFC 60 (SAE J211-1 / ISO 6487, phaseless 4-pole Butterworth)" in fig.axes[2].get_title(loc="left")
    matplotlib.pyplot.close(fig)
    # 1 ms samples cannot carry CFC 600 (design frequency 1246 Hz > Nyquist 500 Hz): a clear error
    r = run_tool("plot", lc1_short, "-o", out, "--only", "body", "--cfc", "600")
    assert r.returncode == 2 and "CFC 600 needs samples faster than" in r.stderr, r
