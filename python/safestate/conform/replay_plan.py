"""The compact replay plan: the conformance traces as arrays of small ints, replayed in C++.

Built once from the concrete traces (the model's side of the comparison), for any system
whose adapter defines `expected_line` (the canonical observe line its binding builds):

* each distinct event becomes a call id (`Adapter.plan_call` gives the binding's call);
* each distinct concrete model state becomes a line id (its expected observe line), with
  the adapter's `state_aux` (e.g. "the queue is full": a submit from it must be refused);
* the first step of each graph edge that fires rows gets the model's rows as a line id.

The binding's `PlanReplayer` (bindings/python/plan_replayer.hpp) walks the arrays with
no Python per step.  Building needs the model's concrete traces (the costly part: model
successors off the BFS tree), so the plan is cached on disk beside the explored graph,
keyed by the graph, the adapter's source, this package's sources and the options.
"""

from __future__ import annotations

import hashlib
import inspect
import time
from array import array
from collections import Counter
from collections.abc import Callable, Iterable
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from .adapter import Adapter
from .events import Event
from .graph import StateGraph, cache_dir, cached_pickle, graph_key
from .traces import ConcreteTrace

# Sources whose change changes a plan (with the adapter's own file and the graph).
PLAN_SOURCES = ("adapter.py", "cover.py", "events.py", "model_step.py", "native_step.py",
                "replay_plan.py", "traces.py")


@dataclass
class ReplayPlan:
    events: list[Event] = field(default_factory=list)      # by call id
    lines: list[str] = field(default_factory=list)          # expected observe lines, by id
    aux: array = field(default_factory=lambda: array("b"))  # per line id
    row_lines: list[str] = field(default_factory=list)      # expected fired rows 'C17|K12|', by id
    starts: array = field(default_factory=lambda: array("q", [0]))
    call_ids: array = field(default_factory=lambda: array("i"))
    exp_ids: array = field(default_factory=lambda: array("i"))
    initial_ids: array = field(default_factory=lambda: array("i"))
    rows_at: array = field(default_factory=lambda: array("q"))   # flat step indices, sorted
    rows_exp: array = field(default_factory=lambda: array("i"))
    first_at: array = field(default_factory=lambda: array("q"))  # first step of each edge, sorted
    first_edge: array = field(default_factory=lambda: array("i"))

    @property
    def traces(self) -> int:
        return len(self.initial_ids)

    def steps_in(self, first: int, last: int) -> int:
        return self.starts[last] - self.starts[first]  # type: ignore[no-any-return]

    def edges_in(self, first: int, last: int) -> array:
        """The edges first taken by traces [first, last)."""
        lo, hi = _bisect(self.first_at, self.starts[first]), _bisect(self.first_at, self.starts[last])
        return self.first_edge[lo:hi]

    def rows_in(self, first: int, last: int) -> tuple[int, Counter]:
        """Row checks in traces [first, last) and the rows they fire (equal to the model's
        when the replay agreed): (checks, Counter row id -> times)."""
        lo, hi = _bisect(self.rows_at, self.starts[first]), _bisect(self.rows_at, self.starts[last])
        rows: Counter = Counter()
        for line_id, n in Counter(self.rows_exp[lo:hi]).items():
            for r in self.row_lines[line_id].split("|")[:-1]:
                rows[r] += n
        return hi - lo, rows


def _bisect(a: array, x: int) -> int:
    lo, hi = 0, len(a)
    while lo < hi:
        mid = (lo + hi) // 2
        if a[mid] < x:
            lo = mid + 1
        else:
            hi = mid
    return lo


def row_line(rows: Iterable[str]) -> str:
    return "".join(f"{r}|" for r in sorted(rows))


class PlanBuilder:
    """Appends concrete traces to a plan; interning keeps the per-step work to a few
    dictionary look-ups (states shared along BFS-tree paths are looked up by identity)."""

    def __init__(self, adapter: Adapter, check_rows: bool) -> None:
        self.adapter = adapter
        self.check_rows = check_rows
        self.plan = ReplayPlan()
        self._event_ids: dict[Event, int] = {}
        self._line_ids: dict[str, int] = {}
        self._state_ids: dict[tuple, int] = {}
        self._by_identity: dict[int, tuple[tuple, int]] = {}  # id(state) -> (state kept alive, line id)
        self._row_ids: dict[str, int] = {}
        self._edge_seen: set[int] = set()

    def _line_id(self, state: tuple) -> int:
        hit = self._by_identity.get(id(state))
        if hit is not None:
            return hit[1]
        lid = self._state_ids.get(state)
        if lid is None:
            line = self.adapter.expected_line(state)
            lid = self._line_ids.get(line)
            if lid is None:
                lid = self._line_ids[line] = len(self.plan.lines)
                self.plan.lines.append(line)
                self.plan.aux.append(self.adapter.state_aux(state))
            self._state_ids[state] = lid
        self._by_identity[id(state)] = (state, lid)
        return lid

    def add(self, ct: ConcreteTrace) -> None:
        p, adapter = self.plan, self.adapter
        p.initial_ids.append(self._line_id(ct.initial))
        flat = len(p.call_ids)
        before = ct.initial
        for st in ct.steps:
            ev = st.event
            cid = self._event_ids.get(ev)
            if cid is None:
                cid = self._event_ids[ev] = len(p.events)
                p.events.append(ev)
            p.call_ids.append(cid)
            p.exp_ids.append(self._line_id(st.state))
            if st.edge >= 0 and st.edge not in self._edge_seen:
                self._edge_seen.add(st.edge)
                p.first_at.append(flat)
                p.first_edge.append(st.edge)
                if self.check_rows and adapter.fires_rows(ev):
                    want = adapter.model_rows(before, ev)
                    if want is not None:
                        line = row_line(want)
                        rid = self._row_ids.get(line)
                        if rid is None:
                            rid = self._row_ids[line] = len(p.row_lines)
                            p.row_lines.append(line)
                        p.rows_at.append(flat)
                        p.rows_exp.append(rid)
            flat += 1
            before = st.state
        p.starts.append(flat)


PROGRESS_SECONDS = 5.0


def build(adapter: Adapter, traces: Iterable[ConcreteTrace], check_rows: bool = True,
          progress: Callable[[str], None] | None = None) -> ReplayPlan:
    b = PlanBuilder(adapter, check_rows)
    last = time.monotonic()
    for ct in traces:
        b.add(ct)
        if progress and time.monotonic() - last >= PROGRESS_SECONDS:
            last = time.monotonic()
            progress(f"conform: building the replay plan: {b.plan.traces} traces, {len(b.plan.call_ids)} steps")
    return b.plan


def plan_key(adapter: Adapter, graph: StateGraph, options: str) -> str:
    """A hash of what a plan is made from (the model, the checker and the native core,
    which computes the model's side, through `graph_key`)."""
    h = hashlib.sha256()
    h.update(graph_key(adapter.stepper.model).encode())
    h.update(array("i", graph.src).tobytes() + array("i", graph.dst).tobytes())
    h.update(Path(inspect.getfile(type(adapter))).read_bytes())
    here = Path(__file__).resolve().parent
    for name in PLAN_SOURCES:
        h.update((here / name).read_bytes())
    h.update(options.encode())
    return h.hexdigest()[:32]


def cached_build(adapter: Adapter, graph: StateGraph, traces: Iterable[ConcreteTrace], options: str,
                 check_rows: bool, progress: Callable[[str], None] | None = None) -> ReplayPlan:
    """`build`, reusing the plan of an earlier run with the same `plan_key` (on disk, beside
    the graph cache; safe for parallel processes as the graph cache is)."""
    stem = Path(adapter.stepper.model.module.file).stem
    path = cache_dir() / f"{stem}-plan-{plan_key(adapter, graph, options)}.pickle"
    return cached_pickle(path, ReplayPlan, lambda: build(adapter, traces, check_rows, progress), "replay plan",
                         progress)


def replayer(adapter: Adapter, plan: ReplayPlan) -> Any:
    """The binding's PlanReplayer over the plan (the adapter's calls for the plan's events)."""
    p = plan
    config = adapter.plan_config()
    head = config if isinstance(config, tuple) else (config,)
    return adapter.core.PlanReplayer(*head, [adapter.plan_call(e) for e in p.events], p.lines, p.aux,
                                     p.row_lines, p.starts, p.call_ids, p.exp_ids, p.initial_ids, p.rows_at,
                                     p.rows_exp)
