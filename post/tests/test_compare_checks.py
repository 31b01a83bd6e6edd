"""landyn-compare cannot pass by accident: unmatched channels, --strict, per-channel tolerances with
units, allowed/pass columns, load-case warnings, exit statuses (0/1/2/3/5)."""
from __future__ import annotations

import csv
from pathlib import Path

import numpy as np
import pytest

import landyn_post
from landyn_post import load

POST = Path(__file__).resolve().parents[1]


def test_package_is_this_tree():
    """The tests exercise this working tree's landyn_post, not an installed copy."""
    assert Path(landyn_post.__file__).resolve().parent == POST / "landyn_post"


@pytest.fixture(scope="module")
def exported(lc1_short, tmp_path_factory, run_tool):
    d = tmp_path_factory.mktemp("exported")
    wide = d / "wide.csv"
    r = run_tool("export", lc1_short, "-o", wide)
    assert r.returncode == 0, r
    return wide


ALL_UNITS = ("1e-5m", "1e-3N", "1e-3N m", "1e-5m/s", "1e-5deg", "1e-5deg/s", "1e-5g", "1e-3J")


def test_renamed_column_fails_by_default_and_is_listed_with_allow_unmatched(lc1_short, exported, tmp_path,
                                                                           run_tool):
    """A reference with one column renamed (as a heritage code would name it): by default the
    comparison fails naming the column (exit 3) although every other check passes; with
    --allow-unmatched the column is listed as not compared (exit 0); --strict fails again."""
    lines = exported.read_text().splitlines()
    assert "gear2_primary_stroke_m" in lines[0].split(",")
    lines[0] = lines[0].replace("gear2_primary_stroke_m", "LG2_primary_stroke_mm")
    ref = tmp_path / "renamed.csv"
    ref.write_text("\n".join(lines) + "\n")
    r = run_tool("compare", lc1_short, ref, "--timeseries", "--rtol-rms", "1", "--tol-rms", *ALL_UNITS)
    assert r.returncode == 3, r
    assert "FAILED: reference channel 'LG2_primary_stroke_mm' not compared" in r.stdout
    assert r.stdout.count("FAILED:") == 1
    assert "gear2_primary_stroke_m" not in r.stdout          # the channel was really not compared
    r = run_tool("compare", lc1_short, ref, "--timeseries", "--tol-rms", *ALL_UNITS, "--allow-unmatched")
    assert r.returncode == 0, r
    assert "without a tolerance" not in r.stdout         # every unit has one, the joint moments' N m included
    assert "Reference channels NOT compared (1): LG2_primary_stroke_mm" in r.stdout
    assert "--strict makes these a failure" in r.stdout
    strict = run_tool("compare", lc1_short, ref, "--timeseries", "--tol-rms", *ALL_UNITS, "--strict",
                      "--allow-unmatched")
    assert strict.returncode == 3, strict
    assert "FAILED: --strict: reference channel 'LG2_primary_stroke_mm' not compared" in strict.stdout
    assert strict.stdout.count("FAILED:") == 1


def test_map_lists_unmapped_columns(lc1_short, tmp_path, run_tool):
    res = load(lc1_short)
    ref = tmp_path / "drop.csv"
    with open(ref, "w", newline="") as fh:
        w = csv.writer(fh)
        w.writerow(["t_ms", "LG1_P_mm", "LG1_F_kN", "LG3_P_mm"])
        for k in range(0, res.n_samples, 2):
            w.writerow([res.time[k] * 1e3, res.stroke[k, 0, 0] * 1e3 + 0.5, res.strut_force[k, 0, 0] / 1e3 * 1.01,
                        res.stroke[k, 2, 0] * 1e3])
    mapf = tmp_path / "drop.map"
    mapf.write_text("time = t_ms unit=ms\n"
                    "LG1_P_mm = stroke[gear=1,strut=primary] unit=mm tol=1mm\n"
                    "LG1_F_kN = strut_force[gear=1,strut=primary] unit=kN tol=0.5kN rtol=2%\n")
    table = tmp_path / "dev.csv"
    plots = tmp_path / "plots"
    r = run_tool("compare", lc1_short, ref, "--timeseries", "--map", mapf, "--table-csv", table, "--plots", plots,
                 "--allow-unmatched")
    assert r.returncode == 0, r
    assert "Reference channels NOT compared (1): LG3_P_mm" in r.stdout and "not listed in the map" in r.stdout
    assert "Struts NOT checked (11 of 12" in r.stdout
    with open(table, newline="") as fh:
        rows = {row["channel"].split(" -> ")[0]: row for row in csv.DictReader(fh)}
    assert set(rows) == {"LG1_P_mm", "LG1_F_kN"}
    # 0.5 mm offset: rms 0.5 mm (in m), allowed 1 mm converted to m
    assert float(rows["LG1_P_mm"]["rms_deviation"]) == pytest.approx(5e-4, rel=0.05)
    assert float(rows["LG1_P_mm"]["allowed_rms"]) == pytest.approx(1e-3, rel=1e-12)
    # allowed = 0.5 kN + 2 % of the reference's range, in N
    rng = float(rows["LG1_F_kN"]["reference_range"])
    assert rng == pytest.approx(np.ptp(res.strut_force[::2, 0, 0]) * 1.01, rel=1e-6)
    assert float(rows["LG1_F_kN"]["allowed_rms"]) == pytest.approx(500.0 + 0.02 * rng, rel=1e-9)
    assert all(row["result"] == "pass" for row in rows.values())
    # one figure per channel
    assert sorted(p.name for p in plots.glob("compare_*.png")) == [
        "compare_01_stroke_gear_1_strut_primary.png", "compare_02_strut_force_gear_1_strut_primary.png"]
    # tighten the stroke tolerance below the offset: that row fails, exit 3
    mapf.write_text(mapf.read_text().replace("tol=1mm", "tol=0.2mm"))
    r = run_tool("compare", lc1_short, ref, "--timeseries", "--map", mapf, "--table-csv", table, "--allow-unmatched")
    assert r.returncode == 3, r
    assert "FAILED: time history LG1_P_mm" in r.stdout and r.stdout.count("FAILED:") == 1
    # --strict also fails on the unmapped column
    r = run_tool("compare", lc1_short, ref, "--timeseries", "--map", mapf, "--strict")
    assert r.stdout.count("FAILED:") == 2 and "LG3_P_mm" in r.stdout and r.returncode == 3


def test_no_tolerance_is_not_a_pass(lc1_short, exported, run_tool):
    r = run_tool("compare", lc1_short, exported, "--timeseries")
    assert r.returncode == 5, r
    assert "NOTHING CHECKED" in r.stdout and "passed" not in r.stdout


def test_bare_rms_tolerance_over_mixed_units_is_a_usage_error(lc1_short, exported, run_tool):
    r = run_tool("compare", lc1_short, exported, "--timeseries", "--tol-rms", "0.002")
    assert r.returncode == 1, r
    assert "has no unit" in r.stderr and "Traceback" not in r.stderr


def test_relative_tolerance_scales_with_the_channel(lc1_short, lc3_short, tmp_path, run_tool):
    """--rtol-rms is relative to each reference's range, so one number serves strokes (m) and forces
    (N); crush lengths without --tol-mm/--tol-pct are listed as compared without a tolerance."""
    ch = ["stroke[gear=1,strut=primary]", "strut_force[gear=1,strut=primary]"]
    r = run_tool("compare", lc1_short, lc1_short, "--channels", *ch, "--rtol-rms", "0")
    assert r.returncode == 0, r
    assert "all 2 checks passed (12 compared without a tolerance)" in r.stdout
    table = tmp_path / "t.csv"
    r = run_tool("compare", lc3_short, lc1_short, "--channels", *ch, "--rtol-rms", "5", "--table-csv", table)
    with open(tmp_path / "t_timeseries.csv", newline="") as fh:
        rows = list(csv.DictReader(fh))
    # the CSV holds 9 significant digits (relative rounding <= 5e-9 per number): compare to 2e-8
    for row in rows:
        assert float(row["allowed_rms"]) == pytest.approx(0.05 * float(row["reference_range"]), rel=2e-8)
    res = load(lc1_short)
    assert float(rows[1]["reference_range"]) == pytest.approx(np.ptp(res.strut_force[:, 0, 0]), rel=1e-8)
    assert r.returncode == (3 if any(row["result"] == "FAIL" for row in rows) else 0), r


def test_partial_table3_names_unchecked_struts(lc1_short, table3_csv, tmp_path, run_tool):
    rows = [ln for ln in table3_csv.read_text().splitlines() if not ln.startswith("#")]
    keep = [rows[0]] + [ln for ln in rows[1:] if ln.startswith("LC-1,") and ln.split(",")[1] in ("1", "2", "3")]
    ref = tmp_path / "three.csv"
    ref.write_text("\n".join(keep) + "\n")
    r = run_tool("compare", lc1_short, ref, "--column", "theory", "--tol-pct", "50")
    assert r.returncode == 0, r
    assert "Struts NOT checked (9 of 12, no reference crush length)" in r.stdout
    assert "No. 4 gear 2 primary" in r.stdout and "all 3 checks passed" in r.stdout
    r = run_tool("compare", lc1_short, ref, "--column", "theory", "--tol-pct", "50", "--strict")
    assert r.returncode == 3 and r.stdout.count("FAILED: --strict: strut") == 9, r


def test_load_case_mismatch_warns(lc3_short, table3_csv, run_tool):
    r = run_tool("compare", lc3_short, table3_csv, "--load-case", "LC-1", "--column", "theory", "--tol-pct", "1000")
    assert "warning: the result was run for LC-3 (its touchdown conditions), but the reference rows are LC-1" \
        in r.stderr, r
    assert "title names LC-3" in r.stderr
    ok = run_tool("compare", lc3_short, table3_csv, "--load-case", "LC-3", "--column", "theory", "--tol-pct", "1000")
    assert "warning" not in ok.stderr, ok


def test_two_runs_different_titles_warn(lc1_short, lc3_short, run_tool):
    r = run_tool("compare", lc1_short, lc3_short, "--tol-mm", "1000", "--channels", "velocity[comp=z]",
                 "--tol-rms", "10m/s")
    assert r.returncode == 0, r
    assert "the titles differ" in r.stderr and "run for LC-1" in r.stderr and "reference for LC-3" in r.stderr
