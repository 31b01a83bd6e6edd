"""Fixtures: result files produced by the LANDYN executable itself.

The executable is $LANDYN_EXE, else the newest <repo>/build*/landyn or <repo>/build*/*/landyn
(e.g. build/release/landyn), else `landyn` on PATH; the tests are skipped (with the reason) when
none is found. Runs are shortened to t_end = 0.4 s, except the full LC-1 run that is compared
with the paper's Table 3.
"""
from __future__ import annotations

import glob
import os
import re
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

POST = Path(__file__).resolve().parents[1]
REPO = POST.parent
sys.path.insert(0, str(POST))

TOOLS = ("plot", "animate", "compare", "export", "envelope", "dispersion", "calibrate")


def _find_landyn() -> tuple[str | None, str]:
    env = os.environ.get("LANDYN_EXE")
    if env:
        if os.path.isfile(env) and os.access(env, os.X_OK):
            return env, ""
        pytest.fail(f"LANDYN_EXE={env} is not an executable file")
    cands = [p for pat in ("build*/landyn", "build*/*/landyn") for p in glob.glob(str(REPO / pat))
             if os.path.isfile(p) and os.access(p, os.X_OK)]
    if cands:
        return max(cands, key=os.path.getmtime), ""
    on_path = shutil.which("landyn")
    if on_path:
        return on_path, ""
    return None, (f"LANDYN executable not found: set LANDYN_EXE, or build it into {REPO}/build*/ "
                  "(cmake -S . -B build && cmake --build build), or put landyn on PATH")


@pytest.fixture(scope="session")
def landyn_exe() -> str:
    exe, why = _find_landyn()
    if exe is None:
        pytest.skip(why)
    return exe


def _run_landyn(exe: str, deck: Path | None, out: Path) -> Path:
    cmd = [exe] + ([str(deck)] if deck else []) + ["-o", str(out), "--quiet"]
    p = subprocess.run(cmd, cwd=out.parent, capture_output=True, text=True, timeout=600)
    assert p.returncode == 0, f"{' '.join(cmd)} failed ({p.returncode}):\n{p.stdout}\n{p.stderr}"
    assert out.is_file()
    return out


@pytest.fixture(scope="session")
def lc1_short(landyn_exe, tmp_path_factory) -> Path:
    """Default case (LC-1) to t = 0.4 s."""
    d = tmp_path_factory.mktemp("lc1_short")
    deck = d / "lc1_short.nml"
    deck.write_text("&simulation t_end = 0.4 /\n")
    return _run_landyn(landyn_exe, deck, d / "lc1_short.h5")


@pytest.fixture(scope="session")
def lc3_short(landyn_exe, tmp_path_factory) -> Path:
    """LC-3 deck (sloped ground, yaw, tilt) to t = 0.4 s."""
    d = tmp_path_factory.mktemp("lc3_short")
    src = (REPO / "input" / "lc3.nml").read_text()
    text, n = re.subn(r"(?im)^(\s*t_end\s*=\s*)[^!\n]*", r"\g<1>0.4 ", src)
    assert n == 1, "input/lc3.nml: expected one t_end line"
    deck = d / "lc3_short.nml"
    deck.write_text(text)
    return _run_landyn(landyn_exe, deck, d / "lc3_short.h5")


@pytest.fixture(scope="session")
def lc1_full(landyn_exe, tmp_path_factory) -> Path:
    """Default case (LC-1), full 1.0 s run as in the paper."""
    d = tmp_path_factory.mktemp("lc1_full")
    return _run_landyn(landyn_exe, None, d / "lc1_full.h5")


@pytest.fixture(scope="session")
def table3_csv() -> Path:
    """The paper's Table 3 (theory and Adams crush lengths, mm), as kept for the regression tests."""
    p = REPO / "tests" / "regression" / "data" / "table3_crush_lengths.csv"
    if not p.is_file():
        pytest.skip(f"{p} not found")
    return p


def _sibling(landyn_exe: str, name: str) -> str:
    p = os.path.join(os.path.dirname(os.path.abspath(landyn_exe)), name)
    if not (os.path.isfile(p) and os.access(p, os.X_OK)):
        pytest.skip(f"{name} not found next to {landyn_exe} (it is built with the LANDYN executables; "
                    "landyn_batch needs MPI)")
    return p


@pytest.fixture(scope="session")
def study_file(landyn_exe, tmp_path_factory) -> Path:
    """A small landyn_study file: LC-1 and LC-2 for 0.2 s, base and Hertz-contact variants."""
    exe = _sibling(landyn_exe, "landyn_study")
    d = tmp_path_factory.mktemp("study")
    inp = REPO / "input"
    (d / "small.nml").write_text(f"""&study
  title = 'pytest study'
  base_deck = '{inp}/lc1.nml', '{inp}/lc2.nml'
  case_label = 'LC-1', 'LC-2'
  common = "&simulation t_end = 0.2, dt = 1.0e-5 /"
  output = 'small_study.h5'
  csv = 'small_study.csv'
/
&variant label = 'Base result' /
&variant label = 'Hertz', set = "&contact law = 'hertz' /" /
""")
    p = subprocess.run([exe, "small.nml", "--quiet"], cwd=d, capture_output=True, text=True, timeout=600)
    assert p.returncode == 0, p.stdout + p.stderr
    return d / "small_study.h5"


def _campaign(landyn_exe, tmp_path_factory, name: str, deck: str) -> Path:
    exe = _sibling(landyn_exe, "landyn_batch")
    d = tmp_path_factory.mktemp(name)
    (d / "base.nml").write_text((REPO / "tests" / "campaign" / "base.nml").read_text())
    (d / f"{name}.nml").write_text(deck)
    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    p = subprocess.run([exe, f"{name}.nml", "-q"], cwd=d, capture_output=True, text=True, timeout=600, env=env)
    assert p.returncode == 0, p.stdout + p.stderr
    return d / f"{name}.h5"


@pytest.fixture(scope="session")
def mc_campaign(landyn_exe, tmp_path_factory) -> Path:
    """A Monte Carlo campaign of 8 short cases (landyn_batch on one rank) with a tight margin
    criterion, so that some cases fail."""
    return _campaign(landyn_exe, tmp_path_factory, "mc", """&campaign
  title = 'pytest Monte Carlo', base_deck = 'base.nml', mode = 'monte_carlo', n_samples = 8, seed = 7
  summary_file = 'mc.h5'
/
&parameter name = 'initial_state%velocity(1)', distribution = 'uniform', lo = 0.0, hi = 2.0 /
&parameter name = 'initial_state%velocity(3)', distribution = 'uniform', lo = 3.5, hi = 4.5 /
&parameter name = 'friction%mu_dynamic', label = 'mu', distribution = 'uniform', lo = 0.2, hi = 0.5 /
&criteria min_stroke_margin = 0.12, max_overload = 3.8 /
""")


@pytest.fixture(scope="session")
def grid_campaign(landyn_exe, tmp_path_factory) -> Path:
    """A 3 x 2 grid over horizontal velocity and slope."""
    return _campaign(landyn_exe, tmp_path_factory, "grid", """&campaign
  title = 'pytest grid', base_deck = 'base.nml', mode = 'grid', summary_file = 'grid.h5'
/
&parameter name = 'initial_state%velocity(1)', values = 0.0, 1.0, 2.0 /
&parameter name = 'terrain%slope(:)', values = 0.0, 8.0 /
&criteria min_stroke_margin = 0.12 /
""")


class ToolRun:
    def __init__(self, p: subprocess.CompletedProcess):
        self.returncode, self.stdout, self.stderr = p.returncode, p.stdout, p.stderr

    def __repr__(self):
        return f"exit {self.returncode}\n--- stdout\n{self.stdout}\n--- stderr\n{self.stderr}"


@pytest.fixture(scope="session")
def run_tool():
    """run_tool('plot', args..., cwd=dir) runs `python3 post/landyn_plot.py args` (the wrapper)."""

    def run(tool: str, *args, cwd=None, timeout=300) -> ToolRun:
        assert tool in TOOLS
        env = dict(os.environ, MPLBACKEND="Agg")
        p = subprocess.run([sys.executable, str(POST / f"landyn_{tool}.py"), *map(str, args)], cwd=cwd,
                           capture_output=True, text=True, timeout=timeout, env=env)
        return ToolRun(p)

    return run
