#!/usr/bin/env bash
# Sets up (scripts/setup.sh) and runs the main job: the demo scenario, then the
# evidence chain for every model: model check (safestate check), unbounded proofs
# (safestate prove) and conformance of the C++ against its model
# (safestate conform), for every system of the registry (systems/*/system.toml).
# Exits non-zero as soon as one step fails.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
SAFESTATE=.venv/bin/safestate
mapfile -t MODELS < <("$SAFESTATE" systems --names)
mapfile -t CONFORM < <("$SAFESTATE" systems --names --with-conformance)

echo "== systems"
"$SAFESTATE" systems

echo "== demo scenario (C++ SystemStateManager, one line per change)"
build/cpp/safestate_demo

echo "== demo scenario (C++ Safety service over UDP on the loopback, one line per change)"
"$SAFESTATE" demo saf

echo "== demo scenario (C++ fan controller closed around its thermal plant, one line per tick)"
"$SAFESTATE" demo protection

for m in "${MODELS[@]}"; do
  echo "== model check: system $m (its model with its CI cfg)"
  "$SAFESTATE" check "$m" --workers 2 | grep -E "states generated|depth of the|No error|Error:|Finished in"
done

echo "== model check: models/SafetyServicePeers.tla (the Safety service against its explicit peers)"
"$SAFESTATE" check models/SafetyServicePeers.tla --workers 2 | grep -E "states generated|depth of the|No error|Error:|Finished in"

for m in "${MODELS[@]}"; do
  echo "== proofs: system $m (every constant symbolic where its ASSUME allows)"
  "$SAFESTATE" prove "$m" --quiet
done

for m in "${CONFORM[@]}"; do
  echo "== conformance: system $m, C++ against the model (trace replay of every transition, Hypothesis lockstep, input-complete pass)"
  "$SAFESTATE" conform "$m" --input-complete
done
echo "== main job: all steps passed"
