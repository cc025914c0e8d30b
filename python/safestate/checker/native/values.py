"""Python TLA+ values (`tla/values.py`) to the native core's interned ids and back."""

from __future__ import annotations

from typing import Any

from ...tla.errors import Loc, UnsupportedError
from ...tla.values import FnValue, IntervalSet, LazySet, ModelValue, Value, make_fn, string_rank

NOT_NATIVE = "not supported by the native engine"

# Kinds as the C++ core numbers them (enum Kind).
_BOOL, _INT, _STR, _MV, _SEQ, _FUN, _SET = range(7)
# Ids the core gives without interning (Store: kFalse, kTrue, kIntTag).
_FALSE, _TRUE, _INT_TAG = 0, 1, 0x80000000


def known_string_ranks() -> dict[str, int]:
    """The ranks of the strings named so far (the spec's, in TLC's order), for a string
    the core makes while checking (ToString)."""
    from ...tla import values
    return dict(values._STRING_RANK)


def _step_error() -> type[Exception]:
    from ... import _tla_native  # type: ignore[attr-defined]
    return _tla_native.StepError  # type: ignore[no-any-return]


class ValueBridge:
    def __init__(self, engine: Any) -> None:
        self.engine = engine
        self._back: dict[int, Value] = {}
        self._strings: dict[str, int] = {}  # the core interns them: each is looked up once

    def to_native(self, v: Value, loc: Loc) -> int:
        e = self.engine
        t = type(v)
        if t is bool:
            return _TRUE if v else _FALSE
        if t is int:
            if not -(1 << 30) <= v < (1 << 30):
                raise UnsupportedError(f"the integer {v} is {NOT_NATIVE} (31-bit integers only)", loc)
            return _INT_TAG | (v + (1 << 30))  # tagged inline, as Store::mk_int
        if t is str:
            vid = self._strings.get(v)  # type: ignore[call-overload]
            if vid is None:
                vid = self._strings[v] = e.mk_str(v, string_rank(v))  # type: ignore[index]
            return vid
        if t is ModelValue:
            return e.mk_model_value(v.name, string_rank(v.name))
        if t is tuple:
            return e.mk_seq([self.to_native(x, loc) for x in v])
        if t is FnValue:
            keys = list(v.d)
            try:
                return e.mk_fun([self.to_native(k, loc) for k in keys], [self.to_native(v.d[k], loc) for k in keys])
            except _step_error() as err:
                raise UnsupportedError(f"a function whose keys are of incomparable kinds is {NOT_NATIVE}", loc) from err
        if t is frozenset or isinstance(v, IntervalSet):
            elems = v if t is frozenset else range(v.lo, v.hi + 1)
            try:
                return e.mk_set([self.to_native(x, loc) for x in elems])
            except _step_error() as err:
                # The core sorts as TLC: a set of elements it cannot compare.
                raise UnsupportedError(f"a set of values of incomparable kinds is {NOT_NATIVE}", loc) from err
        what = v.describe() if isinstance(v, LazySet) else t.__name__
        raise UnsupportedError(f"the value {what} is {NOT_NATIVE}", loc)

    def to_python(self, vid: int) -> Value:
        v = self._back.get(vid)
        if v is None:
            kind, payload = self.engine.describe(vid)
            if kind in (_BOOL, _INT, _STR):
                v = payload
            elif kind == _MV:
                v = ModelValue(payload)
            elif kind == _SEQ:
                v = tuple(self.to_python(x) for x in payload)
            elif kind == _FUN:
                n = len(payload) // 2
                v = make_fn({self.to_python(payload[i]): self.to_python(payload[n + i]) for i in range(n)})
            else:
                v = frozenset(self.to_python(x) for x in payload)
            self._back[vid] = v
        return v

    def state(self, ids: list[int]) -> tuple:
        return tuple(self.to_python(x) for x in ids)
