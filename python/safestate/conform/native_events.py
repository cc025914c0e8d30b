"""The native core's action leaves and parameter tuples as the Python engine's events.

The core records a successor's action as the index of its `Leaf` and the leaf's
parameters as one interned tuple of value ids; both the state graph
(`native_graph.py`) and one-step evaluation (`native_step.py`) turn them into the
`Event` the Python engine gives (`Model.successors`), one shared object per pair.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from ..checker.model import Model
from .events import Event

if TYPE_CHECKING:
    from ..checker.native.search import NativeRun
    from ..checker.native.values import ValueBridge


def prepare_run(model: Model) -> "tuple[NativeRun, list[list[int]]] | str":
    """The model translated for the core with its leaves' parameter slots, or why the
    core does not take it (a construct outside its subset, with file:line:col)."""
    from ..checker.native.search import NativeRun
    from ..tla.errors import UnsupportedError
    try:
        run = NativeRun(model)
    except UnsupportedError as e:
        return str(e)
    slots = leaf_slots(model, run)
    return slots if isinstance(slots, str) else (run, slots)


def leaf_slots(model: Model, run: "NativeRun") -> list[list[int]] | str:
    """Per leaf, the core's slots of its parameters in the Python leaf's order, or why
    the two engines' leaves do not line up (then the caller uses the Python engine)."""
    out = []
    for leaf, native in zip(model.leaves, run.leaf_params):
        if [n for n, _ in leaf.params] != [n for n, _ in native]:
            return (f"{leaf.loc}: the parameters of action {leaf.name} differ between the engines "
                    f"({[n for n, _ in leaf.params]} and {[n for n, _ in native]})")
        out.append([sl for _, sl in native])
    return out


class EventCache:
    """(leaf, parameter tuple id) -> the Python engine's `Event` (one object per pair)."""

    def __init__(self, model: Model, bridge: "ValueBridge") -> None:
        self.leaves = model.leaves
        self.bridge = bridge
        self._events: dict[tuple[int, int], Event] = {}

    def event(self, leaf: int, params: int) -> Event:
        key = (leaf, params)
        ev = self._events.get(key)
        if ev is None:
            lf = self.leaves[leaf]
            values = self.bridge.to_python(params)
            ev = self._events[key] = Event.of(lf.name, {n: v for (n, _), v in zip(lf.params, values)})
        return ev
