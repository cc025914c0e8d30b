"""Conditionals and choice: IF/THEN/ELSE (with the chain and row-table fast paths),
CASE and bounded CHOOSE, each picking the first arm or witness that holds.
"""

from __future__ import annotations

from typing import Any

from .. import ast as A
from ..constfold import NO_VALUE, const_value
from ..env import Code, Env
from ..errors import EvalError
from .binders import _enum_checked, _assign
from .closures import Value, check_bool
from .host import CompilerHost


class ConditionalsMixin(CompilerHost):
    """IF, CASE and CHOOSE."""

    def c_If(self, e: A.If, env: Env) -> Code:
        if isinstance(e.other, A.If) and self.fast_paths:
            return self._if_chain(e, env)
        c, a, b = self.expr(e.cond, env), self.expr(e.then, env), self.expr(e.other, env)
        loc = e.cond.loc

        def ite(s: Any, t: Any, L: list) -> Value:
            v = c(s, t, L)
            if v is True:
                return a(s, t, L)
            if v is False:
                return b(s, t, L)
            return check_bool(v, loc, "IF condition")
        return ite

    def _if_chain(self, e: A.If, env: Env) -> Code:
        """IF c1 THEN a1 ELSE IF c2 THEN a2 ... ELSE b as one loop instead of nested
        closures (long row tables are written this way)."""
        arms = []
        node: A.Expr = e
        while isinstance(node, A.If):
            arms.append((self.expr(node.cond, env), self.expr(node.then, env), node.cond.loc))
            node = node.other
        other = self.expr(node, env)
        if all(const_value(a) is not NO_VALUE for _, a, _ in arms):
            # Every branch a constant (a row table): return the values directly.
            arms = [(c, const_value(a), cl) for c, a, cl in arms]

            def if_table(s: Any, t: Any, L: list) -> Value:
                for c, v, cl in arms:
                    r = c(s, t, L)
                    if r is True:
                        return v
                    if r is not False:
                        check_bool(r, cl, "IF condition")
                return other(s, t, L)
            return if_table

        def if_chain(s: Any, t: Any, L: list) -> Value:
            for c, a, cl in arms:
                r = c(s, t, L)
                if r is True:
                    return a(s, t, L)
                if r is not False:
                    check_bool(r, cl, "IF condition")
            return other(s, t, L)
        return if_chain

    def c_Case(self, e: A.Case, env: Env) -> Code:
        arms = [(self.expr(g, env), self.expr(v, env), g.loc) for g, v in e.arms]
        other = self.expr(e.other, env) if e.other is not None else None
        loc = e.loc

        def case(s: Any, t: Any, L: list) -> Value:
            for g, v, gl in arms:
                r = g(s, t, L)
                if r is True:
                    return v(s, t, L)
                if r is not False:
                    check_bool(r, gl, "CASE guard")
            if other is None:
                raise EvalError("Attempted to evaluate a CASE with no arm whose guard is true", loc)
            return other(s, t, L)
        return case

    def c_Choose(self, e: A.Choose, env: Env) -> Code:
        if e.set is None:
            raise EvalError("TLC cannot evaluate an unbounded CHOOSE (CHOOSE x : P); bound it with \\in", e.loc)
        inner, binds = self.bind_bounds([A.Bound(e.names, e.tuple, e.set)], env)
        body = self.expr(e.body, inner)
        set_code, slots, is_tuple, sloc = binds[0]
        loc = e.loc

        def choose(s: Any, t: Any, L: list) -> Value:
            S = set_code(s, t, L)
            for v in _enum_checked(S, sloc):
                _assign(L, slots, is_tuple, v, sloc)
                r = body(s, t, L)
                if r is True:
                    return v
                if r is not False:
                    check_bool(r, e.body.loc, "CHOOSE body")
            raise EvalError("Attempted to compute the value of an expression of form\nCHOOSE x \\in S: P, "
                            "but no element of S satisfied P.", loc)
        return choose
