"""TLC's integers are 32-bit Java ints: a numeral above 2^31 - 1 anywhere in a module
(used or not) stops TLC before the search ("TLC can't handle a number this big.",
EC.TLC_INTEGER_TOO_BIG, exit 255); SpecProcessor checks every definition's constants."""

from __future__ import annotations

import dataclasses
from collections.abc import Iterable

from ..tla import ast as A
from ..tla.errors import Loc, TlaError

TLC_MAX_INT = 2**31 - 1


def check_numerals(modules: Iterable[A.Module]) -> None:
    """Raise TLC's error for the first numeral (in source order) TLC cannot represent."""
    for module in modules:
        big = _first_too_big(module)
        if big is not None:
            raise TlaError("integer too big", f"TLC can't handle a number this big: {big.value} (TLC's integers "
                           f"are 32-bit, at most {TLC_MAX_INT})", big.loc)


def _first_too_big(root: object) -> A.Num | None:
    found: list[A.Num] = []
    stack: list[object] = [root]
    seen: set[int] = set()
    while stack:
        node = stack.pop()
        if isinstance(node, A.Num):
            if node.value > TLC_MAX_INT:
                found.append(node)
            continue
        if isinstance(node, (str, int, float, bool, bytes, Loc)) or node is None or id(node) in seen:
            continue
        seen.add(id(node))
        if isinstance(node, dict):
            stack.extend(node.values())
        elif isinstance(node, (list, tuple, set, frozenset)):
            stack.extend(node)
        elif dataclasses.is_dataclass(node):
            stack.extend(getattr(node, f.name, None) for f in dataclasses.fields(node))
    if not found:
        return None
    return min(found, key=lambda n: (n.loc.file, n.loc.line, n.loc.column))
