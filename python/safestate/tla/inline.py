"""Inlining of small state-level operators at their call sites.

A call to a compiled operator allocates a frame (a list), evaluates every
argument into it and calls the body closure.  For small operators -- guards such
as ``IsIdle(m) == m.state = "IDLE"``, updates such as ``WithCat(m, c) ==
[m EXCEPT !.cat = c]`` -- that overhead dominates the work.  Inlining compiles the
body into the caller's frame instead:

* an argument that is a bound variable of the caller (``L[slot]``) is not copied:
  the parameter refers to the same slot;
* an argument that folds to a constant is substituted by name, so constant
  folding and the constant fast paths apply inside the body (``Enter(m, "IDLE")``
  folds ``"IDLE" \\in Powered``);
* an argument that cannot fail, or that the body evaluates first, is evaluated once,
  before the body, into a fresh slot;
* any other argument is passed unevaluated, as TLC passes it: a lazy slot that the
  body's first use fills (`compile/lazy_args.py`).

Only operators without operator parameters, not recursive and not too large are
inlined, and never inside bodies that run re-entrantly on a shared frame (LET
operators, LAMBDAs and operator arguments), where a fresh slot could be
overwritten by a nested call before it is read.
"""

from __future__ import annotations

from typing import Any

from . import ast as A
from .constfold import NO_VALUE, const_value
from .env import ByNameLocal, Code, Env, SlotLocal
from .errors import Loc
from .modules import DefSym

# Body size (AST nodes) up to which an operator is inlined, and the nesting limit.
MAX_NODES = 160
MAX_DEPTH = 12
# The body nodes one model may inline in all, beyond which calls stay calls: nested
# inlining multiplies, and a model whose small operators call each other at every level
# with concrete arguments spends its load time compiling copies (the press's state-chain
# operators: 697,242 nodes inlined, 21 s of its 24 s load; the other models inline
# under 10,000).
MAX_INLINED_NODES = 50_000

_SIZES: dict[int, tuple[Any, int]] = {}


def body_size(e: Any) -> int:
    hit = _SIZES.get(id(e))
    if hit is not None and hit[0] is e:
        return hit[1]
    from .compiler import _children
    n = 1 + sum(body_size(c) for c in _children(e))
    _SIZES[id(e)] = (e, n)
    return n


def can_inline(compiler: Any, sym: DefSym) -> bool:
    d = sym.defn
    return (compiler._no_inline == 0 and not sym.recursive and d.fn_bounds is None
            and compiler._inline_depth < MAX_DEPTH
            and all(p.arity == 0 for p in d.params) and body_size(d.body) <= MAX_NODES
            and compiler._inlined_nodes + body_size(d.body) <= MAX_INLINED_NODES)


def inline_call(compiler: Any, sym: DefSym, args: list[A.Expr], env: Env, loc: Loc) -> Code:
    """The body of `sym` compiled in the caller's frame (see the module docstring); with
    an argument that must be passed unevaluated, a speculative call
    (`compile/lazy_args.py`)."""
    from .compiler import _prefix
    from .compile.lazy_args import passed_by_value, speculable, speculative
    eager = passed_by_value(compiler, sym.defn.params, args, sym.defn.body, sym.scope, env)
    if all(eager) or not speculable(compiler, args):
        return _prefix(*_inline(compiler, sym, args, env, eager))
    pre, by_value = _inline(compiler, sym, args, env, [True] * len(args))
    compiler._lazy_mode += 1
    try:
        lazy = _prefix(*_inline(compiler, sym, args, env, eager))
    finally:
        compiler._lazy_mode -= 1
    return speculative(pre, by_value, lazy)


def _inline(compiler: Any, sym: DefSym, args: list[A.Expr], env: Env, eager: list[bool]
            ) -> tuple[list[tuple[int, Code]], Code]:
    from .compile.lazy_args import lazy_binding
    bindings: dict[str, Any] = {}
    pre: list[tuple[int, Code]] = []
    for p, a, by_value in zip(sym.defn.params, args, eager):
        if isinstance(a, A.Name):
            local = env.locals.get(a.name)
            if isinstance(local, SlotLocal):
                bindings[p.name] = local
                continue
        code = compiler.expr(a, env)
        if const_value(code) is not NO_VALUE:
            bindings[p.name] = ByNameLocal(a, env)
            continue
        if not by_value:
            reset, bindings[p.name] = lazy_binding(compiler, a, env, code)
            if reset is not None:
                pre.append(reset)
            continue
        slot = env.frame.alloc()
        pre.append((slot, code))
        bindings[p.name] = SlotLocal(slot)
    compiler._inlined_nodes += body_size(sym.defn.body)
    compiler._inline_depth += 1
    try:
        body = compiler.expr(sym.defn.body, Env(sym.scope, env.frame, bindings, env.init_mode, env.primed,
                                                enabled_cut=env.enabled_cut))
    finally:
        compiler._inline_depth -= 1
    return pre, body
