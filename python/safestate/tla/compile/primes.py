"""Action-level forms met inside expressions: primed variables and expressions,
UNCHANGED, ``[A]_v`` / ``<<A>>_v``, and the forms an expression may not contain
(fairness).  Separate because these read the next state, which only actions provide.
"""

from __future__ import annotations

from dataclasses import replace
from typing import Any

from .. import ast as A
from ..env import UNSET, Code, Env
from ..errors import EvalError, Loc, TlaError, UnassignedPrimeError, UnsupportedError
from ..modules import VarSym
from .closures import Value
from .host import CompilerHost


class PrimesMixin(CompilerHost):
    """Primes, UNCHANGED and step actions in expressions."""

    def c_Prime(self, e: A.Prime, env: Env) -> Code:
        if env.init_mode:
            # TLC evaluates Init and fails there (exit 75), not in SANY (150).
            raise TlaError("eval", "primed variable in the initial predicate", e.loc)
        arg = e.arg
        if isinstance(arg, A.Name) and arg.name not in env.locals:
            sym = env.scope.lookup(arg.name)
            if isinstance(sym, VarSym):
                return self._next_var(sym.index, sym.name, e.loc)
        if env.primed or self.info(arg, env).action:
            raise TlaError("semantic", "a primed expression may not contain primes or actions", e.loc)
        # e' is e with every variable primed, through operator arguments, LET
        # definitions and operator bodies (see `_primed_local`).
        return self.expr(arg, replace(env, primed=True))

    var_names: list[str] = []

    def _next_var(self, i: int, name: str, loc: Loc, init: bool = False) -> Code:
        def next_var(s: Any, t: Any, L: list) -> Value:
            if t is None:
                raise EvalError(f"{name}' evaluated outside an action", loc)
            v = t[i]
            if v is UNSET:
                raise UnassignedPrimeError(f"The variable {name}{'' if init else chr(39)} is used before it is "
                                           f"assigned a value", loc)
            return v
        return next_var

    def c_StepAction(self, e: A.StepAction, env: Env) -> Code:
        act = self.expr(e.action, env)
        same = self._unchanged_expr(e.sub, env)
        if e.stutter:
            return lambda s, t, L: act(s, t, L) is True or same(s, t, L)
        return lambda s, t, L: act(s, t, L) is True and not same(s, t, L)

    def _unchanged_expr(self, arg: A.Expr, env: Env) -> Code:
        now = self.expr(arg, env)
        nxt = self.c_Prime(A.Prime(arg.loc, arg), env)
        return lambda s, t, L: now(s, t, L) == nxt(s, t, L)

    def c_Fairness(self, e: A.Fairness, env: Env) -> Code:
        raise UnsupportedError("fairness formula evaluated as an expression", e.loc)
