"""Which ``ToString`` the native core may print itself.

The core prints every value as TLC does (`values.fmt`), but it keeps a set only by its
elements, so ``1..3`` and ``{1, 2, 3}`` are one value there while TLC (and the Python
engine) print them as ``1..3`` and ``{1, 2, 3}``; a set of records ``[a : S]`` likewise.
So the translation works out, for every node of the program tree, whether its value may
be such a set (`SELF`) or hold one at any depth (`INNER`) -- over the variables and
bound names as a fixpoint of what is assigned or bound to them -- and a ``ToString`` of
an argument that may is refused: the Python engine prints it.
"""

from __future__ import annotations

from typing import Any, Iterable

from ...tla.values import FnValue, IntervalSet, LazySet
from .ops import Op

Node = tuple

SELF, INNER = 1, 2
_BOTH = SELF | INNER

# Ops whose value is a boolean or an integer (or a string ToString made).
_SCALAR = frozenset((Op.NOT, Op.NEG, Op.AND, Op.OR, Op.IMPLIES, Op.EQUIV, Op.EQ, Op.NEQ, Op.LT, Op.LE, Op.GT, Op.GE,
                     Op.ADD, Op.SUB, Op.MUL, Op.DIV, Op.MOD, Op.IN, Op.NOTIN, Op.SUBSETEQ, Op.FORALL, Op.EXISTS,
                     Op.IN_SD, Op.LEN, Op.CARD, Op.TOSTRING))
# Ops building a container of their operands' values (never a set printed as a rule).
_CONTAINER = frozenset((Op.SETENUM, Op.RECLIT, Op.TUPLE, Op.EXCEPT, Op.TAIL, Op.APPEND, Op.CONCAT, Op.SUBSEQ,
                        Op.SELECTSEQ, Op.CAP, Op.DIFF))
# Ops binding slots to elements of their set operands (ints[i] to kids[i]).
_ELEMENT_BINDERS = frozenset((Op.FORALL, Op.EXISTS, Op.SETFILTER, Op.CHOOSE, Op.FNLIT, Op.SELECTSEQ, Op.SETMAP,
                              Op.A_EXISTS))
_VALUE_BINDERS = frozenset((Op.BIND, Op.BIND_MEMO, Op.A_BIND, Op.LETREF))


def value_flags(v: Any) -> int:
    """SELF / INNER of a Python value (a constant of the model)."""
    if isinstance(v, IntervalSet):
        return SELF if v.lo <= v.hi else 0
    if isinstance(v, LazySet):
        return _BOTH
    if isinstance(v, frozenset | tuple):
        return INNER if any(value_flags(x) for x in v) else 0
    if isinstance(v, FnValue):
        return INNER if any(value_flags(k) or value_flags(x) for k, x in v.d.items()) else 0
    return 0


def _element(f: int) -> int:
    """An element (or a function's value) of a value with flags f."""
    return _BOTH if f & INNER else 0


class _Analysis:
    def __init__(self, const_flags: dict[int, int], nvars: int) -> None:
        self.const_flags = const_flags
        self.var = [0] * nvars
        self.slot: dict[int, int] = {}
        self.var_sources: list[tuple[int, Node, bool]] = []  # (variable, node, an element of it?)
        self.slot_sources: list[tuple[int, Node, bool]] = []
        self.to_string: list[Node] = []
        self._memo: dict[int, int] = {}

    def collect(self, roots: Iterable[Node | None]) -> None:
        seen: set[int] = set()
        stack = [r for r in roots if r is not None]
        while stack:
            n = stack.pop()
            if id(n) in seen:
                continue
            seen.add(id(n))
            op, ints, kids = n[0], n[2], n[4]
            if op in _ELEMENT_BINDERS:
                sets = kids[:len(ints)] if op in (Op.SETMAP, Op.A_EXISTS) else kids[:1]
                self.slot_sources += [(s, k, True) for s, k in zip(ints, sets)]
            elif op in _VALUE_BINDERS:
                self.slot_sources += [(s, k, False) for s, k in zip(ints, kids)]
            elif op == Op.A_FORALL:
                self.slot_sources += [(s, k, True) for s, k in zip(ints[3:], kids)]
            elif op == Op.EXCEPT:
                self.slot_sources.append((ints[0], kids[0], True))  # @: a value inside the base
            elif op in (Op.A_ASSIGN, Op.A_ASSIGN_IN):
                self.var_sources.append((ints[0], kids[0], op == Op.A_ASSIGN_IN))
            elif op == Op.TOSTRING:
                self.to_string.append(n)
            stack += [k for k in kids if k is not None]
            if n[5] is not None:
                stack.append(n[5])

    def solve(self) -> None:
        while True:
            self._memo = {}
            var, slot = list(self.var), dict(self.slot)
            for i, node, elem in self.var_sources:
                f = self.flags(node)
                var[i] |= _element(f) if elem else f
            for s, node, elem in self.slot_sources:
                f = self.flags(node)
                slot[s] = slot.get(s, 0) | (_element(f) if elem else f)
            if var == self.var and slot == self.slot:
                return
            self.var, self.slot = var, slot

    def flags(self, n: Node) -> int:
        got = self._memo.get(id(n))
        if got is None:
            got = self._memo[id(n)] = self._flags(n)
        return got

    def _flags(self, n: Node) -> int:
        op, ints, kids = n[0], n[2], n[4]
        if op == Op.CONST:
            return self.const_flags.get(id(n), 0)
        if op in (Op.VAR, Op.PVAR):
            return self.var[ints[0]]
        if op in (Op.SLOT, Op.AT):
            return self.slot.get(ints[0], 0)
        if op in _SCALAR:
            return 0
        if op in (Op.LETREF, Op.LET):
            return self.flags(kids[0])
        if op in (Op.BIND, Op.BIND_MEMO):
            return self.flags(kids[-1])
        if op in _CONTAINER:
            return INNER if any(self.flags(k) for k in kids) else 0
        if op == Op.RANGE:
            return SELF
        if op in (Op.DOMAIN, Op.RECSET, Op.POWERSET, Op.PRODUCT, Op.FNSET):
            return SELF | (INNER if any(self.flags(k) & INNER for k in kids) else 0)
        if op in (Op.CUP, Op.SETFILTER, Op.IF, Op.CASE):
            # \cup may be one operand itself ({} \cup 1..2 is 1..2); a filter conservatively
            # keeps its base's form.
            return self.flags(kids[0]) | self.flags(kids[1]) if op == Op.CUP else \
                self.flags(kids[0]) if op == Op.SETFILTER else \
                _union(self.flags(k) for k in (kids[1:] if op == Op.IF else kids))
        if op == Op.SETMAP:
            return INNER if self.flags(kids[-1]) else 0
        if op == Op.FNLIT:
            return INNER if self.flags(kids[1]) or self.flags(kids[0]) & INNER else 0
        if op in (Op.FNAPP, Op.HEAD, Op.CHOOSE):
            return _element(self.flags(kids[0]))
        return _BOTH  # anything else: it may


def _union(fs: Iterable[int]) -> int:
    out = 0
    for f in fs:
        out |= f
    return out


def lazily_printed(const_flags: dict[int, int], nvars: int, roots: Iterable[Node | None]) -> tuple[list[Node], bool]:
    """The ToString nodes under `roots` whose argument may be, or hold, a set TLC prints
    as a rule (``1..3``, ``[a : S]``), and whether a variable may hold one (then a
    trace's states are printed from the Python engine's values, `search._trace`)."""
    a = _Analysis(const_flags, nvars)
    a.collect(roots)
    a.solve()
    return [n for n in a.to_string if a.flags(n[4][0])], any(a.var)
