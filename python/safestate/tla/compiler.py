"""Compiles TLA+ expressions into Python closures ``f(s, t, L) -> value``.

Names are resolved once, at compile time, to state slots, frame slots, constants
or compiled operators, so evaluation never dispatches on AST node types.  Each
user operator is compiled once per scope; operators whose body is action-level
(contains primes, UNCHANGED or ENABLED) are expanded at their call site instead,
because the action compiler (`actions.py`) must see their structure.

Semantics follow TLC: ``=`` between values of different kinds is an error (model
values excepted), arithmetic on non-integers is an error, sets are enumerated in
TLC's normalised order (CHOOSE picks the first witness in that order).
"""

from __future__ import annotations

import itertools
import operator
from dataclasses import dataclass, replace
from typing import Any, Callable

from . import ast as A
from .constfold import NO_VALUE, ConstFolder, const_code, const_value, fold
from .op_memo import OpMemo
from .env import (NOTSET, UNSET, ByNameLocal, Code, Env, Frame, LazyLocal, LetOpLocal, OpLocal,
                  SlotLocal)
from .errors import EvalError, JavaOverrideError, Loc, TlaError, UnassignedPrimeError, UnsupportedError
from .modules import BuiltinSym, ConstSym, DefSym, InstanceSym, Scope, SubstSym, VarSym, let_instance_scope
from .inline import can_inline, inline_call
from .specialise import except_flat, dot_code, eq_code, lazy_read, member_const, membership_const, slot_read, var_read
from .tlcget import RUNTIME
from .stdlib import NATURALS, cap, cup, domain, non_integer_error, setminus, subseteq, union
from .values import (BOOLEAN, STRING, FilteredSet, FnSetValue, FnValue, IntervalSet, LazySet, PowerSet,
                     ProductSet, RecSetValue, as_set, fmt, is_set, kind, make_fn, member,
                     sorted_elems, values_equal)

Value = Any
EMPTY: list = []
_LITERALS = (A.Num, A.Str, A.Bool)


def enum(S: Value) -> Any:
    """Elements of a finite set in TLC order (fast paths for frozensets and intervals)."""
    if type(S) is IntervalSet:
        return range(S.lo, S.hi + 1)
    return sorted_elems(S)


def check_bool(v: Value, loc: Loc, what: str = "") -> bool:
    if v is True or v is False:
        return v
    raise EvalError(f"A non-boolean expression ({kind(v)} {fmt(v)}) was used as a "
                    f"{what or 'formula'}", loc)


@dataclass
class Info:
    """Static facts about an expression: the state variables it reads, whether it is
    action-level (primes / UNCHANGED / ENABLED / actions), whether it reads any state."""

    vars: frozenset[int]
    action: bool


_NO_INFO = Info(frozenset(), False)
# In Info.vars: the expression reads TLCGet's counters (a pseudo-variable).
SEARCH_STATE = -1


class RecursiveFunction:
    """``f[x \\in S] == body`` referring to itself: applied lazily, memoised.  Each
    application evaluates `body` on a copy of `frame` (the enclosing LET's frame, or a
    fresh one) after `bind` has stored the argument in its slots."""

    __slots__ = ("dom", "body", "bind", "frame", "memo", "s", "t")

    def __init__(self, dom: Value, body: Code, bind: Callable[[list, Value], None], frame: list,
                 s: Any, t: Any) -> None:
        self.dom, self.body, self.bind, self.frame, self.s, self.t = dom, body, bind, frame, s, t
        self.memo: dict = {}

    def apply(self, x: Value) -> Value:
        r = self.memo.get(x, NOTSET)
        if r is NOTSET:
            if not member(x, self.dom):
                raise EvalError(f"Attempted to apply function to argument {fmt(x)}, which is not in its domain")
            L = list(self.frame)
            self.bind(L, x)
            r = self.memo[x] = self.body(self.s, self.t, L)
        return r

    @property
    def domain(self) -> Value:
        return self.dom

    def materialize(self) -> Value:
        return make_fn({x: self.apply(x) for x in enum(self.dom)})


class Compiler:
    """Compiles expressions of one model (fixed constants) to closures."""

    # Constant folding, inlining and the specialised closures (constfold.py,
    # inline.py, specialise.py).  The tests turn them off to compare with the
    # general closures.
    fast_paths = True
    memoise_operators = True  # op_memo.py; off only to compare with the plain calls

    def __init__(self, constants: dict[str, Value], overrides: dict[str, Any]) -> None:
        # CONSTANT name -> value (from the .cfg); `overrides` maps names to symbols for `C <- Op`.
        self.constants = constants
        self.overrides = overrides
        # id(symbol) -> replacing symbol, for `C <- Op` and definitions given values
        self.sym_overrides: dict[int, Any] = {}
        self._inline_depth = 0
        # > 0 while compiling a body that runs re-entrantly on a shared frame (see inline.py).
        self._no_inline = 0
        self.folder = ConstFolder(self)
        self.op_memo = OpMemo(self)
        # (id of a LET's INSTANCE, id of the enclosing scope) -> the LET body's scope
        self._let_scopes: dict[tuple[int, int], Scope] = {}

    # ================================================================ entry points
    def compile_unit(self, e: A.Expr, scope: Scope) -> tuple[Code, int]:
        """Compile a top-level expression; returns (code, frame size)."""
        frame = Frame()
        code = self.expr(e, Env(scope, frame))
        return code, frame.size

    def evaluator(self, e: A.Expr, scope: Scope) -> Callable[[Any, Any], Value]:
        code, size = self.compile_unit(e, scope)
        if size == 0:
            return lambda s, t: code(s, t, EMPTY)
        return lambda s, t: code(s, t, [None] * size)

    # ================================================================ analysis
    def info(self, e: Any, env: Env) -> Info:
        """Variables read and action level of `e` (names resolved in `env`)."""
        vs: set[int] = set()
        action = [False]
        self._walk(e, env, vs, action, set())
        return Info(frozenset(vs), action[0])

    def def_info(self, sym: DefSym) -> Info:
        if sym.info is None:
            sym.info = _NO_INFO  # recursion guard
            env = Env(sym.scope, Frame())
            vs: set[int] = set()
            action = [False]
            self._walk(sym.defn.body, env, vs, action, {p.name for p in sym.defn.params})
            sym.info = Info(frozenset(vs), action[0])
        return sym.info  # type: ignore[return-value]

    def _walk(self, e: Any, env: Env, vs: set[int], action: list[bool], bound: set[str]) -> None:
        if isinstance(e, A.Unary) and e.op == "ENABLED":
            # ENABLED A is a state predicate: it reads the variables A reads.
            self._walk(e.arg, env, vs, [False], bound)
            return
        if isinstance(e, A.Prime) or (isinstance(e, A.Unary) and e.op == "UNCHANGED"):
            action[0] = True
        if isinstance(e, A.StepAction):
            action[0] = True
        if isinstance(e, (A.Name, A.Apply)):
            name = e.name
            if name not in bound:
                loc = env.locals.get(name)
                if isinstance(loc, ByNameLocal):
                    self._walk(loc.expr, loc.env, vs, action, set())
                elif loc is None:
                    sym = self._resolve(name, env.scope)
                    self._walk_sym(sym, env, vs, action)
        if isinstance(e, A.Prefixed):
            pinfo = self._prefixed_info(e, env)
            vs.update(pinfo.vars)
            action[0] = action[0] or pinfo.action
        if isinstance(e, A.Let):
            bound = bound | {d.name for d in e.defs}
            for d in e.defs:
                if isinstance(d, A.InstanceDef):
                    env = replace(env, scope=self.let_scope(d, env))
                    bound = bound - {d.name}
                    continue
                self._walk(d.body, env, vs, action, bound | {p.name for p in d.params})
            self._walk(e.body, env, vs, action, bound)
            return
        if isinstance(e, A.Lambda):
            self._walk(e.body, env, vs, action, bound | set(e.params))
            return
        if isinstance(e, (A.Quant, A.FnLit, A.SetMap)):
            for b in e.bounds:
                self._walk(b.set, env, vs, action, bound)
            inner = bound | {n for b in e.bounds for n in b.names}
            self._walk(e.body if not isinstance(e, A.SetMap) else e.expr, env, vs, action, inner)
            return
        if isinstance(e, A.SetFilter):
            self._walk(e.bound.set, env, vs, action, bound)
            self._walk(e.pred, env, vs, action, bound | set(e.bound.names))
            return
        if isinstance(e, A.Choose):
            if e.set is not None:
                self._walk(e.set, env, vs, action, bound)
            self._walk(e.body, env, vs, action, bound | set(e.names))
            return
        if isinstance(e, A.UnboundedQuant):
            self._walk(e.body, env, vs, action, bound | set(e.names))
            return
        for child in _children(e):
            self._walk(child, env, vs, action, bound)

    def _walk_sym(self, sym: Any, env: Env, vs: set[int], action: list[bool]) -> None:
        if id(sym) in self.sym_overrides:
            sym = self.sym_overrides[id(sym)]
        if isinstance(sym, VarSym):
            vs.add(sym.index)
        elif isinstance(sym, DefSym):
            i = self.def_info(sym)
            vs.update(i.vars)
            action[0] = action[0] or i.action
        elif isinstance(sym, SubstSym):
            sub_env = Env(sym.scope, env.frame)
            self._walk(sym.expr, sub_env, vs, action, set(sym.instance_params))
        elif isinstance(sym, BuiltinSym) and sym.builtin.name in ("TLCGet", "TLCSet"):
            vs.add(SEARCH_STATE)  # reads the search's counters: never a constant

    def _prefixed_info(self, e: A.Prefixed, env: Env) -> Info:
        scope = self._instance_scope(e, env)
        sym = scope.lookup(e.name)
        if isinstance(sym, DefSym):
            return self.def_info(sym)
        return _NO_INFO

    # ================================================================ resolution
    def _resolve(self, name: str, scope: Scope) -> Any:
        return scope.lookup(name)

    def _unknown(self, name: str, loc: Loc) -> TlaError:
        return TlaError("semantic", f"Unknown operator: `{name}'.", loc)

    # ================================================================ expressions
    def expr(self, e: A.Expr, env: Env) -> Code:
        method = getattr(self, "c_" + type(e).__name__, None)
        if method is None:
            raise UnsupportedError(f"unsupported expression {type(e).__name__}", e.loc)
        code = method(e, env)
        if self.fast_paths and type(e) not in _LITERALS and self.folder.is_constant(e, env):
            code = fold(code, env.frame.size)
        return code

    def c_Num(self, e: A.Num, env: Env) -> Code:
        return const_code(e.value)

    def c_Str(self, e: A.Str, env: Env) -> Code:
        return const_code(e.value)

    def c_Bool(self, e: A.Bool, env: Env) -> Code:
        return const_code(e.value)

    def c_Unsupported(self, e: A.Unsupported, env: Env) -> Code:
        raise UnsupportedError(f"unsupported construct: {e.what}", e.loc)

    def c_At(self, e: A.At, env: Env) -> Code:
        at = env.locals.get("@")
        if not isinstance(at, SlotLocal):
            raise TlaError("semantic", "@ used outside an EXCEPT update", e.loc)
        slot = at.slot
        return lambda s, t, L: L[slot]

    # ---------------------------------------------------------------- names
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

    def inline_let_op(self, name: str, local: LetOpLocal, args: list[A.Expr], env: Env, loc: Loc,
                      compile_body: Callable[[A.Expr, Env], Any]) -> Any:
        """Expand a LET operator at its call site (under a prime, or in an action)."""
        d = local.defn
        self._arity(name, len(d.params), args, loc)
        self._inline_depth += 1
        if self._inline_depth > 60:
            raise UnsupportedError(f"recursive action-level operator {name}", loc)
        try:
            bindings, pre = self.bind_params(d.params, args, env, loc)
            body_env = Env(local.env.scope, env.frame, {**local.env.locals, **bindings},
                           env.init_mode, env.primed)
            return pre, compile_body(d.body, body_env)
        finally:
            self._inline_depth -= 1

    def _arity(self, name: str, arity: int, args: list[A.Expr], loc: Loc) -> None:
        if len(args) != arity:
            raise TlaError("semantic", f"The operator {name} requires {arity} arguments, but "
                           f"{len(args)} were given.", loc)

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
                                                  if p in env.locals}, env.init_mode, env.primed)
            if args:
                return self._apply_operator_expr(sym.expr, args, sub_env, env, loc)
            return self.expr(sym.expr, sub_env)
        if isinstance(sym, InstanceSym):
            raise TlaError("semantic", f"{name} is an instance; use {name}!Op", loc)
        raise self._unknown(name, loc)

    # ENABLED computed as TLC does for an instanced module's variable that is
    # substituted by an expression (done <- flag = 1 /\ tok = "w"): TLC's getPrimedVar
    # stops at the substitution, so done' is a variable of its own in ENABLED's scratch
    # state, assigned by done' = e and UNCHANGED done, read by done' elsewhere.
    enabled_scratch: dict[str, int] | None = None

    def scratch_slot(self, sym: SubstSym, env: Env) -> int | None:
        """The scratch slot of `sym`'s primed value while compiling an ENABLED, if any."""
        scratch = self.enabled_scratch
        if scratch is None or not sym.variable:
            return None
        e = sym.expr
        if isinstance(e, A.Name) and isinstance(sym.scope.lookup(e.name), (VarSym, SubstSym)):
            return None  # a variable (or a further substitution): primed as usual
        slot = scratch.get(sym.name)
        if slot is None:
            slot = scratch[sym.name] = len(self.var_names) + len(scratch)
        return slot

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
        fake = [A.Name(a.loc, f"$arg{i}") for i, a in enumerate(args)]
        code = self.reference(name, fake, op_env.bind_all(bindings), loc)
        return _prefix(pre, code)

    def _bind_args_by_value(self, args: list[A.Expr], env: Env) -> tuple[dict, list]:
        bindings: dict[str, Any] = {}
        pre: list[tuple[int, Code]] = []
        for i, a in enumerate(args):
            slot = env.frame.alloc()
            pre.append((slot, self.expr(a, env)))
            bindings[f"$arg{i}"] = SlotLocal(slot, self.state_source(a, env))
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
        return any(isinstance(l, (SlotLocal, LazyLocal)) and l.source is not None for l in locs)

    def _inline_lambda(self, lam: A.Lambda, args: list[A.Expr], lam_env: Env, env: Env, loc: Loc) -> Code:
        self._arity("LAMBDA", len(lam.params), args, loc)
        bindings, pre = {}, []
        for p, a in zip(lam.params, args):
            slot = env.frame.alloc()
            pre.append((slot, self.expr(a, env)))
            bindings[p] = SlotLocal(slot, self.state_source(a, env))
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
        fake = [A.Name(a.loc, f"$arg{i}") for i, a in enumerate(args)]
        return _prefix(pre, self._symbol_ref(name, sym, fake, env.bind_all(bindings), loc))

    # ---------------------------------------------------------------- operator calls
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
        if self.fast_paths and self.memoise_operators and self.op_memo.applies(sym, args):
            self.op_memo.skip.add(id(sym))
            try:
                plain = self._call_def(sym, args, env, loc)
            finally:
                self.op_memo.skip.discard(id(sym))
            return self.op_memo.wrap(sym, plain, [self.expr(a, env) for a in args])
        if self.fast_paths and (d.params or info.vars) and can_inline(self, sym):
            return inline_call(self, sym, args, env, loc)
        compiled = self._compiled_def(sym)
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
        arg_codes = [self._arg(a, p.arity, env, loc) for a, p in zip(args, d.params)]
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
        arg_codes = [self._arg(a, p.arity, env, loc) for a, p in zip(args, sym.defn.params)]
        holder = self._compiled_def(sym)
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

    def _compiled_def(self, sym: DefSym) -> "CompiledDef":
        if sym.compiled is None:
            holder = CompiledDef(self, sym)
            sym.compiled = holder
            frame = Frame()
            bindings: dict[str, Any] = {}
            for p in sym.defn.params:
                slot = frame.alloc()
                bindings[p.name] = OpLocal(slot, p.arity) if p.arity else SlotLocal(slot)
            holder.body = self.expr(sym.defn.body, Env(sym.scope, frame, bindings))
            holder.size = frame.size
            holder.holder_only = False
        return sym.compiled  # type: ignore[return-value]

    def inline_def(self, sym: DefSym, args: list[A.Expr], env: Env, loc: Loc,
                   compile_body: Callable[[A.Expr, Env], Any]) -> Any:
        """Expand an operator at its call site (action-level operators, Init, instances)."""
        d = sym.defn
        self._arity(d.name, len(d.params), args, loc)
        self._inline_depth += 1
        if self._inline_depth > 60:
            raise UnsupportedError(f"recursive action-level operator {d.name}", loc)
        try:
            bindings, pre = self.bind_params(d.params, args, env, loc)
            inst = {p: env.locals[p] for p in sym.scope.instance_params if p in env.locals}
            body_env = Env(sym.scope, env.frame, {**inst, **bindings}, env.init_mode, env.primed)
            if d.fn_bounds is not None:
                body = compile_body(A.FnLit(d.loc, d.fn_bounds, d.body), body_env)
            else:
                body = compile_body(d.body, body_env)
        finally:
            self._inline_depth -= 1
        return pre, body

    def bind_params(self, params: list[A.Param], args: list[A.Expr], env: Env, loc: Loc) -> tuple[dict, list]:
        """Bind operator parameters: by value into fresh slots (remembering an argument
        that reads state, which a prime in the body primes), or by name for
        action-level arguments (which the body must see unevaluated)."""
        bindings: dict[str, Any] = {}
        pre: list[tuple[int, Code]] = []
        for p, a in zip(params, args):
            if p.arity:
                slot = env.frame.alloc()
                pre.append((slot, self._arg(a, p.arity, env, loc)))
                bindings[p.name] = OpLocal(slot, p.arity)
            elif self.info(a, env).action or env.init_mode:
                bindings[p.name] = ByNameLocal(a, env)
            else:
                slot = env.frame.alloc()
                pre.append((slot, self.expr(a, env)))
                bindings[p.name] = SlotLocal(slot, self.state_source(a, env))
        return bindings, pre

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
        fake = [A.Name(a.loc, f"$p{i}") for i in range(arity)]
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

    def _fn_def_ref(self, sym: DefSym) -> Code:
        """A function definition ``f[x \\in S] == e`` (possibly recursive)."""
        d = sym.defn
        assert d.fn_bounds is not None
        if len(d.fn_bounds) != 1 or len(d.fn_bounds[0].names) != 1 or d.fn_bounds[0].tuple:
            # f[m \in S, n \in T] == ... f[..] ...: as a recursive LET function.
            frame = Frame()
            env, fslot = self._let_recursive_function(d, Env(sym.scope, frame))
            read = self.expr(A.Name(d.loc, d.name), env)
            info = self.def_info(sym)
            constant = not info.vars and not info.action
            cache: list = []  # constant-level: the same function every time

            def several(s: Any, t: Any, L: list) -> Value:
                if cache:
                    return cache[0]
                L2 = [None] * frame.size
                L2[fslot] = NOTSET
                v = read(s, t, L2)
                if constant:
                    cache.append(v)
                return v
            return several
        compiled = sym.compiled
        if compiled is None:
            frame = Frame()
            env = Env(sym.scope, frame)
            dom = self.expr(d.fn_bounds[0].set, env)
            slot = frame.alloc()
            self_slot = frame.alloc()
            compiled = sym.compiled = [dom, None, slot, self_slot, frame]
            compiled[1] = self.expr(d.body, env.bind(**{d.fn_bounds[0].names[0]: SlotLocal(slot),
                                                         d.name: SlotLocal(self_slot)}))
        dom_code, _, slot, self_slot, frame = compiled

        def make(s: Any, t: Any, L: list) -> Value:
            body = compiled[1]
            size = frame.size
            dom = dom_code(s, t, [None] * size)

            def with_self(s2: Any, t2: Any, L2: list) -> Value:
                L2[self_slot] = f
                return body(s2, t2, L2)
            f = RecursiveFunction(dom, with_self, lambda L2, x: L2.__setitem__(slot, x), [None] * size, s, t)
            if isinstance(dom, LazySet) and not dom.finite:
                return f
            return f.materialize()
        return make

    def _let_op_call(self, name: str, local: LetOpLocal, args: list[A.Expr], env: Env, loc: Loc) -> Code:
        d = local.defn
        self._arity(name, len(d.params), args, loc)
        if not local.holder:
            local.holder.extend([None, []])
            bindings = {}
            for p, sl in zip(d.params, local.param_slots):
                bindings[p.name] = OpLocal(sl, p.arity) if p.arity else SlotLocal(sl)
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
        arg_codes = [self._arg(a, p.arity, env, loc) for a, p in zip(args, d.params)]

        def call(s: Any, t: Any, L: list) -> Value:
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

    # ---------------------------------------------------------------- instances
    def _instance_scope(self, e: A.Prefixed, env: Env) -> Scope:
        scope = env.scope
        for step in e.path:
            sym = scope.lookup(step.name)
            if not isinstance(sym, InstanceSym):
                raise TlaError("semantic", f"{step.name} is not an instance (in {step.name}!...)", e.loc)
            scope = sym.scope
        return scope

    def c_Prefixed(self, e: A.Prefixed, env: Env) -> Code:
        return self.prefixed(e, env, self.expr)

    def prefixed(self, e: A.Prefixed, env: Env, compile_body: Callable) -> Any:
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
        arg_bindings, arg_pre = self._bind_args_by_value(e.args, env)
        fake = [A.Name(a.loc, f"$arg{i}") for i, a in enumerate(e.args)]
        inner_env = Env(scope, env.frame, {**bindings, **arg_bindings}, env.init_mode, env.primed)
        pre = pre + arg_pre
        if isinstance(sym, DefSym) and compile_body != self.expr:
            d = sym.defn
            self._arity(d.name, len(d.params), fake, e.loc)
            pb, pp = self.bind_params(d.params, fake, inner_env, e.loc)
            inst = {p: inner_env.locals[p] for p in sym.scope.instance_params if p in inner_env.locals}
            body = compile_body(d.body, Env(sym.scope, env.frame, {**inst, **arg_bindings, **pb}, env.init_mode, env.primed))
            return pre + pp, body
        code = self._symbol_ref(e.name, sym, fake, inner_env, e.loc)
        if compile_body != self.expr:
            return pre, code
        return _prefix(pre, code)

    # ---------------------------------------------------------------- logic
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

    def c_Let(self, e: A.Let, env: Env) -> Code:
        env2, resets = self.bind_let(e.defs, env)
        body = self.expr(e.body, env2)
        if not resets:
            return body

        def let(s: Any, t: Any, L: list) -> Value:
            for sl in resets:
                L[sl] = NOTSET
            return body(s, t, L)
        return let

    def bind_let(self, defs: list[A.OpDef], env: Env) -> tuple[Env, list[int]]:
        resets: list[int] = []
        for d in defs:
            if isinstance(d, A.InstanceDef):
                env = replace(env, scope=self.let_scope(d, env))
                continue
            if d.params:
                local: Any = LetOpLocal(d, env, [env.frame.alloc() for _ in d.params], [])
                env = env.bind(**{d.name: local})
                local.env = env  # may call itself (RECURSIVE)
                continue
            body_expr: A.Expr = A.FnLit(d.loc, d.fn_bounds, d.body) if d.fn_bounds else d.body
            if d.fn_bounds and d.name in all_names(d.body):
                env, reset = self._let_recursive_function(d, env)
                resets.append(reset)
                continue
            if self.info(body_expr, env).action or env.init_mode:
                env = env.bind(**{d.name: ByNameLocal(body_expr, env)})
                continue
            slot = env.frame.alloc()
            code = self.expr(body_expr, env)
            env = env.bind(**{d.name: LazyLocal(slot, code, (body_expr, env),
                                                self.state_source(body_expr, env) is not None)})
            resets.append(slot)
        return env, resets

    def let_scope(self, inst: A.InstanceDef, env: Env) -> Scope:
        """The scope after ``LET I == INSTANCE M ...`` (built once per enclosing scope)."""
        key = (id(inst), id(env.scope))
        scope = self._let_scopes.get(key)
        if scope is None:
            scope = self._let_scopes[key] = let_instance_scope(env.scope, inst, tuple(env.locals))
        return scope

    def _let_recursive_function(self, d: A.OpDef, env: Env) -> tuple[Env, int]:
        """``LET f[x \\in S] == ... f[..] ... IN``: a `RecursiveFunction` over a copy of the
        LET's frame, so that the body sees the enclosing bound variables."""
        assert d.fn_bounds is not None
        slot = env.frame.alloc()
        holder: list[Code] = []
        env = env.bind(**{d.name: LazyLocal(slot, lambda s, t, L: holder[0](s, t, L))})
        inner, binds = self.bind_bounds(d.fn_bounds, env)
        body = self.expr(d.body, inner)
        set_codes = [b[0] for b in binds]
        loc = d.loc

        def bind(L: list, x: Value) -> None:
            if len(binds) == 1:
                _assign(L, binds[0][1], binds[0][2], x, loc)
                return
            if type(x) is not tuple or len(x) != len(binds):
                raise EvalError(f"Attempted to apply function {d.name} to argument {fmt(x)}, which is not in "
                                f"its domain", loc)
            for (_, slots, is_tuple, _), v in zip(binds, x):
                _assign(L, slots, is_tuple, v, loc)

        def make(s: Any, t: Any, L: list) -> Value:
            doms = [_need_set(c(s, t, L), "function definition") for c in set_codes]
            dom = doms[0] if len(doms) == 1 else ProductSet(tuple(doms))
            frame = list(L)
            f = RecursiveFunction(dom, body, bind, frame, s, t)
            frame[slot] = f
            if isinstance(dom, LazySet) and not dom.finite:
                return f
            return f.materialize()
        holder.append(_guard(make, loc))
        return env, slot

    # ---------------------------------------------------------------- quantifiers
    def bind_bounds(self, bounds: list[A.Bound], env: Env) -> tuple[Env, list[tuple[Code, list[int], bool, Loc]]]:
        """Allocate slots for bound variables; returns the body env and, per bound,
        (set code, slots, is-tuple-pattern, loc)."""
        out = []
        inner = env
        for b in bounds:
            set_code = self.expr(b.set, env)
            if b.tuple:
                slots = [env.frame.alloc() for _ in b.names]
                out.append((set_code, slots, True, b.set.loc))
                inner = inner.bind_all({n: SlotLocal(sl) for n, sl in zip(b.names, slots)})
            else:
                for n in b.names:
                    sl = env.frame.alloc()
                    out.append((set_code, [sl], False, b.set.loc))
                    inner = inner.bind(**{n: SlotLocal(sl)})
        return inner, out

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
            raise EvalError(f"Attempted to compute the value of an expression of form\nCHOOSE x \\in S: P, "
                            f"but no element of S satisfied P.", loc)
        return choose

    # ---------------------------------------------------------------- sets
    def c_SetEnum(self, e: A.SetEnum, env: Env) -> Code:
        codes = [self.expr(x, env) for x in e.elems]
        if all(isinstance(x, (A.Num, A.Str, A.Bool)) for x in e.elems):
            v = frozenset(x.value for x in e.elems)  # type: ignore[attr-defined]
            return lambda s, t, L: v
        return lambda s, t, L: frozenset([c(s, t, L) for c in codes])

    def c_SetFilter(self, e: A.SetFilter, env: Env) -> Code:
        inner, binds = self.bind_bounds([e.bound], env)
        pred = self.expr(e.pred, inner)
        set_code, slots, is_tuple, sloc = binds[0]
        ploc = e.pred.loc

        def filt(s: Any, t: Any, L: list) -> Value:
            base = set_code(s, t, L)
            if isinstance(base, LazySet) and not base.finite:
                return _lazy_filter(base, pred, slots, is_tuple, sloc, ploc, s, t, list(L))
            out = []
            for v in _enum_checked(base, sloc):
                _assign(L, slots, is_tuple, v, sloc)
                r = pred(s, t, L)
                if r is True:
                    out.append(v)
                elif r is not False:
                    check_bool(r, ploc, "set filter")
            return frozenset(out)
        return filt

    def c_SetMap(self, e: A.SetMap, env: Env) -> Code:
        inner, binds = self.bind_bounds(e.bounds, env)
        body = self.expr(e.expr, inner)
        if len(binds) == 1 and not binds[0][2]:
            set_code, (slot,), _, sloc = binds[0]

            def smap1(s: Any, t: Any, L: list) -> frozenset:
                out = []
                for v in _enum_checked(set_code(s, t, L), sloc):
                    L[slot] = v
                    out.append(body(s, t, L))
                return frozenset(out)
            return smap1
        return _comprehension(binds, body, lambda out: frozenset(out))

    def c_Binary(self, e: A.Binary, env: Env) -> Code:
        op = e.op
        sym = env.scope.lookup(op)
        if isinstance(sym, DefSym):
            return self._call_def(sym, [e.lhs, e.rhs], env, e.loc)
        if op in ("\\in", "\\notin"):
            if self.fast_paths and self.folder.is_constant(e.rhs, env):
                fast = member_const(self.expr(e.lhs, env), const_value(self.expr(e.rhs, env)), op == "\\notin")
                if fast is not None:
                    return fast
            test = self.membership(e.rhs, env)
            lhs = self.expr(e.lhs, env)
            loc = e.loc
            if op == "\\in":
                return _guard(lambda s, t, L: test(s, t, L, lhs(s, t, L)), loc)
            return _guard(lambda s, t, L: not test(s, t, L, lhs(s, t, L)), loc)
        a, b = self.expr(e.lhs, env), self.expr(e.rhs, env)
        loc = e.loc
        if op in ("=", "/=") and self.fast_paths:
            fast = eq_code(a, b, loc, op == "/=")
            if fast is not None:
                return fast
        if op == "=":
            def eq(s: Any, t: Any, L: list) -> bool:
                x, y = a(s, t, L), b(s, t, L)
                if type(x) is type(y):
                    return x == y
                try:
                    return values_equal(x, y)
                except EvalError as err:
                    raise err.with_loc(loc)
            return eq
        if op == "/=":
            def neq(s: Any, t: Any, L: list) -> bool:
                x, y = a(s, t, L), b(s, t, L)
                if type(x) is type(y):
                    return x != y
                try:
                    return not values_equal(x, y)
                except EvalError as err:
                    raise err.with_loc(loc)
            return neq
        if op == "=>":
            la, lb = e.lhs.loc, e.rhs.loc

            def implies(s: Any, t: Any, L: list) -> bool:
                x = a(s, t, L)
                if x is False:
                    return True
                if x is not True:
                    check_bool(x, la)
                y = b(s, t, L)
                return y if (y is True or y is False) else check_bool(y, lb)
            return implies
        if op in ("<=>", "\\equiv"):
            la, lb = e.lhs.loc, e.rhs.loc
            return lambda s, t, L: check_bool(a(s, t, L), la) is check_bool(b(s, t, L), lb)
        core = _CORE_BINARY.get(op)
        if core is not None:
            return _guard(lambda s, t, L: core(a(s, t, L), b(s, t, L)), loc)
        if isinstance(sym, BuiltinSym):
            fast = _FAST_INT.get(op) if sym.builtin is NATURALS.get(op) else None
            if fast is not None:
                if op == "..":
                    a, b = self._interval_bound(e.lhs, a, env), self._interval_bound(e.rhs, b, env)
                return fast(a, b, loc)
            fn = sym.builtin.fn
            return _guard(lambda s, t, L: fn(a(s, t, L), b(s, t, L)), loc)
        if op in ("~>", "-+->"):
            raise UnsupportedError(f"temporal operator {op}", loc)
        if op == "\\cdot":
            raise UnsupportedError("action composition \\cdot", loc)
        raise self._unknown(op, loc)

    def c_Unary(self, e: A.Unary, env: Env) -> Code:
        op = e.op
        if op in ("[]", "<>"):
            raise UnsupportedError(f"temporal operator {op} in an expression evaluated by the checker", e.loc)
        if op == "ENABLED":
            from .actions import compile_enabled
            return compile_enabled(self, e.arg, env)
        if op == "UNCHANGED":
            return self._unchanged_expr(e.arg, env)
        user = env.scope.lookup("-." if op == "-" else op)
        if isinstance(user, DefSym):
            return self._call_def(user, [e.arg], env, e.loc)
        a = self.expr(e.arg, env)
        loc = e.loc
        if op == "~":
            aloc = e.arg.loc

            def lnot(s: Any, t: Any, L: list) -> bool:
                v = a(s, t, L)
                if v is True:
                    return False
                if v is False:
                    return True
                return check_bool(v, aloc, "operand of ~")
            return lnot
        if op == "-":
            if not isinstance(user, BuiltinSym):
                raise self._unknown("-", loc)
            fn = user.builtin.fn
            return _guard(lambda s, t, L: fn(a(s, t, L)), loc)
        if op == "SUBSET":
            return _guard(lambda s, t, L: PowerSet(_need_set(a(s, t, L), "SUBSET")), loc)
        if op == "UNION":
            return _guard(lambda s, t, L: union(a(s, t, L)), loc)
        if op == "DOMAIN":
            return _guard(lambda s, t, L: domain(a(s, t, L)), loc)
        if isinstance(user, BuiltinSym):
            fn = user.builtin.fn
            return _guard(lambda s, t, L: fn(a(s, t, L)), loc)
        raise self._unknown(op, loc)

    def _unchanged_expr(self, arg: A.Expr, env: Env) -> Code:
        now = self.expr(arg, env)
        nxt = self.c_Prime(A.Prime(arg.loc, arg), env)
        return lambda s, t, L: now(s, t, L) == nxt(s, t, L)

    def _interval_bound(self, e: A.Expr, code: Code, env: Env) -> Code:
        """An operand of `..`.  TLC builds `SUBSET S` without checking S, so with a
        non-set S the error is `..`'s (a Java exception in TLC, `JavaOverrideError`),
        not SUBSET's."""
        if not (isinstance(e, A.Unary) and e.op == "SUBSET"):
            return code
        arg, loc = self.expr(e.arg, env), e.loc

        def bound(s: Any, t: Any, L: list) -> Value:
            v = arg(s, t, L)
            if type(v) is frozenset or isinstance(v, LazySet):
                return PowerSet(v)
            raise JavaOverrideError(f"Attempted to apply the operator .. to SUBSET of the non-set {fmt(v)}", loc)
        return bound

    def _product(self, e: A.Apply, env: Env) -> Code:
        codes = [self.expr(x, env) for x in e.args]
        # Factors are checked when the product is used (values.ProductSet), as by TLC.
        return _guard(lambda s, t, L: ProductSet(tuple(c(s, t, L) for c in codes)), e.loc)

    def membership(self, set_expr: A.Expr, env: Env) -> Callable[[Any, Any, list, Value], bool]:
        """Compile ``v \\in set_expr`` without building structured sets."""
        e = set_expr
        if self.fast_paths and self.folder.is_constant(e, env):
            fast = membership_const(const_value(self.expr(e, env)))
            if fast is not None:
                return fast
        if isinstance(e, A.Binary) and e.op == ".." and isinstance(env.scope.lookup(".."), BuiltinSym):
            lo = self._interval_bound(e.lhs, self.expr(e.lhs, env), env)
            hi = self._interval_bound(e.rhs, self.expr(e.rhs, env), env)
            loc = e.loc

            def in_interval(s: Any, t: Any, L: list, v: Value) -> bool:
                a, b = lo(s, t, L), hi(s, t, L)
                if type(a) is not int or type(b) is not int:
                    first = type(a) is not int
                    raise non_integer_error("..", a if first else b, first).with_loc(loc)
                return type(v) is int and a <= v <= b
            return in_interval
        if isinstance(e, A.FnSet):
            dom = self.expr(e.domain, env)
            rng = self.membership(e.range, env)

            def in_fnset(s: Any, t: Any, L: list, v: Value) -> bool:
                D = dom(s, t, L)
                if type(v) is tuple:
                    if not _domain_is(D, len(v), None):
                        return False
                    vals: Any = v
                elif type(v) is FnValue:
                    if not _domain_is(D, len(v.d), v.d):
                        return False
                    vals = v.d.values()
                else:
                    return False
                for x in vals:
                    if not rng(s, t, L, x):
                        return False
                return True
            return in_fnset
        if isinstance(e, A.RecSet):
            fields = [(n, self.membership(x, env)) for n, x in e.fields]
            nf = len(fields)

            def in_recset(s: Any, t: Any, L: list, v: Value) -> bool:
                if type(v) is not FnValue or len(v.d) != nf:
                    return False
                d = v.d
                for n, test in fields:
                    if n not in d or not test(s, t, L, d[n]):
                        return False
                return True
            return in_recset
        if isinstance(e, A.Unary) and e.op == "SUBSET" and not isinstance(env.scope.lookup("SUBSET"), DefSym):
            base = self.membership(e.arg, env)

            def in_powerset(s: Any, t: Any, L: list, v: Value) -> bool:
                if not is_set(v):
                    return False
                return all(base(s, t, L, x) for x in as_set(v))
            return in_powerset
        if isinstance(e, A.Apply) and e.name == "\\X":
            factors = [self.membership(x, env) for x in e.args]
            n = len(factors)
            return lambda s, t, L, v: (type(v) is tuple and len(v) == n
                                       and all(f(s, t, L, x) for f, x in zip(factors, v)))
        if isinstance(e, A.Apply) and e.name == "Seq" and len(e.args) == 1 and isinstance(
                env.scope.lookup("Seq"), BuiltinSym):
            base = self.membership(e.args[0], env)
            return lambda s, t, L, v: type(v) is tuple and all(base(s, t, L, x) for x in v)
        code = self.expr(e, env)
        return lambda s, t, L, v: member(v, code(s, t, L))

    # ---------------------------------------------------------------- functions
    def c_FnLit(self, e: A.FnLit, env: Env) -> Code:
        inner, binds = self.bind_bounds(e.bounds, env)
        body = self.expr(e.body, inner)
        if len(binds) == 1 and not binds[0][2]:
            set_code, (slot,), _, sloc = binds[0]

            def fnlit(s: Any, t: Any, L: list) -> Value:
                S = set_code(s, t, L)
                if type(S) is IntervalSet and S.lo == 1:
                    out = []
                    for i in range(1, S.hi + 1):
                        L[slot] = i
                        out.append(body(s, t, L))
                    return tuple(out)
                d = {}
                for v in _enum_checked(S, sloc):
                    L[slot] = v
                    d[v] = body(s, t, L)
                return make_fn(d)
            return fnlit
        # Several bound variables: the domain is a product, keys are tuples.
        n_keys = sum(len(sl) if not tup else 1 for _, sl, tup, _ in binds)

        def key_of(L: list) -> Value:
            parts = []
            for _, slots, tup, _ in binds:
                if tup:
                    parts.append(tuple(L[sl] for sl in slots))
                else:
                    parts.append(L[slots[0]])
            return tuple(parts)
        del n_keys
        return _comprehension(binds, body, None, key_of)

    def c_FnApp(self, e: A.FnApp, env: Env) -> Code:
        f = self.expr(e.fn, env)
        loc = e.loc
        if len(e.args) == 1:
            x = self.expr(e.args[0], env)
        else:
            parts = [self.expr(a, env) for a in e.args]
            x = lambda s, t, L: tuple([p(s, t, L) for p in parts])  # noqa: E731

        def app(s: Any, t: Any, L: list) -> Value:
            fv = f(s, t, L)
            k = x(s, t, L)
            if type(fv) is tuple:
                if type(k) is int and 0 < k <= len(fv):
                    return fv[k - 1]
            elif type(fv) is FnValue:
                r = fv.d.get(k, NOTSET)
                if r is not NOTSET:
                    return r
            elif type(fv) is RecursiveFunction:
                try:
                    return fv.apply(k)
                except EvalError as err:
                    raise err.with_loc(loc)
            elif type(fv) is str and type(k) is int and 0 < k <= len(fv):
                return fv[k - 1]
            else:
                raise EvalError(f"A non-function ({kind(fv)} {fmt(fv)}) was applied as a function.", loc)
            raise EvalError(f"Attempted to apply function:\n{fmt(fv)}\nto argument {fmt(k)}, which is "
                            f"not in the domain of the function.", loc)
        return app

    def c_FnSet(self, e: A.FnSet, env: Env) -> Code:
        d, r = self.expr(e.domain, env), self.expr(e.range, env)
        return _guard(lambda s, t, L: FnSetValue(_need_set(d(s, t, L), "[ -> ]"), _need_set(r(s, t, L), "[ -> ]")),
                      e.loc)

    def c_RecLit(self, e: A.RecLit, env: Env) -> Code:
        names = [n for n, _ in e.fields]
        codes = [self.expr(x, env) for _, x in e.fields]
        return lambda s, t, L: FnValue(dict(zip(names, [c(s, t, L) for c in codes])))

    def c_RecSet(self, e: A.RecSet, env: Env) -> Code:
        names = [n for n, _ in e.fields]
        codes = [self.expr(x, env) for _, x in e.fields]
        return _guard(lambda s, t, L: RecSetValue(tuple(zip(names, [_need_set(c(s, t, L), "[a : S]")
                                                                       for c in codes]))), e.loc)

    def c_Dot(self, e: A.Dot, env: Env) -> Code:
        return dot_code(self.expr(e.rec, env), e.field, e.loc, self.fast_paths)

    def c_TupleLit(self, e: A.TupleLit, env: Env) -> Code:
        codes = [self.expr(x, env) for x in e.elems]
        if len(codes) == 2:
            c0, c1 = codes
            return lambda s, t, L: (c0(s, t, L), c1(s, t, L))
        return lambda s, t, L: tuple([c(s, t, L) for c in codes])

    def c_Except(self, e: A.Except, env: Env) -> Code:
        base = self.expr(e.base, env)
        at_slot = env.frame.alloc()
        inner = env.bind(**{"@": SlotLocal(at_slot)})
        updates = []
        for u in e.updates:
            path = []
            for kind_, item in u.path:
                if kind_ == "field":
                    path.append(const_code(item))
                else:
                    exprs = item  # type: ignore[assignment]
                    if len(exprs) == 1:
                        path.append(self.expr(exprs[0], env))
                    else:
                        parts = [self.expr(x, env) for x in exprs]
                        path.append(lambda s, t, L, parts=parts: tuple([p(s, t, L) for p in parts]))
            updates.append((path, self.expr(u.value, inner)))
        loc = e.loc

        def except_(s: Any, t: Any, L: list) -> Value:
            f = base(s, t, L)
            for path, val in updates:
                keys = [p(s, t, L) for p in path]
                f = _update(f, keys, 0, val, s, t, L, at_slot, loc)
            return f
        if self.fast_paths and all(len(path) == 1 for path, _ in updates):
            flat = []
            for (key,), val in updates:
                kv = const_value(key)
                flat.append((kv if kv is not NO_VALUE and type(kv) is not tuple else (key,), val))
            return except_flat(base, flat, at_slot, except_)
        return except_

    # ---------------------------------------------------------------- actions in expressions
    def c_Prime(self, e: A.Prime, env: Env) -> Code:
        if env.init_mode:
            raise TlaError("semantic", "primed variable in the initial predicate", e.loc)
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

    def c_Fairness(self, e: A.Fairness, env: Env) -> Code:
        raise UnsupportedError("fairness formula evaluated as an expression", e.loc)

    def c_Lambda(self, e: A.Lambda, env: Env) -> Code:
        raise TlaError("semantic", "LAMBDA is only allowed as an operator argument", e.loc)

    def c_OpRef(self, e: A.OpRef, env: Env) -> Code:
        raise TlaError("semantic", f"operator {e.name} used as a value", e.loc)


class CompiledDef:
    """A compiled operator definition (body closure and frame size); zero-argument
    constant-level definitions are evaluated once and cached."""

    def __init__(self, compiler: Compiler, sym: DefSym) -> None:
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


# ------------------------------------------------------------------ helpers


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


def _prefix(pre: list[tuple[int, Code]], code: Code) -> Code:
    """Evaluate argument values into their slots, then run `code`."""
    if not pre:
        return code
    if len(pre) == 1:
        (sl, a), = pre

        def pre1(s: Any, t: Any, L: list) -> Value:
            L[sl] = a(s, t, L)
            return code(s, t, L)
        return pre1

    def pren(s: Any, t: Any, L: list) -> Value:
        for sl, a in pre:
            L[sl] = a(s, t, L)
        return code(s, t, L)
    return pren


def _guard(code: Code, loc: Loc) -> Code:
    """Attach `loc` to evaluation errors raised without a position."""
    def guarded(s: Any, t: Any, L: list) -> Value:
        try:
            return code(s, t, L)
        except EvalError as err:
            raise err.with_loc(loc)
        except (TypeError, RecursionError) as err:
            raise EvalError(_python_error(err), loc) from None
    return guarded


def _python_error(err: Exception) -> str:
    if isinstance(err, RecursionError):
        return "recursion too deep (an operator or function probably does not terminate)"
    return f"type error: {err}"


def _apply_fn(fn: Callable, codes: list[Code]) -> Code:
    if len(codes) == 1:
        c0, = codes
        return lambda s, t, L: fn(c0(s, t, L))
    if len(codes) == 2:
        c0, c1 = codes
        return lambda s, t, L: fn(c0(s, t, L), c1(s, t, L))
    return lambda s, t, L: fn(*[c(s, t, L) for c in codes])


def _need_set(v: Value, op: str) -> Value:
    if type(v) is frozenset or isinstance(v, LazySet):
        return v
    raise EvalError(f"Attempted to apply {op} to the non-set {fmt(v)}")


def _enum_checked(S: Value, loc: Loc) -> Any:
    if type(S) is frozenset:
        return sorted_elems(S)
    if type(S) is IntervalSet:
        return range(S.lo, S.hi + 1)
    if isinstance(S, LazySet):
        if not S.finite:
            raise EvalError(f"TLC cannot enumerate the infinite set {S.describe()}", loc)
        return sorted_elems(S)
    raise EvalError(f"Attempted to enumerate the non-set {kind(S)} {fmt(S)}", loc)


def _assign(L: list, slots: list[int], is_tuple: bool, v: Value, loc: Loc) -> None:
    if not is_tuple:
        L[slots[0]] = v
        return
    if type(v) is not tuple or len(v) != len(slots):
        raise EvalError(f"Attempted to match {fmt(v)} against a tuple of {len(slots)} identifiers", loc)
    for sl, x in zip(slots, v):
        L[sl] = x


def _lazy_filter(base: LazySet, pred: Code, slots: list[int], is_tuple: bool, sloc: Loc, ploc: Loc,
                 s: Any, t: Any, L: list) -> FilteredSet:
    """{x \\in S : P} over an infinite S: membership tests x \\in S and P(x) (TLC's
    SetPredValue), enumeration is an error."""
    def test(v: Value) -> bool:
        if not base.contains(v):
            return False
        _assign(L, slots, is_tuple, v, sloc)
        return check_bool(pred(s, t, L), ploc, "set filter")
    return FilteredSet(test, f"{{x \\in {base.describe()} : ...}}")


def _comprehension(binds: list, body: Code, finish: Callable | None, key_of: Callable | None = None) -> Code:
    n = len(binds)

    def run(s: Any, t: Any, L: list) -> Value:
        out: Any = {} if key_of is not None else []

        def rec(i: int) -> None:
            if i == n:
                if key_of is not None:
                    out[key_of(L)] = body(s, t, L)
                else:
                    out.append(body(s, t, L))
                return
            set_code, slots, is_tuple, sloc = binds[i]
            for v in _enum_checked(set_code(s, t, L), sloc):
                _assign(L, slots, is_tuple, v, sloc)
                rec(i + 1)
        rec(0)
        if key_of is not None:
            return make_fn(out)
        return finish(out)  # type: ignore[misc]
    return run


def _domain_is(D: Value, n: int, d: dict | None) -> bool:
    if type(D) is IntervalSet:
        return d is None and D.lo == 1 and D.hi == n or (d is not None and D.size() == n and all(
            type(k) is int and D.lo <= k <= D.hi for k in d))
    S = as_set(D)
    if len(S) != n:
        return False
    if d is None:
        return all(i in S for i in range(1, n + 1))
    return all(k in S for k in d)


def _update(f: Value, keys: list, i: int, val: Code, s: Any, t: Any, L: list, at_slot: int, loc: Loc) -> Value:
    k = keys[i]
    if type(f) is tuple:
        if not (type(k) is int and 0 < k <= len(f)):
            return f
        old = f[k - 1]
    elif type(f) is FnValue:
        old = f.d.get(k, NOTSET)
        if old is NOTSET:
            return f
    else:
        raise EvalError(f"Attempted to apply EXCEPT to the non-function {fmt(f)}", loc)
    if i + 1 == len(keys):
        L[at_slot] = old
        new = val(s, t, L)
    else:
        new = _update(old, keys, i + 1, val, s, t, L, at_slot, loc)
    if type(f) is tuple:
        return f[:k - 1] + (new,) + f[k:]
    d = dict(f.d)
    d[k] = new
    return FnValue(d)


def _subset(a: Value, b: Value) -> bool:
    return subseteq(a, b) and as_set(a) != as_set(b)


_CORE_BINARY: dict[str, Callable[[Value, Value], Value]] = {
    "\\cup": cup, "\\cap": cap, "\\": setminus, "\\subseteq": subseteq,
    "\\supseteq": lambda a, b: subseteq(b, a), "\\subset": _subset, "\\supset": lambda a, b: _subset(b, a),
    "=": lambda a, b: values_equal(a, b), "/=": lambda a, b: not values_equal(a, b),
    "\\in": lambda a, b: member(a, b), "\\notin": lambda a, b: not member(a, b),
}


def _int_op(op: str, f: Callable[[int, int], Value]) -> Callable[[Code, Code, Loc], Code]:
    def make(a: Code, b: Code, loc: Loc) -> Code:
        def slow(x: Value, y: Value) -> Value:
            first = type(x) is not int
            raise non_integer_error(op, x if first else y, first).with_loc(loc)
        c = const_value(b)
        if type(c) is int:
            # `x + 1`, `n - 1`, `i <= N`: the right operand is a constant.
            def code_c(s: Any, t: Any, L: list) -> Value:
                x = a(s, t, L)
                if type(x) is int:
                    return f(x, c)
                return slow(x, c)
            return code_c

        def code(s: Any, t: Any, L: list) -> Value:
            x = a(s, t, L)
            y = b(s, t, L)
            if type(x) is int and type(y) is int:
                return f(x, y)
            return slow(x, y)
        return code
    return make


def _checked(op: str, fn: Callable, fast: Callable[[int, int], int], ok: Callable[[int], bool]) -> Callable[[Code, Code, Loc], Code]:
    """``%`` and ``\\div``: integers with a valid divisor take the fast path; anything
    else goes through the standard-library function for TLC's error message."""
    def make(a: Code, b: Code, loc: Loc) -> Code:
        def code(s: Any, t: Any, L: list) -> Value:
            try:
                x = a(s, t, L)
                y = b(s, t, L)
                if type(x) is int and type(y) is int and ok(y):
                    return fast(x, y)
                return fn(x, y)
            except EvalError as err:
                raise err.with_loc(loc)
            except (TypeError, RecursionError) as err:
                raise EvalError(_python_error(err), loc) from None
        c = const_value(b)
        if type(c) is int and ok(c):
            def code_c(s: Any, t: Any, L: list) -> Value:
                try:
                    x = a(s, t, L)
                except EvalError as err:
                    raise err.with_loc(loc)
                except (TypeError, RecursionError) as err:
                    raise EvalError(_python_error(err), loc) from None
                if type(x) is int:
                    return fast(x, c)
                try:
                    return fn(x, c)
                except EvalError as err:
                    raise err.with_loc(loc)
            return code_c
        return code
    return make


_FAST_INT = {
    "+": _int_op("+", operator.add), "-": _int_op("-", operator.sub),
    "*": _int_op("*", operator.mul), "<": _int_op("<", operator.lt),
    "<=": _int_op("<=", operator.le), ">": _int_op(">", operator.gt),
    ">=": _int_op(">=", operator.ge), "..": _int_op("..", IntervalSet),
    "%": _checked("%", NATURALS["%"].fn, operator.mod, (0).__lt__),
    "\\div": _checked("\\div", NATURALS["\\div"].fn, operator.floordiv, (0).__ne__),
}


def _operator_value(body: Callable, slots: list[int]) -> Callable:
    """A LAMBDA or operator argument as a Python callable: binds its parameters to their
    frame slots for the call and restores them afterwards (the frame is reused)."""
    def make_op(s: Any, t: Any, L: list) -> Callable:
        def op(*vals: Value) -> Value:
            saved = [L[sl] for sl in slots]
            for sl, v in zip(slots, vals):
                L[sl] = v
            try:
                return body(s, t, L)
            finally:
                for sl, v in zip(slots, saved):
                    L[sl] = v
        return op
    return make_op
