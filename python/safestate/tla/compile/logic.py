"""Logic: conjunction, disjunction and the bounded quantifiers, with TLC's checks that
operands are booleans and its enumeration order for several binders.
"""

from __future__ import annotations

import itertools
from typing import Any

from .. import ast as A
from ..env import Code, Env
from ..errors import EvalError
from .binders import _enum_checked, _assign
from .closures import check_bool
from .host import CompilerHost


class LogicMixin(CompilerHost):
    """Conjunctions, disjunctions and quantifiers."""

    def c_And(self, e: A.And, env: Env) -> Code:
        items = [self.expr(i, env) for i in e.items]
        locs = [i.loc for i in e.items]

        def conj(s: Any, t: Any, L: list) -> bool:
            for c, loc in zip(items, locs):
                v = c(s, t, L)
                if v is False:
                    return False
                if v is not True:
                    check_bool(v, loc, "conjunct")
            return True
        if len(items) == 2:
            c0, c1 = items
            l0, l1 = locs

            def conj2(s: Any, t: Any, L: list) -> bool:
                v = c0(s, t, L)
                if v is False:
                    return False
                if v is not True:
                    check_bool(v, l0, "conjunct")
                v = c1(s, t, L)
                if v is True or v is False:
                    return v
                return check_bool(v, l1, "conjunct")
            return conj2
        return conj

    def c_Or(self, e: A.Or, env: Env) -> Code:
        items = [self.expr(i, env) for i in e.items]
        locs = [i.loc for i in e.items]

        def disj(s: Any, t: Any, L: list) -> bool:
            for c, loc in zip(items, locs):
                v = c(s, t, L)
                if v is True:
                    return True
                if v is not False:
                    check_bool(v, loc, "disjunct")
            return False
        return disj

    def c_Quant(self, e: A.Quant, env: Env) -> Code:
        inner, binds = self.bind_bounds(e.bounds, env)
        body = self.expr(e.body, inner)
        exists = e.kind == "\\E"
        bloc = e.body.loc
        if len(binds) == 1 and not binds[0][2]:
            set_code, (slot,), _, sloc = binds[0]

            def quant1(s: Any, t: Any, L: list) -> bool:
                S = set_code(s, t, L)
                for v in _enum_checked(S, sloc):
                    L[slot] = v
                    r = body(s, t, L)
                    if r is exists:
                        return exists
                    if r is not (not exists):
                        check_bool(r, bloc, "quantifier body")
                return not exists
            return quant1
        # As TLC (ContextEnumerator): all bound sets are evaluated first, then the
        # FIRST binder turns fastest (see actions._exists).
        rbinds = binds[::-1]

        def quant_n(s: Any, t: Any, L: list) -> bool:
            elems = [_enum_checked(b[0](s, t, L), b[3]) for b in binds]
            for combo in itertools.product(*elems[::-1]):
                for (_, slots, is_tuple, sloc), v in zip(rbinds, combo):
                    _assign(L, slots, is_tuple, v, sloc)
                r = body(s, t, L)
                if r is not True and r is not False:
                    r = check_bool(r, bloc, "quantifier body")
                if r is exists:
                    return exists
            return not exists
        return quant_n

    def c_UnboundedQuant(self, e: A.UnboundedQuant, env: Env) -> Code:
        raise EvalError(f"TLC encountered the non-enumerable quantifier bound in {e.kind} "
                        f"{', '.join(e.names)} : ...; bound it with \\in", e.loc)
