"""Walks of the TLA+ syntax tree that need no environment: the children of a node and
every name an expression refers to.  Separate because the analysis, the operator calls,
the action compiler and the native translator all walk the tree this way.
"""

from __future__ import annotations

from typing import Any

from .. import ast as A


def all_names(e: Any) -> set[str]:
    """Every name referred to in `e`, LET definitions included."""
    out: set[str] = set()

    def walk(x: Any) -> None:
        if isinstance(x, (A.Name, A.Apply)):
            out.add(x.name)
        for c in _subterms(x):
            walk(c)
    walk(e)
    return out


def _subterms(e: Any) -> list:
    """The children of `e`, and the bodies of its LET definitions."""
    if isinstance(e, A.Let):
        return [d.body for d in e.defs if isinstance(d, A.OpDef)] + _children(e)
    return _children(e)


def _children(e: Any) -> list:
    if isinstance(e, A.Expr) or isinstance(e, (A.Bound, A.ExceptUpdate)):
        out = []
        for name in getattr(e, "__slots__", ()):
            if name == "loc":
                continue
            v = getattr(e, name, None)
            if isinstance(v, (A.Expr, A.Bound, A.ExceptUpdate)):
                out.append(v)
            elif isinstance(v, list):
                for x in v:
                    if isinstance(x, (A.Expr, A.Bound, A.ExceptUpdate)):
                        out.append(x)
                    elif isinstance(x, tuple):
                        out.extend(y for y in x if isinstance(y, A.Expr))
                        for y in x:
                            if isinstance(y, list):
                                out.extend(z for z in y if isinstance(z, A.Expr))
                    elif isinstance(x, A.InstanceStep):
                        out.extend(x.args)
        return out
    return []
