#!/usr/bin/env bash
# Branch coverage of src/*.cpp under the conformance suite.
#   conform/coverage.sh [BUILD_DIR] [--report DIR] [-- extra `safestate conform` arguments]
# Builds safestate_cov._core with --coverage (conform/wrong_variant/CMakeLists.txt,
# unchanged sources), runs the trace replay + Hypothesis through it, prints gcovr's
# branch summary of src/*.cpp; with --report, also DIR/index.html (one page, every file's
# lines and branches) and DIR/summary.json.
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
repo="$(cd "$here/.." && pwd)"
build="${1:-$repo/build/conform-coverage}"; shift || true
report=""
if [ "${1:-}" = "--report" ]; then report="${2:?--report needs a folder}"; shift 2; fi
[ "${1:-}" = "--" ] && shift
report_args=()
if [ -n "$report" ]; then
  mkdir -p "$report"
  report_args=(--html-details "$report/index.html" --html-single-page --json-summary "$report/summary.json")
fi
py="${PYTHON:-$repo/.venv/bin/python}"
"$here/wrong_variant/build.sh" coverage "$build" > /dev/null
find "$build" -name '*.gcda' -delete
SAFESTATE_CORE_PATH="$build" SAFESTATE_CORE_MODULE=safestate_cov._core \
  "$py" -m safestate.conform "$repo/models/SystemStateManager.tla" --hypothesis-steps 10000 "$@" || true
"$py" -m gcovr --root "$repo" --object-directory "$build" --filter "$repo/src/" --txt-metric branch \
  --exclude-unreachable-branches --exclude-throw-branches --print-summary --txt - "${report_args[@]}"
