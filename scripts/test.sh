#!/usr/bin/env bash
# Sets up (scripts/setup.sh) and runs every test: the Python lint and type check (ruff,
# mypy, configured in pyproject.toml), the C++ format check (clang-format, .clang-format),
# GoogleTest through ctest, then pytest (unit tests of the Python tools, model checks,
# proofs and conformance as tests).  .pre-commit-config.yaml runs the first three gates.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
# shellcheck source=scripts/build_env.sh
. scripts/build_env.sh  # ccache for the C++ builds the tests start (wrong variant, C++ mutants)
echo "== lint, types and C++ format (ruff, mypy, clang-format)"
.venv/bin/ruff check
.venv/bin/mypy
bash scripts/check_format.sh
echo "== C++ unit tests (ctest)"
ctest --preset dev -j"$(nproc)"  # build/cpp, output on failure (CMakePresets.json)
echo "== Python tests (pytest, 2 workers; docs/testing.md)"
.venv/bin/python -m pytest -q -p no:cacheprovider -n "${SAFESTATE_TEST_WORKERS:-2}" --dist loadfile "$@"
