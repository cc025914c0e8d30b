"""The reachable state graph built by the native core (`checker/native/`).

The core records one edge per successor inside the model, in the Python engine's
order (`explore_states(model, graph=True)`): source and target state indices, the
action leaf and the leaf's parameters as one interned tuple.  Here they become the
same states (Python values, in discovery order), initial states and (src, dst, Event)
edges the Python engine gives, so `graph._dedup` builds an equal `StateGraph`.
Value ids are converted once each (per-id cache); the edge arrays stay `array("I")`.
"""

from __future__ import annotations

from array import array
from dataclasses import dataclass, field
from typing import Callable, Iterator

from ..checker.explore import CheckResult
from ..checker.model import Model
from .events import Event
from .native_events import EventCache, prepare_run


@dataclass
class NativeGraph:
    result: CheckResult
    states: list[tuple] = field(default_factory=list)
    initial: list[int] = field(default_factory=list)
    src: array = field(default_factory=lambda: array("I"))
    dst: array = field(default_factory=lambda: array("I"))
    events: list[Event] = field(default_factory=list)  # one per edge (shared objects)

    def raw_edges(self) -> Iterator[tuple[int, int, Event]]:
        return zip(self.src, self.dst, self.events)


def native_graph(model: Model, progress: Callable[[str], None] | None = None) -> NativeGraph | str:
    """The state graph from the native core, or why it cannot build it (a construct
    outside its subset with file:line:col, or an evaluation error, which the Python
    engine then reports exactly)."""
    from ..checker.native.search import explore_native
    prepared = prepare_run(model)
    if isinstance(prepared, str):
        return prepared
    run, slots = prepared
    eng = run.engine
    eng.record_edges = True
    eng.leaf_params = slots
    result, error = explore_native(model, None, progress, run, 1)
    if result is None:
        return f"the native engine stopped at an evaluation error ({error})"
    graph = NativeGraph(result)
    if result.result != "success":
        return graph
    bridge = run.bridge
    arena = array("I", eng.states_bytes())
    ids = sorted(set(arena))
    python_of = dict(zip(ids, map(bridge.to_python, ids)))
    values = list(map(python_of.__getitem__, arena))
    nvars = len(model.variables)
    graph.states = [tuple(values[i:i + nvars]) for i in range(0, len(values), nvars)] if nvars else \
        [() for _ in range(result.distinct_states)]
    graph.initial = list(range(eng.initial_count))
    src, dst, leaves, params = (array("I", b) for b in eng.edges_bytes())
    graph.src, graph.dst = src, dst
    graph.events = list(map(EventCache(model, bridge).event, leaves, params))
    return graph
