"""landyn-compare: self-comparison, perturbed reference, the paper's Table 3, time histories."""
from __future__ import annotations

import csv

import pytest

from landyn_post import load


def _table(path):
    with open(path, newline="") as fh:
        return {int(r["measure"]): r for r in csv.DictReader(fh)}


def test_self_comparison_is_zero(lc3_short, tmp_path, run_tool):
    table = tmp_path / "dev.csv"
    r = run_tool("compare", lc3_short, lc3_short, "--tol-mm", "0", "--tol-pct", "0", "--tol-rms", "0m", "0N",
                 "0m/s", "0deg", "0g", "--table-csv", table)
    assert r.returncode == 0, r
    rows = _table(table)
    assert len(rows) == 12
    assert all(float(row["deviation_mm"]) == 0.0 for row in rows.values())
    assert "all 12" not in r.stdout and "checks passed" in r.stdout
    assert all(row["result"] == "pass" and float(row["allowed_mm"]) == 0.0 for row in rows.values())
    # every time-history line reports zero rms and max deviation
    deviations = r.stdout.split("Correlation metrics")[0]       # the deviation table, not the metrics table
    lines = [ln for ln in deviations.splitlines() if ln.startswith(("stroke[", "strut_force[", "normal_force["))]
    assert len(lines) == 4 * 3 * 2 + 4
    assert all(float(ln.split()[2]) == 0.0 and float(ln.split()[3]) == 0.0 for ln in lines)


def test_perturbed_reference(lc1_short, tmp_path, run_tool):
    """Export the crush summary, add 5 mm to measure 5 (gear 2 secondary left): 5 mm deviation, exit 3."""
    r = run_tool("export", lc1_short, "--summary", "-o", tmp_path / "ts.csv")
    assert r.returncode == 0, r
    src = tmp_path / "lc1_short_crush.csv"
    with open(src, newline="") as fh:
        rows = list(csv.reader(fh))
    k = [row[0] for row in rows].index("5")
    rows[k][3] = f"{float(rows[k][3]) + 5.0:.6f}"
    ref = tmp_path / "perturbed.csv"
    with open(ref, "w", newline="") as fh:
        csv.writer(fh).writerows(rows)

    ok = run_tool("compare", lc1_short, src, "--tol-mm", "1")
    assert ok.returncode == 0, ok
    table = tmp_path / "dev.csv"
    bad = run_tool("compare", lc1_short, ref, "--tol-mm", "1", "--table-csv", table)
    assert bad.returncode == 3, bad
    assert "FAILED: crush No. 5" in bad.stdout and bad.stdout.count("FAILED:") == 1
    dev = {m: float(row["deviation_mm"]) for m, row in _table(table).items()}
    assert dev[5] == pytest.approx(-5.0, abs=1e-5)
    assert all(abs(v) < 1e-5 for m, v in dev.items() if m != 5)
    verdict = {m: row["result"] for m, row in _table(table).items()}
    assert verdict[5] == "FAIL" and all(v == "pass" for m, v in verdict.items() if m != 5)
    # percent tolerance alone: 5 mm of ~55 mm is ~9 %
    assert run_tool("compare", lc1_short, ref, "--tol-pct", "10").returncode == 0
    assert run_tool("compare", lc1_short, ref, "--tol-pct", "5").returncode == 3


def test_table3_lc1_within_3_percent(lc1_full, table3_csv, tmp_path, run_tool):
    table = tmp_path / "dev.csv"
    plots = tmp_path / "plots"
    r = run_tool("compare", lc1_full, table3_csv, "--load-case", "LC-1", "--column", "theory", "--tol-pct", "3",
                 "--table-csv", table, "--plots", plots)
    assert r.returncode == 0, r
    rows = _table(table)
    assert sorted(rows) == list(range(1, 13))
    assert max(abs(float(row["deviation_pct"])) for row in rows.values()) < 3.0
    assert float(rows[1]["reference_mm"]) == 287.0
    assert (plots / "compare_crush_lengths.png").stat().st_size > 5000


def test_timeseries_round_trip_and_map(lc1_short, tmp_path, run_tool):
    """An exported CSV compares to its source with ~zero rms; a mapped CSV in other units too."""
    wide = tmp_path / "wide.csv"
    assert run_tool("export", lc1_short, "-o", wide).returncode == 0
    r = run_tool("compare", lc1_short, wide, "--timeseries", "--tol-rms", "1e-5m", "1e-3N", "1e-5m/s", "1e-5deg",
                 "1e-5deg/s", "1e-5g", "1e-3J")
    assert r.returncode == 0, r

    res = load(lc1_short)
    t = res.time[::2]
    stroke_mm = res.stroke[::2, 0, 0] * 1e3 + 2.0          # a 2 mm offset
    fn_kn = res.normal_force[::2, 1] / 1e3
    ref = tmp_path / "drop.csv"
    with open(ref, "w", newline="") as fh:
        fh.write("# synthetic drop test, ms / mm / kN\n")
        w = csv.writer(fh)
        w.writerow(["t_ms", "LG1_P_mm", "LG2_FN_kN"])
        for row in zip(t * 1e3, stroke_mm, fn_kn):
            w.writerow([f"{v:.9g}" for v in row])
    mapf = tmp_path / "drop.map"
    mapf.write_text("time = t_ms * 0.001\n"
                    "LG1_P_mm  = stroke[gear=1,strut=primary] * 0.001   # mm -> m\n"
                    "LG2_FN_kN = normal_force[gear=2] * 1000 tol=1e9\n")
    plots = tmp_path / "plots"
    r = run_tool("compare", lc1_short, ref, "--timeseries", "--map", mapf, "--tol-rms", "0.001", "--plots", plots)
    assert r.returncode == 3, r          # the 2 mm offset exceeds 1 mm rms; the force has its own tol
    line = next(ln for ln in r.stdout.splitlines() if ln.startswith("LG1_P_mm"))
    rms, max_dev = float(line.split()[4]), float(line.split()[5])
    assert rms == pytest.approx(2.0, rel=0.05) and max_dev >= rms      # the table is in mm (engineering unit)
    assert r.stdout.count("FAILED:") == 1
    assert (plots / "compare_01_stroke_gear_1_strut_primary.png").stat().st_size > 5000
    assert (plots / "compare_02_normal_force_gear_2.png").stat().st_size > 5000
    r = run_tool("compare", lc1_short, ref, "--timeseries", "--map", mapf, "--tol-rms", "0.003")
    assert r.returncode == 0, r
