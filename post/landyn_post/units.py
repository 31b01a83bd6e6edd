"""Units: conversion of reference units to LANDYN's channel units, and engineering plot units.

LANDYN's channels are in SI except angles (deg, deg/s) and overload (g), see docs/output.md.
``unit_factor(unit, channel_unit)`` converts a value given in ``unit`` (e.g. 'mm', 'kN', 'ms',
'rad/s', 'm/s^2') to the channel's unit and raises LandynPostError when the two are of different
kinds; ``to_engineering(values, unit)`` gives SI values in the engineering units of plots and
tables (mm, kN, kJ, kN m), as ``landyn-export --units engineering`` writes them.
"""
from __future__ import annotations

import math
import re

from .schema import LandynPostError

G0 = 9.80665  #: standard gravity, m/s^2 (the overload channels are in g)

#: unit -> (LANDYN channel unit of the same kind, factor: value[unit] * factor = value[channel unit])
UNITS = {
    "m": ("m", 1.0), "mm": ("m", 1e-3), "cm": ("m", 1e-2), "um": ("m", 1e-6), "in": ("m", 0.0254),
    "N": ("N", 1.0), "kN": ("N", 1e3), "MN": ("N", 1e6), "lbf": ("N", 4.4482216152605),
    "s": ("s", 1.0), "ms": ("s", 1e-3),
    "m/s": ("m/s", 1.0), "mm/s": ("m/s", 1e-3), "km/h": ("m/s", 1.0 / 3.6),
    "deg": ("deg", 1.0), "rad": ("deg", 180.0 / math.pi),
    "deg/s": ("deg/s", 1.0), "rad/s": ("deg/s", 180.0 / math.pi),
    "g": ("g", 1.0), "m/s^2": ("g", 1.0 / G0), "m/s2": ("g", 1.0 / G0),
    "J": ("J", 1.0), "kJ": ("J", 1e3), "MJ": ("J", 1e6),
    # moments (the joint moments of the interface loads; channel unit 'N m')
    "N m": ("N m", 1.0), "Nm": ("N m", 1.0), "kNm": ("N m", 1e3), "kN m": ("N m", 1e3), "lbf ft": ("N m", 1.3558179483314),
    "-": ("-", 1.0),
}

#: channel unit -> (engineering unit for plots and tables, factor)
ENGINEERING = {"m": ("mm", 1e3), "N": ("kN", 1e-3), "J": ("kJ", 1e-3), "m/s": ("m/s", 1.0), "deg": ("deg", 1.0),
               "deg/s": ("deg/s", 1.0), "g": ("g", 1.0), "s": ("s", 1.0), "N m": ("kN m", 1e-3), "-": ("-", 1.0)}

_QTY = re.compile(r"^\s*([-+]?(?:\d+\.?\d*|\.\d+)(?:[eEdD][-+]?\d+)?)\s*([A-Za-z%/^0-9-]*(?: [A-Za-z]+)?)\s*$")


def known_units() -> str:
    return ", ".join(u for u in UNITS if u != "-")


def unit_factor(unit: str, channel_unit: str, what: str = "") -> float:
    """Factor turning a value in `unit` into `channel_unit`; LandynPostError if they differ in kind."""
    if unit not in UNITS:
        raise LandynPostError(f"{what}unknown unit {unit!r} (known: {known_units()})")
    kind, fac = UNITS[unit]
    if kind != channel_unit:
        raise LandynPostError(f"{what}unit {unit!r} cannot be converted to the channel's unit {channel_unit!r}")
    return fac


def parse_quantity(text: str) -> tuple[float, str | None]:
    """'2mm' -> (2.0, 'mm'); '0.5' -> (0.5, None); '3%' -> (3.0, '%')."""
    m = _QTY.match(text)
    if not m:
        raise LandynPostError(f"malformed quantity {text!r} (expected a number with an optional unit, e.g. 2mm)")
    value = float(m.group(1).lower().replace("d", "e"))
    unit = m.group(2) or None
    if unit is not None and unit != "%" and unit not in UNITS:
        raise LandynPostError(f"unknown unit {unit!r} in {text!r} (known: {known_units()})")
    return value, unit


def engineering(channel_unit: str) -> tuple[str, float]:
    """(engineering unit, factor) for a channel unit: m -> mm, N -> kN, J -> kJ, others unchanged."""
    return ENGINEERING.get(channel_unit, (channel_unit, 1.0))


def to_engineering(values, unit: str):
    """(values, unit) in engineering units: lengths in mm, forces in kN, energies in kJ, moments
    in kN m; velocities (m/s), angles (deg), rates (deg/s), overload (g), time (s) and
    dimensionless values unchanged. For landyn-export --units engineering and landyn-compare."""
    import numpy as np
    eng, factor = engineering(unit)
    if factor == 1.0:
        return values, unit
    return np.asarray(values) * factor, eng
