"""Writes the reachable state graph as JSON (format documented in docs/tla-subset.md):

    {"vars": [...], "states": [{"id": 0, "state": <ITF state>}, ...], "initial": [ids],
     "edges": [{"from": i, "to": j, "action": "Name", "params": {"p": <ITF value>}}, ...]}

States are numbered in BFS discovery order; edges are listed in generation order
(every (state, action, params, successor), duplicates of the same step included
once per way the next-state relation produces it).  Deterministic for a given model.
"""

from __future__ import annotations

import json

from .explore import CheckResult
from .itf import state_to_itf, value_to_itf
from .model import Model


def graph_json(model: Model, result: CheckResult) -> dict:
    assert result.states is not None and result.edges is not None and result.initial is not None
    return {
        "vars": list(model.variables),
        "states": [{"id": i, "state": state_to_itf(model.variables, st)} for i, st in enumerate(result.states)],
        "initial": list(result.initial),
        "edges": [{"from": e.src, "to": e.dst, "action": e.action,
                   "params": {k: value_to_itf(v) for k, v in e.params.items()}} for e in result.edges],
    }


def write_graph(path: str, model: Model, result: CheckResult) -> None:
    with open(path, "w", encoding="utf-8") as f:
        json.dump(graph_json(model, result), f, separators=(",", ":"))
        f.write("\n")
