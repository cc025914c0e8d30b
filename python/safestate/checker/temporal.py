"""The temporal formulas of a model, in the forms the checker handles (as TLC's
`SpecProcessor` sorts them):

* the fairness conjuncts of the specification: ``WF_v(A)``, ``SF_v(A)``, their
  conjunctions and ``\\A p \\in S : ...`` over them, through definitions with or
  without parameters;
* the conjuncts of each PROPERTY, with ``/\\``, definitions (also ``M!Op`` of a
  non-parameterised instance) and bounded ``\\A`` expanded over their (constant) values:

  - a state predicate ``P`` (checked on the initial states),
  - ``[]P`` (an implied invariant, reported as "Invariant X is violated"),
  - ``[][A]_v`` (an action property, checked on every transition),
  - ``<>P``, ``P ~> Q``, ``[]<>P``, ``<>[]P``, ``[](P => []Q)``, ``[]<><<A>>_v``,
    ``WF_v(A)`` and ``SF_v(A)`` (liveness, see `liveness.py`); nested forms that
    are equivalent to one of these are rewritten first (`_normal`):
    ``[](P => <>Q)`` is ``P ~> Q`` (its definition), ``[][]F`` is ``[]F``,
    ``<><>F`` is ``<>F``, ``<>[]<>P`` is ``[]<>P`` and ``[]<>[]P`` is ``<>[]P``,
    and ``P => []Q`` / ``P => <>Q`` (P on the initial state) are checked too,

  where P and Q are state predicates;
  - any other formula ("tableau"): translated as TLC's `Liveness.astToLive` into
    `ltl.Formula` over state and step predicates and checked with the tableau of its
    negation (`tableau_search.py`).  What TLC refuses is refused in its words; what
    we do not translate (\\AA, \\EE, -+->, LET, raw actions) is an "unsupported"
    error at its position, never guessed at.
"""

from __future__ import annotations

import dataclasses
import itertools
from dataclasses import dataclass
from typing import Any, Callable

from ..tla import ast as A
from ..tla.compiler import check_bool
from ..tla.env import Env, Frame, Local, SlotLocal
from ..tla.errors import Loc, TlaError, UnsupportedError
from ..tla.modules import DefSym, InstanceSym, Scope
from ..tla.values import Value, as_set
from . import ltl


@dataclass
class Pred:
    """A compiled state predicate (``t`` is None) or action predicate over (s, t)."""

    code: Callable[[Any, Any, list], Value]
    base: list
    loc: Loc

    def __call__(self, s: tuple, t: tuple | None = None) -> bool:
        v = self.code(s, t, self.base.copy())
        if v is True or v is False:
            return v
        return check_bool(v, self.loc, "temporal formula")


@dataclass
class Fairness:
    """``WF_v(A)`` / ``SF_v(A)`` for one value of its bound parameters."""

    kind: str            # "WF" or "SF"
    enabled: Pred        # ENABLED <<A>>_v, a state predicate
    taken: Pred          # <<A>>_v, an action predicate
    loc: Loc


@dataclass
class Obligation:
    """One conjunct of a PROPERTY.

    kind: "init" (pred on initial states), "always" ([]pred), "action" ([][pred]_v,
    pred is the whole step predicate), or a liveness form "eventually" (<>p),
    "leadsto" (p ~> q), "infinitely" ([]<>p), "stable" (<>[]p), "stays" ([](p => []q)),
    "init_always" (p => []q), "init_eventually" (p => <>q), "infinitely_step"
    ([]<><<A>>_v), "wf" / "sf" (WF_v(A) / SF_v(A), p is ENABLED <<A>>_v)."""

    name: str
    kind: str
    p: Pred
    q: Pred | None = None
    # For "wf", "sf" and "infinitely_step": <<A>>_v, a step the tail never takes.
    forbid: Pred | None = None
    # For "tableau" (and "stays", "init_always", see `tableau_safety.py`): the
    # property over the state and step predicates `atoms`.
    formula: ltl.Formula | None = None
    atoms: list[Pred] = dataclasses.field(default_factory=list)


# The fixed forms over state predicates only (the tableau checks them too).
STATE_LIVENESS_KINDS = ("eventually", "leadsto", "infinitely", "stable", "stays", "init_always", "init_eventually")
LIVENESS_KINDS = (*STATE_LIVENESS_KINDS, "infinitely_step", "wf", "sf", "tableau")


class TemporalCompiler:
    """Expands temporal formulas into `Fairness` and `Obligation` instances."""

    def __init__(self, model: Any, force_tableau: bool = False) -> None:
        self.model = model
        # Check the fixed forms over state predicates with the tableau too (to compare).
        self.force_tableau = force_tableau
        self.compiler = model.compiler
        self._temporal_defs: dict[int, bool] = {}

    # ------------------------------------------------------------ classification
    def is_temporal(self, e: Any, scope: Scope) -> bool:
        """Does `e` contain [], <>, ~>, WF/SF or \\AA/\\EE (also through definitions)?"""
        if isinstance(e, A.Unary) and e.op in ("[]", "<>"):
            return True
        if isinstance(e, (A.Fairness, A.UnboundedQuant)) or (isinstance(e, A.Binary) and e.op in ("~>", "-+->")):
            return True
        if isinstance(e, (A.Name, A.Apply, A.Prefixed)):
            sym = self._instance_def(e, scope) if isinstance(e, A.Prefixed) else scope.lookup(e.name)
            if isinstance(sym, DefSym):
                key = id(sym)
                if key not in self._temporal_defs:
                    self._temporal_defs[key] = False  # recursion guard
                    self._temporal_defs[key] = self.is_temporal(sym.defn.body, sym.scope)
                if self._temporal_defs[key]:
                    return True
            if isinstance(e, A.Name):
                return False
        if isinstance(e, A.Expr):
            for f in dataclasses.fields(e):
                v = getattr(e, f.name)
                items = v if isinstance(v, list) else [v]
                # CASE keeps its arms as (guard, value) pairs.
                items = [y for x in items for y in (x if isinstance(x, tuple) else (x,))]
                for x in items:
                    if isinstance(x, A.Expr) and self.is_temporal(x, scope):
                        return True
                    if isinstance(x, A.Bound) and self.is_temporal(x.set, scope):
                        return True
        return False

    @staticmethod
    def _instance_def(e: A.Prefixed, scope: Scope) -> object:
        """The definition M!Op names; its scope carries the instance's substitutions."""
        for step in e.path:
            sym = scope.lookup(step.name)
            if not isinstance(sym, InstanceSym):
                return None
            scope = sym.scope
        return scope.lookup(e.name)

    # ------------------------------------------------------------ expansion
    def fairness(self, e: A.Expr) -> list[Fairness]:
        out: list[Fairness] = []
        self._expand(e, self.model.scope, {}, lambda x, sc, b: out.append(self._fair(x, sc, b)))
        return out

    def obligations(self, name: str, e: A.Expr, scope: Scope) -> list[Obligation]:
        out: list[Obligation] = []
        self._expand(e, scope, {}, lambda x, sc, b: out.append(self._obligation(name, x, sc, b)))
        return out

    def _expand(self, e: A.Expr, scope: Scope, binds: dict[str, Value],
                leaf: Callable[[A.Expr, Scope, dict], None]) -> None:
        """Calls `leaf` on each conjunct, with conjunctions, temporal definitions and
        bounded \\A over temporal formulas expanded."""
        if isinstance(e, A.And):
            for item in e.items:
                self._expand(item, scope, binds, leaf)
            return
        defn = self._temporal_definition(e, scope, binds)
        if defn is not None:
            self._expand(*defn, leaf)
            return
        if isinstance(e, A.Quant) and e.kind == "\\A" and self.is_temporal(e.body, scope):
            for combo in self._bindings(e, scope, binds):
                self._expand(e.body, scope, combo, leaf)
            return
        leaf(e, scope, binds)

    def _temporal_definition(self, e: A.Expr, scope: Scope,
                             binds: dict[str, Value]) -> tuple[A.Expr, Scope, dict[str, Value]] | None:
        """The body, scope and argument values of the temporal definition `e` applies
        (None when `e` is not one)."""
        if not isinstance(e, (A.Name, A.Apply, A.Prefixed)) or e.name in binds:
            return None
        sym = self._instance_def(e, scope) if isinstance(e, A.Prefixed) else scope.lookup(e.name)
        if not isinstance(sym, DefSym) or not self.is_temporal(e, scope):
            return None
        if isinstance(e, A.Prefixed) and any(step.args for step in e.path):
            raise UnsupportedError("a temporal formula of a parameterised instance (M(p)!Op) is not "
                                   "supported", e.loc)
        args = e.args if isinstance(e, (A.Apply, A.Prefixed)) else []
        if len(args) != len(sym.defn.params):
            raise TlaError("semantic", f"{e.name} expects {len(sym.defn.params)} arguments", e.loc)
        values = {p.name: self._constant(a, scope, binds) for p, a in zip(sym.defn.params, args)}
        return sym.defn.body, sym.scope, values

    def _bindings(self, e: A.Quant, scope: Scope, binds: dict[str, Value]) -> list[dict[str, Value]]:
        """`binds` extended by each combination of values of the quantifier's bounds."""
        names: list[str] = []
        sets: list[list[Value]] = []
        for b in e.bounds:
            if b.tuple:
                raise UnsupportedError("a tuple binder <<..>> \\in S over a temporal formula", b.set.loc)
            for n in b.names:
                names.append(n)
                sets.append(list(as_set(self._constant(b.set, scope, binds))))
        return [{**binds, **dict(zip(names, combo))} for combo in itertools.product(*sets)]

    # ------------------------------------------------------------ leaves
    def _fair(self, e: A.Expr, scope: Scope, binds: dict) -> Fairness:
        if not isinstance(e, A.Fairness):
            raise UnsupportedError("this temporal conjunct of the specification is not supported: only "
                                   "WF_v(A), SF_v(A), their conjunctions and \\A over them are", e.loc)
        step = A.StepAction(e.loc, e.action, e.sub, False)
        return Fairness(e.kind, self.pred(A.Unary(e.loc, "ENABLED", step), scope, binds),
                        self.pred(step, scope, binds), e.loc)

    def _normal(self, e: A.Expr, scope: Scope) -> A.Expr:
        """`e` with the nested temporal forms above rewritten to the checked ones
        (behaviours are stuttering-closed, so these equivalences hold for TLC too)."""
        while isinstance(e, A.Unary) and e.op in ("[]", "<>"):
            arg = self._normal(e.arg, scope)
            if isinstance(arg, A.Unary) and arg.op == e.op:
                e = arg  # [][]F, <><>F
                continue
            inner = arg.arg if isinstance(arg, A.Unary) and arg.op in ("[]", "<>") else None
            if isinstance(inner, A.Unary) and isinstance(arg, A.Unary) and inner.op == e.op and arg.op != e.op:
                e = arg  # <>[]<>P is []<>P, []<>[]P is <>[]P
                continue
            if (e.op == "[]" and isinstance(arg, A.Binary) and arg.op == "=>"
                    and not self.is_temporal(arg.lhs, scope) and isinstance(arg.rhs, A.Unary)
                    and arg.rhs.op == "<>" and not self.is_temporal(arg.rhs.arg, scope)):
                return A.Binary(e.loc, "~>", arg.lhs, arg.rhs.arg)  # [](P => <>Q) is P ~> Q
            return A.Unary(e.loc, e.op, arg) if arg is not e.arg else e
        return e

    def _obligation(self, name: str, e: A.Expr, scope: Scope, binds: dict) -> Obligation:
        if not self.is_temporal(e, scope):
            return Obligation(name, "init", self._state(e, scope, binds))
        try:
            ob = self._fixed_shape(name, self._normal(e, scope), scope, binds)
        except UnsupportedError:
            ob = None  # e.g. a step formula where the fixed form has a state predicate: <>[][A]_v
        if ob is None or (self.force_tableau and ob.kind in STATE_LIVENESS_KINDS):
            return self._general(name, e, scope, binds)
        if ob.kind in ("stays", "init_always"):
            # Its tableau has an accepting node: TLC may stop its search at a finite
            # counterexample (`tableau_safety.py`).
            general = self._general(name, e, scope, binds)
            ob.formula, ob.atoms = general.formula, general.atoms
        return ob

    def _fixed_shape(self, name: str, e: A.Expr, scope: Scope, binds: dict) -> Obligation | None:
        """The obligation of a conjunct of one of the fixed forms (each with its own
        search in `liveness.py`), or None."""
        if (isinstance(e, A.Unary) and e.op == "[]" and isinstance(e.arg, A.Binary) and e.arg.op == "=>"
                and not self.is_temporal(e.arg.lhs, scope) and isinstance(e.arg.rhs, A.Unary)
                and e.arg.rhs.op == "[]" and not self.is_temporal(e.arg.rhs.arg, scope)):
            # [](P => []Q): once P holds, Q holds from then on.
            return Obligation(name, "stays", self._live(e.arg.lhs, scope, binds),
                              self._live(e.arg.rhs.arg, scope, binds))
        if isinstance(e, A.Unary) and e.op == "[]":
            arg = e.arg
            if isinstance(arg, A.StepAction) and arg.stutter:
                return Obligation(name, "action", self.pred(arg, scope, binds))
            if isinstance(arg, A.Unary) and arg.op == "<>" and not self.is_temporal(arg.arg, scope):
                inner = arg.arg
                if isinstance(inner, A.StepAction) and not inner.stutter:
                    return Obligation(name, "infinitely_step", self.pred(inner, scope, binds),
                                      forbid=self.pred(inner, scope, binds))
                return Obligation(name, "infinitely", self._live(inner, scope, binds))
            if not self.is_temporal(arg, scope):
                return Obligation(name, "always", self._state(arg, scope, binds))
        if isinstance(e, A.Unary) and e.op == "<>":
            arg = e.arg
            if isinstance(arg, A.Unary) and arg.op == "[]" and not self.is_temporal(arg.arg, scope):
                return Obligation(name, "stable", self._live(arg.arg, scope, binds))
            if not self.is_temporal(arg, scope):
                return Obligation(name, "eventually", self._live(arg, scope, binds))
        if (isinstance(e, A.Binary) and e.op == "=>" and not self.is_temporal(e.lhs, scope)
                and isinstance(e.rhs, A.Unary) and e.rhs.op in ("[]", "<>")
                and not self.is_temporal(e.rhs.arg, scope) and not isinstance(e.rhs.arg, A.StepAction)):
            # P => []Q and P => <>Q: P is evaluated on the initial state.
            kind = "init_always" if e.rhs.op == "[]" else "init_eventually"
            return Obligation(name, kind, self._live(e.lhs, scope, binds), self._live(e.rhs.arg, scope, binds))
        if isinstance(e, A.Fairness):
            fair = self._fair(e, scope, binds)
            return Obligation(name, e.kind.lower(), fair.enabled, forbid=fair.taken)
        if isinstance(e, A.Binary) and e.op == "~>":
            if not self.is_temporal(e.lhs, scope) and not self.is_temporal(e.rhs, scope):
                return Obligation(name, "leadsto", self._live(e.lhs, scope, binds),
                                  self._live(e.rhs, scope, binds))
        return None

    # ------------------------------------------------------------ general formulas
    def _general(self, name: str, e: A.Expr, scope: Scope, binds: dict) -> Obligation:
        """Any formula of state predicates, ~, /\\, \\/, =>, ~>, [], <>, IF, bounded \\A /
        \\E, WF/SF and the steps [A]_v, <<A>>_v: checked with the tableau of its negation
        (`tableau.py`), after the checks of TLC's `Liveness.processLiveness`."""
        atoms: list[Pred] = []
        formula = self._ltl(name, e, scope, binds, atoms)
        conjuncts = ltl.disjuncts(ltl.negate(formula))
        if conjuncts is not None:
            for c in (c for d in conjuncts for c in d):
                if not ltl.without_tableau(c) and ltl.has_action(c):
                    raise TlaError("temporal", "Temporal formulas containing actions must be of forms <>[]A or "
                                   "[]<>A.", e.loc)
        true = self.pred(A.Bool(e.loc, True), scope, {})  # p is not read for a tableau obligation
        return Obligation(name, "tableau", true, formula=formula, atoms=atoms)

    def _ltl(self, name: str, e: A.Expr, scope: Scope, binds: dict, atoms: list[Pred]) -> ltl.Formula:
        def atom(pred: Pred, action: bool = False) -> ltl.Atom:
            atoms.append(pred)
            return ltl.Atom(len(atoms) - 1, action=action)

        def sub(x: A.Expr, sc: Scope = scope, bs: dict = binds) -> ltl.Formula:
            return self._ltl(name, x, sc, bs, atoms)
        if isinstance(e, A.StepAction):
            return atom(self.pred(e, scope, binds), action=True)
        if isinstance(e, A.Fairness):
            # As TLC: WF_v(A) is []<>(~ENABLED <<A>>_v \/ <<A>>_v), SF_v(A) is
            # <>[]~ENABLED <<A>>_v \/ []<><<A>>_v.
            fair = self._fair(e, scope, binds)
            disabled, taken = ltl.negate(atom(fair.enabled)), atom(fair.taken, action=True)
            if e.kind == "WF":
                return ltl.Always(ltl.Eventually(ltl.Or((disabled, taken))))
            return ltl.Or((ltl.Eventually(ltl.Always(disabled)), ltl.Always(ltl.Eventually(taken))))
        if not self.is_temporal(e, scope):
            return atom(self._live(e, scope, binds))
        if isinstance(e, (A.And, A.Or)):
            items = tuple(sub(x) for x in e.items)
            return ltl.And(items) if isinstance(e, A.And) else ltl.Or(items)
        if isinstance(e, A.Unary) and e.op in ("[]", "<>"):
            arg = sub(e.arg)
            return ltl.Always(arg) if e.op == "[]" else ltl.Eventually(arg)
        if isinstance(e, A.Unary) and e.op in ("~", "\\lnot", "\\neg"):
            return ltl.negate(sub(e.arg))
        if isinstance(e, A.Binary) and e.op in ("=>", "~>"):
            lhs, rhs = sub(e.lhs), sub(e.rhs)
            if e.op == "=>":
                return ltl.Or((ltl.negate(lhs), rhs))
            return ltl.Always(ltl.Or((ltl.negate(lhs), ltl.Eventually(rhs))))
        if isinstance(e, A.If):
            cond = sub(e.cond)
            return ltl.Or((ltl.And((cond, sub(e.then))), ltl.And((ltl.negate(cond), sub(e.other)))))
        defn = self._temporal_definition(e, scope, binds)
        if defn is not None:
            return sub(*defn)
        if isinstance(e, A.Quant) and e.kind in ("\\A", "\\E"):
            items = tuple(sub(e.body, scope, combo) for combo in self._bindings(e, scope, binds))
            return ltl.And(items) if e.kind == "\\A" else ltl.Or(items)
        if isinstance(e, A.Binary) and e.op in ("<=>", "\\equiv") or isinstance(e, A.Case):
            # TLC's astToLive has no case for these either (EC.TLC_LIVE_CANNOT_HANDLE_FORMULA).
            raise TlaError("temporal", f"TLC cannot handle the temporal formula {_what(e)} (of temporal "
                           f"formulas) in property {name}", e.loc)
        raise UnsupportedError(f"the temporal formula in property {name} is not supported: {_what(e)} over "
                               f"temporal formulas is not checked (supported: state predicates, [A]_v, "
                               f"<<A>>_v, WF_v(A) and SF_v(A) under ~, /\\, \\/, =>, ~>, [], <>, IF and "
                               f"bounded \\A / \\E)", e.loc)

    # ------------------------------------------------------------ compilation
    def _env(self, scope: Scope, binds: dict) -> tuple[Env, list[tuple[int, Value]]]:
        frame = Frame()
        slots = [(frame.alloc(), v) for v in binds.values()]
        local: dict[str, Local] = {n: SlotLocal(sl) for n, (sl, _) in zip(binds, slots)}
        return Env(scope, frame, local), slots

    def pred(self, e: A.Expr, scope: Scope, binds: dict) -> Pred:
        env, slots = self._env(scope, binds)
        code = self.compiler.expr(e, env)
        base: list = [None] * env.frame.size
        for sl, v in slots:
            base[sl] = v
        return Pred(code, base, e.loc)

    def _state(self, e: A.Expr, scope: Scope, binds: dict) -> Pred:
        env, _ = self._env(scope, binds)
        if self.compiler.info(e, env).action:
            raise UnsupportedError("an action-level formula is not supported here: this position of a "
                                   "property takes a state predicate", e.loc)
        return self.pred(e, scope, binds)

    def _live(self, e: A.Expr, scope: Scope, binds: dict) -> Pred:
        """A state predicate inside a liveness formula.  Its parts that read no
        variable (below its boolean connectives) are evaluated now, as TLC's tableau
        construction does (`Liveness.astToLive`): an error in one stops TLC before the
        search, with exit code 255."""
        pred = self._state(e, scope, binds)
        self._eval_constant_parts(e, scope, binds)
        return pred

    def _eval_constant_parts(self, e: A.Expr, scope: Scope, binds: dict) -> None:
        if isinstance(e, (A.And, A.Or)):
            for item in e.items:
                self._eval_constant_parts(item, scope, binds)
            return
        if isinstance(e, A.Unary) and e.op in ("~", "\\lnot", "\\neg"):
            self._eval_constant_parts(e.arg, scope, binds)
            return
        if isinstance(e, A.Binary) and e.op == "=>":
            self._eval_constant_parts(e.lhs, scope, binds)
            self._eval_constant_parts(e.rhs, scope, binds)
            return
        env, _ = self._env(scope, binds)
        if self.compiler.info(e, env).vars:
            return
        pred = self.pred(e, scope, binds)
        try:
            pred.code(None, None, pred.base.copy())
        except TlaError as err:
            if err.kind not in ("eval", "module eval"):
                raise
            raise TlaError("module eval", err.message, err.loc or e.loc) from None

    def _constant(self, e: A.Expr, scope: Scope, binds: dict) -> Value:
        p = self.pred(e, scope, binds)
        return p.code(None, None, p.base.copy())


def _what(e: A.Expr) -> str:
    """How an error names the construct at e."""
    if isinstance(e, A.UnboundedQuant):
        return f"temporal quantification {e.kind}"
    if isinstance(e, (A.Binary, A.Unary)):
        return e.op
    return {A.Case: "CASE", A.Let: "LET"}.get(type(e), "this construct")
