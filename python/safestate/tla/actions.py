"""Compiles actions (and the initial predicate) in continuation-passing style.

An action compiles to ``act(s, t, L)`` that calls its continuation ``k(s, t, L)``
once for every way it can be satisfied, with the next state `t` (a list) filled in.
This reproduces TLC's evaluation of the next-state relation:

* a conjunct ``x' = e`` assigns ``x'`` if it is still unassigned, else tests it;
* ``x' \\in S`` enumerates S (TLC's order) when ``x'`` is unassigned, else tests;
* conjunctions are evaluated left to right, disjunctions and ``\\E`` branch;
* ``UNCHANGED <<x, y>>`` is ``x' = x /\\ y' = y``;
* any other conjunct is a guard evaluated as a boolean.

In the initial predicate the same rules apply to unprimed variables.
Continuations are fixed at compile time, so no closures are built while exploring.
"""

from __future__ import annotations

import itertools
from dataclasses import dataclass, field, replace
from typing import Any, Callable

from . import ast as A
from .compiler import Compiler, _enum_checked, _prefix, _subterms, all_names, check_bool
from .compiler import _assign as assign_binder
from .env import UNSET, ByNameLocal, Code, Env, Frame, LazyLocal, LetOpLocal, OpLocal, SlotLocal
from .errors import EvalError, Loc, TlaError, UnassignedPrimeError, UnsupportedError
from .modules import DefSym, SubstSym, VarSym
from .fold_memo import EXPANSION_LIMIT
from .specialise import var_read
from .values import LazySet, member, values_equal

Cont = Callable[[Any, Any, list], None]


@dataclass
class Leaf:
    """One action of the next-state relation as TLC splits it: the operator name,
    the bound variables (\\E variables and operator arguments) with their frame slots."""

    name: str
    loc: Loc
    params: list[tuple[str, int]] = field(default_factory=list)


def _not_compiled(s: Any, t: Any, L: list) -> None:
    raise EvalError("recursive action run before its body is compiled")


@dataclass
class _RecursiveAction:
    """The compiled body of a recursive action-level operator (see
    `ActionCompiler.recursive_action`)."""

    body: Code = _not_compiled
    size: int = 0
    ret: int = 0


def _primes_a_parameter(body: A.Expr, params: set[str]) -> bool:
    """Does `body` prime (or UNCHANGE) an expression naming one of `params`?  TLC
    binds such a parameter by name; a recursive call passes values."""
    def walk(x: Any, primed: bool) -> bool:
        if isinstance(x, (A.Name, A.Apply)) and primed and x.name in params:
            return True
        inner = primed or isinstance(x, A.Prime) or (isinstance(x, A.Unary) and x.op == "UNCHANGED")
        return any(walk(c, inner) for c in _subterms(x))
    return walk(body, False)


class ActionCompiler:
    def __init__(self, compiler: Compiler) -> None:
        self.c = compiler
        self._recursive: dict[tuple[int, bool, frozenset[int]], _RecursiveAction] = {}

    # ---------------------------------------------------------------- splitting Next
    def split(self, e: A.Expr, env: Env, label: str, label_loc: Loc, params: list[tuple[str, int]],
              make_k: Callable[[Leaf], Cont]) -> Code:
        """Compile the next-state relation, giving each of TLC's actions its own
        continuation (made by `make_k`), so each successor knows its action."""
        if isinstance(e, A.Or):
            branches = [self.split(i, env, label, label_loc, params, make_k) for i in e.items]
            return _branches(branches)
        if isinstance(e, A.Quant) and e.kind == "\\E":
            inner, binds = self.c.bind_bounds(e.bounds, env)
            names = [(n, sl) for b, bind in zip(_flat_bounds(e.bounds), binds) for n, sl in zip(b, bind[1])]
            body = self.split(e.body, inner, label, label_loc, params + names, make_k)
            return _exists(binds, body)
        if isinstance(e, A.Let):
            env2, resets = self.c.bind_let(e.defs, env)
            return _let(resets, self.split(e.body, env2, label, label_loc, params, make_k))
        if isinstance(e, (A.Name, A.Apply)) and e.name not in env.locals:
            sym = env.scope.lookup(e.name)
            if isinstance(sym, DefSym) and not sym.recursive and sym.defn.fn_bounds is None:
                args = e.args if isinstance(e, A.Apply) else []
                new_params: list[tuple[str, int]] = []

                def inline_body(b: A.Expr, benv: Env) -> Code:
                    for p in sym.defn.params:
                        loc_ = benv.locals.get(p.name)
                        # An argument passed unevaluated (LazyArgLocal) may never get a
                        # value: it is not one of the action's parameters.
                        if isinstance(loc_, SlotLocal):
                            new_params.append((p.name, loc_.slot))
                    return self.split(b, benv, sym.defn.name, sym.defn.loc, params + new_params, make_k)
                pre, code = self.c.inline_def(sym, args, env, e.loc, inline_body)
                return _prefix_act(pre, code)
        return self.action(e, env, make_k(Leaf(label, label_loc, list(params))))

    # ---------------------------------------------------------------- actions
    def action(self, e: A.Expr, env: Env, k: Cont) -> Code:
        method = getattr(self, "a_" + type(e).__name__, None)
        if method is not None:
            r = method(e, env, k)
            if r is not None:
                return r
        return self.guard(e, env, k)

    def guard(self, e: A.Expr, env: Env, k: Cont) -> Code:
        g = self.c.expr(e, env)
        loc = e.loc

        def guard(s: Any, t: Any, L: list) -> None:
            v = g(s, t, L)
            if v is True:
                k(s, t, L)
            elif v is not False:
                check_bool(v, loc, "action conjunct")
        guard.cont = k  # type: ignore[attr-defined]  # for _plain_guard
        return guard

    def a_Bool(self, e: A.Bool, env: Env, k: Cont) -> Code:
        if e.value:
            return k
        return lambda s, t, L: None

    def a_And(self, e: A.And, env: Env, k: Cont) -> Code:
        # Runs of plain assignments (x' = e, UNCHANGED <<x, y>>) become one closure.
        items = list(e.items)
        while items:
            run: list[tuple[int, Code, Loc]] = []
            while items:
                parts = self._plain_assignments(items[-1], env)
                if parts is None:
                    break
                run[:0] = parts
                items.pop()
            if len(run) > 1 and self.c.fast_paths:
                k = assign_run(run, k)
            elif run and not self.c.fast_paths:
                for i, rhs, loc in reversed(run):
                    k = self._assign(i, rhs, k, loc)
            elif run:
                i, rhs, loc = run[0]
                k = self._assign(i, rhs, k, loc)
            if items:
                item = items.pop()
                act = self.action(item, env, k)
                # TLC (Tool.getNextStatesAllAssigned, getInitStates): once every variable
                # has a value, the remaining conjuncts are evaluated as booleans, so a
                # disjunction or \E among them yields one successor, not one per branch.
                k = act if not items or _plain_guard(act) else self._all_assigned_guard(item, env, act, k)
        return k

    def _all_assigned_guard(self, e: A.Expr, env: Env, act: Code, k: Cont) -> Code:
        try:
            test = self.guard(e, env, k)
        except UnsupportedError:
            # A recursive action cannot be compiled as an expression: run it as an
            # action on the complete state and continue once if any branch holds.
            test = self._once(e, env, k)

        def conjunct(s: Any, t: Any, L: list) -> None:
            for v in t:
                if v is UNSET:
                    act(s, t, L)
                    return
            test(s, t, L)
        return conjunct

    def _once(self, e: A.Expr, env: Env, k: Cont) -> Code:
        hit = [False]

        def mark(s: Any, t: Any, L: list) -> None:
            hit[0] = True
        probe = self.action(e, env, mark)

        def once(s: Any, t: Any, L: list) -> None:
            hit[0] = False
            probe(s, t, L)
            if hit[0]:
                k(s, t, L)
        return once

    def _plain_assignments(self, e: A.Expr, env: Env) -> list[tuple[int, Code, Loc]] | None:
        """``x' = e`` or ``UNCHANGED <<x, y>>`` as (variable, value code, loc) triples."""
        if isinstance(e, A.Binary) and e.op == "=":
            target = self._target_var(e.lhs, env)
            if target is not None:
                return [(target[0], self.c.expr(e.rhs, env), e.loc)]
            return None
        if isinstance(e, A.Unary) and e.op == "UNCHANGED" and not env.init_mode:
            idx = self._unchanged_vars(e.arg, env, 0)
            if idx is not None:
                return [(i, var_read(i), e.loc) for i in idx]
        return None

    def a_Or(self, e: A.Or, env: Env, k: Cont) -> Code:
        return _branches([self.action(i, env, k) for i in e.items])

    def a_Quant(self, e: A.Quant, env: Env, k: Cont) -> Code | None:
        if e.kind != "\\E":
            return self._forall(e, env, k)
        inner, binds = self.c.bind_bounds(e.bounds, env)
        return _exists(binds, self.action(e.body, inner, k))

    def _forall(self, e: A.Quant, env: Env, k: Cont) -> Code | None:
        """``\\A x \\in S : A`` in an action is the conjunction of A for each x, as in
        TLC (Tool.getNextStates, OPCODE_bf): A with the first binding, then the others
        as pending conjuncts, which TLC's list takes last-first (x1, xn, ..., x2);
        pending ones are booleans once every variable is assigned."""
        inner, binds = self.c.bind_bounds(e.bounds, env)
        slot = env.frame.alloc()
        lo = env.frame.size
        body_slots: list[int] = []  # slots the body uses (inlined parameters, LETs)

        def after(s: Any, t: Any, L: list) -> None:
            order, pos = L[slot]
            if pos + 1 >= len(order):
                k(s, t, L)
                return
            # A later branch of this instance continues with its own slot values.
            saved = [L[sl] for sl in body_slots]
            L[slot] = (order, pos + 1)
            _bind_combo(L, binds, order[pos + 1])
            if UNSET in t:
                body(s, t, L)
            else:
                test(s, t, L)
            L[slot] = (order, pos)
            _bind_combo(L, binds, order[pos])
            for sl, v in zip(body_slots, saved):
                L[sl] = v
        body = self.action(e.body, inner, after)
        if _plain_guard(body, after):
            return None  # a plain boolean \\A: the same successors, evaluated once
        test = self.guard(e.body, inner, after)
        body_slots.extend(range(lo, env.frame.size))

        def forall(s: Any, t: Any, L: list) -> None:
            combos = _combos(binds, s, t, L)
            if not combos:
                k(s, t, L)
                return
            saved = L[slot]
            L[slot] = ([combos[0]] + combos[:0:-1], 0)
            _bind_combo(L, binds, combos[0])
            body(s, t, L)
            L[slot] = saved
        return forall

    def a_If(self, e: A.If, env: Env, k: Cont) -> Code | None:
        c = self.c.expr(e.cond, env)
        a, b = self.action(e.then, env, k), self.action(e.other, env, k)
        loc = e.cond.loc

        def ite(s: Any, t: Any, L: list) -> None:
            v = c(s, t, L)
            if v is True:
                a(s, t, L)
            elif v is False:
                b(s, t, L)
            else:
                check_bool(v, loc, "IF condition")
        return ite

    def a_Case(self, e: A.Case, env: Env, k: Cont) -> Code | None:
        arms = [(self.c.expr(g, env), self.action(v, env, k), g.loc) for g, v in e.arms]
        other = self.action(e.other, env, k) if e.other is not None else None
        loc = e.loc

        def case(s: Any, t: Any, L: list) -> None:
            for g, act, gl in arms:
                r = g(s, t, L)
                if r is True:
                    act(s, t, L)
                    return
                if r is not False:
                    check_bool(r, gl, "CASE guard")
            if other is None:
                raise EvalError("Attempted to evaluate a CASE with no arm whose guard is true", loc)
            other(s, t, L)
        return case

    def a_Let(self, e: A.Let, env: Env, k: Cont) -> Code:
        env2, resets = self.c.bind_let(e.defs, env)
        return _let(resets, self.action(e.body, env2, k))

    def a_Name(self, e: A.Name, env: Env, k: Cont) -> Code | None:
        return self._call(e, [], env, k)

    def a_Apply(self, e: A.Apply, env: Env, k: Cont) -> Code | None:
        return self._call(e, e.args, env, k)

    def _call(self, e: A.Name | A.Apply, args: list[A.Expr], env: Env, k: Cont) -> Code | None:
        local = env.locals.get(e.name)
        if local is not None:
            if isinstance(local, ByNameLocal) and not args:
                return self.action(local.expr, local.env, k)
            # TLC expands a LET definition used as a conjunct (getNextStatesAppl), so a
            # disjunction or \\E inside it branches; if nothing branches, its value is the same.
            if isinstance(local, LazyLocal) and local.body is not None and not args:
                code = self.action(local.body[0], local.body[1], k)
                return None if _plain_guard(code, k) else code
            if isinstance(local, LetOpLocal) and e.name not in all_names(local.defn.body):
                # Like a user operator: descend into its body (TLC does).
                pre, code = self.c.inline_let_op(e.name, local, args, env, e.loc,
                                                 lambda b, benv: self.action(b, benv, k))
                return _prefix_act(pre, code)
            return None
        sym = env.scope.lookup(e.name)
        sym = self.c.sym_overrides.get(id(sym), sym)  # C <- Op: expand Op
        if isinstance(sym, SubstSym) and not args:
            inst = {p: env.locals[p] for p in sym.instance_params if p in env.locals}
            return self.action(sym.expr, Env(sym.scope, env.frame, inst, env.init_mode, env.primed,
                                             enabled_cut=env.enabled_cut), k)
        # TLC evaluates every user-defined operator in action position by descending
        # into its body (so a disjunction inside it branches); a recursive one cannot
        # be expanded at compile time and runs with its arguments' values.
        if isinstance(sym, DefSym) and sym.recursive and sym.defn.fn_bounds is None \
                and self.c.def_info(sym).action:
            return self.recursive_action(sym, args, env, e.loc, k)
        if not isinstance(sym, DefSym) or sym.defn.fn_bounds is not None or sym.recursive:
            return None
        if self.c._inline_depth > EXPANSION_LIMIT:
            return None
        pre, code = self.c.inline_def(sym, args, env, e.loc, lambda b, benv: self.action(b, benv, k))
        return _prefix_act(pre, code)

    def recursive_action(self, sym: DefSym, args: list[A.Expr], env: Env, loc: Loc, k: Cont) -> Code:
        """A RECURSIVE operator in action position (``Step(n) == IF n = 0 THEN x' = 1
        ELSE Step(n - 1)``): its body is compiled once as an action whose
        continuation is a frame slot, filled at each call with the caller's."""
        d = sym.defn
        self.c._arity(d.name, len(d.params), args, loc)
        params = {p.name for p in d.params}
        if sym.scope.instance_params or _primes_a_parameter(d.body, params):
            raise UnsupportedError(f"the recursive operator {d.name} primes one of its parameters (or is "
                                   f"defined in a parameterised instance): not supported", loc)
        key = (id(sym), env.init_mode, env.enabled_cut)
        rec = self._recursive.get(key)
        if rec is None:
            rec = self._recursive[key] = _RecursiveAction()
            frame = Frame()
            bindings: dict[str, Any] = {}
            for p in d.params:
                slot = frame.alloc()
                bindings[p.name] = OpLocal(slot, p.arity) if p.arity else SlotLocal(slot)
            ret = rec.ret = frame.alloc()

            def back(s: Any, t: Any, L: list) -> None:
                L[ret](s, t)
            rec.body = self.action(d.body, Env(sym.scope, frame, bindings, env.init_mode,
                                               enabled_cut=env.enabled_cut), back)
            rec.size = frame.size
        arg_codes = [self.c._arg(a, p.arity, env, loc) for a, p in zip(args, d.params)]

        def call(s: Any, t: Any, L: list) -> None:
            frame = [a(s, t, L) for a in arg_codes]
            frame += [None] * (rec.size - len(frame))
            frame[rec.ret] = lambda s2, t2: k(s2, t2, L)
            rec.body(s, t, frame)
        return call

    def a_Prefixed(self, e: A.Prefixed, env: Env, k: Cont) -> Code | None:
        pre, code = self.c.prefixed(e, env, lambda b, benv: self.action(b, benv, k))
        return _prefix_act(pre, code)

    def a_StepAction(self, e: A.StepAction, env: Env, k: Cont) -> Code:
        if e.stutter:
            return _branches([self.action(e.action, env, k), self.unchanged(e.sub, env, k)])
        same = self.c._unchanged_expr(e.sub, env)

        def changed(s: Any, t: Any, L: list) -> None:
            if not same(s, t, L):
                k(s, t, L)
        return self.action(e.action, env, changed)

    def a_Unary(self, e: A.Unary, env: Env, k: Cont) -> Code | None:
        if e.op == "UNCHANGED":
            return self.unchanged(e.arg, env, k)
        return None

    def a_Binary(self, e: A.Binary, env: Env, k: Cont) -> Code | None:
        if e.op == "=>":
            lhs, rhs = self.c.expr(e.lhs, env), self.action(e.rhs, env, k)
            lloc = e.lhs.loc

            def implies(s: Any, t: Any, L: list) -> None:
                v = lhs(s, t, L)
                if v is True:
                    rhs(s, t, L)
                elif v is False:
                    k(s, t, L)
                else:
                    check_bool(v, lloc, "antecedent of =>")
            return implies
        if e.op not in ("=", "\\in"):
            return None
        target = self._target_var(e.lhs, env)
        if target is None:
            return None
        i, name = target
        if e.op == "=":
            return self._assign(i, self.c.expr(e.rhs, env), k, e.loc)
        return self._assign_in(i, self.c.expr(e.rhs, env), k, e.loc, env.init_mode)

    # ---------------------------------------------------------------- assignments
    def _target_var(self, lhs: A.Expr, env: Env, depth: int = 0) -> tuple[int, str] | None:
        """The variable assigned by ``lhs = ...``: ``x'`` in actions, ``x`` in Init.
        As TLC (`Tool.getPrimedVar`), names of arguments and definitions without
        parameters are followed: ``q' = e`` assigns ``a'`` when ``q`` stands for ``a``,
        and ``P = e`` assigns ``a'`` when ``P == a'``."""
        if env.init_mode:
            return self._var_of(lhs, env)
        if isinstance(lhs, A.Prime):
            return self._var_of(lhs.arg, env)
        named = self._named_expr(lhs, env)
        if named is not None and depth < 20:
            return self._target_var(named[0], named[1], depth + 1)
        return None

    def _var_of(self, e: A.Expr, env: Env, depth: int = 0) -> tuple[int, str] | None:
        """The state variable `e` stands for (`Tool.getVar`), if any."""
        if isinstance(e, A.Name) and e.name not in env.locals:
            sym = env.scope.lookup(e.name)
            if isinstance(sym, VarSym):
                return sym.index, sym.name
            slot = self._scratch(sym, env)
            if slot is not None:
                return slot, e.name
        named = self._named_expr(e, env)
        if named is not None and depth < 20:
            return self._var_of(named[0], named[1], depth + 1)
        return None

    def _scratch(self, sym: Any, env: Env) -> int | None:
        return self.c.scratch_slot(sym, env) if isinstance(sym, SubstSym) and not env.init_mode else None

    @staticmethod
    def _named_expr(e: A.Expr, env: Env) -> tuple[A.Expr, Env] | None:
        """The expression a name without arguments stands for: an operator
        argument or LET definition reading state, a definition, a substitution."""
        if not isinstance(e, A.Name):
            return None
        local = env.locals.get(e.name)
        if local is not None:
            if isinstance(local, ByNameLocal):
                return local.expr, local.env
            if isinstance(local, (SlotLocal, LazyLocal)) and local.source is not None:
                return local.source
            return None
        sym = env.scope.lookup(e.name)
        if isinstance(sym, DefSym) and not sym.defn.params and sym.defn.fn_bounds is None:
            return sym.defn.body, Env(sym.scope, env.frame, {}, env.init_mode, enabled_cut=env.enabled_cut)
        if isinstance(sym, SubstSym):
            return sym.expr, Env(sym.scope, env.frame, {p: env.locals[p] for p in sym.instance_params
                                                        if p in env.locals}, env.init_mode,
                                 enabled_cut=env.enabled_cut)
        return None

    def _assign(self, i: int, rhs: Code, k: Cont, loc: Loc) -> Code:
        def assign(s: Any, t: Any, L: list) -> None:
            v = rhs(s, t, L)
            cur = t[i]
            if cur is UNSET:
                t[i] = v
                k(s, t, L)
                t[i] = UNSET
            elif cur == v if type(cur) is type(v) else _eq(cur, v, loc):
                k(s, t, L)
        return assign

    def _assign_in(self, i: int, rhs: Code, k: Cont, loc: Loc, init: bool = False) -> Code:
        # TLC's wording when the set is infinite (Nat, Seq(S), {x \in Nat : P} ...).
        not_enumerable = (f"In computing {'initial' if init else 'next'} states, the right side of \\IN "
                          f"is not enumerable.")

        def assign_in(s: Any, t: Any, L: list) -> None:
            S = rhs(s, t, L)
            cur = t[i]
            if cur is UNSET:
                if isinstance(S, LazySet) and not S.finite:
                    raise EvalError(not_enumerable, loc)
                for v in _enum_checked(S, loc):
                    t[i] = v
                    k(s, t, L)
                t[i] = UNSET
            else:
                try:
                    ok = member(cur, S)
                except EvalError as err:
                    err.with_loc(loc)
                    raise
                if ok:
                    k(s, t, L)
        return assign_in

    def unchanged(self, e: A.Expr, env: Env, k: Cont, depth: int = 0) -> Code:
        """``UNCHANGED e`` as TLC (`Tool.processUnchanged`): a variable is assigned
        (or tested), a tuple is taken element by element, names without
        arguments are expanded; anything else (an operator application too)
        compares e with e'."""
        if isinstance(e, A.Name) and e.name not in env.locals:
            slot = self._scratch(env.scope.lookup(e.name), env)
            if slot is not None:  # ENABLED: the substituted expression's current value
                return self._assign(slot, self.c.expr(e, replace(env, primed=False)), k, e.loc)
        idx = self._unchanged_vars(e, env, 0)
        if idx is not None:
            for i in reversed(idx):
                k = self._assign(i, var_read(i), k, e.loc)
            return k
        if depth < 20:
            if isinstance(e, A.TupleLit):
                for x in reversed(e.elems):
                    k = self.unchanged(x, env, k, depth + 1)
                return k
            named = self._named_expr(e, env)
            if named is not None:
                return self.unchanged(named[0], named[1], k, depth + 1)
        same = self.c._unchanged_expr(e, env)
        return lambda s, t, L: k(s, t, L) if same(s, t, L) else None

    def _unchanged_vars(self, e: A.Expr, env: Env, depth: int) -> list[int] | None:
        """The variables of ``UNCHANGED e`` when e is a variable or a tuple of them,
        possibly through names (see `_named_expr`)."""
        if depth > 20:
            return None
        if isinstance(e, A.TupleLit):
            out: list[int] = []
            for x in e.elems:
                sub = self._unchanged_vars(x, env, depth + 1)
                if sub is None:
                    return None
                out.extend(sub)
            return out
        if isinstance(e, A.Name) and e.name not in env.locals \
                and self._scratch(env.scope.lookup(e.name), env) is not None:
            return None  # a scratch variable of ENABLED: see `unchanged`
        var = self._var_of(e, env)
        if var is not None:
            return [var[0]]
        named = self._named_expr(e, env)
        if named is not None:
            return self._unchanged_vars(named[0], named[1], depth + 1)
        return None


def _plain_guard(code: Code, k: Cont | None = None) -> bool:
    """Is `code` a boolean guard (made by `ActionCompiler.guard`)?  With `k`: a chain of
    guards ending in `k`, which never branches (a guard may continue with a branching
    conjunct, as in ``/\\ P /\\ (Q \\/ R)``)."""
    while getattr(code, "__name__", "") == "guard":
        code = code.cont  # type: ignore[attr-defined]
        if k is None or code is k:
            return True
    return False


def assign_run(run: list[tuple[int, Code, Loc]], k: Cont) -> Code:
    """Consecutive assignments in one closure, with the semantics of the chain of
    `_assign` closures they replace: in order, each assigns its variable if unset
    (later right-hand sides see it) or else tests it; then `k`; then undo."""
    # UNCHANGED x (and x' = x) copy s[x] without calling a closure.
    items = [(i, rhs, loc, getattr(rhs, "var", -1)) for i, rhs, loc in run]

    def assign_all(s: Any, t: Any, L: list) -> None:
        done = []
        for i, rhs, loc, src in items:
            v = s[src] if src >= 0 else rhs(s, t, L)
            cur = t[i]
            if cur is UNSET:
                t[i] = v
                done.append(i)
            elif not (cur == v if type(cur) is type(v) else _eq(cur, v, loc)):
                for j in done:
                    t[j] = UNSET
                return
        k(s, t, L)
        for j in done:
            t[j] = UNSET
    return assign_all


def _eq(a: Any, b: Any, loc: Loc) -> bool:
    try:
        return values_equal(a, b)
    except EvalError as err:
        err.with_loc(loc)
        raise


def _flat_bounds(bounds: list[A.Bound]) -> list[list[str]]:
    """Names per compiled binder, matching `Compiler.bind_bounds` (one binder per
    name, or one per tuple pattern)."""
    out: list[list[str]] = []
    for b in bounds:
        if b.tuple:
            out.append(list(b.names))
        else:
            out.extend([n] for n in b.names)
    return out


def _branches(branches: list[Code]) -> Code:
    if len(branches) == 1:
        return branches[0]
    if len(branches) == 2:
        b0, b1 = branches

        def or2(s: Any, t: Any, L: list) -> None:
            b0(s, t, L)
            b1(s, t, L)
        return or2

    def orn(s: Any, t: Any, L: list) -> None:
        for b in branches:
            b(s, t, L)
    return orn


def _exists(binds: list, body: Code) -> Code:
    if len(binds) == 1 and not binds[0][2]:
        set_code, (slot,), _, sloc = binds[0]

        def exists1(s: Any, t: Any, L: list) -> None:
            for v in _enum_checked(set_code(s, t, L), sloc):
                L[slot] = v
                body(s, t, L)
        return exists1
    # TLC (ContextEnumerator) evaluates every bound set first, then enumerates the
    # combinations like an odometer whose FIRST binder turns fastest:
    # `\E d \in D, z \in BOOLEAN` visits (d1, FALSE), (d2, FALSE), ..., (d1, TRUE), ...
    rbinds = binds[::-1]

    def exists_n(s: Any, t: Any, L: list) -> None:
        elems = [_enum_checked(b[0](s, t, L), b[3]) for b in binds]
        for combo in itertools.product(*elems[::-1]):
            for (_, slots, is_tuple, sloc), v in zip(rbinds, combo):
                assign_binder(L, slots, is_tuple, v, sloc)
            body(s, t, L)
    return exists_n


def _combos(binds: list, s: Any, t: Any, L: list) -> list[tuple]:
    """Every binding of `binds` in TLC's ContextEnumerator order (first binder fastest)."""
    elems = [list(_enum_checked(b[0](s, t, L), b[3])) for b in binds]
    return [combo[::-1] for combo in itertools.product(*elems[::-1])]


def _bind_combo(L: list, binds: list, combo: tuple) -> None:
    for (_, slots, is_tuple, sloc), v in zip(binds, combo):
        assign_binder(L, slots, is_tuple, v, sloc)


def _let(resets: list[int], body: Code) -> Code:
    if not resets:
        return body
    from .env import NOTSET

    def let(s: Any, t: Any, L: list) -> None:
        for sl in resets:
            L[sl] = NOTSET
        body(s, t, L)
    return let


def _prefix_act(pre: list, code: Code) -> Code:
    return _prefix(pre, code)


class _Found(Exception):
    pass


_FOUND = _Found()


def _found(s: Any, t: Any, L: list) -> None:
    raise _FOUND


def compile_enabled(compiler: Compiler, arg: A.Expr, env: Env) -> Code:
    """``ENABLED A``: does A have a successor from the current state?"""
    if env.init_mode:
        raise UnsupportedError("ENABLED in the initial predicate", arg.loc)
    outer = compiler.enabled_scratch
    scratch: dict[str, int] = {}
    compiler.enabled_scratch = scratch
    try:
        act = ActionCompiler(compiler).action(arg, compiler.enabled_env(env), _found)
    finally:
        compiler.enabled_scratch = outer
    n = len(compiler.var_names) + len(scratch)

    def enabled(s: Any, t: Any, L: list) -> bool:
        t2 = [UNSET] * n
        try:
            act(s, t2, L)
        except _Found:
            # One shared instance: each raise would chain its traceback (and the frames
            # it holds) onto the previous ones.
            _FOUND.__traceback__ = None
            return True
        except UnassignedPrimeError as e:
            # e.g. done' = TRUE where an INSTANCE substitutes an expression for done: TLC
            # binds the instanced module's own variable done (docs/tla-subset.md).
            raise UnsupportedError(f"ENABLED of an action that tests a primed expression before its "
                                   f"variables are assigned is not supported ({e.loc}: {e.message})", arg.loc) from None
        return False
    return enabled


__all__ = ["ActionCompiler", "Leaf", "compile_enabled", "TlaError"]
