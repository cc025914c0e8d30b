"""Counterexamples for people and tools: TLA+-style states and ITF traces.

Concrete values are converted to the checker's value representation so the
checker's printer (`fmt`) and ITF writer (`trace_to_itf`) are reused as they are.
"""

from __future__ import annotations

from typing import Any

from ..checker.itf import trace_to_itf
from ..tla.values import FnValue, fmt, make_fn
from .values import FnDict, FrozenFn


def to_value(v: Any) -> Any:
    if isinstance(v, (FnDict, FrozenFn)):
        return make_fn({k: to_value(x) for k, x in v.items()})
    if isinstance(v, dict):
        return FnValue({k: to_value(x) for k, x in v.items()})
    if isinstance(v, tuple):
        return tuple(to_value(x) for x in v)
    if isinstance(v, frozenset):
        return frozenset(to_value(x) for x in v)
    return v


def state_lines(state: dict[str, Any]) -> list[str]:
    return [f"/\\ {name} = {fmt(to_value(v))}" for name, v in state.items()]


def format_trace(states: list[dict[str, Any]], params: dict[str, Any]) -> str:
    out = []
    if params:
        out.append("Constants: " + ", ".join(f"{k} = {fmt(to_value(v))}" for k, v in params.items()))
    for i, st in enumerate(states):
        out.append(f"State {i + 1}:" if i else "State 1: <Initial predicate>")
        out.extend(state_lines(st))
        out.append("")
    return "\n".join(out)


def itf(variables: list[str], states: list[dict[str, Any]], params: dict[str, Any], source: str,
        description: str) -> dict:
    steps = []
    for i, st in enumerate(states):
        steps.append((tuple(to_value(st[v]) for v in variables), "Init" if i == 0 else "Next",
                      {k: to_value(v) for k, v in params.items()} if i == 0 else {}))
    return trace_to_itf(variables, steps, source, description)
