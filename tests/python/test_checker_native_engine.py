"""`safestate check --engine native`: the C++ core (checker/native/, bindings/python/
tla_native/) against the Python engine, the reference.  Wherever the core
accepts a spec — the corpus, the real-world specs, the registered models' CI cfgs —
both engines must give the same verdict, distinct/generated counts, depth, states
left on the queue, violated invariant and counterexample trace (states, actions and
their parameters); a spec outside the core's subset is refused with file:line:col
and "not supported by the native engine", never guessed at."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from conftest import CORPUS, ERRORS, REPO, run_safestate
from safestate.checker.explore import CheckResult, explore_states
from safestate.checker.model import load_model
from safestate.checker.native.search import explore_native, native_unsupported

REALWORLD = REPO / "tests" / "tla" / "realworld" / "specs"
MODELS = REPO / "models"
BENCH = REPO / "bench" / "specs"

# Specs the core must accept (so that this test cannot pass by refusing everything).
ACCEPTED = {
    CORPUS: ["AllAssigned", "ConstraintEdge", "Constraints", "DropParam", "InitViolation", "JugPuzzle",
             "Latin1Comment", "LazyOperatorArguments", "NaiveMutex", "RecordAssignment", "RecordEnumeration",
             "SelectSeqTests", "TrafficView", "TwoPhase", "VendingMachine", "WideRecords"],
    REALWORLD: ["Bakery", "DieHard", "DiningPhilosophers", "HourClock", "InfixOperators", "NestedExcept",
                "Peterson", "RaftElection", "Semaphore", "TCommit", "TheoremsAndProofs"],
    MODELS: ["HydraulicPressFlat", "PLCopenAxis", "Protection"],
}


def _outcome(r: CheckResult) -> tuple:
    trace = [(s.state, s.action, s.params) for s in r.trace or []]
    error = (r.error.kind, r.error.message) if r.error else None
    return (r.result, r.distinct_states, r.states_generated, r.depth, r.left_on_queue, r.violated, error, trace)


def _specs(folder: Path) -> list[str]:
    return sorted(p.stem for p in folder.glob("*.tla") if p.with_suffix(".cfg").exists())


CASES = [(folder, name) for folder in (CORPUS, REALWORLD) for name in _specs(folder)] + \
        [(MODELS, name) for name in ACCEPTED[MODELS]]


@pytest.mark.parametrize("folder,name", CASES, ids=[f"{f.name}/{n}" for f, n in CASES])
def test_native_engine_gives_the_python_engines_result_or_refuses(folder: Path, name: str) -> None:
    tla = str(folder / f"{name}.tla")
    try:
        model = load_model(tla)
    except Exception:
        pytest.skip("the spec does not load (an error-reporting spec)")
    refusal = native_unsupported(model)
    if refusal is not None:
        assert name not in ACCEPTED.get(folder, []), f"{name}: {refusal}"
        assert "not supported by the native engine" in refusal.message
        assert refusal.loc is not None and refusal.loc.line > 0
        return
    native, error = explore_native(model)
    python = explore_states(load_model(tla))
    if native is None:
        # The core stops at an evaluation error and leaves TLC's report to the Python
        # engine (engine_choice.check): only where the Python engine meets an error too.
        assert name not in ACCEPTED.get(folder, []), f"{name}: {error}"
        assert python.result == "error", f"{name}: the core stopped at {error}; Python: {python.result}"
        return
    assert _outcome(native) == _outcome(python)


@pytest.mark.parametrize("spec,cfg,distinct", [
    ("Counters", "A = 5\n    B = 4\n    C = 3\n    D = 7", 5 * 4 * 3 * 7),
    ("QueueMutex", "N = 3\n    MaxTicket = 3\n    MaxEntries = 2", None),
])
def test_native_engine_gives_the_python_engines_result_on_bench_specs(spec: str, cfg: str, distinct: int | None,
                                                                      tmp_path: Path) -> None:
    tla = _bench_spec(spec, cfg, tmp_path)
    native, _ = explore_native(load_model(tla))
    python = explore_states(load_model(tla))
    assert native is not None and _outcome(native) == _outcome(python)
    if distinct is not None:  # every combination of counter values is reachable
        assert native.distinct_states == distinct


ACCEPTED_CASES = [(folder, name) for folder, names in ACCEPTED.items() for name in names]


@pytest.mark.parametrize("folder,name", ACCEPTED_CASES, ids=[f"{f.name}/{n}" for f, n in ACCEPTED_CASES])
def test_native_engine_with_two_workers_gives_the_one_workers_result(folder: Path, name: str) -> None:
    # Issue 10: several workers report what one worker reports — verdict, counts, depth,
    # states left, violated invariant and the same (shortest, first-found) trace.
    tla = str(folder / f"{name}.tla")
    one, error_one = explore_native(load_model(tla), workers=1)
    two, error_two = explore_native(load_model(tla), workers=2)
    assert one is not None and two is not None, (error_one, error_two)
    assert _outcome(two) == _outcome(one)
    assert two.parallel is not None and two.parallel["workers"] == 2


def _bench_spec(spec: str, cfg: str, tmp_path: Path, invariant: str | None = None) -> str:
    """A bench spec with smaller constants (and optionally another invariant)."""
    text = (BENCH / f"{spec}.cfg").read_text()
    body = text[text.index("CONSTANTS"):text.index("SPECIFICATION")]
    tla = (BENCH / f"{spec}.tla").read_text()
    if invariant is not None:
        tla = tla.replace("\n====", f"\nSmall == {invariant}\n====")
        text = text.replace(body, body + "INVARIANT Small\n")
    (tmp_path / f"{spec}.tla").write_text(tla)
    (tmp_path / f"{spec}.cfg").write_text(text.replace(body, f"CONSTANTS\n    {cfg}\n"))
    return str(tmp_path / f"{spec}.tla")


@pytest.mark.parametrize("spec,cfg,invariant", [
    ("Counters", "A = 5\n    B = 4\n    C = 3\n    D = 7", None),
    # Wide levels where the violating state is reached from many parents: the trace and
    # the counts must be the one worker's, not whichever thread got there first.
    ("Counters", "A = 5\n    B = 4\n    C = 3\n    D = 7", "a + b + c + d < 9"),
    ("QueueMutex", "N = 3\n    MaxTicket = 3\n    MaxEntries = 2", None),
])
def test_native_engine_with_two_workers_gives_the_one_workers_result_on_wide_levels(
        spec: str, cfg: str, invariant: str | None, tmp_path: Path) -> None:
    tla = _bench_spec(spec, cfg, tmp_path, invariant)
    one, _ = explore_native(load_model(tla), workers=1)
    two, _ = explore_native(load_model(tla), workers=2)
    assert one is not None and two is not None
    assert _outcome(two) == _outcome(one)
    assert one.result == ("success" if invariant is None else "safety failure")


def test_native_engine_refuses_an_unsupported_construct_with_its_position(tmp_path: Path) -> None:
    (tmp_path / "Rec.tla").write_text("---- MODULE Rec ----\nEXTENDS Naturals\nVARIABLE x\n"
                                      "RECURSIVE F(_)\nF(n) == IF n = 0 THEN 0 ELSE F(n - 1)\n"
                                      "Init == x = 0\nNext == x' = F(x) + 1 /\\ x < 3\n====\n")
    (tmp_path / "Rec.cfg").write_text("INIT Init\nNEXT Next\n")
    r = run_safestate("check", str(tmp_path / "Rec.tla"), "--engine", "native")
    assert r.returncode != 0
    assert "Rec.tla:7:" in r.stderr and "not supported by the native engine" in r.stderr
    assert "Traceback" not in r.stderr
    auto = run_safestate("check", str(tmp_path / "Rec.tla"), "--engine", "auto", "--json")
    assert auto.returncode == 0, auto.stderr
    assert "using the Python engine" in auto.stderr
    assert json.loads(auto.stdout)["distinct_states"] == 2  # F(n) = 0: x is 0, then 1 forever


def test_native_engine_leaves_an_evaluation_error_to_the_python_engine() -> None:
    spec = str(ERRORS / "HeadOfEmpty.tla")
    native = run_safestate("check", spec, "--engine", "native", "--json")
    python = run_safestate("check", spec, "--engine", "python", "--json")
    assert "checking again with the Python engine" in native.stderr
    assert native.returncode == python.returncode != 0
    strip = lambda out: {k: v for k, v in json.loads(out).items() if k != "seconds"}  # noqa: E731
    assert strip(native.stdout) == strip(python.stdout)


def test_native_engine_with_two_workers_stops_at_the_one_workers_evaluation_error() -> None:
    spec = str(ERRORS / "HeadOfEmpty.tla")
    one = explore_native(load_model(spec), workers=1)
    two = explore_native(load_model(spec), workers=2)
    assert one[0] is None and one == two


def test_native_engine_cli_reports_what_the_python_engine_reports() -> None:
    spec = str(CORPUS / "NaiveMutex.tla")
    native = run_safestate("check", spec, "--engine", "native", "--json")
    python = run_safestate("check", spec, "--engine", "python", "--json")
    assert native.returncode == python.returncode == 12
    strip = lambda out: {k: v for k, v in json.loads(out).items() if k != "seconds"}  # noqa: E731
    assert strip(native.stdout) == strip(python.stdout)


MEMBER_OF_A_BUILT_SET = r"""---- MODULE MemberOfBuiltSet ----
EXTENDS Naturals
VARIABLE msg
Msgs == {m \in [a: 0..3, b: 0..3] : m.a # m.b}
Init == msg \in Msgs
Next == \E m \in Msgs : msg' = m
TypeOK == msg \in Msgs
Wrong == msg \in {m \in Msgs : m.a < 3}
====
"""


def test_membership_in_a_constant_set_that_is_built_reads_the_definitions_one_evaluation(tmp_path: Path) -> None:
    """`x \\in Msgs`, with Msgs a filter (built, not tested by structure), goes through
    the definition's remembered node, as `\\E m \\in Msgs` does, instead of building
    the set again in every state (the Safety service's TypeOK did: half its check);
    the results are the Python engine's, a violation and its trace included."""
    from safestate.checker.native.ops import Op
    from safestate.checker.native.search import NativeRun
    (tmp_path / "MemberOfBuiltSet.tla").write_text(MEMBER_OF_A_BUILT_SET)
    for invariants in ("TypeOK", "TypeOK\n    Wrong"):
        (tmp_path / "MemberOfBuiltSet.cfg").write_text(f"INIT Init\nNEXT Next\nINVARIANTS\n    {invariants}\n")
        model = load_model(str(tmp_path / "MemberOfBuiltSet.tla"), str(tmp_path / "MemberOfBuiltSet.cfg"))
        native, _error = explore_native(model, None, None)
        assert native is not None
        assert _outcome(native) == _outcome(explore_states(model))
    assert native.result == "safety failure" and native.violated == "Wrong"
    type_ok = NativeRun(model).invariants[0]
    assert type_ok[0] == Op.IN and type_ok[4][1][0] == Op.BIND_MEMO
