"""The trace-replay conformance run: cover the model's reachable transitions with
traces, replay each through the C++, compare after every step."""

from __future__ import annotations

import os
import time
from collections.abc import Callable
from dataclasses import dataclass, field
from types import ModuleType

from ..checker.model import Model
from ..errors import UsageError
from . import itf_io
from .cover import Trace, bfs_tree, cover, tree_path
from .graph import StateGraph
from .events import Event
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
    replay_seconds: float = 0.0      # in the batched binding call (fast path)
    model_seconds: float = 0.0       # computing the model's concrete traces (fast path)
    traces_written: int = 0


@dataclass
class Options:
    out: str | None = None            # write every trace as ITF under out/traces/
    reproducer_dir: str = "."         # where a mismatch's minimal reproducer goes
    max_len: int = 1000
    max_mismatches: int = 10          # stop after this many traces disagreed
    check_rows: bool = True           # compare fired rows with the model's, per transition
    progress: Callable[[str], None] | None = None
    fast: bool = True                 # batched replay when the adapter has fast_replay()


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
    cg = graph.as_cover_graph()
    parent, _ = bfs_tree(cg)
    plan = cover(cg, opts.max_len)
    mat = Materializer(stepper, graph)
    mat.set_tree(parent)
    res = ConformResult(transitions_total=len(graph.src), traces=len(plan))
    covered = bytearray(len(graph.src))
    if opts.fast and not opts.out and harness.adapter.has_fast_replay():
        _run_fast(model, graph, harness, opts, plan, mat, parent, res, covered, start)
    else:
        _run_steps(model, graph, harness, opts, plan, mat, parent, res, covered, start)
    res.transitions_covered = sum(covered)
    res.model_steps = stepper.calls
    res.seconds = time.monotonic() - start
    return res


FAST_CHUNK = 4000  # traces per batched binding call


def _run_fast(model: Model, graph: StateGraph, h: Harness, opts: Options, plan: list[Trace],
              mat: Materializer, parent: list[int], res: ConformResult, covered: bytearray, start: float) -> None:
    """Replay chunks of traces in one binding call each (`Adapter.fast_replay`); the rows
    of each transition's first replay are compared with the model's.  A trace that
    disagrees is replayed again step by step (`_replay`) for the report and reproducer."""
    adapter = h.adapter
    last = time.monotonic()
    i = 0
    while i < len(plan):
        if i == 0:  # the initial state is compared once, step by step
            if _slow_one(model, graph, h, opts, plan, mat, parent, res, covered, 0):
                return
            i = 1
            continue
        chunk = plan[i:i + FAST_CHUNK]
        t_mat = time.monotonic()
        cts = [mat.trace(t) for t in chunk]
        res.model_seconds += time.monotonic() - t_mat
        rows_at: list[int] = []
        meta: list[tuple[int, tuple, Event, int]] = []
        pending: set[int] = set()
        flat = 0
        for k, ct in enumerate(cts):
            before = ct.initial
            for st in ct.steps:
                if st.edge >= 0 and not covered[st.edge] and st.edge not in pending:
                    pending.add(st.edge)
                    if opts.check_rows and adapter.fires_rows(st.event):
                        rows_at.append(flat)
                        meta.append((k, before, st.event, st.edge))
                flat += 1
                before = st.state
        t_rep = time.monotonic()
        bad, fired = adapter.fast_replay(cts, rows_at)
        res.replay_seconds += time.monotonic() - t_rep
        cut = bad if bad >= 0 else len(cts)
        for (k, before, event, _), got in zip(meta, fired):
            if k >= cut:
                break
            for r in got:
                h.stats.rows[r] += 1
            h.stats.row_checks += 1
            want = adapter.model_rows(before, event)
            if want is not None and want != got:
                cut = k
                break
        for ct in cts[:cut]:
            res.steps += len(ct.steps)
            h.stats.steps += len(ct.steps)
            for st in ct.steps:
                if st.edge >= 0:
                    covered[st.edge] = 1
        i += cut
        if cut < len(cts):
            if _slow_one(model, graph, h, opts, plan, mat, parent, res, covered, i):
                return
            i += 1
        if opts.progress and time.monotonic() - last >= PROGRESS_SECONDS:
            last = time.monotonic()
            opts.progress(f"conform: trace {i}/{len(plan)}, {res.steps} steps, {sum(covered)} transitions "
                          f"covered, {len(res.found)} mismatches, {last - start:.0f}s")


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
