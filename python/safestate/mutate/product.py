"""The difference search: the original and the mutant driven by the same inputs.

A breadth-first search over pairs (original state, mutant state).  The inputs are the
model variables the environment chooses (system.toml `[mutate] inputs`); a step of the
pair is a step of each whose successors carry the same input values.  At each pair and
for each input value v offered by either side, the sets of observable projections of
the successors with input v are compared:

* they differ (one side cannot take v, or it produces an observation the other cannot)
  -> a *difference*: the path of inputs to this pair, then v, is the shortest input
  trace after which the two models can be told apart (breadth-first: no shorter one);
* they agree -> every pair of successors with the same inputs and the same observables
  is a new pair (each side's nondeterminism beyond its inputs is paired with the other's
  on equal observations).

The search ends at the first difference, or when every reachable pair has been
expanded (*equivalent*: no input trace tells them apart), or at the budget (*timeout*).
The initial states are compared the same way.  For a model deterministic in its inputs
(one successor per input value) this decides observational equivalence exactly.  Where
a model chooses more than its inputs, pairs are matched on equal observations, so a
reported difference is one a resolution of the choices can show (docs/mutate.md).

States are the Python engine's (`Model.successors`), so any model `safestate check`
accepts is searched; pairs are identified by the models' fingerprints (`Model.key`:
the VIEW, then SYMMETRY), as the checker identifies states.
"""

from __future__ import annotations

import time
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Any

from ..checker.model import Model
from ..tla.values import Value


@dataclass
class DiffStep:
    inputs: dict[str, Value]
    original: dict[str, Value] | None     # None: this side cannot take the step
    mutant: dict[str, Value] | None


@dataclass
class ProductResult:
    verdict: str                      # "difference" | "equivalent" | "timeout"
    pairs: int                        # pairs expanded
    steps: list[DiffStep] = field(default_factory=list)  # the difference trace (Init first)
    nondeterministic: bool = False    # a side had two successors for the same input
    reason: str = ""


@dataclass(frozen=True)
class Projection:
    inputs: tuple[str, ...]
    observables: tuple[str, ...]

    def indices(self, model: Model) -> tuple[tuple[int, ...], tuple[int, ...]]:
        idx = {v: i for i, v in enumerate(model.variables)}
        return tuple(idx[v] for v in self.inputs), tuple(idx[v] for v in self.observables)


class OriginalSide:
    """The original's initial states and successors (inside its constraints), computed
    once: in `classify_all` before the workers fork, so every mutant's search reads them
    instead of evaluating the original's Next again.  Looked up by the exact state, not
    its fingerprint: under a VIEW, two states with one fingerprint may differ in a
    variable outside the VIEW that their successors keep (the flagship's
    last_reject_reason), and the pair's successors must be those of its own state."""

    def __init__(self, model: Model) -> None:
        self.model = model
        self.init = [s for s in model.initial_states() if model.in_model(s)]
        self.table: dict[tuple, list[tuple]] = {}

    def successors(self, st: tuple) -> list[tuple]:
        out = self.table.get(st)
        if out is None:
            out = [t.state for t in self.model.successors(st) if self.model.in_model(t.state)]
            self.table[st] = out
        return out

    def explore(self, deadline: float | None = None) -> None:
        """Fills the table for every reachable state (until the deadline)."""
        todo = list(self.init)
        seen = {self.model.key(s) for s in todo}
        while todo:
            if deadline is not None and time.process_time() > deadline:
                return
            for t in self.successors(todo.pop()):
                k = self.model.key(t)
                if k not in seen:
                    seen.add(k)
                    todo.append(t)


def search(original: Model | OriginalSide, mutant: Model, proj: Projection, max_pairs: int = 2_000_000,
           deadline: float | None = None, progress: Callable[[int], None] | None = None) -> ProductResult:
    """The search of the module docstring; `deadline`: a value of `time.process_time()`
    (the budget is CPU seconds)."""
    side = original if isinstance(original, OriginalSide) else OriginalSide(original)
    original = side.model
    ii, oi = proj.indices(original)
    mi, mo = proj.indices(mutant)

    def inp(st: tuple, ix: tuple[int, ...]) -> tuple:
        return tuple(st[i] for i in ix)

    # Each pair: (orig state, mutant state, parent pair index, the input of the step)
    parents: list[int] = []
    states: list[tuple[tuple, tuple]] = []
    seen: set[tuple[Any, Any]] = set()
    nondet = False

    def grouped(sts: list[tuple], ix: tuple[int, ...], ox: tuple[int, ...]) -> dict[tuple, dict[tuple, list[tuple]]]:
        g: dict[tuple, dict[tuple, list[tuple]]] = {}
        for st in dict.fromkeys(sts):  # a successor generated twice is one successor
            g.setdefault(inp(st, ix), {}).setdefault(inp(st, ox), []).append(st)
        return g

    def trace_to(k: int, last: list[DiffStep]) -> list[DiffStep]:
        out: list[DiffStep] = []
        while k >= 0:
            o, m = states[k]
            out.append(DiffStep(dict(zip(proj.inputs, inp(o, ii))), dict(zip(proj.observables, inp(o, oi))),
                                dict(zip(proj.observables, inp(m, mo)))))
            k = parents[k]
        out.reverse()
        return out + last

    def compare(go: dict, gm: dict, parent: int) -> list[DiffStep] | None:
        nonlocal nondet
        for v in list(go) + [v for v in gm if v not in go]:
            a, b = go.get(v, {}), gm.get(v, {})
            if sum(len(x) for x in a.values()) > 1 or sum(len(x) for x in b.values()) > 1:
                nondet = True
            if set(a) != set(b):
                only_a = [o for o in a if o not in b]
                only_b = [o for o in b if o not in a]
                step = DiffStep(dict(zip(proj.inputs, v)),
                                dict(zip(proj.observables, only_a[0] if only_a else next(iter(a)))) if a else None,
                                dict(zip(proj.observables, only_b[0] if only_b else next(iter(b)))) if b else None)
                return trace_to(parent, [step])
            for obs, olist in a.items():
                for o in olist:
                    for m in b[obs]:
                        key = (original.key(o), mutant.key(m))
                        if key not in seen:
                            seen.add(key)
                            states.append((o, m))
                            parents.append(parent)
        return None

    o0 = side.init
    m0 = [s for s in mutant.initial_states() if mutant.in_model(s)]
    diff = compare(grouped(o0, ii, oi), grouped(m0, mi, mo), -1)
    if diff is not None:
        return ProductResult("difference", 0, diff, nondet)
    k = 0
    while k < len(states):
        if k >= max_pairs or (deadline is not None and time.process_time() > deadline):
            why = f"{k} pairs expanded, {len(states) - k} left" + (
                " (pair budget)" if k >= max_pairs else " (time budget)")
            return ProductResult("timeout", k, nondeterministic=nondet, reason=why)
        o, m = states[k]
        so = side.successors(o)
        sm = [t.state for t in mutant.successors(m) if mutant.in_model(t.state)]
        diff = compare(grouped(so, ii, oi), grouped(sm, mi, mo), k)
        if diff is not None:
            return ProductResult("difference", k + 1, diff, nondet)
        k += 1
        if progress is not None and k % 2000 == 0:
            progress(k)
    return ProductResult("equivalent", k, nondeterministic=nondet)
