"""Killing by the model's reachability witnesses.

A model declares its reachability witnesses as `Witness_X ==` definitions of its own
module (`safestate.mutants.witnesses`): each is the negation of a situation, most often
a property's antecedent, and the original must violate it -- reach the situation
(test_model_mutants.py checks each with the model's cfg).  A mutant that passes every
property of the CI cfg but never violates Witness_X has lost that situation: the
property whose antecedent it is now holds vacuously.  Such a mutant is *killed by the
witness*, as a `models/mutants/*.toml` entry with `expect = "holds"` is: a category of
its own in the report, counted as killed in the score.

A witness is evaluated as the original defines it, on the states the mutant's check
stored -- the states `safestate check` with the witness as its invariant tests (under a
VIEW, one per fingerprint).  On the native core the mutant's own engine evaluates it on
the states of the check that just ran (no second search); a witness that reads the
mutated definition (transitively) would there be the mutant's text, so it is evaluated
by the original's Python evaluator on the same states instead.  On the Python engine the
mutant's check records its states (`check --graph`'s list) and the original's evaluator
reads them.  A witness whose evaluation fails in a state counts as reached there: an
error never kills.  Only witnesses the original reaches are used; the others are
reported (`not_reached`).
"""

from __future__ import annotations

from array import array
from collections.abc import Iterable, Iterator
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from ..checker.model import Model
from ..tla import ast as A
from ..tla.errors import TlaError, UnsupportedError


@dataclass
class WitnessSet:
    """The witnesses a model's mutants are measured against."""

    names: tuple[str, ...] = ()          # the original reaches each: used
    not_reached: tuple[str, ...] = ()    # declared, never reached by the original: not used
    reads: dict[str, frozenset[str]] = field(default_factory=dict)  # the definitions each reads
    _python: dict[str, Any] = field(default_factory=dict)           # compiled by the original

    def evaluator(self, original: Model, name: str) -> Any:
        fn = self._python.get(name)
        if fn is None:
            fn = self._python[name] = original.compiler.evaluator(A.Name(original.module_loc(), name), original.scope)
        return fn


def declared(model: Path) -> list[str]:
    """The model's reachability witnesses (`Witness_X ==` of its own module), in order."""
    from ..mutants import witnesses
    return witnesses(model)


def _python_holds(fn: Any, state: tuple) -> bool:
    try:
        return fn(state, None) is True
    except TlaError:
        return False  # counted as reached: an evaluation error never kills


def _scan(names: Iterable[str], states: Iterable[Any], holds: Any) -> list[str]:
    """The names whose witness holds in every state (lost), scanning in order and
    stopping once every witness was violated somewhere."""
    left = list(names)
    for st in states:
        if not left:
            break
        left = [w for w in left if holds(w, st)]
    return left


def on_python_states(ws: WitnessSet, original: Model, names: Iterable[str], states: Iterable[tuple]) -> list[str]:
    """The witnesses of `names` no state of `states` (Python values) violates."""
    fns = {w: ws.evaluator(original, w) for w in names}
    return _scan(fns, states, lambda w, st: _python_holds(fns[w], st))


def _native_states(run: Any, nvars: int) -> Iterator[list[int]]:
    ids = array("I", run.engine.states_bytes())
    for i in range(0, len(ids), nvars):
        yield ids[i:i + nvars].tolist()


def on_native_states(ws: WitnessSet, original: Model, run: Any, model: Model, mutated: str | None) -> list[str]:
    """The witnesses the states stored by the native check of `run` (of `model`) never
    violate: evaluated by that engine where the witness does not read the definition
    `mutated`, else (or where the core refuses the witness) by the original's Python
    evaluator on the same states."""
    from ..checker.native.translate import TEnv
    from ..checker.native.values import _TRUE
    trees: dict[str, Any] = {}
    python: list[str] = []
    for w in ws.names:
        if mutated is not None and mutated in ws.reads.get(w, frozenset()):
            python.append(w)
            continue
        try:
            trees[w] = run.translator.expr(A.Name(model.module_loc(), w), TEnv(model.scope, {}))
        except (UnsupportedError, TlaError):
            python.append(w)
    eng = run.engine
    eng.set_slots(run.translator.nslots)  # room for the witnesses' bound names
    from .. import _tla_native  # type: ignore[attr-defined]
    step_error = _tla_native.StepError
    fns = {w: ws.evaluator(original, w) for w in python}
    bridge = run.bridge

    def holds(w: str, ids: list[int]) -> bool:
        if w in trees:
            try:
                return bool(eng.evaluate(trees[w], ids, []) == _TRUE)
            except step_error:
                return False
        return _python_holds(fns[w], tuple(map(bridge.to_python, ids)))
    return _scan(ws.names, _native_states(run, len(model.variables)), holds)


def witness_set(model_path: Path, original: Model, states: Iterable[tuple] = (),
                native: tuple[Any, Model] | None = None) -> WitnessSet:
    """The declared witnesses of the model, split by whether the original reaches them
    -- on the states its native check (`native`: the run and the model it translated)
    stored, else on `states` (Python values) -- and what each reads."""
    from .generate import definition_reads
    names = declared(model_path)
    if not names:
        return WitnessSet()
    ws = WitnessSet(names=tuple(names), reads=definition_reads(model_path, names))
    if native is not None:
        lost = on_native_states(ws, original, native[0], native[1], None)
    else:
        lost = on_python_states(ws, original, names, states)
    ws.names = tuple(w for w in names if w not in lost)
    ws.not_reached = tuple(lost)
    return ws
