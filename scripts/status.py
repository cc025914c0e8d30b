#!/usr/bin/env python3
"""Write docs/status.md: the figures that change with the code, read from the repository's data.

    python scripts/status.py              # write docs/status.md
    python scripts/status.py --check      # exit 1 if docs/status.md differs from what would be written
    python scripts/status.py --collect    # also count the tests (pytest --collect-only, ctest -N)

Every figure comes from a data file the tools themselves read: models/expected.json (TLC's
figures that the tests pin), systems/*/system.toml (the registry), proofs/*.toml (the proof
plans), models/mutants/*.toml (the model mutants), conform/cpp_mutants/mutants.toml and
tests/tla/*/expected.json (the checker's corpus).  Without --collect nothing is run, so the
check is cheap enough for the test command (tests/python/test_docs_status.py); the test
counts need a collection, so they are kept from the existing file unless --collect is given.

Exit codes: 0 written or current, 1 stale (--check), 2 bad input (a data file that does not
parse, a collection that fails), each with one line naming the file.
"""

from __future__ import annotations

import argparse
import difflib
import json
import re
import subprocess
import sys
import tomllib
from dataclasses import dataclass
from pathlib import Path
from typing import Any

ROOT = Path(__file__).resolve().parent.parent
OUT = Path("docs/status.md")
BEGIN = "<!-- collected: begin -->"
END = "<!-- collected: end -->"
CORPORA = ("corpus", "errors", "liveness", "tableau", "realworld/specs", "realworld/errors")


class DataError(Exception):
    """A data file that cannot be read; the message names it."""


@dataclass(frozen=True)
class System:
    name: str
    model: str
    requirements: tuple[str, ...]
    proofs: int
    mutants: int
    conformance: bool
    expected_check: str


def _rel(path: Path) -> str:
    try:
        return str(path.relative_to(ROOT))
    except ValueError:
        return str(path)


def _toml(path: Path) -> dict[str, Any]:
    try:
        with path.open("rb") as f:
            return tomllib.load(f)
    except (OSError, tomllib.TOMLDecodeError) as e:
        raise DataError(f"{_rel(path)}: {e}") from None


def _json(path: Path) -> Any:
    try:
        return json.loads(path.read_text(encoding="utf-8"))
    except (OSError, json.JSONDecodeError) as e:
        raise DataError(f"{_rel(path)}: {e}") from None


def _count(root: Path, rel: str, key: str) -> int:
    """Number of [[key]] tables in the TOML file rel (0 when rel is empty)."""
    if not rel:
        return 0
    entries = _toml(root / rel).get(key, [])
    return len(entries) if isinstance(entries, list) else 0


def systems(root: Path) -> list[System]:
    out = []
    for manifest in sorted((root / "systems").glob("*/system.toml")):
        d = _toml(manifest)
        out.append(System(
            name=str(d.get("name", manifest.parent.name)),
            model=str(d.get("model", "")),
            requirements=tuple(str(r) for r in d.get("requirements", [])),
            proofs=_count(root, str(d.get("proofs", "")), "proof"),
            mutants=_count(root, str(d.get("mutants", "")), "mutant"),
            conformance="conformance" in d,
            expected_check=str(d.get("expected_check", "")),
        ))
    return out


def _n(v: object) -> str:
    return f"{v:,}" if isinstance(v, int) else str(v)


def model_rows(root: Path) -> list[str]:
    rows = ["| cfg | model | verdict | distinct states | states generated | depth |", "|---|---|---|--:|--:|--:|"]
    for key, v in _json(root / "models/expected.json").items():
        rows.append(f"| `{key}` | `models/{v.get('model', key)}.tla` | {v.get('result', '?')} | {_n(v.get('distinct_states', '?'))}"
                    f" | {_n(v.get('states_generated', '?'))} | {_n(v.get('depth', '?'))} |")
    return rows


def unregistered(root: Path, found: list[System]) -> str:
    """Proof plans and mutant files that no system.toml names (checked by their own tests)."""
    named = set()
    for manifest in sorted((root / "systems").glob("*/system.toml")):
        d = _toml(manifest)
        named |= {str(d.get("proofs", "")), str(d.get("mutants", ""))}
    extra = [f"`{p}` ({_count(root, p, key)})" for pattern, key in (("proofs/*.toml", "proof"), ("models/mutants/*.toml", "mutant"))
             for p in (str(f.relative_to(root)) for f in sorted(root.glob(pattern))) if p not in named]
    return ("Not in a registered system: " + ", ".join(extra) + ".") if extra else ""


def system_rows(found: list[System]) -> list[str]:
    rows = ["| system | model | requirements | proofs declared | model mutants | conformance |", "|---|---|---|--:|--:|---|"]
    for s in found:
        model = f"`{s.model}`" + (f" (expected: {s.expected_check})" if s.expected_check else "")
        reqs = f"{len(s.requirements)}: " + ", ".join(s.requirements)
        rows.append(f"| {s.name} | {model} | {reqs} | {s.proofs} | {s.mutants} | {'yes' if s.conformance else 'no'} |")
    return rows


def corpus_rows(root: Path) -> list[str]:
    rows = ["| folder | specs with TLC's recorded figures |", "|---|--:|"]
    for rel in CORPORA:
        path = root / "tests/tla" / rel / "expected.json"
        if path.exists():
            rows.append(f"| `tests/tla/{rel}/` | {len(_json(path))} |")
    return rows


def collect(root: Path, build_dir: Path) -> list[str]:
    """The test counts, by collection: pytest --collect-only and ctest -N (nothing is run)."""
    py = subprocess.run([sys.executable, "-m", "pytest", "--collect-only", "-q", "-p", "no:cacheprovider"],
                        cwd=root, capture_output=True, text=True)
    m = re.search(r"^(\d+) tests? collected", py.stdout, re.MULTILINE)
    if py.returncode != 0 or not m:
        raise DataError(f"pytest --collect-only failed (exit {py.returncode}): {py.stdout.strip().splitlines()[-1:]}")
    ct = subprocess.run(["ctest", "-N", "--test-dir", str(build_dir)], cwd=root, capture_output=True, text=True)
    c = re.search(r"Total Tests: (\d+)", ct.stdout)
    if ct.returncode != 0 or not c:
        raise DataError(f"ctest -N --test-dir {build_dir}: no test count (build the C++ tree first: bash scripts/setup.sh)")
    return ["| suite | tests | counted by |", "|---|--:|---|",
            f"| pytest (`tests/python/`) | {int(m.group(1)):,} | `pytest --collect-only -q` |",
            f"| GoogleTest and the other ctest cases (`build/cpp`) | {int(c.group(1)):,} | `ctest -N --test-dir build/cpp` |"]


def kept_collection(current: str) -> list[str]:
    """The collected block of the existing file, unchanged (the counts need a collection to renew)."""
    if BEGIN in current and END in current:
        block = current.split(BEGIN, 1)[1].split(END, 1)[0]
        return block.strip("\n").splitlines()
    return ["Not counted yet: `python scripts/status.py --collect`."]


def render(root: Path, collected: list[str]) -> str:
    found = systems(root)
    reqs = sorted({r for s in found for r in s.requirements})
    cpp_mutants = _count(root, "conform/cpp_mutants/mutants.toml", "mutant")
    lines = [
        "# Status: the figures that change with the code",
        "",
        "Generated by `python scripts/status.py` from the repository's data files; do not edit by hand.",
        "`python scripts/status.py --check` (run by the test command, `tests/python/test_docs_status.py`)",
        "fails when this page is stale.",
        "",
        "## Registered systems (`systems/*/system.toml`)",
        "",
        *system_rows(found),
        "",
        f"{len(found)} systems; {len(reqs)} distinct requirement IDs; {sum(s.proofs for s in found)} proofs declared"
        " (`[[proof]]` entries of `proofs/*.toml`, one per invariant);"
        f" {sum(s.mutants for s in found)} model mutants in the systems' files (`models/mutants/*.toml`);"
        f" {cpp_mutants} hand-written C++ mutants (`conform/cpp_mutants/mutants.toml`).",
        unregistered(root, found),
        "",
        "## Model checks: TLC's figures, pinned by the tests (`models/expected.json`)",
        "",
        "`safestate check` must give these for each CI cfg (`tests/python/test_models.py`); the",
        "figures were recorded with TLC 1.8.0 (`-workers 1`).",
        "",
        *model_rows(root),
        "",
        "## The checker's corpus (`tests/tla/*/expected.json`)",
        "",
        *corpus_rows(root),
        "",
        "## Tests, by collection",
        "",
        "Counted by `python scripts/status.py --collect` (nothing is run; `--check` keeps these lines).",
        "",
        BEGIN,
        *collected,
        END,
        "",
    ]
    return "\n".join(lines)


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0] if __doc__ else None)
    ap.add_argument("--check", action="store_true", help="exit 1 if docs/status.md is stale; write nothing")
    ap.add_argument("--collect", action="store_true", help="count the tests too (pytest --collect-only, ctest -N)")
    ap.add_argument("--root", type=Path, default=ROOT, help="the repository (default: this script's)")
    ap.add_argument("--build-dir", type=Path, default=Path("build/cpp"), help="the C++ build tree for ctest -N")
    args = ap.parse_args(argv)
    root: Path = args.root.resolve()
    out = root / OUT
    current = out.read_text(encoding="utf-8") if out.exists() else ""
    try:
        collected = collect(root, args.build_dir) if args.collect else kept_collection(current)
        text = render(root, collected)
    except DataError as e:
        print(f"status.py: {e}", file=sys.stderr)
        return 2
    if args.check:
        if text == current:
            print(f"{OUT}: current")
            return 0
        diff = difflib.unified_diff(current.splitlines(), text.splitlines(), str(OUT), "generated", lineterm="", n=0)
        print(f"{OUT} is stale; run: python scripts/status.py", file=sys.stderr)
        print("\n".join(list(diff)[:40]), file=sys.stderr)
        return 1
    out.write_text(text, encoding="utf-8")
    print(f"wrote {OUT}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
