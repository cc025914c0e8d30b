"""Typed abstract syntax of the supported TLA+ subset.

This is the stable AST other tools (the z3 prover) translate: `Module` holds the
declarations and definitions of one module in source order; expressions are the
`Expr` subclasses below.  Operator symbols are kept in their ASCII spelling
(``"+"``, ``"\\in"``, ``"=>"``...), whatever Unicode form the source used.
Every node has a `loc` (file, line, column) for error reporting.
"""

from __future__ import annotations

from dataclasses import dataclass, field

from .errors import Loc


@dataclass(slots=True, eq=False)
class Expr:
    loc: Loc


@dataclass(slots=True, eq=False)
class Num(Expr):
    value: int


@dataclass(slots=True, eq=False)
class Str(Expr):
    value: str


@dataclass(slots=True, eq=False)
class Bool(Expr):
    value: bool


@dataclass(slots=True, eq=False)
class Name(Expr):
    """A reference to a declared or defined identifier (also Nat, Int, STRING, BOOLEAN)."""

    name: str


@dataclass(slots=True, eq=False)
class Apply(Expr):
    """Application of a named operator: ``Op(a, b)``, or a user-defined infix/prefix symbol."""

    name: str
    args: list[Expr]


@dataclass(slots=True, eq=False)
class InstanceStep:
    """One ``M`` or ``M(args)`` component of a ``M!N!Op`` reference."""

    name: str
    args: list[Expr]


@dataclass(slots=True, eq=False)
class Prefixed(Expr):
    """``M!Op(args)``: an operator of a named instance."""

    path: list[InstanceStep]
    name: str
    args: list[Expr]


@dataclass(slots=True, eq=False)
class OpRef(Expr):
    """A built-in or user operator symbol passed as an argument, e.g. ``Fold(+, ...)``."""

    name: str


@dataclass(slots=True, eq=False)
class Lambda(Expr):
    params: list[str]
    body: Expr


@dataclass(slots=True, eq=False)
class Binary(Expr):
    op: str
    lhs: Expr
    rhs: Expr


@dataclass(slots=True, eq=False)
class Unary(Expr):
    """Prefix operators: ``~ - SUBSET UNION DOMAIN ENABLED UNCHANGED [] <>``."""

    op: str
    arg: Expr


@dataclass(slots=True, eq=False)
class Prime(Expr):
    arg: Expr


@dataclass(slots=True, eq=False)
class And(Expr):
    items: list[Expr]


@dataclass(slots=True, eq=False)
class Or(Expr):
    items: list[Expr]


@dataclass(slots=True, eq=False)
class Bound:
    """``x, y \\in S`` (names, tuple=False) or ``<<x, y>> \\in S`` (tuple=True)."""

    names: list[str]
    tuple: bool
    set: Expr


@dataclass(slots=True, eq=False)
class Quant(Expr):
    """Bounded ``\\A`` / ``\\E``."""

    kind: str
    bounds: list[Bound]
    body: Expr


@dataclass(slots=True, eq=False)
class UnboundedQuant(Expr):
    kind: str
    names: list[str]
    body: Expr


@dataclass(slots=True, eq=False)
class Choose(Expr):
    names: list[str]
    tuple: bool
    set: Expr | None
    body: Expr


@dataclass(slots=True, eq=False)
class SetEnum(Expr):
    elems: list[Expr]


@dataclass(slots=True, eq=False)
class SetFilter(Expr):
    bound: Bound
    pred: Expr


@dataclass(slots=True, eq=False)
class SetMap(Expr):
    expr: Expr
    bounds: list[Bound]


@dataclass(slots=True, eq=False)
class FnApp(Expr):
    fn: Expr
    args: list[Expr]


@dataclass(slots=True, eq=False)
class FnLit(Expr):
    bounds: list[Bound]
    body: Expr


@dataclass(slots=True, eq=False)
class FnSet(Expr):
    domain: Expr
    range: Expr


@dataclass(slots=True, eq=False)
class RecLit(Expr):
    fields: list[tuple[str, Expr]]


@dataclass(slots=True, eq=False)
class RecSet(Expr):
    fields: list[tuple[str, Expr]]


@dataclass(slots=True, eq=False)
class Dot(Expr):
    rec: Expr
    field: str


@dataclass(slots=True, eq=False)
class ExceptUpdate:
    """``!.a[i] = v``: path items are ``("field", name)`` or ``("index", [exprs])``."""

    path: list[tuple[str, object]]
    value: Expr


@dataclass(slots=True, eq=False)
class Except(Expr):
    base: Expr
    updates: list[ExceptUpdate]


@dataclass(slots=True, eq=False)
class At(Expr):
    """``@`` inside an EXCEPT update."""


@dataclass(slots=True, eq=False)
class TupleLit(Expr):
    elems: list[Expr]


@dataclass(slots=True, eq=False)
class If(Expr):
    cond: Expr
    then: Expr
    other: Expr


@dataclass(slots=True, eq=False)
class Case(Expr):
    arms: list[tuple[Expr, Expr]]
    other: Expr | None


@dataclass(slots=True, eq=False)
class Let(Expr):
    defs: list["OpDef | InstanceDef"]
    body: Expr
    # Names of the LET's RECURSIVE declarations: only these may be used before (or
    # inside) their own definition.
    recursive: list[str] = field(default_factory=list)


@dataclass(slots=True, eq=False)
class StepAction(Expr):
    """``[A]_v`` (stutter=True) or ``<<A>>_v`` (stutter=False)."""

    action: Expr
    sub: Expr
    stutter: bool


@dataclass(slots=True, eq=False)
class Fairness(Expr):
    kind: str  # "WF" or "SF"
    sub: Expr
    action: Expr


@dataclass(slots=True, eq=False)
class Unsupported(Expr):
    """A parsed construct outside the subset; evaluating it raises `UnsupportedError`."""

    what: str


# ---------------------------------------------------------------- declarations


@dataclass(slots=True, eq=False)
class Param:
    """An operator parameter or CONSTANT declaration; arity > 0 for ``F(_, _)``."""

    name: str
    arity: int
    loc: Loc


@dataclass(slots=True, eq=False)
class OpDef:
    """``Op(params) == body``.  Function definitions ``f[x \\in S] == e`` have
    `fn_bounds` set and `body` = e."""

    name: str
    params: list[Param]
    body: Expr
    loc: Loc
    local: bool = False
    fn_bounds: list[Bound] | None = None


@dataclass(slots=True, eq=False)
class InstanceDef:
    """``INSTANCE M WITH a <- e`` (name None) or ``N(p) == INSTANCE M WITH ...``."""

    name: str | None
    params: list[Param]
    module: str
    substs: list[tuple[str, Expr]]
    loc: Loc
    local: bool = False


@dataclass(slots=True, eq=False)
class Assume:
    expr: Expr
    loc: Loc
    name: str | None = None


@dataclass(slots=True, eq=False)
class Module:
    name: str
    file: str
    extends: list[tuple[str, Loc]]
    constants: list[Param] = field(default_factory=list)
    variables: list[Param] = field(default_factory=list)
    # Definitions and instances in source order (later ones may refer to earlier ones).
    units: list[OpDef | InstanceDef] = field(default_factory=list)
    assumes: list[Assume] = field(default_factory=list)
    # THEOREM/LEMMA/... statements (name or None, statement, position): resolved like
    # every definition, never evaluated; their proofs are skipped.
    theorems: list[tuple[str | None, Expr, Loc]] = field(default_factory=list)
    recursive: set[str] = field(default_factory=set)
    # Nested modules declared inside this module's text, by name.
    submodules: dict[str, "Module"] = field(default_factory=dict)
    # The words (identifiers, keywords) and the string contents of the module's file, in
    # order of first appearance (TLC orders strings by when they were interned).
    token_order: list[str] = field(default_factory=list)
    string_order: list[str] = field(default_factory=list)
