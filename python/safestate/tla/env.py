"""Compile-time environments: frames of run-time slots and local bindings.

Compiled code has the signature ``f(s, t, L)``: `s` the current state (a tuple,
indexed by variable number), `t` the next state under construction (a list, or
None outside actions), `L` the frame (a list) holding bound variables.  A `Frame`
hands out slot numbers at compile time; each compiled unit (an operator body, an
invariant, Next) allocates ``[None] * frame.size`` per evaluation.
"""

from __future__ import annotations

from dataclasses import dataclass, field, replace
from typing import Any, Callable, Mapping

from . import ast as A
from .modules import Scope

Code = Callable[[Any, Any, list], Any]


class _Sentinel:
    __slots__ = ("name",)

    def __init__(self, name: str) -> None:
        self.name = name

    def __repr__(self) -> str:
        return self.name


UNSET = _Sentinel("UNSET")      # a next-state variable not yet assigned
NOTSET = _Sentinel("NOTSET")    # a LET definition not yet evaluated


class Frame:
    __slots__ = ("size",)

    def __init__(self) -> None:
        self.size = 0

    def alloc(self) -> int:
        self.size += 1
        return self.size - 1


@dataclass(eq=False)
class SlotLocal:
    """A bound variable or by-value operator argument stored in ``L[slot]``.

    `source` is the argument expression (and its environment) of an operator
    argument that reads state: priming the parameter primes that expression."""

    slot: int
    source: "tuple[A.Expr, Env] | None" = None


@dataclass(eq=False)
class LazyLocal:
    """A zero-argument LET definition, evaluated on first use into ``L[slot]``.

    `body` is the definition's body and its environment: in an action TLC expands a
    LET name used as a conjunct, so a disjunction inside it branches.  `source` is the
    same when the body reads state: priming the name primes that expression."""

    slot: int
    code: Code
    body: "tuple[A.Expr, Env] | None" = None
    reads_state: bool = False

    @property
    def source(self) -> "tuple[A.Expr, Env] | None":
        return self.body if self.reads_state else None


@dataclass(eq=False)
class LazyArgLocal(LazyLocal):
    """An operator argument passed unevaluated, as TLC passes it (a `LazyValue`): the
    body is expanded in the caller's frame, the call resets ``L[slot]`` to NOTSET and
    the body's first use evaluates the argument there (`compile/lazy_args.py`).
    `arg_source` is the argument and its environment when it reads state."""

    arg_source: "tuple[A.Expr, Env] | None" = None

    @property
    def source(self) -> "tuple[A.Expr, Env] | None":
        return self.arg_source


@dataclass(eq=False)
class ThunkLocal:
    """A parameter of a body compiled once and called with a frame of its own: ``L[slot]``
    holds the argument's value or a `Thunk` that computes it in the caller's context,
    replaced by its value at the first use (`compile/lazy_args.py`)."""

    slot: int


@dataclass(eq=False)
class ByNameLocal:
    """An argument substituted by name (action-level arguments, instance parameters)."""

    expr: A.Expr
    env: "Env"


@dataclass(eq=False)
class OpLocal:
    """A higher-order operator parameter; ``L[slot]`` holds a Python callable."""

    slot: int
    arity: int


@dataclass(eq=False)
class LetOpLocal:
    """A LET operator with parameters, sharing the enclosing frame."""

    defn: A.OpDef
    env: "Env"
    param_slots: list[int]
    holder: list  # [compiled body] once compiled


Local = SlotLocal | LazyLocal | ThunkLocal | ByNameLocal | OpLocal | LetOpLocal


@dataclass(eq=False)
class Env:
    scope: Scope
    frame: Frame
    locals: dict[str, Local] = field(default_factory=dict)
    # Compiling the initial predicate: unprimed variables are the state being built.
    init_mode: bool = False
    # Compiling the inside of ``e'``: variables (and operator arguments and LET
    # definitions that read them) denote their values in the next state `t`.
    primed: bool = False
    # Inside ENABLED: the ids of the INSTANCE substitutions (`SubstSym`) made before the
    # ENABLED was entered.  TLC's ENABLED starts a branch of its evaluation context and a
    # primed variable is looked up only up to that branch, so a primed variable whose
    # substitution lies outside is the instanced module's own variable, by name, in
    # ENABLED's scratch state (`NamesMixin.scratch_slot`).  Environments derived from
    # this one keep the set; those captured before the ENABLED (operator arguments) do not.
    enabled_cut: frozenset[int] = frozenset()

    def bind(self, /, **bindings: Local) -> "Env":  # positional-only: a TLA+ name may be `self`
        return replace(self, locals={**self.locals, **bindings})

    def bind_all(self, bindings: Mapping[str, Local]) -> "Env":
        return replace(self, locals={**self.locals, **bindings})
