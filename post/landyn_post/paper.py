"""The paper's reference data shipped with the package (docs/model_conventions.md).

``data/table2_load_cases.csv`` (Table 2, the load cases) and ``data/table3_crush_lengths.csv``
(Table 3, crush lengths of the theory and MSC Adams models, mm). ``load_case_of(res)`` tells
which of the paper's load cases a result was run for, from its touchdown conditions (/model:
velocity, yaw, slope) -- not from its title -- and ``table3(load_case, column)`` gives the
crush lengths per measure.
"""
from __future__ import annotations

import csv
import math
import os
import re

import numpy as np

from .schema import LandynFileError, Result

DATA = os.path.join(os.path.dirname(os.path.abspath(__file__)), "data")
TABLE2 = os.path.join(DATA, "table2_load_cases.csv")
TABLE3 = os.path.join(DATA, "table3_crush_lengths.csv")


def _rows(path: str) -> list[dict[str, str]]:
    with open(path, newline="", encoding="utf-8") as fh:
        return list(csv.DictReader(line for line in fh if not line.startswith("#")))


def load_cases() -> list[dict[str, str]]:
    """Rows of Table 2."""
    return _rows(TABLE2)


def table3(load_case: str, column: str = "theory") -> dict[int, float]:
    """Table 3 crush lengths (m) of one load case by measure number; column 'theory' or 'adams'."""
    col = column if column.endswith("_mm") else column + "_mm"
    out = {int(r["measure"]): float(r[col]) / 1e3 for r in _rows(TABLE3) if r["load_case"].upper() == load_case.upper()}
    if not out:
        raise KeyError(load_case)
    return out


def touchdown_conditions(res: Result) -> dict[str, float]:
    """Touchdown conditions: vertical and horizontal speed (m/s), horizontal direction (deg from
    +x), yaw/pitch/roll (deg), slope under footpad 1 (deg) and its uphill azimuth (deg), whether
    every footpad has that plane (slope_uniform, 1.0 or 0.0), friction coefficients, mass (kg),
    gravity (m/s^2), clearance (m).

    From /model (schema 1.5: /model/touchdown, /model/friction, /model/mass, /model/gravity,
    /model/terrain). A file older than 1.5 lacks them: see _touchdown_from_deck, the deck fallback.
    """
    if not res.has_model_since("1.5"):
        return _touchdown_from_deck(res)
    att = res.model("touchdown/attitude")
    ter = res.terrain()
    return _conditions(res.model("touchdown/velocity"), att, ter[:, 1], ter[:, 2], {
        "mu_static": float(res.model("friction/mu_static")), "mu_dynamic": float(res.model("friction/mu_dynamic")),
        "mass": float(res.model("mass")), "gravity": float(res.model("gravity")),
        "clearance": float(res.model("touchdown/clearance"))})


def _conditions(v, att, slope, sdir, scalars: dict[str, float]) -> dict[str, float]:
    """touchdown_conditions' dictionary from the velocity (3,), attitude (3,), slopes and uphill
    azimuths per footpad (g,) and the scalar conditions."""
    out: dict[str, float] = {}
    out["v_vertical"] = float(v[2])
    out["v_horizontal"] = float(math.hypot(v[0], v[1]))
    out["v_direction"] = float(math.degrees(math.atan2(v[1], v[0]))) if out["v_horizontal"] > 0 else 0.0
    out["yaw"], out["pitch"], out["roll"] = (float(a) for a in att)
    out["slope"] = float(slope[0])
    out["slope_direction"] = float(sdir[0])
    out["slope_uniform"] = float(np.allclose(slope, slope[0]) and np.allclose(sdir, sdir[0]))
    out.update(scalars)
    return out


def _touchdown_from_deck(res: Result) -> dict[str, float]:
    """Deck fallback of touchdown_conditions for files older than schema 1.5 (no /model/touchdown):
    the conditions read from /meta/resolved_input; a value the deck lacks is NaN."""
    d = res.deck

    def num(group, name, shape=None, fill=math.nan):
        try:
            if shape is None:
                return float(d.get(group, name))
            return d.array(group, name, shape, fill=fill)
        except Exception:  # noqa: BLE001 - a value the deck lacks is reported as NaN
            return math.nan if shape is None else np.full(shape, math.nan)

    g = res.n_gears
    return _conditions(num("initial_state", "velocity", (3,)), num("initial_state", "attitude", (3,)),
                       num("terrain", "slope", (g,), fill=0.0), num("terrain", "slope_direction", (g,), fill=0.0),
                       {"mu_static": num("friction", "mu_static"), "mu_dynamic": num("friction", "mu_dynamic"),
                        "mass": num("lander", "mass"), "gravity": num("simulation", "gravity"),
                        "clearance": num("initial_state", "clearance")})


def load_case_of(res: Result) -> str | None:
    """'LC-1' ... 'LC-4' when the result's touchdown conditions are those of one of Table 2's load
    cases (vertical and horizontal speed within 1e-6 m/s, yaw within 0.5 deg -- the decks' yaw of
    LC-3 is 45.07 deg after the pitch conversion --, slope within 1e-6 deg, four gears), else None."""
    try:
        c = touchdown_conditions(res)
    except LandynFileError:
        return None
    if res.n_gears != 4:
        return None
    for row in load_cases():
        if (abs(c["v_vertical"] - float(row["vertical_velocity_m_s"])) < 1e-6
                and abs(c["v_horizontal"] - float(row["horizontal_velocity_m_s"])) < 1e-6
                and abs(c["yaw"] - float(row["yaw_deg"])) < 0.5
                and abs(c["slope"] - float(row["slope_deg"])) < 1e-6 and c["slope_uniform"] == 1.0):
            return row["load_case"]
    return None


_LC_IN_TITLE = re.compile(r"\bLC-?\s*([0-9]+)\b", re.I)


def load_case_in_title(title: str) -> str | None:
    """'LC-3' when the title names a load case ('LC-3 easy turnover ...'), else None."""
    m = _LC_IN_TITLE.search(title or "")
    return f"LC-{int(m.group(1))}" if m else None
