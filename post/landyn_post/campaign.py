"""Campaign summaries (landyn_batch, docs/campaign.md): engineering labels of the varied inputs,
the failure-cause breakdown and the input-vs-margin sensitivity (Spearman rank correlation)."""
from __future__ import annotations

import re

import numpy as np

from .namelist import parse_namelist

#: failure criteria in the bit order of /cases/failed_criteria
CRITERIA = (("tipped_over", "tipped over"), ("stroke_margin", "stroke margin (bottoming out)"),
            ("overload", "overload"), ("body_clearance", "body clearance"),
            ("not_at_rest", "not at rest (still moving: inconclusive)"),
            ("no_result", "no result (invalid input / failed run / failed health check)"),
            ("no_touchdown", "no touchdown"), ("tipover_margin", "tip-over margin at rest"),
            ("friction_ratio", "static friction ratio at rest"))

_NAME = re.compile(r"^\s*([a-z_]+)%([a-z_0-9]+)\s*(?:\(([^)]*)\))?\s*$", re.I)

_LABELS = {
    ("initial_state", "velocity", "3"): "vertical touchdown velocity, down",
    ("initial_state", "velocity", "2"): "lateral touchdown velocity along global y",
    ("initial_state", "attitude", "1"): "yaw",
    ("initial_state", "attitude", "2"): "pitch",
    ("initial_state", "attitude", "3"): "roll",
    ("initial_state", "angular_rate", "1"): "roll rate p",
    ("initial_state", "angular_rate", "2"): "pitch rate q",
    ("initial_state", "angular_rate", "3"): "yaw rate r",
    ("initial_state", "clearance", ""): "initial footpad clearance",
    ("terrain", "slope", ""): "terrain slope",
    ("terrain", "slope_direction", ""): "uphill direction (azimuth from global +x)",
    ("terrain", "height", ""): "terrain height",
    ("friction", "mu_dynamic", ""): "dynamic friction coefficient",
    ("friction", "mu_static", ""): "static friction coefficient",
    ("contact", "stiffness", ""): "ground contact stiffness",
    ("contact", "damping", ""): "ground contact damping",
    ("contact", "soil_stiffness", ""): "soil stiffness",
    ("lander", "mass", ""): "lander mass",
    ("simulation", "dt", ""): "time step",
    ("simulation", "gravity", ""): "gravity",
    ("primary_strut", "stage_force", ""): "primary honeycomb crush force",
    ("secondary_strut", "force_lengthening", ""): "secondary crush force in lengthening",
    ("secondary_strut", "force_shortening", ""): "secondary crush force in shortening",
}

#: metrics of /cases: (dataset, label, scale to the plotted unit, unit, larger is worse)
METRICS = (
    ("min_stroke_margin", "smallest stroke margin", 1000.0, "mm", False),
    ("peak_overload", "peak overload", 1.0, "g", True),
    ("max_tilt", "largest tilt", 1.0, "deg", True),
    ("peak_penetration", "largest footpad penetration", 1000.0, "mm", True),
    ("max_slide_distance", "largest footpad slide", 1000.0, "mm", True),
    ("min_body_clearance", "body clearance", 1.0, "m", False),
)


def _uphill_sense(base_deck_text: str) -> str | None:
    """'uphill' / 'downhill' for +x motion when the base deck's terrain has one slope direction
    0 or 180 deg (the default 0: rising toward +x), else None."""
    try:
        d = parse_namelist(base_deck_text)
        sd = float(d.get("terrain", "slope_direction")) if d.has("terrain", "slope_direction") else 0.0
    except Exception:  # noqa: BLE001 - a base deck the simple reader cannot parse: no direction word
        sd = 0.0
    sd %= 360.0
    if abs(sd) < 1e-9:
        return "uphill"
    if abs(sd - 180.0) < 1e-9:
        return "downhill"
    return None


def _varies_slope_direction(varied) -> bool:
    """True when one of the campaign's varied parameters is the terrain's slope direction."""
    for other in varied or ():
        mo = _NAME.match(other or "")
        if mo and (mo.group(1).lower(), mo.group(2).lower()) == ("terrain", "slope_direction"):
            return True
    return False


def input_label(name: str, units: str, base_deck_text: str = "", varied=()) -> str:
    """Engineering axis label of a varied input, derived from what was sampled: e.g. 'horizontal
    velocity along global +x, uphill [m/s]' for initial_state%velocity(1) on the default terrain
    (rising toward +x); when the campaign also varies the slope direction (`varied`: the names of
    every varied parameter) the direction relative to the slope varies from case to case and the
    label says so instead of naming the base deck's direction."""
    m = _NAME.match(name or "")
    unit = f" [{units}]" if units and units != "-" else " [-]"
    if not m:
        return f"{name}{unit}"
    group, var, sub = m.group(1).lower(), m.group(2).lower(), (m.group(3) or "").replace(" ", "")
    if (group, var, sub) == ("initial_state", "velocity", "1"):
        if _varies_slope_direction(varied):
            return f"horizontal velocity along global +x (slope direction sampled){unit}"
        sense = _uphill_sense(base_deck_text)
        return f"horizontal velocity along global +x{', ' + sense if sense else ''}{unit}"
    key = (group, var, sub) if (group, var, sub) in _LABELS else (group, var, "")
    if key in _LABELS and (sub in ("", ":") or key[2] == sub):
        return f"{_LABELS[key]}{unit}"
    if key in _LABELS:
        return f"{_LABELS[key]} ({sub}){unit}"
    return f"{name}{unit}"


def failure_breakdown(failed_criteria: np.ndarray) -> list[tuple[str, str, int]]:
    """(name, label, number of cases failing it) per criterion, from the bit sets."""
    fc = np.asarray(failed_criteria, dtype=int)
    return [(n, lab, int(np.sum((fc & (1 << k)) != 0))) for k, (n, lab) in enumerate(CRITERIA)]


def spearman(x: np.ndarray, y: np.ndarray) -> tuple[float, float, int]:
    """Spearman rank correlation (rho, two-sided p-value, n) over the finite pairs (scipy.stats)."""
    from scipy import stats
    ok = np.isfinite(x) & np.isfinite(y)
    n = int(ok.sum())
    if n < 3 or np.ptp(x[ok]) == 0 or np.ptp(y[ok]) == 0:
        return float("nan"), float("nan"), n
    r = stats.spearmanr(x[ok], y[ok])
    return float(r.statistic), float(r.pvalue), n
