#!/usr/bin/env bash
# Sets up (scripts/setup.sh) and runs the main job. For now: the demo scenario of the
# SystemStateManager, printing the state per cycle. Later: model-check, prove, conformance, report.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
echo "== demo scenario"
build/cpp/safestate_demo
