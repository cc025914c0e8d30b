"""The model side of a conformance step evaluated by the native core (`checker/native/`).

`ModelStepper` asks this first and falls back to the Python evaluator wherever it
answers None: an action or operator the core does not translate (per action / per
operator, remembered), a value it cannot hold (a lazy set, a wide integer), or an
evaluation error inside the core (the Python evaluator then gives its located error,
or its answer).  So the results are the Python engine's, only computed in C++:
`transitions` lists the same events in the same order (the core runs Next in TLC's
order, as the graph search does), and states and values convert back to the same
Python values (`ValueBridge.to_python`, one object per value id).

States met here are kept as core ids too: a successor's ids are remembered with the
Python tuple made for it (one tuple per distinct state), so a trace's next step
starts from ids without converting the state back.
"""

from __future__ import annotations

from typing import Any

from ..checker.model import Model
from ..tla import ast as A
from ..tla.errors import TlaError, UnsupportedError
from ..tla.values import Value
from .events import Event
from .native_events import EventCache, prepare_run

# Identity caches are cleared past this many entries (probe events are made afresh).
_CACHE_LIMIT = 200_000
_NO_VIEW = 0xFFFFFFFF  # the core's "no VIEW" in a step's successors


class NativeStepper:
    def __init__(self, model: Model, run: Any, slots: list[list[int]]) -> None:
        from .. import _tla_native  # type: ignore[attr-defined]
        self.model = model
        self.run = run
        self.engine = run.engine
        self.engine.leaf_params = slots
        self.engine.set_slots(run.nslots)
        if run.view is not None:
            self.engine.set_view(run.view)  # each step's successors come with their VIEW
        self.bridge = run.bridge
        self.tr = run.translator
        self.events = EventCache(model, self.bridge)
        self.error = _tla_native.StepError
        self.loc = model.module_loc()
        self.calls = 0      # answered by the core
        self.fallbacks = 0  # handed back to the Python evaluator
        self._ids: dict[int, tuple[tuple, tuple[int, ...]]] = {}  # id(state) -> (state, ids)
        self._states: dict[tuple[int, ...], tuple] = {}           # ids -> the Python state
        self._values: dict[int, tuple[Value, int]] = {}           # id(value) -> (value, id)
        self._nodes: dict[Any, tuple | None] = {}                 # translated actions / operators
        self._views: dict[tuple[int, ...], int] = {}              # ids -> VIEW id (from the core's steps)

    # ------------------------------------------------------------ values
    def ids(self, state: tuple) -> tuple[int, ...] | None:
        """The core's ids of a Python state (None: a value the core cannot hold)."""
        hit = self._ids.get(id(state))
        if hit is not None and hit[0] is state:
            return hit[1]
        try:
            ids = tuple(self.value_id(v) for v in state)
        except UnsupportedError:
            return None
        self._remember(state, ids)
        return ids

    def value_id(self, v: Value) -> int:
        hit = self._values.get(id(v))
        if hit is not None and hit[0] is v:
            return hit[1]
        vid = self.bridge.to_native(v, self.loc)
        if len(self._values) > _CACHE_LIMIT:
            self._values.clear()
        self._values[id(v)] = (v, vid)
        return vid

    def state(self, ids: tuple[int, ...]) -> tuple:
        """The Python state of `ids` (the same tuple object each time)."""
        st = self._states.get(ids)
        if st is None:
            st = self._states[ids] = tuple(map(self.bridge.to_python, ids))
            self._remember(st, ids)
        return st

    def _remember(self, state: tuple, ids: tuple[int, ...]) -> None:
        if len(self._ids) > _CACHE_LIMIT:
            self._ids.clear()
        self._ids[id(state)] = (state, ids)

    # ------------------------------------------------------------ translation
    def _node(self, key: Any, translate: Any) -> tuple | None:
        """A translated program tree, once per key; None when the core refuses it."""
        if key in self._nodes:
            return self._nodes[key]
        try:
            node = translate()
        except (UnsupportedError, TlaError):
            node = None
        if node is not None:
            self.engine.set_slots(self.tr.nslots)  # room for the new tree's slots
        self._nodes[key] = node
        return node

    def _env(self, names: tuple[str, ...]) -> tuple[Any, list[int]]:
        from ..checker.native.translate import SlotArg, TEnv
        slots = [self.tr.alloc() for _ in names]
        return TEnv(self.model.scope, {n: SlotArg(sl, None) for n, sl in zip(names, slots)}), slots

    def action(self, key: Any, body: A.Expr, names: tuple[str, ...]) -> tuple | None:
        """(tree, slots): `body`, an action called with `names` bound, as the core runs it."""
        def translate() -> tuple:
            from ..checker.native.ops import Op
            env, slots = self._env(names)
            return self.tr.action(body, env, self.tr.node(Op.A_EMIT, body.loc, (-1,))), slots
        return self._node(("action", key, names), translate)

    def expression(self, key: Any, body: A.Expr, names: tuple[str, ...]) -> tuple | None:
        def translate() -> tuple:
            env, slots = self._env(names)
            return self.tr.expr(body, env), slots
        return self._node(("expr", key, names), translate)

    # ------------------------------------------------------------ evaluation
    def transitions(self, state: tuple) -> list[tuple[Event, tuple]] | None:
        if self.run.next is None:
            return self._fallback()
        out = self._call(self.engine.step, (self.run.next, []), state, [])
        if out is None:
            return None
        return [(self.events.event(leaf, params), self._successor(st, view)) for leaf, params, st, view in out]

    def _successor(self, ids: tuple[int, ...], view: int) -> tuple:
        if view != _NO_VIEW:
            self._views[ids] = view
        return self.state(ids)

    def run_action(self, compiled: tuple, state: tuple, values: list[Value]) -> list[tuple] | None:
        """The successors of `state` under an action from `action()`, its names bound to `values`."""
        out = self._call(self.engine.step, compiled, state, values)
        return None if out is None else [self._successor(st, view) for _, _, st, view in out]

    def evaluate(self, compiled: tuple, state: tuple, values: list[Value]) -> tuple[Value] | None:
        """(value,) of an expression from `expression()` in `state`, or None."""
        vid = self._call(self.engine.evaluate, compiled, state, values)
        return None if vid is None else (self.bridge.to_python(vid),)

    def _call(self, method: Any, compiled: tuple, state: tuple, values: list[Value]) -> Any:
        """The core's `method` (step / evaluate / evaluate_all) on its tree(s) in `state`
        with the slots bound to `values`; None (counted as a fallback) when a value or the
        evaluation fails."""
        node, slots = compiled
        binds = self._binds(state, slots, values)
        if binds is None:
            return self._fallback()
        try:
            out = method(node, binds[0], binds[1])
        except self.error:
            return self._fallback()
        self.calls += 1
        return out

    def evaluate_all(self, compiled: list[tuple], state: tuple) -> list[Value] | None:
        """Several zero-argument expressions from `expression()` in `state`, in one call."""
        vids = self._call(self.engine.evaluate_all, ([c[0] for c in compiled], []), state, [])
        return None if vids is None else list(map(self.bridge.to_python, vids))

    def view(self, state: tuple) -> tuple[Value] | None:
        """(the model's VIEW of `state`,) or None (no VIEW in the core, or an error); a
        successor's VIEW comes with the step that made it."""
        if self.run.view is None:
            return None
        ids = self.ids(state)
        vid = self._views.get(ids) if ids is not None else None
        if vid is not None:
            return (self.bridge.to_python(vid),)
        return self.evaluate((self.run.view, []), state, [])

    def _binds(self, state: tuple, slots: list[int], values: list[Value]) -> tuple | None:
        ids = self.ids(state)
        if ids is None:
            return None
        try:
            return ids, [(sl, self.value_id(v)) for sl, v in zip(slots, values)]
        except UnsupportedError:
            return None

    def _fallback(self) -> Any:
        self.fallbacks += 1
        return None


def native_stepper(model: Model) -> NativeStepper | str:
    """The core's stepper for `model`, or why the core does not take it."""
    try:
        prepared = prepare_run(model)
    except ImportError as e:
        return f"the native core is not built ({e})"
    return prepared if isinstance(prepared, str) else NativeStepper(model, *prepared)
