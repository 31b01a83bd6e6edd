"""The reader against files LANDYN writes: schema drift, shapes, input read-back, geometry."""
from __future__ import annotations

import h5py
import numpy as np
import pytest

from conftest import REPO
from landyn_post import load
from landyn_post.geometry import lander_geometry, lug_length_error
from landyn_post.namelist import parse_namelist
from landyn_post.schema import DATASETS, ROOT_ATTRIBUTES, SCHEMA_VERSION, LandynPostError


def _file_datasets(path):
    out = {}
    with h5py.File(path, "r") as f:
        def visit(name, obj):
            if isinstance(obj, h5py.Dataset):
                u = obj.attrs.get("units")
                out["/" + name] = u.decode() if isinstance(u, bytes) else str(u)
        f.visititems(visit)
        attrs = set(f.attrs)
        version = f.attrs["schema_version"]
    return out, attrs, version.decode() if isinstance(version, bytes) else str(version)


@pytest.mark.parametrize("case", ["lc1_short", "lc3_short"])
def test_file_matches_schema_exactly(case, request):
    """Every dataset LANDYN writes is in schema.DATASETS with the same units, and vice versa."""
    path = request.getfixturevalue(case)
    found, attrs, version = _file_datasets(path)
    expected = {d.path: d.units for d in DATASETS if d.written not in ("api inputs", "summaries")}
    assert set(found) == set(expected), (f"only in file: {sorted(set(found) - set(expected))}, "
                                         f"only in schema.py: {sorted(set(expected) - set(found))}")
    assert {p: u for p, u in found.items()} == expected
    assert {a for a, _ in ROOT_ATTRIBUTES} <= attrs
    assert version == SCHEMA_VERSION


def test_docs_describe_every_dataset():
    text = (REPO / "docs" / "output.md").read_text()
    missing = [d.path for d in DATASETS if f"`{d.path}`" not in text]
    assert not missing, f"docs/output.md does not describe {missing}"
    assert "schema_version" in text


def test_shapes_and_values(lc3_short):
    r = load(lc3_short)
    n, g = r.n_samples, r.n_gears
    assert g == 4 and n == 401
    assert r.time.shape == (n,) and r.time[-1] == pytest.approx(0.4)
    assert r.stroke.shape == (n, g, 3)
    assert r.footpad_position.shape == (n, g, 3)
    assert r.normal_force.shape == (n, g)
    assert r.crush_length.shape == (g, 3)
    assert r.final_attitude.shape == (3,)
    assert isinstance(r.tipped_over, bool) and isinstance(r.end_reason, str)
    assert r.schema_version == SCHEMA_VERSION and r.producer.startswith("LANDYN")
    # summary consistent with the time series: net crush = crushed(+) - crushed(-)
    np.testing.assert_allclose(r.crush_length, r.crushed_positive - r.crushed_negative, atol=1e-12)
    assert set(r.energy) >= {"honeycomb_work", "residual", "input"}


def _without(src, dst, *paths):
    """A copy of result file src without the datasets or groups `paths`."""
    import shutil
    shutil.copyfile(src, dst)
    with h5py.File(dst, "r+") as f:
        for p in paths:
            del f[p]
    return dst


def _with_nonsense_deck(src, dst):
    """A copy of result file src whose /meta deck texts cannot be parsed: what is read from it
    then comes from /model."""
    p = _without(src, dst, "/meta/resolved_input", "/meta/deck_text")
    with h5py.File(p, "r+") as f:
        for k in ("resolved_input", "deck_text"):
            f["/meta/" + k] = np.bytes_(b"&nonsense x = /")
            f["/meta/" + k].attrs["units"] = np.bytes_(b"-")
    return p


def test_capacities_and_terrain_from_model(lc3_short, tmp_path):
    """Capacities, hard points and terrain come from /model: the deck in /meta is not read."""
    r = load(_with_nonsense_deck(lc3_short, tmp_path / "nodeck.h5"))
    cap = r.strut_capacity()
    np.testing.assert_allclose(cap[:, 0, 0], 0.475)
    assert np.all(np.isnan(cap[:, 0, 1]))
    np.testing.assert_allclose(cap[:, 1:, :], 0.27)
    np.testing.assert_allclose(r.terrain()[:, 1], 8.0)
    hp = r.hard_points()
    np.testing.assert_allclose(hp["a"][1], [0.0, 3.89, -2.18], atol=1e-12)   # gear 2 = gear 1 turned 90 deg
    np.testing.assert_allclose(hp["rotation"], [0, 90, 180, 270])
    np.testing.assert_allclose(r.primary_stage_ends(), [0.2, 0.475])
    # the strut frames are orthonormal, z0 along the nominal strut
    fr = hp["strut_frame"]
    np.testing.assert_allclose(np.einsum("gsji,gsjk->gsik", fr, fr), np.broadcast_to(np.eye(3), fr.shape), atol=1e-12)
    z0 = (hp["d"] - hp["a"]) / np.linalg.norm(hp["d"] - hp["a"], axis=1)[:, None]
    np.testing.assert_allclose(fr[:, 0, :, 2], z0, atol=1e-12)


#: LC-3's touchdown conditions (input/lc3.nml; yaw from the deck's pitch conversion, within 0.5 deg)
LC3 = {"v_vertical": 4.0, "v_horizontal": 1.0, "slope": 8.0, "slope_uniform": 1.0, "mu_static": 0.4,
       "mu_dynamic": 0.4, "mass": 16000.0, "gravity": 1.62}


def test_levels_and_touchdown_from_model(lc3_short, tmp_path):
    """Crush levels and touchdown conditions come from /model (schema 1.5): the deck is not read.
    The levels are axial forces, compression +: each primary stage +, a secondary's lengthening
    level -, its shortening level +; the plot's level lines are those."""
    from landyn_post import paper, plot
    r = load(_with_nonsense_deck(lc3_short, tmp_path / "nodeck.h5"))
    rows = r.crush_levels()
    per_gear = [(0, 78000.0, "stage 1"), (0, 156000.0, "stage 2"), (1, -43000.0, "lengthening"),
                (1, 30000.0, "shortening"), (2, -43000.0, "lengthening"), (2, 30000.0, "shortening")]
    assert rows == [(i, k, f, n) for i in range(4) for k, f, n in per_gear]
    lv = plot._crush_levels(r)
    assert lv["primary"] == [(78000.0, "stage 1 78 kN"), (156000.0, "stage 2 156 kN")]
    assert lv["secondary"] == [(-43000.0, "lengthening 43 kN"), (30000.0, "shortening 30 kN")]
    c = paper.touchdown_conditions(r)
    for k, v in LC3.items():
        assert c[k] == pytest.approx(v, abs=1e-9), k
    assert paper.load_case_of(r) == "LC-3"


def test_levels_and_touchdown_deck_fallback(lc3_short, tmp_path):
    """A file older than schema 1.5 (no /model/crush_levels, /model/touchdown, ...): the same levels
    and conditions from /meta/resolved_input; with an unreadable deck, no levels, and the conditions
    raise the reader's error (no load case)."""
    from landyn_post import paper
    new = load(lc3_short)
    added = [d.path for d in DATASETS if d.since == "1.5"]
    p = _without(lc3_short, tmp_path / "old.h5", *added)
    with h5py.File(p, "r+") as f:
        f.attrs["schema_version"] = np.bytes_(b"1.4")
    old = load(p)
    assert not old.has_model_since("1.5") and new.has_model_since("1.5")
    assert old.crush_levels() == new.crush_levels()
    c_old, c_new = paper.touchdown_conditions(old), paper.touchdown_conditions(new)
    assert set(c_old) == set(c_new)
    for k in c_new:
        assert c_old[k] == pytest.approx(c_new[k], abs=1e-9), k
    bad = load(_with_nonsense_deck(p, tmp_path / "old_nodeck.h5"))
    assert bad.crush_levels() == []
    with pytest.raises(LandynPostError, match="resolved_input cannot be read"):
        paper.touchdown_conditions(bad)
    assert paper.load_case_of(bad) is None


def test_file_without_model_group(lc3_short, tmp_path):
    """A file older than schema 1.4 (no /model): a clear error naming the group where the model is
    needed; the + capacity from the summary, as before."""
    p = _without(lc3_short, tmp_path / "old.h5", "/model")
    with h5py.File(p, "r+") as f:
        f.attrs["schema_version"] = np.bytes_(b"1.3")
    r = load(p)
    assert not r.has_model
    for fn in (r.hard_points, r.terrain, lambda: lander_geometry(r)):
        with pytest.raises(LandynPostError, match="no /model group"):
            fn()
    cap = r.strut_capacity()
    np.testing.assert_allclose(cap[:, :, 0], r.crushed_positive + r.stroke_margin)
    with h5py.File(p, "r+") as f:
        f.attrs["schema_version"] = np.bytes_(b"1.4")
    with pytest.raises(LandynPostError, match="missing dataset /model/"):
        load(p)


def test_campaign_schema_defined_once():
    """The campaign summary's schema string: one constant (from the manifest LANDYN writes), used by
    every reader; no module spells it again."""
    import json

    from landyn_post import dispersion, envelope, exchange, schema
    manifest = json.loads((REPO / "post" / "landyn_post" / "data" / "output_schema.json").read_text())
    assert schema.CAMPAIGN_SCHEMA == manifest["campaign_schema"]
    assert envelope.SCHEMA.decode() == dispersion.SCHEMA.decode() == exchange.CAMPAIGN_SCHEMA == schema.CAMPAIGN_SCHEMA
    spelled = [p.name for p in (REPO / "post" / "landyn_post").glob("*.py") if "landyn-campaign-" in p.read_text()]
    assert not spelled, f"the campaign schema string is spelled out in {spelled}"


def test_geometry_rebuild_reproduces_strut_lengths(lc3_short):
    """The lugs rebuilt on the primary's outer tube give the stored secondary lengths exactly."""
    r = load(lc3_short)
    geom = lander_geometry(r)
    assert lug_length_error(r, geom) < 1e-8
    lp = np.linalg.norm(geom.footpad - geom.upper[:, :, 0], axis=-1)
    np.testing.assert_allclose(lp, r.strut_length[:, :, 0], atol=1e-9)


def test_channels(lc1_short):
    r = load(lc1_short)
    c = r.channel("stroke[gear=2,strut=left]")
    assert c.column == "gear2_secondary_left_stroke_m" and c.units == "m"
    np.testing.assert_array_equal(c.values, r.stroke[:, 1, 1])
    assert r.channel("body/velocity[comp=z]").column == "body_velocity_z_m_per_s"
    assert r.channel("energy/friction").column == "energy_friction_J"
    for bad in ("stroke[gear=9,strut=primary]", "stroke[gear=1]", "nonsense", "velocity[comp=w]"):
        with pytest.raises(LandynPostError):
            r.channel(bad)


def test_namelist_subset():
    nl = parse_namelist("""
! comment
&gears
  n_gears = 2
  rotation(1:2) = 0.0, 180.0   ! deg
  point_a(:, 2) = -3.89, 0.0, -2.18
/
&terrain
  height = 4*0.5, 2*0.0
  slope = 1.0d0, 2.5e-1
/
&simulation
  title = 'it''s a test, with comma! not a comment'
  stop_at_rest = .true.
/
""")
    assert nl.get("simulation", "title") == "it's a test, with comma! not a comment"
    assert nl.get("simulation", "stop_at_rest") is True
    np.testing.assert_allclose(nl.array("gears", "rotation", (2,)), [0, 180])
    a = nl.array("gears", "point_a", (3, 2))
    np.testing.assert_allclose(a[:, 1], [-3.89, 0, -2.18])
    assert np.all(np.isnan(a[:, 0]))
    np.testing.assert_allclose(nl.array("terrain", "height", (6,)), [0.5] * 4 + [0, 0])
    np.testing.assert_allclose(nl.array("terrain", "slope", (2,)), [1.0, 0.25])
    assert nl.get("gears", "n_gears") == 2
