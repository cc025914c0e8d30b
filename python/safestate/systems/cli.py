"""``safestate systems [--json]``: every registered system and the state of its parts.

A part is `ok` when its file exists (binding: importable; adapter: loads and is an
Adapter), `missing` when named but absent, `-` when the manifest names none.  The
mutation score is the last `safestate mutate SYSTEM` result (build/mutate/SYSTEM.json),
with what it was measured on and when; `-` when never measured.
"""

from __future__ import annotations

import argparse
import importlib
import json
import sys
from pathlib import Path
from typing import Any

from ..errors import SafestateError
from .registry import System, registry_dir, scan


def add_arguments(p: argparse.ArgumentParser) -> None:
    p.add_argument("--json", action="store_true", help="print one JSON object instead of a table")
    p.add_argument("--names", action="store_true", help="print only the names, one a line (for scripts)")
    p.add_argument("--with-conformance", action="store_true",
                   help="only the systems with a conformance adapter")


def _file(p: Path | None) -> str:
    if p is None:
        return "-"
    return "ok" if p.is_file() else "missing"


def _mutant_count(s: System) -> str:
    """How many mutants the system declares ("-": no file named, else why not)."""
    from .. import mutants

    if s.mutants is None:
        return "-"
    try:
        return str(len(mutants.of_system(s)))
    except mutants.MutationError as e:
        return f"error ({e})"


def _mutation(s: System) -> dict[str, Any] | None:
    """The system's last `safestate mutate` result (mutate/results.py), None if never measured."""
    from ..mutate import results

    d = results.read(s)
    if d is None:
        return None
    keys = ("score", "counts", "generated", "classified", "sampled", "sample", "seed", "when", "seconds", "gaps",
            "justified")
    return {k: d.get(k) for k in keys}


def _mutation_cell(m: dict[str, Any] | None) -> str:
    if m is None:
        return "-"
    sc = "n/a" if m.get("score") is None else f"{100 * m['score']:.1f}%"
    what = f"sample {m.get('classified')} seed {m.get('seed')}" if m.get("sampled") else "all"
    return f"{sc} ({what} of {m.get('generated')}, {str(m.get('when', '?'))[:10]})"


def status(s: System) -> dict[str, Any]:
    from ..conform.adapter import Adapter

    out: dict[str, Any] = {
        "name": s.name, "summary": s.summary, "manifest": str(s.manifest.relative_to(s.root)),
        "design": _file(s.design), "model": _file(s.model),
        "configs": "ok" if all(c.is_file() for c in s.configs) else "missing",
        "proofs": _file(s.proofs), "mutants": _mutant_count(s),
        "requirements": s.requirements, "mutation": _mutation(s),
    }
    if s.conformance is None:
        out["binding"] = out["adapter"] = "-"
        return out
    try:
        importlib.import_module(s.conformance.binding)
        out["binding"] = "ok"
    except ImportError as e:
        out["binding"] = f"not importable ({e})"
    try:
        cls = s.load_adapter_class()
        out["adapter"] = "ok" if issubclass(cls, Adapter) else "not an Adapter"
    except (SafestateError, ImportError, SyntaxError) as e:
        out["adapter"] = f"error ({e})"
    return out


def run(args: argparse.Namespace) -> int:
    from ..errors import run_guarded

    return run_guarded(lambda: _run(args), "the system registry", 2)


def _run(args: argparse.Namespace) -> int:
    every, broken = scan()
    code = _listing(args, [s for s in every if s.conformance is not None or not args.with_conformance])
    for e in broken:  # the others are listed; each unreadable manifest is one line and exit 2
        print(f"error: {e}", file=sys.stderr)
    return 2 if broken else code


def _listing(args: argparse.Namespace, systems: list[System]) -> int:
    if args.names:
        print("\n".join(s.name for s in systems))
        return 0
    rows = [status(s) for s in systems]
    if args.json:
        print(json.dumps({"registry": str(registry_dir()), "systems": rows}))
        return 0
    cols = ("name", "model", "configs", "proofs", "mutants", "binding", "adapter", "mutation score")
    for r in rows:
        r["mutation score"] = _mutation_cell(r["mutation"])
    print(f"registry: {registry_dir()}")
    w = {c: max([len(c)] + [len(str(r[c])) for r in rows]) for c in cols}
    print("  ".join(f"{c:<{w[c]}}" for c in cols) + "  requirements")
    for r in rows:
        reqs = r["requirements"]
        req = f"{reqs[0]}..{reqs[-1]} ({len(reqs)})" if len(reqs) > 2 else " ".join(reqs)
        print("  ".join(f"{str(r[c]):<{w[c]}}" for c in cols) + f"  {req}")
    return 0
