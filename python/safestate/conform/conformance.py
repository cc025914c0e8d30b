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
from .model_step import ModelStepper
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
    replay_seconds: float = 0.0
    traces_written: int = 0


@dataclass
class Options:
    out: str | None = None            # write every trace as ITF under out/traces/
    reproducer_dir: str = "."         # where a mismatch's minimal reproducer goes
    max_len: int = 1000
    max_mismatches: int = 10          # stop after this many traces disagreed
    check_rows: bool = True           # compare fired rows with the model's, per transition
    progress: Callable[[str], None] | None = None


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
    res.transitions_covered = sum(covered)
    res.model_steps = stepper.calls
    res.seconds = time.monotonic() - start
    return res


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
