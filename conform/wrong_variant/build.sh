#!/usr/bin/env bash
# Build a variant of the binding: build.sh wrong|coverage BUILD_DIR
# Prints the directory to put on sys.path (SAFESTATE_CORE_PATH).
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
repo="$(cd "$here/../.." && pwd)"
kind="$1"; out="$2"
py="${PYTHON:-$repo/.venv/bin/python}"
case "$kind" in
  wrong) flags=(-DSAFESTATE_WRONG=ON) ;;
  coverage) flags=(-DSAFESTATE_COVERAGE=ON) ;;
  *) echo "usage: build.sh wrong|coverage BUILD_DIR" >&2; exit 2 ;;
esac
# -O1: the suite replays these modules for a few seconds; -O3 cost 25% more compile CPU.
cmake -S "$here" -B "$out" -G Ninja -DCMAKE_BUILD_TYPE=Release "-DCMAKE_CXX_FLAGS_RELEASE=-O1 -DNDEBUG" "${flags[@]}" \
  -DPython_EXECUTABLE="$py" -Dpybind11_DIR="$("$py" -m pybind11 --cmakedir)" >&2
cmake --build "$out" >&2
echo "$out"
