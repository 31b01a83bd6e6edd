"""landyn-export: time histories (and the crush-length summary) of a LANDYN result to CSV.

Column names carry their units: time_s, body_velocity_z_m_per_s, body_euler_angles_pitch_deg,
gear1_primary_stroke_m, gear1_secondary_left_strut_force_N, gear1_footpad_position_x_m,
gear1_normal_force_N, energy_honeycomb_work_J ... (SI, z down, signs as in docs/output.md).
"""
from __future__ import annotations

import csv
import os
import sys

import numpy as np

from . import cli
from .schema import STRUTS, Channel, LandynPostError, Result, load, measure_number

TIME_COLUMN = "time_s"


def write_csv(path: str, time: np.ndarray, channels: list[Channel]) -> str:
    """One table: time_s then one column per channel; values with 12 significant digits."""
    data = np.column_stack([time] + [c.values for c in channels])
    try:
        with open(path, "w", newline="") as fh:
            w = csv.writer(fh)
            w.writerow([TIME_COLUMN] + [c.column for c in channels])
            for row in data:
                w.writerow([f"{v:.12g}" for v in row])
    except OSError as exc:
        raise LandynPostError(f"cannot write {path}: {exc.strerror}") from None
    return path


def write_summary_csv(path: str, res: Result) -> str:
    """Per-strut summary in Table 3's row layout (measure 1..3*n_gears), lengths in mm, forces in kN.
    `landyn-compare RESULT this.csv --column crush` compares against it."""
    with open(path, "w", newline="") as fh:
        w = csv.writer(fh)
        w.writerow(["measure", "gear", "strut", "crush_mm", "crushed_positive_mm", "crushed_negative_mm",
                    "stroke_margin_mm", "bottomed_out", "peak_strut_force_kN", "crush_work_J"])
        for i in range(res.n_gears):
            for k in range(3):
                w.writerow([measure_number(i + 1, k), i + 1, STRUTS[k],
                            f"{res.crush_length[i, k] * 1e3:.6f}", f"{res.crushed_positive[i, k] * 1e3:.6f}",
                            f"{res.crushed_negative[i, k] * 1e3:.6f}", f"{res.stroke_margin[i, k] * 1e3:.6f}",
                            int(res.bottomed_out[i, k]), f"{res.peak_strut_force[i, k] / 1e3:.6f}",
                            f"{res.crush_work[i, k]:.6g}"])
    return path


def _main(argv=None) -> int:
    p = cli.make_parser(
        "landyn-export", "Export the time histories of a LANDYN result file to CSV (column names carry units).",
        epilog="outputs:\n"
               "  default      OUT (default <stem>_timeseries.csv): one wide table, all channels\n"
               "  --per-gear   OUT is a directory (default <stem>_csv/): <stem>_body.csv (body and energy)\n"
               "               and <stem>_gear<i>.csv for every gear\n"
               "  --summary    also <stem>_crush.csv (or next to OUT): per-strut crush lengths in Table 3 rows\n\n"
               "example:\n  landyn-export landyn.h5 -o landyn.csv\n  landyn-export lc3.h5 --per-gear -o lc3_csv")
    p.add_argument("file", metavar="FILE", help="LANDYN result file (.h5)")
    p.add_argument("-o", "--output", metavar="OUT", help="output CSV file (directory with --per-gear)")
    p.add_argument("--per-gear", action="store_true", help="one file per gear plus one for body and energy")
    p.add_argument("--summary", action="store_true", help="also write the per-strut crush-length summary CSV")
    a = p.parse_args(argv)
    res = load(a.file)
    base = cli.stem(a.file)
    if a.per_gear:
        outdir = cli.output_dir(a.output or base + "_csv")
        print(write_csv(os.path.join(outdir, f"{base}_body.csv"), res.time, res.channels(gears=[])))
        for g in range(1, res.n_gears + 1):
            print(write_csv(os.path.join(outdir, f"{base}_gear{g}.csv"), res.time,
                            res.channels(gears=[g], include_body=False)))
        summary_dir = outdir
    else:
        out = a.output or base + "_timeseries.csv"
        d = os.path.dirname(out)
        if d:
            cli.output_dir(d)
        print(write_csv(out, res.time, res.channels()))
        summary_dir = d
    if a.summary:
        print(write_summary_csv(os.path.join(summary_dir, f"{base}_crush.csv"), res))
    return cli.EXIT_OK


def main(argv=None) -> int:
    return cli.run("landyn-export", _main, argv)


if __name__ == "__main__":
    sys.exit(main())
