"""landyn-export: LANDYN run results, landyn_study files and landyn_batch campaign summaries to
CSV, MATLAB .mat and (runs) a ParaView-readable XDMF file.

Column names carry their units: time_s, body_velocity_z_m_per_s, body_euler_angles_pitch_deg,
gear1_primary_stroke_m, gear1_secondary_left_strut_force_N, gear1_footpad_position_x_m,
gear1_normal_force_N, energy_honeycomb_work_J ... (SI, z down, signs as in docs/output.md);
``--units engineering``: mm, kN, kJ, kN m (gear1_primary_stroke_mm, gear1_normal_force_kN ...).
Every file is written under a temporary name and renamed when complete; an input file is never
overwritten.
"""
from __future__ import annotations

import csv
import os
import sys

import numpy as np

from . import cli
from .schema import STRUTS, Channel, LandynPostError, Result, load, measure_number, units_token

TIME_COLUMN = "time_s"


def write_csv(path: str, time: np.ndarray, channels: list[Channel]) -> str:
    """One table: time_s then one column per channel; values with 12 significant digits."""
    data = np.column_stack([time] + [c.values for c in channels])
    with cli.atomic_output(path, "w", newline="") as fh:
        w = csv.writer(fh)
        w.writerow([TIME_COLUMN] + [c.column for c in channels])
        for row in data:
            w.writerow([f"{v:.12g}" for v in row])
    return path


def engineering_channels(channels: list[Channel]) -> list[Channel]:
    """The channels in engineering units (units.to_engineering: m -> mm, N -> kN, J -> kJ, N m ->
    kN m), the unit at the end of each column name changed with them."""
    from dataclasses import replace

    from .exchange import units_suffix
    from .units import to_engineering
    out = []
    for c in channels:
        values, unit = to_engineering(c.values, c.units)
        column = c.column
        old = units_token(c.units)
        if unit != c.units and old and column.endswith("_" + old):
            column = column[:-len(old)] + units_suffix(unit)
        out.append(replace(c, values=values, units=unit, column=column))
    return out


def write_summary_csv(path: str, res: Result) -> str:
    """Per-strut summary in Table 3's row layout (measure 1..3*n_gears), lengths in mm, forces in kN.
    `landyn-compare RESULT this.csv --column crush` compares against it."""
    with cli.atomic_output(path, "w", newline="") as fh:
        w = csv.writer(fh)
        w.writerow(["measure", "gear", "strut", "crush_mm", "crushed_positive_mm", "crushed_negative_mm",
                    "stroke_margin_mm", "bottomed_out", "peak_strut_force_kN", "crush_work_J"])
        for i in range(res.n_gears):
            for k in range(res.n_struts):
                w.writerow([measure_number(i + 1, k, res.n_struts), i + 1, STRUTS[k],
                            f"{res.crush_length[i, k] * 1e3:.6f}", f"{res.crushed_positive[i, k] * 1e3:.6f}",
                            f"{res.crushed_negative[i, k] * 1e3:.6f}", f"{res.stroke_margin[i, k] * 1e3:.6f}",
                            int(res.bottomed_out[i, k]), f"{res.peak_strut_force[i, k] / 1e3:.6f}",
                            f"{res.crush_work[i, k]:.6g}"])
    return path


def _main(argv=None) -> int:
    p = cli.make_parser(
        "landyn-export", "Export a LANDYN result, landyn_study file or landyn_batch campaign summary to CSV,\n"
        "MATLAB .mat and (results) a ParaView-readable XDMF file. Column names carry units.",
        epilog="outputs of a result file (run):\n"
               "  default      OUT (default <stem>_timeseries.csv): one wide table, all time histories\n"
               "  --per-gear   OUT is a directory (default <stem>_csv/): <stem>_body.csv (body and energy)\n"
               "               and <stem>_gear<i>.csv for every gear\n"
               "  --summary    also <stem>_crush.csv (or next to OUT): per-strut crush lengths in Table 3 rows\n"
               "  --tables     every other table as CSV: <stem>_summary.csv (per gear and strut), <stem>_scalars.csv\n"
               "               (every scalar, the provenance and the root attributes) ... in DIR (default <stem>_tables/)\n"
               "  --mat        every dataset to MATLAB (default <stem>.mat; layout in post/README.md)\n"
               "  --xdmf       <stem>.xdmf + <stem>_mesh.h5: struts and footpads moving, for ParaView\n"
               "outputs of a campaign summary or a study file:\n"
               "  default      every table as CSV in OUT (default <stem>_csv/): campaign <stem>_cases.csv (one\n"
               "               row per case: inputs, status, failed criteria, metrics, crush per strut),\n"
               "               _parameters, _probability, _scalars; study <stem>_table.csv (Tables 6/9/10\n"
               "               layout), _runs.csv (one row per variant and load case), _study, _summary, _scalars\n"
               "  --mat        MATLAB file (default <stem>.mat)\n\n"
               "examples:\n  landyn-export lc3.h5 -o lc3.csv\n"
               "  landyn-export lc3.h5 --units engineering -o lc3_mm_kN.csv\n"
               "  landyn-export lc3.h5 --mat --xdmf --tables\n"
               "  landyn-export dispersion.h5 --mat\n  landyn-export study_friction.h5 -o friction_csv")
    p.add_argument("file", metavar="FILE", help="LANDYN result, study or campaign file (.h5)")
    p.add_argument("-o", "--output", metavar="OUT", help="output CSV file (a directory with --per-gear and for "
                   "study and campaign files)")
    p.add_argument("--per-gear", action="store_true", help="one file per gear plus one for body and energy")
    p.add_argument("--units", choices=("si", "engineering"), default="si",
                   help="si (default: m, N, J, N m) or engineering (mm, kN, kJ, kN m; m/s, deg, g and s unchanged); "
                        "the column names and the MATLAB 'units' fields say which")
    p.add_argument("--summary", action="store_true", help="also write the per-strut crush-length summary CSV")
    p.add_argument("--tables", nargs="?", const="", metavar="DIR", help="a result's summary tables as CSV")
    p.add_argument("--mat", nargs="?", const="", metavar="FILE", help="MATLAB .mat file (default <stem>.mat)")
    p.add_argument("--xdmf", nargs="?", const="", metavar="FILE",
                   help="XDMF file for ParaView, with <stem>_mesh.h5 beside it (results only; default <stem>.xdmf)")
    a = p.parse_args(argv)
    from .exchange import file_kind, write_mat, write_tables, write_xdmf
    kind = file_kind(a.file)
    base = cli.stem(a.file)
    written: list[str] = []

    def out_path(given: str | None, default: str) -> str:
        path = given or default
        cli.refuse_overwrite(path, [a.file])
        return path

    if kind != "run":
        if a.per_gear or a.summary or a.tables is not None or a.xdmf is not None:
            p.error(f"--per-gear, --summary, --tables and --xdmf apply to result files; {a.file} is a {kind} file")
        if a.mat is None or a.output:
            outdir = out_path(a.output, base + "_csv")
            written += write_tables(a.file, kind, cli.output_dir(outdir), a.units)
        if a.mat is not None:
            written.append(write_mat(out_path(a.mat, base + ".mat"), a.file, a.units))
        for fn in written:
            print(fn)
        return cli.EXIT_OK

    res = load(a.file)

    def channels(**kw) -> list[Channel]:
        ch = res.channels(**kw)
        return engineering_channels(ch) if a.units == "engineering" else ch

    default_csv = a.output is not None or a.per_gear or a.summary or all(
        x is None for x in (a.tables, a.mat, a.xdmf))
    if default_csv:
        if a.per_gear:
            outdir = cli.output_dir(out_path(a.output, base + "_csv"))
            written.append(write_csv(os.path.join(outdir, f"{base}_body.csv"), res.time, channels(gears=[])))
            for g in range(1, res.n_gears + 1):
                written.append(write_csv(os.path.join(outdir, f"{base}_gear{g}.csv"), res.time,
                                         channels(gears=[g], include_body=False)))
            summary_dir = outdir
        else:
            out = out_path(a.output, base + "_timeseries.csv")
            d = os.path.dirname(out)
            if d:
                cli.output_dir(d)
            written.append(write_csv(out, res.time, channels()))
            summary_dir = d
        if a.summary:
            written.append(write_summary_csv(os.path.join(summary_dir, f"{base}_crush.csv"), res))
    if a.tables is not None:
        written += write_tables(a.file, kind, cli.output_dir(out_path(a.tables, base + "_tables")), a.units)
    if a.mat is not None:
        written.append(write_mat(out_path(a.mat, base + ".mat"), a.file, a.units))
    if a.xdmf is not None:
        xdmf = out_path(a.xdmf, base + ".xdmf")
        cli.refuse_overwrite(os.path.splitext(xdmf)[0] + "_mesh.h5", [a.file], hdf5=True)   # its heavy data
        written += write_xdmf(xdmf, res)
    for fn in written:
        print(fn)
    return cli.EXIT_OK


def main(argv=None) -> int:
    return cli.run("landyn-export", _main, argv)


if __name__ == "__main__":
    sys.exit(main())
