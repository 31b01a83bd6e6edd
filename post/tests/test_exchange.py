"""Exchange formats on files LANDYN produces: results, study files and campaign summaries to CSV,
MATLAB .mat and XDMF; study figure; campaign tools (failure causes, sensitivity, envelope)."""
from __future__ import annotations

import csv
import xml.etree.ElementTree as ET

import h5py
import numpy as np
import pytest
from scipy.io import loadmat

from landyn_post import load
from landyn_post.campaign import input_label, spearman


def _csv(path):
    with open(path, newline="") as fh:
        return list(csv.DictReader(fh))


def _field(struct, *names):
    """A nested MATLAB struct as loadmat returns it: m["a"] is a 1 x 1 array of records."""
    struct = struct[0, 0]
    for n in names:
        struct = struct[n][0, 0]
    return struct


# ----------------------------------------------------------------------------------------- results

def test_run_to_mat(lc3_short, tmp_path, run_tool):
    out = tmp_path / "r.mat"
    r = run_tool("export", lc3_short, "--mat", out)
    assert r.returncode == 0, r
    res = load(lc3_short)
    m = loadmat(out)
    ts = m["timeseries"][0, 0]
    assert ts["time"].shape == (res.n_samples, 1)                       # a column vector
    stroke = _field(m["timeseries"], "gears")["stroke"]
    assert stroke.shape == (res.n_samples, res.n_gears, 3)              # sample index first
    np.testing.assert_array_equal(stroke, res.stroke)
    assert str(_field(m["timeseries"], "gears", "units")["stroke"][0]) == "m"
    np.testing.assert_array_equal(m["summary"][0, 0]["crush_length"], res.crush_length)
    assert "sample or case index first" in str(m["landyn_info"][0])
    assert str(m["meta"][0, 0]["deck_name"][0]).endswith("lc3_short.nml")


def test_run_to_xdmf_for_paraview(lc3_short, tmp_path, run_tool):
    out = tmp_path / "lc3.xdmf"
    r = run_tool("export", lc3_short, "--xdmf", out)
    assert r.returncode == 0, r
    res = load(lc3_short)
    heavy = tmp_path / "lc3_mesh.h5"
    root = ET.parse(out).getroot()
    colls = root.findall("./Domain/Grid")
    assert [c.get("Name") for c in colls] == ["struts", "footpads"]
    assert all(c.get("CollectionType") == "Temporal" for c in colls)
    steps = colls[0].findall("Grid")
    assert len(steps) == res.n_samples
    assert float(steps[7].find("Time").get("Value")) == pytest.approx(res.time[7])
    with h5py.File(heavy, "r") as f:
        # every HDF reference of the XDMF names a dataset of the right size
        for di in root.iter("DataItem"):
            if di.get("Format") == "HDF":
                fname, ds = di.text.strip().split(":")
                assert fname == heavy.name
                assert tuple(int(x) for x in di.get("Dimensions").split()) == f[ds].shape, ds
        pts, conn, part = f["points"][()], f["connectivity"][()], f["part"][()]
        # the primary struts (a-d lines) have the stored strut lengths at every sample
        prim = conn[part == 1]
        lengths = np.linalg.norm(pts[:, prim[:, 0]] - pts[:, prim[:, 1]], axis=-1)
        np.testing.assert_allclose(lengths, res.strut_length[:, :, 0], atol=1e-9)
        sec = conn[part == 2]
        np.testing.assert_allclose(np.linalg.norm(pts[:, sec[:, 0]] - pts[:, sec[:, 1]], axis=-1),
                                   res.strut_length[:, :, 1], atol=1e-9)
        # height up: footpad heights are -z of the result
        np.testing.assert_allclose(f["footpads"][()][..., 2], -res.footpad_position[..., 2])
        force = f["strut_force"][()]
        np.testing.assert_allclose(force[:, -3 * res.n_gears:], res.strut_force.reshape(res.n_samples, -1) / 1e3)


def test_run_tables_and_no_overwrite(lc1_short, tmp_path, run_tool):
    r = run_tool("export", lc1_short, "--tables", tmp_path / "t")
    assert r.returncode == 0, r
    res = load(lc1_short)
    rows = _csv(tmp_path / "t" / "lc1_short_summary.csv")
    assert len(rows) == res.n_gears and [int(x["gear"]) for x in rows] == [1, 2, 3, 4]
    assert float(rows[1]["secondary_left_crush_length_m"]) == pytest.approx(res.crush_length[1, 1], rel=1e-11)
    sc = {x["path"]: x for x in _csv(tmp_path / "t" / "lc1_short_scalars.csv")}
    assert float(sc["/summary/peak_overload"]["value"]) == pytest.approx(res.peak_overload, rel=1e-11)
    assert sc["/summary/peak_overload"]["units"] == "g" and "/summary/final_attitude/pitch" in sc
    assert sc["/meta/git_revision"]["value"] == res.git_revision       # provenance travels along
    before = lc1_short.read_bytes()
    r = run_tool("export", lc1_short, "--mat", lc1_short)
    assert r.returncode == 4 and "refusing to overwrite" in r.stderr, r   # the output-file policy: exit 4
    assert lc1_short.read_bytes() == before


def test_interface_loads_equilibrium_and_peak_table(lc3_short, tmp_path, run_tool):
    """Interface loads on LC-3 (sloped ground, yawed and tilted lander): the three joint forces add
    up to the gear's total force on the body at every sample; the exported peak-load table has a row
    per gear, joint and quantity, its peak is the load of its own simultaneous set, and it is at
    least the largest stored sample (the table is taken over every step)."""
    res = load(lc3_short)
    total = res.joint_force_a + res.joint_force_b + res.joint_force_c
    scale = np.abs(res.interface_force).max()
    assert scale > 1e4                                   # real loads (N)
    np.testing.assert_allclose(total, res.interface_force, rtol=0, atol=1e-9 * scale)
    # gear axes: the lander-axes vector turned by the gear's rotation about z
    rot = np.radians(res.hard_points()["rotation"])
    for i in range(res.n_gears):
        c, s_ = np.cos(rot[i]), np.sin(rot[i])
        r = np.array([[c, -s_, 0.0], [s_, c, 0.0], [0.0, 0.0, 1.0]])       # gear frame -> lander frame
        np.testing.assert_allclose(res.data["gear_axes/joint_force_b"][:, i] @ r.T, res.joint_force_b[:, i],
                                   atol=1e-9 * scale)
    # the names of the table as the reader returns them: lists of strings
    assert res.data["peak_joint_load/load_names"][:4] == ("Fa_x", "Fa_y", "Fa_z", "Fb_x")
    assert res.data["peak_joint_load/joint_names"] == ("a", "b", "c", "d")
    assert res.data["health/checks"][0] and isinstance(res.data["health/checks"], tuple)
    r = run_tool("export", lc3_short, "--tables", tmp_path / "t")
    assert r.returncode == 0, r
    rows = _csv(tmp_path / "t" / "lc3_short_peak_joint_loads.csv")
    assert len(rows) == res.n_gears * 4 * 4
    stored = {"a": res.joint_force_a, "b": res.joint_force_b, "c": res.joint_force_c, "d": res.footpad_joint_force}
    for row in rows:
        g, j, q = int(row["gear"]) - 1, row["joint"], row["quantity"]
        peak = float(row["peak_kN"])
        hist = stored[j][:, g]
        if q == "magnitude":
            own = np.linalg.norm([float(row[f"F{j}_{c}_kN"]) for c in "xyz"])
            assert own == pytest.approx(peak, rel=1e-9)
            assert peak >= np.linalg.norm(hist, axis=1).max() / 1e3 * (1 - 1e-11)   # CSV: 12 digits
        else:
            assert float(row[f"F{j}_{q}_kN"]) == pytest.approx(peak, rel=1e-9)
            assert abs(peak) >= np.abs(hist[:, "xyz".index(q)]).max() / 1e3 * (1 - 1e-11)   # CSV: 12 digits
        assert 0.0 <= float(row["time_s"]) <= 0.4


# ----------------------------------------------------------------------------------------- studies

def test_study_export_and_figure(study_file, tmp_path, run_tool):
    r = run_tool("export", study_file, "-o", tmp_path / "csv")
    assert r.returncode == 0, r
    with h5py.File(study_file, "r") as f:
        tab = f["table/crush_length"][()]
        variants = [x.decode() for x in f["study/variant_label"][()]]
        lc2 = f["variants/002/LC-2/crush_length"][()]
    rows = _csv(tmp_path / "csv" / "small_study_table.csv")
    assert len(rows) == tab.shape[0] == 9
    assert float(rows[0]["crush_length_Base_result_m"]) == pytest.approx(tab[0, 0], rel=1e-11)
    assert float(rows[4]["crush_length_Hertz_m"]) == pytest.approx(tab[4, 1], rel=1e-11)
    runs = _csv(tmp_path / "csv" / "small_study_runs.csv")
    assert len(runs) == 2 * len(variants)
    hz = next(x for x in runs if x["variant_label"] == "Hertz" and x["load_case"] == "LC-2")
    assert float(hz["gear3_secondary_left_crush_length_m"]) == pytest.approx(lc2[2, 1], rel=1e-11)
    r = run_tool("export", study_file, "--mat", tmp_path / "s.mat")
    assert r.returncode == 0, r
    m = loadmat(tmp_path / "s.mat")
    np.testing.assert_array_equal(m["table"][0, 0]["crush_length"], tab)
    np.testing.assert_array_equal(_field(m["variants"], "v002", "LC_2")["crush_length"], lc2)
    r = run_tool("plot", study_file, "-o", tmp_path / "p")
    assert r.returncode == 0, r
    png = tmp_path / "p" / "small_study_study.png"
    assert png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n" and png.stat().st_size > 20000
    r = run_tool("export", study_file, "--xdmf")
    assert r.returncode == 1 and "apply to result files" in r.stderr, r


# ----------------------------------------------------------------------------------------- campaigns

def test_campaign_export(mc_campaign, tmp_path, run_tool):
    r = run_tool("export", mc_campaign, "-o", tmp_path / "csv")
    assert r.returncode == 0, r
    with h5py.File(mc_campaign, "r") as f:
        n = int(f.attrs["n_rows"])
        fc = f["cases/failed_criteria"][()]
        names = [x.decode() for x in f["cases/failed_criteria_names"][()]]
        crush = f["cases/crush_length"][()]
        mu = f["cases/inputs/mu"][()]
    rows = _csv(tmp_path / "csv" / "mc_cases.csv")
    assert len(rows) == n == 8
    assert list(rows[0])[:4] == ["case_id", "status", "success", "failed_criteria_names"]
    assert [x["failed_criteria_names"] for x in rows] == [s.strip() for s in names]
    assert [int(x["failed_criteria"]) for x in rows] == list(fc)
    assert float(rows[5]["gear2_secondary_right_crush_length_m"]) == pytest.approx(crush[5, 1, 2], rel=1e-11)
    assert float(rows[3]["inputs_mu"]) == pytest.approx(mu[3], rel=1e-11)
    prob = _csv(tmp_path / "csv" / "mc_probability.csv")
    assert [x["failure_criterion"] for x in prob][:2] == ["tipped_over", "stroke_margin"]
    r = run_tool("export", mc_campaign, "--mat", tmp_path / "c.mat")
    assert r.returncode == 0, r
    m = loadmat(tmp_path / "c.mat")
    assert m["cases"][0, 0]["crush_length"].shape == (8, 4, 3)
    np.testing.assert_array_equal(_field(m["cases"], "inputs")["mu"].ravel(), mu)


def test_dispersion_failure_causes_and_sensitivity(mc_campaign, tmp_path, run_tool):
    with h5py.File(mc_campaign, "r") as f:
        fc = f["cases/failed_criteria"][()]
        v1 = f["cases/inputs/initial_state.velocity_3"][()]
        margin = f["cases/min_stroke_margin"][()]
    assert np.any(fc != 0), "the criteria are chosen so that some cases fail"
    out = tmp_path / "mc_dispersion.png"
    r = run_tool("dispersion", mc_campaign, "-o", out, "--inputs", "--sensitivity")
    assert r.returncode == 0, r
    assert out.stat().st_size > 20000 and (tmp_path / "mc_sensitivity.png").stat().st_size > 20000
    n_margin = int(np.sum((fc & 2) != 0))
    line = next(ln for ln in r.stdout.splitlines() if "stroke margin (bottoming out)" in ln)
    assert int(line.split()[-1]) == n_margin
    rho, _, _ = spearman(v1, margin)
    line = next(ln for ln in r.stdout.splitlines() if ln.strip().startswith("vertical touchdown velocity, down"))
    assert f"{rho:+.3f}" in line
    assert "horizontal velocity along global +x, uphill [m/s]" in r.stdout


def test_envelope_installed_tool(grid_campaign, tmp_path, run_tool):
    out = tmp_path / "env.png"
    r = run_tool("envelope", grid_campaign, "-o", out)
    assert r.returncode == 0, r
    assert out.stat().st_size > 20000
    assert "largest initial_state.velocity_1" in r.stdout
    r = run_tool("envelope", grid_campaign, "-o", grid_campaign)
    assert r.returncode == 4 and "refusing to overwrite" in r.stderr   # the output-file policy: exit 4


def test_input_labels():
    assert input_label("initial_state%velocity(1)", "m/s", "") == "horizontal velocity along global +x, uphill [m/s]"
    assert input_label("initial_state%velocity(1)", "m/s", "&terrain slope_direction = 4*180.0 /") == \
        "horizontal velocity along global +x, downhill [m/s]"
    assert input_label("terrain%slope(:)", "deg") == "terrain slope [deg]"
    assert input_label("friction%mu_dynamic", "-") == "dynamic friction coefficient [-]"
    assert input_label("gears%point_d(3, 1)", "m") == "gears%point_d(3, 1) [m]"


def test_pyproject_installs_the_campaign_tools():
    import pathlib
    text = (pathlib.Path(__file__).resolve().parents[1] / "pyproject.toml").read_text()
    for tool in ("landyn-envelope", "landyn-dispersion"):
        assert f'{tool} = "landyn_post.' in text
