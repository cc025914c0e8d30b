"""The model's reachable state graph with one edge per transition (state, event).

Built by the checker (`explore_states(model, graph=True)`) or read from the JSON
that `safestate check --graph FILE` writes.  The checker lists an edge once per
way Next produces it; a transition is the pair (source node, event), so duplicates
are merged here (and a pair with two different successors is an error: the model
would not be deterministic per event).
"""

from __future__ import annotations

import fcntl
import hashlib
import json
import os
import pickle
from contextlib import contextmanager
from dataclasses import dataclass
from pathlib import Path
from typing import Callable, Iterable, Iterator, TypeVar

from ..checker.explore import CheckResult, explore_states
from ..checker.model import Model
from ..checker.native import native_core_sources
from ..errors import SafestateError
from .cover import Graph
from .events import Event
from .json_input import load_json
from .native_graph import native_graph


@dataclass
class StateGraph:
    states: list[tuple]       # one representative state per node (the first found)
    initial: list[int]
    src: list[int]
    dst: list[int]
    events: list[Event]

    def as_cover_graph(self) -> Graph:
        return Graph(len(self.states), self.initial, self.src, self.dst)


class NondeterministicEvent(SafestateError):
    pass


class GraphFileError(SafestateError):
    """A --graph file that is not a state graph of this model."""


def _dedup(states: list[tuple], initial: list[int], raw: Iterable[tuple[int, int, Event]]) -> StateGraph:
    seen: dict[tuple[int, Event], int] = {}
    g = StateGraph(states, initial, [], [], [])
    for s, d, ev in raw:
        k = (s, ev)
        if k in seen:
            if seen[k] != d:
                raise NondeterministicEvent(f"node {s}: event {ev} leads to nodes {seen[k]} and {d}")
            continue
        seen[k] = d
        g.src.append(s)
        g.dst.append(d)
        g.events.append(ev)
    return g


def explore(model: Model, progress=None) -> StateGraph:  # type: ignore[no-untyped-def]
    """The graph from the native core when it accepts the model (the same graph, several
    times faster), else from the Python engine ($SAFESTATE_GRAPH_ENGINE=python: always,
    to compare the two)."""
    forced = os.environ.get(GRAPH_ENGINE_ENV) == "python"
    native = f"${GRAPH_ENGINE_ENV}=python" if forced else native_graph(model, progress)
    if not isinstance(native, str):
        if progress:
            progress("conform: state graph built by the native engine")
        _require_success(native.result)
        return _dedup(native.states, native.initial, native.raw_edges())
    if progress:
        progress(f"conform: state graph built by the Python engine ({native})")
    return explore_python(model, progress)


def explore_python(model: Model, progress=None) -> StateGraph:  # type: ignore[no-untyped-def]
    """The graph from the Python engine alone (the reference the native graph is tested against)."""
    res = explore_states(model, workers=1, graph=True, progress=progress)
    _require_success(res)
    assert res.states is not None and res.edges is not None and res.initial is not None
    return _dedup(res.states, list(res.initial), ((e.src, e.dst, Event.of(e.action, e.params)) for e in res.edges))


def _require_success(res: CheckResult) -> None:
    if res.result != "success":
        raise SafestateError(f"model checking did not succeed: {res.result} {res.violated or ''} "
                           f"{res.error.message if res.error else ''}".strip())


CACHE_ENV = "SAFESTATE_CACHE_DIR"
GRAPH_ENGINE_ENV = "SAFESTATE_GRAPH_ENGINE"
CHECKER_SOURCES = ("checker", "tla", "conform/graph.py", "conform/events.py", "conform/native_graph.py",
                   "conform/native_events.py")


def cache_dir() -> Path:
    env = os.environ.get(CACHE_ENV)
    if env:
        return Path(env)
    base = os.environ.get("XDG_CACHE_HOME") or os.path.join(os.path.expanduser("~"), ".cache")
    return Path(base) / "safestate" / "graphs"


def graph_key(model: Model) -> str:
    """A hash of the model (every .tla and .cfg beside its module, and every module it
    read from another folder), its cfg file and the checker's own sources (its
    'version'): a change to any gives a new key.  Contents and file names only, never
    absolute paths."""
    h = hashlib.sha256()
    folder = Path(model.module.file).resolve().parent
    beside = list(folder.glob("*.tla")) + list(folder.glob("*.cfg"))
    elsewhere = [Path(f).resolve() for f in model.module_files if Path(f).resolve().parent != folder]
    for f in sorted(beside) + sorted(elsewhere):
        h.update(f.name.encode() + b"\0" + f.read_bytes() + b"\0")
    cfg = Path(model.config.file)
    # The cfg by name and text, not by its absolute path: a fresh clone in another folder
    # (a CI run) reuses the graph of an earlier one (the graph holds no paths).
    h.update(cfg.name.encode() + b"\0" + cfg.read_bytes())
    pkg = Path(__file__).resolve().parents[1]
    for name in CHECKER_SOURCES:
        p = pkg / name
        for f in sorted(p.rglob("*.py")) if p.is_dir() else [p]:
            h.update(str(f.relative_to(pkg)).encode() + b"\0" + f.read_bytes())
    for f in native_core_sources():  # the graph is built by the core (an installed package keys on Python alone)
        h.update(b"native core\0" + f.name.encode() + b"\0" + f.read_bytes())
    return h.hexdigest()[:32]


def cached_explore(model: Model, progress=None) -> StateGraph:  # type: ignore[no-untyped-def]
    """`explore`, reusing the graph of an earlier run with the same `graph_key`."""
    path = cache_dir() / f"{Path(model.module.file).stem}-{graph_key(model)}.pickle"
    return cached_pickle(path, StateGraph, lambda: explore(model, progress=progress), "state graph", progress)


T = TypeVar("T")


def cached_pickle(path: Path, kind: type[T], build: Callable[[], T], what: str, progress=None) -> T:  # type: ignore[no-untyped-def]
    """The object pickled at `path`, else `build()` written there.  Safe for parallel
    processes (pytest-xdist workers): one builds while holding a lock beside the cache file,
    the others wait and then read its result; the file appears atomically."""
    obj = _read_cached(path, kind, what, progress)
    if obj is not None:
        return obj
    with _exploring(path):
        obj = _read_cached(path, kind, what, progress)  # another process may have written it meanwhile
        if obj is not None:
            return obj
        obj = build()
        try:
            tmp = path.with_suffix(f".{os.getpid()}.tmp")
            with open(tmp, "wb") as f:
                pickle.dump(obj, f, protocol=pickle.HIGHEST_PROTOCOL)
            os.replace(tmp, path)
            evict_least_recent(path.parent, keep=path)
        except OSError:
            pass  # a read-only cache only costs time
    return obj


CACHE_MAX_ENV = "SAFESTATE_CACHE_MAX_MB"
CACHE_MAX_MB = 1024  # about a dozen versions of every registered system's graphs and plans


def evict_least_recent(folder: Path, keep: Path) -> None:
    """Deletes the least recently used cache files (their modification time: a read
    touches the file) until the folder's pickles fit in $SAFESTATE_CACHE_MAX_MB (1024);
    `keep`, just written, stays.  Every commit of the checker gives new keys, so without
    this the folder only grows (3.9 GB after one day of development)."""
    try:
        limit = int(os.environ.get(CACHE_MAX_ENV, CACHE_MAX_MB)) * 1024 * 1024
    except ValueError:
        limit = CACHE_MAX_MB * 1024 * 1024
    files = []
    for f in folder.glob("*.pickle"):
        try:
            st = f.stat()
        except OSError:
            continue  # removed by another process meanwhile
        files.append((st.st_mtime, st.st_size, f))
    total = sum(size for _, size, _ in files)
    for _, size, f in sorted(files, key=lambda t: t[0]):
        if total <= limit:
            break
        if f == keep:
            continue
        for stale in (f, f.with_suffix(".lock")):
            try:
                stale.unlink()
            except OSError:
                pass
        total -= size


def _read_cached(path: Path, kind: type[T], what: str, progress) -> T | None:  # type: ignore[no-untyped-def]
    try:
        with open(path, "rb") as f:
            obj = pickle.load(f)
    except (OSError, pickle.UnpicklingError, EOFError, AttributeError):
        return None
    if not isinstance(obj, kind):
        return None
    try:
        os.utime(path)  # most recently used: evict_least_recent keeps it longest
    except OSError:
        pass
    if progress:
        progress(f"conform: {what} from the cache {path}")
    return obj


@contextmanager
def _exploring(path: Path) -> Iterator[None]:
    """An exclusive lock on `path`.lock for the time of one build (none when the cache
    folder cannot be written: then each process builds on its own)."""
    try:
        path.parent.mkdir(parents=True, exist_ok=True)
        lock = open(path.with_suffix(".lock"), "a")
    except OSError:
        yield
        return
    with lock:
        fcntl.flock(lock, fcntl.LOCK_EX)
        try:
            yield
        finally:
            fcntl.flock(lock, fcntl.LOCK_UN)


def load(model: Model, path: str) -> StateGraph:
    doc = load_json(path, "state graph")
    if not isinstance(doc, dict) or not all(k in doc for k in ("vars", "states", "edges", "initial")):
        raise GraphFileError(f"{path}: not a state graph written by `safestate check --graph` "
                             f"(expected an object with vars, states, edges, initial)")
    if doc["vars"] != list(model.variables):
        raise GraphFileError(f"{path}: the graph's variables {doc['vars']} differ from the model's "
                             f"{list(model.variables)}")
    try:
        states = [model.state_from_itf(s["state"]) for s in doc["states"]]
    except (KeyError, TypeError, ValueError) as e:
        raise GraphFileError(f"{path}: a state is not an ITF state of the model ({type(e).__name__}: {e})") from None
    cache: dict[str, Event] = {}
    raw = []
    for i, edge in enumerate(doc["edges"]):
        try:
            key = edge["action"] + json.dumps(edge["params"], sort_keys=True)
            ev = cache.get(key)
            if ev is None:
                ev = cache[key] = Event.from_itf(edge["action"], edge["params"])
            src, dst = int(edge["from"]), int(edge["to"])
        except (KeyError, TypeError, ValueError) as x:
            raise GraphFileError(f"{path}: edge {i} is not {{from, to, action, params}} ({type(x).__name__}: {x})") from None
        if not (0 <= src < len(states) and 0 <= dst < len(states)):
            raise GraphFileError(f"{path}: edge {i} names a state outside 0..{len(states) - 1}")
        raw.append((src, dst, ev))
    return _dedup(states, list(doc["initial"]), raw)
