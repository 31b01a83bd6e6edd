"""landyn-plot and landyn-animate write every figure (and the report) from real result files."""
from __future__ import annotations

import re

import pytest

from landyn_post.plot import FIGURES


def _pdf_pages(path) -> int:
    return len(re.findall(rb"/Type\s*/Page[^s]", path.read_bytes()))


def test_every_figure_and_report(lc1_short, tmp_path, run_tool):
    out = tmp_path / "plots"
    r = run_tool("plot", lc1_short, "-o", out, "--format", "png", "pdf", "--report")
    assert r.returncode == 0, r
    for name, _, _ in FIGURES:
        for fmt in ("png", "pdf"):
            f = out / f"lc1_short_{name}.{fmt}"
            assert f.is_file() and f.stat().st_size > 5000, f"{f} missing or nearly empty"
    assert (out / "lc1_short_strokes.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    report = out / "lc1_short_report.pdf"
    assert report.read_bytes()[:5] == b"%PDF-"
    assert _pdf_pages(report) >= 2
    # the text (conditions, verdict, tables, provenance) takes one or two pages, then one per figure
    assert 1 + len(FIGURES) <= _pdf_pages(report) <= 2 + len(FIGURES)


def test_figures_sloped_case_default_outdir(lc3_short, run_tool):
    r = run_tool("plot", lc3_short.name, cwd=lc3_short.parent)
    assert r.returncode == 0, r
    out = lc3_short.parent / "lc3_short_plots"
    for name, _, _ in FIGURES:
        assert (out / f"lc3_short_{name}.png").stat().st_size > 5000


def test_animate_still(lc3_short, tmp_path, run_tool):
    png = tmp_path / "still.png"
    r = run_tool("animate", lc3_short, "--still", "0.2", "-o", png)
    assert r.returncode == 0, r
    assert png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n" and png.stat().st_size > 10000


def test_animate_gif_few_frames(lc1_short, tmp_path, run_tool):
    pil = pytest.importorskip("PIL.Image")
    gif = tmp_path / "anim.gif"
    r = run_tool("animate", lc1_short, "--frames", "5", "-o", gif)
    assert r.returncode == 0, r
    with pil.open(gif) as im:
        assert im.format == "GIF" and im.n_frames == 5


def test_animate_still_outside_run(lc1_short, run_tool):
    r = run_tool("animate", lc1_short, "--still", "3.0")
    assert r.returncode == 2 and "outside the run" in r.stderr and "Traceback" not in r.stderr
