#!/usr/bin/env bash
# The whole test suite: unit (pFUnit), executable, regression against the paper and the stored
# baselines, physics checks, campaigns (MPI), the Python post-processing tests and the API
# documentation (FORD, label docs: fails on any FORD warning), on the Release build; the unit and
# executable tests, the C API, the FMU and the Python package again on the Debug build (run-time
# checks, FP traps).
# Benchmarks (label bench) are not part of it: run them with  ctest --test-dir build/release -L bench
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh --debug
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
status=0
ctest --test-dir build/release -LE bench -j 2 --output-on-failure || status=1
ctest --test-dir build/debug -L "unit|cli|api|fmu|python_api" -j 2 --output-on-failure || status=1
exit $status
