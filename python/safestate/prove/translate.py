"""Translation of TLA+ expressions (the front end's typed AST) to symbolic values.

`Translator.val` gives the symbolic value of an expression (see values.py and
sets.py); `Translator.act` translates an action or initial predicate to a z3
Bool, replacing each ``\\E x \\in S`` met in a positive position by a fresh
"Skolem" constant constrained to S (one per step of an unrolling), so an
existential over a large set of inputs costs one symbolic copy of its body
instead of one per element.

Operators are inlined at each use and memoised by their z3 arguments (z3 terms
are hash-consed, so equal arguments are the same term).  Anything outside the
translatable subset raises `ProveError` with the position of the construct.
"""

from __future__ import annotations

from dataclasses import dataclass, field, replace
from functools import partial
from typing import Any, Callable

import z3

from ..tla import ast as A
from ..tla.errors import Loc
from ..tla.modules import BuiltinSym, ConstSym, DefSym, InstanceSym, Scope, SubstSym, VarSym
from . import builtins as B
from .obligations import Obligation, Obligations, flatten
from .sets import EnumSet, PredSet, need_enum, need_set
from .values import UNDEF, Fn, ProveError, tracked, Rec, SeqV, Strings, Tup, concrete, eq, is_z3, ite


@dataclass(eq=False)
class _Lazy:
    """A zero-arity LET definition, evaluated on first use."""

    expr: A.Expr
    ctx: "Ctx"
    value: Any = None
    done: bool = False
    obligations: list[Obligation] = field(default_factory=list)  # re-emitted at every use


@dataclass(eq=False)
class _LetOp:
    defn: A.OpDef
    ctx: "Ctx"


@dataclass(eq=False)
class Ctx:
    scope: Scope
    locals: dict[str, Any] = field(default_factory=dict)
    primed: bool = False
    at: Any = None

    def bind(self, names: dict[str, Any]) -> "Ctx":
        return replace(self, locals={**self.locals, **names})


class Translator:
    """Translates expressions over one pair of states (current, next)."""

    def __init__(self, strings: Strings, constants: dict[str, Any], overrides: dict[str, Any],
                 cur: dict[str, Any], nxt: dict[str, Any] | None) -> None:
        self.strings = strings
        self.constants = constants      # CONSTANT name -> symbolic value
        self.overrides = overrides      # cfg: name -> DefSym (``<-``) or symbolic value
        self.cur = cur
        self.nxt = nxt
        self.skolems: list[z3.ExprRef] = []
        self.obl = Obligations()        # well-definedness obligations of what is translated
        self.assigning = False          # translating Init or Next (x = e may assign x)
        self.assigning_next = False     # ... Next (x' = e assigns x)
        # while assigning: id of each structured variable value -> (name, TypeOK domain)
        self.type_targets: dict[int, tuple[str, Any]] = {}
        self.type_invariant = "TypeOK"
        self._memo: dict[tuple, tuple[Any, Any, list[Obligation]]] = {}
        self._fresh = 0

    # ------------------------------------------------------------------ helpers
    def fresh_name(self, base: str) -> str:
        self._fresh += 1
        return f"{base}!{self._fresh}"

    def boolean(self, e: A.Expr, ctx: Ctx) -> z3.BoolRef:
        v = _tracked(self.val(e, ctx), e.loc)
        if v is UNDEF:
            return z3.BoolVal(False)
        if not (is_z3(v) and z3.is_bool(v)):
            raise ProveError("expected a Boolean here", e.loc)
        return v

    def integer(self, e: A.Expr, ctx: Ctx) -> z3.ArithRef:
        v = _tracked(self.val(e, ctx), e.loc)
        if v is UNDEF:
            return z3.IntVal(0)
        if not (is_z3(v) and z3.is_int(v)):
            raise ProveError("expected an integer here", e.loc)
        return v

    def conc(self, v: Any) -> Any:
        return concrete(v, self.strings)

    # ------------------------------------------------------------------ actions
    def act(self, e: A.Expr, ctx: Ctx) -> z3.BoolRef:
        """An action or initial predicate in a positive position."""
        if isinstance(e, A.And):
            return self._conjunction(e.items, ctx, self.act)
        if isinstance(e, A.Or):
            # TLC evaluates every disjunct of an action: each is obliged on its own
            return z3.Or([self.act(x, ctx) for x in e.items])
        if isinstance(e, A.Quant) and e.kind == "\\E":
            return self._skolem(e.bounds, e.body, ctx)
        if isinstance(e, A.If):
            c = self.boolean(e.cond, ctx)
            if z3.is_true(c) or z3.is_false(c):
                return self.act(e.then if z3.is_true(c) else e.other, ctx)
            with self.obl.under(c):
                a = self.act(e.then, ctx)
            with self.obl.under(z3.Not(c)):
                b = self.act(e.other, ctx)
            return z3.If(c, a, b)
        if isinstance(e, A.Let):
            return self.act(e.body, self._let(e, ctx))
        if isinstance(e, A.StepAction):
            a = self.act(e.action, ctx)
            unch = self._unchanged(e.sub, ctx, e.loc)
            return z3.Or(a, unch) if e.stutter else z3.And(a, z3.Not(unch))
        if isinstance(e, (A.Name, A.Apply)) and e.name not in ctx.locals:
            sym = self._lookup(e.name, ctx, e.loc)
            if isinstance(sym, DefSym) and not sym.defn.fn_bounds:
                args = e.args if isinstance(e, A.Apply) else []
                body_ctx = self._bind_params(sym, args, ctx, e.loc)
                return self.act(sym.defn.body, body_ctx)
        return self.boolean(e, ctx)

    def _skolem(self, bounds: list[A.Bound], body: A.Expr, ctx: Ctx) -> z3.BoolRef:
        conds = []
        for b in bounds:
            s = need_set(self.val(b.set, ctx), "\\E", b.set.loc)
            names = {}
            for n in (b.names if not b.tuple else ["<<" + ",".join(b.names) + ">>"]):
                x = s.fresh(self.fresh_name(n), b.set.loc)
                from .values import leaves
                self.skolems.extend(leaves(x))
                conds.append(s.member(x, b.set.loc))
                if b.tuple:
                    if not isinstance(x, Tup) or len(x.items) != len(b.names):
                        raise ProveError("tuple pattern over a set of non-tuples", b.set.loc)
                    names.update(dict(zip(b.names, x.items)))
                else:
                    names[n] = x
            ctx = ctx.bind(names)
        with self.obl.under(z3.And(conds)):
            return z3.And(conds + [self.act(body, ctx)])

    def _conjunction(self, items: list[A.Expr], ctx: Ctx, each: Callable[[A.Expr, Ctx], z3.BoolRef]) -> z3.BoolRef:
        """A /\\ B /\\ ...: each conjunct is evaluated only where the ones before it hold."""
        out: list[z3.BoolRef] = []
        for x in items:
            with self.obl.under(partial(_all, list(out))):
                v = each(x, ctx)
            if z3.is_false(v):
                return z3.BoolVal(False)  # TLA+ stops here: the rest is not evaluated
            out.append(v)
        return z3.And(out)

    def _unchanged(self, sub: A.Expr, ctx: Ctx, loc: Loc) -> z3.BoolRef:
        if ctx.primed:
            raise ProveError("UNCHANGED inside a primed expression", loc)
        return eq(self.val(sub, replace(ctx, primed=True)), self.val(sub, ctx), loc)

    # ------------------------------------------------------------------ names
    def upper_bound(self, t: z3.ArithRef) -> int | None:
        """A concrete upper bound of `t`: a bounded symbolic constant (or a sequence length),
        sums of those, IF, minus a number."""
        c = self.conc(t)
        if c is not None:
            return c
        if z3.is_const(t):
            return self.const_upper.get(str(t))
        if z3.is_add(t):
            ups = [self.upper_bound(t.arg(i)) for i in range(t.num_args())]
            return None if any(u is None for u in ups) else sum(ups)  # type: ignore[arg-type]
        if z3.is_sub(t) and t.num_args() == 2:
            ua, cb = self.upper_bound(t.arg(0)), self.conc(t.arg(1))
            if ua is not None and cb is not None:
                return ua - cb
        if z3.is_app_of(t, z3.Z3_OP_ITE):
            ups = [self.upper_bound(t.arg(1)), self.upper_bound(t.arg(2))]
            return None if any(u is None for u in ups) else max(ups)  # type: ignore[type-var]
        return None

    def is_variable_value(self, v: Any) -> bool:
        """Is `v` the symbolic value of a state variable (current or next)?"""
        return any(v is x for x in self.cur.values()) or (self.nxt is not None and any(v is x for x in self.nxt.values()))

    def _lookup(self, name: str, ctx: Ctx, loc: Loc) -> Any:
        if name in self.overrides and ctx.scope is self.root_scope:
            return self.overrides[name]
        sym = ctx.scope.lookup(name)
        if sym is None:
            if name in B.BUILTIN_NAMES:
                return BuiltinSym(None)  # type: ignore[arg-type]
            raise ProveError(f"unknown identifier {name}", loc)
        return sym

    root_scope: Scope  # set by the caller
    const_upper: dict[str, int]  # symbolic integer constant -> its largest value, when bounded

    def _bind_params(self, sym: DefSym, args: list[A.Expr], ctx: Ctx, loc: Loc) -> Ctx:
        params = sym.defn.params
        if len(params) != len(args):
            raise ProveError(f"{sym.defn.name} takes {len(params)} argument(s), given {len(args)}", loc)
        if any(p.arity > 0 for p in params):
            raise ProveError(f"higher-order operator {sym.defn.name}", loc)
        vals = {p.name: self.val(a, ctx) for p, a in zip(params, args)}
        return Ctx(sym.scope, vals, ctx.primed)

    def _apply_def(self, sym: DefSym, args: list[A.Expr], ctx: Ctx, loc: Loc) -> Any:
        if sym.recursive and not sym.defn.fn_bounds:
            raise ProveError(f"recursive operator {sym.defn.name}", loc)
        if sym.defn.fn_bounds:
            if args:
                raise ProveError(f"function {sym.defn.name} applied with ()", loc)
            if sym.defn.name in _free_names(sym.defn.body):
                raise ProveError(f"recursive function {sym.defn.name}", loc)
            return self._fn_lit(sym.defn.fn_bounds, sym.defn.body, Ctx(sym.scope, {}, ctx.primed), loc)
        body_ctx = self._bind_params(sym, args, ctx, loc)
        key = (id(sym), ctx.primed, tuple(_vkey(body_ctx.locals[p.name]) for p in sym.defn.params))
        hit = self._memo.get(key)
        if hit is not None:
            self.obl.emit(hit[2])
            return hit[1]
        with self.obl.capture() as inner:
            v = self.val(sym.defn.body, body_ctx)
        # keeps the argument terms alive (their ids are the key); the body's obligations hold at every use
        self._memo[key] = (body_ctx.locals, v, inner)
        self.obl.emit(inner)
        return v

    def _name(self, e: A.Name | A.Apply, ctx: Ctx) -> Any:
        name = e.name
        args = e.args if isinstance(e, A.Apply) else []
        if name in ctx.locals:
            loc_v = ctx.locals[name]
            if isinstance(loc_v, _Lazy):
                if args:
                    raise ProveError(f"{name} takes no arguments", e.loc)
                if not loc_v.done:
                    with self.obl.capture() as obligations:
                        loc_v.value = self.val(loc_v.expr, loc_v.ctx)
                    loc_v.obligations = obligations
                    loc_v.done = True
                self.obl.emit(loc_v.obligations)
                return loc_v.value
            if isinstance(loc_v, _LetOp):
                d = loc_v.defn
                if len(d.params) != len(args):
                    raise ProveError(f"{name} takes {len(d.params)} argument(s)", e.loc)
                if d.fn_bounds:
                    return self._fn_lit(d.fn_bounds, d.body, loc_v.ctx, e.loc)
                return self.val(d.body, loc_v.ctx.bind({p.name: self.val(a, ctx) for p, a in zip(d.params, args)}))
            if args:
                raise ProveError(f"{name} is not an operator", e.loc)
            return loc_v
        sym = self._lookup(name, ctx, e.loc)
        if isinstance(sym, VarSym):
            state = self.nxt if ctx.primed else self.cur
            if state is None:
                raise ProveError(f"primed variable {name}' outside an action", e.loc)
            return state[name]
        if isinstance(sym, ConstSym):
            if sym.arity > 0:
                raise ProveError(f"operator constant {name}", e.loc)
            if name not in self.constants:
                raise ProveError(f"constant {name} has no value", e.loc)
            return self.constants[name]
        if isinstance(sym, DefSym):
            return self._apply_def(sym, args, ctx, e.loc)
        if isinstance(sym, SubstSym):
            inner = Ctx(sym.scope, {}, ctx.primed)
            return self.val(sym.expr, inner)
        if isinstance(sym, BuiltinSym):
            return B.apply_builtin(self, name, args, ctx, e.loc)
        if isinstance(sym, InstanceSym):
            raise ProveError(f"instance {name} used as a value", e.loc)
        # a cfg override by value
        return sym

    # ------------------------------------------------------------------ values
    def val(self, e: A.Expr, ctx: Ctx) -> Any:
        m = getattr(self, "_v_" + type(e).__name__, None)
        if m is None:
            raise ProveError(f"the construct {type(e).__name__}", e.loc)
        return m(e, ctx)

    def _v_Num(self, e: A.Num, ctx: Ctx) -> Any:
        return z3.IntVal(e.value)

    def _v_Str(self, e: A.Str, ctx: Ctx) -> Any:
        return self.strings.val(e.value, e.loc)

    def _v_Bool(self, e: A.Bool, ctx: Ctx) -> Any:
        return z3.BoolVal(e.value)

    def _v_Name(self, e: A.Name, ctx: Ctx) -> Any:
        return self._name(e, ctx)

    def _v_Apply(self, e: A.Apply, ctx: Ctx) -> Any:
        if e.name == "\\X" and e.name not in ctx.locals:
            return B.product([need_set(self.val(a, ctx), "\\X", a.loc) for a in e.args], e.loc)
        return self._name(e, ctx)

    def _v_Prefixed(self, e: A.Prefixed, ctx: Ctx) -> Any:
        scope = ctx.scope
        for step in e.path:
            if step.args:
                raise ProveError("parameterised INSTANCE", e.loc)
            sym = scope.lookup(step.name)
            if not isinstance(sym, InstanceSym):
                raise ProveError(f"{step.name} is not an instance", e.loc)
            scope = sym.scope
        return self._name(A.Apply(e.loc, e.name, e.args), Ctx(scope, {}, ctx.primed)) if not e.args else \
            self._prefixed_apply(e, scope, ctx)

    def _prefixed_apply(self, e: A.Prefixed, scope: Scope, ctx: Ctx) -> Any:
        sym = scope.lookup(e.name)
        if not isinstance(sym, DefSym):
            raise ProveError(f"{e.name} is not a definition of the instance", e.loc)
        vals = [self.val(a, ctx) for a in e.args]
        inner = Ctx(sym.scope, {p.name: v for p, v in zip(sym.defn.params, vals)}, ctx.primed)
        return self.val(sym.defn.body, inner)

    def _v_Prime(self, e: A.Prime, ctx: Ctx) -> Any:
        if ctx.primed:
            raise ProveError("doubly primed expression", e.loc)
        if self.nxt is None:
            raise ProveError("prime in a state predicate", e.loc)
        return self.val(e.arg, replace(ctx, primed=True))

    def _v_And(self, e: A.And, ctx: Ctx) -> Any:
        return self._conjunction(e.items, ctx, self.boolean)

    def _v_Or(self, e: A.Or, ctx: Ctx) -> Any:
        out: list[z3.BoolRef] = []
        for x in e.items:
            with self.obl.under(partial(_none, list(out))):
                v = self.boolean(x, ctx)
            if z3.is_true(v):
                return v  # TLA+ stops at the first true disjunct
            out.append(v)
        return z3.Or(out)

    def implies(self, lhs: A.Expr, rhs: A.Expr, ctx: Ctx) -> z3.BoolRef:
        a = self.boolean(lhs, ctx)
        if z3.is_false(a):
            return z3.BoolVal(True)
        with self.obl.under(a):
            return z3.Implies(a, self.boolean(rhs, ctx))

    def _v_If(self, e: A.If, ctx: Ctx) -> Any:
        c = self.boolean(e.cond, ctx)
        cc = self.conc(c) if not (z3.is_true(c) or z3.is_false(c)) else z3.is_true(c)
        if cc is True:
            return self.val(e.then, ctx)
        if cc is False:
            return self.val(e.other, ctx)
        with self.obl.under(c):
            a = self.val(e.then, ctx)
        with self.obl.under(z3.Not(c)):
            b = self.val(e.other, ctx)
        return ite(c, a, b, e.loc)

    def _v_Case(self, e: A.Case, ctx: Ctx) -> Any:
        # Arms are tried in order (TLC's choice); with no arm true and no OTHER, TLC fails:
        # an obligation, and the last arm's value stands for the unspecified one.
        arms: list[tuple[z3.BoolRef, A.Expr]] = []
        for g, x in e.arms:
            with self.obl.under(partial(_none, [a for a, _ in arms])):
                arms.append((self.boolean(g, ctx), x))
            if z3.is_true(arms[-1][0]):
                break
        none_before = [z3.Not(_any([a for a, _ in arms[:i]])) for i in range(len(arms) + 1)]
        values = []
        for i, (g, x) in enumerate(arms):
            if z3.is_false(g):
                continue
            with self.obl.under(z3.And(none_before[i], g)):
                values.append((g, self.val(x, ctx)))
        if z3.is_true(arms[-1][0]):
            out = values.pop()[1]
        elif e.other is not None:
            with self.obl.under(none_before[-1]):
                out = self.val(e.other, ctx)
        else:
            self.obl.add("case", e.loc, "some CASE arm is true (there is no OTHER)", _any([a for a, _ in arms]))
            if not values:
                return UNDEF
            out = values.pop()[1]
        for g, x in reversed(values):
            out = ite(g, x, out, e.loc)
        return out

    def _let(self, e: A.Let, ctx: Ctx) -> Ctx:
        new: dict[str, Any] = {}
        inner = ctx.bind(new)
        for d in e.defs:
            if isinstance(d, A.InstanceDef):  # the checker takes INSTANCE in LET; the prover not yet
                raise ProveError("INSTANCE inside LET", d.loc)
            if d.params or d.fn_bounds:
                new[d.name] = _LetOp(d, inner)
            else:
                new[d.name] = _Lazy(d.body, inner)
            inner.locals[d.name] = new[d.name]
        return inner

    def _v_Let(self, e: A.Let, ctx: Ctx) -> Any:
        return self.val(e.body, self._let(e, ctx))

    def _v_Unary(self, e: A.Unary, ctx: Ctx) -> Any:
        op = e.op
        if op == "~":
            return z3.Not(self.boolean(e.arg, ctx))
        if op in ("-", "-."):
            return -self.integer(e.arg, ctx)
        if op == "UNCHANGED":
            return self._unchanged(e.arg, ctx, e.loc)
        if op == "DOMAIN":
            return B.domain(self, self.val(e.arg, ctx), e.loc)
        if op == "SUBSET":
            return B.powerset(self, self.val(e.arg, ctx), e.loc)
        if op == "UNION":
            return B.big_union(self.val(e.arg, ctx), e.loc)
        raise ProveError(f"the operator {op}", e.loc)

    def _v_Binary(self, e: A.Binary, ctx: Ctx) -> Any:
        return B.binary(self, e, ctx)

    def _v_Quant(self, e: A.Quant, ctx: Ctx) -> Any:
        return self._quant(e.kind, e.bounds, e.body, ctx, e.loc)

    def _quant(self, kind: str, bounds: list[A.Bound], body: A.Expr, ctx: Ctx, loc: Loc) -> z3.BoolRef:
        if not bounds:
            return self.boolean(body, ctx)
        b, rest = bounds[0], bounds[1:]
        s = need_set(self.val(b.set, ctx), kind, b.set.loc)
        for i, n in enumerate(b.names):
            sub = A.Bound(b.names[i + 1:], False, b.set) if (not b.tuple and i == 0 and len(b.names) > 1) else None
            if sub is not None:
                return self._quant(kind, [A.Bound([n], False, b.set), sub] + rest, body, ctx, loc)
        if isinstance(s, EnumSet):
            parts = []
            for g, x in s.items:
                with self.obl.under(g):
                    inner = self._quant(kind, rest, body, ctx.bind(self._pattern(b, x)), loc)
                parts.append(z3.Implies(g, inner) if kind == "\\A" else z3.And(g, inner))
            return z3.And(parts) if kind == "\\A" else z3.Or(parts)
        # a non-enumerable set: a z3 quantifier over a fresh element
        from .values import leaves
        x = s.fresh(self.fresh_name("q"), b.set.loc)
        with self.obl.capture() as obligations:
            inner = self._quant(kind, rest, body, ctx.bind(self._pattern(b, x)), loc)
        vs = leaves(x)
        member = s.member(x, loc)
        for o in flatten(obligations):  # the body is evaluated for every element of the set
            self.obl.emit([Obligation(o.kind, o.loc, o.what, z3.ForAll(vs, z3.Implies(member, o.cond)))])
        if kind == "\\A":
            return z3.ForAll(vs, z3.Implies(s.member(x, loc), inner))
        return z3.Exists(vs, z3.And(s.member(x, loc), inner))

    def _pattern(self, b: A.Bound, x: Any) -> dict[str, Any]:
        if not b.tuple:
            return {b.names[0]: x}
        if not isinstance(x, Tup) or len(x.items) != len(b.names):
            raise ProveError("tuple pattern over a set of non-tuples", b.set.loc)
        return dict(zip(b.names, x.items))

    def _v_UnboundedQuant(self, e: A.UnboundedQuant, ctx: Ctx) -> Any:
        raise ProveError("unbounded quantifier (\\A x : ... without a set)", e.loc)

    def _v_Choose(self, e: A.Choose, ctx: Ctx) -> Any:
        if e.set is None:
            raise ProveError("unbounded CHOOSE", e.loc)
        s = need_enum(self.val(e.set, ctx), "CHOOSE", e.loc)
        b = A.Bound(e.names, e.tuple, e.set)
        holds = []
        for g, x in s.items:
            with self.obl.under(g):
                holds.append((g, self.boolean(e.body, ctx.bind(self._pattern(b, x)))))
        self.obl.add("choose", e.loc, "some element of the set satisfies the CHOOSE predicate",
                     _any([z3.And(g, p) for g, p in holds]))
        if not s.items:
            return UNDEF
        out = s.items[-1][1]  # the first element (in set order) satisfying the predicate
        for (g, x), (_, p) in reversed(list(zip(s.items[:-1], holds[:-1]))):
            out = ite(z3.And(g, p), x, out, e.loc)
        return out

    def _v_SetEnum(self, e: A.SetEnum, ctx: Ctx) -> Any:
        return EnumSet([(z3.BoolVal(True), self.val(x, ctx)) for x in e.elems])

    def _v_SetFilter(self, e: A.SetFilter, ctx: Ctx) -> Any:
        from .sets import filter_set
        s = need_set(self.val(e.bound.set, ctx), "set filter", e.loc)
        if isinstance(s, EnumSet):
            items = []
            for g, x in s.items:
                with self.obl.under(g):
                    items.append((_simp(z3.And(g, self.boolean(e.pred, ctx.bind(self._pattern(e.bound, x))))), x))
            return EnumSet(items, s.shape)
        return filter_set(s, lambda x: self.boolean(e.pred, ctx.bind(self._pattern(e.bound, x))), e.loc)

    def _v_SetMap(self, e: A.SetMap, ctx: Ctx) -> Any:
        combos: list[tuple[z3.BoolRef, dict[str, Any]]] = [(z3.BoolVal(True), {})]
        for b in e.bounds:
            s = need_enum(self.val(b.set, ctx), "set map", b.set.loc)
            names = b.names if b.tuple else b.names
            nxt = []
            for g0, binds in combos:
                if b.tuple:
                    for g, x in s.items:
                        nxt.append((z3.And(g0, g), {**binds, **self._pattern(b, x)}))
                else:
                    partial = [(g0, binds)]
                    for n in names:
                        partial = [(z3.And(gp, g), {**bp, n: x}) for gp, bp in partial for g, x in s.items]
                    nxt.extend(partial)
            combos = nxt
        items = []
        for g, binds in combos:
            g = _simp(g)
            if z3.is_false(g):
                continue
            with self.obl.under(g):
                items.append((g, self.val(e.expr, ctx.bind(binds))))
        return EnumSet(items)

    def _v_FnApp(self, e: A.FnApp, ctx: Ctx) -> Any:
        f = _tracked(self.val(e.fn, ctx), e.loc)
        args = [self.val(a, ctx) for a in e.args]
        arg = args[0] if len(args) == 1 else Tup(tuple(args))
        return B.fn_apply(self, f, arg, e.loc)

    def _fn_lit(self, bounds: list[A.Bound], body: A.Expr, ctx: Ctx, loc: Loc) -> Any:
        seq = self._seq_lit(bounds, body, ctx)
        if seq is not None:
            return seq
        domains = []
        for b in bounds:
            s = need_enum(self.val(b.set, ctx), "function domain", b.set.loc)
            keys = []
            for g, x in s.items:
                k = self.conc(x)
                if k is None or not z3.is_true(_simp(g)):
                    raise ProveError("function over a domain that is not a constant finite set", b.set.loc)
                keys.append((k, x))
            for n in (b.names if not b.tuple else ["<<>>"]):
                domains.append((b, n, keys))
        import itertools
        out_keys, vals = [], {}
        for combo in itertools.product(*[d[2] for d in domains]):
            binds: dict[str, Any] = {}
            for (b, n, _), (_k, x) in zip(domains, combo):
                binds.update(self._pattern(b, x) if b.tuple else {n: x})
            key = combo[0][0] if len(combo) == 1 else tuple(c[0] for c in combo)
            if key in vals:
                continue
            out_keys.append(key)
            vals[key] = self.val(body, ctx.bind(binds))
        return Fn(tuple(out_keys), vals)

    def _seq_lit(self, bounds: list[A.Bound], body: A.Expr, ctx: Ctx) -> SeqV | Tup | None:
        """[i \\in 1..n |-> e] or [i \\in DOMAIN s |-> e] with a symbolic, bounded n (Len(s)):
        a bounded sequence of n elements (slot i is evaluated only where i <= n)."""
        if len(bounds) != 1 or bounds[0].tuple or len(bounds[0].names) != 1:
            return None
        b = bounds[0]
        s = self.val(b.set, ctx)
        if isinstance(s, EnumSet) and s.prefix_len is not None:
            length, cap = s.prefix_len, len(s.items)
        elif isinstance(s, PredSet) and "interval" in s.extra and self.conc(s.extra["interval"][0]) == 1 \
                and s.upper is not None:
            length, cap = s.extra["interval"][1], max(s.upper, 0)
        else:
            return None
        items = []
        for i in range(1, cap + 1):
            with self.obl.under(length >= i):
                items.append(self.val(body, ctx.bind({b.names[0]: z3.IntVal(i)})))
        if any(x is UNDEF for x in items):
            raise ProveError("a sequence with an undefined element", b.set.loc)
        if self.conc(length) == cap:
            return Tup(tuple(items))  # [i \\in DOMAIN t |-> e] of a tuple t: a tuple
        return SeqV(tuple(items), z3.If(length > 0, length, 0) if cap else z3.IntVal(0))

    def _v_FnLit(self, e: A.FnLit, ctx: Ctx) -> Any:
        return self._fn_lit(e.bounds, e.body, ctx, e.loc)

    def _v_FnSet(self, e: A.FnSet, ctx: Ctx) -> Any:
        return B.fn_set(self, need_enum(self.val(e.domain, ctx), "function set domain", e.loc),
                        need_set(self.val(e.range, ctx), "function set range", e.loc), e.loc)

    def _v_RecLit(self, e: A.RecLit, ctx: Ctx) -> Any:
        return Rec({f: self.val(x, ctx) for f, x in e.fields})

    def _v_RecSet(self, e: A.RecSet, ctx: Ctx) -> Any:
        return B.rec_set({f: need_set(self.val(x, ctx), "record set", x.loc) for f, x in e.fields}, e.loc)

    def _v_Dot(self, e: A.Dot, ctx: Ctx) -> Any:
        r = _tracked(self.val(e.rec, ctx), e.loc)
        if r is UNDEF:
            return UNDEF
        if isinstance(r, Rec):
            if e.field not in r.fields:
                self.obl.add("field", e.loc, f"the record has a field {e.field}", False)
                return UNDEF
            return r.fields[e.field]
        if isinstance(r, Fn):
            return B.fn_apply(self, r, self.strings.val(e.field, e.loc), e.loc)
        raise ProveError(f"field .{e.field} of a value that is not a record", e.loc)

    def _v_Except(self, e: A.Except, ctx: Ctx) -> Any:
        v = self.val(e.base, ctx)
        for u in e.updates:
            path = []
            for kind, item in u.path:
                if kind == "field":
                    path.append(("field", item))
                else:
                    assert isinstance(item, list)
                    idx = [self.val(x, ctx) for x in item]
                    path.append(("index", idx[0] if len(idx) == 1 else Tup(tuple(idx))))
            v = B.update(self, v, path, _with_at(self, u.value, ctx), e.loc)
        return v

    def _v_At(self, e: A.At, ctx: Ctx) -> Any:
        if ctx.at is None:
            raise ProveError("@ outside an EXCEPT", e.loc)
        return ctx.at

    def _v_TupleLit(self, e: A.TupleLit, ctx: Ctx) -> Any:
        return Tup(tuple(self.val(x, ctx) for x in e.elems))

    def _v_StepAction(self, e: A.StepAction, ctx: Ctx) -> Any:
        # as a value (possibly under a negation): no Skolem constants, \E is expanded
        a = self.boolean(e.action, ctx)
        unch = self._unchanged(e.sub, ctx, e.loc)
        return z3.Or(a, unch) if e.stutter else z3.And(a, z3.Not(unch))

    def _v_Unsupported(self, e: A.Unsupported, ctx: Ctx) -> Any:
        raise ProveError(e.what, e.loc)

    def _v_Lambda(self, e: A.Lambda, ctx: Ctx) -> Any:
        raise ProveError("LAMBDA", e.loc)

    def _v_OpRef(self, e: A.OpRef, ctx: Ctx) -> Any:
        raise ProveError("operator passed as an argument", e.loc)

    def _v_Fairness(self, e: A.Fairness, ctx: Ctx) -> Any:
        raise ProveError("fairness (WF/SF) is temporal", e.loc)


def _with_at(tr: Translator, value: A.Expr, ctx: Ctx) -> Callable[[Any], Any]:
    """The new value of an EXCEPT update, as a function of the old one (@)."""
    return lambda old: tr.val(value, replace(ctx, at=old))


_tracked = tracked


def _all(items: list[z3.BoolRef]) -> z3.BoolRef:
    return z3.BoolVal(True) if not items else items[0] if len(items) == 1 else z3.And(items)


def _any(items: list[z3.BoolRef]) -> z3.BoolRef:
    return z3.BoolVal(False) if not items else items[0] if len(items) == 1 else z3.Or(items)


def _none(items: list[z3.BoolRef]) -> z3.BoolRef:
    return z3.Not(_any(items))


def _simp(g: z3.BoolRef) -> z3.BoolRef:
    return g if z3.is_true(g) or z3.is_false(g) else z3.simplify(g)


def _vkey(v: Any) -> Any:
    if is_z3(v):
        return ("z", v.get_id())
    if isinstance(v, Rec):
        return ("R",) + tuple((f, _vkey(x)) for f, x in v.fields.items())
    if isinstance(v, Tup):
        return ("T",) + tuple(_vkey(x) for x in v.items)
    if isinstance(v, SeqV):
        return ("S", _vkey(v.length)) + tuple(_vkey(x) for x in v.items)
    if isinstance(v, Fn):
        return ("F",) + tuple((k, _vkey(v.vals[k])) for k in v.keys)
    return ("o", id(v))


def _free_names(e: Any) -> set[str]:
    """Identifiers occurring in an expression (a syntactic over-approximation)."""
    out: set[str] = set()
    stack = [e]
    while stack:
        x = stack.pop()
        if isinstance(x, (A.Name, A.Apply)):
            out.add(x.name)
        if isinstance(x, A.Expr) or isinstance(x, (A.Bound, A.ExceptUpdate, A.OpDef)):
            for f in getattr(x, "__slots__", ()):
                stack.append(getattr(x, f, None))
        elif isinstance(x, (list, tuple)):
            stack.extend(x)
    return out
