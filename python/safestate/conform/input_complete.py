"""The input-complete pass: from every reachable state, every input vector of the
adapter's full alphabet for one step, compared with the model.

"Every reachable transition" is only as strong as the input alphabet of the model's
cfg (the CI cfg offers a restricted set of channel pairs and abstract speed classes).
Here each state reached along the BFS tree is probed with `Adapter.input_alphabet`
(for the flagship: every channel pair, every selector contact pattern, every enabling
pair, concrete velocities around each threshold, each free signal), each probe on a
fresh C++ object brought to the state by the tree path (`Adapter.probe_batch`, one
binding call per state).  The model must accept every probe (exactly one successor);
the C++ must then observe the model's projection and fire the model's rows.  A probe
with `before` events is a short sequence (the flagship: a command outside the cfg's
alphabet, then one cycle): the model takes each step, the C++ is compared after the last.
"""

from __future__ import annotations

import time
from collections.abc import Callable
from dataclasses import dataclass

from .adapter import differing
from .cover import Trace, bfs_tree, tree_path
from .diff import report
from .events import Event
from .graph import StateGraph
from .model_step import ModelStepError
from .replay import Harness
from .traces import Materializer

PROGRESS_SECONDS = 5.0


@dataclass
class InputCompleteResult:
    states: int = 0          # states probed
    probes: int = 0          # probes compared
    model_steps: int = 0     # distinct (state, model event) evaluated
    mismatch: str | None = None
    seconds: float = 0.0

    def summary(self) -> dict[str, object]:
        return {"states": self.states, "probes": self.probes, "model_steps": self.model_steps,
                "mismatch": self.mismatch, "seconds": round(self.seconds, 3)}

    def render(self) -> str:
        head = self.mismatch + "\n" if self.mismatch else ""
        return (f"{head}input-complete: {self.states} states x full alphabet, {self.probes} probes, "
                f"{'1 mismatch' if self.mismatch else 'no mismatch'}")


def run_input_complete(h: Harness, g: StateGraph, stride: int = 1,
                       progress: Callable[[str], None] | None = None) -> InputCompleteResult:
    """Probe every `stride`-th node (in BFS order) of the graph; stops at the first
    disagreement."""
    start = last = time.monotonic()
    cg = g.as_cover_graph()
    parent, order = bfs_tree(cg)
    mat = Materializer(h.stepper, g)
    mat.set_tree(parent)
    res = InputCompleteResult()
    adapter, stepper = h.adapter, h.stepper
    for n, node in enumerate(order[::stride]):
        root, path = tree_path(cg, parent, node)
        ct = mat.trace(Trace(root, path))
        state = ct.steps[-1].state if ct.steps else ct.initial
        prefix = [st.event for st in ct.steps]
        probes = adapter.input_alphabet(state)
        expected: dict[tuple[Event, ...], tuple[dict[str, object], frozenset[str] | None]] = {}
        for p in probes:
            key = p.before + (p.event,)
            if key in expected:
                continue
            try:
                at = state
                for ev in p.before:
                    at = stepper.edge_successor(at, ev)
                succ = stepper.edge_successor(at, p.event)
            except ModelStepError as e:
                res.mismatch = f"the model does not accept probe '{p.label}' at node {node}: {e}"
                return _done(res, start)
            expected[key] = (adapter.project(succ), adapter.model_rows(at, p.event))
            res.model_steps += len(key)
        for p, (cpp, fired) in zip(probes, adapter.probe_batch(prefix, probes)):
            res.probes += 1
            key = p.before + (p.event,)
            model, rows = expected[key]
            note = "" if rows is None or rows == fired else \
                f"rows: model fires {sorted(rows)}, C++ fired {sorted(fired)}"
            if note or differing(model, cpp):
                where = f"after the {len(prefix)}-step tree path to node {node} ({', '.join(map(str, prefix)) or 'initial'})"
                what = ", then ".join(map(str, p.before + (p.event,)))
                res.mismatch = report(len(prefix) + len(key), f"probe '{p.label}' = {what}", model, cpp,
                                      note) + f"\n  {where}"
                res.states += 1
                return _done(res, start)
        res.states += 1
        if progress and time.monotonic() - last >= PROGRESS_SECONDS:
            last = time.monotonic()
            progress(f"conform: input-complete {n + 1}/{len(order[::stride])} states, {res.probes} probes, "
                     f"{last - start:.0f}s")
    return _done(res, start)


def _done(res: InputCompleteResult, start: float) -> InputCompleteResult:
    res.seconds = time.monotonic() - start
    return res
