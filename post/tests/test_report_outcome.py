"""The report's first page for each outcome class (docs/output.md, "Outcome"): the verdict banner
and the outcome block never call a run that did not touch down, or has not come to rest, a
success. The runs are made by the LANDYN executable (conftest.landyn_exe) from small decks."""
from __future__ import annotations

import subprocess

import matplotlib

matplotlib.use("Agg")

import pytest  # noqa: E402

from landyn_post import load  # noqa: E402
from landyn_post.report import outcome_lines, verdict  # noqa: E402

DECKS = {
    # an upward velocity: no footpad ever touches the ground (landyn exits 7)
    "no_touchdown": ("&simulation t_end = 0.3 /\n&initial_state velocity = 1.0, 0.0, -3.0 /\n", 7),
    # a slow landing on damped regolith with sticking friction: at rest at about 0.6 s
    "at_rest": ("&simulation t_end = 3.0 /\n&contact law = 'regolith', damping = 1.0e5 /\n"
                "&friction law = 'ty4', mu_static = 0.5, mu_dynamic = 0.4 /\n"
                "&initial_state velocity = 0.0, 0.0, 0.5 /\n", 0),
    # LC-1 cut at 0.1 s: still crushing
    "still_moving": ("&simulation t_end = 0.1 /\n", 0),
    # pitched 30 deg, pitching at 90 deg/s: tips over
    "tipped_over": ("&simulation t_end = 3.0 /\n&initial_state velocity = 0.0, 0.0, 1.0, "
                    "attitude = 0.0, 30.0, 0.0, angular_rate = 0.0, 90.0, 0.0 /\n", 0),
}


@pytest.fixture(scope="module", params=sorted(DECKS))
def outcome_run(request, landyn_exe, tmp_path_factory):
    name = request.param
    text, status = DECKS[name]
    d = tmp_path_factory.mktemp(name)
    (d / f"{name}.nml").write_text(text)
    p = subprocess.run([landyn_exe, f"{name}.nml", "-q", "-o", f"{name}.h5"], cwd=d, capture_output=True,
                       text=True, timeout=600)
    assert p.returncode == status, p.stdout + p.stderr
    return name, d / f"{name}.h5"


def test_first_page_outcome(outcome_run, tmp_path, run_tool):
    name, path = outcome_run
    res = load(path)
    block = "\n".join(outcome_lines(res))
    assert block.startswith(f"outcome: {name.replace('_', ' ')}")
    ok, lines = verdict(res)
    head = lines[0]
    if name == "at_rest":
        assert ok and head.startswith("SUCCESSFUL LANDING: at rest")
        assert "tip-over margin" in block and "static friction ratio" in block
    elif name == "still_moving":
        assert not ok and head.startswith("INCONCLUSIVE")
        assert "inconclusive" in block and "body speed" in block
        # a criterion failed besides the motion: a plain failure, not inconclusive
        ok2, lines2 = verdict(res, min_stroke_margin=10.0)
        assert not ok2 and lines2[0].startswith("NOT A SUCCESSFUL LANDING")
    elif name == "no_touchdown":
        assert not ok and head.startswith("NO TOUCHDOWN")
        assert "tip-over margin" not in block
    else:
        assert not ok and head.startswith("NOT A SUCCESSFUL LANDING")
        assert any("[FAILED] no tip-over" in ln for ln in lines)
    # the PDF's first page is written with that banner
    out = tmp_path / "r"
    r = run_tool("plot", path, "-o", out, "--report", "--only", "strokes")
    assert r.returncode == 0, r
    assert (out / f"{name}_report.pdf").read_bytes()[:5] == b"%PDF-"
