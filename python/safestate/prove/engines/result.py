"""The outcome of one proof attempt."""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any


@dataclass
class Result:
    invariant: str
    status: str                      # "proved" | "violated" | "unknown"
    engine: str
    k: int | None = None
    seconds: float = 0.0
    trace: list[dict[str, Any]] | None = None   # states of a counterexample
    params: dict[str, Any] = field(default_factory=dict)   # constant values of the counterexample
    cti: list[dict[str, Any]] | None = None     # [s, s'] counterexample to induction
    cti_params: dict[str, Any] = field(default_factory=dict)
    note: str = ""
