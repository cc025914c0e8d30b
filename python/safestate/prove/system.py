"""A TLA+ model as a symbolic transition system: state variables, symbolic
constants, Init, Next, invariants and the variable domains taken from TypeOK.

Domains: each conjunct of TypeOK of the form ``x \\in S`` gives the shape and
range of variable x (``x \\in a..b``, ``x \\in [D -> S]``, ``x \\in [f : S]``,
``x \\in S1 \\cup S2``...); ``x \\in Seq(S)`` needs a conjunct ``Len(x) <= N``
whose N is a number or a constant with a bounded range.  A variable that
TypeOK does not type is "untracked": its assignments are dropped, which is
sound only because such a variable cannot be read (reading it is an error).

Constants: a CONSTANT C with an ASSUME conjunct ``C \\in S`` (S a set of
numbers, strings...) or ``C \\subseteq S`` (S a small constant finite set)
stays symbolic, constrained by every ASSUME conjunct that mentions it; any
other constant takes its .cfg value.
"""

from __future__ import annotations

import os
from dataclasses import dataclass, field
from typing import Any

import z3
from z3.z3 import _to_expr_ref  # what z3.substitute wraps its result with (not exported)

from ..checker.cfg import Config, parse_config
from ..tla import ast as A
from ..tla.errors import Loc, TlaError
from ..tla.modules import (BuiltinSym, ConstSym, DefSym, InstanceSym, ModuleLoader, Scope, SubstSym, VarSym,
                           build_root_scope, load_module)
from ..tla.values import ModelValue
from .builtins import powerset
from .obligations import Obligation, conjunction, distinct, flatten
from .sets import EnumSet, PredSet, SetV
from .translate import Ctx, Translator
from .values import UNTRACKED, ProveError, SeqV, Strings, Tup, concrete, is_z3, leaves

_TAG = [0]


class Renaming:
    """`z3.substitute(f, pairs)` with the pairs checked and converted once."""

    def __init__(self, pairs: list[tuple[z3.ExprRef, z3.ExprRef]]) -> None:
        if not all(a.sort().eq(b.sort()) for a, b in pairs):
            raise ValueError("a renaming pair of mismatching sorts")
        self.pairs = pairs  # keeps the terms alive: the arrays hold bare pointers
        self.n = len(pairs)
        self.sources = (z3.Ast * self.n)(*(a.as_ast() for a, _ in pairs))
        self.targets = (z3.Ast * self.n)(*(b.as_ast() for _, b in pairs))

    def __call__(self, f: z3.ExprRef) -> z3.ExprRef:
        return _to_expr_ref(z3.Z3_substitute(f.ctx.ref(), f.as_ast(), self.n, self.sources, self.targets), f.ctx)


@dataclass
class System:
    module: A.Module
    scope: Scope
    strings: Strings
    tr: Translator
    variables: list[str]          # tracked variables, in declaration order
    untracked: list[str]
    cur: dict[str, Any]
    nxt: dict[str, Any]
    params: dict[str, Any]        # symbolic constants -> their symbolic value
    constants_report: dict[str, Any]
    assumptions: z3.BoolRef
    domain: z3.BoolRef            # the TypeOK domains of the tracked variables
    init: z3.BoolRef
    init_aux: list[z3.ExprRef]
    trans: z3.BoolRef
    trans_aux: list[z3.ExprRef]
    init_obligations: list[Obligation] = field(default_factory=list)   # over the state and Init's inputs
    trans_obligations: list[Obligation] = field(default_factory=list)  # over s, s' and Next's inputs
    cur_leaves: list[z3.ExprRef] = field(default_factory=list)
    nxt_leaves: list[z3.ExprRef] = field(default_factory=list)
    param_leaves: list[z3.ExprRef] = field(default_factory=list)
    _copies: dict[int, list[z3.ExprRef]] = field(default_factory=dict)
    _aux: dict[int, list[z3.ExprRef]] = field(default_factory=dict)
    _renamings: dict[tuple[str, int], "Renaming"] = field(default_factory=dict)
    _base_quantified: bool | None = None
    _predicates: dict[str, tuple[z3.BoolRef, list[Obligation]]] = field(default_factory=dict)

    # ----------------------------------------------------------- formulas
    def predicate(self, name: str) -> z3.BoolRef:
        """A state predicate defined in the model (or its proofs module)."""
        return self.predicate_obligations(name)[0]

    def predicate_obligations(self, name: str) -> tuple[z3.BoolRef, list[Obligation]]:
        """A state predicate and the well-definedness obligations of evaluating it
        (translated once: a joint proof and its vacuity check ask again)."""
        if name in self._predicates:
            return self._predicates[name]
        sym = self.scope.lookup(name)
        if not isinstance(sym, DefSym) or sym.defn.params:
            raise TlaError("config", f"{name} is not a state predicate of {self.module.name}", None)
        with self.tr.obl.capture() as obligations:
            f = self.tr.boolean(sym.defn.body, Ctx(self.scope, {}, False))
        self._predicates[name] = (f, flatten(obligations))
        return self._predicates[name]

    def implications(self, name: str) -> list[tuple[str, z3.BoolRef]]:
        """The antecedents of the conjuncts of `name` written A => B, labelled by position (vacuity)."""
        sym = self.scope.lookup(name)
        if not isinstance(sym, DefSym) or sym.defn.params:
            raise TlaError("config", f"{name} is not a state predicate of {self.module.name}", None)
        out = []
        for c in _conjuncts(_expand(sym.defn.body, self.scope)):
            if isinstance(c, A.Binary) and c.op == "=>":
                with self.tr.obl.capture():
                    out.append((f"{c.loc.file}:{c.loc.line}:{c.loc.column}", self.expr(c.lhs)))
        return out

    def conjuncts(self, name: str) -> dict[str, z3.BoolRef]:
        """The top-level conjuncts of a state predicate, labelled (for CTI reports)."""
        sym = self.scope.lookup(name)
        if not isinstance(sym, DefSym) or sym.defn.params:
            raise TlaError("config", f"{name} is not a state predicate of {self.module.name}", None)
        out = {}
        for c in _conjuncts(_expand(sym.defn.body, self.scope)):
            label = f"{name}: {os.path.basename(c.loc.file)}:{c.loc.line}"
            if label in out:  # two conjuncts on one line: keep both (a dict key each)
                label = f"{label}:{c.loc.column}"
            out[label] = self.expr(c)
        return out

    def expr(self, e: A.Expr) -> z3.BoolRef:
        return self.tr.boolean(e, Ctx(self.scope, {}, False))

    def state(self, i: int) -> list[z3.ExprRef]:
        if i not in self._copies:
            self._copies[i] = [z3.Const(f"{leaf}@{i}", leaf.sort()) for leaf in self.cur_leaves]
        return self._copies[i]

    # The renamings below are built once per step: the well-definedness check of a
    # counterexample renames every obligation of Next at every step (hundreds of calls
    # with the same pairs), and z3.substitute re-checks each pair's sorts at every call.
    def _renaming(self, kind: str, i: int) -> "Renaming":
        r = self._renamings.get((kind, i))
        if r is None:
            pairs = list(zip(self.cur_leaves, self.state(i)))
            if kind == "init":
                pairs += zip(self.init_aux, [z3.Const(f"{a}@i{i}", a.sort()) for a in self.init_aux])
            elif kind == "trans":
                aux = [z3.Const(f"{a}@{i}", a.sort()) for a in self.trans_aux]
                self._aux[i] = aux
                pairs += list(zip(self.nxt_leaves, self.state(i + 1))) + list(zip(self.trans_aux, aux))
            r = self._renamings[(kind, i)] = Renaming(pairs)
        return r

    def at(self, f: z3.BoolRef, i: int) -> z3.BoolRef:
        """A state formula about step i of an unrolling."""
        return self._renaming("at", i)(f)

    def init_at(self, i: int = 0, f: z3.BoolRef | None = None) -> z3.BoolRef:
        """Init (or a formula over its state and inputs, e.g. an obligation) at step i."""
        return self._renaming("init", i)(self.init if f is None else f)

    def trans_at(self, i: int, f: z3.BoolRef | None = None) -> z3.BoolRef:
        """Next (or a formula over s, s' and its inputs) between steps i and i+1 (the
        step's own copies of the Skolem constants)."""
        return self._renaming("trans", i)(self.trans if f is None else f)

    def solver(self, *formulas: z3.ExprRef) -> z3.Solver:
        """A solver for unrollings of Init, Next and `formulas`: quantifier-free when they are.

        z3's default solver is several times slower on these unrollings than the
        one configured for QF_AUFLIA (measured on the flagship model).
        """
        if self._base_quantified is None:
            self._base_quantified = _quantified(self.init, self.trans, self.assumptions, self.domain)
        quantified = self._base_quantified or _quantified(*formulas)
        return z3.Solver() if quantified else z3.SolverFor("QF_AUFLIA")

    # ----------------------------------------------------------- models
    def state_values(self, model: z3.ModelRef, i: int | None, primed: bool = False) -> dict[str, Any]:
        """The concrete value of every tracked variable at step i (None: the template state,
        its successor when `primed`)."""
        from .values import evaluate
        rename = self._renaming("at", i) if i is not None else None  # the pairs checked once, not per term

        def ev(t: z3.ExprRef) -> z3.ExprRef:
            return model.eval(rename(t) if rename is not None else t, model_completion=True)
        state = self.nxt if primed else self.cur
        return {v: evaluate(state[v], ev, self.strings) for v in self.variables}

    def param_values(self, model: z3.ModelRef) -> dict[str, Any]:
        from .values import evaluate
        return {n: evaluate(v, lambda t: model.eval(t, model_completion=True), self.strings)
                for n, v in self.params.items() if not isinstance(v, SetV)} | {
            n: _set_value(v, model, self.strings) for n, v in self.params.items() if isinstance(v, EnumSet)}


def _quantified(*formulas: z3.BoolRef) -> bool:
    """Does one of `formulas` contain a quantifier?  Asked of z3's own probe, inside z3:
    a walk of the DAG from Python (even through the C API) cost seconds on the press,
    whose well-definedness obligations (sites under long path conditions) are asked
    about at once."""
    if not formulas:
        return False
    g = z3.Goal(ctx=formulas[0].ctx)
    g.add(conjunction(list(formulas)))
    return z3.Probe("has-quantifiers", formulas[0].ctx)(g) > 0


def _set_value(s: SetV, model: z3.ModelRef, strings: Strings) -> frozenset:
    from .values import evaluate
    assert isinstance(s, EnumSet)
    ev = lambda t: model.eval(t, model_completion=True)  # noqa: E731
    out = []
    for g, x in s.items:
        if z3.is_true(ev(g)):
            out.append(_freeze(evaluate(x, ev, strings)))
    return frozenset(out)


def _freeze(v: Any) -> Any:
    if isinstance(v, dict):
        return tuple(sorted((k, _freeze(x)) for k, x in v.items()))
    return v


# ---------------------------------------------------------------- building

def _walk(e: Any):
    stack = [e]
    while stack:
        x = stack.pop()
        if isinstance(x, list) or isinstance(x, tuple):
            stack.extend(x)
            continue
        if x is None or isinstance(x, (str, int, bool, Loc)):
            continue
        yield x
        for cls in type(x).__mro__:
            for f in getattr(cls, "__slots__", ()):
                if f != "loc":
                    stack.append(getattr(x, f, None))


def _strings_of(modules: list[A.Module], config: Config | None) -> list[str]:
    out: set[str] = set()
    for m in modules:
        for u in m.units:
            for x in _walk(u):
                if isinstance(x, A.Str):
                    out.add(x.value)
                elif isinstance(x, (A.RecLit, A.RecSet)):
                    out.update(f for f, _ in x.fields)
                elif isinstance(x, A.Dot):
                    out.add(x.field)
        for a in m.assumes:
            for x in _walk(a.expr):
                if isinstance(x, A.Str):
                    out.add(x.value)
    if config is not None:
        def add(v: Any) -> None:
            if isinstance(v, str):
                out.add(v)
            elif isinstance(v, ModelValue):
                out.add(v.name)  # type: ignore[attr-defined]
            elif isinstance(v, (frozenset, tuple)):
                for y in v:
                    add(y)
        for v, _ in config.constants.values():
            add(v)
    return sorted(out)


def _from_cfg(v: Any, strings: Strings, loc: Loc) -> Any:
    if isinstance(v, bool):
        return z3.BoolVal(v)
    if isinstance(v, int):
        return z3.IntVal(v)
    if isinstance(v, str):
        return strings.val(v, loc)
    if isinstance(v, ModelValue):
        return strings.val(v.name, loc)  # type: ignore[attr-defined]
    if isinstance(v, tuple):
        return Tup(tuple(_from_cfg(x, strings, loc) for x in v))
    if isinstance(v, frozenset):
        return EnumSet([(z3.BoolVal(True), _from_cfg(x, strings, loc)) for x in sorted(v, key=repr)])
    raise ProveError(f"constant value {v!r} of the .cfg", loc)


def _conjuncts(e: A.Expr) -> list[A.Expr]:
    if isinstance(e, A.And):
        return [c for x in e.items for c in _conjuncts(x)]
    return [e]


def _names_in(e: A.Expr) -> set[str]:
    return {x.name for x in _walk(e) if isinstance(x, (A.Name, A.Apply))}


def _all_modules(loader: ModuleLoader) -> list[A.Module]:
    return list(loader.cache.values())


def build(model_path: str, cfg_path: str | None, *, proofs_module: str | None = None,
          type_invariant: str = "TypeOK", cfg_constants: set[str] | None = None, log=lambda s: None) -> System:
    """The z3 transition system of a model: parse, constants (from the .cfg, or symbolic
    where an ASSUME gives their range), variable domains (from TypeOK), Init and Next."""
    src = _load(model_path, cfg_path, proofs_module)
    tr, ctx, consts = _constants(src, cfg_constants, log)
    var_names = [v.name for v in src.var_syms]
    cur, nxt, tracked, untracked, domain_parts, doms = _variables(tr, src.scope, type_invariant, var_names,
                                                                  model_path)
    if untracked:
        log(f"not typed by {type_invariant}, not tracked: {', '.join(untracked)}")
    tr.cur, tr.nxt = cur, nxt
    init, nxt_step = _init_and_next(tr, ctx, src, type_invariant, (cur, nxt), {v: doms[v] for v in tracked})
    sys_ = System(src.module, src.scope, src.strings, tr, tracked, untracked, cur, nxt, consts.params,
                  consts.report, z3.And(consts.constraints), z3.And(domain_parts), init.formula, init.aux,
                  nxt_step.formula, nxt_step.aux, distinct(init.obligations), distinct(nxt_step.obligations))
    sys_.cur_leaves = [x for v in tracked for x in leaves(cur[v])]
    sys_.nxt_leaves = [x for v in tracked for x in leaves(nxt[v])]
    sys_.param_leaves = [x for v in consts.params.values() for x in _param_leaves(v)]
    return sys_


@dataclass
class _Source:
    """The parsed model, its .cfg, its root scope and every module it reads."""
    path: str
    module: A.Module
    config: Config | None
    scope: Scope
    var_syms: list[Any]
    modules: list[A.Module]
    strings: Strings


def _load(model_path: str, cfg_path: str | None, proofs_module: str | None) -> _Source:
    """Parse the model (and its proofs module, merged into its scope) and its .cfg
    (default: MODEL.cfg beside it, if any); collect every string the translation meets."""
    module = load_module(model_path)
    if cfg_path is None:
        cand = os.path.splitext(model_path)[0] + ".cfg"
        cfg_path = cand if os.path.exists(cand) else None
    config = parse_config(cfg_path) if cfg_path else None
    loader = ModuleLoader(module)
    scope, var_syms = build_root_scope(module, loader)
    modules = _all_modules(loader)
    if proofs_module:
        extra = load_module(proofs_module)
        _merge_proofs_module(scope, extra, module, loader)
        modules.append(extra)
    _TAG[0] += 1
    strings = Strings(_strings_of(modules, config), str(_TAG[0]))
    return _Source(model_path, module, config, scope, var_syms, modules, strings)


@dataclass
class _Constants:
    params: dict[str, Any]      # the symbolic constants
    constraints: list[Any]      # the ASSUME conjuncts about them
    report: dict[str, Any]      # how each constant is taken


def _constants(src: _Source, cfg_constants: set[str] | None, log: Any) -> tuple[Translator, Ctx, _Constants]:
    """The translator with every constant's value: the .cfg's, or symbolic where an
    ASSUME gives its range (unless `cfg_constants` fixes it to the .cfg's)."""
    declared = {n: s for n, s in src.scope.names.items() if isinstance(s, ConstSym)}
    constants, overrides = _cfg_values(src.config, src.scope, declared, src.strings)
    tr = Translator(src.strings, constants, overrides, {}, None)
    tr.root_scope = src.scope
    tr.const_upper = {}
    ctx = Ctx(src.scope, {}, False)
    assumes = [c for m in src.modules for a in m.assumes for c in _conjuncts(a.expr)]
    fixed = set(declared) if cfg_constants is not None and not cfg_constants else (cfg_constants or set())
    if fixed - set(declared):
        raise TlaError("config", f"--cfg-constants names no constant {', '.join(sorted(fixed - set(declared)))}",
                       None)
    params, defining = _symbolic_params(tr, ctx, assumes, declared, fixed, src.strings)
    for n, v in params.items():
        constants[n] = v
        overrides.pop(n, None)
    constraints = _assume_constraints(tr, ctx, assumes, params, defining, log)
    report = _constant_report(declared, params, constants, overrides, assumes, src.config, src.strings)
    tr._memo.clear()
    return tr, ctx, _Constants(params, constraints, report)


@dataclass
class _Action:
    """Init or Next translated: the formula, its Skolem inputs and its obligations."""
    formula: z3.BoolRef
    aux: list[z3.ExprRef]
    obligations: list[Obligation]


def _init_and_next(tr: Translator, ctx: Ctx, src: _Source, type_invariant: str,
                   states: tuple[dict[str, Any], dict[str, Any]], doms: dict[str, SetV]) -> tuple[_Action, _Action]:
    """Init and Next (the .cfg's INIT/NEXT, or SPECIFICATION's parts), each with the
    well-definedness obligations of evaluating it."""
    config = src.config
    init_name = config.init.name if config and config.init else "Init"
    next_name = config.next.name if config and config.next else "Next"
    if config and config.specification and not config.init:
        init_name, next_name = _split_spec(src.scope, config.specification.name)
    tr.obl.take()  # ASSUMEs and TypeOK's sets: TLC evaluates them once, before Init (not obliged here)
    tr.assigning = True
    tr.type_invariant = type_invariant
    # A structured variable (set, function, record, sequence) is represented only inside
    # its TypeOK domain, so a value assigned outside it would make the step (or initial
    # state) disappear instead of violating TypeOK: such assignments are obliged to stay
    # in the domain (builtins._oblige_type).  A scalar can hold any value of its sort.
    actions = []
    for name, state in zip((init_name, next_name), states):  # Init assigns the state, Next the successor
        tr.assigning_next = state is states[1]
        tr.type_targets = {id(state[v]): (v, d) for v, d in doms.items() if not is_z3(state[v])}
        formula = tr.act(_def_body(src.scope, name, src.path), ctx)
        aux, tr.skolems = tr.skolems, []
        actions.append(_Action(formula, aux, tr.obl.take()))
    tr.type_targets = {}
    tr.assigning = tr.assigning_next = False
    return actions[0], actions[1]


def _cfg_values(config: Config | None, scope: Any, declared: dict[str, Any],
                strings: Strings) -> tuple[dict[str, Any], dict[str, Any]]:
    """The .cfg's constant values and overrides (ASSUME sets may mention other constants,
    so these come first)."""
    constants: dict[str, Any] = {}
    overrides: dict[str, Any] = {}
    if config is None:
        return constants, overrides
    for name, (value, loc) in config.constants.items():
        if name in declared:
            constants[name] = _from_cfg(value, strings, loc)
        elif scope.lookup(name) is not None:
            overrides[name] = _from_cfg(value, strings, loc)
    for name, (target, loc) in config.substitutions.items():
        tsym = scope.lookup(target)
        if tsym is None:
            raise TlaError("config", f"{target} (substituted for {name}) is not defined", loc)
        overrides[name] = tsym
    return constants, overrides


def _symbolic_params(tr: Translator, ctx: Ctx, assumes: list[A.Expr], declared: dict[str, Any],
                     fixed: set[str], strings: Strings) -> tuple[dict[str, Any], set[int]]:
    """Symbolic constants from the ASSUME conjuncts C \\in S and C \\subseteq S, and the
    ids of the conjuncts that define their ranges."""
    params: dict[str, Any] = {}
    defining: set[int] = set()
    for c in assumes:
        if not (isinstance(c, A.Binary) and c.op in ("\\in", "\\subseteq") and isinstance(c.lhs, A.Name)
                and c.lhs.name in declared and c.lhs.name not in params and c.lhs.name not in fixed):
            continue
        name = c.lhs.name
        try:
            s = tr.val(c.rhs, ctx)
        except TlaError:
            continue
        if c.op == "\\in" and isinstance(s, SetV) and not (isinstance(s, PredSet) and "seq_elem" in s.extra):
            try:
                v = s.fresh(name, c.loc)
            except TlaError:
                continue
            if isinstance(s, PredSet) and s.upper is not None:
                tr.const_upper[name] = s.upper
            if isinstance(s, EnumSet):
                ints = [concrete(x, strings) for _, x in s.items]
                if ints and all(isinstance(i, int) for i in ints):
                    tr.const_upper[name] = max(ints)  # type: ignore[type-var]
            params[name] = v
            defining.add(id(c))
        elif c.op == "\\subseteq" and isinstance(s, EnumSet) and len(s.items) <= 64 and \
                all(z3.is_true(g) for g, _ in s.items):
            params[name] = EnumSet([(z3.Bool(f"{name}!has{i}"), x) for i, (_, x) in enumerate(s.items)],
                                   s.items[0][1] if s.items else None)
            defining.add(id(c))
        elif c.op == "\\subseteq" and isinstance(s, PredSet) and "seq_elem" not in s.extra:
            try:
                proto = s.fresh(name + "!elem", c.loc)
            except TlaError:
                continue
            sorts = [x.sort() for x in leaves(proto)]
            if not sorts:
                continue
            # any subset of an infinite set: membership is an uninterpreted predicate
            has = z3.Function(f"{name}!has", *sorts, z3.BoolSort())
            params[name] = _uf_subset(name, s, has)
            defining.add(id(c))
    return params, defining


def _assume_constraints(tr: Translator, ctx: Ctx, assumes: list[A.Expr], params: dict[str, Any],
                        defining: set[int], log: Any) -> list[Any]:
    """The ASSUME conjuncts that constrain the symbolic constants, as z3 formulas."""
    constraints = []
    for c in assumes:
        names = _names_in(c)
        if not names & set(params):
            continue
        if id(c) in defining and isinstance(c, A.Binary) and isinstance(c.lhs, A.Name) and \
                isinstance(params.get(c.lhs.name), PredSet):
            continue  # holds by construction of the uninterpreted subset
        try:
            constraints.append(tr.boolean(c, ctx))
        except TlaError as e:
            log(f"warning: ASSUME at {c.loc} not translated ({e.message}); the proof covers more constant values")
    return constraints


def _constant_report(declared: dict[str, Any], params: dict[str, Any], constants: dict[str, Any],
                     overrides: dict[str, Any], assumes: list[A.Expr], config: Config | None,
                     strings: Strings) -> dict[str, Any]:
    """How each constant is taken (symbolic, with its ASSUMEs, or its .cfg value); a
    constant with neither is an error."""
    report: dict[str, Any] = {}
    for n in declared:
        if n in params:
            rel = [f"ASSUME {_show(c)}" for c in assumes if n in _names_in(c)]
            report[n] = "symbolic (" + "; ".join(rel) + ")"
        elif n in constants:
            report[n] = _report_value(constants[n], strings)
        elif n in overrides:
            report[n] = f"cfg: <- {config.substitutions[n][0]}" if config else "cfg"
        else:
            raise TlaError("config", f"the constant {n} has no value: give it in the .cfg or constrain it "
                                     f"with ASSUME {n} \\in S", declared[n].loc)
    return report


def _variables(tr: Translator, scope: Any, type_invariant: str, var_names: list[str], model_path: str
               ) -> tuple[dict[str, Any], dict[str, Any], list[str], list[str], list[Any], dict[str, SetV]]:
    """Current and next-state z3 variables, typed by the domains TypeOK gives; the
    variables TypeOK does not type are not tracked."""
    tsym = scope.lookup(type_invariant)
    if not isinstance(tsym, DefSym):
        raise TlaError("config", f"the model defines no {type_invariant}: the proof takes variable domains "
                                 f"from it", Loc(model_path, 1, 1))
    domains: dict[str, tuple[SetV, A.Expr]] = {}
    bounds: dict[str, tuple[A.Expr, Ctx]] = {}
    for c, cscope in _typing_conjuncts(tsym.defn.body, scope):
        cctx = Ctx(cscope, {}, False)
        if not isinstance(c, A.Binary):
            continue
        lhs = _root_var(c.lhs, cscope, var_names)
        if c.op == "\\in" and lhs is not None and lhs not in domains:
            domains[lhs] = (tr.val(c.rhs, cctx), c)
        elif c.op == "\\subseteq" and lhs is not None and lhs not in domains:
            domains[lhs] = (powerset(tr, tr.val(c.rhs, cctx), c.loc), c)
        elif c.op in ("<=", "<") and isinstance(c.lhs, A.Apply) and c.lhs.name == "Len":
            v = _root_var(c.lhs.args[0], cscope, var_names)
            if v is not None:
                rhs = c.rhs if c.op == "<=" else A.Binary(c.loc, "-", c.rhs, A.Num(c.loc, 1))
                bounds[v] = (rhs, cctx)
    cur: dict[str, Any] = {}
    nxt: dict[str, Any] = {}
    untracked = []
    domain_parts = []
    for v in var_names:
        if v not in domains:
            cur[v] = nxt[v] = UNTRACKED
            untracked.append(v)
            continue
        s, c = domains[v]
        cur[v] = _fresh_var(tr, s, v, bounds.get(v), c)
        nxt[v] = _fresh_var(tr, s, v + "'", bounds.get(v), c)
        domain_parts.append(s.member(cur[v], c.loc))
    tracked = [v for v in var_names if v not in untracked]
    return cur, nxt, tracked, untracked, domain_parts, {v: domains[v][0] for v in tracked}


def _uf_subset(name: str, s: PredSet, has: z3.FuncDeclRef) -> PredSet:
    """Any subset of the infinite set s: membership is an uninterpreted predicate `has`."""
    return PredSet(f"{name} (symbolic subset)", lambda x: z3.And(s.member(x), has(*leaves(x))),
                   lambda n: s.fresh(n), extra={"uf": has})


def _param_leaves(v: Any) -> list[z3.ExprRef]:
    if isinstance(v, PredSet):
        return []
    if isinstance(v, EnumSet):
        return [g for g, _ in v.items]
    return leaves(v)


def _show(e: A.Expr) -> str:
    if isinstance(e, A.Binary):
        return f"{_show(e.lhs)} {e.op} {_show(e.rhs)}"
    if isinstance(e, A.Name):
        return e.name
    if isinstance(e, A.Num):
        return str(e.value)
    if isinstance(e, A.SetEnum):
        return "{" + ", ".join(_show(x) for x in e.elems) + "}"
    if isinstance(e, A.Apply) and e.name == "\\X":
        return " \\X ".join(_show(x) for x in e.args)
    if isinstance(e, A.Apply):
        return f"{e.name}(" + ", ".join(_show(x) for x in e.args) + ")"
    if isinstance(e, A.TupleLit):
        return "<<" + ", ".join(_show(x) for x in e.elems) + ">>"
    if isinstance(e, A.Bool):
        return "TRUE" if e.value else "FALSE"
    if isinstance(e, A.RecSet):
        return "[" + ", ".join(f"{f} : {_show(x)}" for f, x in e.fields) + "]"
    if isinstance(e, A.Str):
        return f'"{e.value}"'
    return "..."


def _report_value(v: Any, strings: Strings) -> Any:
    c = concrete(v, strings)
    if c is not None:
        return c
    if isinstance(v, EnumSet):
        return "cfg: {" + ", ".join(str(concrete(x, strings)) for _, x in v.items) + "}"
    return "cfg"


def _expand(e: A.Expr, scope: Scope, keep_names: bool = False) -> A.Expr:
    """Unfold zero-arity definitions used as TypeOK conjuncts (TypeOK == A /\\ Other)."""
    if isinstance(e, A.And):
        return A.And(e.loc, [_expand(x, scope) for x in e.items])
    if isinstance(e, A.Name):
        sym = scope.lookup(e.name)
        if isinstance(sym, DefSym) and not sym.defn.params and not sym.defn.fn_bounds and sym.scope is scope:
            return _expand(sym.defn.body, scope)
    return e


def _typing_conjuncts(e: A.Expr, scope: Scope) -> list[tuple[A.Expr, Scope]]:
    """TypeOK's conjuncts with the scope they are written in, through definitions and M!Op."""
    if isinstance(e, A.And):
        return [x for item in e.items for x in _typing_conjuncts(item, scope)]
    if isinstance(e, A.Name):
        sym = scope.lookup(e.name)
        if isinstance(sym, DefSym) and not sym.defn.params and not sym.defn.fn_bounds:
            return _typing_conjuncts(sym.defn.body, sym.scope)
    if isinstance(e, A.Prefixed) and not e.args and all(not s.args for s in e.path):
        inner: Scope | None = scope
        for step in e.path:
            isym = inner.lookup(step.name) if inner is not None else None
            inner = isym.scope if isinstance(isym, InstanceSym) else None
        dsym = inner.lookup(e.name) if inner is not None else None
        if isinstance(dsym, DefSym) and not dsym.defn.params:
            return _typing_conjuncts(dsym.defn.body, dsym.scope)
    return [(e, scope)]


def _root_var(e: A.Expr, scope: Scope, var_names: list[str]) -> str | None:
    """The state variable an expression names, through INSTANCE substitutions (q <- buf)."""
    if not isinstance(e, A.Name):
        return None
    sym = scope.lookup(e.name)
    if isinstance(sym, VarSym) and e.name in var_names:
        return e.name
    if isinstance(sym, SubstSym):
        return _root_var(sym.expr, sym.scope, var_names)
    return None


def _fresh_var(tr: Translator, s: SetV, name: str, bound: tuple[A.Expr, Ctx] | None, c: A.Expr) -> Any:
    if isinstance(s, PredSet) and "subset_of" in s.extra:
        base = s.extra["subset_of"]
        if not (isinstance(base, EnumSet) and base.all_certain()) or len(base.items) > 256:
            raise ProveError(f"{name} is a subset of a set that is not a small constant finite set", c.loc)
        return EnumSet([(z3.Bool(f"{name}[{i}]"), x) for i, (_, x) in enumerate(base.items)],
                       base.items[0][1] if base.items else None)
    if isinstance(s, PredSet) and "seq_elem" in s.extra:
        if bound is None:
            raise ProveError(f"{name} \\in Seq(S) needs a length bound: add the TypeOK conjunct Len({name}) <= N",
                             c.loc)
        b = tr.val(bound[0], bound[1])
        cap = tr.upper_bound(b)
        if cap is None:
            raise ProveError(f"the length bound of {name} has no finite upper bound (bound its constant with "
                             f"ASSUME N \\in a..b)", bound[0].loc)
        elem: SetV = s.extra["seq_elem"]
        tr.const_upper[f"{name}.len"] = cap  # Len(x) <= cap bounds 1..Len(x)
        return SeqV(tuple(elem.fresh(f"{name}[{i + 1}]", c.loc) for i in range(cap)), z3.Int(f"{name}.len"))
    return s.fresh(name, c.loc)


def _def_body(scope: Scope, name: str, path: str) -> A.Expr:
    sym = scope.lookup(name)
    if not isinstance(sym, DefSym):
        raise TlaError("config", f"the model defines no {name}", Loc(path, 1, 1))
    return sym.defn.body


def _split_spec(scope: Scope, name: str) -> tuple[str, str]:
    sym = scope.lookup(name)
    if isinstance(sym, DefSym):
        items = _conjuncts(sym.defn.body)
        init = next((x for x in items if isinstance(x, A.Name)), None)
        box = next((x for x in items if isinstance(x, A.Unary) and x.op == "[]"), None)
        if init is not None and box is not None and isinstance(box.arg, A.StepAction) and \
                isinstance(box.arg.action, A.Name):
            return init.name, box.arg.action.name
    raise ProveError(f"SPECIFICATION {name} is not of the form Init /\\ [][Next]_v", None)


def _merge_proofs_module(scope: Scope, extra: A.Module, model: A.Module, loader: ModuleLoader) -> None:
    """Add the definitions of proofs/<Model>Proofs.tla (which EXTENDS the model) to the model's scope.

    The front end looks for extended modules beside the root module only, so the
    proofs module cannot be the root; its definitions are evaluated in the model's scope.
    """
    for name, loc in extra.extends:
        if name != model.name:
            found = loader.find(name, loc)
            if not isinstance(found, dict):
                raise ProveError(f"a proofs module may EXTEND only {model.name} and standard modules", loc)
            for n, b in found.items():
                scope.names.setdefault(n, BuiltinSym(b))
    if extra.constants or extra.variables:
        raise ProveError("a proofs module declares no CONSTANTS or VARIABLES", Loc(extra.file, 1, 1))
    for u in extra.units:
        if not isinstance(u, A.OpDef):
            raise ProveError("INSTANCE in a proofs module", u.loc)
        scope.names[u.name] = DefSym(u, scope, u.name in extra.recursive or u.fn_bounds is not None)
