#!/usr/bin/env bash
# Sets up (scripts/setup.sh) and runs the main job: the demo scenario, then the
# evidence chain for every model: model check (safestate check), unbounded proofs
# (safestate prove) and conformance of the C++ against the flagship model
# (safestate conform). Exits non-zero as soon as one step fails.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
SAFESTATE=.venv/bin/safestate
MODELS=(SystemStateManager PLCopenAxis SafetyService)

echo "== demo scenario (C++ SystemStateManager, one line per change)"
build/cpp/safestate_demo

echo "== demo scenario (C++ Safety service over UDP on the loopback, one line per change)"
"$SAFESTATE" demo saf

for m in "${MODELS[@]}"; do
  echo "== model check: models/$m.tla with models/$m.cfg"
  "$SAFESTATE" check "models/$m.tla" --workers 2 | grep -E "states generated|depth of the|No error|Error:|Finished in"
done

echo "== model check: models/SafetyServicePeers.tla (the Safety service against its explicit peers)"
"$SAFESTATE" check models/SafetyServicePeers.tla --workers 2 | grep -E "states generated|depth of the|No error|Error:|Finished in"

for m in "${MODELS[@]}"; do
  echo "== proofs: models/$m.tla (every constant symbolic where its ASSUME allows)"
  "$SAFESTATE" prove "models/$m.tla" --quiet
done

echo "== conformance: C++ against models/SystemStateManager.tla (trace replay of every transition + Hypothesis lockstep)"
"$SAFESTATE" conform models/SystemStateManager.tla --hypothesis-steps 10000
echo "== main job: all steps passed"
