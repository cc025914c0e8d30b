#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""python/safestate/checker/native/ops.py from the core's op table, bindings/python/tla_native/ops.def.

The C++ core reads ops.def itself (an X-macro); the Python translator needs the same
numbers as a static enum (for mypy and for a package that runs without a build step), so
ops.py is generated from ops.def and checked in.  `--check` exits 1 when the checked-in
file differs from what ops.def gives (tests/python/test_native_ops_table.py runs it).

usage: scripts/gen_native_ops.py [--check]
"""

from __future__ import annotations

import argparse
import re
import sys
import textwrap
from pathlib import Path

REPO = Path(__file__).resolve().parents[1]
DEF = REPO / "bindings" / "python" / "tla_native" / "ops.def"
OPS_PY = REPO / "python" / "safestate" / "checker" / "native" / "ops.py"

_OP = re.compile(r'TLA_OP\((\w+), ([01]), "((?:[^"\\]|\\.)*)"\)$')
_SECTION = re.compile(r"// -- (.+)$")

HEADER = '''"""Op codes of the native core's program tree, and what each node holds.

Generated from bindings/python/tla_native/ops.def by scripts/gen_native_ops.py: edit
ops.def and run the script (tests/python/test_native_ops_table.py fails when this file
and ops.def differ).  At import the names are compared with the compiled core's.
"""

from __future__ import annotations

from enum import IntEnum

from ... import _tla_native as core


class Op(IntEnum):
'''

FOOTER = '''

if tuple(Op.__members__) != tuple(core.OP_NAMES):
    raise ImportError("checker/native/ops.py is out of step with the compiled native core "
                      "(rebuild it: scripts/setup.sh; or regenerate ops.py: scripts/gen_native_ops.py)")
'''


class DefError(ValueError):
    pass


def parse(text: str, name: str = "ops.def") -> list[tuple[str, str, bool, str]]:
    """(section, op name, folds, doc) per op, in order; a line that is neither a comment,
    blank nor an op is an error naming the line."""
    ops: list[tuple[str, str, bool, str]] = []
    section = ""
    for n, raw in enumerate(text.splitlines(), 1):
        line = raw.strip()
        if m := _SECTION.match(line):
            section = m.group(1)
            continue
        if not line or line.startswith("//"):
            continue
        m = _OP.match(line)
        if not m:
            raise DefError(f'{name}:{n}: expected TLA_OP(NAME, 0|1, "doc"), got {line!r}')
        doc = re.sub(r"\\(.)", r"\1", m.group(3))
        ops.append((section, m.group(1), m.group(2) == "1", doc))
    names = [op[1] for op in ops]
    dup = sorted({x for x in names if names.count(x) > 1})
    if dup:
        raise DefError(f"{name}: ops defined twice: {', '.join(dup)}")
    return ops


def render(text: str) -> str:
    lines: list[str] = []
    section = None
    for i, (sec, op, folds, doc) in enumerate(parse(text)):
        if sec != section:
            lines.append(f"    # {sec}")
            section = sec
        doc += " (folded when constant)" if folds else ""
        member = f"    {op} = {i}"
        if len(member) + 4 + len(doc) <= 120:
            lines.append(f"{member}  # {doc}")
        else:  # the doc above the member, wrapped
            lines += textwrap.wrap(doc, 116, initial_indent="    # ", subsequent_indent="    # ")
            lines.append(member)
    return HEADER + "\n".join(lines) + "\n" + FOOTER


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--check", action="store_true", help="exit 1 if ops.py differs from what ops.def gives")
    args = ap.parse_args()
    try:
        want = render(DEF.read_text())
    except DefError as e:
        print(f"gen_native_ops: {e}", file=sys.stderr)
        return 2
    if args.check:
        if OPS_PY.read_text() != want:
            print(f"gen_native_ops: {OPS_PY.relative_to(REPO)} differs from {DEF.relative_to(REPO)}; "
                  "run scripts/gen_native_ops.py", file=sys.stderr)
            return 1
        return 0
    OPS_PY.write_text(want)
    return 0


if __name__ == "__main__":
    sys.exit(main())
