"""Symbolic TLA+ values: the shapes a TLA+ value takes once translated to z3.

A value is either a z3 term (Bool, Int, or the enumeration sort of the model's
strings) or a Python structure whose leaves are z3 terms:

- `Rec`: a record with a fixed set of fields;
- `Tup`: a tuple (a sequence of statically known length);
- `SeqV`: a bounded sequence, `cap` element slots and a symbolic length;
- `Fn`: a function over a finite, concrete domain;
- `Untracked`: a state variable that no TypeOK conjunct types and nothing reads.

Sets live in `sets.py`.  Structures are compared and merged field by field, so
z3 only ever sees first-order terms over Bool, Int and the string sort.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any, Callable

import z3
from z3 import z3core as C
from z3.z3types import Ast

from ..tla.errors import Loc, UnsupportedError

Key = Any  # a concrete key of a function domain: int, str, bool, or a tuple of keys


class ProveError(UnsupportedError):
    """A construct outside the translatable subset, with its source position."""

    def __init__(self, message: str, loc: Loc | None = None) -> None:
        super().__init__(f"unsupported in proofs: {message}", loc)


@dataclass(frozen=True, slots=True, eq=False)
class Rec:
    fields: dict[str, Any]


@dataclass(frozen=True, slots=True, eq=False)
class Tup:
    items: tuple[Any, ...]


@dataclass(frozen=True, slots=True, eq=False)
class SeqV:
    items: tuple[Any, ...]  # `cap` slots; only those below `length` are meaningful
    length: z3.ArithRef

    @property
    def cap(self) -> int:
        return len(self.items)


@dataclass(frozen=True, slots=True, eq=False)
class Fn:
    keys: tuple[Key, ...]
    vals: dict[Key, Any]


class _Untracked:
    def __repr__(self) -> str:
        return "<untracked>"


UNTRACKED = _Untracked()


class _Undefined:
    """The value of an expression TLA+ leaves unspecified (a record without the field, Head
    of << >>): its well-definedness obligation fails wherever it is evaluated, so any
    value will do; comparisons with it are FALSE and IF picks the other branch."""

    def __repr__(self) -> str:
        return "<undefined>"


UNDEF = _Undefined()


class Strings:
    """The finite enumeration standing for the model's string literals."""

    def __init__(self, names: list[str], tag: str) -> None:
        names = sorted(set(names)) or ["<none>"]
        self.sort, consts = z3.EnumSort(f"Str{tag}", [f'"{n}"' for n in names])
        self.by_name: dict[str, z3.ExprRef] = dict(zip(names, consts))
        self.by_decl: dict[str, str] = {str(c): n for n, c in self.by_name.items()}

    def val(self, s: str, loc: Loc | None = None) -> z3.ExprRef:
        v = self.by_name.get(s)
        if v is None:
            raise ProveError(f"string {s!r} is not a literal of the model", loc)
        return v


def tracked(v: Any, loc: Loc | None) -> Any:
    """`v`, unless it is an untracked variable (which may be assigned, never read)."""
    if v is UNTRACKED:
        raise ProveError("a variable that TypeOK does not type is read here (add a conjunct x \\in S to TypeOK)",
                         loc)
    return v


def is_z3(v: Any) -> bool:
    return isinstance(v, z3.ExprRef)


def concrete(v: Any, strings: Strings) -> Any:
    """The Python value of a fully concrete value, or None when it is symbolic."""
    if is_z3(v):
        if z3.is_true(v):
            return True
        if z3.is_false(v):
            return False
        if z3.is_int_value(v):
            return v.as_long()
        if z3.is_const(v) and v.sort() == strings.sort and str(v) in strings.by_decl:
            return strings.by_decl[str(v)]
        s = z3.simplify(v)
        if s.eq(v):
            return None
        return concrete(s, strings)
    if isinstance(v, Tup):
        items = [concrete(x, strings) for x in v.items]
        return None if any(x is None for x in items) else tuple(items)
    return None


def key_value(k: Key, strings: Strings) -> Any:
    """The symbolic value of a concrete domain key."""
    if isinstance(k, bool):
        return z3.BoolVal(k)
    if isinstance(k, int):
        return z3.IntVal(k)
    if isinstance(k, str):
        return strings.val(k)
    if isinstance(k, tuple):
        return Tup(tuple(key_value(x, strings) for x in k))
    raise ProveError(f"domain element {k!r} of unsupported kind")


_VALUE_KINDS = (C.Z3_OP_ANUM, C.Z3_OP_DT_CONSTRUCTOR, C.Z3_OP_TRUE, C.Z3_OP_FALSE)


def value_key(v: Any) -> tuple[Any, Any] | None:
    """(shape, identity) of a fully concrete value: two values of the same shape are
    equal (`eq` is TRUE) exactly when their identities are (z3 shares equal terms, so a
    concrete leaf is known by its id; the shape gives each leaf's sort).  None when some
    leaf is symbolic, or for a set, sequence or function (compared otherwise)."""
    if isinstance(v, z3.ExprRef):
        ctx, a = v.ctx.ref(), v.as_ast()
        if C.Z3_get_ast_kind(ctx, a) != C.Z3_APP_AST or C.Z3_get_app_num_args(ctx, a) != 0:
            return None
        if C.Z3_get_decl_kind(ctx, C.Z3_get_app_decl(ctx, a)) not in _VALUE_KINDS:
            return None
        return C.Z3_get_ast_id(ctx, C.Z3_sort_to_ast(ctx, C.Z3_get_sort(ctx, a))), C.Z3_get_ast_id(ctx, a)
    if isinstance(v, (Rec, Tup)):
        names = sorted(v.fields) if isinstance(v, Rec) else range(len(v.items))
        parts = [value_key(v.fields[f] if isinstance(v, Rec) else v.items[f]) for f in names]  # type: ignore[index]
        if any(p is None for p in parts):
            return None
        shape = tuple(p[0] for p in parts)  # type: ignore[index]
        ident = tuple(p[1] for p in parts)  # type: ignore[index]
        return (("rec", tuple(names), shape) if isinstance(v, Rec) else ("tup", shape)), ident
    return None


def and_(fs: list[z3.BoolRef]) -> z3.BoolRef:
    """z3.And(fs) through the C API (z3py's coerces and sort-checks every argument), with
    the TRUE conjuncts left out and FALSE when one is FALSE."""
    keep = []
    for f in fs:
        if z3.is_false(f):
            return f
        if not z3.is_true(f):
            keep.append(f)
    if len(keep) <= 1:
        return keep[0] if keep else z3.BoolVal(True, fs[0].ctx if fs else None)
    args = (Ast * len(keep))(*(f.as_ast() for f in keep))
    return z3.BoolRef(C.Z3_mk_and(keep[0].ctx.ref(), len(keep), args), keep[0].ctx)


def or_(fs: list[z3.BoolRef]) -> z3.BoolRef:
    """z3.Or(fs) likewise: the FALSE disjuncts left out, TRUE when one is TRUE."""
    keep = []
    for f in fs:
        if z3.is_true(f):
            return f
        if not z3.is_false(f):
            keep.append(f)
    if len(keep) <= 1:
        return keep[0] if keep else z3.BoolVal(False, fs[0].ctx if fs else None)
    args = (Ast * len(keep))(*(f.as_ast() for f in keep))
    return z3.BoolRef(C.Z3_mk_or(keep[0].ctx.ref(), len(keep), args), keep[0].ctx)


def eq(a: Any, b: Any, loc: Loc | None = None) -> z3.BoolRef:
    """TLA+ equality of two symbolic values of compatible shapes."""
    from .sets import SetV, set_eq
    if a is UNTRACKED or b is UNTRACKED:
        return z3.BoolVal(True)
    if a is UNDEF or b is UNDEF:
        return z3.BoolVal(False)
    if is_z3(a) and is_z3(b):
        if a.sort() != b.sort():
            raise ProveError(f"comparison of a {a.sort()} with a {b.sort()}", loc)
        return a == b
    if isinstance(a, Tup) and isinstance(b, Fn):
        a = tup_as_fn(a)
    if isinstance(b, Tup) and isinstance(a, Fn):
        b = tup_as_fn(b)
    if isinstance(a, Rec) and isinstance(b, Rec):
        if set(a.fields) != set(b.fields):
            return z3.BoolVal(False)
        return z3.And([eq(a.fields[f], b.fields[f], loc) for f in a.fields])
    if isinstance(a, Tup) and isinstance(b, Tup):
        if len(a.items) != len(b.items):
            return z3.BoolVal(False)
        return z3.And([eq(x, y, loc) for x, y in zip(a.items, b.items)])
    if isinstance(a, (SeqV, Tup)) and isinstance(b, (SeqV, Tup)):
        return _seq_eq(as_seq(a), as_seq(b), loc)
    if isinstance(a, Fn) and isinstance(b, Fn):
        if set(a.keys) != set(b.keys):
            return z3.BoolVal(False)
        return z3.And([eq(a.vals[k], b.vals[k], loc) for k in a.keys])
    if isinstance(a, SetV) and isinstance(b, SetV):
        return set_eq(a, b, loc)
    raise ProveError(f"comparison of values of different kinds ({kind(a)} and {kind(b)})", loc)


def _seq_eq(a: SeqV, b: SeqV, loc: Loc | None) -> z3.BoolRef:
    parts = [a.length == b.length]
    for i in range(min(a.cap, b.cap)):
        parts.append(z3.Implies(a.length > i, eq(a.items[i], b.items[i], loc)))
    # slots one side cannot hold: the other side's length must stay below them
    parts.append(a.length <= min(a.cap, b.cap) if a.cap > b.cap else b.length <= min(a.cap, b.cap))
    return z3.And(parts)


def as_seq(v: Any) -> SeqV:
    if isinstance(v, SeqV):
        return v
    return SeqV(tuple(v.items), z3.IntVal(len(v.items)))


def tup_as_fn(t: Tup) -> Fn:
    keys = tuple(range(1, len(t.items) + 1))
    return Fn(keys, {k: t.items[k - 1] for k in keys})


def kind(v: Any) -> str:
    from .sets import SetV
    if is_z3(v):
        return str(v.sort())
    if isinstance(v, Rec):
        return "record"
    if isinstance(v, Tup):
        return "tuple"
    if isinstance(v, SeqV):
        return "sequence"
    if isinstance(v, Fn):
        return "function"
    if isinstance(v, SetV):
        return "set"
    return type(v).__name__


def ite(c: z3.BoolRef, a: Any, b: Any, loc: Loc | None = None) -> Any:
    """IF c THEN a ELSE b, merged leaf by leaf."""
    from .sets import SetV, set_ite
    if z3.is_true(c):
        return a
    if z3.is_false(c):
        return b
    if a is b:
        return a
    if a is UNTRACKED or b is UNTRACKED:
        return UNTRACKED
    if a is UNDEF or b is UNDEF:
        return b if a is UNDEF else a
    if is_z3(a) and is_z3(b):
        if a.sort() != b.sort():
            raise ProveError(f"IF/CASE branches of different types ({a.sort()} and {b.sort()})", loc)
        if a.eq(b):
            return a
        return z3.If(c, a, b)
    if isinstance(a, Rec) and isinstance(b, Rec):
        if set(a.fields) != set(b.fields):
            raise ProveError("IF/CASE branches are records with different fields", loc)
        return Rec({f: ite(c, a.fields[f], b.fields[f], loc) for f in a.fields})
    if isinstance(a, Tup) and isinstance(b, Tup) and len(a.items) == len(b.items):
        return Tup(tuple(ite(c, x, y, loc) for x, y in zip(a.items, b.items)))
    if isinstance(a, (SeqV, Tup)) and isinstance(b, (SeqV, Tup)):
        sa, sb = as_seq(a), as_seq(b)
        cap = max(sa.cap, sb.cap)
        if not sa.items or not sb.items:  # << >>: its slots are irrelevant, borrow the other's
            sa = SeqV(sb.items, sa.length) if not sa.items else sa
            sb = SeqV(sa.items, sb.length) if not sb.items else sb
        sa, sb = pad(sa, cap, loc), pad(sb, cap, loc)
        return SeqV(tuple(ite(c, x, y, loc) for x, y in zip(sa.items, sb.items)), z3.If(c, sa.length, sb.length))
    if isinstance(a, Fn) and isinstance(b, Fn):
        if set(a.keys) != set(b.keys):
            raise ProveError("IF/CASE branches are functions with different domains", loc)
        return Fn(a.keys, {k: ite(c, a.vals[k], b.vals[k], loc) for k in a.keys})
    if isinstance(a, SetV) and isinstance(b, SetV):
        return set_ite(c, a, b, loc)
    raise ProveError(f"IF/CASE branches of different kinds ({kind(a)} and {kind(b)})", loc)


def pad(s: SeqV, cap: int, loc: Loc | None = None) -> SeqV:
    """`s` with `cap` slots (new slots repeat the last one: their content is irrelevant);
    `loc` is the IF/CASE whose branches need the common width."""
    if s.cap >= cap:
        return s
    if s.cap == 0:
        raise ProveError("cannot widen an empty sequence literal to a bounded sequence without a shape "
                         "(the other branch of this IF/CASE is a non-empty sequence)", loc)
    return SeqV(s.items + (s.items[-1],) * (cap - s.cap), s.length)


def fresh_like(v: Any, name: str) -> Any:
    """A value of the same shape as `v` whose leaves are fresh z3 constants."""
    from .sets import SetV
    if is_z3(v):
        return z3.Const(name, v.sort())
    if isinstance(v, Rec):
        return Rec({f: fresh_like(x, f"{name}.{f}") for f, x in v.fields.items()})
    if isinstance(v, Tup):
        return Tup(tuple(fresh_like(x, f"{name}[{i + 1}]") for i, x in enumerate(v.items)))
    if isinstance(v, SeqV):
        return SeqV(tuple(fresh_like(x, f"{name}[{i + 1}]") for i, x in enumerate(v.items)),
                    z3.Int(f"{name}.len"))
    if isinstance(v, Fn):
        return Fn(v.keys, {k: fresh_like(x, f"{name}[{_kname(k)}]") for k, x in v.vals.items()})
    if v is UNTRACKED:
        return v
    if isinstance(v, SetV):
        raise ProveError("a set-valued variable or bound (sets of sets are not translated)")
    raise ProveError(f"cannot build a symbolic value shaped like {kind(v)}")


def _kname(k: Key) -> str:
    if isinstance(k, str):
        return f'"{k}"'
    if isinstance(k, tuple):
        return "<<" + ",".join(_kname(x) for x in k) + ">>"
    return str(k).upper() if isinstance(k, bool) else str(k)


def leaves(v: Any) -> list[z3.ExprRef]:
    """The z3 terms at the leaves of a value, in a fixed order."""
    if is_z3(v):
        return [v]
    if isinstance(v, Rec):  # sorted: records built by literals list their fields in any order
        return [x for f in sorted(v.fields) for x in leaves(v.fields[f])]
    if isinstance(v, Tup):
        return [x for i in v.items for x in leaves(i)]
    if isinstance(v, SeqV):
        return [v.length] + [x for i in v.items for x in leaves(i)]
    if isinstance(v, Fn):
        return [x for k in v.keys for x in leaves(v.vals[k])]
    from .sets import EnumSet
    if isinstance(v, EnumSet):  # a set-valued variable: one membership Boolean per candidate element
        return [g for g, _ in v.items]
    return []


def evaluate(v: Any, ev: Callable[[z3.ExprRef], z3.ExprRef], strings: Strings) -> Any:
    """The concrete Python value of `v` under a model (`ev` evaluates a z3 term).

    Records become dicts, tuples and sequences Python tuples, functions dicts.
    """
    if is_z3(v):
        r = ev(v)
        c = concrete(r, strings)
        return c if c is not None else str(r)
    if isinstance(v, Rec):
        return {f: evaluate(x, ev, strings) for f, x in v.fields.items()}
    if isinstance(v, Tup):
        return tuple(evaluate(x, ev, strings) for x in v.items)
    if isinstance(v, SeqV):
        n = concrete(ev(v.length), strings)
        n = max(0, min(int(n or 0), v.cap))
        return tuple(evaluate(x, ev, strings) for x in v.items[:n])
    if isinstance(v, Fn):
        return FnDict({k: evaluate(v.vals[k], ev, strings) for k in v.keys})
    from .sets import EnumSet
    if isinstance(v, EnumSet):
        return frozenset(_hashable(evaluate(x, ev, strings)) for g, x in v.items if z3.is_true(ev(g)))
    return None


def _hashable(v: Any) -> Any:
    if isinstance(v, FnDict):
        return FrozenFn(v)
    if isinstance(v, dict):
        return FrozenRec(v)
    return v


class FrozenRec(dict):
    """A record inside a set (hashable)."""

    def __hash__(self) -> int:  # type: ignore[override]
        return hash(tuple(sorted(self.items(), key=repr)))


class FrozenFn(FrozenRec):
    """A function inside a set (hashable)."""


class FnDict(dict):
    """A concrete function value (a record evaluates to a plain dict)."""
