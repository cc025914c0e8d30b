"""General temporal properties checked by TLC's tableau method (tests/tla/tableau):
verdicts, counts, exit codes and the named properties equal TLC 1.8.0's; every
counterexample is a fair behaviour of the spec that violates the property and no
longer than TLC's; the tableau agrees with the fixed forms' own searches; what TLC
refuses is refused in its words, what we do not check is an "unsupported" error
at its position."""

from __future__ import annotations

import itertools
import json
import os
import random
from array import array

import pytest

from conftest import REPO, fair_lasso, load_expected
from safestate.checker import exit_codes, ltl, tableau
from safestate.checker.explore import Explorer, explore_states
from safestate.checker.liveness import LivenessChecker, StateGraph, violated_on
from safestate.checker.model import load_model
from safestate.cli import main
from safestate.checker.tableau_search import BehaviourChecker, BehaviourGraph, tableau_counterexample
from safestate.checker.temporal import STATE_LIVENESS_KINDS, TemporalCompiler
from safestate.tla import ast as A
from safestate.tla.errors import TlaError

TABLEAU = REPO / "tests" / "tla" / "tableau"
LIVENESS = REPO / "tests" / "tla" / "liveness"
EXPECTED = load_expected(TABLEAU)
FIELDS = ("result", "distinct_states", "states_generated", "depth", "violated")


@pytest.mark.parametrize("name", sorted(EXPECTED))
def test_tableau_property_verdict_counts_exit_code_and_lasso_match_tlc(name: str) -> None:
    want = EXPECTED[name]
    if want["result"] == "error":  # TLC refuses the formula before the search
        with pytest.raises(TlaError) as err:
            load_model(str(TABLEAU / f"{name}.tla"))
        assert exit_codes.BY_KIND[err.value.kind] == want["exit_code"]
        assert want["message"] in err.value.message and err.value.loc is not None
        return
    model = load_model(str(TABLEAU / f"{name}.tla"))
    assert any(ob.formula is not None for ob in model.liveness)  # a tableau is built for it
    r = explore_states(model)
    for f in FIELDS:
        assert getattr(r, f) == want[f], f"{f}: ours {getattr(r, f)!r}, TLC {want[f]!r}"
    assert exit_codes.BY_RESULT[r.result] == want["exit_code"]
    if "left_on_queue" in want:  # where TLC stopped its search
        assert r.left_on_queue == want["left_on_queue"]
    if "lasso" in want:
        assert r.violated_properties == want["violated_properties"]
        states, _, _ = fair_lasso(model, r)
        assert r.trace is not None and len(r.trace) <= want["lasso"]["length"]
        assert r.loop is not None
        for ob in model.liveness:  # TLC names exactly the properties its lasso violates
            assert violated_on(ob, states, r.loop, r.loop_step is None) == (ob.name in r.violated_properties)
    if want["result"] == "temporal safety failure":
        # TLC's finite counterexample: a behaviour every continuation of which violates
        # the property (checked on the one that stutters at its end).
        assert r.violated_properties == want["violated_properties"] and r.loop is None
        assert r.trace is not None and len(r.trace) <= want["trace_length"]
        states = [step.state for step in r.trace]
        assert states[0] in model.initial_states()
        assert all(b in [t.state for t in model.successors(a)] for a, b in zip(states, states[1:]))
        assert all(violated_on(ob, states, len(states) - 1, True) for ob in model.liveness)


def test_tableau_corpus_covers_the_required_cases() -> None:
    results = [w["result"] for w in EXPECTED.values()]
    assert len(EXPECTED) >= 15
    assert results.count("liveness failure") >= 5 and results.count("success") >= 5
    assert "temporal safety failure" in results and "error" in results
    # an early stop before, and at the same expanded state as, an invariant violation
    assert {"StopBeforeInvariant", "StopWithInvariant"} <= set(EXPECTED)
    assert any(w.get("lasso", {}).get("stuttering") for w in EXPECTED.values())
    assert any(w.get("lasso", {}).get("stuttering") is False for w in EXPECTED.values())
    specs = {n: (TABLEAU / f"{n}.tla").read_text() for n in EXPECTED}
    assert any("WF_" in t for t in specs.values()) and any("SF_" in t for t in specs.values())
    assert any("WF_" not in t and "SF_" not in t for t in specs.values())


def _liveness_specs() -> list[str]:
    return sorted(p.stem for p in LIVENESS.glob("*.tla") if p.with_suffix(".cfg").exists())


@pytest.mark.parametrize("name", _liveness_specs())
def test_tableau_agrees_with_the_fixed_forms_on_the_liveness_corpus(name: str) -> None:
    """Every fixed-form conjunct over state predicates, checked by its own search and
    by the tableau: the same verdict and the same lasso (length, loop, stuttering)."""
    model = load_model(str(LIVENESS / f"{name}.tla"))
    fixed = [ob for ob in model.liveness if ob.kind in STATE_LIVENESS_KINDS]
    if not fixed:
        pytest.skip("no fixed-form liveness conjunct over state predicates")
    explorer = Explorer(model, False, None, None)
    explorer.run()
    graph = StateGraph(len(explorer.states), explorer.edge_src, explorer.edge_dst)
    tc = TemporalCompiler(model, force_tableau=True)
    general = [ob for entry in model.config.properties
               for ob in tc.obligations(entry.name, A.Name(model.liveness[0].p.loc, entry.name), model.scope)
               if ob.kind == "tableau"]
    assert len(general) == len(fixed)
    checker = LivenessChecker(graph, explorer.states, explorer.initial, model.fairness, lambda: None)
    for ob, gen in zip(fixed, general):
        a = checker.counterexample(ob)
        b = tableau_counterexample(graph, explorer.states, explorer.initial, model.fairness, gen, lambda: None)
        shape_a = None if a is None else (len(a.nodes), a.loop, a.stuttering)
        shape_b = None if b is None else (len(b.nodes), b.loop, b.stuttering)
        assert shape_a == shape_b, f"{ob.name} ({ob.kind}): fixed form {shape_a}, tableau {shape_b}"


def _random_formula(r: random.Random, depth: int) -> ltl.Formula:
    if depth == 0 or r.random() < 0.25:
        return ltl.Atom(r.randrange(2), r.random() < 0.4)
    op = r.choice(["and", "or", "always", "eventually", "always", "eventually"])
    if op in ("and", "or"):
        items = (_random_formula(r, depth - 1), _random_formula(r, depth - 1))
        return ltl.And(items) if op == "and" else ltl.Or(items)
    arg = _random_formula(r, depth - 1)
    return ltl.Always(arg) if op == "always" else ltl.Eventually(arg)


def _violating_lasso_exists(succ: list[list[int]], labels: list[tuple[bool, bool]], initial: list[int],
                            f: ltl.Formula, length: int) -> bool:
    """Brute force: a lasso of at most `length` states (stuttering allowed) violating f."""
    for n in range(1, length + 1):
        for path in itertools.product(range(len(succ)), repeat=n):
            if path[0] not in initial or any(b != a and b not in succ[a] for a, b in zip(path, path[1:])):
                continue
            for loop in range(n):
                if path[loop] == path[-1] or path[loop] in succ[path[-1]]:
                    if not ltl.holds_on_lasso(f, [list(labels[v]) for v in path], loop):
                        return True
    return False


@pytest.mark.parametrize("seed", range(60))
def test_tableau_of_random_formulas_on_random_graphs_matches_the_semantics(seed: int) -> None:
    """A lasso the tableau search finds violates the formula (by its semantics on the
    lasso), and when a short violating lasso exists the search finds one."""
    r = random.Random(seed)
    n = r.randint(2, 4)
    succ = [sorted(set(r.sample(range(n), r.randint(0, 2))) - {v}) for v in range(n)]
    labels = [(r.random() < 0.5, r.random() < 0.5) for _ in range(n)]
    f = _random_formula(r, 3)
    src, dst = array("i"), array("i")
    for v in range(n):
        for w in succ[v]:
            src.append(v)
            dst.append(w)
    graph = StateGraph(n, src, dst)
    states = [(v,) for v in range(n)]
    atoms = [lambda s, t=None, k=k: labels[s[0]][k] for k in range(2)]
    bg = BehaviourGraph(graph, states, [0], tableau.build(ltl.negate(f)), atoms, lambda: None)
    lasso = BehaviourChecker(bg, [], lambda: None).counterexample_lasso()
    if lasso is not None:
        assert not ltl.holds_on_lasso(f, [list(labels[v]) for v in lasso.nodes], lasso.loop), f
        assert lasso.nodes[0] == 0
        hops = list(zip(lasso.nodes, lasso.nodes[1:])) + [(lasso.nodes[-1], lasso.nodes[lasso.loop])]
        assert all(b == a or b in succ[a] for a, b in hops)
    assert (lasso is not None) or not _violating_lasso_exists(succ, labels, [0], f, 5), f


REFUSED = {
    # name: (property, exit code, message, column)
    "temporal_exists": ("\\EE v : <>(x = v)", 151, "temporal quantifier \\AA/\\EE", 9),
    "plus_arrow": ("[](x = 0) -+-> [](x = 1)", 151, "-+-> over temporal formulas is not checked", 9),
    "let": ("LET P == x = 1 IN <>P", 151, "LET over temporal formulas is not checked", 9),
    "raw_action": ("[]<>(x' > x)", 151, "an action-level formula is not supported here", 14),
    "equiv": ("<>(x = 1) <=> <>(x = 0)", 255, "TLC cannot handle the temporal formula <=>", 9),
    "case": ("CASE x = 0 -> <>(x = 1) [] OTHER -> TRUE", 255, "TLC cannot handle the temporal formula CASE", 9),
    "nested_action": ("[](x = 0 => <>[][x' = x]_x)", 255,
                      "Temporal formulas containing actions must be of forms <>[]A or []<>A.", 9),
}


def _refused_spec(tla_dir, prop: str):  # noqa: ANN001, ANN202
    return tla_dir("U", f"""---- MODULE U ----
EXTENDS Naturals
VARIABLE x
Init == x = 0
Next == x' = 1 - x
Spec == Init /\\ [][Next]_x

Live == {prop}
====
""", "SPECIFICATION Spec\nPROPERTY Live\n")


@pytest.mark.parametrize("case", sorted(REFUSED))
def test_tableau_refuses_what_it_does_not_check_with_a_position(tla_dir, case: str) -> None:
    prop, code, message, col = REFUSED[case]
    with pytest.raises(TlaError) as err:
        load_model(str(_refused_spec(tla_dir, prop)))
    assert exit_codes.BY_KIND[err.value.kind] == code
    assert message in err.value.message
    assert err.value.loc is not None and (err.value.loc.line, err.value.loc.column) == (8, col)


def test_tableau_refusal_is_a_one_line_error_with_tlcs_exit_code(tla_dir, capsys) -> None:  # noqa: ANN001
    code = main(["check", str(_refused_spec(tla_dir, REFUSED["nested_action"][0]))])
    err = capsys.readouterr().err
    assert code == 255 and "Traceback" not in err
    assert err.strip().endswith("U.tla:8:9: error: Temporal formulas containing actions must be of forms "
                                "<>[]A or []<>A.")


def test_tableau_text_and_itf_output_of_a_general_property(tmp_path, capsys) -> None:  # noqa: ANN001
    itf = tmp_path / "cex.itf.json"
    code = main(["check", str(TABLEAU / "StableOrInfinitelyFails.tla"), "--itf", str(itf)])
    out = capsys.readouterr().out
    assert code == 13 and "Error: Temporal property Prop was violated." in out
    assert "State 2: <Next line 6, col 1 of module StableOrInfinitelyFails>" in out
    assert "Back to state 1: <Next line 6, col 1 of module StableOrInfinitelyFails>" in out
    trace = json.loads(itf.read_text())
    assert trace["loop"] == 0 and [s["x"]["#bigint"] for s in trace["states"]] == ["0", "1"]


@pytest.mark.skipif(not os.path.isfile(os.environ.get("TLA2TOOLS_JAR", "")), reason="TLA2TOOLS_JAR not set")
@pytest.mark.parametrize("name", sorted(EXPECTED))
def test_tableau_expected_results_are_tlcs(name: str) -> None:
    from safestate.checker.tlc import run_tlc
    tlc = run_tlc(os.environ["TLA2TOOLS_JAR"], str(TABLEAU / f"{name}.tla"), str(TABLEAU / f"{name}.cfg"))
    want = EXPECTED[name]
    assert tlc.exit_code == want["exit_code"]
    if want["result"] == "error":
        return
    for f in FIELDS:
        assert getattr(tlc, f) == want[f], f
    if "left_on_queue" in want:
        assert tlc.left_on_queue == want["left_on_queue"]
    assert (tlc.lasso is None) == ("lasso" not in want)
    assert tlc.violated_properties == want.get("violated_properties")


def _random_property(r: random.Random, depth: int) -> str:
    """A random temporal formula over x and y (TLA+ text)."""
    if depth == 0 or r.random() < 0.2:
        return r.choice([f"x = {r.randrange(4)}", f"x # {r.randrange(4)}", "y = 1", "y = 0", f"x < {r.randrange(1, 4)}"])
    op = r.choice(["[]", "<>", "[]", "<>", "/\\", "\\/", "=>", "~>", "~"])
    if op in ("[]", "<>", "~"):
        return f"{op}({_random_property(r, depth - 1)})"
    return f"({_random_property(r, depth - 1)}) {op} ({_random_property(r, depth - 1)})"


def _random_tableau_spec(seed: int) -> tuple[str, str]:
    """x in 0..3 moved by random actions, a bit y, random WF/SF, and a random
    general property (nested temporal operators, disjunctions, implications)."""
    r = random.Random(seed)
    names, acts = [], []
    for i in range(r.randint(2, 4)):
        moves = " \\/ ".join(f"(x = {r.randrange(4)} /\\ x' = {r.randrange(4)})" for _ in range(r.randint(1, 3)))
        acts.append(f"A{i} == ({moves}) /\\ y' = {'1 - y' if r.random() < 0.3 else 'y'}")
        names.append(f"A{i}")
    fair = [f"{'WF' if c < 0.3 else 'SF'}_vars({n})" for n in names if (c := r.random()) < 0.5]
    step = r.choice(["", "", " \\/ []<><<A0>>_vars", " \\/ <>[][x' >= x]_vars"])
    # The root is a temporal operator or \\/, =>, ~>: TLC names a non-temporal conjunct
    # of a PROPERTY by its position, not by the property's name (a known difference).
    root = r.choice(["[]", "<>", "\\/", "=>", "~>"])
    a, b = _random_property(r, 2), _random_property(r, 2)
    prop = f"{root}({a})" if root in ("[]", "<>") else f"({a}) {root} ({b})"
    nxt = " \\/ ".join(names)
    spec = " /\\ ".join(["Init", "[][Next]_vars", *fair])
    tla = "\n".join([f"---- MODULE T{seed} ----", "EXTENDS Naturals", "VARIABLES x, y", "vars == <<x, y>>",
                     "Init == x = 0 /\\ y \\in {0, 1}", *acts, f"Next == {nxt}", f"Spec == {spec}",
                     f"Prop == ({prop}){step}", "===="])
    return tla + "\n", "SPECIFICATION Spec\nPROPERTY Prop\nCHECK_DEADLOCK FALSE\n"


def _check_random(tla_dir, seed: int):  # noqa: ANN001, ANN202
    tla, cfg = _random_tableau_spec(seed)
    path = tla_dir(f"T{seed}", tla, cfg)
    try:
        model = load_model(str(path))
    except TlaError as e:
        return path, None, e
    return path, model, explore_states(model)


@pytest.mark.parametrize("seed", range(30))
def test_tableau_counterexamples_of_random_specs_are_fair_violating_behaviours(tla_dir, seed: int) -> None:
    _, model, r = _check_random(tla_dir, seed)
    if model is None:  # TLC's refusal of a step outside <>[]A / []<>A
        assert r.kind == "temporal", r
        return
    assert r.result != "error", r.error  # also a safety or initial-state violation of a []P or P conjunct
    if r.result == "liveness failure":
        states, _, _ = fair_lasso(model, r)
        ob = next(o for o in model.liveness if o.name == r.violated)
        assert violated_on(ob, states, r.loop, r.loop_step is None)


@pytest.mark.skipif(not os.path.isfile(os.environ.get("TLA2TOOLS_JAR", "")), reason="TLA2TOOLS_JAR not set")
@pytest.mark.parametrize("seed", range(30))
def test_tableau_verdicts_on_random_specs_equal_tlcs(tla_dir, seed: int) -> None:
    from safestate.checker.tlc import run_tlc
    path, model, r = _check_random(tla_dir, seed)
    tlc = run_tlc(os.environ["TLA2TOOLS_JAR"], str(path), str(path.with_suffix(".cfg")))
    if model is None:
        assert tlc.exit_code == exit_codes.BY_KIND[r.kind]
        return
    for f in FIELDS:
        if getattr(tlc, f) is not None or f == "violated":  # no statistics after an initial state
            assert getattr(r, f) == getattr(tlc, f), f
    assert (r.loop is None) == (tlc.lasso is None)
