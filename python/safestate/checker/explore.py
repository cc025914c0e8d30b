"""Breadth-first exploration of a model's state space with TLC's counting rules.

`explore_states(model, workers=1, ...) -> CheckResult` reproduces TLC's
single-worker breadth-first search exactly:

* "states generated" counts every initial state and every successor produced by
  the next-state relation, duplicates and constraint-violating states included;
* a state is "distinct" when its fingerprint (the state, or its VIEW, reduced by
  SYMMETRY) is new and it satisfies the state and action constraints;
* invariants are checked on every new state and on every constraint-violating
  successor (as TLC does), in generation order; the search stops at the first
  violation, so the reported counts are those at that moment;
* a state without any successor (constraint-violating ones count) is a deadlock;
* depth is the number of BFS levels reached (initial states are level 1).

Deduplication uses the exact states (a Python dict), not 64-bit fingerprints, so
no state can be lost to a fingerprint collision (probability 0).  Python's ``True ==
1`` would make the states x = 1 and x = TRUE one: a state found in the dict is checked
to be the same TLA+ state (`values.same_kinds`, cheap), and the rare states that only
Python finds equal get entries of their own, keyed by `values.exact_key`
(`Explorer._resolve`).

With ``workers > 1`` the fingerprint space is sharded over forked worker processes
(`parallel.py`, `shard_worker.py`); every count, verdict and trace is identical for
any number of workers.  Liveness, --graph and TLCGet need one search in one process:
they use one worker (said on stderr).
"""

from __future__ import annotations

import sys
import time
from array import array
from itertools import compress
from operator import is_not
from dataclasses import dataclass, field
from typing import Any, Callable

from ..tla.enum_watch import ENUM_WATCH, MemoryLimitExceeded, rss_mb
from ..tla.errors import EvalError, JavaOverrideError, ModuleEvalError, TlaError
from ..tla.modules import DefSym
from ..tla.tlcget import RUNTIME
from ..tla.values import CONTAINER_TYPES, exact_key, same_kinds
from ..errors import UsageError
from .model import Model
from .deep_stack import call_with_deep_stack, stack_overflow_message

PROGRESS_SECONDS = 5.0


@dataclass
class Step:
    state: tuple
    action: str
    params: dict


@dataclass
class Edge:
    src: int
    dst: int
    action: str
    params: dict


@dataclass
class CheckResult:
    result: str  # "success" | "safety failure" | "deadlock failure" | "error"
    distinct_states: int
    states_generated: int
    depth: int
    left_on_queue: int
    violated: str | None = None
    trace: list[Step] | None = None
    error: TlaError | None = None
    seconds: float = 0.0
    # True when the violation is in an initial state (TLC prints no statistics then).
    initial_violation: bool = False
    # Filled when explore_states(..., graph=True).
    states: list[tuple] | None = None
    initial: list[int] | None = None
    edges: list[Edge] | None = None
    warnings: list[str] = field(default_factory=list)
    # A liveness counterexample is a lasso: after the last state of `trace` the
    # behaviour takes `loop_step` back to trace[loop], or stutters forever when
    # `loop_step` is None.
    loop: int | None = None
    loop_step: Step | None = None
    # Every property the liveness counterexample violates, in .cfg order (TLC names them all).
    violated_properties: list[str] | None = None
    # With several workers: their CPU seconds and the critical path's (see parallel.py).
    parallel: dict | None = None


class _Found(Exception):
    """Ends the replay of a state's successors in `step_params`."""


class _Stop(Exception):
    """Ends the search: a violation, a deadlock or an error was recorded."""


# Values every state can hold: a state of these only needs no fingerprint check.
_PLAIN = frozenset((int, str, bool))


def step_params(m: Model, state: tuple, leaf: int, want: tuple) -> dict:
    """The parameters of the step `state` -> `want` by action `leaf`: the successors
    are generated again up to that step only, so an action after it that fails to
    evaluate (TLC never got there) cannot turn a violation into an error."""
    found: list[dict] = []

    def match(st: tuple, lf: int, L: list) -> None:
        if lf == leaf and st == want:
            found.append(m.leaf_params(lf, L))
            raise _Found()
    try:
        m.run_next(state, match)
    except _Found:
        return found[0]
    return {}


def default_memory_limit_mb() -> int:
    try:
        with open("/proc/meminfo") as f:
            for line in f:
                if line.startswith("MemTotal:"):
                    return int(int(line.split()[1]) / 1024 * 0.7)
    except OSError:
        pass
    return 8192


class Explorer:
    def __init__(self, model: Model, graph: bool, max_memory_mb: int | None,
                 progress: Callable[[str], None] | None) -> None:
        self.m = model
        self.graph = graph
        self.max_memory_mb = max_memory_mb or default_memory_limit_mb()
        self.progress = progress
        self.states: list[tuple] = []
        self.parent = array("q")
        self.leaf = array("i")
        self.level = array("i")
        self.seen: dict[Any, int] = {}
        # The key of each state when it is not the state (VIEW, SYMMETRY), and the states
        # Python alone finds equal to an earlier one, by `exact_key` (see the docstring).
        self.keys: list | None = [] if (model.view is not None or model.symmetry is not None) else None
        self.exact_seen: dict[Any, int] = {}
        self.generated = 0
        self.max_level = 0
        self.edges: list[Edge] = []
        self.initial: list[int] = []
        self.outcome: CheckResult | None = None
        self.next_check = 0
        self.last_progress = time.monotonic()
        self.head = 0
        self.computing_init = False
        # The graph's steps as state ids, kept for liveness checking (compact arrays).
        self.live_edges = bool(model.liveness)
        self.edge_src = array("i")
        self.edge_dst = array("i")
        # With liveness, once state i is expanded: the states generated and distinct (TLC's
        # counts where it stops at a temporal property's finite counterexample,
        # `tableau_safety.py`, or at an error its per-state liveness check meets,
        # `_at_tlc_liveness_error`).
        self.generated_after = array("q")
        self.distinct_after = array("q")
        # The successor whose CONSTRAINT or ACTION_CONSTRAINT failed to evaluate.
        self.failed_successor: Step | None = None
        # States TLC adds to its state set but not to its queue after an error
        # (`_replay_for_call_stack`).
        self.unqueued = 0

    # ---------------------------------------------------------------- bookkeeping
    def _resolve(self, key: Any, idx: int) -> int:
        """The state with `key` given that Python finds it equal to state `idx`'s key:
        `idx` if it is the same TLA+ value, else its own entry (-1 if new)."""
        stored = self.states[idx] if self.keys is None else self.keys[idx]
        if same_kinds(key, stored):
            return idx
        ek = exact_key(key)
        if ek == exact_key(stored):
            return idx
        return self.exact_seen.get(ek, -1)

    def _add(self, st: tuple, key: Any, parent: int, leaf: int, level: int) -> int:
        idx = len(self.states)
        if key in self.seen:
            self.exact_seen[exact_key(key)] = idx
        else:
            self.seen[key] = idx
        if self.keys is not None:
            self.keys.append(key)
        self.states.append(st)
        self.parent.append(parent)
        self.leaf.append(leaf)
        self.level.append(level)
        if level > self.max_level:
            self.max_level = level
        if idx >= self.next_check:
            self.next_check = idx + 20000
            self._periodic()
        return idx

    def _periodic(self) -> None:
        if rss_mb() > self.max_memory_mb:
            raise MemoryLimitExceeded()
        now = time.monotonic()
        if self.progress is not None and now - self.last_progress >= PROGRESS_SECONDS:
            self.last_progress = now
            self.progress(f"Progress({self.max_level}): {self.generated} states generated, "
                          f"{len(self.states)} distinct states found, "
                          f"{len(self.states) - self.head} states left on queue.")

    def _finish(self, result: str, violated: str | None = None, trace_to: int | None = None,
                extra: Step | None = None, error: TlaError | None = None, initial: bool = False) -> None:
        trace = None
        if trace_to is not None:
            trace = self.trace(trace_to)
            if extra is not None:
                trace.append(extra)
        left = len(self.states) - self.head - self.unqueued
        if not initial:
            # As TLC's queue: the state being expanded (`self.head`) has been dequeued,
            # and a new successor violating an invariant is never enqueued.
            left -= 1
            if result in ("safety failure", "action property failure", "error") and extra is None:
                left -= 1
        self.outcome = CheckResult(result, len(self.states), self.generated,
                                   self.max_level if self.generated else 0,
                                   left, violated, trace, error,
                                   initial_violation=initial)
        raise _Stop()

    def trace(self, idx: int) -> list[Step]:
        """The path from an initial state to state `idx`, with the actions taken."""
        path = []
        while idx >= 0:
            path.append(idx)
            idx = self.parent[idx]
        path.reverse()
        steps = [Step(self.states[path[0]], "Init", {})]
        for a, b in zip(path, path[1:]):
            want, leaf = self.states[b], self.leaf[b]
            steps.append(Step(want, self.m.leaves[leaf].name, step_params(self.m, self.states[a], leaf, want)))
        return steps

    # ---------------------------------------------------------------- search
    def run(self) -> CheckResult:
        if RUNTIME.used:
            RUNTIME.search = self
        ENUM_WATCH.arm(self.max_memory_mb, self.progress)
        try:
            try:
                self._initial_states()
                self._expand_all()
            except _Stop:
                pass
            except MemoryLimitExceeded as over:
                detail = f" ({over.where})" if over.where else ""
                where = (f"while computing the initial states{detail}" if self.computing_init
                         else f"after {len(self.states)} distinct states{detail}")
                err = TlaError("memory", f"memory limit of {self.max_memory_mb} MB exceeded {where}; "
                               f"raise it with --max-memory or add a state constraint")
                self.outcome = CheckResult("error", len(self.states), self.generated, self.max_level,
                                           len(self.states) - self.head, error=err)
        except RecursionError:
            # TLC: "This was a Java StackOverflowError" (a recursion that does not end).
            msg = stack_overflow_message("computing states")
            # TLC exits with 75 when this happens in Init, with 255 (a system error) after.
            e = EvalError(msg) if not self.states else TlaError("stack overflow", msg)
            self.outcome = CheckResult("error", len(self.states), self.generated,
                                       self.max_level if self.generated else 0,
                                       len(self.states) - self.head, error=e)
        except TlaError as e:
            # An evaluation error while computing Init or successors.
            self.outcome = CheckResult("error", len(self.states), self.generated,
                                       self.max_level if self.generated else 0,
                                       len(self.states) - self.head, error=e)
        finally:
            ENUM_WATCH.disarm()
        if self.outcome is None:
            self.outcome = CheckResult("success", len(self.states), self.generated,
                                       self.max_level if self.generated else 0, 0)
        if self.graph:
            self.outcome.states = self.states
            self.outcome.initial = self.initial
            self.outcome.edges = self.edges
        return self.outcome

    def _initial_states(self) -> None:
        """Init's states, with TLC's progress lines around them (it can take long)."""
        if self.progress is not None:
            self.progress("Computing initial states...")
        self.computing_init = True
        self.m.run_init(self._on_init)
        self.computing_init = False
        if self.progress is not None:
            self.progress(f"Finished computing initial states: {len(self.states)} distinct "
                          f"state{'' if len(self.states) == 1 else 's'} generated.")

    def _on_init(self, st: tuple, leaf: int, L: list) -> None:
        m = self.m
        self.generated += 1
        if self.generated % 20000 == 0:
            # Duplicates and states outside the constraints add nothing, so _add's check
            # would not run: the memory limit and progress are checked here as well.
            ENUM_WATCH.check("the initial states", self.generated)
        m.check_complete(st, None)
        new = True
        idx = -1
        if RUNTIME.used:
            RUNTIME.level = 1
        if m.in_model(st):
            key = m.key(st)
            found = self.seen.get(key)
            if found is not None:
                found = self._resolve(key, found)
            if found is None or found < 0:
                if not _PLAIN.issuperset(map(type, st)):
                    m.check_storable(key if m.view is not None else st, None)
                idx = self._add(st, key, -1, -1, 1)
                self.initial.append(idx)
            else:
                new = False
        if new:
            for inv in m.invariants:
                if not self._invariant_holds(inv, st, idx, -1, -1, L):
                    if idx >= 0:
                        self._finish("safety failure", inv.name, idx, initial=True)
                    self.outcome = CheckResult("safety failure", len(self.states), self.generated, 1,
                                               len(self.states), inv.name, [Step(st, "Init", {})],
                                               initial_violation=True)
                    raise _Stop()
            for prop in m.init_properties:
                if not m.holds(prop, st):
                    self.outcome = CheckResult("init property failure", len(self.states), self.generated, 1,
                                               len(self.states), prop.name, [Step(st, "Init", {})],
                                               initial_violation=True)
                    raise _Stop()

    def _invariant_holds(self, inv: Any, st: tuple, idx: int, parent: int, leaf: int, L: list) -> bool:
        """`inv` on the new state `st` (stored at `idx`, or a successor of `parent` that
        a constraint excluded).  An evaluation error (a failed Assert too) is TLC's
        "Evaluating invariant Inv failed" (exit 76), with the trace up to `st`."""
        try:
            return self.m.holds(inv, st)
        except TlaError as e:
            if not (isinstance(e, EvalError) or e.kind in ("eval", "assert")):
                raise
            if parent < 0:
                # In an initial state TLC reports the error itself (exit 75), with statistics.
                err = TlaError("eval", f"{e.message}\nWhile working on the initial state", e.loc)
                self.outcome = CheckResult("error", len(self.states), self.generated, 1,
                                           len(self.states) - self.head, None, [Step(st, "Init", {})], err)
                raise _Stop() from None  # ends the search; the error is in self.outcome
            err = TlaError("invariant eval", f"Evaluating invariant {inv.name} failed.\n{e.message}", e.loc)
            if self._replay_for_call_stack(parent):
                err.kind = "invariant eval, replay failed"
            if idx >= 0:
                self._finish("error", None, idx, error=err)
            lf = self.m.leaves[leaf]
            self._finish("error", None, parent, Step(st, lf.name, self.m.leaf_params(leaf, L)), error=err)
            raise  # not reached: _finish raises _Stop

    def _replay_for_call_stack(self, parent: int) -> bool:
        """What TLC 1.8.0 does after an invariant failed to evaluate in a successor of
        `parent`, to print the error's call stack: it generates the successors of
        `parent` again (ModelChecker.doNext with a CallStackTool and a worker whose
        counts are not reported).  Each new one among them joins the state set and, if
        its invariants and action properties hold, the queue; the generated count stays.
        The replay stops at the first step that violates one, or that fails to evaluate:
        then TLC prints where that second error occurred and exits with 75, not 76
        (returned True)."""
        m = self.m
        cur = self.states[parent]
        level = self.level[parent] + 1
        keyed = m.view is not None or m.symmetry is not None
        constrained = bool(m.constraints or m.action_constraints)

        class _Done(Exception):
            pass

        def on_succ(st: tuple, leaf: int, L: list) -> None:
            if _UNSET in st:
                raise _Done()  # TLC: a state not completely specified ends the replay
            in_model = not constrained or (m.in_model(st) and m.action_ok(cur, st))
            new = True  # as TLC: a successor outside the constraints has its invariants checked
            if in_model:
                key = m.key(st) if keyed else st
                idx = self.seen.get(key, -1)
                if idx >= 0:
                    idx = self._resolve(key, idx)
                new = idx < 0
                if new:
                    self._add(st, key, parent, leaf, level)
            added = int(new and in_model)
            try:
                holds = not new or all(m.holds(inv, st) for inv in m.invariants)
                holds = holds and all(m.holds(prop, cur, st) for prop in m.action_properties)
            except TlaError:
                self.unqueued += added
                raise
            if not holds:
                self.unqueued += added
                raise _Done()
        try:
            m.run_next(cur, on_succ)
        except _Done:
            pass
        except TlaError:
            return True
        return False

    def _expand_all(self) -> None:
        while self.head < len(self.states):
            self.expand(self.head)
            if self.live_edges:
                self.generated_after.append(self.generated)
                self.distinct_after.append(len(self.states))
            self.head += 1

    def expand(self, i: int) -> None:
        """Generate the successors of state `i` in TLC order, counting as TLC does."""
        m = self.m
        cur = self.states[i]
        next_level = self.level[i] + 1
        before = self.generated
        seen_get = self.seen.get
        resolve = self._resolve
        states, keys, same_kinds_, containers = self.states, self.keys, same_kinds, CONTAINER_TYPES
        invariants = m.invariants
        constrained = bool(m.constraints or m.action_constraints)
        keyed = m.view is not None or m.symmetry is not None
        graph = self.graph
        action_properties = m.action_properties
        UNSET_ = _UNSET
        plain = _PLAIN.issuperset
        runtime = RUNTIME if RUNTIME.used else None
        if runtime is not None:
            runtime.expanding, runtime.level = 1, next_level - 1

        def on_succ(st: tuple, leaf: int, L: list) -> None:
            self.generated += 1
            if UNSET_ in st:
                m.check_complete(st, leaf)
            if runtime is not None:
                runtime.level = next_level
            in_model = True
            if constrained:
                try:
                    in_model = m.in_model(st) and m.action_ok(cur, st)
                except TlaError:
                    # TLC's trace of an error in a constraint ends with this successor.
                    self.failed_successor = Step(st, m.leaves[leaf].name, m.leaf_params(leaf, L))
                    raise
            new = True
            idx = -1
            if in_model:
                key = m.key(st) if keyed else st
                idx = seen_get(key, -1)
                if idx >= 0:
                    if keys is None:
                        # same_kinds(key, stored), inlined for the state tuple (the hot path)
                        stored = states[idx]
                        for x, y in compress(zip(key, stored), map(is_not, key, stored)):
                            tx = type(x)
                            if tx is not type(y) or (tx in containers and not same_kinds_(x, y)):
                                idx = resolve(key, idx)
                                break
                    elif not same_kinds_(key, keys[idx]):
                        idx = resolve(key, idx)
                if idx < 0:
                    if not plain(map(type, st)):
                        m.check_storable(key if keyed and m.view is not None else st, leaf)
                    idx = self._add(st, key, i, leaf, next_level)
                    if runtime is not None:
                        runtime.pending = 1
                else:
                    new = False
            if self.live_edges and in_model:
                self.edge_src.append(i)
                self.edge_dst.append(idx)
            if graph and in_model:
                self.edges.append(Edge(i, idx, m.leaves[leaf].name, m.leaf_params(leaf, L)))
            if new:
                for inv in invariants:
                    if not self._invariant_holds(inv, st, idx, i, leaf, L):
                        if idx >= 0:
                            self._finish("safety failure", inv.name, idx)
                        lf = m.leaves[leaf]
                        self._finish("safety failure", inv.name, i, Step(st, lf.name, m.leaf_params(leaf, L)))
            if action_properties:
                self._check_action_properties(i, cur, st, idx if new else -1, leaf, lambda: m.leaf_params(leaf, L))
            if runtime is not None:
                runtime.pending, runtime.level = 0, next_level - 1
        try:
            m.run_next(cur, on_succ)
        except TlaError as e:
            if isinstance(e, ModuleEvalError) or (isinstance(e, JavaOverrideError) and self._fairness_fails(cur)):
                e.kind = "module eval"  # TLC: the module's own error code, exit 255
            if isinstance(e, EvalError) or e.kind == "eval":
                trace = self.trace(i)
                if self.failed_successor is not None:
                    trace.append(self.failed_successor)
                self.outcome = CheckResult("error", len(self.states), self.generated, self.max_level,
                                           len(self.states) - self.head - 1, error=e, trace=trace)
                raise _Stop() from None
            raise
        if self.generated == before and m.check_deadlock:
            self._finish("deadlock failure", None, i)

    def _fairness_fails(self, cur: tuple) -> bool:
        """Whether TLC's liveness check fails on `cur` too: TLC 1.8.0 evaluates the
        fairness conditions' ENABLED on a state even after its successors failed to
        evaluate (Worker.doNextCheckLiveness); meeting an error there again, it keeps the
        first error's code, which for a Java exception is 255, instead of replaying the
        error for its call stack (exit 75)."""
        if not self.m.liveness:
            return False
        for fair in self.m.fairness:
            try:
                fair.enabled(cur)
            except TlaError:
                return True
        return False

    def _check_action_properties(self, i: int, cur: tuple, st: tuple, added: int, leaf: int,
                                 params: Callable[[], dict]) -> None:
        """TLC checks [][A]_v properties on every step, seen and constraint-violating ones too.
        `added` is the id of `st` if this step added it to the graph (it is not queued then)."""
        for prop in self.m.action_properties:
            if not self.m.holds(prop, cur, st):
                if added >= 0:
                    self._finish("action property failure", prop.name, added)
                self._finish("action property failure", prop.name, i, Step(st, self.m.leaves[leaf].name, params()))


from ..tla.env import UNSET as _UNSET  # noqa: E402


def explore_states(model: Model, workers: int = 1, graph: bool = False, max_memory_mb: int | None = None,
                   progress: Callable[[str], None] | None = None, ray: Any = None) -> CheckResult:
    """Explore every reachable state; see the module docstring for the semantics.
    `ray`: a `distributed.ray_search.RayTarget`, the search sharded over Ray actors."""
    start = time.monotonic()
    if workers > 1 or ray is not None:
        reason = _needs_one_worker(model, graph)
        if reason and ray is not None:
            raise UsageError(f"--ray: {reason}, which a search sharded over a cluster does not have")
        if reason:
            print(f"safestate check: {reason}; using one worker", file=sys.stderr, flush=True)
            workers = 1
    if ray is not None:
        from ..distributed.ray_search import RayExplorer
        explorer: Explorer = RayExplorer(model, graph, max_memory_mb, progress, workers, ray)
    elif workers > 1:
        from .parallel import ParallelExplorer
        explorer = ParallelExplorer(model, graph, max_memory_mb, progress, workers)
    else:
        explorer = Explorer(model, graph, max_memory_mb, progress)
    cpu_start = time.process_time()
    RUNNING[:] = [explorer]
    result = call_with_deep_stack(explorer.run)
    if workers > 1 or ray is not None:
        result.parallel = explorer.cpu_report(time.process_time() - cpu_start)  # type: ignore[attr-defined]
    if result.result == "success" and model.liveness:
        from .liveness_run import check_liveness
        call_with_deep_stack(lambda: check_liveness(model, explorer, result))
        if result.result == "error":
            _at_tlc_liveness_error(model, explorer, result)
    elif model.liveness:
        from .liveness_run import stop_before_safety_failure
        call_with_deep_stack(lambda: stop_before_safety_failure(model, explorer, result))
    if result.result == "success" and model.postcondition is not None:
        _check_postcondition(model, result)
    result.seconds = time.monotonic() - start
    return result


# The search under way (one at a time per process): what `counts_so_far` reads when the
# search is interrupted (Ctrl-C with --json still reports how far it got).
RUNNING: list[Explorer] = []


def counts_so_far() -> dict[str, int]:
    """Distinct and generated states, depth and queue of the search under way (zeros
    before it started)."""
    if not RUNNING:
        return {"distinct_states": 0, "states_generated": 0, "depth": 0, "left_on_queue": 0}
    e = RUNNING[0]
    distinct = max(int(getattr(e, "distinct_so_far", 0)), len(e.states))
    return {"distinct_states": distinct, "states_generated": e.generated, "depth": e.max_level,
            "left_on_queue": max(0, distinct - e.head)}


STATE_LEVEL_KINDS = ("eventually", "leadsto", "infinitely", "stable", "stays", "init_always", "init_eventually",
                     "wf", "sf")


def _at_tlc_liveness_error(model: Model, explorer: Explorer, result: CheckResult) -> None:
    """TLC evaluates the liveness conditions of each state (its fairness conditions'
    ENABLED, the properties' state predicates) right after expanding it, so an error in
    one stops its search there, not after it, with exit code 255 (an Assert keeps 14):
    `result` gets the counts, depth and trace of that moment."""
    err = result.error
    if err is None or err.kind not in ("eval", "module eval", "assert") or not explorer.distinct_after:
        return
    preds = [f.enabled for f in model.fairness]
    for ob in model.liveness:
        if ob.kind in STATE_LEVEL_KINDS:
            preds += [p for p in (ob.p, ob.q) if p is not None]
    for i in range(len(explorer.distinct_after)):
        try:
            for p in preds:
                p(explorer.states[i])
        except TlaError as e:
            if not isinstance(e, EvalError) and e.kind != "eval":
                raise
            if e.kind != "assert":
                e.kind = "module eval"
            distinct = explorer.distinct_after[i]
            result.result, result.error = "error", e
            result.distinct_states, result.states_generated = distinct, explorer.generated_after[i]
            result.depth = max(explorer.level[:distinct])
            result.left_on_queue = distinct - i - 1
            result.trace = explorer.trace(i)
            return


def _needs_one_worker(model: Model, graph: bool) -> str | None:
    """Why the search cannot be sharded over workers (None if it can)."""
    if model.liveness:
        return "liveness checking needs the whole state graph in one process"
    if graph:
        return "--graph needs the whole state graph in one process"
    if RUNTIME.used:
        return "TLCGet/TLCSet need the counters of a single search"
    return None


def _check_postcondition(model: Model, result: CheckResult) -> None:
    """TLC evaluates the POSTCONDITION after a search without error (TLCGet sees the
    final counters); a false one is reported as TLC does, with exit code 10."""
    post = model.postcondition
    assert post is not None
    RUNTIME.level = RUNTIME.expanding = RUNTIME.pending = 0  # the search is over
    try:
        ok = model.holds(post, ())
    except TlaError as e:
        result.result, result.error = "error", e
        return
    if not ok:
        sym = model.scope.lookup(post.name)
        loc = sym.defn.body.loc if isinstance(sym, DefSym) else post.loc
        result.result = "error"
        result.error = TlaError("assumption", f"Postcondition {post.name} at line {loc.line}, col {loc.column} "
                                f"of module {model.module.name} is false.", loc)


def print_progress(msg: str) -> None:
    print(msg, file=sys.stderr, flush=True)
