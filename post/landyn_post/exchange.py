"""Exchange formats for every LANDYN file: run results, landyn_study files and landyn_batch
campaign summaries, to CSV tables, MATLAB .mat (scipy.io) and, for runs, a ParaView-readable
XDMF sidecar over an HDF5 file of the moving struts and footpads.

File kinds (``file_kind``): 'run' (root attribute schema_version 1.x), 'campaign'
(root attribute schema_version = schema.CAMPAIGN_SCHEMA) and 'study' (producer '... landyn_study' with /table).

MATLAB layout (``write_mat``): one struct per HDF5 group, named after it (``timeseries``,
``summary``, ``meta``, ``cases``, ``table`` ...), fields named after the datasets; names that are
not MATLAB identifiers are changed (``LC-1`` -> ``LC_1``, ``001`` -> ``v001``, ``energy/input``
-> ``energy.input``). Arrays keep the order h5py reads, which puts the sample or case index
FIRST, as MATLAB users expect: ``timeseries.gears.stroke`` is n_samples x n_gears x 3, so
``plot(timeseries.time, timeseries.gears.stroke(:, 1, 1))`` is gear 1's primary stroke;
``cases.crush_length`` is n_cases x n_gears x 3; vectors are columns (n x 1). Texts are char
arrays, lists of texts cell arrays. Every struct has a field ``units`` with the unit of each field
(a struct of strings), a field ``components`` naming the entries of every axis of fixed length
(``components.stroke = {'primary'; 'secondary_left'; 'secondary_right'}``, ``components.velocity
= {'x'; 'y'; 'z'}``, ``components.euler_angles = {'yaw'; 'pitch'; 'roll'}``) and a field ``dims``
naming every axis (``dims.stroke = 'sample x gear x strut'``); the file has a char variable
``landyn_info`` describing the layout.

CSV column names are MATLAB-safe (``readtable`` keeps them as they are): letters, digits and
``_`` only, starting with a letter, at most 63 characters, the units last
(``inputs_initial_state_attitude_1_deg``, ``inputs_soil_stiffness_N_per_m_pow_n``).
``--units engineering`` (``engineering_tree``) writes lengths in mm, forces in kN, energies in kJ
and moments in kN m instead of SI.
"""
from __future__ import annotations

import csv
import os
import re
import xml.etree.ElementTree as ET

import numpy as np

from . import cli
from .schema import (CAMPAIGN_SCHEMA, DATASETS, LOAD_NAMES, PEAK_JOINTS, PEAK_QUANTITIES, STRUTS, LandynPostError,
                     is_hdf5)



def _text(v) -> str:
    if isinstance(v, (bytes, np.bytes_)):
        return bytes(v).decode("utf-8", errors="replace").rstrip("\x00 ")
    return str(v)


def file_kind(path: str) -> str:
    """'run', 'campaign' or 'study'; LandynPostError for anything else."""
    import h5py
    if not os.path.exists(path):
        raise LandynPostError(f"{path}: no such file")
    if not is_hdf5(path):
        raise LandynPostError(f"{path}: not an HDF5 file (expected a LANDYN result, study or campaign file)")
    with h5py.File(path, "r") as f:
        ver = _text(f.attrs.get("schema_version", ""))
        prod = _text(f.attrs.get("producer", ""))
        if ver == CAMPAIGN_SCHEMA:
            missing = [g for g in ("campaign", "parameters", "cases") if not isinstance(f.get(g), h5py.Group)]
            if missing:
                raise LandynPostError(f"{path}: a campaign summary without /{', /'.join(missing)}: the file is "
                                      "damaged or incomplete")
            return "campaign"
        if ver.split(".")[0] == "1":
            return "run"
        if prod.endswith("landyn_study") and "table" in f:
            return "study"
    raise LandynPostError(f"{path}: neither a LANDYN result (schema_version {ver or 'missing'}), a campaign summary "
                          f"({CAMPAIGN_SCHEMA}) nor a landyn_study file")


# ----------------------------------------------------------------------------------------- reading

class Node(dict):
    """A group: name -> Node or Leaf."""


class Leaf:
    def __init__(self, value, units: str, description: str = ""):
        self.value, self.units, self.description = value, units, description


def read_tree(path: str) -> tuple[dict[str, str], Node]:
    """Root attributes (as text) and every group and dataset of an HDF5 file."""
    import h5py

    def walk(g) -> Node:
        node = Node()
        for k, obj in g.items():
            if isinstance(obj, h5py.Group):
                node[k] = walk(obj)
                continue
            raw = obj[()]
            if obj.dtype.kind in "SO":
                val = _text(raw) if np.ndim(raw) == 0 else [_text(x) for x in np.ravel(raw)]
            else:
                val = np.asarray(raw)
            node[k] = Leaf(val, _text(obj.attrs.get("units", "-")), _text(obj.attrs.get("description", "")))
        return node

    with h5py.File(path, "r") as f:
        attrs = {k: (_text(v) if not isinstance(v, np.ndarray) or v.dtype.kind in "SO" else v) for k, v in f.attrs.items()}
        attrs = {k: (v if isinstance(v, str) else (float(v) if np.ndim(v) == 0 else v)) for k, v in attrs.items()}
        return attrs, walk(f)


# ----------------------------------------------------------------------------------------- MATLAB

_MAT_NAME = re.compile(r"[^A-Za-z0-9_]")


def mat_name(name: str) -> str:
    """A MATLAB identifier for a group or dataset name ('LC-1' -> 'LC_1', '001' -> 'v001')."""
    s = _MAT_NAME.sub("_", name)
    if not s or not s[0].isalpha():
        s = "v" + s
    return s[:63]


def _mat_value(v):
    if isinstance(v, str):
        return v
    if isinstance(v, list):
        out = np.empty((len(v), 1), dtype=object)
        for i, x in enumerate(v):
            out[i, 0] = x
        return out
    a = np.asarray(v)
    if a.ndim == 1:
        return a.reshape(-1, 1)         # column vector
    return a


#: dataset path -> (names of the last axis, names of every axis) from the result schema
_AXIS_WORDS = {"n": "sample", "g": "gear", "s": "strut"}
_SCHEMA_AXES = {d.path: (tuple(d.components), " x ".join(_AXIS_WORDS.get(str(a), "strut" if d.components == STRUTS
                                                                     else "component") for a in d.shape))
                for d in DATASETS if d.shape}
#: datasets of study and campaign files whose last axis is the strut (n_cases x n_gears x 3 ...)
_STRUT_FIELDS = {"crush_length", "crushed_positive", "crushed_negative", "stroke_final", "stroke_margin",
                 "bottomed_out", "crush_work", "mode_switches", "peak_strut_force"}


def _axes_of(path: str, name: str, value) -> tuple[tuple, str]:
    """(names of the last axis' entries or (), names of the axes or '') of a dataset."""
    if path in _SCHEMA_AXES:
        return _SCHEMA_AXES[path]
    shape = np.shape(value) if not isinstance(value, (str, list)) else ()
    if name in _STRUT_FIELDS and len(shape) >= 2 and shape[-1] == len(STRUTS):
        lead = {"cases": "case", "table": "row"}.get(path.strip("/").split("/")[0], "row")
        return STRUTS, " x ".join(([lead] if len(shape) == 3 else []) + ["gear", "strut"])
    if name == "final_attitude" and shape == (3,):
        return ("yaw", "pitch", "roll"), "component"
    return (), ""


def _cell(names) -> np.ndarray:
    out = np.empty((len(names), 1), dtype=object)
    for i, x in enumerate(names):
        out[i, 0] = x
    return out


def _mat_struct(node: Node, path: str = "") -> dict:
    out, units, comps, dims = {}, {}, {}, {}
    for k, v in node.items():
        name = mat_name(k)
        if isinstance(v, Node):
            out[name] = _mat_struct(v, f"{path}/{k}")
        else:
            out[name] = _mat_value(v.value)
            units[name] = v.units
            c, d = _axes_of(f"{path}/{k}", k, v.value)
            if c:
                comps[name] = _cell(c)
            if d:
                dims[name] = d
    if units:
        out["units"] = units
    if comps:
        out["components"] = comps
    if dims:
        out["dims"] = dims
    return out


MAT_INFO = ("LANDYN export (landyn-export --mat). One struct per HDF5 group, fields named after the datasets "
            "(MATLAB identifiers: '-' -> '_', a leading digit gets 'v'). Arrays as h5py reads them: the sample or "
            "case index first (timeseries.gears.stroke is n_samples x n_gears x 3: primary, secondary left, "
            "secondary right; cases.crush_length is n_cases x n_gears x 3); vectors are columns. Each struct's "
            "field 'units' gives the unit of every field, 'components' the names of the entries of a fixed-length "
            "last axis (components.stroke = {'primary'; 'secondary_left'; 'secondary_right'}, components.velocity "
            "= {'x'; 'y'; 'z'}, components.euler_angles = {'yaw'; 'pitch'; 'roll'}) and 'dims' the names of the "
            "axes (dims.stroke = 'sample x gear x strut'). Frames and signs: docs/output.md, docs/campaign.md, "
            "docs/study.md.")


def write_mat(path: str, src: str, units: str = "si") -> str:
    """Every group and dataset of `src` (run, study or campaign file) as a MATLAB .mat file; with
    units='engineering' lengths in mm, forces in kN, energies in kJ, moments in kN m."""
    from scipy.io import savemat
    attrs, tree = read_tree(src)
    if units == "engineering":
        tree = engineering_tree(tree)
    data = {"landyn_info": MAT_INFO, "landyn_file": os.path.abspath(src), "landyn_units": units,
            "attributes": {mat_name(k): (v if isinstance(v, str) else _mat_value(v)) for k, v in attrs.items()}}
    for k, v in tree.items():
        data[mat_name(k)] = _mat_struct(v, "/" + k) if isinstance(v, Node) else _mat_value(v.value)
    with cli.atomic_output(path, mode=None) as tmp:
        with open(tmp, "wb") as fh:
            savemat(fh, data, long_field_names=True, do_compression=True, oned_as="column")
    return path


def engineering_tree(node: Node) -> Node:
    """A copy of a read tree with every numeric dataset in engineering units (units.to_engineering:
    m -> mm, N -> kN, J -> kJ, N m -> kN m; others unchanged), its units attribute changed with it."""
    from .units import to_engineering
    out = Node()
    for k, v in node.items():
        if isinstance(v, Node):
            out[k] = engineering_tree(v)
        elif isinstance(v.value, (str, list)) or np.asarray(v.value).dtype.kind not in "fiu":
            out[k] = v
        else:
            val, unit = to_engineering(np.asarray(v.value), v.units)
            out[k] = Leaf(val, unit, v.description)
    return out


# ----------------------------------------------------------------------------------------- CSV tables

_NOT_MATLAB = re.compile(r"[^A-Za-z0-9_]+")


def units_suffix(units: str) -> str:
    """Units as a MATLAB-safe column-name suffix: 'm/s' -> 'm_per_s', 'm/s^2' -> 'm_per_s2',
    'N/m^1.5' -> 'N_per_m1p5', 'N/m^n' -> 'N_per_m_pow_n', 'kN m' -> 'kN_m', '-' -> ''."""
    if units in ("-", ""):
        return ""
    u = units.replace("/", "_per_").replace(" ", "_")
    u = re.sub(r"\^([0-9]+(?:\.[0-9]+)?)", lambda m: m.group(1).replace(".", "p"), u)
    u = re.sub(r"\^([A-Za-z]+)", r"_pow_\1", u)
    return _NOT_MATLAB.sub("_", u).strip("_")


def matlab_column(name: str) -> str:
    """A column name MATLAB's readtable keeps unchanged: [A-Za-z][A-Za-z0-9_]*, at most 63
    characters ('inputs_initial_state.attitude_1_deg' -> 'inputs_initial_state_attitude_1_deg')."""
    s = _NOT_MATLAB.sub("_", name).strip("_")
    if not s or not s[0].isalpha():
        s = "x" + s
    return s[:63]


def _unique_columns(names: list[str]) -> list[str]:
    out, seen = [], set()
    for n in names:
        c, k = matlab_column(n), 2
        while c in seen:
            tail = f"_{k}"
            c, k = matlab_column(n)[:63 - len(tail)] + tail, k + 1
        seen.add(c)
        out.append(c)
    return out


def _col_names(name: str, units: str, shape: tuple, labels: tuple | None = None) -> list[str]:
    """Column names of a dataset whose first axis is the table's rows: trailing (g, 3) axes as
    gear<i>_<strut>_<name>, a trailing axis with labels as <label>_<name> (struts) or
    <name>_<label> (components), else numbered 1..k."""
    tok = units_suffix(units)
    suf = f"_{tok}" if tok else ""
    trail = shape[1:]
    if not trail:
        return [name + suf]
    if len(trail) == 2 and trail[1] == len(STRUTS):
        return [f"gear{g + 1}_{STRUTS[k]}_{name}{suf}" for g in range(trail[0]) for k in range(trail[1])]
    if len(trail) == 1:
        if labels is not None and len(labels) == trail[0]:
            if tuple(labels) == STRUTS:
                return [f"{c}_{name}{suf}" for c in labels]
            return [f"{name}_{_MAT_NAME.sub('_', str(c))}{suf}" for c in labels]
        return [f"{name}_{i + 1}{suf}" for i in range(trail[0])]
    return [f"{name}_{'_'.join(str(i + 1) for i in idx)}{suf}" for idx in np.ndindex(*trail)]


def _fmt(v) -> str:
    if isinstance(v, str):
        return v
    if isinstance(v, (float, np.floating)):
        return f"{v:.12g}"
    return str(v)


def _write_table(path: str, columns: list[tuple[str, list]]) -> str:
    n = max((len(c) for _, c in columns), default=0)
    with cli.atomic_output(path, "w", newline="") as fh:
        w = csv.writer(fh)
        w.writerow(_unique_columns([h for h, _ in columns]))
        for i in range(n):
            w.writerow([_fmt(c[i]) for _, c in columns])
    return path


def _table_columns(items: list[tuple[str, Leaf]], labels: dict[str, tuple] | None = None) -> list[tuple[str, list]]:
    cols = []
    for name, leaf in items:
        v = leaf.value
        if isinstance(v, list):
            cols.append((name, v))
            continue
        a = np.asarray(v)
        names = _col_names(name, leaf.units, a.shape, (labels or {}).get(name))
        flat = a.reshape(a.shape[0], -1)
        for j, cn in enumerate(names):
            cols.append((cn, list(flat[:, j])))
    return cols


def _length(leaf: Leaf) -> int | None:
    v = leaf.value
    if isinstance(v, list):
        return len(v)
    return None if np.ndim(v) == 0 else int(np.shape(v)[0])


def tables_of(tree: Node, attrs: dict, skip: tuple[str, ...] = (), labels: dict[str, tuple] | None = None,
              row_names: dict[str, str] | None = None) -> dict[str, list[tuple[str, list]]]:
    """Every dataset as a CSV table: the datasets of a group that share their first axis form one
    table (a subgroup whose datasets all have the length of such a table joins it, e.g.
    /cases/inputs); scalars, short vectors named in `labels` and the root attributes form the
    table 'scalars' (path, value, units). `labels` names the last axis of datasets (by name);
    `row_names` adds a first column '<name>' = 1..n to the table of a group."""
    tables: dict[str, list[tuple[str, list]]] = {}
    scalars: list[tuple[str, str, str]] = [("/@" + k, _fmt(v) if isinstance(v, str) or np.ndim(v) == 0 else
                                           " ".join(map(_fmt, np.ravel(v))), "-") for k, v in attrs.items()]
    labels = labels or {}

    def visit(node: Node, path: str):
        parts: dict[int, list[tuple[str, Leaf]]] = {}
        subgroups = []
        for k, v in node.items():
            p = f"{path}/{k}"
            if p in skip:
                continue
            if isinstance(v, Node):
                subgroups.append((k, v, p))
                continue
            n = _length(v)
            if n is not None and np.ndim(v.value) == 1 and labels.get(k) is not None and len(labels[k]) == n \
                    and not isinstance(v.value, list):
                for lab, x in zip(labels[k], np.ravel(v.value)):          # a labelled vector: scalars
                    scalars.append((f"{p}/{lab}", _fmt(x), v.units))
            elif n is None:
                scalars.append((p, _fmt(v.value if isinstance(v.value, str) else v.value.item()), v.units))
            else:
                parts.setdefault(n, []).append((k, v))
        for k, v, p in subgroups:
            lens = {_length(x) for x in v.values() if isinstance(x, Leaf)}
            if (len(lens) == 1 and None not in lens and next(iter(lens)) in parts
                    and not any(isinstance(x, Node) for x in v.values())):
                parts[next(iter(lens))].extend((f"{k}_{kk}", x) for kk, x in v.items())
            else:
                visit(v, p)
        big = max(parts, key=lambda m: len(parts[m]), default=None)
        for n, items in parts.items():
            name = path.strip("/").replace("/", "_") or "root"
            if n != big:
                name += "_" + items[0][0]
            cols = _table_columns(items, labels)
            if path in (row_names or {}):
                cols.insert(0, (row_names[path], list(range(1, n + 1))))
            tables[name] = cols

    visit(tree, "")
    tables["scalars"] = [("path", [s[0] for s in scalars]), ("value", [s[1] for s in scalars]),
                         ("units", [s[2] for s in scalars])]
    return tables


def study_runs_table(tree: Node) -> list[tuple[str, list]]:
    """landyn_study: one row per variant and load case with the run summary and every strut's
    crush length (from /variants/NNN/<case>/...)."""
    rows: list[dict[str, object]] = []
    for vk in sorted(k for k in tree.get("variants", {}) if isinstance(tree["variants"][k], Node)):
        var = tree["variants"][vk]
        label = var["label"].value if "label" in var else vk
        for ck in (k for k in var if isinstance(var[k], Node)):
            run = var[ck]
            row: dict[str, object] = {"variant": int(vk), "variant_label": label, "load_case": ck}
            for k, leaf in run.items():
                if k == "crush_length":
                    a = np.asarray(leaf.value)
                    for g in range(a.shape[0]):
                        for s in range(a.shape[1]):
                            row[f"gear{g + 1}_{STRUTS[s]}_crush_length_{units_suffix(leaf.units)}"] = a[g, s]
                else:
                    v = leaf.value
                    row[k + (f"_{units_suffix(leaf.units)}" if units_suffix(leaf.units) else "")] = \
                        v if isinstance(v, str) else np.asarray(v).item()
            rows.append(row)
    keys: list[str] = []
    for r in rows:
        keys += [k for k in r if k not in keys]
    return [(k, [r.get(k, "") for r in rows]) for k in keys]


def peak_joint_load_table(tree: Node) -> list[tuple[str, list]]:
    """The peak-load table of a result (schema >= 1.2) as CSV columns: one row per gear, joint
    (a, b, c, d) and quantity (x, y, z, magnitude; lander axes), the peak in kN and its instant,
    then the gear's 21 simultaneous loads (forces in kN, moments in kN m). Empty for older files."""
    summary = tree.get("summary") if isinstance(tree, Node) else None
    grp = summary.get("peak_joint_load") if isinstance(summary, Node) else None
    if not isinstance(grp, Node):
        return []
    value = np.asarray(grp["value"].value, dtype=float)           # (g, 4, 4)
    if grp["value"].units == "kN":                               # already engineering_tree'd
        value = value * 1e3
    time = np.asarray(grp["time"].value, dtype=float)
    simul = np.asarray(grp["simultaneous"].value, dtype=float)     # (g, 16, 21)
    load_cols = [nm + ("_kN" if nm[0] == "F" else "_kNm") for nm in LOAD_NAMES]
    cols: dict[str, list] = {k: [] for k in ["gear", "joint", "quantity", "peak_kN", "time_s"] + load_cols}
    for i in range(value.shape[0]):
        for j, joint in enumerate(PEAK_JOINTS):
            for k, quantity in enumerate(PEAK_QUANTITIES):
                cols["gear"].append(i + 1)
                cols["joint"].append(joint)
                cols["quantity"].append(quantity)
                cols["peak_kN"].append(value[i, j, k] / 1e3)
                cols["time_s"].append(time[i, j, k])
                row = simul[i, len(PEAK_QUANTITIES) * j + k] / 1e3
                for c, x in zip(load_cols, row):
                    cols[c].append(x)
    return list(cols.items())


def write_tables(src: str, kind: str, outdir: str, units: str = "si") -> list[str]:
    """CSV files of every table of a study or campaign file (and of a run's summary and meta);
    units='engineering': mm, kN, kJ, kN m instead of SI (the column names say which)."""
    attrs, tree = read_tree(src)
    if units == "engineering":
        tree = engineering_tree(tree)
    stem = cli.stem(src)
    if kind == "run":
        labels = {k: STRUTS for k in ("crush_length", "crushed_positive", "crushed_negative", "stroke_final",
                                      "stroke_margin", "bottomed_out", "crush_work", "mode_switches",
                                      "peak_strut_force")}
        labels["final_attitude"] = ("yaw", "pitch", "roll")
        tables = tables_of(tree, attrs, ("/timeseries", "/summary/peak_joint_load"), labels, {"/summary": "gear"})
        peaks = peak_joint_load_table(tree)
        if peaks:
            tables["peak_joint_loads"] = peaks
    elif kind == "study":
        variants = tuple(tree["study"]["variant_label"].value) if "study" in tree else ()
        labels = {"crush_length": variants, "status": variants, "energy_residual": variants}
        tables = tables_of(tree, attrs, ("/variants",), labels)
        tables["runs"] = study_runs_table(tree)
    else:
        tables = tables_of(tree, attrs, (), {"body_points": ("x", "y", "z")}, {"/criteria": "body_point"})
    if kind == "campaign" and "cases" in tables:         # the case id, verdict and cause first
        first = ("case_id", "status", "success", "failed_criteria_names", "failed_criteria", "end_reason")
        cols = tables["cases"]
        tables["cases"] = sorted(cols, key=lambda c: (first.index(c[0]) if c[0] in first else
                                                       len(first) + (0 if c[0].startswith("inputs_") else 1)))
    out = []
    for name, cols in tables.items():
        if cols:
            out.append(_write_table(os.path.join(outdir, f"{stem}_{name}.csv"), cols))
    return out


# ----------------------------------------------------------------------------------------- XDMF (ParaView)

PARTS = ("body", "primary", "secondary_left", "secondary_right")


def write_xdmf(path: str, res) -> list[str]:
    """A ParaView-readable XDMF 3 file `path` (.xdmf) and its heavy data `<stem>_mesh.h5`: a temporal
    collection of two grids per output sample, 'struts' (line cells: the body outline edges and
    every strut, with cell data part, strut_force [kN], stroke [mm]) and 'footpads' (vertices with
    normal_force [kN] and penetration [mm]). Coordinates are the global frame turned 180 deg about
    x, (x, -y, -z), so that height is up in ParaView (a proper rotation; nothing is mirrored)."""
    import h5py

    from .geometry import lander_geometry
    geom = lander_geometry(res)
    n, g = res.n_samples, res.n_gears
    hull = geom.body_hull
    k = len(hull)
    top = np.column_stack([hull, np.full(k, geom.body_z[0])])
    bot = np.column_stack([hull, np.full(k, geom.body_z[1])])
    body = np.stack([geom.to_global(np.vstack([top, bot]), i) for i in range(n)])        # (n, 2k, 3)
    joints = np.concatenate([geom.upper, geom.footpad[:, :, None, :], geom.lug], axis=2)  # (n, g, 6, 3): a b c d e f
    pts = np.concatenate([body, joints.reshape(n, 6 * g, 3)], axis=1)
    pts = pts * np.array([1.0, -1.0, -1.0])                                               # height up
    npts = pts.shape[1]
    conn, part = [], []
    for j in range(k):                                       # body: top ring, bottom ring, verticals
        conn += [[j, (j + 1) % k], [k + j, k + (j + 1) % k], [j, k + j]]
        part += [0, 0, 0]
    for i in range(g):
        base = 2 * k + 6 * i
        conn += [[base + 0, base + 3], [base + 1, base + 4], [base + 2, base + 5]]   # a-d, b-e, c-f
        part += [1, 2, 3]
    conn = np.asarray(conn, dtype=np.int32)
    ncell = len(conn)
    nbody = 3 * k
    force = np.full((n, ncell), np.nan)
    stroke = np.full((n, ncell), np.nan)
    force[:, nbody:] = (res.strut_force / 1e3).reshape(n, -1)
    stroke[:, nbody:] = (res.stroke * 1e3).reshape(n, -1)
    foot = res.footpad_position * np.array([1.0, -1.0, -1.0])
    heavy = os.path.splitext(path)[0] + "_mesh.h5"
    hname = os.path.basename(heavy)
    with cli.atomic_output(heavy, mode=None, hdf5=True) as tmp:
        with h5py.File(tmp, "w") as f:
            f.attrs["producer"] = "landyn-export --xdmf"
            f.attrs["source"] = os.path.abspath(res.path)
            f.attrs["frame"] = "global frame turned 180 deg about x: (x, -y, -z), height up, m"
            f["time"] = res.time
            f["points"] = pts
            f["connectivity"] = conn
            f["part"] = np.asarray(part, dtype=np.int32)
            f["strut_force"] = force
            f["stroke"] = stroke
            f["footpads"] = foot
            f["normal_force"] = res.normal_force / 1e3
            f["penetration"] = res.penetration * 1e3

    def slab(ds: str, i: int, shape_all: tuple, shape_one: tuple, nt="Float", prec="8"):
        hs = ET.Element("DataItem", ItemType="HyperSlab", Dimensions=" ".join(map(str, shape_one)), Type="HyperSlab")
        rank = len(shape_all)
        start = [i] + [0] * (rank - 1)
        stride = [1] * rank
        count = [1] + list(shape_all[1:])
        sel = ET.SubElement(hs, "DataItem", Dimensions=f"3 {rank}", Format="XML", NumberType="Int")
        sel.text = " ".join(map(str, start)) + "\n" + " ".join(map(str, stride)) + "\n" + " ".join(map(str, count))
        whole = ET.SubElement(hs, "DataItem", Dimensions=" ".join(map(str, shape_all)), Format="HDF",
                              NumberType=nt, Precision=prec)
        whole.text = f"{hname}:/{ds}"
        return hs

    root = ET.Element("Xdmf", Version="3.0")
    dom = ET.SubElement(root, "Domain")
    ET.SubElement(dom, "Information", Name="source", Value=os.path.abspath(res.path))
    ET.SubElement(dom, "Information", Name="frame", Value="global frame turned 180 deg about x: (x, -y, -z), m")
    ET.SubElement(dom, "Information", Name="title", Value=res.title)
    for name, build in (("struts", True), ("footpads", False)):
        coll = ET.SubElement(dom, "Grid", Name=name, GridType="Collection", CollectionType="Temporal")
        for i in range(n):
            grid = ET.SubElement(coll, "Grid", Name=f"{name}_{i}", GridType="Uniform")
            ET.SubElement(grid, "Time", Value=f"{res.time[i]:.9g}")
            if build:
                top_el = ET.SubElement(grid, "Topology", TopologyType="Polyline", NumberOfElements=str(ncell),
                                       NodesPerElement="2")
                di = ET.SubElement(top_el, "DataItem", Dimensions=f"{ncell} 2", Format="HDF", NumberType="Int",
                                   Precision="4")
                di.text = f"{hname}:/connectivity"
                geo = ET.SubElement(grid, "Geometry", GeometryType="XYZ")
                geo.append(slab("points", i, (n, npts, 3), (npts, 3)))
                att = ET.SubElement(grid, "Attribute", Name="part (0 body, 1 primary, 2 secondary left, 3 right)",
                                    AttributeType="Scalar", Center="Cell")
                pd = ET.SubElement(att, "DataItem", Dimensions=str(ncell), Format="HDF", NumberType="Int", Precision="4")
                pd.text = f"{hname}:/part"
                for ds, label in (("strut_force", "strut_force [kN] (compression +)"),
                                  ("stroke", "stroke [mm] (Table 3 sense)")):
                    att = ET.SubElement(grid, "Attribute", Name=label, AttributeType="Scalar", Center="Cell")
                    att.append(slab(ds, i, (n, ncell), (ncell,)))
            else:
                ET.SubElement(grid, "Topology", TopologyType="Polyvertex", NumberOfElements=str(g), NodesPerElement="1")
                geo = ET.SubElement(grid, "Geometry", GeometryType="XYZ")
                geo.append(slab("footpads", i, (n, g, 3), (g, 3)))
                for ds, label in (("normal_force", "normal_force [kN]"), ("penetration", "penetration [mm]")):
                    att = ET.SubElement(grid, "Attribute", Name=label, AttributeType="Scalar", Center="Node")
                    att.append(slab(ds, i, (n, g), (g,)))
    ET.indent(root)
    with cli.atomic_output(path, "w", encoding="utf-8") as fh:
        fh.write('<?xml version="1.0" ?>\n<!DOCTYPE Xdmf SYSTEM "Xdmf.dtd" []>\n')
        fh.write(ET.tostring(root, encoding="unicode"))
        fh.write("\n")
    return [path, heavy]
