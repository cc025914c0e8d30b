"""manifest.json of the evidence package: SHA-256 of every input and every output,
the tool versions, the machine and the date."""

from __future__ import annotations

import datetime
import json
import platform
import subprocess
import sys
from importlib import metadata
from pathlib import Path
from typing import Any

from .collect import sha256_file
from .sources import rel

NAME = "manifest.json"


def _cmd(argv: list[str]) -> str:
    try:
        p = subprocess.run(argv, capture_output=True, text=True, timeout=30)
    except (OSError, subprocess.TimeoutExpired):
        return "not found"
    return (p.stdout or p.stderr).strip().splitlines()[0] if (p.stdout or p.stderr).strip() else "unknown"


def _dist(name: str) -> str:
    try:
        return metadata.version(name)
    except metadata.PackageNotFoundError:
        return "not installed"


def tool_versions(root: Path) -> dict[str, str]:
    commit = _cmd(["git", "-C", str(root), "rev-parse", "HEAD"])
    dirty = _cmd(["git", "-C", str(root), "status", "--porcelain", "--untracked-files=no"])
    return {
        "safestate_commit": commit + (" (with uncommitted changes)" if dirty not in ("", "unknown", "not found") else ""),
        "python": sys.version.split()[0],
        "z3": _dist("z3-solver"),
        "tree-sitter": _dist("tree-sitter"),
        "tree-sitter-tlaplus": _dist("tree-sitter-tlaplus"),
        "hypothesis": _dist("hypothesis"),
        "pytest": _dist("pytest"),
        "gcovr": _dist("gcovr"),
        "compiler": _cmd(["c++", "--version"]),
        "cmake": _cmd(["cmake", "--version"]),
        "graphviz": _cmd(["dot", "-V"]),
    }


def now() -> str:
    return datetime.datetime.now(datetime.timezone.utc).isoformat(timespec="seconds")


def machine() -> dict[str, str]:
    return {"hostname": platform.node(), "system": platform.platform(), "machine": platform.machine(),
            "processor": platform.processor() or platform.machine()}


def hashes(files: list[Path], base: Path) -> dict[str, str]:
    return {rel(base, f): sha256_file(f) for f in sorted(set(files)) if f.is_file()}


def write(out: Path, root: Path, inputs: list[Path], extra: dict[str, Any]) -> dict[str, Any]:
    """Hashes every file under `out` (but the manifest) and every input; writes the manifest."""
    outputs = [f for f in sorted(out.rglob("*")) if f.is_file() and f.name != NAME]
    doc = {
        "format": "safestate evidence manifest 1",
        "date": now(),
        "root": str(root),
        "tools": tool_versions(root),
        "machine": machine(),
        "inputs": hashes(inputs, root),
        "outputs": hashes(outputs, out),
        **extra,
    }
    (out / NAME).write_text(json.dumps(doc, indent=1, sort_keys=False) + "\n", encoding="utf-8")
    return doc
