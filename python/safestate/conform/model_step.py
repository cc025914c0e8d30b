"""The model side of a step: the successor of a concrete model state under one event,
computed by the checker (`Model.successors`), plus compiled evaluators of the
model's operators (outputs, rows) so that nothing is re-implemented here.

`successor()` enumerates the model's transitions from the state and keeps those
whose event matches: there must be exactly one (the model is deterministic per
event, and the event must be one the model allows in that state).
"""

from __future__ import annotations

import os
from typing import Any, Callable

from ..checker.model import Model
from ..tla import ast as A
from ..tla.actions import ActionCompiler
from ..tla.env import UNSET, Env, Frame, SlotLocal
from ..tla.parser import parse_text
from ..tla.values import Value
from .events import Event
from .native_step import NativeStepper, native_stepper

# $SAFESTATE_STEP_ENGINE=python: every step and operator in the Python evaluator (to compare).
STEP_ENGINE_ENV = "SAFESTATE_STEP_ENGINE"


class ModelStepError(Exception):
    """The event is not allowed in the state, or has several successors."""


class ModelStepper:
    """The model's steps and operators, computed by the native core where it takes the
    model (`native_step.py`: the same answers, in C++), else by the Python evaluator."""

    def __init__(self, model: Model) -> None:
        self.model = model
        self._defs: dict[str, Callable[[tuple], Value]] = {}
        self._applied: dict[str, Callable[[tuple, Value], Value]] = {}
        self.calls = 0
        self._actions: dict[tuple[str, tuple[str, ...]], Callable[[tuple, list], list[tuple]] | None] = {}
        self._edge_calls: dict[int, tuple[Event, Callable[[tuple, list], list[tuple]] | None, list]] = {}
        forced = os.environ.get(STEP_ENGINE_ENV) == "python"
        native = f"${STEP_ENGINE_ENV}=python" if forced else native_stepper(model)
        self.native: NativeStepper | None = None if isinstance(native, str) else native
        self.engine_note = "the native engine" if self.native else f"the Python engine ({native})"

    def transitions(self, state: tuple) -> list[tuple[Event, tuple]]:
        if self.native is not None:
            got = self.native.transitions(state)
            if got is not None:
                return got
        return [(Event.of(t.action, t.params), t.state) for t in self.model.successors(state)]

    def key(self, state: tuple) -> Any:
        """The model's key of `state` (its VIEW, if any: `Model.key`)."""
        if self.native is not None:
            got = self.native.view(state)
            if got is not None:
                return got[0]
        return self.model.key(state)

    def successor(self, state: tuple, event: Event) -> tuple:
        self.calls += 1
        found = [s for e, s in self.transitions(state) if e == event]
        if len(found) != 1:
            what = "no transition" if not found else f"{len(found)} transitions"
            raise ModelStepError(f"the model has {what} for event {event} in this state")
        return found[0]

    def edge_successor(self, state: tuple, event: Event) -> tuple:
        """The successor along a graph edge the checker already found: only that
        action is evaluated (its parameters bound to the edge's values), not the
        whole next-state relation.  Exactly one successor is still required."""
        self.calls += 1
        hit = self._edge_calls.get(id(event))
        if hit is None or hit[0] is not event:
            hit = self._edge_call(event)
        run, args = hit[1], hit[2]
        if run is None:
            return self.successor(state, event)
        found = run(state, args)
        if len(found) != 1:
            raise ModelStepError(f"action {event} has {len(found)} successors in this state")
        return found[0]

    def _edge_call(self, event: Event) -> tuple[Event, Callable[[tuple, list], list[tuple]] | None, list]:
        """(event, its action compiled, its arguments in call order), kept per event object
        (a graph's events are shared objects: a trace step finds its call by identity)."""
        names = tuple(k for k, _ in event.params)
        key = (event.action, names)
        if key not in self._actions:
            self._actions[key] = self._compile_action(event.action, names)
        values = dict(event.params)
        hit = (event, self._actions[key], [values[n] for n in self._call_order(event.action, names)])
        if len(self._edge_calls) > 100_000:
            self._edge_calls.clear()  # probe events are made afresh: do not keep them all
        self._edge_calls[id(event)] = hit
        return hit

    def _parse(self, text: str) -> A.Expr:
        mod = parse_text(f"---- MODULE __Conform ----\n__E == {text}\n====", "<conform>")[0]
        return mod.units[0].body  # type: ignore[union-attr]

    def _bound(self, names: tuple[str, ...]) -> tuple[Env, Frame, list[int]]:
        """An environment where `names` are bound variables stored in frame slots,
        so one compiled unit serves every parameter value."""
        frame = Frame()
        slots = [frame.alloc() for _ in names]
        env = Env(self.model.scope, frame).bind(**{n: SlotLocal(sl) for n, sl in zip(names, slots)})
        return env, frame, slots

    def _call_order(self, action: str, names: tuple[str, ...]) -> tuple[str, ...]:
        """The event's parameter names in the order of the action's formal parameters
        (an event keeps them sorted by name; Tick(t, v, ok, clr) must get them in order)."""
        if len(names) < 2:
            return names
        sym = self.model.scope.lookup(action)
        formals = tuple(p.name for p in getattr(getattr(sym, "defn", None), "params", ()))
        return formals if sorted(formals) == sorted(names) else ()

    def _compile_action(self, action: str, names: tuple[str, ...]) -> Callable[[tuple, list], list[tuple]] | None:
        """The action called with the event's parameters; None when they cannot be matched
        to its formal parameters by name (then the whole next-state relation is used)."""
        order = self._call_order(action, names)
        if len(order) != len(names):
            return None
        env, frame, slots = self._bound(order)
        body = self._parse(f"{action}({', '.join(order)})" if order else action)
        out: list[tuple] = []
        code = ActionCompiler(self.model.compiler).action(body, env, lambda s, t, L: out.append(tuple(t)))
        nvars = len(self.model.variables)
        native = self.native.action((action, names), body, order) if self.native else None

        def run(state: tuple, values: list) -> list[tuple]:
            if native is not None:
                got = self.native.run_action(native, state, values)  # type: ignore[union-attr]
                if got is not None:
                    return got
            out.clear()
            L: list = [None] * frame.size
            for sl, v in zip(slots, values):
                L[sl] = v
            code(state, [UNSET] * nvars, L)
            res = list(out)
            for st in res:
                self.model.check_complete(st, None)
            return res
        return run

    # ------------------------------------------------------------ operators
    def definition(self, name: str) -> Callable[[tuple], Value]:
        """A compiled evaluator of a zero-argument definition (or variable) `name`."""
        fn = self._defs.get(name)
        if fn is None:
            body = A.Name(self.model.module_loc(), name)
            ev = self.model.compiler.evaluator(body, self.model.scope)
            fn = self._defs[name] = self._native_first(name, body, (), lambda s, args: ev(s, None))
        return fn

    def definitions(self, names: tuple[str, ...]) -> Callable[[tuple], list[Value]]:
        """f(state) -> the values of the zero-argument definitions `names` (in one call
        to the core when it translates them all)."""
        each = [self.definition(n) for n in names]
        native = self.native
        compiled = [native.expression(n, A.Name(self.model.module_loc(), n), ()) for n in names] if native else []
        if native is None or not names or any(c is None for c in compiled):
            return lambda state: [f(state) for f in each]

        def fn(state: tuple) -> list[Value]:
            got = native.evaluate_all(compiled, state)  # type: ignore[arg-type]
            return got if got is not None else [f(state) for f in each]
        return fn

    def applied(self, op: str) -> Callable[[tuple, Value], Value]:
        """A compiled evaluator of `op(x)`, called as f(state, x)."""
        fn = self._applied.get(op)
        if fn is None:
            env, frame, (slot,) = self._bound(("__x",))
            body = self._parse(f"{op}(__x)")
            code = self.model.compiler.expr(body, env)

            def python(state: tuple, args: tuple) -> Value:
                L: list = [None] * frame.size
                L[slot] = args[0]
                return code(state, None, L)
            first = self._native_first(f"{op}(__x)", body, ("__x",), python)
            fn = self._applied[op] = first
        return fn

    def _native_first(self, key: str, body: A.Expr, names: tuple[str, ...],
                      python: Callable[[tuple, tuple], Value]) -> Callable[..., Value]:
        """f(state, *args): `body` (with `names` bound to args) evaluated by the core when
        it translates it and evaluates it without error, else by `python(state, args)`."""
        native = self.native.expression(key, body, names) if self.native else None
        if native is None:
            return lambda state, *args: python(state, args)
        evaluate = self.native.evaluate  # type: ignore[union-attr]

        def fn(state: tuple, *args: Value) -> Value:
            got = evaluate(native, state, list(args))
            return got[0] if got is not None else python(state, args)
        return fn

    def constant(self, name: str) -> Any:
        return self.model.eval_in_state(name, None)

    def has(self, name: str) -> bool:
        return self.model.scope.lookup(name) is not None
