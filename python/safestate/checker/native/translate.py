"""The model's Init, Next, invariants and constraints as the native core's program tree.

A node is a tuple ``(op, loc, ints, value id, kids, continuation)`` (`ops.Op`).  Actions
are translated in continuation-passing style exactly as `tla/actions.py` compiles them
(same conjunct order, same assignment rules, same disjunct and ``\\E`` order, the
same rule for conjuncts once every variable is assigned), so the successors come in
TLC's order and each `A_EMIT` carries the index of the same `Leaf` as the Python
engine's.  Operators are expanded at their call sites; their arguments are
evaluated into slots first (by name when they are action-level or in Init, as the
Python compiler binds them).  Anything outside the subset raises `UnsupportedError`
naming file:line:col and "not supported by the native engine": never a guess.
"""

from __future__ import annotations

from dataclasses import dataclass, replace
from collections.abc import Callable
from typing import Any, Iterable, cast

from ...tla import ast as A
from ...tla.compile.lazy_args import first_evaluated
from ...tla.errors import Loc, UnsupportedError
from ...tla.modules import BuiltinSym, ConstSym, DefSym, Scope, VarSym
from ...tla.values import BOOLEAN, string_rank
from ..model import Model
from .ops import Op
from .printing import value_flags
from .values import NOT_NATIVE, ValueBridge

# Ops that iterate over a set: an operator call whose body has one is worth remembering.
_ITERATING = frozenset((Op.FORALL, Op.EXISTS, Op.SETFILTER, Op.SETMAP, Op.CHOOSE, Op.FNLIT, Op.SELECTSEQ))

Node = tuple

_NATIVE_MODULES = {"Naturals", "Integers", "Sequences", "FiniteSets"}
_INT_BINARY = {"+": Op.ADD, "-": Op.SUB, "*": Op.MUL, "\\div": Op.DIV, "%": Op.MOD, "<": Op.LT,
               ">": Op.GT, "<=": Op.LE, ">=": Op.GE, "..": Op.RANGE, "\\o": Op.CONCAT}
_CORE_BINARY = {"=": Op.EQ, "/=": Op.NEQ, "=>": Op.IMPLIES, "<=>": Op.EQUIV, "\\equiv": Op.EQUIV,
                "\\cup": Op.CUP, "\\cap": Op.CAP, "\\": Op.DIFF, "\\subseteq": Op.SUBSETEQ}
_BUILTIN_APPLY = {"Append": (Op.APPEND, 2), "Head": (Op.HEAD, 1), "Tail": (Op.TAIL, 1), "Len": (Op.LEN, 1),
                  "SubSeq": (Op.SUBSEQ, 3), "Cardinality": (Op.CARD, 1)}


def _tlc_function_definition(e: A.Binary) -> A.Expr:
    """``d :> e`` and ``f @@ g`` as the TLC module defines them, for the core's function
    constructor: ``[x \\in {d} |-> e]`` and ``LET F == f  G == g IN [x \\in DOMAIN F \\cup
    DOMAIN G |-> IF x \\in DOMAIN F THEN F[x] ELSE G[x]]``.  An argument that is not a
    function, or keys of incomparable kinds, stop the core at an evaluation error, and
    the Python engine reports TLC's CombineFcn message.  The names cannot clash: no
    TLA+ identifier contains a space."""
    loc = e.loc
    x = A.Name(loc, "tlc fn key")
    if e.op == ":>":
        return A.FnLit(loc, [A.Bound([x.name], False, A.SetEnum(loc, [e.lhs]))], e.rhs)
    f, g = A.Name(loc, "tlc fn left"), A.Name(loc, "tlc fn right")
    dom_f, dom_g = A.Unary(loc, "DOMAIN", f), A.Unary(loc, "DOMAIN", g)
    body = A.If(loc, A.Binary(loc, "\\in", x, dom_f), A.FnApp(loc, f, [x]), A.FnApp(loc, g, [x]))
    fn = A.FnLit(loc, [A.Bound([x.name], False, A.Binary(loc, "\\cup", dom_f, dom_g))], body)
    return A.Let(loc, [A.OpDef(f.name, [], e.lhs, loc), A.OpDef(g.name, [], e.rhs, loc)], fn)


@dataclass(frozen=True)
class TEnv:
    scope: Scope
    locals: dict
    primed: bool = False
    init: bool = False


@dataclass
class SlotArg:
    """A parameter evaluated into a slot; priming it primes the argument (`source`)."""
    slot: int
    source: tuple[A.Expr, TEnv] | None  # None for a bound variable (x' is x)


@dataclass
class LazyArg:
    """A parameter bound to its argument unevaluated, as TLC binds it: a LETREF node
    (evaluated at the first use, the slot reset at each call, `tla/compile/lazy_args.py`);
    priming it primes the argument (`source`)."""
    node: Node
    source: tuple[A.Expr, TEnv]


@dataclass
class ByName:
    expr: A.Expr
    env: TEnv


@dataclass
class LetRef:
    node: Node
    expr: A.Expr
    env: TEnv


@dataclass
class LetOp:
    defn: A.OpDef
    env: TEnv


@dataclass
class AtSlot:
    slot: int


def unsupported(what: str, loc: Loc) -> UnsupportedError:
    return UnsupportedError(f"{what} is {NOT_NATIVE}", loc)


def _mentions_prime(e: Any) -> bool:
    from ...tla.compiler import _subterms
    if isinstance(e, A.Prime) or (isinstance(e, A.Unary) and e.op == "UNCHANGED"):
        return True
    return any(_mentions_prime(c) for c in _subterms(e))


class Translator:
    def __init__(self, model: Model, bridge: ValueBridge) -> None:
        self.m = model
        self.c = model.compiler
        self.bridge = bridge
        self.nslots = 0
        self.locs: list[Loc] = []
        self._loc_index: dict[tuple, int] = {}
        self._defs: dict[tuple, Node] = {}
        self.leaves = 0
        self.leaf_params: list[tuple[tuple[str, int], ...]] = []  # per leaf: (name, slot) as Leaf.params
        self._depth = 0
        self._free: dict[int, tuple[Node, frozenset[int]]] = {}
        self._iterates: dict[int, tuple[Node, bool]] = {}
        self.foralls = 0  # A_FORALL nodes so far (each has its own index)
        self.const_flags: dict[int, int] = {}  # printing.value_flags of the constants that have some
        self._keep: list[Node] = []

    # ---------------------------------------------------------------- nodes
    def node(self, op: Op, loc: Loc, ints: Iterable[int] = (), v: int = 0, kids: tuple = (), k: Node | None = None) -> Node:
        key = (loc.file, loc.line, loc.column) if loc else ("", 0, 0)
        li = self._loc_index.get(key)
        if li is None:
            li = self._loc_index[key] = len(self.locs)
            self.locs.append(loc)
        return (int(op), li, tuple(int(i) for i in ints), v, tuple(kids), k)

    def const(self, value: Any, loc: Loc) -> Node:
        n = self.node(Op.CONST, loc, v=self.bridge.to_native(value, loc))
        flags = value_flags(value)
        if flags:
            self.const_flags[id(n)] = flags
            self._keep.append(n)  # its id stays its own
        return n

    def alloc(self) -> int:
        self.nslots += 1
        return self.nslots - 1

    def lookup(self, name: str, env: TEnv) -> Any:
        sym = env.scope.lookup(name)
        return self.c.sym_overrides.get(id(sym), sym)

    # ---------------------------------------------------------------- expressions
    def expr(self, e: A.Expr, env: TEnv) -> Node:
        method = getattr(self, "x_" + type(e).__name__, None)
        if method is None:
            raise unsupported(f"the construct {type(e).__name__}", e.loc)
        return method(e, env)

    def x_Num(self, e: A.Num, env: TEnv) -> Node:
        return self.const(e.value, e.loc)

    def x_Str(self, e: A.Str, env: TEnv) -> Node:
        return self.node(Op.CONST, e.loc, v=self.bridge.engine.mk_str(e.value, string_rank(e.value)))

    def x_Bool(self, e: A.Bool, env: TEnv) -> Node:
        return self.const(e.value, e.loc)

    def x_Name(self, e: A.Name, env: TEnv) -> Node:
        return self.ref(e.name, [], env, e.loc)

    def x_Apply(self, e: A.Apply, env: TEnv) -> Node:
        if e.name == "\\X":
            return self.node(Op.PRODUCT, e.loc, kids=tuple(self.expr(x, env) for x in e.args))
        return self.ref(e.name, e.args, env, e.loc)

    def x_FnSet(self, e: A.FnSet, env: TEnv) -> Node:
        return self.node(Op.FNSET, e.loc, kids=(self.expr(e.domain, env), self.expr(e.range, env)))

    def ref(self, name: str, args: list[A.Expr], env: TEnv, loc: Loc) -> Node:
        local = env.locals.get(name)
        if local is not None:
            return self.local_ref(name, local, args, env, loc)
        sym = self.lookup(name, env)
        if sym is None:
            if name == "BOOLEAN" and not args:
                return self.const(BOOLEAN, loc)
            raise unsupported(f"the name {name}", loc)
        if hasattr(sym, "value") and not args:  # a definition given a value in the .cfg
            return self.const(sym.value, loc)
        if isinstance(sym, ConstSym) and not args and name in self.c.constants:
            return self.const(self.c.constants[name], loc)
        if isinstance(sym, VarSym) and not args:
            return self.node(Op.PVAR if (env.primed or env.init) else Op.VAR, loc, (sym.index,))
        if isinstance(sym, DefSym):
            return self.call_def(sym, args, env, loc)
        if isinstance(sym, BuiltinSym):
            return self.builtin(sym, args, env, loc)
        raise unsupported(f"the operator {name} ({type(sym).__name__})", loc)

    def local_ref(self, name: str, local: Any, args: list[A.Expr], env: TEnv, loc: Loc) -> Node:
        if isinstance(local, LetOp):
            return self.inline(local.defn, args, local.env.scope, local.env.locals, env, loc, self.expr)
        if args:
            raise unsupported(f"applying the local {name} to arguments", loc)
        if isinstance(local, SlotArg):
            if env.primed and local.source is not None:
                src, senv = local.source
                return self.expr(src, replace(senv, primed=True))
            return self.node(Op.SLOT, loc, (local.slot,))
        if isinstance(local, LazyArg):
            if env.primed:
                src, senv = local.source
                return self.expr(src, replace(senv, primed=True))
            return local.node
        if isinstance(local, ByName):
            return self.expr(local.expr, replace(local.env, primed=local.env.primed or env.primed))
        if isinstance(local, LetRef):
            if env.primed and not local.env.primed:
                raise unsupported(f"priming the LET definition {name}", loc)
            return local.node
        if isinstance(local, AtSlot):
            return self.node(Op.AT, loc, (local.slot,))
        raise unsupported(f"the local {name}", loc)

    def call_def(self, sym: DefSym, args: list[A.Expr], env: TEnv, loc: Loc) -> Node:
        d = sym.defn
        if sym.recursive:
            raise unsupported(f"the recursive operator {d.name}", loc)
        if sym.scope.instance_params or sym.scope.parameterised:
            raise unsupported(f"the operator {d.name} of a parameterised INSTANCE", loc)
        if d.fn_bounds is not None:
            fn = self.expr(A.FnLit(d.loc, d.fn_bounds, d.body), TEnv(sym.scope, {}, env.primed, env.init))
            if not args:
                return fn
            return self.node(Op.FNAPP, loc, kids=(fn, self.fn_arg(args, env, loc)))
        if not d.params:
            key = (id(sym), env.primed, env.init)
            got = self._defs.get(key)
            if got is None:
                if args:
                    raise unsupported(f"applying {d.name} to arguments", loc)
                got = self.expr(d.body, TEnv(sym.scope, {}, env.primed, env.init))
                if got[0] != Op.CONST and not self.free_slots(got):
                    got = self.node(Op.BIND_MEMO, loc, (), kids=(got,))  # a constant: evaluated once
                self._defs[key] = got
            return got
        return self.inline(d, args, sym.scope, {}, env, loc, self.expr)

    def inline(self, d: A.OpDef, args: list[A.Expr], scope: Scope, base: dict, env: TEnv, loc: Loc,
               body_of: Any) -> Node:
        """An operator expanded at its call: arguments into fresh slots (by name when
        action-level or in Init, as `Compiler.bind_params`; unevaluated into a lazy slot
        where evaluating them first could be told from TLC's lazy arguments), then the
        body."""
        if len(args) != len(d.params):
            raise unsupported(f"{d.name} applied to {len(args)} arguments", loc)
        self._depth += 1
        if self._depth > 40:
            raise unsupported(f"operator nesting this deep ({d.name})", loc)
        try:
            locals_ = dict(base)
            slots: list[int] = []
            values: list[Node] = []
            lazy: list[int] = []
            for p, a, by_value in zip(d.params, args, self.passed_by_value(d.params, args, d.body, scope, env)):
                if p.arity:
                    raise unsupported(f"the operator parameter {p.name}", p.loc)
                if env.init or _mentions_prime(a):
                    locals_[p.name] = ByName(a, env)
                elif by_value:
                    slot = self.alloc()
                    slots.append(slot)
                    values.append(self.expr(a, env))
                    locals_[p.name] = SlotArg(slot, (a, env))
                else:
                    outer = env.locals.get(a.name) if isinstance(a, A.Name) else None
                    if isinstance(outer, LazyArg) and not env.primed:
                        locals_[p.name] = outer  # passed on: the same lazy slot
                        continue
                    slot = self.alloc()
                    lazy.append(slot)
                    locals_[p.name] = LazyArg(self.node(Op.LETREF, a.loc, (slot,), kids=(self.expr(a, env),)),
                                              (a, env))
            body = body_of(d.body, TEnv(scope, locals_, env.primed, env.init))
        finally:
            self._depth -= 1
        if lazy:
            body = self.node(Op.LET if body_of == self.expr else Op.A_LET, loc, lazy, kids=(body,))
        if not slots:
            return body
        if body_of != self.expr:
            op = Op.A_BIND
        else:
            # A body that reads nothing but its parameters is a function of their values:
            # the core remembers them (constant-level helpers called once per state) when
            # it iterates over a set; for a cheap body the key costs more than the call
            # (the flagship: 1.5x slower with every such call remembered).
            pure = not (self.free_slots(body) - set(slots))
            op = Op.BIND_MEMO if pure and self.iterates(body) else Op.BIND
        return self.node(op, loc, slots, kids=tuple(values) + (body,))

    def passed_by_value(self, params: list[A.Param], args: list[A.Expr], body: A.Expr, scope: Scope,
                        env: TEnv) -> list[bool]:
        """For each argument: may it be evaluated before the call?  The rule of
        `tla/compile/lazy_args.py`: when it cannot fail, or when it is the only one that
        can and the body evaluates its parameter first."""
        eager = [p.arity > 0 or self.cannot_fail(a, env) for p, a in zip(params, args)]
        risky = [i for i, ok in enumerate(eager) if not ok]
        if len(risky) == 1 and first_evaluated(body, scope) == params[risky[0]].name:
            eager[risky[0]] = True
        return eager

    def cannot_fail(self, a: A.Expr, env: TEnv) -> bool:
        if isinstance(a, (A.Num, A.Str, A.Bool)):
            return True
        if isinstance(a, A.Name):
            local = env.locals.get(a.name)
            if local is not None:
                return isinstance(local, SlotArg) and not (env.primed and local.source is not None)
            sym = self.lookup(a.name, env)
            if hasattr(sym, "value"):
                return True
            if isinstance(sym, ConstSym):
                return a.name in self.c.constants
            return isinstance(sym, VarSym) and not (env.primed or env.init)
        if isinstance(a, (A.TupleLit, A.SetEnum)):
            return all(self.cannot_fail(x, env) for x in a.elems)
        if isinstance(a, A.RecLit):
            return all(self.cannot_fail(x, env) for _, x in a.fields)
        return False

    def iterates(self, n: Node) -> bool:
        """Does the expression iterate over a set (a quantifier, set filter or map,
        CHOOSE, function constructor or SelectSeq), itself or in a sub-expression?"""
        got = self._iterates.get(id(n))
        if got is not None:
            return got[1]
        op, kids, k = n[0], n[4], n[5]
        r = op in _ITERATING or any(self.iterates(x) for x in kids if x is not None) or (
            k is not None and self.iterates(k))
        self._iterates[id(n)] = (n, r)  # the node kept alive: its id stays its own
        return r

    def free_slots(self, n: Node) -> frozenset[int]:
        """The slots an expression reads but does not bind itself; -1 stands for the state."""
        got = self._free.get(id(n))
        if got is not None:
            return got[1]
        op, ints, kids, k = n[0], n[2], n[4], n[5]
        if op in (Op.VAR, Op.PVAR):
            free: frozenset[int] = frozenset((-1,))
        elif op in (Op.SLOT, Op.AT):
            free = frozenset((ints[0],))
        else:
            inner = frozenset().union(*(self.free_slots(x) for x in kids if x is not None))
            if k is not None:
                inner |= self.free_slots(k)
            if op == Op.LETREF:
                free = inner | {ints[0]}
            elif op in (Op.LET, Op.EXCEPT):
                free = inner - {ints[0]} if op == Op.EXCEPT else inner - set(ints)
            elif op in (Op.BIND, Op.BIND_MEMO, Op.SETMAP):
                nb = len(ints)
                free = frozenset().union(*(self.free_slots(x) for x in kids[:nb])) | (self.free_slots(kids[-1]) - set(ints))
            elif op in (Op.SETFILTER, Op.FORALL, Op.EXISTS, Op.CHOOSE, Op.FNLIT, Op.SELECTSEQ):
                free = self.free_slots(kids[0]) | (self.free_slots(kids[1]) - {ints[0]})
            else:
                free = inner
        self._free[id(n)] = (n, free)  # the node kept alive: its id stays its own
        return free

    def builtin(self, sym: BuiltinSym, args: list[A.Expr], env: TEnv, loc: Loc) -> Node:
        b = sym.builtin
        if b.name == "SelectSeq" and b.module == "Sequences" and len(args) == 2:
            slot = self.alloc()
            return self.node(Op.SELECTSEQ, loc, (slot,), kids=(self.expr(args[0], env), self.test_body(args[1], slot, env)))
        if b.name == "ToString" and b.module == "TLC" and len(args) == 1:
            return self.node(Op.TOSTRING, loc, kids=(self.expr(args[0], env),))
        spec = _BUILTIN_APPLY.get(b.name)
        if spec is None or b.module not in _NATIVE_MODULES or b.refused:
            raise unsupported(f"the operator {b.name} as a value", loc)
        op, arity = spec
        if len(args) != arity:
            raise unsupported(f"{b.name} applied to {len(args)} arguments", loc)
        return self.node(op, loc, kids=tuple(self.expr(a, env) for a in args))

    def test_body(self, op: A.Expr, slot: int, env: TEnv) -> Node:
        """The body of a one-parameter operator argument (``LAMBDA x : e``, a user
        operator or a LET operator, as SelectSeq's test), its parameter in `slot`."""
        if isinstance(op, A.Lambda) and len(op.params) == 1:
            return self.expr(op.body, replace(env, locals={**env.locals, op.params[0]: SlotArg(slot, None)}))
        name = op.name if isinstance(op, (A.Name, A.OpRef)) else None
        local = env.locals.get(name) if name else None
        if isinstance(local, LetOp):
            defn, scope, base = local.defn, local.env.scope, local.env.locals
        else:
            sym = self.lookup(name, env) if name and local is None else None
            if not isinstance(sym, DefSym) or sym.recursive or sym.defn.fn_bounds is not None \
                    or sym.scope.instance_params or sym.scope.parameterised:
                raise unsupported("this operator argument", op.loc)
            defn, scope, base = sym.defn, sym.scope, {}
        if len(defn.params) != 1 or defn.params[0].arity:
            raise unsupported(f"the operator argument {defn.name} (one parameter expected)", op.loc)
        return self.expr(defn.body, TEnv(scope, {**base, defn.params[0].name: SlotArg(slot, None)}, env.primed, env.init))

    def fn_arg(self, args: list[A.Expr], env: TEnv, loc: Loc) -> Node:
        if len(args) == 1:
            return self.expr(args[0], env)
        return self.node(Op.TUPLE, loc, kids=tuple(self.expr(a, env) for a in args))

    def x_Binary(self, e: A.Binary, env: TEnv) -> Node:
        op = e.op
        sym = self.lookup(op, env)
        if isinstance(sym, DefSym):
            return self.inline(sym.defn, [e.lhs, e.rhs], sym.scope, {}, env, e.loc, self.expr)
        if op in ("\\in", "\\notin"):
            return self.member(e.lhs, e.rhs, env, e.loc, op == "\\notin")
        if op == "/\\":
            return self.node(Op.AND, e.loc, kids=(self.expr(e.lhs, env), self.expr(e.rhs, env)))
        if op == "\\/":
            return self.node(Op.OR, e.loc, kids=(self.expr(e.lhs, env), self.expr(e.rhs, env)))
        if op in (":>", "@@") and isinstance(sym, BuiltinSym) and sym.builtin.module == "TLC":
            return self.expr(_tlc_function_definition(e), env)
        code = _CORE_BINARY.get(op)
        if code is None and isinstance(sym, BuiltinSym) and sym.builtin.module in _NATIVE_MODULES:
            code = _INT_BINARY.get(op)
        if code is None:
            raise unsupported(f"the operator {op}", e.loc)
        return self.node(code, e.loc, kids=(self.expr(e.lhs, env), self.expr(e.rhs, env)))

    def member(self, x: A.Expr, s: A.Expr, env: TEnv, loc: Loc, negated: bool) -> Node:
        sd = self.set_test(s, env, 0)
        lhs = self.expr(x, env)
        if sd[0] == Op.SD_SET:
            return self.node(Op.NOTIN if negated else Op.IN, loc, kids=(lhs, sd[4][0]))
        return self.node(Op.IN_SD, loc, (1 if negated else 0,), kids=(lhs, sd))

    def set_test(self, e: A.Expr, env: TEnv, depth: int, built: Callable[[], Node] | None = None) -> Node:
        """A membership test for `e`, which may be an infinite or structured set
        (``Seq(S)``, ``[S -> T]``, ``[a : S]``, ``Nat``, ``a..b``) that is never built.
        `built`: where `e` is the body of a zero-arity definition, that definition's node
        (a constant set is evaluated once there), used if the set must be built."""
        if depth > 40:
            raise unsupported("a set defined this deep", e.loc)
        if isinstance(e, A.FnSet):
            return self.node(Op.SD_FN, e.loc, kids=(self.expr(e.domain, env), self.set_test(e.range, env, depth + 1)))
        if isinstance(e, A.RecSet):
            keys = [self.bridge.engine.mk_str(f, string_rank(f)) for f, _ in e.fields]
            return self.node(Op.SD_REC, e.loc, keys, kids=tuple(self.set_test(s, env, depth + 1) for _, s in e.fields))
        set_op = {"\\cup": Op.SD_CUP, "\\cap": Op.SD_CAP, "\\": Op.SD_DIFF}.get(e.op) \
            if isinstance(e, A.Binary) and not isinstance(self.lookup(e.op, env), DefSym) else None
        if set_op is not None and isinstance(e, A.Binary):  # set_op implies a Binary
            return self.node(set_op, e.loc, kids=(self.set_test(e.lhs, env, depth + 1), self.set_test(e.rhs, env, depth + 1)))
        if isinstance(e, A.Unary) and e.op == "SUBSET" and not isinstance(self.lookup("SUBSET", env), DefSym):
            return self.node(Op.SD_SUBSET, e.loc, kids=(self.set_test(e.arg, env, depth + 1),))
        if isinstance(e, A.Apply) and e.name == "\\X":
            return self.node(Op.SD_PRODUCT, e.loc, kids=tuple(self.set_test(x, env, depth + 1) for x in e.args))
        if isinstance(e, A.Binary) and e.op == ".." and isinstance(self.lookup("..", env), BuiltinSym):
            return self.node(Op.SD_RANGE, e.loc, kids=(self.expr(e.lhs, env), self.expr(e.rhs, env)))
        if isinstance(e, (A.Name, A.Apply)):
            local = env.locals.get(e.name)
            if isinstance(local, ByName) and not isinstance(e, A.Apply):
                return self.set_test(local.expr, local.env, depth + 1)
            if local is None:
                sym = self.lookup(e.name, env)
                args = e.args if isinstance(e, A.Apply) else []
                if isinstance(sym, BuiltinSym) and sym.builtin.module in _NATIVE_MODULES | {"Sequences"}:
                    name = sym.builtin.name
                    if name == "Seq" and len(args) == 1:
                        return self.node(Op.SD_SEQ, e.loc, kids=(self.set_test(args[0], env, depth + 1),))
                    if name in ("Nat", "Int") and not args:
                        return self.node(Op.SD_NAT if name == "Nat" else Op.SD_INT, e.loc)
                if sym is None and e.name == "STRING" and not args:
                    return self.node(Op.SD_STRING, e.loc)
                if isinstance(sym, DefSym) and not sym.recursive and sym.defn.fn_bounds is None \
                        and not sym.scope.instance_params and not sym.scope.parameterised:
                    if not sym.defn.params and not args:
                        # A set that must be built is the definition's own node: the Safety
                        # service's TypeOK rebuilt its 1,440-record inbox filter in every state.
                        d, at = sym, e.loc
                        return self.set_test(d.defn.body, TEnv(d.scope, {}, env.primed, env.init), depth + 1,
                                             lambda: self.call_def(d, [], env, at))
                    if len(args) == len(sym.defn.params) and not any(p.arity for p in sym.defn.params):
                        locals_ = {p.name: ByName(a, env) for p, a in zip(sym.defn.params, args)}
                        return self.set_test(sym.defn.body, TEnv(sym.scope, locals_, env.primed, env.init), depth + 1)
        return self.node(Op.SD_SET, e.loc, kids=(built() if built is not None else self.expr(e, env),))

    def x_Unary(self, e: A.Unary, env: TEnv) -> Node:
        op = e.op
        user = self.lookup("-." if op == "-" else op, env)
        if isinstance(user, DefSym):
            return self.inline(user.defn, [e.arg], user.scope, {}, env, e.loc, self.expr)
        if op == "~":
            return self.node(Op.NOT, e.loc, kids=(self.expr(e.arg, env),))
        if op == "-" and isinstance(user, BuiltinSym):
            return self.node(Op.NEG, e.loc, kids=(self.expr(e.arg, env),))
        if op == "DOMAIN":
            return self.node(Op.DOMAIN, e.loc, kids=(self.expr(e.arg, env),))
        if op == "SUBSET":
            return self.node(Op.POWERSET, e.loc, kids=(self.expr(e.arg, env),))
        if op == "UNCHANGED" and not env.primed and not env.init:  # e' = e
            return self.node(Op.EQ, e.loc, kids=(self.expr(e.arg, replace(env, primed=True)), self.expr(e.arg, env)))
        raise unsupported(f"the operator {op}", e.loc)

    def x_And(self, e: A.And, env: TEnv) -> Node:
        return self.node(Op.AND, e.loc, kids=tuple(self.expr(i, env) for i in e.items))

    def x_Or(self, e: A.Or, env: TEnv) -> Node:
        return self.node(Op.OR, e.loc, kids=tuple(self.expr(i, env) for i in e.items))

    def x_Prime(self, e: A.Prime, env: TEnv) -> Node:
        if env.primed or env.init:
            raise unsupported("a prime here", e.loc)
        return self.expr(e.arg, replace(env, primed=True))

    def x_If(self, e: A.If, env: TEnv) -> Node:
        return self.node(Op.IF, e.loc, kids=(self.expr(e.cond, env), self.expr(e.then, env), self.expr(e.other, env)))

    def x_Case(self, e: A.Case, env: TEnv) -> Node:
        kids: list[Node] = []
        for g, v in e.arms:
            kids += [self.expr(g, env), self.expr(v, env)]
        if e.other is not None:
            kids.append(self.expr(e.other, env))
        return self.node(Op.CASE, e.loc, (len(e.arms),), kids=tuple(kids))

    def bind_let(self, e: A.Let, env: TEnv) -> tuple[TEnv, list[int]]:
        locals_ = dict(env.locals)
        slots: list[int] = []
        for d in e.defs:
            if not isinstance(d, A.OpDef):
                raise unsupported("INSTANCE inside LET", d.loc)
            inner = replace(env, locals=dict(locals_))
            if d.params:
                locals_[d.name] = LetOp(d, inner)
                continue
            body = A.FnLit(d.loc, d.fn_bounds, d.body) if d.fn_bounds is not None else d.body
            if d.name in _names(body):
                raise unsupported(f"the recursive LET definition {d.name}", d.loc)
            slot = self.alloc()
            slots.append(slot)
            locals_[d.name] = LetRef(self.node(Op.LETREF, d.loc, (slot,), kids=(self.expr(body, inner),)), body, inner)
        return replace(env, locals=locals_), slots

    def x_Let(self, e: A.Let, env: TEnv) -> Node:
        env2, slots = self.bind_let(e, env)
        return self.node(Op.LET, e.loc, slots, kids=(self.expr(e.body, env2),))

    def names_of(self, bounds: list[A.Bound], loc: Loc) -> list[tuple[str, A.Expr]]:
        out: list[tuple[str, A.Expr]] = []
        for b in bounds:
            if b.tuple:
                raise unsupported("a tuple of bound names <<x, y>> \\in S", loc)
            out += [(n, b.set) for n in b.names]
        return out

    def x_Quant(self, e: A.Quant, env: TEnv) -> Node:
        op = Op.FORALL if e.kind == "\\A" else Op.EXISTS
        pairs = self.names_of(e.bounds, e.loc)
        sets = [self.expr(s, env) for _, s in pairs]
        locals_ = dict(env.locals)
        slots = []
        for n, _ in pairs:
            slots.append(self.alloc())
            locals_[n] = SlotArg(slots[-1], None)
        body = self.expr(e.body, replace(env, locals=locals_))
        for slot, s in reversed(list(zip(slots, sets))):
            body = self.node(op, e.loc, (slot,), kids=(s, body))
        return body

    def _bind_one(self, bound: A.Bound, env: TEnv, loc: Loc) -> tuple[int, Node, TEnv]:
        pairs = self.names_of([bound], loc)
        if len(pairs) != 1:
            raise unsupported("several bound names here", loc)
        slot = self.alloc()
        name, s = pairs[0]
        return slot, self.expr(s, env), replace(env, locals={**env.locals, name: SlotArg(slot, None)})

    def x_RecSet(self, e: A.RecSet, env: TEnv) -> Node:
        keys = [self.bridge.engine.mk_str(f, string_rank(f)) for f, _ in e.fields]
        return self.node(Op.RECSET, e.loc, keys, kids=tuple(self.expr(s, env) for _, s in e.fields))

    def x_Prefixed(self, e: A.Prefixed, env: TEnv) -> Node:
        """``M!Op(args)`` of an ``M == INSTANCE ...`` without parameters."""
        from ...tla.modules import InstanceSym
        inst = self.lookup(e.path[0].name, env) if len(e.path) == 1 and not e.path[0].args else None
        if not isinstance(inst, InstanceSym) or inst.inst.params or inst.let_locals:
            raise unsupported("this instance reference M!Op", e.loc)
        sym = inst.scope.lookup(e.name)
        sym = self.c.sym_overrides.get(id(sym), sym)
        if not isinstance(sym, DefSym):
            raise unsupported(f"the instance operator {e.name}", e.loc)
        return self.call_def(sym, e.args, env, e.loc)

    def x_SetEnum(self, e: A.SetEnum, env: TEnv) -> Node:
        return self.node(Op.SETENUM, e.loc, kids=tuple(self.expr(x, env) for x in e.elems))

    def x_Choose(self, e: A.Choose, env: TEnv) -> Node:
        if e.set is None or e.tuple or len(e.names) != 1:
            raise unsupported("this CHOOSE (unbounded, or over a tuple of names)", e.loc)
        slot = self.alloc()
        s = self.expr(e.set, env)
        env2 = replace(env, locals={**env.locals, e.names[0]: SlotArg(slot, None)})
        return self.node(Op.CHOOSE, e.loc, (slot,), kids=(s, self.expr(e.body, env2)))

    def x_SetFilter(self, e: A.SetFilter, env: TEnv) -> Node:
        slot, s, env2 = self._bind_one(e.bound, env, e.loc)
        return self.node(Op.SETFILTER, e.loc, (slot,), kids=(s, self.expr(e.pred, env2)))

    def x_SetMap(self, e: A.SetMap, env: TEnv) -> Node:
        pairs = self.names_of(e.bounds, e.loc)
        sets = tuple(self.expr(s, env) for _, s in pairs)
        slots = [self.alloc() for _ in pairs]
        env2 = replace(env, locals={**env.locals, **{n: SlotArg(sl, None) for (n, _), sl in zip(pairs, slots)}})
        return self.node(Op.SETMAP, e.loc, slots, kids=sets + (self.expr(e.expr, env2),))

    def x_FnApp(self, e: A.FnApp, env: TEnv) -> Node:
        return self.node(Op.FNAPP, e.loc, kids=(self.expr(e.fn, env), self.fn_arg(e.args, env, e.loc)))

    def x_FnLit(self, e: A.FnLit, env: TEnv) -> Node:
        if len(e.bounds) != 1:
            raise unsupported("a function over several bounds", e.loc)
        slot, s, env2 = self._bind_one(e.bounds[0], env, e.loc)
        return self.node(Op.FNLIT, e.loc, (slot,), kids=(s, self.expr(e.body, env2)))

    def x_RecLit(self, e: A.RecLit, env: TEnv) -> Node:
        keys = [self.bridge.engine.mk_str(f, string_rank(f)) for f, _ in e.fields]
        return self.node(Op.RECLIT, e.loc, keys, kids=tuple(self.expr(x, env) for _, x in e.fields))

    def x_Dot(self, e: A.Dot, env: TEnv) -> Node:
        key = self.node(Op.CONST, e.loc, v=self.bridge.engine.mk_str(e.field, string_rank(e.field)))
        return self.node(Op.FNAPP, e.loc, kids=(self.expr(e.rec, env), key))

    def x_Except(self, e: A.Except, env: TEnv) -> Node:
        at = self.alloc()
        env2 = replace(env, locals={**env.locals, "@": AtSlot(at)})
        ints = [at]
        kids = [self.expr(e.base, env)]
        for u in e.updates:
            ints.append(len(u.path))
            for kind, item in u.path:
                if kind == "field":
                    name = cast(str, item)  # a ("field", name) item
                    kids.append(self.node(Op.CONST, e.loc, v=self.bridge.engine.mk_str(name, string_rank(name))))
                else:
                    kids.append(self.fn_arg(item, env, e.loc))  # type: ignore[arg-type]
            kids.append(self.expr(u.value, env2))
        return self.node(Op.EXCEPT, e.loc, ints, kids=tuple(kids))

    def x_At(self, e: A.At, env: TEnv) -> Node:
        local = env.locals.get("@")
        if not isinstance(local, AtSlot):
            raise unsupported("@ outside EXCEPT", e.loc)
        return self.node(Op.AT, e.loc, (local.slot,))

    def x_TupleLit(self, e: A.TupleLit, env: TEnv) -> Node:
        return self.node(Op.TUPLE, e.loc, kids=tuple(self.expr(x, env) for x in e.elems))

    # ---------------------------------------------------------------- actions
    def split(self, e: A.Expr, env: TEnv, params: tuple[tuple[str, int], ...] = ()) -> Node:
        """Next as `ActionCompiler.split`: each of TLC's actions ends in its own leaf,
        whose parameters (the \\E variables and the operator arguments bound to slots
        on the way, as `Leaf.params`) are recorded in `leaf_params`."""
        if isinstance(e, A.Or):
            return self.node(Op.A_OR, e.loc, kids=tuple(self.split(i, env, params) for i in e.items))
        if isinstance(e, A.Quant) and e.kind == "\\E":
            names = [n for n, _ in self.names_of(e.bounds, e.loc)]
            return self.exists(e, env, lambda env2: self.split(
                e.body, env2, params + tuple((n, env2.locals[n].slot) for n in names)))
        if isinstance(e, A.Let):
            env2, slots = self.bind_let(e, env)
            return self.node(Op.A_LET, e.loc, slots, kids=(self.split(e.body, env2, params),))
        if isinstance(e, (A.Name, A.Apply)) and e.name not in env.locals:
            sym = env.scope.lookup(e.name)
            if isinstance(sym, DefSym) and not sym.recursive and sym.defn.fn_bounds is None:
                args = e.args if isinstance(e, A.Apply) else []
                if sym.scope.instance_params or sym.scope.parameterised:
                    raise unsupported(f"the operator {sym.defn.name} of a parameterised INSTANCE", e.loc)

                def body(b: A.Expr, benv: TEnv) -> Node:
                    bound = [(p.name, benv.locals[p.name]) for p in sym.defn.params]
                    return self.split(b, benv, params + tuple((n, a.slot) for n, a in bound if isinstance(a, SlotArg)))
                return self.inline(sym.defn, args, sym.scope, {}, env, e.loc, body)
        leaf = self.leaves
        self.leaves += 1
        self.leaf_params.append(params)
        return self.action(e, env, self.node(Op.A_EMIT, e.loc, (leaf,)))

    def _bound_slots(self, e: A.Quant, env: TEnv) -> tuple[tuple, list, TEnv]:
        """The bound sets of a quantifier over actions, a slot for each bound name, and
        the environment of its body (each name read from its slot)."""
        pairs = self.names_of(e.bounds, e.loc)
        sets = tuple(self.expr(s, env) for _, s in pairs)
        locals_ = dict(env.locals)
        slots = []
        for n, _ in pairs:
            slots.append(self.alloc())
            locals_[n] = SlotArg(slots[-1], None)
        return sets, slots, replace(env, locals=locals_)

    def exists(self, e: A.Quant, env: TEnv, body_of: Any) -> Node:
        sets, slots, inner = self._bound_slots(e, env)
        return self.node(Op.A_EXISTS, e.loc, slots, kids=sets + (body_of(inner),))

    def action(self, e: A.Expr, env: TEnv, k: Node) -> Node:
        method = getattr(self, "a_" + type(e).__name__, None)
        if method is not None:
            r = method(e, env, k)
            if r is not None:
                return r
        return self.guard(e, env, k)

    def guard(self, e: A.Expr, env: TEnv, k: Node) -> Node:
        return self.node(Op.A_GUARD, e.loc, kids=(self.expr(e, env),), k=k)

    def a_Bool(self, e: A.Bool, env: TEnv, k: Node) -> Node:
        return k if e.value else self.node(Op.A_FALSE, e.loc)

    def a_And(self, e: A.And, env: TEnv, k: Node) -> Node:
        items = list(e.items)
        while items:
            item = items.pop()
            plain = self.plain_assignments(item, env)
            if plain is not None:
                for i, rhs, loc in reversed(plain):
                    k = self.node(Op.A_ASSIGN, loc, (i,), kids=(rhs,), k=k)
                continue
            act = self.action(item, env, k)
            # Once every variable is assigned, a later conjunct is a boolean (TLC's
            # getNextStatesAllAssigned): a disjunction in it yields one successor.
            if items and act[0] != Op.A_GUARD:
                act = self.node(Op.A_ALLASSIGNED, item.loc, kids=(act, self.guard(item, env, k)))
            k = act
        return k

    def plain_assignments(self, e: A.Expr, env: TEnv) -> list[tuple[int, Node, Loc]] | None:
        if isinstance(e, A.Binary) and e.op == "=":
            target = self.target_var(e.lhs, env, 0)
            if target is not None:
                return [(target, self.expr(e.rhs, env), e.loc)]
            return None
        if isinstance(e, A.Unary) and e.op == "UNCHANGED" and not env.init:
            idx = self.unchanged_vars(e.arg, env, 0)
            if idx is not None:
                return [(i, self.node(Op.VAR, e.loc, (i,)), e.loc) for i in idx]
        return None

    def a_Or(self, e: A.Or, env: TEnv, k: Node) -> Node:
        return self.node(Op.A_OR, e.loc, kids=tuple(self.action(i, env, k) for i in e.items))

    def a_Quant(self, e: A.Quant, env: TEnv, k: Node) -> Node | None:
        if e.kind != "\\E":
            return self.forall(e, env, k)
        return self.exists(e, env, lambda env2: self.action(e.body, env2, k))

    def forall(self, e: A.Quant, env: TEnv, k: Node) -> Node | None:
        """A plain boolean \\A (its body never branches) is a guard (None); otherwise TLC
        takes it as a conjunction of actions, one per binding (`ActionCompiler._forall`):
        A_FORALL, its body and the same body as a guard both ending in A_FORALL_NEXT."""
        sets, slots, env2 = self._bound_slots(e, env)
        index = self.foralls
        self.foralls += 1
        after = self.node(Op.A_FORALL_NEXT, e.loc, (index,))
        lo = self.nslots
        body = self.action(e.body, env2, after)
        if _guard_chain(body, after):
            return None
        test = self.guard(e.body, env2, after)
        return self.node(Op.A_FORALL, e.loc, (index, lo, self.nslots, *slots), kids=sets + (body, test, after), k=k)

    def a_If(self, e: A.If, env: TEnv, k: Node) -> Node:
        return self.node(Op.A_IF, e.loc, kids=(self.expr(e.cond, env), self.action(e.then, env, k),
                                               self.action(e.other, env, k)))

    def a_Case(self, e: A.Case, env: TEnv, k: Node) -> Node:
        kids: list[Node] = []
        for g, v in e.arms:
            kids += [self.expr(g, env), self.action(v, env, k)]
        if e.other is not None:
            kids.append(self.action(e.other, env, k))
        return self.node(Op.A_CASE, e.loc, (len(e.arms),), kids=tuple(kids))

    def a_Let(self, e: A.Let, env: TEnv, k: Node) -> Node:
        env2, slots = self.bind_let(e, env)
        return self.node(Op.A_LET, e.loc, slots, kids=(self.action(e.body, env2, k),))

    def a_Name(self, e: A.Name, env: TEnv, k: Node) -> Node | None:
        return self.call_action(e, [], env, k)

    def a_Apply(self, e: A.Apply, env: TEnv, k: Node) -> Node | None:
        return self.call_action(e, e.args, env, k)

    def call_action(self, e: A.Name | A.Apply, args: list[A.Expr], env: TEnv, k: Node) -> Node | None:
        local = env.locals.get(e.name)
        if local is not None:
            if isinstance(local, ByName) and not args:
                return self.action(local.expr, local.env, k)
            if isinstance(local, LetRef) and not args:
                code = self.action(local.expr, local.env, k)
                return None if _guard_chain(code, k) else code
            if isinstance(local, LetOp) and e.name not in _names(local.defn.body):
                return self.inline(local.defn, args, local.env.scope, local.env.locals, env, e.loc,
                                   lambda b, benv: self.action(b, benv, k))
            return None
        sym = self.lookup(e.name, env)
        if not isinstance(sym, DefSym) or sym.defn.fn_bounds is not None:
            return None
        if sym.recursive:
            raise unsupported(f"the recursive operator {sym.defn.name}", e.loc)
        if sym.scope.instance_params or sym.scope.parameterised:
            raise unsupported(f"the operator {sym.defn.name} of a parameterised INSTANCE", e.loc)
        if self._depth > 40:
            return None
        return self.inline(sym.defn, args, sym.scope, {}, env, e.loc, lambda b, benv: self.action(b, benv, k))

    def a_StepAction(self, e: A.StepAction, env: TEnv, k: Node) -> Node:
        raise unsupported("[A]_v or <<A>>_v inside an action", e.loc)

    def a_Prefixed(self, e: A.Prefixed, env: TEnv, k: Node) -> Node:
        raise unsupported("an instance operator M!Op", e.loc)

    def a_Unary(self, e: A.Unary, env: TEnv, k: Node) -> Node | None:
        if e.op != "UNCHANGED":
            return None
        return self.unchanged(e.arg, env, k, 0)

    def a_Binary(self, e: A.Binary, env: TEnv, k: Node) -> Node | None:
        if e.op == "=>":
            return self.node(Op.A_IMPLIES, e.loc, kids=(self.expr(e.lhs, env), self.action(e.rhs, env, k)), k=k)
        if e.op not in ("=", "\\in"):
            return None
        target = self.target_var(e.lhs, env, 0)
        if target is None:
            return None
        if e.op == "=":
            return self.node(Op.A_ASSIGN, e.loc, (target,), kids=(self.expr(e.rhs, env),), k=k)
        return self.node(Op.A_ASSIGN_IN, e.loc, (target,), kids=(self.expr(e.rhs, env), self.set_test(e.rhs, env, 0)),
                         k=k)

    def target_var(self, lhs: A.Expr, env: TEnv, depth: int) -> int | None:
        """The variable ``lhs = ...`` assigns (`ActionCompiler._target_var`)."""
        if env.init:
            return self.var_of(lhs, env, 0)
        if isinstance(lhs, A.Prime):
            return self.var_of(lhs.arg, env, 0)
        named = self.named_expr(lhs, env)
        if named is not None and depth < 20:
            return self.target_var(named[0], named[1], depth + 1)
        return None

    def var_of(self, e: A.Expr, env: TEnv, depth: int) -> int | None:
        if isinstance(e, A.Name) and e.name not in env.locals:
            sym = self.lookup(e.name, env)
            if isinstance(sym, VarSym):
                return sym.index
        named = self.named_expr(e, env)
        if named is not None and depth < 20:
            return self.var_of(named[0], named[1], depth + 1)
        return None

    def named_expr(self, e: A.Expr, env: TEnv) -> tuple[A.Expr, TEnv] | None:
        if not isinstance(e, A.Name):
            return None
        local = env.locals.get(e.name)
        if local is not None:
            if isinstance(local, ByName):
                return local.expr, local.env
            if isinstance(local, (SlotArg, LazyArg)):
                return local.source
            if isinstance(local, LetRef):
                return local.expr, local.env
            return None
        sym = self.lookup(e.name, env)
        if isinstance(sym, DefSym) and not sym.defn.params and sym.defn.fn_bounds is None:
            return sym.defn.body, TEnv(sym.scope, {}, False, env.init)
        return None

    def unchanged(self, e: A.Expr, env: TEnv, k: Node, depth: int) -> Node:
        idx = self.unchanged_vars(e, env, 0)
        if idx is not None:
            for i in reversed(idx):
                k = self.node(Op.A_ASSIGN, e.loc, (i,), kids=(self.node(Op.VAR, e.loc, (i,)),), k=k)
            return k
        if depth < 20:
            if isinstance(e, A.TupleLit):
                for x in reversed(e.elems):
                    k = self.unchanged(x, env, k, depth + 1)
                return k
            named = self.named_expr(e, env)
            if named is not None:
                return self.unchanged(named[0], named[1], k, depth + 1)
        raise unsupported("UNCHANGED of an expression that is not a tuple of variables", e.loc)

    def unchanged_vars(self, e: A.Expr, env: TEnv, depth: int) -> list[int] | None:
        if depth > 20:
            return None
        if isinstance(e, A.TupleLit):
            out: list[int] = []
            for x in e.elems:
                sub = self.unchanged_vars(x, env, depth + 1)
                if sub is None:
                    return None
                out.extend(sub)
            return out
        var = self.var_of(e, env, 0)
        if var is not None:
            return [var]
        named = self.named_expr(e, env)
        if named is not None:
            return self.unchanged_vars(named[0], named[1], depth + 1)
        return None


def _guard_chain(n: Node, k: Node) -> bool:
    """Is `n` a chain of guards ending in `k` (never branches; `actions._plain_guard`)?"""
    while n[0] == Op.A_GUARD:
        n = n[5]
        if n is k:
            return True
    return False


def _names(e: Any) -> set[str]:
    from ...tla.compiler import all_names
    return all_names(e)
