"""The outcome of one proof attempt."""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any


@dataclass
class Result:
    invariant: str
    status: str                      # "proved" | "violated" | "unknown" | "ill-defined" | "vacuous"
    engine: str
    k: int | None = None
    seconds: float = 0.0
    trace: list[dict[str, Any]] | None = None   # states of a counterexample
    params: dict[str, Any] = field(default_factory=dict)   # constant values of the counterexample
    cti: list[dict[str, Any]] | None = None     # [s, s'] counterexample to induction
    cti_params: dict[str, Any] = field(default_factory=dict)
    note: str = ""
    model: Any = None                # the z3 model of `trace` (its unrolling has len(trace) - 1 steps)
    obligations: int = 0             # well-definedness obligations proved alongside
    undefined: str = ""              # the ill-defined site, when status is ill-defined
    vacuity: list[str] = field(default_factory=list)
