"""Operator calls: user definitions (compiled once, expanded at the call site, inlined or
memoised), LET operators with RECURSIVE calls, LAMBDA and operator arguments, built-ins.
Separate because it holds the hooks of the specialisations (`inline.py`, `op_memo.py`)
and the rules on when an operator is expanded (`expansion.py`) instead of called.
"""

from __future__ import annotations

from typing import Any

from .. import ast as A
from ..env import NOTSET, UNSET, Code, Env, Frame, LetOpLocal, Local, OpLocal, SlotLocal, ThunkLocal
from ..errors import EvalError, Loc, TlaError, UnassignedPrimeError, UnsupportedError
from ..modules import BuiltinSym, DefSym
from ..inline import can_inline, inline_call
from ..tlcget import RUNTIME
from .closures import Value, EMPTY, _prefix, _guard, _apply_fn, _operator_value
from .lazy_args import (cannot_fail, first_evaluated, lazy_binding, passed_by_value, speculable,
                        speculative_call, thunk_code)
from .operators import _CORE_BINARY
from .syntax import all_names
from .host import CompilerHost


class CompiledDef:
    """A compiled operator definition (body closure and frame size); zero-argument
    constant-level definitions are evaluated once and cached."""

    def __init__(self, compiler: CompilerHost, sym: DefSym) -> None:
        self.body: Code = _not_ready
        self.size = 0
        self.holder_only = True
        info = compiler.def_info(sym)
        self.constant = (not sym.defn.params and not info.vars and not info.action)
        self.value: Any = NOTSET

    def constant_ref(self) -> Code:
        holder = self

        def const(s: Any, t: Any, L: list) -> Value:
            v = holder.value
            if v is NOTSET:
                v = holder.value = holder.body(None, None, [None] * holder.size)
            return v
        return const


def _not_ready(s: Any, t: Any, L: list) -> Value:
    raise EvalError("definition used before it is compiled (circular definition?)")


class CallsMixin(CompilerHost):
    """Calls of user, LET, LAMBDA and built-in operators."""

    _lazy_defs: dict[int, tuple[Any, Any]]  # set by Compiler.__init__, as _lazy_mode
    _lazy_mode: int

    def _arity(self, name: str, arity: int, args: list[A.Expr], loc: Loc) -> None:
        if len(args) != arity:
            raise TlaError("semantic", f"The operator {name} requires {arity} arguments, but "
                           f"{len(args)} were given.", loc)

    def _apply_operator_expr(self, op: A.Expr, args: list[A.Expr], op_env: Env, env: Env, loc: Loc) -> Code:
        """Apply an operator given as an expression (a substituted operator constant)."""
        if isinstance(op, A.Name):
            return self._reference_with_caller_args(op.name, args, op_env, env, loc)
        if isinstance(op, A.OpRef):
            return self._call_symbol_op(op.name, args, env, loc, op_env)
        if isinstance(op, A.Lambda):
            return self._inline_lambda(op, args, op_env, env, loc)
        raise TlaError("semantic", "an operator is expected here", loc)

    def _reference_with_caller_args(self, name: str, args: list[A.Expr], op_env: Env, env: Env, loc: Loc) -> Code:
        # Arguments belong to the caller's environment: bind them by value first.
        bindings, pre = self._bind_args_by_value(args, env)
        fake: list[A.Expr] = [A.Name(a.loc, f"$arg{i}") for i, a in enumerate(args)]
        code = self.reference(name, fake, op_env.bind_all(bindings), loc)
        return _prefix(pre, code)

    def _inline_lambda(self, lam: A.Lambda, args: list[A.Expr], lam_env: Env, env: Env, loc: Loc) -> Code:
        self._arity("LAMBDA", len(lam.params), args, loc)
        bindings: dict[str, Any] = {}
        pre: list[tuple[int, Code]] = []
        risky = [i for i, a in enumerate(args) if not cannot_fail(self, a, env)]
        first = first_evaluated(lam.body, lam_env.scope)
        for i, (p, a) in enumerate(zip(lam.params, args)):
            if i not in risky or (len(risky) == 1 and first == p):
                slot = env.frame.alloc()
                pre.append((slot, self.expr(a, env)))
                bindings[p] = SlotLocal(slot, self.state_source(a, env))
            else:  # unevaluated, as TLC passes it (lazy_args.py)
                reset, bindings[p] = lazy_binding(self, a, env)
                if reset is not None:
                    pre.append(reset)
        body = self.expr(lam.body, Env(lam_env.scope, env.frame, {**lam_env.locals, **bindings}, env.init_mode, env.primed))
        return _prefix(pre, body)

    def _call_symbol_op(self, name: str, args: list[A.Expr], env: Env, loc: Loc, op_env: Env) -> Code:
        sym = op_env.scope.lookup(name)
        if sym is None:
            codes = [self.expr(a, env) for a in args]
            core = _CORE_BINARY.get(name)
            if core is not None and len(codes) == 2:
                a0, a1 = codes
                return lambda s, t, L: core(a0(s, t, L), a1(s, t, L))
            raise self._unknown(name, loc)
        bindings, pre = self._bind_args_by_value(args, env)
        fake: list[A.Expr] = [A.Name(a.loc, f"$arg{i}") for i, a in enumerate(args)]
        return _prefix(pre, self._symbol_ref(name, sym, fake, env.bind_all(bindings), loc))

    def _call_def(self, sym: DefSym, args: list[A.Expr], env: Env, loc: Loc) -> Code:
        d = sym.defn
        if d.fn_bounds is None:
            self._arity(d.name, len(d.params), args, loc)
        elif args:
            raise TlaError("semantic", f"{d.name} is a function; apply it with {d.name}[...]", loc)
        info = self.def_info(sym)
        # Under a prime the body must be compiled with its variables primed.
        # In Init only bodies that read variables need the state being built (and a
        # recursive one cannot be expanded).
        init = env.init_mode and (info.vars or not sym.recursive)
        # An action-level argument (Send(p, x, x')) is passed by name, as TLC expands
        # the operator: its body may assign the primed variable.
        action_arg = any(self.info(a, env).action for a in args if not isinstance(a, A.Lambda))
        # A recursive operator cannot be expanded at its call site; a state-level one is
        # called instead: on the next state under a prime or in Init, else on the current
        # state with arguments such as Len(log') evaluated first (TLC reads the body's
        # unprimed variables in the current state too).
        by_call = sym.recursive and not (info.action or sym.scope.parameterised)
        if by_call and info.vars and (init or env.primed):
            return self._call_on_next_state(sym, args, env, loc)
        if by_call and action_arg and not (init or env.primed):
            action_arg = False
        if info.action or sym.scope.parameterised or init or action_arg or (env.primed and info.vars):
            pre, body = self.inline_def(sym, args, env, loc, self.expr)
            return _prefix(pre, body)
        if d.fn_bounds is not None:
            return self._fn_def_ref(sym)
        eager = passed_by_value(self, d.params, args, d.body, sym.scope, env)
        # The memo's key is every argument's value, evaluated first: only where that
        # cannot be told from TLC's lazy arguments (an argument that fails: the memo
        # makes the ordinary call, which evaluates what TLC evaluates).
        if self.fast_paths and self.memoise_operators and (all(eager) or speculable(self, args)) \
                and self.op_memo.applies(sym, args):
            self.op_memo.skip.add(id(sym))
            try:
                plain = self._call_def(sym, args, env, loc)
            finally:
                self.op_memo.skip.discard(id(sym))
            return self.op_memo.wrap(sym, plain, [self.expr(a, env) for a in args])
        if self.fast_paths and (d.params or info.vars) and can_inline(self, sym):
            return inline_call(self, sym, args, env, loc)
        compiled = self._compiled_def(sym, lazy=not all(eager))
        if not d.params:
            if compiled.constant:
                return compiled.constant_ref()
            body, size = compiled.body, compiled.size
            if compiled.holder_only:
                holder = compiled
                return lambda s, t, L: holder.body(s, t, [None] * holder.size)
            if size == 0:
                return lambda s, t, L: body(s, t, EMPTY)
            return lambda s, t, L: body(s, t, [None] * size)
        if not all(eager) and speculable(self, args):
            by_value = self._compiled_def(sym)
            values = [self._arg(a, p.arity, env, loc) for a, p in zip(args, d.params)]
            thunks = [self._arg(a, p.arity, env, loc) if ok else thunk_code(self, a, env, False)
                      for a, p, ok in zip(args, d.params, eager)]
            return speculative_call(values, by_value, thunks, compiled)
        arg_codes = [self._arg(a, p.arity, env, loc) if ok else thunk_code(self, a, env, False)
                     for a, p, ok in zip(args, d.params, eager)]
        holder = compiled
        if compiled.holder_only:  # a recursive call: the frame size is not known yet
            n = len(args)
            return lambda s, t, L: holder.body(s, t, [a(s, t, L) for a in arg_codes]
                                               + [None] * (holder.size - n))
        pad = [None] * (compiled.size - len(args))
        if len(arg_codes) == 1:
            a0, = arg_codes
            return lambda s, t, L: holder.body(s, t, [a0(s, t, L)] + pad)
        if len(arg_codes) == 2:
            a0, a1 = arg_codes
            return lambda s, t, L: holder.body(s, t, [a0(s, t, L), a1(s, t, L)] + pad)
        return lambda s, t, L: holder.body(s, t, [a(s, t, L) for a in arg_codes] + pad)

    def _call_on_next_state(self, sym: DefSym, args: list[A.Expr], env: Env, loc: Loc) -> Code:
        """A recursive state-level operator under a prime (``Sum(n)'``) or in Init: it
        cannot be expanded at its call site, so its compiled body is run with the state
        being built (or the next state) in place of the current one; its arguments are
        compiled in the caller's primed (or Init) environment."""
        eager = passed_by_value(self, sym.defn.params, args, sym.defn.body, sym.scope, env)
        arg_codes = [self._arg(a, p.arity, env, loc) if ok else thunk_code(self, a, env, False)
                     for a, p, ok in zip(args, sym.defn.params, eager)]
        holder = self._compiled_def(sym, lazy=not all(eager))
        names = self.var_names
        reads = sorted(i for i in self.def_info(sym).vars if i >= 0)
        mark = "" if env.init_mode else "'"

        def call(s: Any, t: Any, L: list) -> Value:
            for i in reads:
                if t[i] is UNSET:
                    raise UnassignedPrimeError(f"The variable {names[i]}{mark} is used before it is assigned a "
                                               f"value", loc)
            frame = [a(s, t, L) for a in arg_codes]
            return holder.body(t, None, frame + [None] * (holder.size - len(frame)))
        return call

    def _compiled_def(self, sym: DefSym, lazy: bool = False) -> "CompiledDef":
        """The body compiled once, with a frame of its own.  `lazy`: the version whose
        parameters may hold thunks (arguments passed unevaluated, lazy_args.py), for
        the calls that pass any; the others use the plain version."""
        if lazy and sym.defn.params:
            hit = self._lazy_defs.get(id(sym))
            if hit is not None and hit[0] is sym:
                return hit[1]
        elif sym.compiled is not None:
            return sym.compiled  # type: ignore[return-value]
        holder = CompiledDef(self, sym)
        if lazy and sym.defn.params:
            self._lazy_defs[id(sym)] = (sym, holder)
        else:
            sym.compiled = holder
        frame = Frame()
        bindings: dict[str, Any] = {}
        for p in sym.defn.params:
            slot = frame.alloc()
            bindings[p.name] = OpLocal(slot, p.arity) if p.arity else ThunkLocal(slot) if lazy else SlotLocal(slot)
        # The version for lazy arguments makes lazy calls; the other speculative ones.
        mode, self._lazy_mode = self._lazy_mode, int(lazy)
        try:
            holder.body = self.expr(sym.defn.body, Env(sym.scope, frame, bindings))
        finally:
            self._lazy_mode = mode
        holder.size = frame.size
        holder.holder_only = False
        return holder

    def _arg(self, a: A.Expr, arity: int, env: Env, loc: Loc) -> Code:
        """Compile an argument; operator arguments become Python callables."""
        if arity == 0:
            return self.expr(a, env)
        if isinstance(a, A.Lambda):
            if len(a.params) != arity:
                raise TlaError("semantic", f"LAMBDA has {len(a.params)} parameters, {arity} expected", a.loc)
            slots = [env.frame.alloc() for _ in a.params]
            self._no_inline += 1
            try:
                body = self.expr(a.body, env.bind_all({p: SlotLocal(sl) for p, sl in zip(a.params, slots)}))
            finally:
                self._no_inline -= 1

            return _operator_value(body, slots)
        name = a.name if isinstance(a, (A.Name, A.OpRef)) else None
        if name is None:
            raise TlaError("semantic", f"an operator of {arity} arguments is expected here", a.loc)
        local = env.locals.get(name)
        if isinstance(local, OpLocal):
            slot = local.slot
            return lambda s, t, L: L[slot]
        # A named operator: build a callable evaluating it on argument values.
        slots = [env.frame.alloc() for _ in range(arity)]
        fake: list[A.Expr] = [A.Name(a.loc, f"$p{i}") for i in range(arity)]
        inner_env = env.bind_all({f"$p{i}": SlotLocal(sl) for i, sl in enumerate(slots)})
        self._no_inline += 1
        try:
            if local is not None:
                body = self._local_ref(name, local, fake, inner_env, a.loc)
            else:
                sym = env.scope.lookup(name)
                if sym is None:
                    core = _CORE_BINARY.get(name)
                    if core is None or arity != 2:
                        raise self._unknown(name, a.loc)
                    return lambda s, t, L: core
                body = self._symbol_ref(name, sym, fake, inner_env, a.loc)
        finally:
            self._no_inline -= 1

        return _operator_value(body, slots)

    def _let_op_call(self, name: str, local: LetOpLocal, args: list[A.Expr], env: Env, loc: Loc) -> Code:
        d = local.defn
        self._arity(name, len(d.params), args, loc)
        if not local.holder:
            local.holder.extend([None, []])
            bindings: dict[str, Local] = {}
            for p, sl in zip(d.params, local.param_slots):
                bindings[p.name] = OpLocal(sl, p.arity) if p.arity else ThunkLocal(sl)
            self._no_inline += 1
            lo = local.env.frame.size
            try:
                local.holder[0] = self.expr(d.body, local.env.bind_all(bindings))
            finally:
                self._no_inline -= 1
            if d.name in all_names(d.body):
                # A recursive call reuses the slots of the body's own LETs and binders:
                # save and restore them around each call, as for the parameters.
                local.holder[1] = list(range(lo, local.env.frame.size))
        holder = local.holder
        param_slots = local.param_slots
        # The body shares the caller's frame and overwrites its slots: a thunk keeps a copy.
        eager = passed_by_value(self, d.params, args, d.body, local.env.scope, env)
        arg_codes = [self._arg(a, p.arity, env, loc) if ok else thunk_code(self, a, env, True)
                     for a, p, ok in zip(args, d.params, eager)]
        speculate = not all(eager) and speculable(self, args)
        # Speculative (lazy_args.py): the values, or if one fails the thunks; the body
        # reads its parameters through thunk_read either way.
        values = [self._arg(a, p.arity, env, loc) for a, p in zip(args, d.params)] if speculate else arg_codes

        def call(s: Any, t: Any, L: list) -> Value:
            if speculate:
                try:
                    vals = [a(s, t, L) for a in values]
                except Exception:  # noqa: BLE001 - the body raises it if TLC would
                    vals = [a(s, t, L) for a in arg_codes]
            else:
                vals = [a(s, t, L) for a in arg_codes]
            slots = param_slots + holder[1] if holder[1] else param_slots
            saved = [L[sl] for sl in slots]
            for sl, v in zip(slots, vals):
                L[sl] = v
            try:
                return holder[0](s, t, L)
            finally:
                for sl, v in zip(slots, saved):
                    L[sl] = v
        return call

    def _call_builtin(self, sym: BuiltinSym, args: list[A.Expr], env: Env, loc: Loc) -> Code:
        b = sym.builtin
        self._arity(b.name, b.arity, args, loc)
        if b.refused is not None:
            raise UnsupportedError(b.refused, loc)
        fn = b.fn
        if b.name in ("TLCGet", "TLCSet"):
            RUNTIME.used = True  # the explorer keeps the counters up to date
        if b.arity == 0:
            v = fn()
            return lambda s, t, L: v
        if b.higher_order:
            arities = {"SelectSeq": [0, 1], "SortSeq": [0, 2], "BagOfAll": [1, 0]}[b.name]
            codes = [self._arg(a, ar, env, loc) for a, ar in zip(args, arities)]
        else:
            codes = [self.expr(a, env) for a in args]
        return _guard(_apply_fn(fn, codes), loc)
