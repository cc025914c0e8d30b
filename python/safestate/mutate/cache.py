"""The outcome cache: one JSON file per (mutant text, cfgs, projection, checker version).

The key hashes the mutated model's modules (the spec and every module of its folder it
names, transitively: a superset of what EXTENDS and INSTANCE load; the mutant applied), so
a change to another system's model keeps this one's outcomes; the cfg as used (invariants the original violates left out) and the screening
cfg as used (or that there is none: an outcome decided without screening is not one
decided with it, and the other way round -- the `cfg` it names differs), the inputs and
observables, the budgets, and the sources of the checker and of the classifier (their
"version": any change to the checker gives new keys).  Timeouts and errors of the worker
itself are not cached, so a later run with a larger budget retries them.

The original's own check (the invariants it violates, the witnesses it reaches) is cached
beside the outcomes under `originals/`, keyed the same way with no mutant applied (and
the CLI's source, which decides what is checked of it): a re-run whose every outcome is
cached checks nothing.

Folder: $SAFESTATE_CACHE_DIR/mutate, else $XDG_CACHE_HOME/safestate/mutate, else
~/.cache/safestate/mutate.
"""

from __future__ import annotations

import hashlib
import json
import os
import re
from dataclasses import dataclass
from functools import lru_cache
from pathlib import Path

from .. import __version__
from .classify import Outcome, Subject, without_invariants
from .generate import Mutant

CACHE_ENV = "SAFESTATE_CACHE_DIR"
_PACKAGE = Path(__file__).resolve().parent.parent
# What decides an outcome: the checker, the front end, the classifier, the product
# search and the witnesses (with the definitions each reads, from generate.py); the
# mutant's own text is in the key; the report and the CLI are not.
_SOURCES = ("checker", "tla", "mutate/classify.py", "mutate/product.py", "mutate/graph.py", "mutate/witness.py",
            "mutate/generate.py")


def cache_dir() -> Path:
    env = os.environ.get(CACHE_ENV)
    if env:
        return Path(env) / "mutate"
    base = os.environ.get("XDG_CACHE_HOME") or os.path.join(os.path.expanduser("~"), ".cache")
    return Path(base) / "safestate" / "mutate"


@lru_cache(maxsize=1)
def checker_version() -> str:
    """safestate's version and a hash of the sources that decide an outcome."""
    h = hashlib.sha256(__version__.encode())
    for sub in _SOURCES:
        path = _PACKAGE / sub
        for f in sorted(path.rglob("*.py")) if path.is_dir() else [path]:
            h.update(str(f.relative_to(_PACKAGE)).encode() + b"\0" + f.read_bytes() + b"\0")
    try:
        from .. import _tla_native  # type: ignore[attr-defined]
        h.update(Path(_tla_native.__file__).read_bytes())
    except (ImportError, OSError, AttributeError):
        pass
    return h.hexdigest()[:16]


@dataclass(frozen=True)
class OriginalRecord:
    """What checking the original found: the invariants it violates itself (left out of
    every mutant's cfg) and the witnesses it reaches and does not reach."""

    dropped: tuple[str, ...]
    witnesses: tuple[str, ...]
    not_reached: tuple[str, ...]


def key(subject: Subject, mutant: Mutant) -> str:
    return _key(subject, mutant, subject.dropped)


def original_key(subject: Subject) -> str:
    h = hashlib.sha256((_PACKAGE / "mutate" / "cli.py").read_bytes())
    h.update(_key(subject, None, ()).encode())
    return h.hexdigest()


_WORD = re.compile(rb"[A-Za-z0-9_]+")


def module_closure(model: Path) -> list[Path]:
    """The spec and every .tla of its folder whose module name occurs as a word in a module
    already included, transitively: each module EXTENDS or INSTANCE can load is one of them
    (a name in a comment only adds a file, never leaves one out)."""
    local = {f.stem.encode(): f for f in model.parent.glob("*.tla") if f.is_file()}
    seen = {model.resolve()}
    todo, out = [model], [model]
    while todo:
        for word in set(_WORD.findall(todo.pop().read_bytes())):
            f = local.get(word)
            if f is not None and f.resolve() not in seen:
                seen.add(f.resolve())
                todo.append(f)
                out.append(f)
    return sorted(out, key=lambda f: f.name)


def _key(subject: Subject, mutant: Mutant | None, dropped: tuple[str, ...]) -> str:
    h = hashlib.sha256()
    for f in module_closure(subject.model):
        data = f.read_bytes()
        if mutant is not None and f.name == mutant.file:
            data = mutant.apply(data)
        h.update(f.name.encode() + b"\0" + data + b"\0")
    cfg = without_invariants(subject.cfg.read_text(encoding="utf-8"), dropped)
    h.update(b"cfg\0" + subject.model.name.encode() + b"\0" + cfg.encode())
    if subject.screen is None:
        h.update(b"no screen\0")
    else:
        screen = without_invariants(subject.screen.read_text(encoding="utf-8"), dropped)
        h.update(b"screen\0" + subject.screen.name.encode() + b"\0" + screen.encode())
    p = subject.projection
    h.update(json.dumps([p.inputs, p.observables, subject.engine, subject.timeout, subject.max_pairs]).encode())
    h.update(checker_version().encode())
    return h.hexdigest()


class Cache:
    def __init__(self, folder: Path | None, enabled: bool = True) -> None:
        self.folder = folder or cache_dir()
        self.enabled = enabled

    def get(self, subject: Subject, mutant: Mutant) -> Outcome | None:
        if not self.enabled:
            return None
        f = self.folder / f"{key(subject, mutant)}.json"
        try:
            out = Outcome.from_json(json.loads(f.read_text(encoding="utf-8")))
        except (OSError, ValueError, TypeError):
            return None
        out.mutant = mutant.id
        out.cached = True
        return out

    def put(self, subject: Subject, mutant: Mutant, out: Outcome) -> None:
        if not self.enabled or (out.status == "error" and out.reason.startswith(("internal error", "the worker"))):
            return
        if out.status == "timeout" and "exceeded" in out.reason:
            return
        self._write(self.folder / f"{key(subject, mutant)}.json", out.to_json())

    def get_original(self, subject: Subject) -> OriginalRecord | None:
        if not self.enabled:
            return None
        try:
            d = json.loads((self.folder / "originals" / f"{original_key(subject)}.json").read_text(encoding="utf-8"))
            return OriginalRecord(tuple(d["dropped"]), tuple(d["witnesses"]), tuple(d["not_reached"]))
        except (OSError, ValueError, TypeError, KeyError):
            return None

    def put_original(self, subject: Subject, record: OriginalRecord) -> None:
        if self.enabled:
            self._write(self.folder / "originals" / f"{original_key(subject)}.json",
                        {"dropped": list(record.dropped), "witnesses": list(record.witnesses),
                         "not_reached": list(record.not_reached)})

    def _write(self, path: Path, data: object) -> None:
        try:
            path.parent.mkdir(parents=True, exist_ok=True)
            tmp = path.parent / f".{os.getpid()}.tmp"
            tmp.write_text(json.dumps(data), encoding="utf-8")
            tmp.replace(path)
        except OSError:
            pass  # a read-only cache folder costs time, never a result
