"""Exports a reviewer can use as they are (issue 24): --units engineering (mm, kN, kJ, kN m),
component and axis names stored as fields of the MATLAB file, and CSV column names that MATLAB's
readtable keeps unchanged, with their units spelled correctly."""
from __future__ import annotations

import csv
import re

import numpy as np
import pytest

from landyn_post.exchange import matlab_column, units_suffix
from landyn_post.units import to_engineering

SAFE = re.compile(r"^[A-Za-z][A-Za-z0-9_]{0,62}$")


def _header(path):
    with open(path, newline="") as fh:
        return next(csv.reader(fh))


def _table(path):
    with open(path, newline="") as fh:
        rows = list(csv.reader(fh))
    return {h: np.array([float(r[i]) for r in rows[1:]]) for i, h in enumerate(rows[0])}


def test_units_suffix_and_names():
    assert units_suffix("m/s") == "m_per_s" and units_suffix("m/s^2") == "m_per_s2"
    assert units_suffix("N/m^1.5") == "N_per_m1p5" and units_suffix("N/m^n") == "N_per_m_pow_n"
    assert units_suffix("kN m") == "kN_m" and units_suffix("-") == ""
    assert matlab_column("inputs_initial_state.attitude_1_deg") == "inputs_initial_state_attitude_1_deg"
    assert matlab_column("1st") == "x1st" and len(matlab_column("a" * 80)) == 63
    v, u = to_engineering(np.array([0.25]), "m")
    assert u == "mm" and v[0] == pytest.approx(250.0)
    assert to_engineering(np.array([2.0]), "m/s")[1] == "m/s" and to_engineering(np.array([3.0]), "N m")[1] == "kN m"


def test_engineering_units_csv_and_mat(lc3_short, tmp_path, run_tool):
    from scipy.io import loadmat
    r = run_tool("export", lc3_short, "-o", tmp_path / "si.csv")
    assert r.returncode == 0, r
    r = run_tool("export", lc3_short, "--units", "engineering", "-o", tmp_path / "eng.csv",
                 "--mat", tmp_path / "eng.mat")
    assert r.returncode == 0, r
    si, eng = _table(tmp_path / "si.csv"), _table(tmp_path / "eng.csv")
    assert len(si) == len(eng)
    np.testing.assert_allclose(eng["gear1_primary_stroke_mm"], si["gear1_primary_stroke_m"] * 1e3)
    np.testing.assert_allclose(eng["gear2_normal_force_kN"], si["gear2_normal_force_N"] * 1e-3)
    np.testing.assert_allclose(eng["energy_honeycomb_work_kJ"], si["energy_honeycomb_work_J"] * 1e-3)
    np.testing.assert_array_equal(eng["body_velocity_z_m_per_s"], si["body_velocity_z_m_per_s"])
    np.testing.assert_array_equal(eng["body_overload_z_g"], si["body_overload_z_g"])
    m = loadmat(tmp_path / "eng.mat", simplify_cells=True)
    g = m["timeseries"]["gears"]
    assert g["units"]["stroke"] == "mm" and g["units"]["strut_force"] == "kN"
    assert m["landyn_units"] == "engineering"
    np.testing.assert_allclose(g["stroke"][:, 0, 0], si["gear1_primary_stroke_m"] * 1e3)
    # component and axis names are fields, not a text blob
    assert list(g["components"]["stroke"]) == ["primary", "secondary_left", "secondary_right"]
    assert g["dims"]["stroke"] == "sample x gear x strut"
    assert list(m["timeseries"]["body"]["components"]["euler_angles"]) == ["yaw", "pitch", "roll"]
    assert list(m["timeseries"]["body"]["components"]["velocity"]) == ["x", "y", "z"]
    assert list(m["summary"]["components"]["crush_length"]) == ["primary", "secondary_left", "secondary_right"]


def test_campaign_columns_are_matlab_safe(mc_campaign, tmp_path, run_tool):
    from scipy.io import loadmat
    r = run_tool("export", mc_campaign, "-o", tmp_path / "csv", "--mat", tmp_path / "c.mat")
    assert r.returncode == 0, r
    files = list((tmp_path / "csv").glob("*.csv"))
    assert files
    for f in files:
        head = _header(f)
        bad = [h for h in head if not SAFE.match(h)]
        assert not bad and len(set(head)) == len(head), (f.name, bad)
    head = _header(tmp_path / "csv" / "mc_cases.csv")
    assert "inputs_initial_state_velocity_1_m_per_s" in head and "inputs_mu" in head
    m = loadmat(tmp_path / "c.mat", simplify_cells=True)
    assert list(m["cases"]["components"]["crush_length"]) == ["primary", "secondary_left", "secondary_right"]
    assert m["cases"]["dims"]["crush_length"] == "case x gear x strut"
