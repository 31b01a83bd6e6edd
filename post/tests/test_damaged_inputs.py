"""Damaged inputs, bad options and outputs that name inputs (issue 25, items 8 and 9).

Every failure of every tool is one ``<tool>: error:`` line on stderr and a documented exit status
(post/README.md, docs/exit_status.md): 2 invalid input, 1 usage error, 4 output refused or not
written; never a traceback. An output never replaces an input, an HDF5 file, a directory or a
device (docs/files.md).
"""
from __future__ import annotations

import shutil

import h5py
import numpy as np
import pytest


def _one_error(r, status, *words):
    assert "Traceback" not in r.stderr and "Traceback" not in r.stdout, r
    assert r.returncode == status, r
    msg = [ln for ln in r.stderr.splitlines() if "error:" in ln]
    assert len(msg) == 1, r
    for w in words:
        assert w in msg[0], (w, r)


def _copy(src, tmp_path, name):
    p = tmp_path / name
    shutil.copy(src, p)
    return p


def _truncated(src, tmp_path):
    p = tmp_path / "truncated.h5"
    data = src.read_bytes()
    p.write_bytes(data[: len(data) // 2])
    return p


def _text_for_numbers(src, tmp_path, path):
    p = _copy(src, tmp_path, "strings.h5")
    with h5py.File(p, "a") as f:
        shape = f[path].shape
        del f[path]
        f[path] = np.full(shape, b"oops", dtype="S4")
    return p


RESULT_TOOLS = [("plot", ()), ("export", ()), ("animate", ("--still", "0.1")), ("compare", ("--tol-mm", "1"))]


def _args(tool, extra, path, other):
    return [path, other, *extra] if tool == "compare" else [path, *extra]


@pytest.mark.parametrize("tool,extra", RESULT_TOOLS)
def test_truncated_result(tool, extra, lc1_short, tmp_path, run_tool):
    bad = _truncated(lc1_short, tmp_path)
    _one_error(run_tool(tool, *_args(tool, extra, bad, lc1_short), cwd=tmp_path), 2)


@pytest.mark.parametrize("tool,extra", RESULT_TOOLS)
def test_text_where_numbers_belong(tool, extra, lc1_short, tmp_path, run_tool):
    bad = _text_for_numbers(lc1_short, tmp_path, "/timeseries/body/position")
    _one_error(run_tool(tool, *_args(tool, extra, bad, lc1_short), cwd=tmp_path), 2, "/timeseries/body/position")


@pytest.mark.parametrize("tool,extra", RESULT_TOOLS)
def test_bit_flipped_result(tool, extra, lc1_short, tmp_path, run_tool):
    """Bytes of the file's metadata overwritten (after the superblock): an error line or a clean run."""
    data = bytearray(lc1_short.read_bytes())
    rng = np.random.default_rng(25)
    for seed in range(4):
        p = tmp_path / f"flip{seed}.h5"
        d = bytearray(data)
        for k in rng.integers(96, min(len(d), 40000), 64):
            d[k] ^= 0xFF
        p.write_bytes(bytes(d))
        r = run_tool(tool, *_args(tool, extra, p, lc1_short), cwd=tmp_path)
        assert "Traceback" not in r.stderr, r
        assert r.returncode in (0, 2, 3, 5), r
        if r.returncode == 2:
            _one_error(r, 2)


def test_animate_nan_data(lc1_short, tmp_path, run_tool):
    p = _copy(lc1_short, tmp_path, "nan.h5")
    with h5py.File(p, "a") as f:
        f["/timeseries/body/position"][...] = np.nan
    _one_error(run_tool("animate", p, "--still", "0.1", cwd=tmp_path), 2)


@pytest.mark.parametrize("tool", ["envelope", "dispersion", "export"])
def test_campaign_without_cases(tool, grid_campaign, tmp_path, run_tool):
    p = _copy(grid_campaign, tmp_path, "nocases.h5")
    with h5py.File(p, "a") as f:
        del f["/cases"]
    _one_error(run_tool(tool, p, cwd=tmp_path), 2)


@pytest.mark.parametrize("tool", ["envelope", "dispersion", "export"])
def test_campaign_with_zero_rows(tool, mc_campaign, grid_campaign, tmp_path, run_tool):
    src = grid_campaign if tool == "envelope" else mc_campaign
    p = _copy(src, tmp_path, "zero.h5")
    with h5py.File(p, "a") as f:
        for name in list(f["/cases"]):
            ds = f["/cases"][name]
            if isinstance(ds, h5py.Dataset) and ds.ndim >= 1:
                data = ds[()][:0]
                del f["/cases"][name]
                f["/cases"][name] = data
    r = run_tool(tool, p, cwd=tmp_path)
    assert "Traceback" not in r.stderr, r
    assert r.returncode in (0, 2), r          # an empty table may be exported; a figure cannot be made
    if r.returncode == 2:
        _one_error(r, 2)


@pytest.mark.parametrize("content", [bytes(range(256)) * 4, "time,x\n0,1\n".encode("utf-16")])
def test_binary_or_utf16_map(content, lc1_short, tmp_path, run_tool):
    ref = tmp_path / "ref.csv"
    ref.write_text("time,x\n0,1\n0.1,2\n")
    m = tmp_path / "bad.map"
    m.write_bytes(content)
    r = run_tool("compare", lc1_short, ref, "--timeseries", "--map", m, "--tol-rms", "1mm", cwd=tmp_path)
    _one_error(r, 2)


@pytest.mark.parametrize("tool,args", [
    ("plot", ["--dpi", "0"]), ("plot", ["--dpi", "-3"]), ("animate", ["--dpi", "0", "--still", "0.1"]),
    ("animate", ["--fps", "nan"]), ("dispersion", ["--bins", "-1"]), ("dispersion", ["--dpi", "0"]),
    ("envelope", ["--dpi", "0"]), ("envelope", ["-o", "x.h5"]), ("dispersion", ["-o", "x.xyz"]),
])
def test_bad_options_are_usage_errors(tool, args, lc1_short, mc_campaign, grid_campaign, tmp_path, run_tool):
    src = {"dispersion": mc_campaign, "envelope": grid_campaign}.get(tool, lc1_short)
    _one_error(run_tool(tool, src, *args, cwd=tmp_path), 1)
    assert not (tmp_path / "x.h5").exists() and not (tmp_path / "x.xyz").exists()


def test_compare_table_csv_never_replaces_an_input(lc1_short, tmp_path, run_tool):
    v = _copy(lc1_short, tmp_path, "v.h5")
    before = v.read_bytes()
    r = run_tool("compare", v, v, "--tol-mm", "1", "--table-csv", v, cwd=tmp_path)
    _one_error(r, 4, "refusing")
    assert v.read_bytes() == before
    # a CSV reference is an input too, and so is the map
    ref = tmp_path / "ref.csv"
    ref.write_text("measure,gear,strut,x_mm\n1,1,primary,60\n")
    before = ref.read_bytes()
    r = run_tool("compare", v, ref, "--column", "x", "--tol-mm", "1", "--table-csv", ref, cwd=tmp_path)
    _one_error(r, 4, "input")
    assert ref.read_bytes() == before


def test_outputs_follow_the_file_policy(lc1_short, grid_campaign, tmp_path, run_tool):
    other = _copy(lc1_short, tmp_path, "other.h5")          # an HDF5 file that is not an input
    before = other.read_bytes()
    _one_error(run_tool("export", lc1_short, "-o", other, cwd=tmp_path), 4, "HDF5")
    link = tmp_path / "link.png"
    link.symlink_to(other)                                  # through a link: still the HDF5 file
    _one_error(run_tool("envelope", grid_campaign, "-o", link, cwd=tmp_path), 4, "HDF5")
    assert other.read_bytes() == before
    _one_error(run_tool("export", lc1_short, "-o", "/dev/null", cwd=tmp_path), 4, "not a regular file")
    ro = tmp_path / "ro.csv"
    ro.write_text("keep\n")
    ro.chmod(0o444)
    _one_error(run_tool("export", lc1_short, "-o", ro, cwd=tmp_path), 4, "read-only")
    assert ro.read_text() == "keep\n"
    d = tmp_path / "adir"
    d.mkdir()
    _one_error(run_tool("export", lc1_short, "-o", d, cwd=tmp_path), 4, "directory")


def test_export_replaces_its_own_outputs_but_never_an_input(lc1_short, tmp_path, run_tool):
    """--tables DIR is a directory output; the XDMF mesh (HDF5) replaces the previous mesh, never an input."""
    src = _copy(lc1_short, tmp_path, "r.h5")
    for _ in range(2):                                      # a second run replaces the first one's files
        r = run_tool("export", src, "--tables", "--mat", "--xdmf", cwd=tmp_path)
        assert r.returncode == 0, r
    assert (tmp_path / "r_mesh.h5").is_file() and (tmp_path / "r_tables").is_dir()
    m = _copy(lc1_short, tmp_path, "a_mesh.h5")
    before = m.read_bytes()
    _one_error(run_tool("export", m, "--xdmf", "a.xdmf", cwd=tmp_path), 4, "input")
    assert m.read_bytes() == before
    notes = tmp_path / "n_mesh.h5"
    notes.write_text("my notes\n")                          # an HDF5 output never replaces text
    _one_error(run_tool("export", src, "--xdmf", "n.xdmf", cwd=tmp_path), 4, "not an HDF5 file")
    assert notes.read_text() == "my notes\n"
