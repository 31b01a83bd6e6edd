#!/usr/bin/env python3
"""docs/ARCHITECTURE.md is current, and the sources keep to its layers:

1. its module map names every source file of src/ (by its path relative to src/, e.g.
   `physics/landyn_gear.f90`), in the section of the file's layer, and every source path it names
   exists;
2. every `use` of a LANDYN module in a Fortran source of src/<layer>/ names a module of the same layer
   or of a layer in that layer's "may use" column of the table under "Layers" (the layers in
   backquotes, e.g. `core`, `config`). A module's layer is the folder of the file that defines it; the
   generated modules are those the module map lists as "(generated) `landyn_x.f90`" in a layer's
   section.

The build enforces the same order (one module directory per layer, CMakeLists.txt; CTest
layer_refusal); this check is the fast second line of defence, with the file and line of the `use`.
Before checking, the script checks itself on two small made-up trees (one clean, one with an upward
`use`), so it cannot pass by finding nothing. Exit 0 when current, 1 with the differences otherwise.

  check_architecture.py --src SOURCE_DIR
"""
import argparse
import os
import re
import sys
import tempfile

from check_doc_comments import statements  # noqa: E402  (one reading of Fortran statements)

LAYERS = ("core", "config", "physics", "input", "numerics", "output", "api", "study", "campaign", "app")
SOURCE_ENDINGS = (".f90", ".F90", ".c", ".f90.in", ".fypp", ".fypi")
MODULE_START = re.compile(r"^\s*module\s+(\w+)\s*$", re.I)
USE = re.compile(r"^\s*use\s*(?:,\s*(?:non_)?intrinsic\s*)?(?:::)?\s*(\w+)", re.I)
INTRINSIC_USE = re.compile(r"^\s*use\s*,\s*intrinsic\b", re.I)


def layer_table(text):
    """The table under "## Layers": {layer: set of the layers it may use} (layers in backquotes in
    the row's last cell; a row's first cell is `layer/`)."""
    may_use = {}
    in_layers = False
    for line in text.splitlines():
        if line.startswith("## "):
            in_layers = line.strip() == "## Layers"
            continue
        if not in_layers or not line.startswith("|"):
            continue
        cells = [c.strip() for c in line.strip().strip("|").split("|")]
        m = re.match(r"^`(\w+)/`$", cells[0])
        if m and m.group(1) in LAYERS:
            may_use[m.group(1)] = set(re.findall(r"`(%s)`" % "|".join(LAYERS), cells[-1]))
    return may_use


def module_map(text):
    """The module map: {`layer/file` path named: set of the sections naming it} and {generated module
    name: layer} (the "(generated)" rows)."""
    sections = {}
    generated = {}
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
        if current and line.startswith("| (generated)"):
            first_cell = line.split("|")[1]
            for name in re.findall(r"`(\w+)\.f90`", first_cell):
                generated[name.lower()] = current
    return sections, generated


def fortran_sources(src_dir):
    """{path relative to src/: layer} of every Fortran source under src/<layer>/ (subfolders too)."""
    found = {}
    for layer in LAYERS:
        top = os.path.join(src_dir, "src", layer)
        for root, _dirs, names in os.walk(top):
            for name in names:
                if name.endswith((".f90", ".F90", ".f90.in")):
                    found[os.path.relpath(os.path.join(root, name), os.path.join(src_dir, "src"))] = layer
    return found


def use_problems(src_dir, may_use, generated):
    """Problems of the `use` statements: a module of a layer that the user's layer may not use."""
    problems = []
    sources = fortran_sources(src_dir)
    owner = dict(generated)
    lines_of = {}
    for path, layer in sources.items():
        with open(os.path.join(src_dir, "src", path), encoding="utf-8") as f:
            lines_of[path] = f.read().splitlines()
        for line in lines_of[path]:
            m = MODULE_START.match(line)
            if m and m.group(1).lower() != "procedure":
                owner[m.group(1).lower()] = layer
    for layer in LAYERS:
        if layer not in may_use:
            problems.append("the table under 'Layers' has no row for `%s/` (or no `may use` layers)" % layer)
    for path, layer in sorted(sources.items()):
        allowed = may_use.get(layer, set()) | {layer}
        for lineno, code, _comments, _last in statements(lines_of[path]):
            m = USE.match(code)
            if not m or INTRINSIC_USE.match(code):
                continue
            used = m.group(1).lower()
            if used in owner and owner[used] not in allowed:
                problems.append("src/%s:%d: layer %s uses %s of layer %s, which is not in its 'may use' (%s)"
                                % (path, lineno + 1, layer, used, owner[used], ", ".join(sorted(may_use.get(layer, [])))
                                   or "nothing"))
    return problems


def check(src_dir):
    """Every problem of docs/ARCHITECTURE.md and the sources under src_dir, as text lines."""
    with open(os.path.join(src_dir, "docs", "ARCHITECTURE.md"), encoding="utf-8") as f:
        text = f.read()
    problems = []

    # the sources, by layer folder
    files = {}
    for layer in sorted(os.listdir(os.path.join(src_dir, "src"))):
        d = os.path.join(src_dir, "src", layer)
        if not os.path.isdir(d):
            continue
        if layer not in LAYERS:
            problems.append("src/%s/ is not a known layer (%s)" % (layer, ", ".join(LAYERS)))
        for name in sorted(os.listdir(d)):
            if name.endswith(SOURCE_ENDINGS):
                files["%s/%s" % (layer, name)] = layer

    sections, generated = module_map(text)
    for path, layer in files.items():
        if path not in sections:
            problems.append("%s is not in the module map of docs/ARCHITECTURE.md" % path)
        elif layer not in sections[path]:
            problems.append("%s is named outside the section of its layer '%s'" % (path, layer))
    for path in sections:
        if path not in files:
            problems.append("docs/ARCHITECTURE.md names %s, which does not exist in src/" % path)

    problems += use_problems(src_dir, layer_table(text), generated)
    return problems


SELF_TEST_DOC = """# made-up architecture
## Layers
| layer | what | may use |
|---|---|---|
%s
## Module map
### core
| `core/landyn_a.f90` | a |
### physics
| `physics/landyn_b.f90` | b |
| (generated) `landyn_g.f90` | generated |
"""


def self_test():
    """Problems of this script itself: on a made-up tree it must accept a downward `use` and report an
    upward one (and one of a generated module) with its file and line."""
    rows = "\n".join("| `%s/` | x | %s |" % (layer, "`core`" if layer != "core" else "nothing")
                     for layer in LAYERS)
    sources = {"core/landyn_a.f90": "module landyn_a\n  use, intrinsic :: iso_fortran_env\n%s"
                                    "  implicit none\nend module landyn_a\n",
               "physics/landyn_b.f90": "module landyn_b\n  use landyn_a, only: x ! use landyn_b\n"
                                       "  use landyn_g\nend module landyn_b\n"}
    problems = []
    for upward, expected in (("", []),
                             ("  use landyn_b, only: &\n    y\n  use landyn_g\n",
                              ["src/core/landyn_a.f90:3: layer core uses landyn_b of layer physics",
                               "src/core/landyn_a.f90:5: layer core uses landyn_g of layer physics"])):
        with tempfile.TemporaryDirectory() as tree:
            os.makedirs(os.path.join(tree, "docs"))
            with open(os.path.join(tree, "docs", "ARCHITECTURE.md"), "w", encoding="utf-8") as f:
                f.write(SELF_TEST_DOC % rows)
            for path, body in sources.items():
                os.makedirs(os.path.join(tree, "src", os.path.dirname(path)), exist_ok=True)
                with open(os.path.join(tree, "src", path), "w", encoding="utf-8") as f:
                    f.write(body % upward if "%s" in body else body)
            found = check(tree)
        if [p.split(", which")[0] for p in found] != expected:
            problems.append("self-test: expected %s, found %s" % (expected, found))
    return problems


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--src", required=True)
    a = ap.parse_args()
    problems = self_test() + check(a.src)
    for p in problems:
        print("FAIL: " + p)
    print("%d source files checked, %d problems" % (len(fortran_sources(a.src)), len(problems)))
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
