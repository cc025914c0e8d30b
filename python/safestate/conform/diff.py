"""Side-by-side rendering of a disagreement between the model and the C++."""

from __future__ import annotations

from typing import Any

from .adapter import differing


def side_by_side(model: dict[str, Any], cpp: dict[str, Any]) -> str:
    bad = set(differing(model, cpp))
    keys = list(model) + [k for k in cpp if k not in model]
    w = max(len(k) for k in keys)
    wm = max([len("model")] + [len(repr(model.get(k, "<missing>"))) for k in keys])
    lines = [f"  {'field':<{w}}  {'model':<{wm}}  C++"]
    for k in keys:
        mark = "!" if k in bad else " "
        lines.append(f"{mark} {k:<{w}}  {model.get(k, '<missing>')!r:<{wm}}  {cpp.get(k, '<missing>')!r}")
    return "\n".join(lines)


def report(step: int, event: str, model: dict[str, Any], cpp: dict[str, Any], extra: str = "") -> str:
    bad = differing(model, cpp)
    head = f"MISMATCH at step {step}, event {event}: {', '.join(bad) if bad else extra}"
    if extra and bad:
        head += f" ({extra})"
    return head + "\n" + side_by_side(model, cpp)
