"""Instance-prefixed references ``I!Op(args)``: the instance's scope with its parameters
bound.  Separate because the action compiler reuses `prefixed` with its own body compiler.
"""

from __future__ import annotations

from typing import Any, Callable

from .. import ast as A
from ..env import Code, Env
from ..errors import TlaError
from ..modules import DefSym, InstanceSym, Scope
from .closures import _prefix
from .lazy_args import cannot_fail, speculable, speculative
from .host import CompilerHost


class InstancesMixin(CompilerHost):
    """References through ``I!`` prefixes."""

    _lazy_mode: int  # set by Compiler.__init__ (compile/lazy_args.py)

    def _instance_scope(self, e: A.Prefixed, env: Env) -> Scope:
        scope = env.scope
        for step in e.path:
            sym = scope.lookup(step.name)
            if not isinstance(sym, InstanceSym):
                raise TlaError("semantic", f"{step.name} is not an instance (in {step.name}!...)", e.loc)
            scope = sym.scope
        return scope

    def c_Prefixed(self, e: A.Prefixed, env: Env) -> Code:
        if all(cannot_fail(self, a, env) for a in e.args) or not speculable(self, e.args):
            return self.prefixed(e, env, self.expr)
        # An argument that may fail: a speculative call (compile/lazy_args.py).
        pre, by_value = self.prefixed(e, env, self.expr, lazy=False)
        self._lazy_mode += 1
        try:
            lazy = self.prefixed(e, env, self.expr)
        finally:
            self._lazy_mode -= 1
        return speculative(pre, by_value, lazy)

    def prefixed(self, e: A.Prefixed, env: Env, compile_body: Callable, lazy: bool = True) -> Any:
        scope = env.scope
        bindings: dict[str, Any] = {}
        pre: list = []
        for step in e.path:
            sym = scope.lookup(step.name)
            if not isinstance(sym, InstanceSym):
                raise TlaError("semantic", f"{step.name} is not an instance (in {step.name}!...)", e.loc)
            params = sym.inst.params
            self._arity(step.name, len(params), step.args, e.loc)
            b, p = self.bind_params(params, step.args, env, e.loc)
            bindings.update({n: env.locals[n] for n in sym.let_locals if n in env.locals})
            bindings.update(b)
            pre.extend(p)
            scope = sym.scope
        sym = scope.lookup(e.name)
        if sym is None:
            raise self._unknown(e.name, e.loc)
        # Operator arguments are compiled in the caller's environment, by value.
        arg_bindings, arg_pre = self._bind_args_by_value(e.args, env, lazy)
        fake: list[A.Expr] = [A.Name(a.loc, f"$arg{i}") for i, a in enumerate(e.args)]
        inner_env = Env(scope, env.frame, {**bindings, **arg_bindings}, env.init_mode, env.primed,
                        enabled_cut=env.enabled_cut)
        pre = pre + arg_pre
        if isinstance(sym, DefSym) and compile_body != self.expr:
            d = sym.defn
            self._arity(d.name, len(d.params), fake, e.loc)
            pb, pp = self.bind_params(d.params, fake, inner_env, e.loc)
            inst = {p: inner_env.locals[p] for p in sym.scope.instance_params if p in inner_env.locals}
            body = compile_body(d.body, Env(sym.scope, env.frame, {**inst, **arg_bindings, **pb}, env.init_mode,
                                            env.primed, enabled_cut=env.enabled_cut))
            return pre + pp, body
        code = self._symbol_ref(e.name, sym, fake, inner_env, e.loc)
        if compile_body != self.expr or not lazy:
            return pre, code
        return _prefix(pre, code)
