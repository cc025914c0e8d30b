"""Names: resolution of an identifier to a bound variable, LET definition, operator
argument, state variable, constant, definition, built-in or instance substitution, and
the primed forms of each.  Separate because every reference goes through here before
it becomes an operator call (`calls.py`) or a slot read.
"""

from __future__ import annotations

from dataclasses import replace
from typing import Any

from .. import ast as A
from ..env import ByNameLocal, Code, Env, LazyLocal, LetOpLocal, OpLocal, SlotLocal, ThunkLocal
from ..errors import Loc, TlaError, UnsupportedError
from ..modules import BuiltinSym, ConstSym, DefSym, InstanceSym, SubstSym, VarSym
from ..specialise import lazy_read, slot_read, var_read
from ..values import BOOLEAN, STRING
from .closures import _prefix
from .lazy_args import thunk_read
from .host import CompilerHost


class NamesMixin(CompilerHost):
    """References to names and their primed forms."""

    def c_Name(self, e: A.Name, env: Env) -> Code:
        return self.reference(e.name, [], env, e.loc)

    def c_Apply(self, e: A.Apply, env: Env) -> Code:
        if e.name == "\\X":
            return self._product(e, env)
        return self.reference(e.name, e.args, env, e.loc)

    def reference(self, name: str, args: list[A.Expr], env: Env, loc: Loc) -> Code:
        local = env.locals.get(name)
        if local is not None:
            return self._local_ref(name, local, args, env, loc)
        sym = env.scope.lookup(name)
        if sym is None:
            if name in ("BOOLEAN", "STRING") and not args:
                v = BOOLEAN if name == "BOOLEAN" else STRING
                return lambda s, t, L: v
            raise self._unknown(name, loc)
        return self._symbol_ref(name, sym, args, env, loc)

    def _local_ref(self, name: str, local: Any, args: list[A.Expr], env: Env, loc: Loc) -> Code:
        if env.primed:
            primed = self._primed_local(name, local, args, env, loc)
            if primed is not None:
                return primed
        if isinstance(local, SlotLocal):
            self._arity(name, 0, args, loc)
            return slot_read(local.slot)
        if isinstance(local, LazyLocal):
            self._arity(name, 0, args, loc)
            return lazy_read(local.slot, local.code)
        if isinstance(local, ThunkLocal):
            self._arity(name, 0, args, loc)
            return thunk_read(local.slot)
        if isinstance(local, ByNameLocal):
            self._arity(name, 0, args, loc)
            return self.expr(local.expr, replace(local.env, primed=local.env.primed or env.primed))
        if isinstance(local, OpLocal):
            self._arity(name, local.arity, args, loc)
            slot = local.slot
            arg_codes = [self.expr(a, env) for a in args]
            return lambda s, t, L: L[slot](*[a(s, t, L) for a in arg_codes])
        if isinstance(local, LetOpLocal):
            if self.info(local.defn.body, local.env).action:
                pre, body = self.inline_let_op(name, local, args, env, loc, self.expr)
                return _prefix(pre, body)
            return self._let_op_call(name, local, args, env, loc)
        raise TlaError("semantic", f"cannot use {name} here", loc)

    def _primed_local(self, name: str, local: Any, args: list[A.Expr], env: Env, loc: Loc) -> Code | None:
        """A local inside ``e'`` that stands for an expression reading state (an
        operator argument, a LET definition): that expression, primed (TLC
        substitutes arguments and definitions by name).  None if the local is a
        plain value (a bound variable), which priming leaves unchanged."""
        if isinstance(local, (SlotLocal, LazyLocal)) and local.source is not None:
            self._arity(name, 0, args, loc)
            src, src_env = local.source
            return self.expr(src, replace(src_env, primed=True))
        if isinstance(local, LetOpLocal):
            pre, body = self.inline_let_op(name, local, args, env, loc, self.expr)
            return _prefix(pre, body)
        if isinstance(local, OpLocal):
            raise UnsupportedError(f"priming an expression that applies the operator argument {name}", loc)
        return None

    def _symbol_ref(self, name: str, sym: Any, args: list[A.Expr], env: Env, loc: Loc) -> Code:
        override = self.sym_overrides.get(id(sym))
        if override is not None:
            sym = override
        if hasattr(sym, "value"):  # a definition or constant given a value by the .cfg
            self._arity(name, 0, args, loc)
            cv = sym.value
            return lambda s, t, L: cv
        if isinstance(sym, VarSym):
            self._arity(name, 0, args, loc)
            i = sym.index
            if env.init_mode:
                return self._next_var(i, name, loc, init=True)
            if env.primed:
                return self._next_var(i, name, loc)
            return var_read(i)
        if isinstance(sym, ConstSym):
            if name not in self.constants:
                raise TlaError("config", f"The constant parameter {name} is not assigned a value by the "
                               f"configuration file.", loc)
            self._arity(name, 0, args, loc)
            v = self.constants[name]
            return lambda s, t, L: v
        if isinstance(sym, DefSym):
            return self._call_def(sym, args, env, loc)
        if isinstance(sym, BuiltinSym):
            return self._call_builtin(sym, args, env, loc)
        if isinstance(sym, SubstSym):
            slot = self.scratch_slot(sym, env) if env.primed and not args else None
            if slot is not None:
                return self._next_var(slot, sym.name, loc)
            sub_env = Env(sym.scope, env.frame, {p: env.locals[p] for p in sym.instance_params
                                                  if p in env.locals}, env.init_mode, env.primed,
                          enabled_cut=env.enabled_cut)
            if args:
                return self._apply_operator_expr(sym.expr, args, sub_env, env, loc)
            return self.expr(sym.expr, sub_env)
        if isinstance(sym, InstanceSym):
            raise TlaError("semantic", f"{name} is an instance; use {name}!Op", loc)
        raise self._unknown(name, loc)

    # ENABLED computed as TLC does for a variable of an instanced module whose
    # substitution was made outside the ENABLED (`I!F` with ``F == ENABLED A`` in the
    # instanced module, or a fairness condition of ``I!Spec``): TLC's ENABLED starts a
    # branch of its evaluation context (`Context.branch`) and looks a primed variable up
    # only as far as that branch (`Spec.getPrimedVar`, `Context.lookup(var, cutoff)`),
    # so it never reaches the substitution: ``x'`` is the instanced module's own
    # variable x, by name, in ENABLED's scratch state -- assigned by ``x' = e``,
    # ``x' \in S`` and ``UNCHANGED x`` (the substituted expression's current value)
    # and read back by ``x'`` elsewhere.  With ``x <- z, y <- z``, ``x'`` and ``y'``
    # are then two variables, not both z'.  A substitution made inside the ENABLED
    # (``ENABLED I!A``) is followed as usual.
    enabled_scratch: dict[str, int] | None = None
    var_names: list[str]  # the checked module's variables (set by the model loader)

    def scratch_slot(self, sym: SubstSym, env: Env) -> int | None:
        """The scratch slot of `sym`'s primed value while compiling an ENABLED, if any."""
        scratch = self.enabled_scratch
        if scratch is None or not sym.variable or id(sym) not in env.enabled_cut:
            return None
        if sym.name in self.var_names:
            # TLC's scratch state binds variables by name: one of the checked module's
            # variables with the same name is the same variable there.
            return self.var_names.index(sym.name)
        slot = scratch.get(sym.name)
        if slot is None:
            slot = scratch[sym.name] = len(self.var_names) + len(scratch)
        return slot

    def enabled_env(self, env: Env) -> Env:
        """`env` as the body of an ENABLED: every substitution visible in its scope
        (and in the scopes those substitutions come from) is behind ENABLED's branch."""
        cut = set(env.enabled_cut)
        todo = [env.scope]
        seen: set[int] = set()
        while todo:
            scope = todo.pop()
            if id(scope) in seen:
                continue
            seen.add(id(scope))
            for sym in scope.names.values():
                if isinstance(sym, SubstSym):
                    cut.add(id(sym))
                    todo.append(sym.scope)
        return replace(env, enabled_cut=frozenset(cut))

    def c_Lambda(self, e: A.Lambda, env: Env) -> Code:
        raise TlaError("semantic", "LAMBDA is only allowed as an operator argument", e.loc)

    def c_OpRef(self, e: A.OpRef, env: Env) -> Code:
        raise TlaError("semantic", f"operator {e.name} used as a value", e.loc)
