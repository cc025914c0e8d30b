"""Expansion of an operator's body at its call site: its parameters bound by value
(into fresh frame slots, remembering an argument that reads state) or by name
(action-level arguments).  Separate from `calls.py` because the action compiler
(`actions.py`) expands operators through these too (`inline_def`, `bind_params`).
"""

from __future__ import annotations

from typing import Any, Callable

from .. import ast as A
from ..env import ByNameLocal, Code, Env, LazyLocal, LetOpLocal, OpLocal, SlotLocal
from ..errors import Loc, UnsupportedError
from ..fold_memo import EXPANSION_LIMIT
from ..modules import DefSym
from .host import CompilerHost
from .lazy_args import cannot_fail, lazy_binding, passed_by_value
from .syntax import all_names

# How often one definition may be nested in its own expansion before it is taken as
# a (RECURSIVE) recursion; a higher-order operator passed to itself nests a few times.
RECURSION_LIMIT = 50


class ExpansionMixin(CompilerHost):
    """Operators expanded at their call site, and the binding of their parameters."""

    # Operators being expanded, by definition: how often each is nested in itself.
    _expanding: dict[int, int] | None = None

    def enter_expansion(self, name: str, loc: Loc, defn: object = None) -> None:
        """One level deeper into expanded operator bodies (the caller calls
        `leave_expansion` when done).  SANY allows recursion only through RECURSIVE,
        and expanding a RECURSIVE operator at its call site never ends (its
        arguments are not known at compile time): `defn` nested in its own expansion
        RECURSION_LIMIT times is such a recursion.  A chain of distinct definitions
        may nest as deep as EXPANSION_LIMIT (the Python stack's guard)."""
        self._inline_depth += 1
        counts = self._expanding
        if counts is None:
            counts = self._expanding = {}
        key = id(defn)
        n = counts[key] = counts.get(key, 0) + 1
        if defn is not None and n > RECURSION_LIMIT:
            self.leave_expansion(defn)
            raise UnsupportedError(f"the recursive operator {name} is used where TLC expands it at its call site "
                                   f"(in an action, in Init or under a prime), so its expansion never ends: "
                                   f"not supported", loc)
        if self._inline_depth > EXPANSION_LIMIT:
            self.leave_expansion(defn)
            raise UnsupportedError(f"operator {name} expanded at a depth of more than {EXPANSION_LIMIT} nested "
                                   f"definitions: not supported", loc)
        if self._inline_depth > self.fold_memo.depth_peak:
            self.fold_memo.depth_peak = self._inline_depth

    def leave_expansion(self, defn: object = None) -> None:
        self._inline_depth -= 1
        counts = self._expanding
        if counts is not None:
            key = id(defn)
            n = counts.get(key, 0) - 1
            if n > 0:
                counts[key] = n
            else:
                counts.pop(key, None)

    def inline_let_op(self, name: str, local: LetOpLocal, args: list[A.Expr], env: Env, loc: Loc,
                      compile_body: Callable[[A.Expr, Env], Any]) -> Any:
        """Expand a LET operator at its call site (under a prime, or in an action)."""
        d = local.defn
        self._arity(name, len(d.params), args, loc)
        self.enter_expansion(name, loc, d)
        try:
            bindings, pre = self.bind_params(d.params, args, env, loc, d.body, local.env.scope)
            body_env = Env(local.env.scope, env.frame, {**local.env.locals, **bindings},
                           env.init_mode, env.primed, enabled_cut=env.enabled_cut)
            return pre, compile_body(d.body, body_env)
        finally:
            self.leave_expansion(d)

    def inline_def(self, sym: DefSym, args: list[A.Expr], env: Env, loc: Loc,
                   compile_body: Callable[[A.Expr, Env], Any]) -> Any:
        """Expand an operator at its call site (action-level operators, Init, instances)."""
        d = sym.defn
        self._arity(d.name, len(d.params), args, loc)
        self.enter_expansion(d.name, loc, d)
        try:
            bindings, pre = self.bind_params(d.params, args, env, loc, d.body if d.fn_bounds is None else None,
                                             sym.scope)
            inst = {p: env.locals[p] for p in sym.scope.instance_params if p in env.locals}
            body_env = Env(sym.scope, env.frame, {**inst, **bindings}, env.init_mode, env.primed,
                           enabled_cut=env.enabled_cut)
            if d.fn_bounds is not None:
                body = compile_body(A.FnLit(d.loc, d.fn_bounds, d.body), body_env)
            else:
                body = compile_body(d.body, body_env)
        finally:
            self.leave_expansion(d)
        return pre, body

    def bind_params(self, params: list[A.Param], args: list[A.Expr], env: Env, loc: Loc,
                    body: A.Expr | None = None, body_scope: Any = None) -> tuple[dict, list]:
        """Bind operator parameters: by value into fresh slots (remembering an argument
        that reads state, which a prime in the body primes) where that cannot be told
        from TLC's lazy arguments, else unevaluated into a lazy slot (`lazy_args.py`;
        `body`, if given, is the body they are bound for, in `body_scope`); by name for action-level
        arguments (which the body must see unevaluated) and in Init."""
        bindings: dict[str, Any] = {}
        pre: list[tuple[int, Code]] = []
        eager = passed_by_value(self, params, args, body, body_scope, env)
        for p, a, by_value in zip(params, args, eager):
            if p.arity:
                slot = env.frame.alloc()
                pre.append((slot, self._arg(a, p.arity, env, loc)))
                bindings[p.name] = OpLocal(slot, p.arity)
            elif self.info(a, env).action or env.init_mode:
                bindings[p.name] = ByNameLocal(a, env)
            elif by_value:
                slot = env.frame.alloc()
                pre.append((slot, self.expr(a, env)))
                bindings[p.name] = SlotLocal(slot, self.state_source(a, env))
            else:
                reset, bindings[p.name] = lazy_binding(self, a, env)
                if reset is not None:
                    pre.append(reset)
        return bindings, pre

    def _bind_args_by_value(self, args: list[A.Expr], env: Env, lazy: bool = True) -> tuple[dict, list]:
        """Arguments of an operator given as an expression (a substituted operator
        constant, an instance's operator), bound to names the callee's arguments refer
        to: unevaluated unless they cannot fail (or `lazy` is False)."""
        bindings: dict[str, Any] = {}
        pre: list[tuple[int, Code]] = []
        for i, a in enumerate(args):
            if not lazy or cannot_fail(self, a, env):
                slot = env.frame.alloc()
                pre.append((slot, self.expr(a, env)))
                bindings[f"$arg{i}"] = SlotLocal(slot, self.state_source(a, env))
            else:
                reset, bindings[f"$arg{i}"] = lazy_binding(self, a, env)
                if reset is not None:
                    pre.append(reset)
        return bindings, pre

    def state_source(self, a: A.Expr, env: Env) -> tuple[A.Expr, Env] | None:
        """`a` and its environment if `a` reads state (see `SlotLocal.source`)."""
        if env.primed or env.init_mode:
            return None  # already evaluated in the state that a prime would select
        return (a, env) if self._reads_state(a, env) else None

    def _reads_state(self, a: A.Expr, env: Env) -> bool:
        if self.info(a, env).vars:
            return True
        # A name bound to a state-reading argument reads state too.
        locs = [env.locals.get(n) for n in all_names(a)]
        return any(isinstance(b, (SlotLocal, LazyLocal)) and b.source is not None for b in locs)
