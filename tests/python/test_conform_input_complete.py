"""Input-complete conformance: from reachable states, every input vector of the full
alphabet (every channel pair, selector contact pattern, enabling pair, concrete speeds
just below / at / above each threshold) for one step, and with the queue empty a
JOG_START at each bound of its argument check followed by one cycle; the model accepts
each and the C++ agrees.  C++ mutants that the CI cfg's restricted alphabet cannot see are caught.

The test probes every 16th state of the BFS order (the full pass is
`safestate conform SystemStateManager --input-complete`, run by the main job); the
full mutant kill table is `conform/cpp_mutants/kill_table.py`.  The mutant
modules are built once under build/cpp_mutants (incremental afterwards).
"""

from pathlib import Path

import pytest

from safestate.checker.model import load_model
from safestate.conform import graph as graph_mod
from safestate.conform.cli import make_harness
from safestate.conform.input_complete import run_input_complete
from safestate.systems.registry import find

REPO = Path(__file__).resolve().parents[2]
MUTANTS_DIR = REPO / "conform" / "cpp_mutants"
# Mistakes invisible to the CI cfg's alphabet (channel pairs {both closed, A closed/B
# open}, abstract speed classes), one per kind of gap.
# jog_speed_zero_accepted needs the two-step probes (a zero-speed JOG_START, then a cycle)
# and, being a transition-table guard, also checks that a mutant module loaded after the
# real binding runs its own table (see mutate.py: hidden visibility).
# discrepancy_checked_after_selector needs two groups disagreeing from the same cycle on
# (the combined-disagreement probes): both faults mature in one scan.
SUBSET = ("estop_1oo2_as_xor", "t1_limit_inclusive", "tcp_speed_in_m_per_s", "selector_several_contacts_first_wins",
          "jog_speed_zero_accepted", "discrepancy_checked_after_selector")



@pytest.fixture(scope="module")
def flagship():
    system = find("SystemStateManager", REPO / "systems")
    model = load_model(str(system.model), str(system.ci_config))
    return system, model, graph_mod.cached_explore(model)


@pytest.fixture(scope="module")
def mutant_build():
    import sys

    sys.path.insert(0, str(MUTANTS_DIR))
    import mutate as mutants_build

    from safestate.conform.binding import load_core

    out = REPO / "build" / "cpp_mutants"
    mutants = [m for m in mutants_build.load() if m.id in SUBSET]
    mutants_build.build_all(out, mutants)
    sys.path.insert(0, str(out))
    # The real binding first: every mutant must still run its own code, not the symbols
    # of a module loaded before it.
    load_core()
    return mutants_build


def test_input_complete_pass_agrees_on_every_16th_state(flagship):
    system, model, graph = flagship
    res = run_input_complete(make_harness(system, model), graph, stride=16)
    assert res.mismatch is None, res.mismatch
    assert res.states == len(range(0, len(graph.states), 16))
    # every probe of the alphabet, from every probed state: at least 4+4+9+8 channel and
    # selector vectors and the 10 speed probes
    assert res.probes >= res.states * 35


def test_flagship_alphabet_has_every_channel_pair_contact_pattern_and_threshold_speed(flagship):
    system, model, _ = flagship
    h = make_harness(system, model)
    labels = [p.label for p in h.adapter.input_alphabet(model.initial_states()[0])]
    for a in "01":
        for b in "01":
            assert f"estop {a}{b}" in labels and f"gate {a}{b}" in labels
    assert sum(1 for x in labels if x.startswith("enabling ")) == 9
    assert sum(1 for x in labels if x.startswith("selector contacts ")) == 8
    for must in ("just below the T1 limit", "exactly at the T1 limit", "just above the T1 limit",
                 "at the zero threshold", "just above the zero threshold", "NaN"):
        assert any(must in x for x in labels), must
    # the queue is empty: a JOG_START at each bound of its argument check, then a cycle
    # two groups disagreeing from one cycle on, held D+1 cycles: every pair of the four
    for pair in ("estop and gate", "estop and enable", "estop and selector", "gate and enable",
                 "gate and selector", "enable and selector"):
        assert f"{pair} disagreeing from one cycle on, held 3 cycles" in labels, pair
    for must in ("JOG_START speed 0", "JOG_START axis 0", "JOG_START direction 0", "JOG_START exactly at the T1 limit"):
        assert any(x.startswith(f"submit {must}") for x in labels), must


@pytest.mark.parametrize("mutant", SUBSET)
def test_input_complete_pass_catches_cpp_mutant(flagship, mutant_build, mutant):
    system, model, graph = flagship
    h = make_harness(system, model, f"safestate_mut_{mutant}._core")
    res = run_input_complete(h, graph)
    assert res.mismatch is not None and "MISMATCH" in res.mismatch, f"{mutant} survived {res.probes} probes"


def test_a_cpp_mutation_that_no_longer_applies_is_an_error(mutant_build):
    m = mutant_build.load()[0]
    stale = mutant_build.Mutant(m.id, m.kind, m.what, m.file, m.original + " /* gone */", m.replacement)
    with pytest.raises(mutant_build.MutationError, match="no longer applies"):
        mutant_build.apply(stale)


def test_every_cpp_mutant_still_applies_to_the_sources():
    import sys

    sys.path.insert(0, str(MUTANTS_DIR))
    import mutate as mutants_build

    mutants = mutants_build.load()
    assert len(mutants) >= 15
    for m in mutants:
        assert mutants_build.apply(m) != (REPO / m.file).read_text(encoding="utf-8")


def test_cpp_mutation_score_end_to_end_on_two_universalmutator_mutants(mutant_build, tmp_path):
    """score.py as the main job runs it, on 2 of universalmutator's mutants of
    src/arm_kinematics.cpp (seed 1: a declaration commented out, which must be filtered as
    stillborn by the compile-only pass, and a DH-matrix entry `-st * ca` -> `-st + ca`,
    which the kinematics GoogleTest must kill).  Shares build/cpp_mutants with the subset
    above (same file: one xdist worker), so only the mutated unit and one test are built."""
    import json
    import subprocess
    import sys

    out = tmp_path / "score.json"
    r = subprocess.run([sys.executable, str(MUTANTS_DIR / "score.py"), str(REPO / "build" / "cpp_mutants"),
                        "--files", "src/arm_kinematics.cpp", "--sample", "2", "--seed", "1", "--passes", "gtest",
                        "--gtest-tests", "test_arm_kinematics", "--out", str(out)],
                       capture_output=True, text=True, timeout=900)
    assert r.returncode == 0, r.stderr[-2000:]
    d = json.loads(out.read_text(encoding="utf-8"))
    assert d["sampled"] == 2 and d["generated"] > 100 and d["targets"] == ["src/arm_kinematics.cpp"]
    by_status = {m["status"]: m for m in d["mutants"]}
    assert by_status["stillborn"]["stillborn_at"] == "compile-only", d["mutants"]
    assert by_status["killed"]["killed_by"].startswith("GoogleTest: test_arm_kinematics"), d["mutants"]
    assert (d["stillborn"], d["evaluated"], d["killed"], d["score_percent"]) == (1, 1, 1, 100.0)
    assert d["confidence_95_percent"][1] == 100.0 and d["survivors"] == []
    assert "C++ mutation score: 100.0% (1/1 killed" in r.stdout
