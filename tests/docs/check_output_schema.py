#!/usr/bin/env python3
"""Keeps the result-file schema's three places in step (src/output/landyn_output_schema.f90 is the source).

  --check manifest  the manifest landyn_post ships (post/landyn_post/data/output_schema.json) equals the
                    one this build's landyn_schema wrote (--manifest)
  --check docs      every dataset table row of docs/output.md (a row whose first cell is a `/path`) is the
                    manifest's row for that dataset, and every dataset of the manifest has its row
  --write           copies the build's manifest into the package and rewrites docs/output.md's rows from it
                    (a new dataset's row must first be placed by hand in its section)

Exit 0 when in step, 1 with a list of what differs.
"""
from __future__ import annotations

import argparse
import json
import os
import re
import shutil
import sys

ROW = re.compile(r"^\| `(/[^`]+)` \|")
SHIPPED = os.path.join("post", "landyn_post", "data", "output_schema.json")
DOC = os.path.join("docs", "output.md")


def doc_row(d: dict) -> str:
    """The docs/output.md table row of a manifest dataset."""
    shape = "(" + ", ".join(str(s) for s in d["shape"]) + ")"
    return f"| `{d['path']}` | {shape} | {d['units']} | {d['meaning'].replace('|', chr(92) + '|')} |"


def check_manifest(manifest_path: str, src: str) -> list[str]:
    shipped = os.path.join(src, SHIPPED)
    if not os.path.exists(shipped):
        return [f"{SHIPPED} is missing"]
    with open(manifest_path, encoding="utf-8") as fh:
        built = fh.read()
    with open(shipped, encoding="utf-8") as fh:
        have = fh.read()
    if built == have:
        return []
    out = [f"{SHIPPED} differs from the build's manifest {manifest_path}:"]
    for k, (a, b) in enumerate(zip(have.splitlines(), built.splitlines())):
        if a != b:
            out += [f"  line {k + 1}: shipped {a.strip()[:150]}", f"  line {k + 1}: build   {b.strip()[:150]}"]
            break
    return out + ["update it with: python tests/docs/check_output_schema.py --manifest <build>/landyn_output_schema.json "
                  "--src . --write"]


def check_docs(manifest: dict, src: str) -> list[str]:
    with open(os.path.join(src, DOC), encoding="utf-8") as fh:
        lines = fh.read().splitlines()
    datasets = manifest["datasets"]
    want = {d["path"]: doc_row(d) for d in datasets}
    seen, out = set(), []
    version = manifest["schema_version"]
    if f"schema version {version}" not in lines[0] or f"now `{version}`" not in "\n".join(lines):
        out.append(f"{DOC}: its title and the root attribute schema_version do not say version {version}")
    for k, line in enumerate(lines):
        m = ROW.match(line)
        if not m:
            continue
        path = m.group(1)
        if path not in want:
            out.append(f"{DOC}:{k + 1}: {path} is not a dataset of the schema")
        elif path in seen:
            out.append(f"{DOC}:{k + 1}: {path} has a second row")
        elif line.rstrip() != want[path]:
            out.append(f"{DOC}:{k + 1}: the row of {path} differs from the schema:\n  doc:    {line.rstrip()}\n"
                       f"  schema: {want[path]}")
        seen.add(path)
    out += [f"{DOC}: no row for {p} (add one to its section's table)" for p in want if p not in seen]
    return out


def write(manifest_path: str, datasets: list[dict], src: str) -> None:
    shutil.copyfile(manifest_path, os.path.join(src, SHIPPED))
    want = {d["path"]: doc_row(d) for d in datasets}
    doc = os.path.join(src, DOC)
    with open(doc, encoding="utf-8") as fh:
        lines = fh.read().splitlines()
    for k, line in enumerate(lines):
        m = ROW.match(line)
        if m and m.group(1) in want:
            lines[k] = want[m.group(1)]
    with open(doc, "w", encoding="utf-8") as fh:
        fh.write("\n".join(lines) + "\n")


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--manifest", required=True, help="landyn_output_schema.json of a build")
    ap.add_argument("--src", default=".", help="source tree")
    ap.add_argument("--check", choices=("manifest", "docs"), action="append", default=[])
    ap.add_argument("--write", action="store_true", help="update the shipped manifest and the docs rows")
    a = ap.parse_args(argv)
    with open(a.manifest, encoding="utf-8") as fh:
        manifest = json.load(fh)
    datasets = manifest["datasets"]
    if a.write:
        write(a.manifest, datasets, a.src)
    problems = []
    if "manifest" in a.check:
        problems += check_manifest(a.manifest, a.src)
    if "docs" in a.check:
        problems += check_docs(manifest, a.src)
    for p in problems:
        print(p)
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
