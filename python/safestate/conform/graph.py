"""The model's reachable state graph with one edge per transition (state, event).

Built by the checker (`explore_states(model, graph=True)`) or read from the JSON
that `safestate check --graph FILE` writes.  The checker lists an edge once per
way Next produces it; a transition is the pair (source node, event), so duplicates
are merged here (and a pair with two different successors is an error: the model
would not be deterministic per event).
"""

from __future__ import annotations

import json
from dataclasses import dataclass

from ..checker.explore import explore_states
from ..checker.model import Model
from .cover import Graph
from .events import Event


@dataclass
class StateGraph:
    states: list[tuple]       # one representative state per node (the first found)
    initial: list[int]
    src: list[int]
    dst: list[int]
    events: list[Event]

    def as_cover_graph(self) -> Graph:
        return Graph(len(self.states), self.initial, self.src, self.dst)


class NondeterministicEvent(Exception):
    pass


def _dedup(states: list[tuple], initial: list[int], raw: list[tuple[int, int, Event]]) -> StateGraph:
    seen: dict[tuple[int, Event], int] = {}
    g = StateGraph(states, initial, [], [], [])
    for s, d, ev in raw:
        k = (s, ev)
        if k in seen:
            if seen[k] != d:
                raise NondeterministicEvent(f"node {s}: event {ev} leads to nodes {seen[k]} and {d}")
            continue
        seen[k] = d
        g.src.append(s)
        g.dst.append(d)
        g.events.append(ev)
    return g


def explore(model: Model, progress=None) -> StateGraph:  # type: ignore[no-untyped-def]
    res = explore_states(model, workers=1, graph=True, progress=progress)
    if res.result != "success":
        raise RuntimeError(f"model checking did not succeed: {res.result} {res.violated or ''} "
                           f"{res.error.message if res.error else ''}".strip())
    assert res.states is not None and res.edges is not None and res.initial is not None
    raw = [(e.src, e.dst, Event.of(e.action, e.params)) for e in res.edges]
    return _dedup(res.states, list(res.initial), raw)


def load(model: Model, path: str) -> StateGraph:
    with open(path, encoding="utf-8") as f:
        doc = json.load(f)
    if doc["vars"] != list(model.variables):
        raise ValueError(f"{path}: the graph's variables differ from the model's")
    states = [model.state_from_itf(s["state"]) for s in doc["states"]]
    cache: dict[str, Event] = {}
    raw = []
    for e in doc["edges"]:
        key = e["action"] + json.dumps(e["params"], sort_keys=True)
        ev = cache.get(key)
        if ev is None:
            ev = cache[key] = Event.from_itf(e["action"], e["params"])
        raw.append((e["from"], e["to"], ev))
    return _dedup(states, list(doc["initial"]), raw)
