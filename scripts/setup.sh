#!/usr/bin/env bash
# One command from a fresh Debian 12 machine to a first result: installs the prerequisites,
# builds LANDYN, runs the default case (the paper's 16 t lunar lander, load case LC-1) and plots it.
#   result:  run/landyn.h5        plots:  run/plots/*.png and run/plots/report.pdf
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install_prereqs.sh
bash scripts/build.sh
mkdir -p run
cd run
../build/release/landyn
../.venv/bin/python ../post/landyn_plot.py landyn.h5 -o plots --report
echo "setup: result run/landyn.h5, plots in run/plots/"
