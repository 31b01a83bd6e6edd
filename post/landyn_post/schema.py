"""The LANDYN result-file schema (docs/output.md) and the one reader that maps it to numpy.

The dataset table is not written here: LANDYN declares it once (src/output/landyn_output_schema.f90)
and its build prints it as a JSON manifest, which this package ships as data/output_schema.json
(CTest output_schema_manifest keeps the copy equal to the build's). DATASETS, the schema and
campaign versions, the energy and /meta names come from it. What is added here is the reading:
the strut and component labels, the channel names used by ``landyn-compare`` and
``landyn-export``, and the model of the run from /model (capacities, hard points, frames, terrain).

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

import json
import os
import re
from dataclasses import dataclass

import numpy as np

from .namelist import Namelist, NamelistError, parse_namelist

__all__ = [
    "SCHEMA_VERSION", "CAMPAIGN_SCHEMA", "SUPPORTED_MAJOR", "STRUTS", "STRUT_LABELS", "ENERGY_NAMES", "DATASETS",
    "DatasetSpec", "Channel", "Result", "LandynPostError", "LandynFileError", "load", "is_hdf5",
    "measure_number", "measure_gear_strut", "parse_channel_spec", "units_token", "strut_index",
    "ROOT_ATTRIBUTES", "META", "JOINT_BLOCKS", "LOAD_NAMES", "PEAK_JOINTS", "PEAK_QUANTITIES",
]

_MANIFEST_PATH = os.path.join(os.path.dirname(os.path.abspath(__file__)), "data", "output_schema.json")


def _load_manifest(path: str = _MANIFEST_PATH) -> dict:
    """The result-file schema as LANDYN declares it (src/output/landyn_output_schema.f90), from the
    manifest landyn_schema writes; this package ships a copy (CTest output_schema_manifest keeps it
    equal to the build's)."""
    try:
        with open(path, encoding="utf-8") as fh:
            return json.load(fh)
    except (OSError, ValueError) as exc:
        raise ImportError(f"landyn_post: cannot read the output-schema manifest {path}: {exc}") from None


_MANIFEST = _load_manifest()
SCHEMA_VERSION: str = _MANIFEST["schema_version"]     #: the result schema version this package reads
CAMPAIGN_SCHEMA: str = _MANIFEST["campaign_schema"]   #: root attribute schema_version of a campaign summary
SUPPORTED_MAJOR = SCHEMA_VERSION.split(".")[0]        #: files with schema_version MAJOR.x are read (minor versions only add)

#: strut order of the last axis of gear arrays (Table 3 measure order within a gear)
STRUTS = ("primary", "secondary_left", "secondary_right")
STRUT_LABELS = {"primary": "primary", "secondary_left": "secondary left", "secondary_right": "secondary right"}
_STRUT_ALIASES = {"primary": 0, "p": 0, "1": 0, "secondary_left": 1, "left": 1, "l": 1, "2": 1,
                  "secondary_right": 2, "right": 2, "r": 2, "3": 2}


class LandynPostError(Exception):
    """A user-facing error: the tools print its message on one line and exit with status 2."""


class LandynFileError(LandynPostError):
    """The file is missing, not HDF5, of another schema version or lacks a dataset."""


@dataclass(frozen=True)
class DatasetSpec:
    """One dataset of the schema (one entry of the manifest).

    shape uses symbols: ``n`` output samples, ``g`` gears, ``s`` struts per gear, ``m`` rows of
    /api/inputs, ``k`` primary honeycomb stages, ``l`` crush levels, integers for fixed lengths.
    kind is ``real``, ``int``, ``bool`` (int 0/1 with attribute type=logical) or ``text``.
    components labels the last axis (vectors) where it has a meaning; STRUTS for strut axes.
    written is ``always``, ``with health``, ``api inputs`` (only in C API files with inputs) or ``summaries``
    (only in campaign summaries, never in a result file).
    """
    key: str
    path: str
    units: str
    shape: tuple
    kind: str
    meaning: str
    components: tuple = ()
    since: str = "1.0"    #: schema version that added it (older files are read without it)
    written: str = "always"

    @property
    def is_timeseries(self) -> bool:
        return self.path.startswith("/timeseries/") and self.key != "time"


_KEY_PREFIXES = ("/timeseries/body/", "/timeseries/gears/", "/timeseries/", "/summary/", "/meta/", "/")


def _key(path: str) -> str:
    """Short name of a dataset (the attribute of Result): the path without its group prefix, e.g.
    stroke, energy/friction, gear_axes/joint_force_a, integrator/name, model/stroke_capacity."""
    for pre in _KEY_PREFIXES:
        if path.startswith(pre):
            return path[len(pre):]
    return path


def _spec(d: dict) -> DatasetSpec:
    comps = tuple(d["components"])
    return DatasetSpec(_key(d["path"]), d["path"], d["units"], tuple(d["shape"]), d["kind"], d["meaning"],
                       STRUTS if comps == ("s",) else comps, d["since"], d["written"])


#: Every dataset of the schema (root attributes title, producer, schema_version are separate).
DATASETS: tuple[DatasetSpec, ...] = tuple(_spec(d) for d in _MANIFEST["datasets"])

#: energy-audit channels, in the order LANDYN writes them
ENERGY_NAMES = tuple(d.key.split("/", 1)[1] for d in DATASETS if d.path.startswith("/timeseries/energy/"))
#: interface loads (schema 1.2): the load vector's blocks as LANDYN writes them, (key, units, meaning)
JOINT_BLOCKS = tuple((d.key, d.units, d.meaning) for d in DATASETS
                     if d.path.startswith(("/timeseries/gears/joint_", "/timeseries/gears/footpad_joint")))
#: names of the 21 loads of /summary/peak_joint_load/simultaneous
LOAD_NAMES = tuple(f"F{j}_{c}" for j in "abcd" for c in "xyz") + tuple(f"M{j}_{c}" for j in "abc" for c in "xyz")
PEAK_JOINTS = ("a", "b", "c", "d")
PEAK_QUANTITIES = ("x", "y", "z", "magnitude")
#: /meta: provenance strings (all scalar text, units '-'), (key, meaning)
META = tuple((d.key, d.meaning) for d in DATASETS if d.path.startswith("/meta/") and d.written != "summaries")

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

    # -- the model (/model, schema 1.4)
    def model(self, name: str) -> np.ndarray:
        """Dataset /model/<name>; LandynFileError naming the missing group for a file older than
        schema 1.4 (it has no /model: rewrite it with this LANDYN)."""
        v = self.data.get("model/" + name)
        if v is None:
            raise LandynFileError(f"{self.path}: no /model group (schema_version {self.schema_version}; /model "
                                  f"came with 1.4): /model/{name} is needed here; run the deck again with this LANDYN")
        return v

    @property
    def has_model(self) -> bool:
        """The file has the /model group (schema 1.4 or later)."""
        return self.data.get("model/n_gears") is not None

    def strut_capacity(self) -> np.ndarray:
        """Stroke capacity per gear and strut, shape (n_gears, n_struts, 2): [..., 0] toward +
        (primary shortening, secondary lengthening), [..., 1] toward - (secondary shortening,
        as a positive length; NaN where a strut has none, as the primary).

        From /model/stroke_capacity; a file older than schema 1.4 has only the + capacity as
        crushed_positive + stroke_margin from /summary (exact where the + side governs).
        """
        if not self.has_model:
            cap = np.full((self.n_gears, self.n_struts, 2), np.nan)
            cap[:, :, 0] = self.data["crushed_positive"] + self.data["stroke_margin"]
            return cap
        cap = np.array(self.model("stroke_capacity"), dtype=float)
        cap[..., 1] = np.where(cap[..., 1] > 0.0, cap[..., 1], np.nan)
        return cap

    def primary_stage_ends(self) -> np.ndarray:
        """Primary honeycomb stage ends (m), from /model/primary_stage_end; empty for an older file."""
        return np.asarray(self.model("primary_stage_end"), dtype=float) if self.has_model else np.array([])

    def hard_points(self) -> dict[str, np.ndarray]:
        """Hard points a..f of every gear in the LANDER frame, each (n_gears, 3) m (a, b, c the
        upper joints of the primary and the secondaries, d the footpad joint, e, f the lugs), plus
        'rotation' (n_gears,) deg (gear frame = lander frame rotated about z), 'mass_centre' (3,) m,
        'gear_axes' (n_gears, 3, 3) (rows: the gear's axes in lander axes) and 'strut_frame'
        (n_gears, n_struts, 3, 3) (each strut's nominal frame, columns x0 y0 z0 in lander axes),
        all from /model."""
        upper, lower = self.model("upper_joint"), self.model("lower_joint")
        axes = self.model("gear_axes")
        out = {p: np.array(upper[:, k]) for k, p in enumerate("abc")}
        out.update({p: np.array(lower[:, k]) for k, p in enumerate("def")})
        out["rotation"] = np.mod(np.degrees(np.arctan2(axes[:, 0, 1], axes[:, 0, 0])), 360.0)
        out["mass_centre"] = np.array(self.model("mass_centre"))
        out["gear_axes"] = np.array(axes)
        out["strut_frame"] = np.stack([self.model("strut_frame/" + c) for c in "xyz"], axis=-1)
        return out

    def terrain(self) -> np.ndarray:
        """Terrain plane under each footpad, (n_gears, 3): elevation at the global origin (m, up
        positive), slope (deg), uphill azimuth (deg, from +x toward +y); from /model/terrain."""
        return np.stack([np.asarray(self.model("terrain/" + k), dtype=float)
                         for k in ("height", "slope", "slope_direction")], axis=1)

    def has_model_since(self, version: str) -> bool:
        """The file's schema is `version` (MAJOR.MINOR) or later: it has the /model datasets that
        version added."""
        return self.has_model and _minor(self.schema_version) >= _minor(version)

    def crush_levels(self) -> list[tuple[int, int, float, str]]:
        """Every strut's crush levels as rows (gear, strut, force, name): gear and strut 0-based,
        force the axial force at which the strut's buffer crushes (N, compression +, like
        strut_force), name what the level is ('stage 1', 'lengthening', ...).

        From /model/crush_levels (schema 1.5: the buffer laws report them). A file older than 1.5
        lacks them: see _crush_levels_from_deck, the deck fallback.
        """
        if not self.has_model_since("1.5"):
            return _crush_levels_from_deck(self)
        return [(int(i), int(k), float(f), str(n)) for i, k, f, n in
                zip(self.model("crush_levels/gear"), self.model("crush_levels/strut"),
                    self.model("crush_levels/force"), self.model("crush_levels/name"))]

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


def _crush_levels_from_deck(res: Result) -> list[tuple[int, int, float, str]]:
    """Deck fallback of Result.crush_levels for files older than schema 1.5 (no
    /model/crush_levels): the honeycomb laws' levels re-derived from /meta/resolved_input
    (&primary_strut stage_force, &secondary_strut force_lengthening / force_shortening), for a
    tripod of every gear; empty when the deck lacks them (the levels are decoration)."""
    rows: list[tuple[int, int, float, str]] = []
    try:
        d = res.deck
        n = int(d.get("primary_strut", "n_stages"))
        stages = [float(f) for f in d.array("primary_strut", "stage_force", (n,))]
        fl = float(d.get("secondary_strut", "force_lengthening"))
        fsh = float(d.get("secondary_strut", "force_shortening"))
    except Exception:  # noqa: BLE001 - a deck without them draws none
        return rows
    for i in range(res.n_gears):
        rows += [(i, 0, f, f"stage {k + 1}") for k, f in enumerate(stages)]
        for k in range(1, min(3, res.n_struts)):
            rows += [(i, k, -fl, "lengthening"), (i, k, fsh, "shortening")]
    return rows


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
            if d.path not in f and (minor < _minor(d.since) or d.written in ("api inputs", "summaries")):
                data[d.key] = None       # added after the file's schema version, or not written by this producer
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
        free = [isinstance(w, str) for w in want]      # m, k, l: any length
        if len(got) != len(want) or any(a != b for a, b, x in zip(got, want, free) if not x):
            raise LandynFileError(f"{path}: {d.path} has shape {got}, expected {want} "
                                  f"({', '.join(map(str, d.shape))})")
