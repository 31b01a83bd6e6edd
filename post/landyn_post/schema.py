"""The LANDYN result-file schema (docs/output.md) and the one reader that maps it to numpy.

Everything the post-processing tools know about the file layout lives here: dataset paths,
units, shapes, the strut and component labels, the channel names used by ``landyn-compare`` and
``landyn-export``, and the input variables read back from ``/meta/resolved_input``.

Shapes are as h5py reads them (C order): Fortran ``x(3, n)`` is ``(n, 3)``, gear arrays
``(3, n_gears, n)`` are ``(n, n_gears, 3)``, summary arrays ``(3, n_gears)`` are ``(n_gears, 3)``.
In DATASETS, "n" is the number of samples, "g" of gears and "s" of struts per gear; the file says
them (``/timeseries/time``, ``/summary/crush_length``), nothing here assumes them.

Typical use::

    from landyn_post import load
    res = load("landyn.h5")
    res.time                      # (n,) s
    res.stroke[:, 0, 0]           # gear 1 primary stroke (n,) m
    res.crush_length              # (n_gears, 3) m, Table 3 sense
    res.channel("stroke[gear=1,strut=primary]").values
"""
from __future__ import annotations

import os
import re
from dataclasses import dataclass

import numpy as np

from .namelist import Namelist, NamelistError, parse_namelist

__all__ = [
    "SCHEMA_VERSION", "SUPPORTED_MAJOR", "STRUTS", "STRUT_LABELS", "ENERGY_NAMES", "DATASETS",
    "DatasetSpec", "Channel", "Result", "LandynPostError", "LandynFileError", "load", "is_hdf5",
    "measure_number", "measure_gear_strut", "parse_channel_spec", "units_token", "strut_index",
    "ROOT_ATTRIBUTES", "META", "JOINT_BLOCKS", "LOAD_NAMES", "PEAK_JOINTS", "PEAK_QUANTITIES",
]

SCHEMA_VERSION = "1.3"     #: the schema version this package was written for
SUPPORTED_MAJOR = "1"      #: files with schema_version 1.x are read (minor versions only add)

#: strut order of the last axis of gear arrays (Table 3 measure order within a gear)
STRUTS = ("primary", "secondary_left", "secondary_right")
STRUT_LABELS = {"primary": "primary", "secondary_left": "secondary left", "secondary_right": "secondary right"}
_STRUT_ALIASES = {"primary": 0, "p": 0, "1": 0, "secondary_left": 1, "left": 1, "l": 1, "2": 1,
                  "secondary_right": 2, "right": 2, "r": 2, "3": 2}

#: energy-audit channels, in the order LANDYN writes them
ENERGY_NAMES = ("kinetic_body", "kinetic_legs", "potential_released", "honeycomb_work", "contact_damping",
                "contact_elastic", "friction", "strut_impacts", "thrust_work", "input", "residual")

_XYZ = ("x", "y", "z")


class LandynPostError(Exception):
    """A user-facing error: the tools print its message on one line and exit with status 2."""


class LandynFileError(LandynPostError):
    """The file is missing, not HDF5, of another schema version or lacks a dataset."""


@dataclass(frozen=True)
class DatasetSpec:
    """One dataset of the schema.

    shape uses symbols: ``n`` output samples, ``g`` gears, integers for fixed lengths.
    kind is ``real``, ``int``, ``bool`` (int 0/1 with attribute type=logical) or ``text``.
    components labels the last axis of length 3 (vectors) where it has a meaning.
    """
    key: str
    path: str
    units: str
    shape: tuple
    kind: str
    meaning: str
    components: tuple = ()
    since: str = "1.0"    #: schema version that added it (older files are read without it)

    @property
    def is_timeseries(self) -> bool:
        return self.path.startswith("/timeseries/") and self.key != "time"


def _ts(key, path, units, shape, meaning, components=(), since="1.0"):
    return DatasetSpec(key, path, units, shape, "real", meaning, components, since)


#: interface loads (schema 1.2): the load vector's blocks as LANDYN writes them
JOINT_BLOCKS = (
    ("joint_force_a", "N", "force joint a (upper joint of the primary) puts on the body"),
    ("joint_force_b", "N", "force joint b (upper joint of the left secondary) puts on the body"),
    ("joint_force_c", "N", "force joint c (upper joint of the right secondary) puts on the body"),
    ("footpad_joint_force", "N", "force the footpad puts on the primary strut at its ball joint d"),
    ("joint_moment_a", "N m", "moment joint a puts on the body (about its universal-joint axis)"),
    ("joint_moment_b", "N m", "moment joint b puts on the body (about its universal-joint axis)"),
    ("joint_moment_c", "N m", "moment joint c puts on the body (about its universal-joint axis)"),
)
#: names of the 21 loads of /summary/peak_joint_load/simultaneous
LOAD_NAMES = tuple(f"F{j}_{c}" for j in "abcd" for c in "xyz") + tuple(f"M{j}_{c}" for j in "abc" for c in "xyz")
PEAK_JOINTS = ("a", "b", "c", "d")
PEAK_QUANTITIES = ("x", "y", "z", "magnitude")


#: /meta: provenance strings (all scalar text, units '-')
META = (
    ("code_version", "LANDYN version"),
    ("git_revision", "git describe of the source tree at build time"),
    ("build_type", "CMake build type (Release, Debug, ...)"),
    ("compiler", "compiler name and version"),
    ("compiler_flags", "flags of the LANDYN sources as configured"),
    ("compiler_options", "compiler_options() of the module that wrote the file"),
    ("date", "time the file was written, ISO 8601 with UTC offset"),
    ("command_line", "the command that ran LANDYN"),
    ("deck_name", "input deck path, or '(built-in default)'"),
    ("deck_text", "the input deck as given"),
    ("resolved_input", "fully resolved input as a namelist deck (angles in degrees)"),
    ("units", "unit system statement"),
)

#: Every dataset of schema 1.2 (root attributes title, producer, schema_version are separate).
DATASETS: tuple[DatasetSpec, ...] = tuple(
    [DatasetSpec(k, "/meta/" + k, "-", (), "text", m) for k, m in META]
    + [
        _ts("time", "/timeseries/time", "s", ("n",), "output time"),
        _ts("position", "/timeseries/body/position", "m", ("n", 3),
            "lander-frame origin O_L (geometric centre), global frame, z down", _XYZ),
        _ts("mass_centre_position", "/timeseries/body/mass_centre_position", "m", ("n", 3),
            "mass centre, global frame, z down", _XYZ),
        _ts("velocity", "/timeseries/body/velocity", "m/s", ("n", 3),
            "mass-centre velocity, global frame, z down (+z = descending)", _XYZ),
        _ts("euler_angles", "/timeseries/body/euler_angles", "deg", ("n", 3),
            "Z-Y-X Euler angles yaw, pitch, roll; R = Rz(yaw) Ry(pitch) Rx(roll) maps lander to global",
            ("yaw", "pitch", "roll")),
        _ts("angular_rate", "/timeseries/body/angular_rate", "deg/s", ("n", 3),
            "body rates p, q, r about the lander axes", ("p", "q", "r")),
        _ts("overload", "/timeseries/body/overload", "g", ("n", 3),
            "(a - g)/9.80665 at the mass centre in lander axes (accelerometer reading; "
            "-z = upward deceleration in the z-down frame)", _XYZ),
        _ts("overload_peak", "/timeseries/body/overload_peak", "g", ("n",),
            "largest |overload| over every integration step since the previous sample (this one included)"),
        _ts("strut_length", "/timeseries/gears/strut_length", "m", ("n", "g", "s"),
            "strut length between its joints; last axis primary, secondary left, secondary right", STRUTS),
        _ts("stroke", "/timeseries/gears/stroke", "m", ("n", "g", "s"),
            "stroke: primary shortening positive, secondaries lengthening positive (Table 3 sense)", STRUTS),
        _ts("strut_force", "/timeseries/gears/strut_force", "N", ("n", "g", "s"),
            "axial buffer force, compression positive", STRUTS),
        _ts("strut_force_peak", "/timeseries/gears/strut_force_peak", "N", ("n", "g", "s"),
            "largest |axial force| over every integration step since the previous sample", STRUTS),
        _ts("footpad_position", "/timeseries/gears/footpad_position", "m", ("n", "g", 3),
            "footpad ball joint d_i, global frame, z down", _XYZ),
        _ts("ground_force", "/timeseries/gears/ground_force", "N", ("n", "g", 3),
            "ground force on the footpad (normal + friction), global frame", _XYZ),
        _ts("normal_force", "/timeseries/gears/normal_force", "N", ("n", "g"),
            "normal contact force on the footpad (>= 0)"),
        _ts("normal_force_peak", "/timeseries/gears/normal_force_peak", "N", ("n", "g"),
            "largest normal force over every integration step since the previous sample"),
        _ts("friction_force", "/timeseries/gears/friction_force", "N", ("n", "g"),
            "magnitude of the friction force on the footpad"),
        _ts("penetration", "/timeseries/gears/penetration", "m", ("n", "g"),
            "depth below the local surface along its normal (negative: above)"),
        _ts("slip_speed", "/timeseries/gears/slip_speed", "m/s", ("n", "g"),
            "footpad speed tangential to the local surface"),
    ]
    + [_ts(k, "/timeseries/gears/" + k, u, ("n", "g", 3), m + ", lander axes", _XYZ, "1.2")
       for k, u, m in JOINT_BLOCKS]
    + [_ts("gear_axes/" + k, "/timeseries/gears/gear_axes/" + k, u, ("n", "g", 3), m + ", gear axes", _XYZ, "1.2")
       for k, u, m in JOINT_BLOCKS]
    + [_ts("interface_force", "/timeseries/gears/interface_force", "N", ("n", "g", 3),
           "the gear's total force on the body from its momentum balance (= joint_force_a + b + c), lander axes",
           _XYZ, "1.2")]
    + [_ts("energy/" + e, "/timeseries/energy/" + e, "J", ("n",), "energy audit: " + e.replace("_", " "))
       for e in ENERGY_NAMES]
    + [
        DatasetSpec("crush_length", "/summary/crush_length", "m", ("g", "s"), "real",
                    "signed net crush per gear and strut (Table 3 sense)", STRUTS),
        DatasetSpec("crushed_positive", "/summary/crushed_positive", "m", ("g", "s"), "real",
                    "crushed length toward + (primary shortening, secondary lengthening)", STRUTS),
        DatasetSpec("crushed_negative", "/summary/crushed_negative", "m", ("g", "s"), "real",
                    "crushed length toward - (secondary shortening)", STRUTS),
        DatasetSpec("stroke_final", "/summary/stroke_final", "m", ("g", "s"), "real", "stroke at the end", STRUTS),
        DatasetSpec("stroke_margin", "/summary/stroke_margin", "m", ("g", "s"), "real",
                    "stroke capacity minus crushed length, worst direction (negative: bottomed out)", STRUTS),
        DatasetSpec("bottomed_out", "/summary/bottomed_out", "-", ("g", "s"), "int",
                    "1 where a stroke exceeded its capacity", STRUTS),
        DatasetSpec("crush_work", "/summary/crush_work", "J", ("g", "s"), "real", "honeycomb crush work", STRUTS),
        DatasetSpec("mode_switches", "/summary/mode_switches", "-", ("g", "s"), "int",
                    "crush-mode changes (locked, crushing +/-, free) per strut", STRUTS),
        DatasetSpec("peak_strut_force", "/summary/peak_strut_force", "N", ("g", "s"), "real",
                    "largest |axial force| at the output samples", STRUTS),
        DatasetSpec("peak_overload", "/summary/peak_overload", "g", (), "real",
                    "largest |overload| at the mass centre (every step)"),
        DatasetSpec("time_of_peak_overload", "/summary/time_of_peak_overload", "s", (), "real",
                    "time of peak_overload"),
        DatasetSpec("peak_penetration", "/summary/peak_penetration", "m", ("g",), "real",
                    "largest penetration per footpad (every step)"),
        DatasetSpec("slide_distance", "/summary/slide_distance", "m", ("g",), "real",
                    "path length of each footpad along the surface while in contact"),
        DatasetSpec("peak_normal_force", "/summary/peak_normal_force", "N", ("g",), "real",
                    "largest normal force per footpad (every step)"),
        DatasetSpec("final_attitude", "/summary/final_attitude", "deg", (3,), "real",
                    "Z-Y-X Euler angles yaw, pitch, roll at the end", ("yaw", "pitch", "roll")),
        DatasetSpec("final_tilt", "/summary/final_tilt", "deg", (), "real",
                    "angle between the lander z axis and the vertical at the end"),
        DatasetSpec("max_tilt", "/summary/max_tilt", "deg", (), "real", "largest tilt during the run"),
        DatasetSpec("tipped_over", "/summary/tipped_over", "-", (), "bool", "tilt exceeded tipover_angle"),
        DatasetSpec("at_rest", "/summary/at_rest", "-", (), "bool", "the lander came to rest"),
        DatasetSpec("end_reason", "/summary/end_reason", "-", (), "text",
                    "'end time reached', 'at rest' or 'tipped over'"),
        DatasetSpec("energy_input", "/summary/energy_input", "J", (), "real",
                    "initial kinetic energy + potential energy released + thrust work"),
        DatasetSpec("energy_residual", "/summary/energy_residual", "-", (), "real",
                    "final energy-audit residual relative to energy_input"),
    ] + [
        DatasetSpec("energy_audit/" + e, "/summary/energy_audit/" + e, "J", (), "real",
                    "final value of /timeseries/energy/" + e)
        for e in ENERGY_NAMES
    ] + [
        DatasetSpec("max_constraint_violation", "/summary/max_constraint_violation", "m", (), "real",
                    "largest constraint violation after correction"),
        DatasetSpec("max_constraint_drift", "/summary/max_constraint_drift", "m", (), "real",
                    "largest constraint violation before correction (one step of drift)"),
        DatasetSpec("final_time", "/summary/final_time", "s", (), "real", "time at the end of the run"),
        DatasetSpec("n_steps", "/summary/n_steps", "-", (), "int", "accepted time steps"),
        DatasetSpec("integrator/name", "/summary/integrator/name", "-", (), "text", "time integrator: fixed or adaptive"),
        DatasetSpec("integrator/n_evaluations", "/summary/integrator/n_evaluations", "-", (), "int",
                    "force evaluations, rejected steps included"),
        DatasetSpec("integrator/n_rejected", "/summary/integrator/n_rejected", "-", (), "int", "rejected steps"),
        DatasetSpec("integrator/n_events", "/summary/integrator/n_events", "-", (), "int",
                    "accepted steps that ended at a located event"),
        DatasetSpec("integrator/n_forced", "/summary/integrator/n_forced", "-", (), "int",
                    "steps of event_resolution accepted above the tolerance (discontinuities)"),
        DatasetSpec("integrator/n_releases", "/summary/integrator/n_releases", "-", (), "int",
                    "strut releases (locked to crushing or free)", since="1.3"),
        DatasetSpec("integrator/n_releases_after_lock", "/summary/integrator/n_releases_after_lock", "-", (), "int",
                    "strut releases in the step after a strut locked", since="1.3"),
        DatasetSpec("integrator/dt_smallest", "/summary/integrator/dt_smallest", "s", (), "real", "smallest accepted step"),
        DatasetSpec("integrator/dt_largest", "/summary/integrator/dt_largest", "s", (), "real", "largest accepted step"),
        DatasetSpec("wall_time", "/summary/wall_time", "s", (), "real", "wall-clock time of the simulation"),
        DatasetSpec("peak_joint_load/value", "/summary/peak_joint_load/value", "N", ("g", 4, 4), "real",
                    "peak interface load per gear, joint (a, b, c, d) and quantity (x, y, z, magnitude), lander "
                    "axes, over every accepted step; components signed", (), "1.2"),
        DatasetSpec("peak_joint_load/time", "/summary/peak_joint_load/time", "s", ("g", 4, 4), "real",
                    "instant of each peak", (), "1.2"),
        DatasetSpec("peak_joint_load/simultaneous", "/summary/peak_joint_load/simultaneous", "N, N m",
                    ("g", 16, 21), "real", "the gear's 21 loads (load_names) at the instant of each peak; "
                    "row = 4 * joint + quantity", (), "1.2"),
        DatasetSpec("peak_joint_load/load_names", "/summary/peak_joint_load/load_names", "-", (21,), "text",
                    "names of the simultaneous loads: Fa_x ... Fd_z [N], Ma_x ... Mc_z [N m]", (), "1.2"),
        DatasetSpec("peak_joint_load/joint_names", "/summary/peak_joint_load/joint_names", "-", (4,), "text",
                    "a, b, c, d", (), "1.2"),
        DatasetSpec("peak_joint_load/quantity_names", "/summary/peak_joint_load/quantity_names", "-", (4,), "text",
                    "x, y, z, magnitude", (), "1.2"),
        DatasetSpec("health/status", "/summary/health/status", "-", (), "int",
                    "worst run-health check: 0 passed, 1 warnings, 2 failed (run meaningless; docs/health.md)"),
        DatasetSpec("health/checks", "/summary/health/checks", "-", (6,), "text", "names of the run-health checks"),
        DatasetSpec("health/results", "/summary/health/results", "-", (6,), "int",
                    "per check: 0 passed, 1 warning, 2 failed"),
        DatasetSpec("health/messages", "/summary/health/messages", "-", (), "text",
                    "one line per check that did not pass; 'none' when all passed"),
        DatasetSpec("outcome/code", "/summary/outcome/code", "-", (), "int",
                    "0 not classified, 1 no_touchdown, 2 at_rest, 3 still_moving (inconclusive), 4 tipped_over",
                    (), "1.3"),
        DatasetSpec("outcome/name", "/summary/outcome/name", "-", (), "text",
                    "no_touchdown, at_rest, still_moving or tipped_over", (), "1.3"),
        DatasetSpec("outcome/touched_down", "/summary/outcome/touched_down", "-", (), "bool",
                    "a footpad touched the ground", (), "1.3"),
        DatasetSpec("outcome/body_speed", "/summary/outcome/body_speed", "m/s", (), "real",
                    "mass-centre speed at the final time", (), "1.3"),
        DatasetSpec("outcome/angular_rate", "/summary/outcome/angular_rate", "deg/s", (), "real",
                    "|omega| at the final time", (), "1.3"),
        DatasetSpec("outcome/slide_rate", "/summary/outcome/slide_rate", "m/s", (), "real",
                    "largest footpad speed along the terrain at the final time", (), "1.3"),
        DatasetSpec("outcome/footpad_speed", "/summary/outcome/footpad_speed", "m/s", (), "real",
                    "largest footpad speed (slide and sink) at the final time", (), "1.3"),
        DatasetSpec("outcome/stroke_rate", "/summary/outcome/stroke_rate", "m/s", (), "real",
                    "largest strut stroke rate at the final time", (), "1.3"),
        DatasetSpec("outcome/tipover_margin", "/summary/outcome/tipover_margin", "deg", (), "real",
                    "further tilt about the nearest support-polygon edge that puts the gravity line through the mass "
                    "centre on it, final state (<= 0: not statically stable)", (), "1.3"),
        DatasetSpec("outcome/friction_ratio", "/summary/outcome/friction_ratio", "-", ("g",), "real",
                    "per footpad |F_t|/(mu_s F_n), final state (< 1 held by static friction, 0 off the ground)",
                    (), "1.3"),
    ]
)

#: root attributes of the file
ROOT_ATTRIBUTES = (
    ("schema_version", "version of this schema, 'MAJOR.MINOR'"),
    ("producer", "'LANDYN <version>'"),
    ("title", "&simulation title"),
)

_BY_KEY = {d.key: d for d in DATASETS}


def units_token(units: str) -> str:
    """Units as a column-name suffix: 'm/s' -> 'm_per_s', 'deg/s' -> 'deg_per_s', '-' -> ''."""
    if units in ("-", ""):
        return ""
    return units.replace("/", "_per_").replace("^", "").replace(" ", "_")


def measure_number(gear: int, strut: int, n_struts: int = len(STRUTS)) -> int:
    """Table 3 measure number (1-based) of gear (1-based) and strut index (0 primary, 1 left, 2 right)
    on a lander with n_struts struts per gear."""
    return n_struts * (gear - 1) + strut + 1


def measure_gear_strut(measure: int, n_struts: int = len(STRUTS)) -> tuple[int, int]:
    """(gear 1-based, strut index 0..n_struts-1) of a Table 3 measure number."""
    return (measure - 1) // n_struts + 1, (measure - 1) % n_struts


def strut_index(name: str) -> int:
    """Strut index 0..2 from a name ('primary', 'secondary_left', 'left', '2', ...)."""
    key = str(name).strip().lower().replace(" ", "_").replace("-", "_")
    if key not in _STRUT_ALIASES:
        raise LandynPostError(f"unknown strut {name!r} (use primary, secondary_left or secondary_right)")
    return _STRUT_ALIASES[key]


# ----------------------------------------------------------------------------------------- channels

@dataclass
class Channel:
    """One scalar time history selected from the file: a dataset and the gear/strut/component."""
    key: str
    gear: int | None          #: 1-based, for gear datasets
    index: int | None         #: last-axis index for 3-vectors (strut or component)
    values: np.ndarray
    units: str
    label: str                #: canonical spec, e.g. 'stroke[gear=1,strut=primary]'
    column: str               #: CSV column name with units, e.g. 'gear1_primary_stroke_m'


_SPEC_RE = re.compile(r"^\s*([A-Za-z_][A-Za-z0-9_/]*)\s*(?:\[(.*)\])?\s*$")


def parse_channel_spec(text: str) -> tuple[str, dict[str, str]]:
    """Splits 'stroke[gear=1,strut=primary]' into ('stroke', {'gear': '1', 'strut': 'primary'})."""
    m = _SPEC_RE.match(text)
    if not m:
        raise LandynPostError(f"malformed channel {text!r} (expected e.g. stroke[gear=1,strut=primary])")
    name = m.group(1).strip("/").replace("/", "_")
    # accept dataset paths like body/velocity, energy/friction or timeseries/gears/stroke
    for prefix in ("timeseries_", "body_", "gears_"):
        if name.startswith(prefix):
            name = name[len(prefix):]
    sel = {}
    if m.group(2):
        for part in m.group(2).split(","):
            if not part.strip():
                continue
            if "=" not in part:
                raise LandynPostError(f"malformed selector {part.strip()!r} in channel {text!r} (expected key=value)")
            k, v = part.split("=", 1)
            sel[k.strip().lower()] = v.strip()
    return name, sel


# ----------------------------------------------------------------------------------------- result

class Result:
    """One LANDYN result file read into memory.

    Every dataset is an attribute named by its key (see ``DATASETS``), e.g. ``res.time``,
    ``res.stroke``, ``res.crush_length``, ``res.code_version``; the energy audit is the dict
    ``res.energy`` (``res.energy["friction"]``; keys ``energy/<name>`` in ``res.data``).
    """

    def __init__(self, path: str, attrs: dict[str, str], data: dict[str, object]):
        self.path = path
        self.schema_version = attrs.get("schema_version", "")
        self.producer = attrs.get("producer", "")
        self.title = attrs.get("title", "")
        self.data = data
        self._deck: Namelist | None = None

    def __getattr__(self, name):
        data = self.__dict__.get("data")
        if data is not None and name in data:
            return data[name]
        raise AttributeError(name)

    # -- sizes and labels
    @property
    def n_samples(self) -> int:
        return int(self.data["time"].shape[0])

    @property
    def n_gears(self) -> int:
        return int(self.data["crush_length"].shape[0])

    @property
    def n_struts(self) -> int:
        """Struts per gear: the last axis of the strut arrays (shape "s" in DATASETS)."""
        return int(self.data["crush_length"].shape[1])

    @staticmethod
    def units(key: str) -> str:
        return _BY_KEY[key].units

    @staticmethod
    def spec(key: str) -> DatasetSpec:
        return _BY_KEY[key]

    @property
    def energy(self) -> dict[str, np.ndarray]:
        """Energy-audit channels by name (J)."""
        return {e: self.data["energy/" + e] for e in ENERGY_NAMES}

    @property
    def meta(self) -> dict[str, str]:
        """/meta provenance strings."""
        return {k: self.data[k] for k, _ in META}

    def provenance(self) -> list[tuple[str, str]]:
        """Short provenance lines for reports: (label, value)."""
        return [
            ("file", os.path.abspath(self.path)),
            ("title", self.title),
            ("producer", self.producer),
            ("schema version", self.schema_version),
            ("git revision", self.data["git_revision"]),
            ("build type", self.data["build_type"]),
            ("compiler", self.data["compiler"]),
            ("compiler flags", self.data["compiler_flags"]),
            ("written", self.data["date"]),
            ("deck", self.data["deck_name"]),
            ("command line", self.data["command_line"]),
        ]

    # -- the resolved input
    @property
    def deck(self) -> Namelist:
        """/meta/resolved_input parsed (raises LandynFileError if it cannot be read)."""
        if self._deck is None:
            try:
                self._deck = parse_namelist(self.data["resolved_input"])
            except NamelistError as exc:
                raise LandynFileError(f"{self.path}: /meta/resolved_input cannot be read: {exc}") from None
        return self._deck

    def _deck_value(self, fn, what: str):
        try:
            return fn()
        except NamelistError as exc:
            raise LandynFileError(f"{self.path}: {what} not found in /meta/resolved_input ({exc})") from None

    def strut_capacity(self) -> np.ndarray:
        """Stroke capacity per gear and strut, shape (n_gears, n_struts, 2): [..., 0] toward +
        (primary shortening, secondary lengthening), [..., 1] toward - (secondary shortening,
        as a positive length; NaN for the primary, which has none).

        From /meta/resolved_input (&primary_strut stage_end(n_stages), &secondary_strut
        stroke_lengthening / stroke_shortening); if that cannot be read, the + capacity falls back
        to crushed_positive + stroke_margin from /summary (exact where the + side governs).
        """
        cap = np.full((self.n_gears, self.n_struts, 2), np.nan)
        try:
            d = self.deck
            n_st = int(d.get("primary_strut", "n_stages"))
            ends = d.array("primary_strut", "stage_end", (max(n_st, 1),))
            cap[:, 0, 0] = ends[n_st - 1]
            cap[:, 1:, 0] = float(d.get("secondary_strut", "stroke_lengthening"))
            cap[:, 1:, 1] = float(d.get("secondary_strut", "stroke_shortening"))
        except (LandynFileError, NamelistError, ValueError):
            cap[:, :, 0] = self.data["crushed_positive"] + self.data["stroke_margin"]
        return cap

    def primary_stage_ends(self) -> np.ndarray:
        """Primary honeycomb stage ends (m), from /meta/resolved_input; empty if unavailable."""
        try:
            n_st = int(self.deck.get("primary_strut", "n_stages"))
            return self.deck.array("primary_strut", "stage_end", (n_st,))
        except (LandynFileError, NamelistError, ValueError):
            return np.array([])

    def hard_points(self) -> dict[str, np.ndarray]:
        """Hard points a..f of every gear in the LANDER frame, each (n_gears, 3) m, plus
        'rotation' (n_gears,) deg (gear frame = lander frame rotated about z) and
        'mass_centre' (3,) m, from /meta/resolved_input."""
        d, g = self.deck, self.n_gears

        def read():
            out = {}
            for p in "abcdef":
                out[p] = d.array("gears", "point_" + p, (3, g)).T.copy()
            out["rotation"] = d.array("gears", "rotation", (g,))
            out["mass_centre"] = d.array("lander", "mass_centre", (3,))
            return out

        out = self._deck_value(read, "&gears hard points")
        if not all(np.all(np.isfinite(v)) for v in out.values()):
            raise LandynFileError(f"{self.path}: /meta/resolved_input does not give every gear's hard points")
        return out

    def terrain(self) -> np.ndarray:
        """Terrain plane under each footpad, (n_gears, 3): elevation at the global origin (m, up
        positive), slope (deg), uphill azimuth (deg, from +x toward +y)."""
        d, g = self.deck, self.n_gears

        def read():
            return np.stack([d.array("terrain", k, (g,), fill=0.0)
                             for k in ("height", "slope", "slope_direction")], axis=1)

        return self._deck_value(read, "&terrain")

    # -- channels
    def channel(self, text: str) -> Channel:
        """A scalar time history from a spec such as ``stroke[gear=1,strut=primary]``,
        ``velocity[comp=z]``, ``normal_force[gear=2]`` or ``energy_friction``."""
        name, sel = parse_channel_spec(text)
        for group in ("energy", "gear_axes"):      # column names write group/key as group_key
            if name.startswith(group + "_") and group + "/" + name[len(group) + 1:] in _BY_KEY:
                name = group + "/" + name[len(group) + 1:]
        if name not in _BY_KEY or not _BY_KEY[name].is_timeseries:
            known = ", ".join(d.key for d in DATASETS if d.is_timeseries)
            raise LandynPostError(f"unknown quantity {name!r} in channel {text!r} (known: {known})")
        s = _BY_KEY[name]
        gear = index = None
        unknown = set(sel) - {"gear", "strut", "comp", "component"}
        if unknown:
            raise LandynPostError(f"channel {text!r}: unknown selector(s) {', '.join(sorted(unknown))}")
        if "g" in s.shape:
            if "gear" not in sel:
                raise LandynPostError(f"channel {text!r}: {name} needs gear=1..{self.n_gears}")
            try:
                gear = int(sel["gear"])
            except ValueError:
                raise LandynPostError(f"channel {text!r}: gear must be an integer") from None
            if not 1 <= gear <= self.n_gears:
                raise LandynPostError(f"channel {text!r}: gear {gear} not in 1..{self.n_gears}")
        if s.shape and s.shape[-1] in (3, "s"):
            if s.components == STRUTS:
                if "strut" not in sel:
                    raise LandynPostError(f"channel {text!r}: {name} needs strut=primary|secondary_left|secondary_right")
                index = strut_index(sel["strut"])
            else:
                comp = sel.get("comp", sel.get("component"))
                if comp is None:
                    raise LandynPostError(f"channel {text!r}: {name} needs comp={'|'.join(s.components)}")
                comp_l = comp.lower()
                if comp_l in s.components:
                    index = s.components.index(comp_l)
                elif comp_l in ("1", "2", "3"):
                    index = int(comp_l) - 1
                else:
                    raise LandynPostError(f"channel {text!r}: comp must be one of {', '.join(s.components)}")
        return self._make_channel(name, gear, index)

    def _make_channel(self, key: str, gear: int | None, index: int | None) -> Channel:
        """Channel of dataset `key`, gear (1-based or None), last-axis index (or None).

        Column names: [body_ | gear<i>_] [<strut>_] <dataset> [_<component>] _<units>, e.g.
        body_velocity_z_m_per_s, gear1_primary_stroke_m, gear2_footpad_position_x_m, energy_friction_J.
        """
        s = _BY_KEY[key]
        arr = self.data[key]
        sel, parts = [], []
        if s.path.startswith("/timeseries/body/"):
            parts.append("body")
        if gear is not None:
            arr = arr[:, gear - 1]
            sel.append(f"gear={gear}")
            parts.append(f"gear{gear}")
        name = key.replace("/", "_")
        if index is None:
            parts.append(name)
        else:
            arr = arr[..., index]
            lab = s.components[index]
            if s.components == STRUTS:
                sel.append("strut=" + lab)
                parts += [lab, name]
            else:
                sel.append("comp=" + lab)
                parts += [name, lab]
        tok = units_token(s.units)
        column = "_".join(parts + ([tok] if tok else []))
        label = key + (f"[{','.join(sel)}]" if sel else "")
        return Channel(key, gear, index, np.asarray(arr, dtype=float), s.units, label, column)

    def channels(self, keys=None, gears=None, include_body: bool = True) -> list[Channel]:
        """All scalar time histories (export order): body vectors, then per gear every gear dataset,
        then the energy audit. ``keys`` restricts the datasets, ``gears`` (1-based list) the gears
        (None: all, []: none); ``include_body=False`` drops the body and energy channels."""
        out = []
        wanted = [d for d in DATASETS if d.is_timeseries and (keys is None or d.key in keys)]
        if include_body:
            for d in wanted:
                if d.path.startswith("/timeseries/body/"):
                    if d.shape[-1] == 3:
                        out += [self._make_channel(d.key, None, i) for i in range(3)]
                    else:
                        out.append(self._make_channel(d.key, None, None))
        for g in range(1, self.n_gears + 1) if gears is None else gears:
            for d in wanted:
                if d.path.startswith("/timeseries/gears/"):
                    if d.shape[-1] in (3, "s"):
                        k = self.n_struts if d.shape[-1] == "s" else 3
                        out += [self._make_channel(d.key, g, i) for i in range(k)]
                    else:
                        out.append(self._make_channel(d.key, g, None))
        if include_body:
            out += [self._make_channel(d.key, None, None) for d in wanted if d.path.startswith("/timeseries/energy/")]
        return out

    def channel_by_column(self) -> dict[str, Channel]:
        """Every channel keyed by its CSV column name (as landyn-export writes it)."""
        return {c.column: c for c in self.channels()}


# ----------------------------------------------------------------------------------------- reading

_HDF5_SIGNATURE = b"\x89HDF\r\n\x1a\n"


def is_hdf5(path: str) -> bool:
    """True when the file starts with the HDF5 signature (at offset 0, 512, 1024, ...)."""
    try:
        with open(path, "rb") as fh:
            size = os.fstat(fh.fileno()).st_size
            off = 0
            while off + 8 <= size:
                fh.seek(off)
                if fh.read(8) == _HDF5_SIGNATURE:
                    return True
                off = 512 if off == 0 else off * 2
    except OSError:
        return False
    return False


def _text(v) -> str:
    if isinstance(v, (bytes, np.bytes_)):
        return bytes(v).decode("utf-8", errors="replace").rstrip("\x00 ")
    if isinstance(v, np.ndarray) and v.dtype.kind in "SO" and v.shape == ():
        return _text(v[()])
    return str(v).rstrip("\x00 ")


def load(path: str | os.PathLike) -> Result:
    """Reads a LANDYN result file.

    Raises LandynFileError with a one-line message when the file does not exist, is not HDF5, is
    not a LANDYN result, has an unsupported schema version, lacks a dataset or has one of the
    wrong shape.
    """
    import h5py  # imported here so that `--help` works without h5py

    path = os.fspath(path)
    if not os.path.exists(path):
        raise LandynFileError(f"{path}: no such file")
    if os.path.isdir(path):
        raise LandynFileError(f"{path}: is a directory, not a LANDYN result file")
    if not is_hdf5(path):
        raise LandynFileError(f"{path}: not an HDF5 file (expected a LANDYN result file, .h5)")
    try:
        f = h5py.File(path, "r")
    except OSError as exc:
        raise LandynFileError(f"{path}: cannot open as HDF5 ({exc})") from None
    with f:
        attrs = {k: _text(f.attrs[k]) for k in ("schema_version", "producer", "title") if k in f.attrs}
        ver = attrs.get("schema_version")
        if ver is None:
            raise LandynFileError(f"{path}: no root attribute 'schema_version': not a LANDYN result file")
        if ver.split(".")[0] != SUPPORTED_MAJOR:
            raise LandynFileError(
                f"{path}: schema_version {ver} is not supported (this landyn_post reads {SUPPORTED_MAJOR}.x, "
                f"written for {SCHEMA_VERSION})")
        data: dict[str, object] = {}
        minor = _minor(ver)
        for d in DATASETS:
            if d.path not in f and minor < _minor(d.since):
                data[d.key] = None       # added after the file's schema version
                continue
            if d.path not in f:
                raise LandynFileError(f"{path}: missing dataset {d.path} (schema {ver}); "
                                      "the file is incomplete or not a LANDYN result")
            try:
                obj = f[d.path]
            except (KeyError, OSError, ValueError) as exc:     # a damaged link or object header
                raise LandynFileError(f"{path}: cannot read {d.path}: the file is damaged ({exc})") from None
            if not isinstance(obj, h5py.Dataset):
                raise LandynFileError(f"{path}: {d.path} is a group, expected a dataset")
            data[d.key] = _read_dataset(path, d, obj)
    _check_shapes(path, data)
    return Result(path, attrs, data)


def _read_dataset(path: str, d: DatasetSpec, obj):
    """The value of dataset `obj` as `d` describes it; LandynFileError when it cannot be read (a
    truncated or damaged file) or is not of its kind (text where numbers belong, say)."""
    try:
        raw = obj[()]
    except (OSError, ValueError, KeyError, TypeError) as exc:
        raise LandynFileError(f"{path}: cannot read {d.path}: the file is truncated or damaged ({exc})") from None
    if d.kind != "text" and np.asarray(raw).dtype.kind not in "biuf":
        raise LandynFileError(f"{path}: {d.path} holds {np.asarray(raw).dtype} data, expected numbers "
                              f"({d.kind}); the file is damaged or not a LANDYN result")
    if d.kind == "text" and np.ndim(raw) >= 1:
        return tuple(_text(x) for x in np.ravel(raw))     # a list of names
    if d.kind == "text":
        return _text(raw)
    if d.kind == "bool":
        return bool(np.asarray(raw).item())
    if d.kind == "int":
        return np.asarray(raw).astype(int) if np.ndim(raw) else int(raw)
    return np.asarray(raw, dtype=float) if np.ndim(raw) else float(raw)


def _minor(version: str) -> int:
    """Minor number of 'MAJOR.MINOR' (0 when absent)."""
    parts = version.split(".")
    return int(parts[1]) if len(parts) > 1 and parts[1].isdigit() else 0


def _check_shapes(path: str, data: dict[str, object]) -> None:
    n = np.shape(data["time"])[0] if np.ndim(data["time"]) == 1 else -1
    g, ns = np.shape(data["crush_length"]) if np.ndim(data["crush_length"]) == 2 else (-1, -1)
    if n < 1 or g < 1 or ns < 1:
        raise LandynFileError(f"{path}: /timeseries/time or /summary/crush_length has an unexpected shape")
    for d in DATASETS:
        if d.kind == "text" or data[d.key] is None:
            continue
        want = tuple({"n": n, "g": g, "s": ns}.get(s, s) for s in d.shape)
        got = np.shape(data[d.key])
        if got != want:
            raise LandynFileError(f"{path}: {d.path} has shape {got}, expected {want} "
                                  f"({', '.join(map(str, d.shape))})")
