"""The outcome cache: one JSON file per (mutant text, cfg, projection, checker version).

The key hashes the mutated model's files (every .tla and .cfg of its folder, the mutant
applied), the cfg as used (invariants the original violates left out), the inputs and
observables, the budgets, and the sources of the checker and of the classifier (their
"version": any change to the checker gives new keys).  Timeouts and errors of the worker
itself are not cached, so a later run with a larger budget retries them.

Folder: $SAFESTATE_CACHE_DIR/mutate, else $XDG_CACHE_HOME/safestate/mutate, else
~/.cache/safestate/mutate.
"""

from __future__ import annotations

import hashlib
import json
import os
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


def key(subject: Subject, mutant: Mutant) -> str:
    h = hashlib.sha256()
    for f in sorted(subject.model.parent.iterdir()):
        if f.is_file() and f.suffix in (".tla", ".cfg"):
            data = f.read_bytes()
            if f.name == mutant.file:
                data = mutant.apply(data)
            h.update(f.name.encode() + b"\0" + data + b"\0")
    cfg = without_invariants(subject.cfg.read_text(encoding="utf-8"), subject.dropped)
    h.update(b"cfg\0" + subject.model.name.encode() + b"\0" + cfg.encode())
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
        try:
            self.folder.mkdir(parents=True, exist_ok=True)
            tmp = self.folder / f".{os.getpid()}.tmp"
            tmp.write_text(json.dumps(out.to_json()), encoding="utf-8")
            tmp.replace(self.folder / f"{key(subject, mutant)}.json")
        except OSError:
            pass  # a read-only cache folder costs time, never a result
