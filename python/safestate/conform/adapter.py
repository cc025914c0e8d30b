"""The fixed interface between a model and its C++ binding (docs/adding-a-system.md).

Everything in `safestate conform` (trace cover, replay, Hypothesis lockstep, the
input-complete pass, table audit, reproducers) works from an `Adapter`; nothing else
in this package names a model variable or a binding call.  An adapter is mostly data
(class attributes), plus three methods where data cannot say it:

* data -- which model variables and zero-argument operators are compared with the
  key of the same name in the C++ `observe()`; which record variables are split into
  several keys; which variables are environment/history and never compared (every
  model variable must be in exactly one of these lists: a new variable is an error,
  not silently ignored); which model constant is which C++ Config field; the model
  operator giving the rows a step fires; the rows unreachable by construction;
* `new_sut()` -- a fresh C++ object in its initial state;
* `apply(sut, event, before)` -- the C++ call(s) for one model event, returning the
  rows the C++ fired (or None when the event fires none) and a note when the call's
  own result disagrees with the model;
* `observe(sut)` -- the C++ observable state as a dict (usually `sut.observe()`).

Optional: `input_alphabet(state)` and `probe_batch(prefix, probes)` for the
input-complete pass; `expected_line(state)` (with `plan_call`, `plan_config`,
`state_aux`) for the replay as a compact plan walked in the binding (replay_plan.py);
and `hypothesis_rules()`, a mixin class of Hypothesis rules for the shapes random walks
rarely reach.
"""

from __future__ import annotations

from collections.abc import Callable, Iterable
from dataclasses import dataclass
from types import ModuleType
from typing import Any, ClassVar

from ..errors import SafestateError
from ..tla.values import FnValue, Value
from .events import Event
from .model_step import ModelStepper


class AdapterError(SafestateError):
    """The adapter does not fit the model (a variable unaccounted for, a missing operator)."""


@dataclass
class Applied:
    fired: frozenset[str] | None   # row ids the C++ fired; None: this event fires no row
    note: str = ""                 # non-empty: the call's own result disagrees with the model


@dataclass(frozen=True)
class Probe:
    """One input vector of the input-complete pass: the model event it stands for and
    the concrete C++ input it is sent as (several probes may share an event).  With
    `before`, a short sequence: those model events first (e.g. a command outside the
    cfg's alphabet), then `event`; `concrete` then stands for all the steps."""

    event: Event
    concrete: Any
    label: str
    before: tuple[Event, ...] = ()


def plain(v: Value) -> Any:
    """A model value as the plain Python value a binding returns."""
    if type(v) is tuple:
        return [plain(x) for x in v]
    if type(v) is FnValue:
        return {k: plain(x) for k, x in v.d.items()}  # type: ignore[union-attr]
    return v


def differing(model: dict[str, Any], cpp: dict[str, Any]) -> list[str]:
    """Keys whose values differ (a key missing on either side differs)."""
    keys = list(model) + [k for k in cpp if k not in model]
    return [k for k in keys if k not in model or k not in cpp or model[k] != cpp[k]]


class Adapter:
    # ------------------------------------------------------------------ data
    #: model variables compared with observe()[same name]
    observed_variables: ClassVar[tuple[str, ...]] = ()
    #: zero-argument model operators compared with observe()[same name]
    observed_operators: ClassVar[tuple[str, ...]] = ()
    #: record variable -> ((observe key, record field), ...)
    split_records: ClassVar[dict[str, tuple[tuple[str, str], ...]]] = {}
    #: environment / history variables, or state observed only through an operator
    hidden_variables: ClassVar[tuple[str, ...]] = ()
    #: model constant -> C++ Config field
    config_constants: ClassVar[dict[str, str]] = {}
    #: model operator Op(param) giving the set of row ids an event fires (None: no rows)
    rows_operator: ClassVar[str | None] = None
    #: C++ table rows the design page declares unreachable by construction
    unreachable_rows: ClassVar[tuple[str, ...]] = ()

    def __init__(self, core: ModuleType, stepper: ModelStepper) -> None:
        self.core = core
        self.stepper = stepper
        self.constants = {k: stepper.constant(k) for k in self.config_constants}
        self._check_variables(stepper.model.variables)
        names = list(stepper.model.variables)
        self.index = {n: names.index(n) for n in names}
        for op in self._ops_missing():
            raise AdapterError(f"the model has no operator {op} (adapter {type(self).__name__})")
        self._ops = stepper.definitions(self.observed_operators)

    def _ops_missing(self) -> list[str]:
        ops = list(self.observed_operators) + ([self.rows_operator] if self.rows_operator else [])
        return [op for op in ops if not self.stepper.has(op)]

    def _check_variables(self, variables: Iterable[str]) -> None:
        lists = (self.observed_variables, tuple(self.split_records), self.hidden_variables)
        claimed = [v for lst in lists for v in lst]
        model_vars = list(variables)
        dup = sorted({v for v in claimed if claimed.count(v) > 1})
        unknown = [v for v in claimed if v not in model_vars]
        unclaimed = [v for v in model_vars if v not in claimed]
        problems = []
        if unclaimed:
            problems.append(f"model variables neither compared nor hidden: {', '.join(unclaimed)}")
        if unknown:
            problems.append(f"adapter names variables the model lacks: {', '.join(unknown)}")
        if dup:
            problems.append(f"variables listed twice: {', '.join(dup)}")
        if problems:
            raise AdapterError(f"adapter {type(self).__name__}: " + "; ".join(problems))

    # ------------------------------------------------------------ projection
    def project(self, state: tuple) -> dict[str, Any]:
        """What `observe()` must return in model state `state`."""
        out: dict[str, Any] = {k: plain(state[self.index[k]]) for k in self.observed_variables}
        for var, fields in self.split_records.items():
            rec = state[self.index[var]].d  # type: ignore[union-attr]
            for key, field in fields:
                out[key] = plain(rec[field])
        for key, v in zip(self.observed_operators, self._ops(state)):
            out[key] = plain(v)
        return out

    def model_rows(self, state: tuple, event: Event) -> frozenset[str] | None:
        """The rows the model fires for `event` in `state` (None: not compared)."""
        if self.rows_operator is None:
            return None
        return frozenset(self.stepper.applied(self.rows_operator)(state, event.param()))  # type: ignore[arg-type]

    def config(self) -> Any:
        """The C++ Config for the model's constants."""
        return self.core.Config(**{self.config_constants[k]: v for k, v in self.constants.items()})

    def table_rows(self) -> list[str]:
        """Ids of every row of the C++ transition table (for the audit); none when the
        adapter compares no rows (a C++ without a row table, such as the state chain's)."""
        if self.rows_operator is None:
            return []
        return [r["id"] for r in self.core.transition_table()]

    # ------------------------------------------------------------------ code
    def new_sut(self) -> Any:
        raise NotImplementedError

    def apply(self, sut: Any, event: Event, before: tuple) -> Applied:
        raise NotImplementedError

    def observe(self, sut: Any) -> dict[str, Any]:
        return sut.observe()  # type: ignore[no-any-return]

    def input_alphabet(self, state: tuple) -> list[Probe]:
        """Every input vector to try from `state` in the input-complete pass."""
        raise NotImplementedError(f"{type(self).__name__} defines no input alphabet")

    def probe_batch(self, prefix: list[Event], probes: list[Probe]) -> list[tuple[dict[str, Any], frozenset[str]]]:
        """For each probe: a fresh C++ object brought to a state by the events `prefix`,
        then the probe's concrete input; (observe(), rows fired) per probe."""
        raise NotImplementedError(f"{type(self).__name__} defines no input alphabet")

    def fires_rows(self, event: Event) -> bool:
        """Whether `event` fires table rows (compared with `rows_operator`)."""
        return self.rows_operator is not None

    # ------------------------------------------- compact replay plan (optional)
    def expected_line(self, state: tuple) -> str:
        """The binding's canonical observe line for the model's projection of `state`
        (what its PlanReplayer compares after each step; conform/replay_plan.py)."""
        raise NotImplementedError

    def state_aux(self, state: tuple) -> int:
        """A small int the binding checks on the call that leaves `state` (e.g. 1: the
        model's queue is full, a submit must be refused).  Default 0."""
        return 0

    def plan_call(self, event: Event) -> Any:
        """The binding's PlanReplayer call for `event` (default: the event's parameter)."""
        return event.param()

    def plan_config(self) -> Any:
        """The leading argument of the binding's PlanReplayer (what builds a fresh object);
        a tuple is several leading arguments."""
        return self.config()

    def has_plan_replay(self) -> bool:
        """Whether the replay can run as a compact plan in the binding."""
        return type(self).expected_line is not Adapter.expected_line and hasattr(self.core, "PlanReplayer")

    def measurements(self) -> dict[str, Any]:
        """Figures the adapter measured on the C++ over the run (e.g. the Protection
        adapter's worst-case response in ticks), reported by `safestate conform`."""
        return {}

    def hypothesis_rules(self) -> type | None:
        """A mixin class of Hypothesis `@rule`s (see lockstep.py for the helpers it may use)."""
        return None


AdapterFactory = Callable[[ModuleType, ModelStepper], Adapter]
