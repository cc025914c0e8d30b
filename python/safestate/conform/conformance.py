"""The trace-replay conformance run: cover the model's reachable transitions with
traces, replay each through the C++, compare after every step."""

from __future__ import annotations

import hashlib
import os
import time
from array import array
from collections.abc import Callable
from dataclasses import dataclass, field
from types import ModuleType

from ..checker.model import Model
from ..errors import SafestateError, UsageError
from . import itf_io, replay_plan
from .cover import Trace, bfs_tree, cover, tree_path
from .graph import StateGraph
from .replay import Harness, Mismatch
from .traces import ConcreteTrace, Materializer

PROGRESS_SECONDS = 5.0


@dataclass
class Found:
    mismatch: Mismatch
    trace: int                # index of the trace
    reproducer: str | None    # ITF file replayable with --replay
    reproducer_steps: int


@dataclass
class ConformResult:
    transitions_total: int
    transitions_covered: int = 0
    traces: int = 0
    steps: int = 0
    model_steps: int = 0
    found: list[Found] = field(default_factory=list)
    seconds: float = 0.0
    replay_seconds: float = 0.0      # in the binding's PlanReplayer (plan path)
    model_seconds: float = 0.0       # building the replay plan, or reading it from the cache
    traces_written: int = 0


@dataclass
class Options:
    out: str | None = None            # write every trace as ITF under out/traces/
    reproducer_dir: str = "."         # where a mismatch's minimal reproducer goes
    max_len: int = 1000
    max_mismatches: int = 10          # stop after this many traces disagreed
    check_rows: bool = True           # compare fired rows with the model's, per transition
    progress: Callable[[str], None] | None = None
    fast: bool = True                 # replay as a compact plan when the adapter has one


def check_writable(out: str | None) -> None:
    """Fail before any work when `--out DIR` cannot be created or written."""
    if out is None:
        return
    if os.path.exists(out) and not os.path.isdir(out):
        raise UsageError(f"{out}: --out must be a directory, this is a file")
    try:
        os.makedirs(out, exist_ok=True)
        probe = os.path.join(out, f".safestate-write-test-{os.getpid()}")
        with open(probe, "w", encoding="utf-8"):
            pass
        os.remove(probe)
    except OSError as e:
        raise UsageError(f"{out}: --out directory is not writable ({e.strerror or e})") from None


def run(model: Model, core: ModuleType, graph: StateGraph, harness: Harness, opts: Options) -> ConformResult:
    start = time.monotonic()
    stepper = harness.stepper
    plan, mat, parent = _traces(harness, graph, opts)
    res = ConformResult(transitions_total=len(graph.src), traces=len(plan))
    covered = bytearray(len(graph.src))
    if opts.fast and not opts.out and harness.adapter.has_plan_replay():
        _run_plan(model, graph, harness, opts, plan, mat, parent, res, covered, start)
    else:
        _run_steps(model, graph, harness, opts, plan, mat, parent, res, covered, start)
    res.transitions_covered = sum(covered)
    res.model_steps = stepper.calls
    res.seconds = time.monotonic() - start
    return res


class PlanDisagreement(SafestateError):
    """The compact plan and the step-by-step replay disagree on a trace: a bug in an
    adapter's plan methods or its binding's PlanReplayer, never a verdict on the C++."""


PLAN_CHUNK = 20000  # traces per PlanReplayer.run call (a progress line between calls)


def _run_plan(model: Model, graph: StateGraph, h: Harness, opts: Options, plan: list[Trace],
              mat: Materializer, parent: list[int], res: ConformResult, covered: bytearray, start: float) -> None:
    """Replay the traces as a compact plan in the binding (replay_plan.py), cached on disk
    beside the graph.  The first trace (and the initial state) is replayed step by step; a
    trace that disagrees is replayed again step by step (`_slow_one`) for the report and
    reproducer, and the plan goes on after it."""
    adapter = h.adapter
    t_mat = time.monotonic()
    if _slow_one(model, graph, h, opts, plan, mat, parent, res, covered, 0):
        return
    cp = _cached_plan(h, graph, plan, mat, opts)
    res.model_seconds += time.monotonic() - t_mat
    t_rep = time.monotonic()
    rp = replay_plan.replayer(adapter, cp)
    res.replay_seconds += time.monotonic() - t_rep
    last = time.monotonic()
    i = 1
    while i < cp.traces:
        t_rep = time.monotonic()
        bad, step = rp.run(i, min(i + PLAN_CHUNK, cp.traces))
        res.replay_seconds += time.monotonic() - t_rep
        cut = bad if bad >= 0 else min(i + PLAN_CHUNK, cp.traces)
        _account(cp, h, res, covered, i, cut)
        i = cut
        if bad >= 0:
            found = len(res.found)
            if _slow_one(model, graph, h, opts, plan, mat, parent, res, covered, i):
                return
            if len(res.found) == found:
                raise PlanDisagreement(f"the plan replay disagrees at trace {i} step {step + 1}, the step-by-step "
                                       f"replay of that trace does not: {type(adapter).__name__}.expected_line (or "
                                       f"plan_call / state_aux) does not match the binding's PlanReplayer")
            i += 1
        if opts.progress and time.monotonic() - last >= PROGRESS_SECONDS:
            last = time.monotonic()
            opts.progress(f"conform: trace {i}/{len(plan)}, {res.steps} steps, {sum(covered)} transitions "
                          f"covered, {len(res.found)} mismatches, {last - start:.0f}s")


def _cached_plan(h: Harness, graph: StateGraph, plan: list[Trace], mat: Materializer,
                 opts: Options) -> replay_plan.ReplayPlan:
    options = f"max_len={opts.max_len} check_rows={opts.check_rows} traces={len(plan)} cover={_digest(plan)}"
    return replay_plan.cached_build(h.adapter, graph, (mat.trace(t) for t in plan), options, opts.check_rows,
                                    opts.progress)


def _digest(plan: list[Trace]) -> str:
    """A hash of the traces themselves: the plan follows them, whichever code walked them
    (the cover's walk is in the binding, bindings/python/cover_module.cpp)."""
    flat = array("q")
    for t in plan:
        flat.append(t.start)
        flat.append(len(t.edges))
        flat.extend(t.edges)
    return hashlib.sha256(flat.tobytes()).hexdigest()[:16]


def plan_of(h: Harness, graph: StateGraph, opts: Options) -> replay_plan.ReplayPlan:
    """The compact replay plan of the whole conformance run (cached as `run` caches it)."""
    plan, mat, _ = _traces(h, graph, opts)
    return _cached_plan(h, graph, plan, mat, opts)


def _traces(h: Harness, graph: StateGraph, opts: Options) -> tuple[list[Trace], Materializer, list[int]]:
    """The trace cover of the graph, the materializer of its concrete states, and the BFS
    tree's parent edges (computed once for both)."""
    cg = graph.as_cover_graph()
    tree = bfs_tree(cg)
    mat = Materializer(h.stepper, graph)
    mat.set_tree(tree[0])
    return cover(cg, opts.max_len, tree=tree), mat, tree[0]


def _account(cp: replay_plan.ReplayPlan, h: Harness, res: ConformResult, covered: bytearray,
             first: int, last: int) -> None:
    """Steps, covered transitions and rows of plan traces [first, last), which agreed."""
    n = cp.steps_in(first, last)
    res.steps += n
    h.stats.steps += n
    for e in cp.edges_in(first, last):
        covered[e] = 1
    checks, rows = cp.rows_in(first, last)
    h.stats.row_checks += checks
    h.stats.rows.update(rows)


def _slow_one(model: Model, graph: StateGraph, h: Harness, opts: Options, plan: list[Trace],
              mat: Materializer, parent: list[int], res: ConformResult, covered: bytearray, i: int) -> bool:
    """Replay trace i step by step; True when enough mismatches were found to stop."""
    ct = mat.trace(plan[i])
    mm, upto = _replay(h, ct, covered, opts.check_rows, first=(i == 0))
    res.steps += upto
    if mm is not None:
        res.found.append(_reproduce(model, h, mat, graph, parent, ct, plan[i], i, mm, upto, opts))
    return len(res.found) >= opts.max_mismatches


def _run_steps(model: Model, graph: StateGraph, harness: Harness, opts: Options, plan: list[Trace],
               mat: Materializer, parent: list[int], res: ConformResult, covered: bytearray,
               start: float) -> None:
    """Replay every trace step by step through the adapter (and write ITF with --out)."""
    last = time.monotonic()
    total_steps = sum(len(t.edges) for t in plan)
    for i, t in enumerate(plan):
        ct = mat.trace(t)
        mm, upto = _replay(harness, ct, covered, opts.check_rows, first=(i == 0))
        res.steps += upto
        if mm is not None:
            res.found.append(_reproduce(model, harness, mat, graph, parent, ct, t, i, mm, upto, opts))
            if len(res.found) >= opts.max_mismatches:
                break
        if opts.out:
            itf_io.write(os.path.join(opts.out, "traces", f"trace-{i:06d}.itf.json"), model, ct,
                         f"conformance trace {i} of {len(plan)}")
            res.traces_written += 1
        if opts.progress and time.monotonic() - last >= PROGRESS_SECONDS:
            last = time.monotonic()
            opts.progress(f"conform: trace {i + 1}/{len(plan)}, {res.steps}/{total_steps} steps, "
                          f"{sum(covered)} transitions covered, {len(res.found)} mismatches, "
                          f"{last - start:.0f}s")


def _replay(h: Harness, ct: ConcreteTrace, covered: bytearray | None, check_rows: bool,
            first: bool) -> tuple[Mismatch | None, int]:
    """Replay one concrete trace; the first disagreement and the steps replayed."""
    ls = h.lockstep(ct.initial)
    if first:
        mm = ls.check_initial()
        if mm is not None:
            return mm, 0
    for j, st in enumerate(ct.steps):
        new = covered is not None and st.edge >= 0 and not covered[st.edge]
        mm = ls.step(st.event, st.state, check_rows and (new or st.edge < 0))
        if mm is not None:
            return mm, j + 1
        if new:
            covered[st.edge] = 1  # type: ignore[index]
    return None, len(ct.steps)


def replay_trace(h: Harness, ct: ConcreteTrace) -> tuple[Mismatch | None, int]:
    return _replay(h, ct, None, True, True)


def _reproduce(model: Model, h: Harness, mat: Materializer, graph: StateGraph, parent: list[int],
               ct: ConcreteTrace, t: Trace, index: int, mm: Mismatch, upto: int, opts: Options) -> Found:
    """The shortest known trace that shows the disagreement: the BFS-tree path to the
    failing edge's source plus that edge, if it still disagrees there; else the
    failing trace's prefix.  Written as ITF for `safestate conform --replay`."""
    best = ConcreteTrace(ct.initial, ct.steps[:upto])
    if upto > 0 and ct.steps[upto - 1].edge >= 0:
        edge = ct.steps[upto - 1].edge
        root, path = tree_path(graph.as_cover_graph(), parent, graph.src[edge])
        if len(path) + 1 < upto:
            short = mat.trace(Trace(root, path + [edge]))
            smm, n = replay_trace(h, short)
            if smm is not None and n == len(short.steps):
                best, mm = short, smm
    path_out = os.path.join(opts.reproducer_dir, f"conform-mismatch-{index:06d}.itf.json")
    itf_io.write(path_out, model, best, f"reproducer: first disagreement at step {len(best.steps)}")
    return Found(mm, index, path_out, len(best.steps))
