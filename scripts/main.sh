#!/usr/bin/env bash
# Sets up (scripts/setup.sh) and runs the main job: the demo scenarios, then the
# evidence chain for every system of the registry (systems/*/system.toml): model check
# (safestate check), unbounded proofs (safestate prove), conformance of the C++
# against its model (safestate conform), model mutants and tests -- run by
# `safestate evidence`, which ends the job with the evidence package (build/evidence)
# and prints its path and gap count.  SAFESTATE_CPP_MUTATION=N first measures the
# C++ mutation score on a stratified sample of N mutants (slow; SAFESTATE_CPP_MUTATION_BUDGET
# seconds, SAFESTATE_CPP_MUTATION_STRIDE K: the input-complete pass on every K-th state).
# Exits non-zero as soon as one step fails.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
SAFESTATE=.venv/bin/safestate

echo "== systems"
"$SAFESTATE" systems

echo "== demo scenario (C++ SystemStateManager, one line per change)"
build/cpp/safestate_demo

echo "== demo scenario (C++ Safety service over UDP on the loopback, one line per change)"
"$SAFESTATE" demo saf

echo "== demo scenario (C++ fan controller closed around its thermal plant, one line per tick)"
"$SAFESTATE" demo protection

echo "== demo scenario (the hydraulic press accident: flat reference and chain press side by side)"
"$SAFESTATE" demo press

echo "== model check: models/SafetyServicePeers.tla (the Safety service against its explicit peers)"
"$SAFESTATE" check models/SafetyServicePeers.tla --workers 2 | grep -E "states generated|depth of the|No error|Error:|Finished in"

echo "== model check: the flagship with the native engine (must give TLC's counts, models/expected.json)"
.venv/bin/python - <<'PY'
import json, subprocess, sys
want = json.load(open("models/expected.json"))["SystemStateManager"]
out = subprocess.run([".venv/bin/safestate", "check", "models/SystemStateManager.tla", "--engine", "native", "--json"],
                     capture_output=True, text=True)
got = json.loads(out.stdout)
keys = ("result", "distinct_states", "states_generated", "depth")
print({k: got[k] for k in keys}, f"{got['seconds']} s")
sys.exit(0 if all(got[k] == want[k] for k in keys) else 1)
PY

if [ -n "${SAFESTATE_CPP_MUTATION:-}" ]; then
  echo "== C++ mutation score (universalmutator, stratified sample of $SAFESTATE_CPP_MUTATION mutants; slow)"
  .venv/bin/python conform/cpp_mutants/score.py build/cpp-mutation --sample "$SAFESTATE_CPP_MUTATION" \
    --budget "${SAFESTATE_CPP_MUTATION_BUDGET:-3600}" --stride "${SAFESTATE_CPP_MUTATION_STRIDE:-1}"
fi

# The model mutation score of every system (docs/mutate.md): generated mutants of each
# model, checked with its CI cfg, survivors told apart by the difference search; each
# result goes to build/mutate/SYSTEM.json for `safestate systems` and the evidence
# package.  Outcomes are cached (~/.cache/safestate/mutate), so a re-run classifies only
# what changed.  The whole sets of the flagship (about 900 mutants) and the Safety service
# (about 500, each a 730k-step check) take hours on 2 cores: every system is measured on a
# stratified sample of SAFESTATE_MUTATE_SAMPLE mutants (default 60, seed 1; a system with
# fewer is measured whole; 0: every whole set), said so in its result.
echo "== model mutation score of every system (safestate mutate)"
sample="${SAFESTATE_MUTATE_SAMPLE:-60}"
for s in $("$SAFESTATE" systems --names); do
  args=()
  if [ "$sample" != 0 ]; then
    args=(--sample "$sample" --seed 1)
  fi
  mkdir -p build/mutate
  "$SAFESTATE" mutate "$s" --workers 2 "${args[@]}" > "build/mutate/$s.txt" 2> "build/mutate/$s.log"
  head -1 "build/mutate/$s.txt"
done

# The evidence chain of every system of the registry, and the package that shows it:
# model check, unbounded proofs (every constant symbolic where its ASSUME allows),
# conformance of the C++ against the model (trace replay of every transition,
# Hypothesis lockstep, input-complete pass) where the system has an adapter, every
# model mutant, GoogleTest and the requirement-named pytest tests, the flagship's
# branch coverage under conformance; then index.html, the traceability matrix, the
# diagrams and manifest.json (verify: safestate evidence --verify build/evidence).
# The last C++ mutation score (build/cpp-mutation/score.json) goes into the package.
echo "== evidence: check, prove, conform, mutants and tests of every system; the evidence package"
"$SAFESTATE" evidence --out build/evidence --coverage
echo "== main job: all steps passed"
