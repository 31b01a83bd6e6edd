#!/usr/bin/env python3
"""The build refuses a `use` across the layers of docs/ARCHITECTURE.md that the table under "Layers"
does not allow, and accepts every one it allows.

For each layer built as its own target (landyn_layer_<layer>), the script takes the exact compile
command of one of the layer's Fortran sources from <build>/compile_commands.json and compiles small
probe programs with it, in place of that source (the object goes to a scratch directory):

- one probe that uses a module of the layer itself and of every layer in its "may use" column must
  compile;
- for every other layer that is built, a probe that uses one of its modules must fail with
  gfortran's "Cannot open module file '<module>.mod'".

A layer's modules are the .mod files in <build>/mod/<layer>/ (one module of each is used). So the test
fails when a layer's include paths leak (a module directory it may not use is visible) and when they
are too narrow (one it may use is missing). The only allowed use the build refuses on purpose is
listed in EXPECTED_REFUSALS, with its reason, and is checked to be refused. Exit 0 when every probe
behaves, 1 with the differences otherwise.

  check_layer_refusal.py --build BUILD_DIR --src SOURCE_DIR
"""
import argparse
import json
import os
import re
import shlex
import subprocess
import sys
import tempfile

from check_architecture import LAYERS, layer_table  # noqa: E402  (the one reading of the table)

# (layer, used layer) allowed by the table but refused by the build, and why
EXPECTED_REFUSALS = {
    ("app", "campaign"): "the app layer's library modules (landyn_cli, landyn_app_support) are in landyn_lib, "
                         "which has no MPI; only the programs (landyn_batch) use campaign",
}
TARGET_DIR = re.compile(r"CMakeFiles/landyn_layer_(\w+)\.dir/")


def layer_commands(build_dir):
    """{layer: (directory, argument list, source file)}: the first Fortran source of each layer target."""
    with open(os.path.join(build_dir, "compile_commands.json"), encoding="utf-8") as f:
        entries = json.load(f)
    found = {}
    for e in entries:
        if not e["file"].endswith((".f90", ".F90")):
            continue
        args = e["arguments"] if "arguments" in e else shlex.split(e["command"])
        out = args[args.index("-o") + 1] if "-o" in args else ""
        m = TARGET_DIR.search(out)
        if m and m.group(1) not in found:
            found[m.group(1)] = (e["directory"], args, e["file"])
    return found


def layer_modules(build_dir):
    """{layer: a module of it}: the first .mod file (by name) in <build>/mod/<layer>/."""
    modules = {}
    for layer in LAYERS:
        d = os.path.join(build_dir, "mod", layer)
        if os.path.isdir(d):
            names = sorted(n[:-4] for n in os.listdir(d) if n.endswith(".mod"))
            if names:
                modules[layer] = names[0]
    return modules


def module_dir(args):
    """The module directory of a gfortran command (its -J option), '' without one."""
    for i, arg in enumerate(args):
        if arg == "-J" and i + 1 < len(args):
            return os.path.normpath(args[i + 1])
        if arg.startswith("-J"):
            return os.path.normpath(arg[2:])
    return ""


def compile_probe(command, scratch, used):
    """Compile a program that uses the modules `used` with the layer's command; (status, output)."""
    directory, args, source = command
    probe = os.path.join(scratch, "landyn_layer_probe.f90")
    with open(probe, "w", encoding="utf-8") as f:
        f.write("program landyn_layer_probe\n")
        for module in used:
            f.write("  use %s\n" % module)
        f.write("  implicit none\nend program landyn_layer_probe\n")
    run = [probe if a == source else a for a in args]
    run[run.index("-o") + 1] = os.path.join(scratch, "landyn_layer_probe.o")
    if probe not in run:
        return 1, "the compile command of %s does not name its source" % source
    p = subprocess.run(run, cwd=directory, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    return p.returncode, p.stdout


def probe_layer(layer, command, modules, may_use, scratch):
    """(number of probes, problems) of one layer: its allowed uses compile, the others are refused."""
    problems = []
    if not module_dir(command[1]).endswith(os.path.join("mod", layer)):
        problems.append("layer %s: its modules do not go to mod/%s (-J%s)" % (layer, layer, module_dir(command[1])))
    allowed = [u for u in LAYERS if u in may_use.get(layer, set()) | {layer}
               and (layer, u) not in EXPECTED_REFUSALS and u in modules]
    status, out = compile_probe(command, scratch, [modules[u] for u in allowed])
    probes = 1
    if status != 0:
        problems.append("layer %s: a use of %s (layers %s) does not compile:\n%s"
                        % (layer, ", ".join(modules[u] for u in allowed), ", ".join(allowed), out))
    for other in (x for x in LAYERS if x in modules and x not in allowed):
        status, out = compile_probe(command, scratch, [modules[other]])
        probes += 1
        if status == 0 or not re.search("Cannot open module file .%s[.]mod." % modules[other], out):
            problems.append("layer %s: a use of %s (layer %s) is not refused with \"Cannot open module file "
                            "'%s.mod'\" (status %d):\n%s" % (layer, modules[other], other, modules[other], status, out))
    return probes, problems


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--build", required=True)
    ap.add_argument("--src", required=True)
    a = ap.parse_args()
    with open(os.path.join(a.src, "docs", "ARCHITECTURE.md"), encoding="utf-8") as f:
        may_use = layer_table(f.read())
    commands = layer_commands(a.build)
    modules = layer_modules(a.build)
    problems = ["layer %s: no compile command or no module in %s/mod/%s" % (layer, a.build, layer)
                for layer in LAYERS
                if (layer not in commands or layer not in modules) and not (layer == "campaign" and layer not in commands)]
    probes = 0
    with tempfile.TemporaryDirectory() as scratch:
        for layer in (x for x in LAYERS if x in commands):
            n, found = probe_layer(layer, commands[layer], modules, may_use, scratch)
            probes += n
            problems += found
    for p in problems:
        print("FAIL: " + p)
    print("%d layers, %d probes compiled, %d problems" % (len(commands), probes, len(problems)))
    return 1 if problems or not probes else 0


if __name__ == "__main__":
    sys.exit(main())
