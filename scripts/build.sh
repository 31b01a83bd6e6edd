#!/usr/bin/env bash
# Configures and builds LANDYN: build/release (the one users run) and, with --debug, build/debug
# (run-time checks and floating-point traps). Uses the Python of .venv for tests and tools.
# Compiler warnings fail the build (LANDYN_WERROR, and a search of the log for what it misses).
set -euo pipefail
cd "$(dirname "$0")/.."
PY="$PWD/.venv/bin/python"
[ -x "$PY" ] || PY="$(command -v python3)"
types="Release"
[ "${1:-}" = "--debug" ] && types="Release Debug"
for t in $types; do
  dir="build/$(echo "$t" | tr '[:upper:]' '[:lower:]')"
  cmake -S . -B "$dir" -DCMAKE_BUILD_TYPE="$t" -DPython3_EXECUTABLE="$PY" -DLANDYN_WERROR=ON > "build-$t.log" 2>&1 \
    || { cat "build-$t.log"; exit 1; }
  cmake --build "$dir" -j "$(nproc)" >> "build-$t.log" 2>&1 || { tail -50 "build-$t.log"; exit 1; }
  if grep -q "Warning:" "build-$t.log"; then
    echo "build: compiler warnings in the $t build:"; grep -A3 "Warning:" "build-$t.log"; exit 1
  fi
  rm -f "build-$t.log"
  echo "build: $t build in $dir"
done
