"""Delta debugging (Zeller's ddmin) on the lines of a spec and its cfg.

A candidate keeps a subset of the removable lines (everything but the module
header and footer); it is kept when the test still fails the same way (the
caller's `still_fails`, e.g. "TLC and we still differ on the same fields").
Candidates that no longer parse simply do not fail the same way.
"""

from __future__ import annotations

from typing import Callable


def ddmin(items: list, still_fails: Callable[[list], bool]) -> list:
    """A 1-minimal sublist of `items` (in order) for which `still_fails` holds."""
    n = 2
    while len(items) >= 2:
        chunk = max(1, len(items) // n)
        subsets = [items[i:i + chunk] for i in range(0, len(items), chunk)]
        reduced = False
        for i in range(len(subsets)):
            complement = [x for j, s in enumerate(subsets) if j != i for x in s]
            if complement and still_fails(complement):
                items = complement
                n = max(n - 1, 2)
                reduced = True
                break
        if not reduced:
            if n >= len(items):
                break
            n = min(len(items), 2 * n)
    return items


def minimise_spec(tla: str, cfg: str, still_fails: Callable[[str, str], bool]) -> tuple[str, str]:
    """Shrink (tla, cfg) line by line while `still_fails(tla, cfg)` holds."""
    tla_lines = tla.splitlines()
    head, body, foot = tla_lines[:1], tla_lines[1:-1], tla_lines[-1:]
    items = [("tla", line) for line in body] + [("cfg", line) for line in cfg.splitlines()]

    def rebuild(kept: list) -> tuple[str, str]:
        t = "\n".join(head + [x for k, x in kept if k == "tla"] + foot) + "\n"
        c = "\n".join(x for k, x in kept if k == "cfg") + "\n"
        return t, c

    cache: dict[tuple, bool] = {}

    def test(kept: list) -> bool:
        key = tuple(kept)
        if key not in cache:
            cache[key] = still_fails(*rebuild(kept))
        return cache[key]

    return rebuild(ddmin(items, test))
