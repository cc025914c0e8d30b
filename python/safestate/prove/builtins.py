"""The standard-module operators, infix operators and function/record/set
constructors, on symbolic values (see translate.py)."""

from __future__ import annotations

import itertools
from typing import TYPE_CHECKING, Any, Callable

import z3

from ..tla import ast as A
from ..tla.errors import Loc
from .sets import (EnumSet, PredSet, SetV, cardinality, difference, intersect, need_enum, need_set, subseteq,
                   union)
from .values import UNDEF, UNTRACKED, Fn, ProveError, Rec, SeqV, Tup, as_seq, eq, is_z3, ite, key_value, tracked

if TYPE_CHECKING:
    from .translate import Ctx, Translator

BUILTIN_NAMES = {"Nat", "Int", "BOOLEAN", "STRING"}
_ENUM_LIMIT = 4096  # largest interval or product enumerated explicitly


def _int_set(desc: str, pred: Callable[[Any], z3.BoolRef], upper: int | None = None) -> PredSet:
    def member(x: Any) -> z3.BoolRef:
        if not (is_z3(x) and z3.is_int(x)):
            return z3.BoolVal(False)
        return pred(x)
    return PredSet(desc, member, lambda n: z3.Int(n), upper=upper)


NAT = lambda: _int_set("Nat", lambda x: x >= 0)  # noqa: E731
INT = lambda: _int_set("Int", lambda x: z3.BoolVal(True))  # noqa: E731


def boolean_set() -> EnumSet:
    return EnumSet([(z3.BoolVal(True), z3.BoolVal(False)), (z3.BoolVal(True), z3.BoolVal(True))])


def interval(tr: "Translator", lo: z3.ArithRef, hi: z3.ArithRef, loc: Loc) -> SetV:
    clo, chi = tr.conc(lo), tr.conc(hi)
    if clo is not None and chi is not None and chi - clo < _ENUM_LIMIT:
        return EnumSet([(z3.BoolVal(True), z3.IntVal(i)) for i in range(clo, chi + 1)], z3.IntVal(0))
    upper = chi if chi is not None else tr.upper_bound(hi)
    # (printing z3 terms is slow: the bounds are shown only when concrete)
    desc = f"{clo if clo is not None else 'a'}..{chi if chi is not None else 'b'}"
    s = _int_set(desc, lambda x: z3.And(lo <= x, x <= hi), upper)
    s.extra["interval"] = (lo, hi)  # 1..n with n bounded: a function over it is a bounded sequence
    return s


def product(sets: list[SetV], loc: Loc) -> SetV:
    enums = [s for s in sets if isinstance(s, EnumSet)]
    if len(enums) == len(sets):
        items = []
        for combo in itertools.product(*[s.items for s in enums]):
            items.append((z3.And([g for g, _ in combo]) if len(combo) > 1 else combo[0][0],
                          Tup(tuple(x for _, x in combo))))
        return EnumSet([(_s(g), x) for g, x in items])

    def member(x: Any) -> z3.BoolRef:
        if not isinstance(x, Tup) or len(x.items) != len(sets):
            return z3.BoolVal(False)
        return z3.And([s.member(v, loc) for s, v in zip(sets, x.items)])
    return PredSet("\\X", member, lambda n: Tup(tuple(s.fresh(f"{n}[{i + 1}]", loc) for i, s in enumerate(sets))))


def _s(g: z3.BoolRef) -> z3.BoolRef:
    return g if z3.is_true(g) or z3.is_false(g) else z3.simplify(g)


def rec_set(fields: dict[str, SetV], loc: Loc) -> SetV:
    enums = [s for s in fields.values() if isinstance(s, EnumSet)]
    size = 1
    for s in enums:
        size *= max(1, len(s.items))
    names = list(fields)
    if len(enums) == len(fields) and size <= _ENUM_LIMIT:
        items = []
        for combo in itertools.product(*[need_enum(fields[f], "record set", loc).items for f in names]):
            items.append((_s(z3.And([g for g, _ in combo])), Rec({f: x for f, (_, x) in zip(names, combo)})))
        return EnumSet(items)

    def member(x: Any) -> z3.BoolRef:
        if not isinstance(x, Rec) or set(x.fields) != set(names):
            return z3.BoolVal(False)
        return z3.And([fields[f].member(x.fields[f], loc) for f in names])
    return PredSet("[f : S]", member, lambda n: Rec({f: fields[f].fresh(f"{n}.{f}", loc) for f in names}))


def fn_set(tr: "Translator", dom: EnumSet, rng: SetV, loc: Loc) -> SetV:
    keys = []
    for g, x in dom.items:
        k = tr.conc(x)
        if k is None or not z3.is_true(_s(g)):
            raise ProveError("[D -> S] with a domain that is not a constant finite set", loc)
        keys.append(k)

    def member(f: Any) -> z3.BoolRef:
        if isinstance(f, Tup):
            from .values import tup_as_fn
            f = tup_as_fn(f)
        if not isinstance(f, Fn) or set(f.keys) != set(keys):
            return z3.BoolVal(False)
        return z3.And([rng.member(f.vals[k], loc) for k in keys])
    return PredSet("[D -> S]", member, lambda n: Fn(tuple(keys), {k: rng.fresh(f"{n}[{k}]", loc) for k in keys}))


def seq_set(elem: SetV, loc: Loc) -> PredSet:
    def member(s: Any) -> z3.BoolRef:
        if isinstance(s, Tup):
            return z3.And([elem.member(x, loc) for x in s.items])
        if not isinstance(s, SeqV):
            return z3.BoolVal(False)
        return z3.And([s.length >= 0, s.length <= s.cap] +
                      [z3.Implies(s.length > i, elem.member(x, loc)) for i, x in enumerate(s.items)])

    def maker(n: str) -> Any:
        raise ProveError("Seq(S) needs a length bound (a TypeOK conjunct Len(x) <= N)", loc)
    return PredSet("Seq(S)", member, maker, extra={"seq_elem": elem})


def domain(tr: "Translator", v: Any, loc: Loc) -> SetV:
    if isinstance(v, Rec):
        return EnumSet([(z3.BoolVal(True), tr.strings.val(f, loc)) for f in v.fields])
    if isinstance(v, Fn):
        return EnumSet([(z3.BoolVal(True), key_value(k, tr.strings)) for k in v.keys])
    if isinstance(v, Tup):
        return EnumSet([(z3.BoolVal(True), z3.IntVal(i)) for i in range(1, len(v.items) + 1)], z3.IntVal(0),
                       z3.IntVal(len(v.items)))
    if isinstance(v, SeqV):
        return EnumSet([(v.length >= i, z3.IntVal(i)) for i in range(1, v.cap + 1)], z3.IntVal(0), v.length)
    raise ProveError("DOMAIN of a value that is not a function", loc)


def powerset(tr: "Translator", s: Any, loc: Loc) -> SetV:
    base = need_set(s, "SUBSET", loc)

    def maker(n: str) -> Any:
        raise ProveError("SUBSET over a non-constant set (only membership in SUBSET S is translated)", loc)
    return PredSet("SUBSET", lambda x: subseteq(need_set(x, "\\in SUBSET", loc), base, loc), maker,
                   extra={"subset_of": base})


def big_union(s: Any, loc: Loc) -> SetV:
    outer = need_enum(s, "UNION", loc)
    items: list[tuple[z3.BoolRef, Any]] = []
    for g, inner in outer.items:
        e = need_enum(inner, "UNION", loc)
        items.extend((_s(z3.And(g, g2)), x) for g2, x in e.items)
    return EnumSet(items)


def fn_apply(tr: "Translator", f: Any, arg: Any, loc: Loc) -> Any:
    """f[arg], with the obligation that arg is in DOMAIN f (outside it the value is unspecified)."""
    if f is UNDEF or arg is UNDEF:
        return UNDEF
    if isinstance(f, Rec):
        k = tr.conc(arg)
        if isinstance(k, str):
            if k not in f.fields:
                tr.obl.add("field", loc, f"the record has a field {k}", False)
                return UNDEF
            return f.fields[k]
        cases = [(eq(arg, tr.strings.val(n, loc)), x) for n, x in f.fields.items()]
        tr.obl.add("domain", loc, "the argument is a field of the record", z3.Or([c for c, _ in cases]))
        return _select(cases, loc)
    if isinstance(f, Fn):
        k = tr.conc(arg)
        if k is not None:
            if k not in f.vals:
                tr.obl.add("domain", loc, f"the function is applied inside its domain (argument {k!r})", False)
                return f.vals[f.keys[-1]] if f.keys else UNDEF
            return f.vals[k]
        cases = [(eq(arg, key_value(kk, tr.strings), loc), f.vals[kk]) for kk in f.keys]
        tr.obl.add("domain", loc, "the function is applied inside its domain", z3.Or([c for c, _ in cases]))
        return _select(cases, loc)
    if isinstance(f, (Tup, SeqV)):
        items = f.items
        k = tr.conc(arg)
        if not (is_z3(arg) and z3.is_int(arg)):
            tr.obl.add("domain", loc, "a sequence is applied to an integer", False)
            return UNDEF
        length = f.length if isinstance(f, SeqV) else z3.IntVal(len(items))
        tr.obl.add("domain", loc, "the index is in 1..Len of the sequence", z3.And(arg >= 1, arg <= length))
        if k is not None:
            return items[k - 1] if 1 <= k <= len(items) else UNDEF
        return _select([(arg == i + 1, x) for i, x in enumerate(items)], loc)
    raise ProveError("application of a value that is not a function", loc)


def _select(cases: list[tuple[z3.BoolRef, Any]], loc: Loc) -> Any:
    # outside the domain the result is unspecified (the caller's obligation): take the last case
    if not cases:
        return UNDEF
    out = cases[-1][1]
    for c, x in reversed(cases[:-1]):
        out = ite(c, x, out, loc)
    return out


def update(tr: "Translator", v: Any, path: list[tuple[str, Any]], new: Callable[[Any], Any], loc: Loc) -> Any:
    """[v EXCEPT !path = new(@)]"""
    if not path:
        return new(v)
    kind, item = path[0]
    rest = path[1:]
    if kind == "field" or isinstance(v, Rec):
        name = item if kind == "field" else tr.conc(item)
        if isinstance(v, Rec):
            if not isinstance(name, str):
                return Rec({f: ite(eq(item, tr.strings.val(f, loc)), update(tr, x, rest, new, loc), x, loc)
                            for f, x in v.fields.items()})
            if name not in v.fields:
                raise ProveError(f"EXCEPT on a missing field {name}", loc)
            return Rec({**v.fields, name: update(tr, v.fields[name], rest, new, loc)})
        item = tr.strings.val(item, loc)
    if isinstance(v, Fn):
        k = tr.conc(item)
        if k is not None:
            if k not in v.vals:
                return v  # TLA+: EXCEPT outside the domain changes nothing
            return Fn(v.keys, {**v.vals, k: update(tr, v.vals[k], rest, new, loc)})
        return Fn(v.keys, {kk: ite(eq(item, key_value(kk, tr.strings), loc), update(tr, x, rest, new, loc), x, loc)
                           for kk, x in v.vals.items()})
    if isinstance(v, (Tup, SeqV)):
        k = tr.conc(item)
        items = list(v.items)
        if k is not None:
            if isinstance(k, int) and 1 <= k <= len(items):
                items[k - 1] = update(tr, items[k - 1], rest, new, loc)
        else:
            items = [ite(item == i + 1, update(tr, x, rest, new, loc), x, loc) for i, x in enumerate(items)]
        return Tup(tuple(items)) if isinstance(v, Tup) else SeqV(tuple(items), v.length)
    raise ProveError("EXCEPT on a value that is not a function or record", loc)


# ---------------------------------------------------------------- named operators

def apply_builtin(tr: "Translator", name: str, args: list[A.Expr], ctx: "Ctx", loc: Loc) -> Any:
    if name == "Nat":
        return NAT()
    if name == "Int":
        return INT()
    if name == "BOOLEAN":
        return boolean_set()
    if name == "STRING":
        return PredSet("STRING", lambda x: z3.BoolVal(is_z3(x) and x.sort() == tr.strings.sort),
                       lambda n: z3.Const(n, tr.strings.sort))
    if name == "Cardinality" and len(args) == 1 and isinstance(args[0], A.SetEnum) and len(args[0].elems) == 1:
        return z3.IntVal(1)  # a literal singleton: its element need not be translated
    if name == "SelectSeq":
        return select_seq(tr, tracked(tr.val(args[0], ctx), args[0].loc), args[1], ctx, loc)
    vals = [tracked(tr.val(a, ctx), a.loc) for a in args]
    if name == "Len":
        s = vals[0]
        if isinstance(s, Tup):
            return z3.IntVal(len(s.items))
        if isinstance(s, SeqV):
            return s.length
        raise ProveError("Len of a value that is not a sequence", loc)
    if name in ("Head", "Tail"):
        s = vals[0]
        if not isinstance(s, (Tup, SeqV)):
            raise ProveError(f"{name} of a value that is not a sequence", loc)
        tr.obl.add("sequence", loc, f"the sequence is not empty ({name})",
                   s.length > 0 if isinstance(s, SeqV) else bool(s.items))
        if not s.items:
            return UNDEF if name == "Head" else s
        if name == "Head":
            return s.items[0]
        if isinstance(s, Tup):
            return Tup(s.items[1:])
        return SeqV(s.items[1:] + (s.items[-1],), z3.If(s.length > 0, s.length - 1, 0))
    if name == "SubSeq":
        return subseq(tr, vals[0], vals[1], vals[2], loc)
    if name == "Append":
        s, x = vals
        if isinstance(s, Tup):
            return Tup(s.items + (x,))
        if isinstance(s, SeqV):
            items = tuple(ite(s.length == i, x, old, loc) for i, old in enumerate(s.items))
            return SeqV(items, s.length + 1)
        raise ProveError("Append to a value that is not a sequence", loc)
    if name == "\\o":
        return concat(vals[0], vals[1], loc)
    if name == "Seq":
        return seq_set(need_set(vals[0], "Seq", loc), loc)
    if name == "Cardinality":
        return cardinality(need_enum(vals[0], "Cardinality", loc), loc)
    if name == "IsFiniteSet":
        return z3.BoolVal(isinstance(vals[0], EnumSet))
    if name in (":>", "@@"):
        return _tlc_fn(tr, name, vals[0], vals[1], loc)
    if name in ("+", "-", "*", "\\div", "%", "<", ">", "<=", ">=", ".."):
        return _arith(tr, name, vals[0], vals[1], loc)
    if name == "-.":
        return -vals[0]
    raise ProveError(f"the standard operator {name}", loc)


def _tlc_fn(tr: "Translator", op: str, a: Any, b: Any, loc: Loc) -> Any:
    if op == ":>":
        k = tr.conc(a)
        if k is None:
            raise ProveError(":> with a symbolic key", loc)
        return Fn((k,), {k: b})
    if not (isinstance(a, Fn) and isinstance(b, Fn)):
        raise ProveError("@@ of values that are not functions", loc)
    keys = a.keys + tuple(k for k in b.keys if k not in a.vals)
    return Fn(keys, {**b.vals, **a.vals})


def _arith(tr: "Translator", op: str, a: Any, b: Any, loc: Loc) -> Any:
    if not (is_z3(a) and z3.is_int(a) and is_z3(b) and z3.is_int(b)):
        raise ProveError(f"{op} of values that are not integers", loc)
    if op == "+":
        return a + b
    if op == "-":
        return a - b
    if op == "*":
        return a * b
    if op in ("\\div", "%"):
        # TLA+ defines a \div b and a % b for b > 0 only (Integers); z3's Euclidean
        # division agrees with them there
        tr.obl.add("division", loc, f"the divisor of {op} is positive", b > 0)
        return a / b if op == "\\div" else a % b
    if op == "<":
        return a < b
    if op == ">":
        return a > b
    if op == "<=":
        return a <= b
    if op == ">=":
        return a >= b
    if op == "..":
        return interval(tr, a, b, loc)
    raise ProveError(f"operator {op}", loc)


def binary(tr: "Translator", e: A.Binary, ctx: "Ctx") -> Any:
    op = e.op
    if op == "=>":
        return tr.implies(e.lhs, e.rhs, ctx)
    if op in ("<=>", "\\equiv"):
        return tr.boolean(e.lhs, ctx) == tr.boolean(e.rhs, ctx)
    a = tr.val(e.lhs, ctx)
    b = tr.val(e.rhs, ctx)
    loc = e.loc
    if op in ("=", "/=", "#"):
        _only_assigned(tr, e, a, b, ctx)
    if op == "=":
        _oblige_capacity(tr, a, b, loc)
        _oblige_type(tr, a, b, loc)
        return eq(a, b, loc)
    if op in ("/=", "#"):
        return z3.Not(eq(a, b, loc))
    a, b = tracked(a, e.lhs.loc), tracked(b, e.rhs.loc)
    if op in (":>", "@@"):
        return _tlc_fn(tr, op, a, b, loc)
    if op == "\\in":
        _oblige_type_of_choice(tr, a, b, loc)
        return need_set(b, "\\in", loc).member(a, loc)
    if op == "\\notin":
        return z3.Not(need_set(b, "\\notin", loc).member(a, loc))
    if op == "\\cup":
        return union(need_set(a, op, loc), need_set(b, op, loc), loc)
    if op == "\\cap":
        return intersect(need_set(a, op, loc), need_set(b, op, loc), loc)
    if op == "\\":
        return difference(need_set(a, op, loc), need_set(b, op, loc), loc)
    if op == "\\subseteq":
        return subseteq(need_set(a, op, loc), need_set(b, op, loc), loc)
    if op in ("+", "-", "*", "\\div", "%", "<", ">", "<=", ">=", ".."):
        return _arith(tr, op, a, b, loc)
    if op == "\\o":
        return concat(a, b, loc)
    raise ProveError(f"the operator {op}", loc)


def subseq(tr: "Translator", s: Any, m: Any, n: Any, loc: Loc) -> Any:
    """SubSeq(s, m, n): << s[m], ..., s[n] >>, empty when m > n; needs 1 <= m and n <= Len(s) otherwise."""
    if not isinstance(s, (Tup, SeqV)):
        raise ProveError("SubSeq of a value that is not a sequence", loc)
    cm, cn = tr.conc(m), tr.conc(n)
    if not (isinstance(cm, int) and isinstance(cn, int)):
        raise ProveError("SubSeq with symbolic bounds", loc)
    length = s.length if isinstance(s, SeqV) else z3.IntVal(len(s.items))
    if cm > cn:
        return Tup(())
    tr.obl.add("sequence", loc, "SubSeq's bounds are inside the sequence (1 <= m, n <= Len)",
               z3.And(z3.BoolVal(cm >= 1), length >= cn))
    items = s.items[max(cm, 1) - 1:cn]
    if len(items) < cn - cm + 1:
        return UNDEF
    return Tup(tuple(items))


def concat(a: Any, b: Any, loc: Loc) -> Any:
    """a \\o b; with a symbolic length of a, slot j of the result is a[j] or b[j - Len(a)]."""
    if isinstance(a, Tup) and isinstance(b, Tup):
        return Tup(a.items + b.items)
    if not (isinstance(a, (Tup, SeqV)) and isinstance(b, (Tup, SeqV))):
        raise ProveError("\\o of values that are not sequences", loc)
    sa, sb = as_seq(a), as_seq(b)
    if not sb.items:
        return a
    if not sa.items:
        return b
    items = []
    for j in range(sa.cap + sb.cap):
        from_b = _select([(sa.length == j - i, x) for i, x in enumerate(sb.items) if 0 <= j - i <= sa.cap], loc)
        items.append(ite(sa.length > j, sa.items[j], from_b, loc) if j < sa.cap else from_b)
    return SeqV(tuple(items), sa.length + sb.length)


def select_seq(tr: "Translator", s: Any, test: A.Expr, ctx: "Ctx", loc: Loc) -> Any:
    """SelectSeq(s, LAMBDA x : P(x)): the elements satisfying P, in order; slot j of the
    result is the element with j elements before it satisfying P."""
    if not isinstance(s, (Tup, SeqV)):
        raise ProveError("SelectSeq of a value that is not a sequence", loc)
    keep = _test_of(tr, test, ctx, loc)
    sq = as_seq(s)
    guards = []
    for i, x in enumerate(sq.items):
        inside = sq.length > i
        with tr.obl.under(inside):
            guards.append(_s(z3.And(inside, keep(x))))
    if isinstance(s, Tup) and all(z3.is_true(g) or z3.is_false(g) for g in guards):
        return Tup(tuple(x for g, x in zip(guards, sq.items) if z3.is_true(g)))
    before: list[z3.ArithRef] = []  # how many kept elements precede element i
    count: z3.ArithRef = z3.IntVal(0)
    for g in guards:
        before.append(count)
        count = _s(count + z3.If(g, 1, 0))
    items = []
    for j in range(len(sq.items)):
        cases = [(z3.And(g, before[i] == j), x) for i, (g, x) in enumerate(zip(guards, sq.items)) if i >= j]
        items.append(_select(cases, loc))
    return SeqV(tuple(items), count)


def _test_of(tr: "Translator", test: A.Expr, ctx: "Ctx", loc: Loc) -> Callable[[Any], z3.BoolRef]:
    """The one-argument predicate of SelectSeq: a LAMBDA, or the name of an operator."""
    from ..tla.modules import DefSym
    if isinstance(test, A.Lambda):
        if len(test.params) != 1:
            raise ProveError("the test of SelectSeq takes one argument", test.loc)
        return lambda x: tr.boolean(test.body, ctx.bind({test.params[0]: x}))
    if isinstance(test, A.OpRef) or isinstance(test, A.Name):
        sym = ctx.scope.lookup(test.name)
        if isinstance(sym, DefSym) and len(sym.defn.params) == 1 and not sym.recursive:
            from .translate import Ctx
            return lambda x: tr.boolean(sym.defn.body, Ctx(sym.scope, {sym.defn.params[0].name: x}, ctx.primed))
    raise ProveError("the test of SelectSeq must be a LAMBDA or a one-argument operator", loc)


def _oblige_type(tr: "Translator", a: Any, b: Any, loc: Loc) -> None:
    """x = e in Init, x' = e in Next, x structured: e must lie in x's TypeOK domain, the
    only values the translation can give x; outside it the step would disappear, and a
    TypeOK violation with it (reported as a failing 'type' obligation)."""
    if not tr.type_targets:
        return
    for var, other in ((a, b), (b, a)):
        hit = tr.type_targets.get(id(var))
        if hit is not None and tr.type_targets.get(id(other)) is None:
            name, domain = hit
            tr.obl.add("type", loc, f"the value given to {name} is in its {tr.type_invariant} domain",
                       domain.member(other, loc))


def _only_assigned(tr: "Translator", e: A.Binary, a: Any, b: Any, ctx: "Ctx") -> None:
    """An untracked variable (TypeOK does not type it) may only be assigned: `x = e` in
    Init, `x' = e` in Next.  Its value stands for any value, so `eq` makes such an
    assignment TRUE (it is dropped, and so is the value assigned); anywhere else -- an
    invariant, a guard, `#`, a tracked variable assigned from it -- that TRUE would be a
    silent wrong answer (an invariant `x = e` would hold in every state), so reading it
    is refused."""
    if e.op == "=" and any(v is UNTRACKED and _is_assigned_variable(tr, side, ctx)
                           for side, v in ((e.lhs, a), (e.rhs, b))):
        return  # the assigned value goes nowhere, whatever it reads
    for side, v in ((e.lhs, a), (e.rhs, b)):
        if _has_untracked(v):
            tracked(UNTRACKED, side.loc)


def _is_assigned_variable(tr: "Translator", x: A.Expr, ctx: "Ctx") -> bool:
    """Is `x` the variable an Init (unprimed) or Next (primed) conjunct assigns?"""
    if not tr.assigning:
        return False
    primed = ctx.primed
    if isinstance(x, A.Prime):
        x, primed = x.arg, True
    return isinstance(x, A.Name) and primed == tr.assigning_next


def _has_untracked(v: Any) -> bool:
    if v is UNTRACKED:
        return True
    if isinstance(v, Rec):
        return any(_has_untracked(x) for x in v.fields.values())
    if isinstance(v, (Tup, SeqV)):
        return any(_has_untracked(x) for x in v.items)
    if isinstance(v, Fn):
        return any(_has_untracked(x) for x in v.vals.values())
    return False


def _oblige_type_of_choice(tr: "Translator", a: Any, b: Any, loc: Loc) -> None:
    """x' \\in S (x \\in S in Init), x structured, S enumerable: every element of S must lie
    in x's TypeOK domain (a non-enumerable S is bounded by the domain itself)."""
    hit = tr.type_targets.get(id(a)) if tr.type_targets else None
    if hit is None or not isinstance(b, EnumSet):
        return
    name, domain = hit
    tr.obl.add("type", loc, f"every value {name} may take is in its {tr.type_invariant} domain",
               z3.And([z3.Implies(g, domain.member(x, loc)) for g, x in b.items]))


def _oblige_capacity(tr: "Translator", a: Any, b: Any, loc: Loc) -> None:
    """x = e (or x' = e) in Init or Next, x a bounded sequence variable: e must fit in the
    bound Len(x) <= N of TypeOK; a longer e would make the step disappear, not fail."""
    if not tr.assigning:
        return
    for var, other in ((a, b), (b, a)):
        if isinstance(var, SeqV) and isinstance(other, (SeqV, Tup)) and tr.is_variable_value(var):
            o = as_seq(other)
            if o.cap > var.cap:
                tr.obl.add("capacity", loc, f"the sequence fits the bound Len <= {var.cap} of TypeOK",
                           o.length <= var.cap)
