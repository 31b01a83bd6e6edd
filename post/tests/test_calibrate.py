"""landyn-calibrate: recovers known parameters from a reference LANDYN made with perturbed ones,
reports what is not identifiable, writes the calibrated deck and never overwrites an input.

Runs are short (t_end = 0.3 s, LC-1, the crushing is over by 0.15 s), two LANDYN processes at a time."""
from __future__ import annotations

import re
import subprocess

import pytest

from landyn_post.calibrate import Variable, get_value, parse_variable, set_value

TRUE = {"primary_strut%stage_force(1)": 84000.0, "secondary_strut%force_lengthening": 40000.0}
BOUNDS = {"primary_strut%stage_force(1)": (60000.0, 100000.0), "secondary_strut%force_lengthening": (30000.0, 55000.0)}


@pytest.fixture(scope="module")
def perturbed(landyn_exe, tmp_path_factory):
    d = tmp_path_factory.mktemp("calibrate")
    (d / "base.nml").write_text("&simulation t_end = 0.3 /\n")
    (d / "pert.nml").write_text("&simulation t_end = 0.3 /\n&primary_strut stage_force = 84000.0, 156000.0 /\n"
                                "&secondary_strut force_lengthening = 40000.0 /\n")
    p = subprocess.run([landyn_exe, str(d / "pert.nml"), "-o", str(d / "pert.h5"), "--quiet"], capture_output=True)
    assert p.returncode == 0
    return d


def test_recovers_known_parameters(perturbed, landyn_exe, run_tool):
    """From the defaults (78 kN, 43 kN) back to the perturbed values (84 kN, 40 kN) within 0.1 % of
    each variable's range (40 N, 25 N); the calibrated deck reproduces the reference."""
    d = perturbed
    before = (d / "base.nml").read_bytes()
    args = ["--case", d / "base.nml", d / "pert.h5", "--sigma-mm", "0.1", "--output-dir", d / "cal",
            "--landyn", landyn_exe]
    for name, (lo, hi) in BOUNDS.items():
        args += ["--param", name, lo, hi]
    r = run_tool("calibrate", *args, timeout=600)
    assert r.returncode == 0, r
    for name, true in TRUE.items():
        lo, hi = BOUNDS[name]
        m = re.search(re.escape(name) + r"\s+\S+\s+(\S+)\s+\S+\s+(\S+) \.\. (\S+)", r.stdout)
        fitted, ci_lo, ci_hi = map(float, m.groups())
        assert abs(fitted - true) <= 1e-3 * (hi - lo), (name, fitted)
    assert "every variable identifiable" in r.stdout
    assert "landyn-calibrate: Jacobian:" in r.stderr and "runs" in r.stderr       # progress on stderr
    deck = d / "cal" / "base_calibrated.nml"
    text = deck.read_text()
    assert abs(get_value(text, parse_variable("primary_strut%stage_force(1)", "0", "1")) - 84000) < 40
    assert (d / "base.nml").read_bytes() == before
    p = subprocess.run([landyn_exe, str(deck), "-o", str(d / "check.h5"), "--quiet"], capture_output=True)
    assert p.returncode == 0
    r2 = run_tool("compare", d / "check.h5", d / "pert.h5", "--tol-mm", "0.01")
    assert r2.returncode == 0, r2


def test_a_variable_without_effect_is_reported_not_identifiable(perturbed, landyn_exe, run_tool):
    """contact%restitution is unused by the 'base' contact law: its column of the Jacobian is zero."""
    d = perturbed
    r = run_tool("calibrate", "--case", d / "base.nml", d / "pert.h5", "--landyn", landyn_exe, "--max-evals", "4",
                 "--param", "secondary_strut%force_lengthening", 30000, 55000,
                 "--param", "contact%restitution", 0.1, 0.9, timeout=600)
    assert r.returncode in (0, 3), r
    assert "contact%restitution: NOT identifiable" in r.stdout
    assert "secondary_strut%force_lengthening: NOT identifiable" not in r.stdout


def test_usage_errors(perturbed, run_tool):
    d = perturbed
    r = run_tool("calibrate", "--case", d / "base.nml", d / "pert.h5", "--param", "mass", 1, 2)
    assert r.returncode == 1 and "group%name" in r.stderr, r
    r = run_tool("calibrate", "--case", d / "base.nml", d / "pert.h5", "--param", "lander%mass", 2, 1)
    assert r.returncode == 1 and "LO < HI" in r.stderr, r
    r = run_tool("calibrate", "--case", d / "nothere.nml", d / "pert.h5", "--param", "lander%mass", 1, 2)
    assert r.returncode == 2 and "no such file" in r.stderr, r


def test_set_value_keeps_the_rest_of_the_line():
    text = "&primary_strut\n  stage_force = 2*78000.0, 0.0 ! [N]\n/\n&x\n  y = 1\n/\n"
    v = Variable("primary_strut", "stage_force", 2, 0, 1)
    out = set_value(text, v, 90000.0)
    assert "stage_force = 78000.0, 90000.0, 0.0  ! [N]" in out and get_value(out, v) == 90000.0
    assert "y = 1" in out


def test_recovers_a_parameter_from_time_histories(perturbed, landyn_exe, run_tool, tmp_path):
    """Reference channels instead of crush lengths: the perturbed run's gear-1 stroke and normal force
    written as a drop-test record (ms, mm, kN) with a map; the honeycomb level comes back within
    0.1 % of its range."""
    import csv

    from landyn_post import load
    res = load(perturbed / "pert.h5")
    ref = tmp_path / "drop.csv"
    with open(ref, "w", newline="") as fh:
        w = csv.writer(fh)
        w.writerow(["t_ms", "LG1_P_mm", "LG1_FN_kN"])
        for k in range(res.n_samples):
            w.writerow([f"{res.time[k] * 1e3:.6f}", f"{res.stroke[k, 0, 0] * 1e3:.6f}",
                        f"{res.normal_force[k, 0] / 1e3:.6f}"])
    mapf = tmp_path / "drop.map"
    mapf.write_text("time = t_ms unit=ms\nLG1_P_mm = stroke[gear=1,strut=primary] unit=mm tol=1mm\n"
                    "LG1_FN_kN = normal_force[gear=1] unit=kN tol=5kN\n")
    (tmp_path / "base.nml").write_text("&simulation t_end = 0.3 /\n&secondary_strut force_lengthening = 40000.0 /\n")
    r = run_tool("calibrate", "--case", tmp_path / "base.nml", ref, "--timeseries", "--map", mapf,
                 "--param", "primary_strut%stage_force(1)", 60000, 100000, "--landyn", landyn_exe, timeout=600)
    assert r.returncode == 0, r
    fitted = float(re.search(r"primary_strut%stage_force\(1\)\s+\S+\s+(\S+)", r.stdout).group(1))
    assert abs(fitted - 84000.0) <= 40.0, fitted
