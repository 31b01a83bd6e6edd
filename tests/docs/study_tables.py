#!/usr/bin/env python3
"""The result tables of docs/study.md, made from landyn_study files, and the check that keeps them
current (CTest `study_doc_tables`).

    study_tables.py --doc docs/study.md --check STUDY.h5 ...    # exit 1 when a table differs
    study_tables.py --doc docs/study.md --update STUDY.h5 ...   # rewrite the tables in place
    study_tables.py --study-exe landyn_study --src SRC --check-studies study_tube [...]
        # run the named studies of SRC/input in a temporary directory, then --check

Each table in the document sits between `<!-- study-table: NAME -->` and `<!-- /study-table -->`,
NAME the stem of the study file (study_contact, study_friction, study_tube). A table has one row
per measure option and one column per variant (crush length in mm, 0.1 mm), in the variants'
order; a two-variant study (Table 10) also has the Error/% column of the paper (second against
first, in % of the first's |crush|). Column titles are the variant labels of the study file.
"""
import argparse
import os
import re
import shutil
import subprocess
import sys
import tempfile

import h5py
import numpy as np

BLOCK = re.compile(r"(<!-- study-table: (\w+) -->\n)(.*?)(<!-- /study-table -->)", re.S)


def _text(x):
    return x.decode() if isinstance(x, bytes) else str(x)


def table_of(path):
    """Markdown table (text, ending in a newline) of a landyn_study file."""
    with h5py.File(path, "r") as f:
        labels = [_text(x) for x in f["study/variant_label"][()]]
        crush = np.asarray(f["table/crush_length"][()], dtype=float) * 1e3     # (options, variants) mm
    head = ["opt"] + labels + (["Error/%"] if len(labels) == 2 else [])
    lines = ["| " + " | ".join(head) + " |", "|" + "---|" * len(head)]
    for k, row in enumerate(crush, 1):
        cells = [str(k)] + [f"{v:.1f}" if np.isfinite(v) else "failed" for v in row]
        if len(labels) == 2:
            base = round(row[0], 1)
            err = (round(row[1], 1) - base) / abs(base) * 100.0 if base != 0 and np.all(np.isfinite(row)) else np.nan
            cells.append(f"{err:.1f}".replace("-", "\u2212") if np.isfinite(err) else "-")
        lines.append("| " + " | ".join(cells) + " |")
    return "\n".join(lines) + "\n"


def compare(doc_text, files):
    """(new document text, names of the tables that differ, names not found in the document)."""
    tables = {os.path.splitext(os.path.basename(p))[0]: table_of(p) for p in files}
    differ, seen = [], set()

    def sub(m):
        name = m.group(2)
        if name not in tables:
            return m.group(0)
        seen.add(name)
        if m.group(3) != tables[name]:
            differ.append(name)
        return m.group(1) + tables[name] + m.group(4)

    new = BLOCK.sub(sub, doc_text)
    return new, differ, sorted(set(tables) - seen)


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--doc", required=True)
    mode = ap.add_mutually_exclusive_group(required=True)
    mode.add_argument("--check", nargs="+", metavar="STUDY.h5")
    mode.add_argument("--update", nargs="+", metavar="STUDY.h5")
    mode.add_argument("--check-studies", nargs="+", metavar="NAME")
    ap.add_argument("--study-exe")
    ap.add_argument("--src")
    a = ap.parse_args(argv)
    text = open(a.doc, encoding="utf-8").read()
    if a.check_studies:
        work = tempfile.mkdtemp(prefix="study_tables_")
        try:
            inp = os.path.join(a.src, "input")
            files = []
            for name in a.check_studies:
                for f in os.listdir(inp):
                    if f == name + ".nml" or f in ("lc1.nml", "lc2.nml", "lc3.nml", "lc4.nml"):
                        shutil.copy(os.path.join(inp, f), work)
                p = subprocess.run([a.study_exe, name + ".nml", "-q"], cwd=work, capture_output=True, text=True)
                if p.returncode != 0:
                    print(p.stdout, p.stderr)
                    print(f"FAIL: landyn_study {name}.nml exited {p.returncode}")
                    return 1
                files.append(os.path.join(work, name + ".h5"))
            return _check(a.doc, text, files)
        finally:
            shutil.rmtree(work, ignore_errors=True)
    if a.check:
        return _check(a.doc, text, a.check)
    new, differ, missing = compare(text, a.update)
    if missing:
        print(f"no table for {', '.join(missing)} in {a.doc}")
        return 1
    with open(a.doc, "w", encoding="utf-8") as fh:
        fh.write(new)
    print(f"{a.doc}: {len(differ)} table(s) updated ({', '.join(differ) or 'none changed'})")
    return 0


def _check(doc, text, files):
    new, differ, missing = compare(text, files)
    for name in missing:
        print(f"FAIL: {doc} has no table <!-- study-table: {name} -->")
    for name in differ:
        print(f"FAIL: {doc}: the table {name} is not what landyn_study gives now; regenerate it with\n"
              f"  python3 tests/docs/study_tables.py --doc {doc} --update {name}.h5")
    if not differ and not missing:
        print(f"ok: {doc}: {', '.join(os.path.splitext(os.path.basename(f))[0] for f in files)} current")
    return 1 if differ or missing else 0


if __name__ == "__main__":
    sys.exit(main())
