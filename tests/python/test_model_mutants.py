"""Every registered system's model mutants and witnesses (issues 9, 17), driven by the
registry: `systems/<Name>/system.toml` names the system's model and its mutant file.

Each mutant is generated as patches into a temporary folder (the test fails when a patch
no longer applies: the mutant went stale) and checked by `safestate check --json` alone
(the CLI's entry point, run in the test's process: no interpreter start and imports per
mutant; `--engine auto`, so the native core searches where it accepts the model), with
only its target invariant listed: it must be violated with TLC's trace length (and TLC's
distinct states where declared), or, for an environment weakening (expect = "holds"),
the witness it targets must hold (be lost). Each `Witness_X` of the model (the negation
of a property's antecedent) must be violated, i.e. the antecedent is reachable."""

from __future__ import annotations

import io
import json
from contextlib import redirect_stderr, redirect_stdout
from pathlib import Path

import pytest

from conftest import REPO
from safestate import mutants
from safestate.cli import main as safestate_main
from safestate.systems import registry

SYSTEMS = registry.load_all(REPO / "systems")
MUTANTS = [(s, m) for s in SYSTEMS for m in mutants.of_system(s)]
WITNESSES = [(s, w) for s in SYSTEMS for w in mutants.witnesses(s.model)]


def _check(tla: Path) -> dict:
    """`safestate check TLA --json`: its JSON summary (the exit code is the one the verdict
    implies; the verdict itself is asserted by the caller)."""
    out, err = io.StringIO(), io.StringIO()
    with redirect_stdout(out), redirect_stderr(err):
        # --engine auto: the native core where it accepts the model (the flagship, PLCopen,
        # Protection, RuntimeSupervisor; identical results to the Python engine, see
        # test_checker_native_engine.py), the Python engine elsewhere.
        safestate_main(["check", str(tla), "--json", "--engine", "auto"])
    assert "internal error" not in out.getvalue() + err.getvalue(), out.getvalue() + err.getvalue()
    return json.loads(out.getvalue())


def test_every_registered_system_declares_mutants() -> None:
    assert all(s.mutants is not None for s in SYSTEMS), [s.name for s in SYSTEMS if s.mutants is None]


@pytest.mark.parametrize("system,mutant", MUTANTS, ids=[m.id for _, m in MUTANTS])
def test_mutant_is_killed_by_check_alone(system: registry.System, mutant: mutants.Mutant,
                                         tmp_path: Path) -> None:
    tla = mutants.variant(system.model, mutant.invariant, tmp_path, mutant.patches, mutant.id)
    got = _check(tla)
    if mutant.expect == "holds":
        # An environment weakening: the witness the real model reaches is lost.
        assert got["result"] == "success", got.get("violated") or got.get("error")
    else:
        assert got["result"] == "safety failure", got.get("error")
        assert got["violated"] == mutant.invariant
        assert mutant.trace_length is not None, f"{mutant.id}: declare TLC's trace_length"
        assert len(got["trace"]["states"]) == mutant.trace_length
    if mutant.distinct_states is not None:
        assert got["distinct_states"] == mutant.distinct_states


@pytest.fixture(scope="module")
def witness_model(tmp_path_factory: pytest.TempPathFactory):
    """witness_model(system) -> Model: the system's model with every Witness_X as an
    invariant, compiled once per system."""
    from safestate.checker.model import load_model

    memo: dict[str, object] = {}

    def get(system: registry.System):
        if system.name not in memo:
            dest = tmp_path_factory.mktemp(f"witness-{system.name}")
            tla = mutants.variant(system.model, " ".join(mutants.witnesses(system.model)), dest)
            memo[system.name] = load_model(str(tla), str(tla.with_suffix(".cfg")))
        return memo[system.name]
    return get


@pytest.mark.parametrize("system,witness", WITNESSES, ids=[f"{s.name}:{w}" for s, w in WITNESSES])
def test_witness_is_reached(system: registry.System, witness: str, witness_model, state_graph) -> None:
    """The antecedent is reachable: some reachable state of the model's .cfg violates
    Witness_X. Evaluated on the explored state graph shared with the other tests (the same
    reachable set a `safestate check` with only the witness listed would search)."""
    model = witness_model(system)
    inv = next(i for i in model.invariants if i.name == witness)
    _, graph = state_graph(system.model, system.model.with_suffix(".cfg"))
    assert any(not model.holds(inv, s) for s in graph.states), f"{witness}: the antecedent is never reached"


def test_a_stale_mutant_is_reported(tmp_path: Path) -> None:
    flagship = next(s for s in SYSTEMS if s.name == "SystemStateManager")
    stale = mutants.Patch(flagship.model.name, "no such text in the model", "x")
    with pytest.raises(mutants.MutationError, match="found 0 times"):
        mutants.variant(flagship.model, "INV_RESET", tmp_path, (stale,), "stale")
