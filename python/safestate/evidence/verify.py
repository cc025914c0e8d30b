"""`safestate evidence --verify DIR`: re-hashes every input and output the manifest
lists, notices files added to the package, and re-runs the cheap checks (the model
check of each system's CI cfg, compared with the recorded verdict and counts)."""

from __future__ import annotations

import json
import subprocess
from collections.abc import Callable
from pathlib import Path

from ..errors import UsageError
from .collect import safestate_argv, sha256_file
from .manifest import NAME

COUNTS = ("result", "distinct_states", "states_generated", "depth")


def _resolve(base: Path, name: str) -> Path:
    p = Path(name)
    return p if p.is_absolute() else base / p


# A recorded model check re-run by --verify that takes longer than this is stopped and
# reported as timed out (`safestate evidence --check-timeout`).
CHECK_TIMEOUT_SECONDS = 600.0


def _shape(mpath: Path, doc: object) -> str | None:
    """What is wrong with the manifest's structure (None: what verify reads is there)."""
    if not isinstance(doc, dict):
        return f"the manifest is a JSON {type(doc).__name__}, not an object"
    if not isinstance(doc.get("root"), str):
        return "'root' (the repository's path) is missing or not a string"
    for key in ("inputs", "outputs"):
        table = doc.get(key)
        if not isinstance(table, dict) or not all(isinstance(v, str) for v in table.values()):
            return f"'{key}' must be an object of file name -> SHA-256 string"
    checks = doc.get("checks", [])
    if not isinstance(checks, list):
        return "'checks' must be a list"
    for i, c in enumerate(checks):
        if not isinstance(c, dict) or not all(isinstance(c.get(k), str) for k in ("system", "model", "cfg")):
            return f"checks[{i}] must be an object with the strings 'system', 'model' and 'cfg'"
    return None


def verify(package: Path, root: Path | None, log: Callable[[str], None] = print,
           timeout: float = CHECK_TIMEOUT_SECONDS, timeouts: list[str] | None = None) -> list[str]:
    """Every difference, one line each (empty: the package is what it says).  A check
    that runs out of `timeout` seconds is no difference: it goes to `timeouts`."""
    mpath = package / NAME
    if not mpath.is_file():
        raise UsageError(f"{package}: no {NAME}: not an evidence package")
    try:
        doc = json.loads(mpath.read_text(encoding="utf-8"))
    except json.JSONDecodeError as e:
        return [f"{mpath}:{e.lineno}:{e.colno}: not valid JSON ({e.msg})"]
    except (UnicodeDecodeError, RecursionError) as e:
        return [f"{mpath}: not a JSON manifest ({type(e).__name__})"]
    wrong = _shape(mpath, doc)
    if wrong:
        return [f"{mpath}: malformed manifest: {wrong}"]
    base = root or Path(doc["root"])
    diffs: list[str] = []
    for name, digest in doc["inputs"].items():
        p = _resolve(base, name)
        if not p.is_file():
            diffs.append(f"input {name}: missing")
        elif sha256_file(p) != digest:
            diffs.append(f"input {name}: SHA-256 differs from the manifest")
    listed = set(doc["outputs"])
    for name, digest in doc["outputs"].items():
        p = package / name
        if not p.is_file():
            diffs.append(f"output {name}: missing")
        elif sha256_file(p) != digest:
            diffs.append(f"output {name}: SHA-256 differs from the manifest")
    for p in sorted(package.rglob("*")):
        rel = str(p.relative_to(package))
        if p.is_file() and rel != NAME and rel not in listed:
            diffs.append(f"output {rel}: not in the manifest")
    for c in doc.get("checks", []):
        log(f"verify: model check of {c['system']} ({c['model']} with {c['cfg']})")
        try:
            run = subprocess.run(safestate_argv("check", str(_resolve(base, c["model"])), "--config",
                                              str(_resolve(base, c["cfg"])), "--json"),
                               capture_output=True, text=True, cwd=base, timeout=timeout)
        except subprocess.TimeoutExpired:
            line = f"check {c['system']}: timed out after {timeout:g} s (raise it with --check-timeout)"
            if timeouts is None:
                diffs.append(line)
            else:
                timeouts.append(line)
            continue
        try:
            got = json.loads(run.stdout.strip().splitlines()[-1])
        except (json.JSONDecodeError, IndexError):
            diffs.append(f"check {c['system']}: no result (exit {run.returncode}): {run.stderr.strip()[:200]}")
            continue
        for k in COUNTS:
            if got.get(k) != c.get(k):
                diffs.append(f"check {c['system']}: {k} is {got.get(k)}, the package says {c.get(k)}")
    return diffs
