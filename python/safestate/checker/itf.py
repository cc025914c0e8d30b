"""Conversion of TLA+ values and states to and from the ITF JSON trace format
(Apalache ADR-015).

Encoding: booleans and strings as JSON; integers as ``{"#bigint": "n"}``; sets as
``{"#set": [...]}`` (TLC order); functions with domain ``1..n`` (tuples and
sequences, which our values do not distinguish) as JSON arrays; records as JSON
objects; other functions as ``{"#map": [[k, v], ...]}``; model values as
``{"#unserializable": "name"}``.  A state is an object from variable name to
value plus ``#meta``.
"""

from __future__ import annotations

from typing import Any

from ..tla.values import FnValue, LazySet, ModelValue, Value, make_fn, sorted_elems


def value_to_itf(v: Value) -> Any:
    t = type(v)
    if t is bool or t is str:
        return v
    if t is int:
        return {"#bigint": str(v)}
    if t is tuple:
        return [value_to_itf(x) for x in v]
    if t is FnValue:
        keys = sorted_elems(frozenset(v.d))
        if all(type(k) is str for k in keys):
            return {k: value_to_itf(v.d[k]) for k in keys}
        return {"#map": [[value_to_itf(k), value_to_itf(v.d[k])] for k in keys]}
    if t is frozenset or isinstance(v, LazySet):
        return {"#set": [value_to_itf(x) for x in sorted_elems(v)]}
    if t is ModelValue:
        return {"#unserializable": v.name}
    return {"#unserializable": repr(v)}


def value_from_itf(j: Any) -> Value:
    if isinstance(j, bool) or isinstance(j, str):
        return j
    if isinstance(j, int):
        return j
    if isinstance(j, list):
        return tuple(value_from_itf(x) for x in j)
    if isinstance(j, dict):
        if "#bigint" in j:
            return int(j["#bigint"])
        if "#set" in j:
            return frozenset(value_from_itf(x) for x in j["#set"])
        if "#tup" in j:
            return tuple(value_from_itf(x) for x in j["#tup"])
        if "#map" in j:
            return make_fn({value_from_itf(k): value_from_itf(x) for k, x in j["#map"]})
        if "#unserializable" in j:
            return ModelValue(j["#unserializable"])
        return FnValue({k: value_from_itf(x) for k, x in j.items()}) if j else ()
    raise ValueError(f"not an ITF value: {j!r}")


def state_to_itf(variables: list[str], state: tuple, meta: dict | None = None) -> dict:
    out: dict[str, Any] = {"#meta": meta} if meta is not None else {}
    for name, v in zip(variables, state):
        out[name] = value_to_itf(v)
    return out


def state_from_itf(variables: list[str], obj: dict) -> tuple:
    missing = [v for v in variables if v not in obj]
    if missing:
        raise ValueError(f"ITF state lacks variable(s) {', '.join(missing)}")
    return tuple(value_from_itf(obj[v]) for v in variables)


def trace_to_itf(variables: list[str], steps: list[tuple[tuple, str, dict]], source: str,
                 description: str, loop: int | None = None) -> dict:
    """An ITF trace from (state, action, params) steps; #meta of each state carries
    the action that produced it.  A lasso (liveness counterexample) has `loop`: the
    index of the state that follows the last one (the last itself when it stutters)."""
    states = []
    for i, (st, action, params) in enumerate(steps):
        meta = {"index": i, "action": action, "params": {k: value_to_itf(v) for k, v in params.items()}}
        states.append(state_to_itf(variables, st, meta))
    out: dict[str, Any] = {
        "#meta": {"format": "ITF", "format-description": "https://apalache-mc.org/docs/adr/015adr-trace.html",
                  "source": source, "description": description},
        "vars": list(variables),
        "states": states,
    }
    if loop is not None:
        out["loop"] = loop
    return out
