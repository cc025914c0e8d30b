"""``safestate check --engine native``: the breadth-first search in the C++ core.

`native_unsupported(model, ...)` says why a model cannot use the native engine (a
construct outside its subset, with file:line:col); `explore_native(model, ...)` runs
the search and returns the Python engine's `CheckResult`, with the same counts, depth
and trace (the trace's states are converted back to Python values and the actions'
parameters found by replaying the step with the Python evaluator, as the Python
engine does).  An evaluation error inside the core returns None: the caller checks
the model again with the Python engine, which reports TLC's exact error.
"""

from __future__ import annotations

import time
from typing import Any, Callable, cast

from ...tla import ast as A
from ...tla.errors import TlaError, UnsupportedError
from ...tla.tlcget import RUNTIME
from ...tla.values import exact_key, register_token_order
from ..explore import RUNNING, CheckResult, Explorer, Step, default_memory_limit_mb, step_params
from ..model import Model
from .ops import Op
from .printing import lazily_printed
from .translate import TEnv, Translator, unsupported
from .values import NOT_NATIVE, ValueBridge, known_string_ranks


class NativeRun:
    """A model translated for the C++ core, ready to search."""

    def __init__(self, model: Model) -> None:
        from ... import _tla_native
        self.m = model
        self.engine = _tla_native.Engine()
        self.engine.nvars = len(model.variables)
        self.bridge = ValueBridge(self.engine)
        _refuse_model(model)
        try:
            self._translate(model)
        except RecursionError:
            # A chain of a thousand definitions nests the translation as deep: refused,
            # and the Python engine (which runs on a deep stack) checks the model.
            raise UnsupportedError(f"definitions nested this deep are {NOT_NATIVE}", model.module_loc()) from None

    def _translate(self, model: Model) -> None:
        tr = Translator(model, self.bridge)
        scope = model.scope
        init = next_ = None
        if model.init_expr is not None and model.next_expr is not None:
            init = tr.action(model.init_expr, TEnv(scope, {}, init=True), tr.node(Op.A_EMIT, model.init_expr.loc, (-1,)))
            next_ = tr.split(model.next_expr, TEnv(scope, {}))
            if tr.leaves != len(model.leaves):
                raise UnsupportedError(f"the next-state relation splits into {tr.leaves} actions here and "
                                       f"{len(model.leaves)} in the Python engine: {NOT_NATIVE}",
                                       model.next_expr.loc)
        cfg = model.config
        self.invariants = [tr.expr(A.Name(e.loc, e.name), TEnv(scope, {})) for e in cfg.invariants]
        self.constraints = [tr.expr(A.Name(e.loc, e.name), TEnv(scope, {})) for e in cfg.constraints]
        self.action_constraints = [tr.expr(A.Name(e.loc, e.name), TEnv(scope, {})) for e in cfg.action_constraints]
        self.view = tr.expr(A.Name(cfg.view.loc, cfg.view.name), TEnv(scope, {})) if cfg.view else None
        self.init, self.next = init, next_
        self.nslots = tr.nslots
        self.leaf_params = tr.leaf_params  # per leaf: (name, slot) of its parameters
        self.translator = tr  # more trees for the same engine (conform/native_step.py)
        lazy, self.rule_sets = lazily_printed(
            tr.const_flags, len(model.variables),
            [init, next_, *self.invariants, *self.constraints, *self.action_constraints, self.view])
        if lazy:
            raise unsupported("ToString of a value that may be or hold a set TLC prints as a rule (1..3, [a : S])",
                              tr.locs[lazy[0][1]])


def _refuse_model(model: Model) -> None:
    """Features of a model (not of an expression) the core does not have."""
    cfg = model.config
    loc = model.module_loc()
    if cfg.properties:
        raise unsupported(f"PROPERTY {cfg.properties[0].name} (temporal properties)", cfg.properties[0].loc)
    for what, entry in (("SYMMETRY", cfg.symmetry), ("POSTCONDITION", cfg.postcondition)):
        if entry is not None:
            raise unsupported(what, entry.loc)
    if RUNTIME.used:
        raise unsupported("TLCGet/TLCSet", loc)
    if model.init_expr is None or model.next_expr is None:
        raise unsupported("a model without Init and Next", loc)


def native_unsupported(model: Model) -> UnsupportedError | None:
    """Why the native engine cannot check `model` (None if it can)."""
    try:
        NativeRun(model)
    except UnsupportedError as e:
        return e
    return None


def explore_native(model: Model, max_memory_mb: int | None = None,
                   progress: Callable[[str], None] | None = None,
                   run: NativeRun | None = None, workers: int = 1) -> tuple[CheckResult | None, str]:
    """Search with the C++ core (`run`: the model already translated) with `workers`
    threads, whose result is the one worker's (counts, depth, trace).  Returns
    (result, "") or (None, why) after an evaluation error, which the Python engine
    then reports exactly."""
    start = time.monotonic()
    run = run or NativeRun(model)
    eng = run.engine
    eng.set_slots(run.nslots)
    eng.workers = workers
    limit = max_memory_mb or default_memory_limit_mb()

    def report(level: int, generated: int, distinct: int, left: int) -> None:
        if progress is not None and level < 0:
            progress(f"Finished computing initial states: {distinct} distinct state{'' if distinct == 1 else 's'} "
                     f"generated.")
        elif progress is not None:
            progress(f"Progress({level}): {generated} states generated, {distinct} distinct states found, "
                     f"{left} states left on queue.")
    if progress is not None:
        progress("Computing initial states...")
    eng.set_known_ranks(known_string_ranks())
    if run.view is not None:
        eng.set_view(run.view)
    eng.configure(run.init, run.next, run.invariants, run.constraints, run.action_constraints,
                  model.check_deadlock, limit, report)
    cpu_start = time.process_time()
    RUNNING[:] = [cast(Explorer, _SoFar(eng))]  # Ctrl-C during eng.run(): the CLI reports these counts
    eng.run()
    register_token_order(eng.made_strings())  # ranked as the core ranked them, after the spec's
    result = _result(run, limit)
    if result is not None:
        result.seconds = time.monotonic() - start
        if workers > 1:
            result.parallel = _cpu_report(workers, list(eng.worker_cpu), eng.critical_cpu,
                                          time.process_time() - cpu_start)
    return result, eng.error


class _SoFar:
    """The core's counts while it searches, as `explore.counts_so_far` reads an Explorer's."""

    states: tuple = ()

    def __init__(self, eng: Any) -> None:
        self.eng = eng

    @property
    def distinct_so_far(self) -> int:
        return int(self.eng.distinct)

    @property
    def generated(self) -> int:
        return int(self.eng.generated)

    @property
    def max_level(self) -> int:
        return int(self.eng.depth)

    @property
    def head(self) -> int:
        return int(self.eng.head)


def _cpu_report(workers: int, worker_cpu: list[float], critical_cpu: float, run_cpu: float) -> dict:
    """`--json`'s "parallel", as the Python engine's (parallel.py): the threads' CPU in
    the levels they searched together, the rest (initial states, barriers, a level
    searched again by one worker) as the coordinator's."""
    coordinator = run_cpu - sum(worker_cpu)
    return {"workers": workers, "worker_cpu_seconds": [round(c, 3) for c in worker_cpu],
            "coordinator_cpu_seconds": round(coordinator, 3),
            "critical_path_cpu_seconds": round(coordinator + critical_cpu, 3)}


def _result(run: NativeRun, limit_mb: int) -> CheckResult | None:
    eng, m = run.engine, run.m
    n, gen, head = eng.distinct, eng.generated, eng.head
    depth = eng.depth if gen else 0
    if eng.result == "error":
        return None
    if eng.result == "success":
        return CheckResult("success", n, gen, depth, 0)
    if eng.result == "memory":
        err = TlaError("memory", f"memory limit of {limit_mb} MB exceeded after {n} distinct states; "
                       f"raise it with --max-memory or add a state constraint")
        return CheckResult("error", n, gen, eng.depth, n - head, error=err)
    if eng.result == "deadlock failure":
        return CheckResult("deadlock failure", n, gen, depth, n - head - 1, None, _trace(run, eng.trace_to))
    name = m.config.invariants[eng.violated].name
    if eng.initial_violation:
        if eng.trace_to >= 0:
            return CheckResult("safety failure", n, gen, depth, n, name, _trace(run, eng.trace_to),
                               initial_violation=True)
        first = run.bridge.state(eng.extra)
        if run.rule_sets:
            first = _python_step(m, None, -1, first)[0]
        return CheckResult("safety failure", n, gen, 1, n, name, [Step(first, "Init", {})], initial_violation=True)
    if not eng.extra:
        return CheckResult("safety failure", n, gen, depth, n - head - 2, name, _trace(run, eng.trace_to))
    trace = _trace(run, eng.trace_to)
    st = run.bridge.state(eng.extra)
    leaf = eng.extra_leaf
    if run.rule_sets:
        st, params = _python_step(m, trace[-1].state, leaf, st)
    else:
        params = step_params(m, trace[-1].state, leaf, st)
    trace.append(Step(st, m.leaves[leaf].name, params))
    return CheckResult("safety failure", n, gen, depth, n - head - 1, name, trace)


def _trace(run: NativeRun, idx: int) -> list[Step]:
    eng, m = run.engine, run.m
    path = []
    while idx >= 0:
        path.append(idx)
        idx = eng.parent(idx)
    path.reverse()
    states = [run.bridge.state(eng.state(i)) for i in path]
    if run.rule_sets:
        return _python_trace(m, states, [eng.leaf(i) for i in path[1:]])
    steps = [Step(states[0], "Init", {})]
    for a, b, i in zip(states, states[1:], path[1:]):
        leaf = eng.leaf(i)
        steps.append(Step(b, m.leaves[leaf].name, step_params(m, a, leaf, b)))
    return steps


class _Found(Exception):
    pass


def _python_trace(m: Model, states: list[tuple], leaves: list[int]) -> list[Step]:
    """The trace with each state as the Python engine holds it: the core keeps ``1..3``
    as its elements, TLC (and the Python engine) print it as ``1..3``."""
    steps = [Step(_python_step(m, None, -1, states[0])[0], "Init", {})]
    for want, leaf in zip(states[1:], leaves):
        st, params = _python_step(m, steps[-1].state, leaf, want)
        steps.append(Step(st, m.leaves[leaf].name, params))
    return steps


def _python_step(m: Model, prev: tuple | None, leaf: int, want: tuple) -> tuple[tuple, dict]:
    """`want` as the Python engine holds it, found again among its initial states (prev
    None) or the successors of `prev` by action `leaf` (by TLA+ equality: TRUE is not
    1), with the step's parameters."""
    key = exact_key(want)
    got: list[tuple[tuple, dict]] = []

    def match(st: tuple, lf: int, L: list) -> None:
        if (prev is None or lf == leaf) and st == want and exact_key(st) == key:
            got.append((st, m.leaf_params(lf, L) if prev is not None else {}))
            raise _Found()
    try:
        if prev is None:
            m.run_init(match)
        else:
            m.run_next(prev, match)
    except _Found:
        return got[0]
    return want, {}
