"""Tests of the Python package landyn (python/landyn) over liblandyn.so (CTest python_api).

Environment: LANDYN_LIBRARY (the library under test), LANDYN_EXE (the landyn program of the same
build, for the comparison of result files); PYTHONPATH holds the source tree's python/.
"""
import copy
import math
import os
import pickle
import re
import subprocess
import threading
from pathlib import Path

import h5py
import numpy as np
import pytest

import landyn
from landyn import (LandynClosedError, LandynError, LandynFileError, LandynInputError, LandynLibraryError,
                    LandynOrderError, LandynOutputNameError, Simulation)

ROOT = Path(__file__).resolve().parents[2]
LC1, LC3 = ROOT / "input" / "lc1.nml", ROOT / "input" / "lc3.nml"
SHORT = "&simulation t_end = 0.2 /"   # overrides for a short run [s]


def short_deck(path):
    """The text of a deck with t_end = 0.2 s (a deck gives each group once: no second &simulation)."""
    text, n = re.subn(r"(?m)^(\s*t_end\s*=\s*)1\.0\b", r"\g<1>0.2", Path(path).read_text())
    assert n == 1
    return text


PROVENANCE = ("meta/command_line", "meta/date", "summary/wall_time")


def datasets(path):
    """{name: value} of every dataset of an HDF5 file but the provenance that names the producer, its
    command and date, and the wall time (a deck read from a file carries its name, as the program's)."""
    out = {}
    with h5py.File(path, "r") as f:
        def visit(name, obj):
            if isinstance(obj, h5py.Dataset) and name not in PROVENANCE:
                out[name] = obj[()]
        f.visititems(visit)
    return out


def test_version_and_library():
    assert landyn.version().strip()
    assert Path(landyn.library_path()).is_file()


def test_output_names_units_values():
    with Simulation(LC1, overrides=SHORT) as sim:
        names = sim.output_names
        assert len(names) == len(set(names))
        for n in ("time", "outcome", "position.z", "velocity.z", "euler.pitch", "tilt", "gear1.strut1.stroke",
                  "gear4.strut3.force"):
            assert n in names and n in sim
        assert "gear5.strut1.stroke" not in sim        # LC-1 has 4 gears
        units = sim.units
        assert set(units) == set(names) and set(sim.meanings) == set(names)
        assert units["time"] == "s" and units["position.z"] == "m" and units["velocity.z"] == "m/s"
        assert units["gear1.strut1.stroke"] == "m" and units["gear1.strut1.force"] == "N"
        assert units["euler.pitch"] == "deg" and units["tilt"] == "deg"
        assert all(sim.meanings[n].strip() for n in names)
        assert sim.time == 0.0 and sim.outcome == "running" and not sim.ended
        v0 = sim.outputs()
        assert v0.shape == (len(names),) and v0.dtype == np.float64
        assert sim["velocity.z"] == 4.0                   # the deck's 4 m/s down (+z)
        assert sim.advance_to(0.1) is True
        assert sim.time == 0.1 and sim["time"] == 0.1
        v = sim.outputs()
        for i, n in enumerate(names):                     # one call equals the calls by name
            assert v[i] == sim.output(n) == sim[n], n
        assert sim["gear1.strut1.stroke"] > 0.01          # the primary shortened by more than 10 mm
        assert sim.as_dict()["position.z"] == v[names.index("position.z")]
        r = repr(sim)
        assert "lc1.nml" in r and "t=0.1 s" in r and "running" in r


def test_deck_as_text_path_and_overrides_mapping():
    with Simulation(str(LC1), overrides=SHORT) as a, Simulation(LC1.read_text(), overrides=SHORT) as b, \
            Simulation(LC1, overrides={"simulation%t_end": 0.2}) as c:
        for s in (a, b, c):
            s.advance_to(0.05)
        assert np.array_equal(a.outputs(), b.outputs()) and np.array_equal(a.outputs(), c.outputs())
    assert landyn.overrides_text({"initial_state%velocity(3)": 5.0, "simulation%integrator": "fixed",
                                  "initial_state%attitude": (1, 2.5, 0), "simulation%stop_at_rest": False}) == (
        "&initial_state velocity(3) = 5.0, attitude = 1, 2.5, 0 /\n"
        "&simulation integrator = 'fixed', stop_at_rest = .false. /\n")
    with Simulation() as d:                               # the defaults: LC-1, 4 m/s
        assert d["velocity.z"] == 4.0


def test_run_equals_the_landyn_program(tmp_path):
    exe = os.environ.get("LANDYN_EXE")
    if not exe:
        pytest.skip("LANDYN_EXE not set")
    deck = tmp_path / "lc1_short.nml"
    deck.write_text(short_deck(LC1))
    prog = tmp_path / "program.h5"
    p = subprocess.run([exe, str(deck), "-o", str(prog), "--quiet"], capture_output=True, text=True)
    assert p.returncode == 0, p.stderr
    with Simulation(deck) as sim:
        assert sim.advance_to(0.2) in (True, False)
        assert sim.write_result(tmp_path / "api.h5") == tmp_path / "api.h5"
    a, b = datasets(prog), datasets(tmp_path / "api.h5")
    assert set(a) == set(b)
    assert len(a) > 50 and "timeseries/gears/stroke" in a
    differ = [k for k in a if not np.array_equal(a[k], b[k], equal_nan=np.asarray(a[k]).dtype.kind == "f")]
    assert differ == []


def test_bad_deck_lists_every_problem():
    with pytest.raises(LandynInputError) as e:
        Simulation("&simulation t_end = -1.0 /\n&terrain slope = 4*95.0 /\n")
    msg = str(e.value)
    assert "simulation" in msg and "t_end" in msg and "-1" in msg
    assert all(f"&terrain: slope({i}) = 95.0" in msg for i in (1, 2, 3, 4))
    assert e.value.status == 1


def test_bad_override_value_names_group_variable_value():
    with pytest.raises(LandynInputError) as e:
        Simulation(LC1, overrides={"initial_state%velocity(3)": "fast"})
    msg = str(e.value)
    assert "initial_state" in msg and "velocity" in msg and "fast" in msg
    with pytest.raises(LandynInputError) as e:
        Simulation(LC1, overrides="&simulation no_such_variable = 1 /")
    assert "no_such_variable" in str(e.value)
    with pytest.raises(LandynInputError, match="simulation%t_end|group%variable"):
        Simulation(LC1, overrides={"t_end": 1.0})
    with pytest.raises(LandynInputError, match="no_such_deck.nml"):
        Simulation("no_such_deck.nml")


def test_time_order_and_range():
    with Simulation(LC1, overrides=SHORT) as sim:
        sim.advance_to(0.05)
        with pytest.raises(LandynOrderError) as e:
            sim.advance_to(0.04)
        assert "0.04" in str(e.value) and e.value.status == 3
        with pytest.raises(LandynOrderError, match="t_end"):
            sim.advance_to(0.3)                           # past t_end = 0.2 s
        with pytest.raises(LandynInputError, match="not finite"):
            sim.advance_to(math.nan)
        assert sim.time == 0.05                           # nothing moved
        assert sim.advance_to(0.05) is True               # to the time it is at: nothing to do


def test_unknown_output_name():
    with Simulation(LC1, overrides=SHORT) as sim:
        with pytest.raises(LandynOutputNameError) as e:
            sim.output("gear1.strut1.strok")
        assert isinstance(e.value, KeyError) and isinstance(e.value, LandynInputError) and isinstance(e.value, LandynError)
        assert "gear1.strut1.strok" in str(e.value) and "gear1.strut1.stroke" in str(e.value)
        with pytest.raises(KeyError):
            sim["nothing"]


def test_set_input_misuse():
    with Simulation(LC1, overrides=SHORT) as sim:
        with pytest.raises(LandynInputError, match="force"):
            sim.set_input(force=(1.0, 2.0))
        with pytest.raises(LandynInputError, match=r"moment\(2\) is not finite"):
            sim.set_input(moment=(0.0, math.inf, 0.0))
        with pytest.raises(LandynInputError, match=r"force\(1\) is not finite"):
            sim.set_input(force=(math.nan, 0.0, 0.0))


def test_no_copy_of_a_handle():
    with Simulation(LC1, overrides=SHORT) as sim:
        for dup in (copy.copy, copy.deepcopy, pickle.dumps):
            with pytest.raises(TypeError, match="Simulation"):
                dup(sim)
        assert sim.advance_to(0.01)


def test_after_close_every_call_raises():
    sim = Simulation(LC1, overrides=SHORT)
    sim.close()
    sim.close()                                           # idempotent
    assert sim.closed and "closed" in repr(sim)
    calls = [lambda: sim.time, lambda: sim.advance_to(0.1), lambda: sim.set_input(), lambda: sim.outputs(),
             lambda: sim.output("time"), lambda: sim["time"], lambda: sim.output_names, lambda: sim.units,
             lambda: sim.outcome, lambda: sim.history([0.1]), lambda: sim.write_result("x.h5"),
             lambda: sim.__enter__()]
    for call in calls:
        with pytest.raises(LandynClosedError, match="closed"):
            call()
    with Simulation(LC1, overrides=SHORT) as s2:
        pass
    with pytest.raises(LandynClosedError):
        s2.advance_to(0.1)


def test_set_input_changes_the_result():
    with Simulation(LC1, overrides=SHORT) as ref, Simulation(LC1, overrides=SHORT) as zero, \
            Simulation(LC1, overrides=SHORT) as lift:
        zero.set_input(force=(0.0, 0.0, 0.0), moment=(0.0, 0.0, 0.0))
        lift.set_input(force=(0.0, 0.0, -6.0e4))           # 60 kN up (lander z down) [N]
        for s in (ref, zero, lift):
            s.advance_to(0.2)
        assert np.array_equal(ref.outputs(), zero.outputs())   # zero inputs give the deck's run
        assert lift["gear1.strut1.stroke"] < ref["gear1.strut1.stroke"] - 1e-3


def test_moment_input_changes_the_attitude():
    with Simulation(LC1, overrides=SHORT) as ref, Simulation(LC1, overrides=SHORT) as turned:
        turned.set_input(moment=(0.0, 2.0e5, 0.0))         # pitch moment [N m]
        ref.advance_to(0.1)
        turned.advance_to(0.1)
        assert abs(turned["euler.pitch"] - ref["euler.pitch"]) > 0.01


def _stepped(deck, overrides, times):
    with Simulation(deck, overrides=overrides) as sim:
        return [(sim.advance_to(t), sim.outputs()) for t in times]


def test_two_simulations_interleaved_equal_separate_runs():
    times = np.linspace(0.0, 0.2, 21)
    alone1, alone3 = _stepped(LC1, SHORT, times), _stepped(LC3, SHORT, times)
    with Simulation(LC1, overrides=SHORT) as a, Simulation(LC3, overrides=SHORT) as b:
        for k, t in enumerate(times):
            ra, rb = a.advance_to(t), b.advance_to(t)
            assert ra == alone1[k][0] and np.array_equal(a.outputs(), alone1[k][1])
            assert rb == alone3[k][0] and np.array_equal(b.outputs(), alone3[k][1])
        assert not np.array_equal(a.outputs(), b.outputs())


def test_two_simulations_in_two_threads():
    times = np.linspace(0.0, 0.2, 11)
    expect = {"a": _stepped(LC1, SHORT, times)[-1][1], "b": _stepped(LC3, SHORT, times)[-1][1]}
    got = {}

    def run(key, deck):
        got[key] = _stepped(deck, SHORT, times)[-1][1]
    threads = [threading.Thread(target=run, args=("a", LC1)), threading.Thread(target=run, args=("b", LC3))]
    for th in threads:
        th.start()
    for th in threads:
        th.join()
    assert np.array_equal(got["a"], expect["a"]) and np.array_equal(got["b"], expect["b"])


def test_history_shapes_and_values():
    times = np.linspace(0.0, 0.2, 11)
    with Simulation(LC1, overrides=SHORT) as sim:
        h = sim.history(times)
        assert list(h) == list(sim.output_names)
        assert all(v.shape == (11,) and v.dtype == np.float64 for v in h.values())
        assert np.array_equal(h["time"], times)
        assert h["gear1.strut1.stroke"][0] == 0.0 and h["gear1.strut1.stroke"][-1] > 0.01
        final = sim.outputs()
    assert np.array_equal(np.array([h[n][-1] for n in h]), final)
    assert np.array_equal(_stepped(LC1, SHORT, times)[-1][1], final)
    with Simulation(LC1, overrides=SHORT) as sim:
        assert all(v.shape == (0,) for v in sim.history([]).values())


def test_run_that_ends_early():
    # tilt limit 5 deg: LC-3 (starting 4 deg tilted on the 8 deg slope) passes it at 0.297 s and ends there
    with Simulation(LC3, overrides="&simulation tipover_angle = 5.0 /") as sim:
        h = sim.history(np.linspace(0.0, 1.0, 101))
        n = h["time"].size
        assert 1 < n < 101 and h["time"][-1] < 1.0
        assert sim.outcome == "tipped_over" and sim.ended
        t_end = sim.time
        assert sim.advance_to(1.0) is False and sim.time == t_end
        with pytest.raises(LandynOrderError):
            sim.set_input(force=(1.0, 0.0, 0.0))


def test_write_result_never_overwrites_an_input(tmp_path):
    deck = tmp_path / "deck.nml"
    deck.write_text(short_deck(LC1))
    before = deck.read_text()
    with Simulation(deck) as sim:
        sim.advance_to(0.01)
        with pytest.raises(LandynFileError, match="deck.nml"):
            sim.write_result(deck)
    assert deck.read_text() == before


def test_library_lookup_errors(monkeypatch, tmp_path):
    monkeypatch.setenv("LANDYN_LIBRARY", str(tmp_path / "nowhere.so"))
    with pytest.raises(LandynLibraryError, match="nowhere.so"):
        landyn.library_path()
    monkeypatch.setenv("LANDYN_LIBRARY", str(tmp_path))        # a directory without the library
    with pytest.raises(LandynLibraryError, match="liblandyn.so"):
        landyn.library_path()


def test_library_lookup_order(monkeypatch):
    monkeypatch.delenv("LANDYN_LIBRARY", raising=False)
    cands = landyn._lib.candidates()
    assert cands[:2] == [ROOT / "build" / "release" / "liblandyn.so", ROOT / "build" / "debug" / "liblandyn.so"]
