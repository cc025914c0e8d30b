"""Runs the liveness check after a successful safety search and turns a
counterexample lasso into the result's trace (with the action of every step)."""

from __future__ import annotations

from typing import TYPE_CHECKING

from ..tla.errors import TlaError
from .liveness import Lasso, StateGraph, find_violation, violated_on
from .tableau_safety import SafetyStop, first_stop
from .temporal import Obligation

if TYPE_CHECKING:
    from .explore import CheckResult, Explorer
    from .model import Model


def check_liveness(model: Model, explorer: Explorer, result: CheckResult) -> None:
    """Check the model's liveness properties on the explored graph; on a violation
    set `result` to a "liveness failure" with the lasso as its trace."""
    from ..tla.enum_watch import rss_mb

    def check_memory() -> None:
        if rss_mb() > explorer.max_memory_mb:
            raise TlaError("memory", f"memory limit of {explorer.max_memory_mb} MB exceeded while checking "
                           f"liveness on {len(explorer.states)} states; raise it with --max-memory or add a "
                           f"state constraint")
    try:
        check_memory()
        graph = StateGraph(len(explorer.states), explorer.edge_src, explorer.edge_dst)
        check_memory()
        if _stopped_early(model, explorer, result, graph):
            return
        found = find_violation(graph, explorer.states, explorer.initial, model.fairness, model.liveness,
                               check_memory)
    except TlaError as e:
        result.result = "error"
        result.error = e
        return
    if found is None:
        return
    ob, lasso = found
    result.result = "liveness failure"
    _name_violated(model, explorer, result, ob, lasso)
    steps = lasso_steps(model, explorer, lasso)
    result.loop = lasso.loop
    if not lasso.stuttering:
        result.loop_step = steps.pop()
    result.trace = steps


def stop_before_safety_failure(model: Model, explorer: Explorer, result: CheckResult) -> None:
    """TLC adds a state to its behaviour graph after generating its successors
    (`Worker.run`: `doNextCheckLiveness` after `getNextStates`), so a finite temporal
    counterexample completed while expanding an earlier state than the one where the
    search met an invariant violation, deadlock or error ends the search first: the
    result becomes that property's.  (Completed while expanding the same state, TLC
    reports the safety failure first and then the property too; we report the former.)"""
    if not model.liveness or model.fairness or not explorer.generated_after:
        return
    try:
        _stopped_early(model, explorer, result,
                       StateGraph(len(explorer.states), explorer.edge_src, explorer.edge_dst))
    except TlaError as e:
        result.result = "error"
        result.error = e


def _stopped_early(model: Model, explorer: Explorer, result: CheckResult, graph: StateGraph) -> bool:
    """Replays TLC's early stop over the states expanded so far; on a stop, `result` is its."""
    stop = first_stop(model.liveness, bool(model.fairness), explorer.states, explorer.initial,
                      lambda v: list(graph.succ(v)), len(explorer.generated_after))
    if stop is None:
        return False
    _stop_at(model, explorer, result, stop)
    return True


def _name_violated(model: Model, explorer: Explorer, result: CheckResult, ob: Obligation, lasso: Lasso) -> None:
    """TLC's message names every property the counterexample violates, in .cfg order."""
    lasso_states = [explorer.states[v] for v in lasso.nodes]
    names: list[str] = []
    for other in model.liveness:
        if other.name not in names and (other is ob or violated_on(other, lasso_states, lasso.loop,
                                                                    lasso.stuttering)):
            names.append(other.name)
    result.violated_properties = names
    result.violated = names[0]


def _stop_at(model: Model, explorer: Explorer, result: CheckResult, stop: SafetyStop) -> None:
    """The result where TLC stops its search at a finite counterexample: the counts
    after expanding state `stop.expanded`, the behaviour (its last state stuttering for
    ever, for naming the violated properties)."""
    k = stop.expanded
    distinct = max(explorer.initial, default=-1) + 1
    for src, dst in zip(explorer.edge_src, explorer.edge_dst):
        if src > k:
            break
        distinct = max(distinct, dst + 1)
    result.result = "temporal safety failure"
    result.error = None
    result.distinct_states = distinct
    result.states_generated = explorer.generated_after[k]
    result.depth = max(explorer.level[:distinct])
    result.left_on_queue = distinct - k - 1
    lasso = Lasso(stop.states, len(stop.states) - 1, True)
    _name_violated(model, explorer, result, stop.obligation, lasso)
    result.loop = None
    result.trace = lasso_steps(model, explorer, lasso)


def lasso_steps(model: Model, explorer: Explorer, lasso: Lasso) -> list:
    """The lasso's states with the action of each step, followed (unless the lasso
    stutters) by the step that closes the loop."""
    from .explore import Step
    states = explorer.states
    nodes = lasso.nodes
    steps = explorer.trace(nodes[0])
    hops = list(zip(nodes, nodes[1:]))
    if not lasso.stuttering:
        hops.append((nodes[-1], nodes[lasso.loop]))
    for u, v in hops:
        action, params = _step_label(model, states[u], states[v])
        steps.append(Step(states[v], action, params))
    return steps


def _step_label(model: Model, src: tuple, dst: tuple) -> tuple[str, dict]:
    """The first (action, params) of Next, in TLC order, that goes from src to dst."""
    want = model.key(dst)
    found: list[tuple[str, dict]] = []

    def on_succ(st: tuple, leaf: int, L: list) -> None:
        if not found and (st == dst or model.key(st) == want):
            found.append((model.leaves[leaf].name, model.leaf_params(leaf, L)))
    model.run_next(src, on_succ)
    return found[0] if found else (model.next_name, {})
