"""landyn-export: rows, unit-bearing column names, values."""
from __future__ import annotations

import csv
import re

import numpy as np
import pytest

from landyn_post import load

UNIT_SUFFIX = re.compile(r"_(s|m|m_per_s|deg|deg_per_s|g|N|J)$")


def _read(path):
    with open(path, newline="") as fh:
        rows = list(csv.reader(fh))
    return rows[0], np.array(rows[1:], dtype=float)


def test_wide_table(lc1_short, tmp_path, run_tool):
    out = tmp_path / "ts.csv"
    r = run_tool("export", lc1_short, "-o", out)
    assert r.returncode == 0, r
    res = load(lc1_short)
    header, data = _read(out)
    assert data.shape[0] == res.n_samples
    assert header[0] == "time_s"
    for name in ("gear1_primary_stroke_m", "gear4_secondary_right_strut_force_N", "gear2_normal_force_N",
                 "gear3_footpad_position_z_m", "body_velocity_z_m_per_s", "body_euler_angles_pitch_deg",
                 "body_angular_rate_q_deg_per_s", "body_overload_z_g", "energy_honeycomb_work_J"):
        assert name in header, name
    assert all(UNIT_SUFFIX.search(h) for h in header), [h for h in header if not UNIT_SUFFIX.search(h)]
    assert len(set(header)) == len(header)
    np.testing.assert_allclose(data[:, header.index("gear1_primary_stroke_m")], res.stroke[:, 0, 0], rtol=1e-10,
                               atol=1e-14)
    np.testing.assert_allclose(data[:, 0], res.time, rtol=1e-12)


def test_per_gear_and_summary(lc3_short, tmp_path, run_tool):
    out = tmp_path / "csv"
    r = run_tool("export", lc3_short, "--per-gear", "--summary", "-o", out)
    assert r.returncode == 0, r
    res = load(lc3_short)
    for g in range(1, res.n_gears + 1):
        header, data = _read(out / f"lc3_short_gear{g}.csv")
        assert data.shape[0] == res.n_samples
        assert header[0] == "time_s" and all(h.startswith(f"gear{g}_") for h in header[1:])
    header, data = _read(out / "lc3_short_body.csv")
    assert data.shape[0] == res.n_samples and not any(h.startswith("gear") for h in header)
    with open(out / "lc3_short_crush.csv", newline="") as fh:
        rows = list(csv.DictReader(fh))
    assert len(rows) == 3 * res.n_gears
    assert float(rows[1]["crush_mm"]) == pytest.approx(res.crush_length[0, 1] * 1e3, abs=1e-6)
