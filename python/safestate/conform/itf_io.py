"""Concrete traces to and from ITF files, with the checker's ITF writer/reader."""

from __future__ import annotations

import json
import os

from ..checker.itf import trace_to_itf
from ..checker.model import Model
from ..errors import UsageError
from .json_input import load_json
from .events import Event
from .traces import ConcreteTrace, Step


def to_itf(model: Model, trace: ConcreteTrace, description: str) -> dict:
    rows: list[tuple[tuple, str, dict]] = [(trace.initial, "Init", {})]
    rows += [(s.state, s.event.action, dict(s.event.params)) for s in trace.steps]
    return trace_to_itf(model.variables, rows, "safestate conform", description)


def write(path: str, model: Model, trace: ConcreteTrace, description: str) -> None:
    os.makedirs(os.path.dirname(os.path.abspath(path)), exist_ok=True)
    with open(path, "w", encoding="utf-8") as f:
        json.dump(to_itf(model, trace, description), f, separators=(",", ":"))
        f.write("\n")


def read(path: str, model: Model) -> ConcreteTrace:
    """A trace from an ITF file: the first state, then each state's #meta action and
    params as the event that produced it."""
    doc = load_json(path, "ITF trace")
    states = doc.get("states") if isinstance(doc, dict) else None
    if not isinstance(states, list) or not states:
        raise UsageError(f"{path}: not an ITF trace (expected an object with a non-empty 'states' list)")
    if "vars" in doc and list(doc["vars"]) != list(model.variables):
        raise UsageError(f"{path}: the trace's variables {doc['vars']} differ from the model's {list(model.variables)}")
    steps = []
    for n, s in enumerate(states):
        missing = [v for v in model.variables if not isinstance(s, dict) or v not in s]
        if missing:
            raise UsageError(f"{path}: state {n} lacks variable(s) {', '.join(missing)}")
    for s in states[1:]:
        meta = s.get("#meta", {})
        if "action" not in meta:
            raise UsageError(f"{path}: state {meta.get('index', '?')} has no #meta.action")
        steps.append(Step(Event.from_itf(meta["action"], meta.get("params", {})), model.state_from_itf(s), -1))
    return ConcreteTrace(model.state_from_itf(states[0]), steps)
