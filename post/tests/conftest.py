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

TOOLS = ("plot", "animate", "compare", "export")


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
