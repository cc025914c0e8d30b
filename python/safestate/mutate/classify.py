"""Classification of a mutant with the model's CI cfg, and the pool that classifies many.

* killed: `safestate check` (the native core where it accepts the model, else the Python
  engine) -- on the system's screening cfg first where it declares one, then on the CI
  cfg (`screen`, below) -- reports a violated invariant or property, a deadlock or an Assert failure --
  named, with the trace length (`by` = "property"); or every property holds but the
  mutant no longer reaches one of the model's reachability witnesses (`witness.py`;
  `by` = "witness", the witnesses named);
* survived: every property holds, and the product search (`product.py`) finds an input
  trace after which the mutant's observables differ from the original's;
* equivalent: every property holds and the product is exhausted without a difference;
* timeout: the check or the product search ran out of its budget -- CPU seconds of the
  worker (`--timeout`), not wall seconds, so that a loaded machine gives the verdicts an
  idle one does;
* error: the mutant does not load, or its evaluation fails (`check` exit 75/150...).

**Screening.**  A system may declare a screening cfg (system.toml `[mutate]
screen_config`): the same model and properties (a subset of the CI cfg's) with other,
smaller constants.  Every mutant is checked there first; a violated property there is a
real kill -- the mutant violates a property of the model for a valid choice of its
constants -- and is reported with that cfg (`cfg`), at the cost of the small state space
instead of the CI cfg's.  So is a reachability witness the original reaches there and
the mutant, passing every property, does not (killed by the witness on that cfg), and
an evaluation error there that the Python engine reproduces (the mutant is not a
well-formed model for those constants; an error is never counted).  Every other mutant is classified on the CI cfg as without screening:
the check, the witnesses and the difference search decide survived and equivalent there.

Only killed and survived count in the score.  Each mutant is classified in a forked
child process (the original model is loaded once, before the fork), at most `workers` at
a time; a child past its CPU budget (read from /proc; wall seconds where there is none) is ended
by its process id and the mutant listed as a timeout.
"""

from __future__ import annotations

import contextlib
import io
import json
import os
import re
import shutil
import tempfile
import time
import traceback
from collections.abc import Callable
from dataclasses import asdict, dataclass, field
from multiprocessing.connection import Connection, wait
from pathlib import Path
from typing import Any

from ..checker.itf import value_to_itf
from ..checker.model import Model, load_model
from ..tla.errors import TlaError, UnsupportedError
from ..tla.values import fmt
from .generate import Mutant
from .graph import LabelledGraph, confirm, graph_search, native_labelled
from .product import DiffStep, OriginalSide, ProductResult, Projection, search
from .witness import WitnessSet, on_native_states, on_python_states, witness_set

KILLING_RESULTS = {"safety failure", "deadlock failure", "liveness failure", "temporal safety failure",
                   "action property failure", "init property failure", "assert failure"}
STATUSES = ("killed", "survived", "equivalent", "timeout", "error")


@dataclass
class Outcome:
    mutant: str                  # Mutant.id
    status: str                  # one of STATUSES
    violated: str | None = None  # killed: the property (or "deadlock"), or the first witness lost
    trace_length: int | None = None
    reason: str = ""             # timeout / error: why; survived/equivalent: search figures
    seconds: float = 0.0         # wall seconds of its classification
    cpu: float = 0.0             # CPU seconds of the worker (what the budget counts)
    pairs: int = 0
    nondeterministic: bool = False
    table: list[dict[str, Any]] = field(default_factory=list)   # the difference trace, printed values
    itf: dict[str, Any] | None = None                           # the same as ITF JSON
    cached: bool = False
    by: str = ""                 # killed: "property" (the check) or "witness" (a witness lost)
    cfg: str = ""                # the cfg (file name) whose check decided: the screening or the CI cfg
    witnesses: list[str] = field(default_factory=list)  # killed by witness: every witness lost

    def to_json(self) -> dict[str, Any]:
        return asdict(self)

    @staticmethod
    def from_json(d: dict[str, Any]) -> "Outcome":
        return Outcome(**{k: v for k, v in d.items() if k in Outcome.__dataclass_fields__})


@dataclass
class Subject:
    """What every mutant of one model is checked against."""

    model: Path                  # the original .tla
    cfg: Path                    # the CI cfg
    projection: Projection
    screen: Path | None = None   # the screening cfg, checked first (module docstring)
    dropped: tuple[str, ...] = ()  # invariants the original itself violates (not used)
    engine: str = "auto"
    timeout: float = 300.0       # CPU seconds per mutant: check and search together
    max_pairs: int = 2_000_000
    max_memory_mb: int = 3000
    original: Model | None = None  # loaded once, before the workers fork
    side: OriginalSide | None = None  # its successors, explored once before the fork (Python engine)
    graph: LabelledGraph | None = None  # or its labelled graph from the native core (graph.py)
    witnesses: WitnessSet | None = None  # the reachability witnesses the original reaches (witness.py)
    screen_witnesses: WitnessSet | None = None  # ... on the screening cfg (the native core's states)
    screen_original: Model | None = None        # the original with the screening cfg, for those witnesses

    def load_original(self) -> Model:
        if self.original is None:
            self.original = load_model(str(self.model), str(self.cfg))
        return self.original


def without_invariants(cfg_text: str, names: tuple[str, ...]) -> str:
    """The cfg with the named invariants left out of its INVARIANT(S) sections."""
    if not names:
        return cfg_text
    out = []
    for line in cfg_text.splitlines():
        words = line.split()
        keep = [w for w in words if w not in names]
        if words and not keep:
            continue
        out.append(line if keep == words else re.sub(r"\b(" + "|".join(map(re.escape, names)) + r")\b", "", line))
    return "\n".join(out) + "\n"


def materialise(subject: Subject, mutant: Mutant | None, dest: Path, screen: bool = False) -> tuple[Path, Path]:
    """The model's folder copied into `dest` with the mutant applied; (model, cfg) there:
    the CI cfg, or with `screen` the screening cfg (the same invariants left out)."""
    for f in subject.model.parent.iterdir():
        if f.is_file() and f.suffix in (".tla", ".cfg"):
            shutil.copyfile(f, dest / f.name)
    if mutant is not None:
        target = dest / mutant.file
        target.write_bytes(mutant.apply(target.read_bytes()))
    source = subject.screen if screen and subject.screen is not None else subject.cfg
    cfg = dest / ("__mutate__" + source.name)
    cfg.write_text(without_invariants(source.read_text(encoding="utf-8"), subject.dropped), encoding="utf-8")
    return dest / subject.model.name, cfg


def check_model(model: Model, engine: str, max_memory_mb: int, states: bool = False) -> Any:
    """`safestate check`'s result; `states`: with the stored states (the Python engine's
    graph), for the witnesses."""
    from ..checker.native.engine_choice import check
    # The engine's notes (Python fallback...) are not the mutant's result: kept off stderr.
    with contextlib.redirect_stderr(io.StringIO()):
        return check(model, "python" if states else engine, workers=1, graph=states, max_memory_mb=max_memory_mb)


def classify(subject: Subject, mutant: Mutant) -> Outcome:
    """The mutant's outcome (in this process): on the screening cfg where it decides,
    else on the CI cfg."""
    start, cpu = time.monotonic(), time.process_time()
    out = None
    if subject.screen is not None:
        with tempfile.TemporaryDirectory(prefix="safestate-mutant-") as tmp:
            out = _screen(subject, mutant, tmp, start)
    if out is None:
        out = _classify_ci(subject, mutant, start, cpu + subject.timeout)
        out.cfg = subject.cfg.name
    out.cpu = round(time.process_time() - cpu, 2)
    return out


def _classify_ci(subject: Subject, mutant: Mutant, start: float, deadline: float) -> Outcome:
    """The classification on the CI cfg; `deadline`: of `time.process_time()`."""
    original = subject.load_original()
    with tempfile.TemporaryDirectory(prefix="safestate-mutant-") as tmp:
        graph: LabelledGraph | None = None
        try:
            tla, cfg = materialise(subject, mutant, Path(tmp))
            model = load_model(str(tla), str(cfg))
            result, graph = _check(subject, model)
        except TlaError as e:
            return Outcome(mutant.id, "error", reason=_where(e, tmp), seconds=time.monotonic() - start)
        verdict = _verdict(mutant, result, tmp, start)
        if verdict is not None:
            return verdict
        try:
            lost = _lost_witnesses(subject, original, model, mutant, result, graph)
        except TlaError as e:
            return Outcome(mutant.id, "error", reason=f"witnesses: {_where(e, tmp)}", seconds=time.monotonic() - start)
        if lost:
            return Outcome(mutant.id, "killed", violated=lost[0], by="witness", witnesses=lost,
                           reason=f"no longer reached: {', '.join(lost)}", seconds=time.monotonic() - start)
        try:
            pr = None
            if graph is not None and graph.same:
                n = len(graph.offsets) - 1
                pr = ProductResult("equivalent", n, reason=f"the original's graph: {n} states, the same steps and observations")
            elif graph is not None and subject.graph is not None:
                pr = graph_search(subject.graph, graph, subject.projection, subject.max_pairs, deadline)
                if pr.verdict == "difference" and model.config.view is not None:
                    steps = confirm(original, model, subject.projection, pr.steps)
                    if steps is None:
                        pr = None  # a difference of stored states only (graph.py): the exact search decides
                    else:
                        pr.steps = steps
            if pr is None:
                side = subject.side or OriginalSide(original)
                pr = search(side, model, subject.projection, subject.max_pairs, deadline)
        except TlaError as e:
            return Outcome(mutant.id, "error", reason=f"product search: {_where(e, tmp)}",
                           seconds=time.monotonic() - start)
    out = Outcome(mutant.id, {"difference": "survived"}.get(pr.verdict, pr.verdict), pairs=pr.pairs,
                  nondeterministic=pr.nondeterministic, reason=pr.reason, seconds=time.monotonic() - start)
    if pr.verdict == "difference":
        out.table = [_row(s) for s in pr.steps]
        out.itf = difference_itf(subject.projection, pr.steps, mutant)
        out.reason = f"observables differ after {len(pr.steps) - 1} step(s)"
    return out


def _screen(subject: Subject, mutant: Mutant, tmp: str, start: float) -> Outcome | None:
    """The mutant's check on the screening cfg: its outcome when that check decides it
    (a violated property; a reachability witness the original reaches there and the
    mutant, passing every property, does not; an evaluation error the Python engine
    reproduces), else None (the CI cfg decides)."""
    assert subject.screen is not None
    try:
        tla, cfg = materialise(subject, mutant, Path(tmp), screen=True)
        model = load_model(str(tla), str(cfg))
        result, run = _screen_check(subject, model)
    except UnsupportedError:
        return None
    except TlaError as e:
        return Outcome(mutant.id, "error", reason=_where(e, tmp), seconds=time.monotonic() - start,
                       cfg=subject.screen.name)
    verdict = _verdict(mutant, result, tmp, start)
    if verdict is None and run is not None and subject.screen_witnesses and subject.screen_original:
        try:
            lost = on_native_states(subject.screen_witnesses, subject.screen_original, run, model, mutant.definition)
        except TlaError:
            return None  # the CI cfg's own witness evaluation reports it
        if lost:
            verdict = Outcome(mutant.id, "killed", violated=lost[0], by="witness", witnesses=lost,
                              reason=f"no longer reached: {', '.join(lost)}", seconds=time.monotonic() - start)
    if verdict is None or verdict.status == "timeout":
        return None
    verdict.cfg = subject.screen.name
    return verdict


def _screen_check(subject: Subject, model: Model) -> tuple[Any, Any]:
    """(result, the native run holding the states it stored, or None): on the native core
    where the original's witnesses on the screening cfg are known and the core takes the
    mutant, else `check_model`'s engine choice (no witnesses evaluated there)."""
    ws = subject.screen_witnesses
    checked = None if ws is None or not ws.names or subject.engine == "python" else \
        _native_check(model, subject.max_memory_mb)
    if checked is None:
        return check_model(model, subject.engine, subject.max_memory_mb), None
    if checked[0] is None:  # an evaluation error of the core: the Python engine reports it as TLC does
        return check_model(model, "python", subject.max_memory_mb), None
    return checked


def _native_check(model: Model, max_memory_mb: int) -> tuple[Any, Any] | None:
    """(result, the run holding the states it stored) of the native core's check, the
    result None after an evaluation error of the core; None when the core does not take
    the model."""
    from ..checker.native.search import NativeRun, explore_native
    try:
        run = NativeRun(model)
    except UnsupportedError:
        return None
    with contextlib.redirect_stderr(io.StringIO()):
        result, _error = explore_native(model, max_memory_mb, None, run, 1)
    return result, run


def _screen_witness_set(subject: Subject) -> None:
    """The witnesses the original reaches on the screening cfg (native core), once before
    the workers fork; none where the core does not take the model there."""
    assert subject.screen is not None
    subject.screen_witnesses = WitnessSet()
    with tempfile.TemporaryDirectory(prefix="safestate-mutate-") as tmp:
        tla, cfg = materialise(subject, None, Path(tmp), screen=True)
        model = load_model(str(tla), str(cfg))
        checked = _native_check(model, subject.max_memory_mb)
        if checked is None or checked[0] is None or checked[0].result != "success":
            return
        original = load_model(str(subject.model), str(subject.screen))
        subject.screen_witnesses = witness_set(subject.model, original, native=(checked[1], model))
        subject.screen_original = original


def _lost_witnesses(subject: Subject, original: Model, model: Model, mutant: Mutant, result: Any,
                    graph: LabelledGraph | None) -> list[str]:
    """The witnesses the original reaches and the mutant, which passed its check, does
    not (witness.py): on the states its check stored."""
    ws = subject.witnesses
    if ws is None or not ws.names:
        return []
    if graph is not None and graph.run is not None:
        return on_native_states(ws, original, graph.run, model, mutant.definition)
    if result.states is None:
        return []
    return on_python_states(ws, original, ws.names, result.states)


def _check(subject: Subject, model: Model) -> tuple[Any, LabelledGraph | None]:
    """The mutant's check; on the native core (where the original's graph was recorded
    there and the core accepts the mutant) recording its labelled graph for the
    difference search, else `check_model`'s engine choice (with the stored states where
    witnesses are to be evaluated: the Python engine)."""
    states = bool(subject.witnesses and subject.witnesses.names)
    if subject.graph is None:
        return check_model(model, subject.engine, subject.max_memory_mb, states), None
    try:
        labelled, graph, _why = native_labelled(model, subject.projection, subject.max_memory_mb, subject.graph)
    except UnsupportedError:
        # A mutant outside the core's subset (the original is inside): the Python engine.
        return check_model(model, subject.engine, subject.max_memory_mb, states), None
    if labelled is None:
        # An evaluation error of the core is not always one of the reference: the
        # Python engine decides (8 of RuntimeSupervisor's 188 mutants stop the core with
        # an evaluation error and pass the Python engine's check), and a mutant it
        # passes is searched exactly (product.py).
        return check_model(model, "python", subject.max_memory_mb, states), None
    return labelled, graph


def _verdict(mutant: Mutant, result: Any, tmp: str, start: float) -> Outcome | None:
    """The outcome a check that did not succeed decides (None: every property held)."""
    if result.result in KILLING_RESULTS:
        what = "deadlock" if result.result == "deadlock failure" else (result.violated or result.result)
        return Outcome(mutant.id, "killed", violated=what, trace_length=len(result.trace or []), by="property",
                       seconds=time.monotonic() - start)
    if result.result != "success":
        why = result.error.message if result.error else result.result
        kind = result.error.kind if result.error else ""
        if kind == "assert":
            return Outcome(mutant.id, "killed", violated=f"Assert: {why[:120]}", by="property",
                           trace_length=len(result.trace or []), seconds=time.monotonic() - start)
        if kind == "memory" or "memory" in why.lower():
            return Outcome(mutant.id, "timeout", reason=f"check: {why}", seconds=time.monotonic() - start)
        return Outcome(mutant.id, "error", reason=f"check: {_where(result.error, tmp) if result.error else why}",
                       seconds=time.monotonic() - start)
    return None


def _where(e: TlaError, tmp: str) -> str:
    loc = f"{Path(e.loc.file).name}:{e.loc.line}:{e.loc.column}: " if e.loc else ""
    return (loc + e.message.replace(tmp + os.sep, "")).splitlines()[0][:300]


def _row(s: DiffStep) -> dict[str, Any]:
    def side(d: dict | None) -> dict[str, str] | None:
        return None if d is None else {k: fmt(v) for k, v in d.items()}
    return {"inputs": {k: fmt(v) for k, v in s.inputs.items()}, "original": side(s.original),
            "mutant": side(s.mutant)}


def difference_itf(proj: Projection, steps: list[DiffStep], mutant: Mutant) -> dict[str, Any]:
    """The difference trace as ITF: the inputs, and each observable of the original
    (`original.x`) and the mutant (`mutant.x`); a side that cannot take the last step
    has `#unserializable: "no step"` there."""
    names = list(proj.inputs) + [f"original.{o}" for o in proj.observables] + [f"mutant.{o}" for o in proj.observables]
    none = {"#unserializable": "no step"}
    states = []
    for i, s in enumerate(steps):
        st: dict[str, Any] = {"#meta": {"index": i}}
        for k, v in s.inputs.items():
            st[k] = value_to_itf(v)
        for side, d in (("original", s.original), ("mutant", s.mutant)):
            for o in proj.observables:
                st[f"{side}.{o}"] = none if d is None else value_to_itf(d[o])
        states.append(st)
    return {"#meta": {"format": "ITF", "format-description": "https://apalache-mc.org/docs/adr/015adr-trace.html",
                      "source": mutant.file, "description": f"difference trace of mutant {mutant.id}: "
                      f"the same inputs, observables differ in the last state"},
            "vars": names, "states": states}


def prepare(subject: Subject, search: bool = True) -> None:
    """Records the original's labelled graph on the native core where it accepts the
    model, else explores its successors with the Python engine, and finds which of its
    reachability witnesses it reaches -- once, before the workers fork.  `search`
    False: only the witnesses (every outcome came from the cache)."""
    if search and subject.screen is not None and subject.screen_witnesses is None and subject.engine != "python":
        _screen_witness_set(subject)
    if subject.witnesses is not None and (not search or subject.side is not None or subject.graph is not None):
        return
    original = subject.load_original()
    if subject.engine != "python":
        with tempfile.TemporaryDirectory(prefix="safestate-mutate-") as tmp:
            tla, cfg = materialise(subject, None, Path(tmp))  # without the invariants it violates
            model = load_model(str(tla), str(cfg))
            try:
                _result, graph, _why = native_labelled(model, subject.projection, subject.max_memory_mb)
            except UnsupportedError:
                if subject.engine == "native":
                    raise
                graph = None
        if graph is not None:
            if subject.witnesses is None:
                subject.witnesses = witness_set(subject.model, original, native=(graph.run, model))
            if search:
                for i in range(len(graph.offsets) - 1):  # shared by every forked search
                    graph.signature(i)
                graph.signature(-1)
                subject.graph = graph
            return
    if subject.witnesses is None:
        subject.witnesses = _python_witnesses(subject, original)
    if search:
        subject.side = OriginalSide(original)
        subject.side.explore(time.process_time() + subject.timeout)


def _python_witnesses(subject: Subject, original: Model) -> WitnessSet:
    """The witnesses the original reaches, on the states the Python engine's check stores."""
    from .witness import declared
    if not declared(subject.model):
        return WitnessSet()
    with tempfile.TemporaryDirectory(prefix="safestate-mutate-") as tmp:
        tla, cfg = materialise(subject, None, Path(tmp))
        result = check_model(load_model(str(tla), str(cfg)), "python", subject.max_memory_mb, states=True)
    return witness_set(subject.model, original, states=result.states or [])


def classify_all(subject: Subject, mutants: list[Mutant], workers: int,
                 on_done: Callable[[Mutant, Outcome], None]) -> None:
    """Classifies every mutant in forked children, at most `workers` at once."""
    import gc
    prepare(subject)
    todo = list(mutants)
    running: dict[Connection, tuple[Mutant, int, float]] = {}
    # The original's graph and model are shared with every child: frozen, the children's
    # collector never walks (and so never copies) their pages.
    gc.collect()
    gc.freeze()
    try:
        while todo or running:
            while todo and len(running) < max(1, workers):
                m = todo.pop(0)
                conn, pid = _fork(subject, m)
                running[conn] = (m, pid, time.monotonic())
            ready = wait(list(running), timeout=1.0)
            for r in ready:
                assert isinstance(r, Connection)
                m, pid, t0 = running.pop(r)
                on_done(m, _receive(r, pid, m, t0))
            now = time.monotonic()
            for conn, (m, pid, t0) in list(running.items()):
                used = _cpu_seconds(pid)
                # The searches stop themselves at the budget; the check is ended from here.
                # A worker that uses no CPU (never expected) is ended at ten times the
                # budget in wall seconds.
                if (now - t0 if used is None else used) > subject.timeout + 30 or now - t0 > 10 * subject.timeout:
                    _end(pid)
                    conn.close()
                    del running[conn]
                    on_done(m, Outcome(m.id, "timeout", reason=f"check exceeded {subject.timeout:.0f} CPU s",
                                       seconds=now - t0, cpu=used or 0.0))
    finally:
        gc.unfreeze()
        for conn, (_m, pid, _t) in running.items():
            _end(pid)
            conn.close()


def _cpu_seconds(pid: int) -> float | None:
    """The CPU seconds (user + system) process `pid` used so far (Linux /proc); None
    where it cannot be read."""
    try:
        fields = Path(f"/proc/{pid}/stat").read_text().rsplit(")", 1)[1].split()
        return (int(fields[11]) + int(fields[12])) / os.sysconf("SC_CLK_TCK")
    except (OSError, ValueError, IndexError):
        return None


def _fork(subject: Subject, m: Mutant) -> tuple[Connection, int]:
    from multiprocessing import Pipe
    parent, child = Pipe(duplex=False)
    pid = os.fork()
    if pid == 0:  # the child: classify, send, exit without the parent's cleanup handlers
        code = 0
        try:
            _die_with_parent()
            parent.close()
            try:
                out = classify(subject, m)
            except Exception as e:  # noqa: BLE001 - reported as the mutant's error, never a traceback
                out = Outcome(m.id, "error", reason=f"internal error: {type(e).__name__}: {e}; "
                              + traceback.format_exc(limit=2).splitlines()[-1])
            child.send_bytes(json.dumps(out.to_json()).encode())
        except BaseException:  # noqa: BLE001
            code = 1
        finally:
            os._exit(code)
    child.close()
    return parent, pid


def _die_with_parent() -> None:
    """Linux: the child gets SIGKILL when the parent ends (killed, interrupted), so no
    worker outlives the run."""
    import ctypes
    import signal
    with contextlib.suppress(OSError, AttributeError):
        ctypes.CDLL("libc.so.6", use_errno=True).prctl(1, int(signal.SIGKILL))  # PR_SET_PDEATHSIG


def _receive(conn: Connection, pid: int, m: Mutant, t0: float) -> Outcome:
    try:
        out = Outcome.from_json(json.loads(conn.recv_bytes()))
    except (EOFError, OSError, ValueError):
        out = Outcome(m.id, "error", reason="the worker process ended without a result (out of memory?)",
                      seconds=time.monotonic() - t0)
    conn.close()
    os.waitpid(pid, 0)
    return out


def _end(pid: int) -> None:
    import signal
    with contextlib.suppress(ProcessLookupError, ChildProcessError):
        os.kill(pid, signal.SIGKILL)
        os.waitpid(pid, 0)
