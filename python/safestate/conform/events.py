"""Model events: the (action, params) of a model transition, as a hashable key.

The event of a step is taken from the graph edge / the model transition (action and
its \\E-bound parameters), never from the model's `event` variable: a VIEW may merge
states that differ only in `event`.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

from ..checker.itf import value_from_itf, value_to_itf
from ..tla.values import FnValue, Value, fmt

@dataclass(frozen=True)
class Event:
    action: str
    params: tuple[tuple[str, Value], ...]  # sorted by name

    @staticmethod
    def of(action: str, params: dict[str, Value]) -> "Event":
        return Event(action, tuple(sorted(params.items())))

    @staticmethod
    def from_itf(action: str, params: dict[str, Any]) -> "Event":
        return Event.of(action, {k: value_from_itf(v) for k, v in params.items()})

    def param(self) -> Value:
        """The single parameter of an action such as Cycle(in) / Submit(c)."""
        if len(self.params) != 1:
            raise ValueError(f"{self.action} has {len(self.params)} parameters, expected 1")
        return self.params[0][1]

    def record(self) -> dict[str, Value]:
        v = self.param()
        if type(v) is not FnValue:
            raise ValueError(f"{self.action}: parameter is not a record: {fmt(v)}")
        return v.d  # type: ignore[union-attr]

    def params_itf(self) -> dict[str, Any]:
        return {k: value_to_itf(v) for k, v in self.params}

    def __str__(self) -> str:
        return f"{self.action}({', '.join(fmt(v) for _, v in self.params)})"
