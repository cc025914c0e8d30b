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

# A system whose manifest says `expected_check = "violated INV"` (the defective press
# reference) must fail exactly that invariant, and is not proved but refuted by BMC.
expected_violation() {
  .venv/bin/python -c "from safestate.systems.registry import find; print(find('$1').extra.get('expected_check', '').removeprefix('violated '))"
}

for m in "${MODELS[@]}"; do
  echo "== model check: system $m (its model with its CI cfg)"
  inv="$(expected_violation "$m")"
  if [[ -n "$inv" ]]; then
    rc=0; out="$("$SAFESTATE" check "$m" --workers 2)" || rc=$?
    grep -E "is violated|states generated|depth of the" <<<"$out"
    [[ $rc -eq 12 ]] && grep -q "Invariant $inv is violated" <<<"$out" || { echo "expected $inv violated (exit 12), got exit $rc"; exit 1; }
    continue
  fi
  "$SAFESTATE" check "$m" --workers 2 | grep -E "states generated|depth of the|No error|Error:|Finished in"
done

echo "== model check: models/SafetyServicePeers.tla (the Safety service against its explicit peers)"
"$SAFESTATE" check models/SafetyServicePeers.tla --workers 2 | grep -E "states generated|depth of the|No error|Error:|Finished in"

for m in "${MODELS[@]}"; do
  inv="$(expected_violation "$m")"
  if [[ -n "$inv" ]]; then
    echo "== proofs: system $m is a defective reference: BMC must refute $inv"
    rc=0; "$SAFESTATE" prove "$m" --engine bmc --depth 6 --invariant "$inv" --quiet || rc=$?
    [[ $rc -eq 12 ]] || { echo "expected BMC to refute $inv (exit 12), got exit $rc"; exit 1; }
    continue
  fi
  echo "== proofs: system $m (every constant symbolic where its ASSUME allows)"
  "$SAFESTATE" prove "$m" --quiet
done

for m in "${CONFORM[@]}"; do
  echo "== conformance: system $m, C++ against the model (trace replay of every transition, Hypothesis lockstep, input-complete pass)"
  "$SAFESTATE" conform "$m" --input-complete
done
echo "== main job: all steps passed"
