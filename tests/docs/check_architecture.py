#!/usr/bin/env python3
"""docs/ARCHITECTURE.md is current: its module map names every source file of src/ (by its path
relative to src/, e.g. `physics/landyn_gear.f90`), in the section of the file's layer, and every
source path it names exists. Exit 0 when current, 1 with the differences otherwise.

  check_architecture.py --src SOURCE_DIR
"""
import argparse
import os
import re
import sys

LAYERS = ("core", "input", "physics", "numerics", "output", "api", "study", "campaign", "app")


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--src", required=True)
    a = ap.parse_args()
    doc_path = os.path.join(a.src, "docs", "ARCHITECTURE.md")
    text = open(doc_path, encoding="utf-8").read()
    problems = []

    # the sources, by layer folder
    files = {}
    for layer in sorted(os.listdir(os.path.join(a.src, "src"))):
        d = os.path.join(a.src, "src", layer)
        if not os.path.isdir(d):
            continue
        if layer not in LAYERS:
            problems.append("src/%s/ is not a known layer (%s)" % (layer, ", ".join(LAYERS)))
        for name in sorted(os.listdir(d)):
            if name.endswith((".f90", ".F90", ".c", ".f90.in", ".fypp", ".fypi")):
                files["%s/%s" % (layer, name)] = layer

    # the module map: "### <layer>" sections listing `layer/file` paths
    sections = {}
    current = None
    for line in text.splitlines():
        m = re.match(r"^###\s+`?(\w+)/?`?", line)
        if m and m.group(1) in LAYERS:
            current = m.group(1)
            continue
        if line.startswith("## "):
            current = None
        for p in re.findall(r"`((?:%s)/[\w.]+)`" % "|".join(LAYERS), line):
            sections.setdefault(p, set()).add(current)

    for path, layer in files.items():
        if path not in sections:
            problems.append("%s is not in the module map of docs/ARCHITECTURE.md" % path)
        elif layer not in sections[path]:
            problems.append("%s is named outside the section of its layer '%s'" % (path, layer))
    for path in sections:
        if path not in files:
            problems.append("docs/ARCHITECTURE.md names %s, which does not exist in src/" % path)

    for p in problems:
        print("FAIL: " + p)
    print("%d source files, %d problems" % (len(files), len(problems)))
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
