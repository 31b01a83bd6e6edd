"""Output files follow the user's umask (issue 24): every PNG, PDF, CSV, MAT and XDMF the tools
write is readable by the group and others under umask 022, as landyn's own .h5 is."""
from __future__ import annotations

import os
import stat
import subprocess
import sys

import pytest

from conftest import POST

from landyn_post import files


def _run(tool: str, umask: int, *args, cwd):
    """Runs a tool in a child process with the given umask (the umask is per process)."""
    code = (f"import os, sys; os.umask({umask:#o}); sys.argv = ['landyn-{tool}'] + {list(map(str, args))!r}; "
            f"sys.path.insert(0, {str(POST)!r}); import runpy; "
            f"runpy.run_path({str(POST / f'landyn_{tool}.py')!r}, run_name='__main__')")
    p = subprocess.run([sys.executable, "-c", code], cwd=cwd, capture_output=True, text=True, timeout=300,
                       env=dict(os.environ, MPLBACKEND="Agg"))
    assert p.returncode == 0, p.stdout + p.stderr
    return [line for line in p.stdout.splitlines() if line and os.path.isfile(os.path.join(cwd, line))]


def _mode(path) -> int:
    return stat.S_IMODE(os.stat(path).st_mode)


def test_default_mode_follows_umask():
    old = os.umask(0o027)
    try:
        assert files.current_umask() == 0o027
        assert files.default_mode() == 0o640
    finally:
        os.umask(old)


@pytest.mark.parametrize("umask,want", [(0o022, 0o644), (0o027, 0o640)])
def test_every_writer_follows_umask(lc1_short, tmp_path, umask, want):
    h5 = tmp_path / "run.h5"
    h5.write_bytes(lc1_short.read_bytes())
    out = []
    out += _run("plot", umask, h5, "-o", "plots", "--only", "strokes", "--format", "png", "pdf", "--report",
                cwd=tmp_path)
    out += _run("export", umask, h5, "--mat", "--xdmf", "--tables", "--summary", "-o", "run.csv", cwd=tmp_path)
    assert any(f.endswith(".png") for f in out) and any(f.endswith(".pdf") for f in out)
    assert any(f.endswith(".mat") for f in out) and any(f.endswith(".csv") for f in out)
    assert any(f.endswith(".xdmf") for f in out)
    for f in out:
        assert _mode(tmp_path / f) == want, f"{f}: mode {_mode(tmp_path / f):o}, umask {umask:o}"
    assert not list(tmp_path.rglob("*.partial")), "temporary files left behind"
