#!/usr/bin/env bash
# Sets up (scripts/setup.sh) and runs the main job: the demo scenarios, then the
# evidence chain for every system of the registry (systems/*/system.toml): model check
# (safestate check), unbounded proofs (safestate prove), conformance of the C++
# against its model (safestate conform), model mutants and tests -- run by
# `safestate evidence`, which ends the job with the evidence package (build/evidence)
# and prints its path and gap count; then what each step cost.
# SAFESTATE_CPP_MUTATION=N first measures the C++ mutation score on a stratified sample of N mutants (slow; SAFESTATE_CPP_MUTATION_BUDGET
# seconds, SAFESTATE_CPP_MUTATION_STRIDE K: the input-complete pass on every K-th state).
# Exits non-zero as soon as one step fails.
set -euo pipefail
cd "$(dirname "$0")/.."

# Every step is timed; what each cost is printed when the job ends (or stops).
step_names=(); step_seconds=()
costs() {
  [ ${#step_names[@]} -gt 0 ] || return 0
  echo "== what each step cost (wall seconds)"
  local total=0 i
  for i in "${!step_names[@]}"; do
    printf '%8d  %s\n' "${step_seconds[$i]}" "${step_names[$i]}"
    total=$(( total + step_seconds[i] ))
  done
  printf '%8d  %s\n' "$total" "total"
}
trap costs EXIT
step() {
  local name=$1 t0=$SECONDS; shift
  echo "== $name"
  "$@"
  step_names+=("$name"); step_seconds+=($(( SECONDS - t0 )))
}

# A step whose inputs are unchanged since it last passed is not run again:
#   reused "FILES AND FOLDERS IT READS" COMMAND...
# its key hashes the command, those files and the built bindings; build/main-cache/<key>
# marks a pass.  (The evidence step caches its own steps the same way.)
reused() {
  local inputs=$1 key; shift
  # shellcheck disable=SC2086  # the inputs are a list of paths
  key=$( { printf '%s\0' "$@"
           find $inputs .venv/lib/python3*/site-packages/safestate -type f \( -name '*.so' -o -name '*.py' \
             -o -name '*.tla' -o -name '*.cfg' -o -name '*.toml' \) -not -path '*/__pycache__/*' -print0 |
             sort -z | xargs -0 sha256sum; } | sha256sum | cut -c1-24)
  if [ -f "build/main-cache/$key" ]; then
    echo "(its inputs are unchanged since it passed: not run again; key $key)"
    return 0
  fi
  "$@"
  mkdir -p build/main-cache && touch "build/main-cache/$key"
}

step "set-up (scripts/setup.sh)" bash scripts/setup.sh
SAFESTATE=.venv/bin/safestate

step "systems" "$SAFESTATE" systems
step "demo scenario (C++ SystemStateManager, one line per change)" build/cpp/safestate_demo
step "demo scenario (C++ Safety service over UDP on the loopback, one line per change)" "$SAFESTATE" demo saf
step "demo scenario (C++ fan controller closed around its thermal plant, one line per tick)" \
  "$SAFESTATE" demo protection
step "demo scenario (the hydraulic press accident: flat reference and chain press side by side)" \
  "$SAFESTATE" demo press

peers() {
  "$SAFESTATE" check models/SafetyServicePeers.tla --workers 2 | grep -E "states generated|depth of the|No error|Error:|Finished in"
}
step "model check: models/SafetyServicePeers.tla (the Safety service against its explicit peers)" peers

# The Safety service's C++ against its model at the production-shaped timings
# (docs/design/safety-service.md section 12): every transition of the 28,917-state graph
# replayed, then 10,000 Hypothesis steps; about 4 CPU minutes, 1.8 GB.
step "conformance: the Safety service at the production timings (models/SafetyService_production.cfg)" \
  reused "models/SafetyService.tla models/SafetyService_production.cfg systems/SafetyService python/safestate" \
  "$SAFESTATE" conform SafetyService --config models/SafetyService_production.cfg --seed 1

if [ -n "${SAFESTATE_CPP_MUTATION:-}" ]; then
  step "C++ mutation score (universalmutator, stratified sample of $SAFESTATE_CPP_MUTATION mutants; slow)" \
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
mutate_all() {
  local sample="${SAFESTATE_MUTATE_SAMPLE:-60}" s args
  mkdir -p build/mutate
  for s in $("$SAFESTATE" systems --names); do
    args=()
    if [ "$sample" != 0 ]; then
      args=(--sample "$sample" --seed 1)
    fi
    "$SAFESTATE" mutate "$s" --workers 2 "${args[@]}" > "build/mutate/$s.txt" 2> "build/mutate/$s.log"
    head -1 "build/mutate/$s.txt"
  done
}
step "model mutation score of every system (safestate mutate)" mutate_all

# The evidence chain of every system of the registry, and the package that shows it:
# model check (its counts compared with TLC's recorded figures, models/expected.json),
# unbounded proofs (every constant symbolic where its ASSUME allows), conformance of the
# C++ against the model (trace replay of every transition, Hypothesis lockstep,
# input-complete pass) where the system has an adapter, every model mutant, GoogleTest
# and the requirement-named pytest tests, the flagship's branch coverage under
# conformance; then index.html, the traceability matrix, the diagrams and manifest.json
# (verify: safestate evidence --verify build/evidence).  Two steps run side by side;
# --reuse takes a step's cached result (build/evidence-cache) while its inputs are unchanged.
# The last C++ mutation score (build/cpp-mutation/score.json) goes into the package.
step "evidence: check, prove, conform, mutants and tests of every system; the evidence package" \
  "$SAFESTATE" evidence --out build/evidence --coverage --reuse
echo "== main job: all steps passed"
