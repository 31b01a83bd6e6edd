"""Bad input gives one clear line on stderr and exit status 2 (usage errors 1), never a traceback."""
from __future__ import annotations

import shutil

import h5py
import pytest


def _assert_clean_error(r, *words):
    assert r.returncode == 2, r
    assert "Traceback" not in r.stderr and "Traceback" not in r.stdout, r
    msg = [ln for ln in r.stderr.splitlines() if "error:" in ln]
    assert len(msg) == 1, r
    for w in words:
        assert w in msg[0], (w, r)


@pytest.fixture
def broken_h5(lc1_short, tmp_path):
    p = tmp_path / "broken.h5"
    shutil.copy(lc1_short, p)
    with h5py.File(p, "a") as f:
        del f["/timeseries/gears/stroke"]
    return p


@pytest.fixture
def not_h5(tmp_path):
    p = tmp_path / "notes.h5"
    p.write_text("this is not HDF5\n")
    return p


@pytest.mark.parametrize("tool", ["plot", "animate", "export"])
def test_missing_dataset(tool, broken_h5, run_tool):
    _assert_clean_error(run_tool(tool, broken_h5), "missing dataset /timeseries/gears/stroke")


@pytest.mark.parametrize("tool", ["plot", "animate", "export"])
def test_not_hdf5(tool, not_h5, run_tool):
    _assert_clean_error(run_tool(tool, not_h5), "not an HDF5 file")


def test_compare_not_hdf5_and_missing_dataset(lc1_short, not_h5, broken_h5, run_tool):
    _assert_clean_error(run_tool("compare", not_h5, lc1_short), "not an HDF5 file")
    _assert_clean_error(run_tool("compare", lc1_short, broken_h5), "missing dataset")


def test_wrong_schema_version(lc1_short, tmp_path, run_tool):
    p = tmp_path / "future.h5"
    shutil.copy(lc1_short, p)
    with h5py.File(p, "a") as f:
        f.attrs["schema_version"] = "2.0"
    _assert_clean_error(run_tool("plot", p), "schema_version 2.0")


def test_missing_file(run_tool, tmp_path):
    _assert_clean_error(run_tool("export", tmp_path / "nothere.h5"), "no such file")


@pytest.mark.parametrize("content, words", [
    ("measure,theory_mm\n1,287.0\n2,forty\n", ["line 3", "not a number"]),
    ("measure,theory_mm\n1,287.0,12\n", ["line 2", "fields"]),
    ("# only a comment\n", ["no header"]),
    ("gear,value_mm\n1,3\n", ["measure"]),
    ("measure,theory_mm\n1,287.0\n1,286.0\n", ["appears twice"]),
    ("measure,theory_mm\n13,287.0\n", ["outside 1..12"]),
])
def test_malformed_strut_csv(content, words, lc1_short, tmp_path, run_tool):
    p = tmp_path / "bad.csv"
    p.write_text(content)
    _assert_clean_error(run_tool("compare", lc1_short, p), *words)


def test_table3_needs_column_and_case(lc1_short, table3_csv, run_tool):
    _assert_clean_error(run_tool("compare", lc1_short, table3_csv), "--column")
    _assert_clean_error(run_tool("compare", lc1_short, table3_csv, "--column", "theory"), "--load-case")
    _assert_clean_error(run_tool("compare", lc1_short, table3_csv, "--column", "theory", "--load-case", "LC-9"),
                        "LC-9")


def test_malformed_timeseries_and_map(lc1_short, tmp_path, run_tool):
    ts = tmp_path / "ts.csv"
    ts.write_text("time_s,gear1_primary_stroke_m\n0.0,0.0\n0.0,0.1\n")
    _assert_clean_error(run_tool("compare", lc1_short, ts, "--timeseries"), "strictly increasing")
    ts.write_text("time,foo\n0.0,0.0\n0.1,0.1\n")
    _assert_clean_error(run_tool("compare", lc1_short, ts, "--timeseries"), "--map")
    m = tmp_path / "bad.map"
    m.write_text("foo stroke[gear=1,strut=primary]\n")
    _assert_clean_error(run_tool("compare", lc1_short, ts, "--timeseries", "--map", m), "line 1")
    m.write_text("foo = stroke[gear=7,strut=primary]\n")
    _assert_clean_error(run_tool("compare", lc1_short, ts, "--timeseries", "--map", m), "gear 7")


def test_bad_option(lc1_short, run_tool):
    """A usage error exits 1, as landyn's does."""
    r = run_tool("plot", lc1_short, "--format", "tiff")
    assert r.returncode == 1 and "Traceback" not in r.stderr


@pytest.mark.parametrize("tool", ["plot", "animate", "compare", "export"])
def test_help(tool, run_tool):
    r = run_tool(tool, "--help")
    assert r.returncode == 0 and f"landyn-{tool}" in r.stdout and "usage" in r.stdout
