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
# The binding's own flags (-O3, see bindings/python/CMakeLists.txt and cmake/BindingModule.cmake):
# the binding sources this variant does not patch (core_module.cpp, saf_module.cpp,
# pro_module.cpp) are then ccache hits on the objects setup.sh compiled, even on a cold cache.
# (-O1 compiled faster, but every one of those sources was then compiled anew.)
# The compiler by the same name as well (ccache hashes it: g++ and its alias c++ miss).
compiler=$(sed -n 's/^CMAKE_CXX_COMPILER:[A-Z]*=//p' "$repo"/build/cp*/CMakeCache.txt 2>/dev/null | head -1 || true)
if [ -n "$compiler" ]; then flags+=("-DCMAKE_CXX_COMPILER=$compiler"); fi
cmake -S "$here" -B "$out" -G Ninja -DCMAKE_BUILD_TYPE=Release "-DCMAKE_CXX_FLAGS_RELEASE=-O3 -DNDEBUG" "${flags[@]}" \
  -DPython_EXECUTABLE="$py" -Dpybind11_DIR="$("$py" -m pybind11 --cmakedir)" >&2
cmake --build "$out" >&2
echo "$out"
