#!/usr/bin/env bash
# Installs everything safestate needs on a fresh Debian machine, idempotently:
# Debian packages (when root), the Python venv at .venv with the safestate package
# (which builds the C++ binding through CMake), and the C++ build tree in build/.
# A second run only rebuilds what changed.
set -euo pipefail
cd "$(dirname "$0")/.."
ROOT=$PWD

log() { printf '[setup] %s\n' "$*"; }

# 1. Debian packages.
need_pkgs=()
for pkg in cmake ninja-build g++ libeigen3-dev libgtest-dev googletest valgrind python3-venv graphviz libmodbus-dev libboost-dev nlohmann-json3-dev chromium chromium-driver ccache clang-format; do
  dpkg -s "$pkg" >/dev/null 2>&1 || need_pkgs+=("$pkg")
done
if ((${#need_pkgs[@]})); then
  if [ "$(id -u)" = 0 ]; then
    log "apt-get install ${need_pkgs[*]}"
    export DEBIAN_FRONTEND=noninteractive
    apt-get update -qq
    apt-get install -y -qq "${need_pkgs[@]}" >/dev/null
  else
    log "missing Debian packages (run as root to install): ${need_pkgs[*]}" >&2
    exit 1
  fi
fi

# shellcheck source=scripts/build_env.sh
. scripts/build_env.sh  # ccache, when installed

# 2. Python venv and the package (editable, with the compiled binding).
PY=${PYTHON:-python3}
if [ ! -x .venv/bin/python ]; then
  log "creating .venv"
  "$PY" -m venv .venv
fi
VPY=.venv/bin/python
# Reinstall only when a file that goes into the package changed.
stamp_src=$( (git ls-files -co --exclude-standard -- pyproject.toml CMakeLists.txt cmake include src bindings python 2>/dev/null || true) \
  | sort | xargs -r sha1sum 2>/dev/null | sha1sum | cut -d' ' -f1)
if [ ! -f .setup-stamp ] || [ "$(cat .setup-stamp)" != "$stamp_src" ]; then
  log "installing the safestate Python package into .venv (builds the C++ binding)"
  # Current build tools first: a new venv's setuptools cannot build an sdist into a wheel
  # without the `wheel` package, and --no-build-isolation builds with these.
  "$VPY" -m pip install -q --upgrade pip setuptools wheel >/dev/null
  "$VPY" -m pip install -q scikit-build-core pybind11 >/dev/null
  "$VPY" -m pip install -q --no-build-isolation -e ".[test]"
  echo "$stamp_src" > .setup-stamp
else
  log ".venv is up to date"
fi

# Byte-compile the package, the tests and the systems' adapters: with PYTHONDONTWRITEBYTECODE
# set (it is, on these machines) Python never writes a .pyc, so each `safestate` subprocess
# compiled every module it imports from source (0.18 -> 0.07 CPU s per CLI run; the tests
# start several hundred).  Only stale files are rewritten (__pycache__ is git-ignored).
"$VPY" -m compileall -q -j 0 python tests/python systems conform/cpp_mutants >/dev/null

# 3. The C++ build tree (library, GoogleTest tests, benchmarks): CMakePresets.json's `dev`
# preset, applied on every run (0.6 s on a configured tree, which ninja then finds up to
# date), so that its settings hold for a tree configured otherwise without this script
# repeating them.  bench/run_bench.py and the coverage build configure their own trees.
log "configuring build/cpp (preset dev)"
cmake --preset dev >/dev/null
log "building build/cpp"
cmake --build --preset dev -j"$(nproc)" | grep -vE '^\[[0-9]+/[0-9]+\]' || true
test "${PIPESTATUS[0]}" -eq 0
log "done"
