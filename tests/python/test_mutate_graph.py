"""Issue 28, speed: the difference search on the native core's labelled graphs
(mutate/graph.py) classifies every mutant as the Python engine's exact product search
does -- killed, survived (with a difference trace of the same length), equivalent --
on a planted model, on one with a VIEW that hides an observed, sticky variable, and
on a registered model whose initial states choose more than the inputs; and a value
an action carries over under a VIEW is no difference of stored states."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from mutate_specs import CARRIED, VIEWED

from safestate.cli import main

PLANTED = r"""---- MODULE Planted ----
EXTENDS Naturals
VARIABLES inp, out, latch, n
Init == inp = 0 /\ out = 0 /\ latch = FALSE /\ n = 0
Next == \E i \in {0, 1, 2} :
    /\ inp' = i
    /\ out' = IF i > 5 THEN 2 ELSE i
    /\ latch' = (latch \/ i = 2)
    /\ n' = IF n < 3 THEN n + 1 ELSE n
TypeOK == inp \in 0..2 /\ out \in 0..2 /\ latch \in BOOLEAN /\ n \in 0..3
Safe == inp = out
====
"""


def _verdicts(capsys: pytest.CaptureFixture[str], engine: str, *args: str) -> dict[str, tuple]:
    assert main(["mutate", *args, "--engine", engine, "--json", "--no-cache"]) == 0
    report = json.loads(capsys.readouterr().out)
    return {m["mutant"]: (m["status"], m["violated"], len(m["table"])) for m in report["mutants"]}


@pytest.mark.parametrize("model", ["planted", "viewed"])
def test_native_graph_search_classifies_every_mutant_as_the_exact_search(
        model: str, tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    if model == "planted":
        (tmp_path / "Planted.tla").write_text(PLANTED)
        (tmp_path / "Planted.cfg").write_text("INIT Init\nNEXT Next\nINVARIANTS\n    TypeOK\n    Safe\n")
        args = [str(tmp_path / "Planted.tla"), "--inputs", "inp", "--observables", "out,latch"]
    else:
        (tmp_path / "Viewed.tla").write_text(VIEWED)
        (tmp_path / "Viewed.cfg").write_text("INIT Init\nNEXT Next\nVIEW View\nINVARIANT TypeOK\n")
        args = [str(tmp_path / "Viewed.tla"), "--inputs", "inp", "--observables", "note"]
    native = _verdicts(capsys, "native", *args)
    python = _verdicts(capsys, "python", *args)
    assert native == python
    statuses = {v[0] for v in native.values()}
    assert "survived" in statuses and "equivalent" in statuses


def test_native_graph_search_agrees_on_a_registered_model_with_nondeterministic_initial_states(
        capsys: pytest.CaptureFixture[str]) -> None:
    args = ["PLCopenAxis", "--operator", "drop-input-value", "--operator", "swap-if", "--operator", "unchanged"]
    native = _verdicts(capsys, "native", *args)
    python = _verdicts(capsys, "python", *args)
    assert native == python and native


def test_input_an_action_carries_under_a_view_is_no_difference_of_stored_states(tmp_path: Path) -> None:
    """The mutant `seen' = seen` changes only the unobserved `seen`, so it is equivalent;
    its stored state of class <<1, FALSE, 1>> carries another `free` than the
    original's, and their Poke steps (which keep `free`) must still pair up: the graph
    search decides "equivalent" itself, without a difference of stored states for the
    exact search to reject."""
    from safestate.checker.model import load_model
    from safestate.mutate.graph import graph_search, native_labelled
    from safestate.mutate.product import Projection, search
    proj = Projection(("inp", "free"), ("out",))
    graphs, models = [], []
    for name, text in (("orig", CARRIED), ("mut", CARRIED.replace("seen' = (seen \\/ f = 0)", "seen' = seen"))):
        d = tmp_path / name
        d.mkdir()
        assert name == "orig" or text != CARRIED
        (d / "Carried.tla").write_text(text)
        (d / "Carried.cfg").write_text("INIT Init\nNEXT Next\nVIEW View\nINVARIANT TypeOK\n")
        model = load_model(str(d / "Carried.tla"), str(d / "Carried.cfg"))
        _result, graph, _why = native_labelled(model, proj, None)
        assert graph is not None
        graphs.append(graph)
        models.append(model)
    assert search(models[0], models[1], proj).verdict == "equivalent"  # the exact search
    assert graph_search(graphs[0], graphs[1], proj).verdict == "equivalent"


def test_a_mutant_whose_graph_is_the_originals_is_equivalent_without_a_pair_search(
        tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    """`i > 5` is never true for the inputs 0..2: its boundary and literal mutants
    leave every state, step and observation as they were, and are equivalent by the
    graphs' equality alone; `n < 3` as `n < 2` changes only the unobserved `n`, so its
    graph has fewer states and the pair search decides it (equivalent too)."""
    (tmp_path / "Planted.tla").write_text(PLANTED)
    (tmp_path / "Planted.cfg").write_text("INIT Init\nNEXT Next\nINVARIANTS\n    TypeOK\n    Safe\n")
    args = [str(tmp_path / "Planted.tla"), "--inputs", "inp", "--observables", "out,latch"]
    assert main(["mutate", *args, "--engine", "native", "--json", "--no-cache"]) == 0
    report = json.loads(capsys.readouterr().out)
    by_text = {m["replacement"].strip(): m for m in report["mutants"]}
    for guard in ("i >= 5", "i > 4", "i > 6"):
        m = by_text[f"/\\ out' = IF {guard} THEN 2 ELSE i"]
        assert m["status"] == "equivalent", m
        assert m["reason"].startswith("the original's graph: 14 states"), m
    hidden = by_text["/\\ n' = IF n < 2 THEN n + 1 ELSE n"]
    assert hidden["status"] == "equivalent" and not hidden["reason"].startswith("the original's graph")


def test_the_cores_copy_masks_are_the_positions_every_step_of_an_action_copies() -> None:
    """The flagship's VIEW leaves out free signals its Submit keeps: the core's per-action
    copy masks (the label positions an action copies from its stored source in every
    step) equal the same rule evaluated here, step by step, on the graph it recorded."""
    from array import array

    from safestate.checker.model import load_model
    from safestate.mutate.graph import NO_SOURCE, native_labelled
    from safestate.mutate.product import Projection
    from safestate.systems.registry import find
    system = find("SystemStateManager")
    assert system is not None
    decl = system.extra["mutate"]
    proj = Projection(tuple(decl["inputs"]), tuple(decl["observables"]))
    model = load_model(str(system.model), str(system.model.with_name("SystemStateManager_reduced.cfg")))
    result, graph, _ = native_labelled(model, proj, None)
    assert result is not None and result.result == "success" and graph is not None and graph.run is not None
    eng = graph.run.engine
    src, _dst, val = (array("I", b) for b in eng.labels_bytes())
    leaves = array("I", eng.edges_bytes()[2])
    states = array("I", eng.states_bytes())
    k = sum(1 for s in src if s == NO_SOURCE)
    nvars, label_vars = len(model.variables), list(eng.label_vars)
    copied = [set(range(len(label_vars))) for _ in range(max(leaves) + 1)]
    for j, lf in enumerate(leaves):
        parts = eng.describe(val[k + j])[1]
        base = src[k + j] * nvars
        copied[lf] -= {q for q in copied[lf] if parts[q] != states[base + label_vars[q]]}
    masks = [graph.masks[graph.step_mask[j]] for j in range(len(leaves))]
    assert masks == [frozenset(copied[lf]) for lf in leaves]
    assert any(graph.masks), "no action of the flagship copies a labelled variable"
