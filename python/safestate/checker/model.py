"""A checkable model: a TLA+ module, its .cfg, and everything compiled from them.

Public API (stable; used by the conformance and proof tools)::

    model = load_model("Spec.tla")            # Spec.cfg beside it by default
    model.variables                           # ["x", "y"], the state layout
    for s in model.initial_states(): ...      # states are tuples in variable order
    for tr in model.successors(s):            # Transition(action, params, state)
        ...
    model.invariant_violations(s)             # names of the invariants s violates
    model.eval_in_state("x + 1", s)           # an expression or a definition name
    model.state_to_itf(s) / model.state_from_itf(obj)

Initial states and successors come in TLC's order, duplicates included (TLC
counts them as "states generated").
"""

from __future__ import annotations

import os
from dataclasses import dataclass, field
from typing import Any, Callable

from ..tla import ast as A
from ..tla.actions import ActionCompiler, Leaf
from ..tla.compiler import Compiler
from ..tla.env import UNSET, Env, Frame
from ..tla.errors import EvalError, Loc, TlaError, UnsupportedError
from ..tla.modules import (BuiltinSym, ConstSym, DefSym, InstanceSym, ModuleLoader, Scope, VarSym, build_root_scope,
                           load_module, tlc_intern_order)
from ..tla.parser import parse_text
from ..tla.resolve import check_modules
from ..tla.tlcget import RUNTIME
from ..tla.values import FnValue, Value, as_set, fmt, register_token_order, reset_token_order
from .cfg import Config, ConfigEntry, parse_config
from .deep_stack import call_with_deep_stack, stack_overflow_message
from .itf import state_from_itf, state_to_itf
from .int_range import check_numerals
from .storable import check_storable
from .symmetry import SymmetryReduction, permutation_group
from .temporal import Fairness, Obligation, TemporalCompiler


@dataclass
class Transition:
    action: str
    params: dict[str, Value]
    state: tuple


@dataclass
class Named:
    name: str
    loc: Loc
    fn: Callable[..., Value]


@dataclass
class Model:
    module: A.Module
    config: Config
    scope: Scope
    variables: list[str]
    compiler: Compiler
    check_deadlock: bool
    invariants: list[Named] = field(default_factory=list)
    constraints: list[Named] = field(default_factory=list)
    action_constraints: list[Named] = field(default_factory=list)
    properties: list[str] = field(default_factory=list)
    # From the specification and the PROPERTY conjuncts (see temporal.py).
    fairness_exprs: list[A.Expr] = field(default_factory=list)
    fairness: list[Fairness] = field(default_factory=list)
    init_properties: list[Named] = field(default_factory=list)
    action_properties: list[Named] = field(default_factory=list)
    liveness: list[Obligation] = field(default_factory=list)
    view: Named | None = None
    # Every module file the model was read from (the root, EXTENDS and INSTANCE).
    module_files: list[str] = field(default_factory=list)
    # ALIAS: the record shown instead of the variables in a text counterexample.
    alias: Named | None = None
    # POSTCONDITION: evaluated once after a search that found no error.
    postcondition: Named | None = None
    symmetry: SymmetryReduction | None = None
    leaves: list[Leaf] = field(default_factory=list)
    _init: Any = None
    _init_size: int = 0
    _next: Any = None
    _next_size: int = 0
    # The continuation at the end of Init/Next calls sink[0](state, leaf_index, frame).
    sink: list = field(default_factory=lambda: [None])
    next_name: str = "Next"
    # Init and Next as expressions (for the native engine's translator).
    init_expr: A.Expr | None = None
    next_expr: A.Expr | None = None

    # ---------------------------------------------------------------- generation
    def run_init(self, callback: Callable[[tuple, int, list], None]) -> None:
        """Call `callback(state, -1, frame)` for each initial state, in TLC order."""
        self.sink[0] = callback
        self._init(None, [UNSET] * len(self.variables), [None] * self._init_size)

    def run_next(self, state: tuple, callback: Callable[[tuple, int, list], None]) -> None:
        """Call `callback(successor, leaf_index, frame)` for each successor, in TLC order."""
        self.sink[0] = callback
        self._next(state, [UNSET] * len(self.variables), [None] * self._next_size)

    def initial_states(self) -> list[tuple]:
        out: list[tuple] = []

        def add(st: tuple, leaf: int, L: list) -> None:
            self.check_complete(st, None)
            out.append(st)
        self.run_init(add)
        return out

    def successors(self, state: tuple) -> list[Transition]:
        out: list[Transition] = []

        def add(st: tuple, leaf: int, L: list) -> None:
            self.check_complete(st, leaf)
            lf = self.leaves[leaf]
            out.append(Transition(lf.name, {n: L[sl] for n, sl in lf.params}, st))
        self.run_next(state, add)
        return out

    def leaf_params(self, leaf: int, L: list) -> dict[str, Value]:
        return {n: L[sl] for n, sl in self.leaves[leaf].params}

    def check_complete(self, st: tuple, leaf: int | None) -> None:
        if UNSET not in st:
            return
        missing = [v for v, x in zip(self.variables, st) if x is UNSET]
        plural = " is" if len(missing) == 1 else "s are"
        if leaf is None:
            raise TlaError("eval", f"State is not completely specified by the initial predicate: the "
                           f"following variable{plural} not defined: {', '.join(missing)}.",
                           self.module_loc())
        lf = self.leaves[leaf]
        raise TlaError("eval", f"Successor state is not completely specified by action {lf.name} of the "
                       f"next-state relation. The following variable{plural} not defined: "
                       f"{', '.join(missing)}.", lf.loc)

    def check_storable(self, st: tuple, leaf: int | None) -> None:
        """TLC's error for a new state holding a value it cannot fingerprint (storable.py)."""
        if leaf is not None:
            loc = self.leaves[leaf].loc
        else:
            sym = self.scope.lookup(self.init_expr.name) if isinstance(self.init_expr, A.Name) else None
            loc = sym.defn.loc if isinstance(sym, DefSym) else self.module_loc()
        check_storable(st, self.variables, loc)

    def module_loc(self) -> Loc:
        return Loc(self.module.file, 1, 1)

    # ---------------------------------------------------------------- checks
    def invariant_violations(self, state: tuple) -> list[str]:
        return [inv.name for inv in self.invariants if not self.holds(inv, state)]

    def holds(self, named: Named, state: tuple, nxt: tuple | None = None) -> bool:
        v = named.fn(state, nxt)
        if v is True or v is False:
            return v
        raise EvalError(f"The value of {named.name} is not a boolean: {fmt(v)}", named.loc)

    def in_model(self, state: tuple) -> bool:
        for c in self.constraints:
            if not self.holds(c, state):
                return False
        return True

    def action_ok(self, state: tuple, nxt: tuple) -> bool:
        for c in self.action_constraints:
            if not self.holds(c, state, nxt):
                return False
        return True

    def key(self, state: tuple) -> Any:
        """The value TLC fingerprints: the state reduced by SYMMETRY (its smallest image),
        then the VIEW (if any) of that."""
        if self.symmetry:
            state = self.symmetry.smallest_image(state)
        return state if self.view is None else self.view.fn(state, None)

    # ---------------------------------------------------------------- evaluation API
    def eval_in_state(self, expr: str, state: tuple | None) -> Value:
        """Evaluate an expression text, or the name of a definition, in `state`."""
        text = f"---- MODULE __Eval ----\n__E == {expr}\n===="
        mod = parse_text(text, "<expression>")[0]
        body = mod.units[0].body  # type: ignore[union-attr]
        fn = self.compiler.evaluator(body, self.scope)
        return fn(state, None)

    def state_to_itf(self, state: tuple, meta: dict | None = None) -> dict:
        return state_to_itf(self.variables, state, meta)

    def state_from_itf(self, obj: dict) -> tuple:
        return state_from_itf(self.variables, obj)

    def format_state(self, state: tuple) -> str:
        """TLC's rendering of a state: one ``/\\ x = v`` line per variable, or per field
        of the ALIAS record."""
        pairs: list[tuple[str, Value]] = list(zip(self.variables, state))
        if self.alias is not None:
            rec = self.alias.fn(state, None)
            if type(rec) is not FnValue or not all(type(k) is str for k in rec.d):
                raise EvalError(f"The ALIAS {self.alias.name} must be a record, not {fmt(rec)}", self.alias.loc)
            pairs = list(rec.d.items())
        if len(pairs) == 1:
            return f"{pairs[0][0]} = {fmt(pairs[0][1])}"
        return "\n".join(f"/\\ {n} = {fmt(v)}" for n, v in pairs)


# ====================================================================== loading


def default_config_path(tla_path: str) -> str:
    return os.path.splitext(tla_path)[0] + ".cfg"


def load_model(tla_path: str, cfg_path: str | None = None) -> Model:
    """Parse, resolve and compile a model.  Raises `TlaError` on any problem; a recursion
    that does not end in an ASSUME or a constant is TLC's StackOverflowError (exit 255)."""
    try:
        return call_with_deep_stack(lambda: _load_model(tla_path, cfg_path))
    except RecursionError:
        raise TlaError("stack overflow", stack_overflow_message("loading the model")) from None


def _load_model(tla_path: str, cfg_path: str | None) -> Model:
    RUNTIME.reset()
    RUNTIME.used = False
    module = load_module(tla_path)
    cfg_path = cfg_path or default_config_path(tla_path)
    if not os.path.exists(cfg_path):
        raise TlaError("config", f"configuration file {os.path.basename(cfg_path)} not found (give one with "
                       f"--config)", Loc(cfg_path, 0, 0))
    try:
        config = parse_config(cfg_path)
    except TlaError as e:
        # TLC: a cfg that does not parse is a ConfigFileException, exit 255 (not 151).
        if e.kind != "config":
            raise
        raise TlaError("cfg syntax", e.message, e.loc) from None
    reset_token_order()
    register_token_order(config.tokens)
    loader = ModuleLoader(module)
    scope, var_syms = build_root_scope(module, loader)
    check_modules(module, loader)
    check_numerals(loader.cache.values())
    register_token_order(tlc_intern_order(loader))
    constants, overrides = _constants(config, scope, module)
    compiler = Compiler(constants, overrides)
    compiler.sym_overrides = {id(scope.lookup(n)): target for n, target in overrides.items()}
    compiler.sym_overrides.update(_module_overrides(config, scope, loader))
    compiler.var_names = [v.name for v in var_syms]
    model = Model(module, config, scope, [v.name for v in var_syms], compiler, config.check_deadlock)
    _check_assumptions(model, loader)
    model.module_files = loader.files()
    _compile_behaviour(model)
    model.invariants = [_predicate(model, e, "invariant") for e in config.invariants]
    model.constraints = [_predicate(model, e, "constraint") for e in config.constraints]
    model.action_constraints = [_predicate(model, e, "action constraint", action=True)
                                for e in config.action_constraints]
    model.properties = [p.name for p in config.properties]
    _compile_properties(model)
    if config.view is not None:
        model.view = _predicate(model, config.view, "view", boolean=False)
    if config.symmetry is not None:
        model.symmetry = _symmetry(model, config.symmetry)
    if config.alias is not None:
        model.alias = _predicate(model, config.alias, "alias", boolean=False)
    if config.postcondition is not None:
        model.postcondition = _predicate(model, config.postcondition, "postcondition")
        if any(v >= 0 for v in model.compiler.def_info(_lookup_def(model, config.postcondition,
                                                                       "postcondition")).vars):
            raise UnsupportedError(f"the postcondition {config.postcondition.name} reads state variables; "
                                   f"only constant-level postconditions (TLCGet, ...) are supported",
                                   config.postcondition.loc)
    return model


def _compile_properties(model: Model) -> None:
    """Sort the PROPERTY conjuncts as TLC does: state predicates are checked on the
    initial states, []P joins the invariants, [][A]_v is checked on every step and
    the rest is liveness, checked on the state graph under the spec's fairness."""
    tc = TemporalCompiler(model)
    if model.fairness_exprs:
        model.fairness = tc.fairness(A.And(model.fairness_exprs[0].loc, model.fairness_exprs))
    for entry in model.config.properties:
        sym = _lookup_def(model, entry, "property")
        for ob in tc.obligations(entry.name, A.Name(sym.defn.loc, entry.name), model.scope):
            named = Named(entry.name, ob.p.loc, ob.p)
            if ob.kind == "always":
                model.invariants.append(Named(entry.name, ob.p.loc, lambda s, t, p=ob.p: p(s)))
            elif ob.kind == "init":
                model.init_properties.append(Named(entry.name, ob.p.loc, lambda s, t, p=ob.p: p(s)))
            elif ob.kind == "action":
                model.action_properties.append(named)
            else:
                model.liveness.append(ob)


def _constants(config: Config, scope: Scope, module: A.Module) -> tuple[dict[str, Value], dict[str, Any]]:
    values: dict[str, Value] = {}
    overrides: dict[str, Any] = {}
    declared = {n: s for n, s in scope.names.items() if isinstance(s, ConstSym)}
    for name, (value, _loc) in config.constants.items():
        sym = scope.lookup(name)
        if sym is None:
            continue  # TLC ignores a value for a name the spec does not have (not so for `<-`)
        if isinstance(sym, ConstSym):
            values[name] = value
        else:
            # TLC lets the .cfg override a definition with a value too.
            overrides[name] = _ValueSym(value)
    for name, (target, loc) in config.substitutions.items():
        sym = scope.lookup(name)
        tsym = scope.lookup(target)
        if sym is None:
            raise TlaError("config", f"In the configuration file, the identifier {name} does not appear in the "
                           f"specification.", loc)
        if tsym is None:
            raise TlaError("config", f"The configuration file substitutes {name} with {target}, which is not "
                           f"defined in the specification.", loc)
        overrides[name] = tsym
    for name, sym in declared.items():
        if name not in values and name not in overrides:
            raise TlaError("config", f"The constant parameter {name} is not assigned a value by the "
                           f"configuration file.", sym.loc)
    return values, overrides


def _module_overrides(config: Config, scope: Scope, loader: ModuleLoader) -> dict[int, Any]:
    """``Op <- [M] Def``: every copy of M's definition Op (in each INSTANCE of M, or
    where M is extended) stands for the spec's definition Def, as in TLC."""
    out: dict[int, Any] = {}
    for name, module, target, loc in config.module_substitutions:
        if module not in _module_names(scope.module, loader):
            raise TlaError("config", f"In the configuration file, the module name {module} is not a module in "
                           f"the specification.", loc)
        mod = loader.find(module, loc)
        defn = next((u for u in mod.units if isinstance(u, A.OpDef) and u.name == name), None) \
            if isinstance(mod, A.Module) else None
        if defn is None:
            raise TlaError("config", f"In the configuration file, the identifier {name} does not appear in the "
                           f"specification.", loc)
        tsym = scope.lookup(target)
        if tsym is None:
            raise TlaError("config", f"The configuration file substitutes for {name} with the undefined "
                           f"identifier {target}.", loc)
        for sym in _defs_of(scope, defn):
            out[id(sym)] = tsym
    return out


def _module_names(root: A.Module, loader: ModuleLoader) -> set[str]:
    """Names of the modules the spec extends or instantiates, directly or not."""
    seen: set[str] = set()
    todo = [root]
    while todo:
        m = todo.pop()
        if m.name in seen:
            continue
        seen.add(m.name)
        deps = list(m.extends) + [(u.module, u.loc) for u in m.units if isinstance(u, A.InstanceDef)]
        for name, where in deps:
            found = loader.find(name, where)
            if isinstance(found, A.Module):
                todo.append(found)
    return seen


def _defs_of(scope: Scope, defn: A.OpDef) -> list[DefSym]:
    """Every symbol for `defn` in `scope` and the scopes of its instances."""
    out: list[DefSym] = []
    seen: set[int] = set()
    todo = [scope]
    while todo:
        sc = todo.pop()
        if id(sc) in seen:
            continue
        seen.add(id(sc))
        for sym in sc.names.values():
            if isinstance(sym, DefSym) and sym.defn is defn:
                out.append(sym)
            elif isinstance(sym, InstanceSym):
                todo.append(sym.scope)
    return out


class _ValueSym(ConstSym):
    """A definition overridden by a value in the .cfg."""

    def __init__(self, value: Value) -> None:
        super().__init__("<cfg value>", 0, Loc("<cfg>", 0, 0))
        self.value = value


def _check_assumptions(model: Model, loader: ModuleLoader) -> None:
    for mod in _modules_in_order(model.module, loader):
        for a in mod.assumes:
            fn = model.compiler.evaluator(a.expr, model.scope)
            try:
                v = fn(None, None)
            except EvalError as e:
                raise TlaError("assumption", f"Evaluating assumption line {a.expr.loc.line}, col {a.expr.loc.column} of "
                               f"module {mod.name} failed.\n{e.message}", e.loc or a.expr.loc) from None
            if v is not True:
                raise TlaError("assumption", f"Assumption line {a.expr.loc.line}, col {a.expr.loc.column} of "
                               f"module {mod.name} is false.", a.expr.loc)


def _modules_in_order(root: A.Module, loader: ModuleLoader) -> list[A.Module]:
    out: list[A.Module] = []

    def visit(m: A.Module) -> None:
        if m in out:
            return
        for name, loc in m.extends:
            ext = loader.find(name, loc)
            if isinstance(ext, A.Module):
                visit(ext)
        out.append(m)
    visit(root)
    return out


def _lookup_def(model: Model, entry: ConfigEntry, what: str) -> DefSym:
    sym = model.scope.lookup(entry.name)
    if not isinstance(sym, DefSym):
        raise TlaError("config", f"The {what} {entry.name} specified in the configuration file is not defined "
                       f"in the specification.", entry.loc)
    return sym


# TLC's exit status for a cfg entry above state level: an INVARIANT is its
# TLC_INVARIANT_VIOLATED_LEVEL (76, SpecProcessor.processConfigInvariants); a CONSTRAINT
# is not level-checked, it fails to evaluate on the first state (75).
_LEVEL_KIND = {"invariant": "invariant eval", "constraint": "eval"}


def _predicate(model: Model, entry: ConfigEntry, what: str, action: bool = False, boolean: bool = True) -> Named:
    sym = _lookup_def(model, entry, what)
    if sym.defn.params:
        raise TlaError("config", f"The {what} {entry.name} must be an operator without arguments.", entry.loc)
    info = model.compiler.def_info(sym)
    temporal = what in _LEVEL_KIND and TemporalCompiler(model).is_temporal(sym.defn.body, sym.scope)
    if (info.action or temporal) and not action:
        level = "a temporal formula" if temporal else "an action"
        raise TlaError(_LEVEL_KIND.get(what, "config"), f"The {what} {entry.name} is {level}; only state "
                       f"predicates are allowed here.", sym.defn.loc)
    code, size = model.compiler.compile_unit(A.Name(sym.defn.loc, entry.name), model.scope)
    loc = sym.defn.loc
    if boolean and not info.vars and not info.action:
        _constant_predicate(entry, what, code, size)
    if action:
        return Named(entry.name, loc, lambda s, t: code(s, t, [None] * size))
    return Named(entry.name, loc, lambda s, t: code(s, None, [None] * size))


def _constant_predicate(entry: ConfigEntry, what: str, code: Any, size: int) -> None:
    """TLC evaluates constant definitions at start-up; an invariant or constraint
    that is then anything but TRUE is a cfg error (`TLC_CONFIG_ID_HAS_VALUE`).  An
    evaluation error is left to be reported during the search, as TLC does."""
    try:
        v = code(None, None, [None] * size)
    except EvalError:
        return
    if v is not True:
        raise TlaError("config", f"The {what} of {entry.name} is equal to {fmt(v)}", entry.loc)


# ---------------------------------------------------------------------- Init / Next


def _not_constant(model: Model, sym: DefSym, entry: ConfigEntry, what: str) -> None:
    """TLC evaluates every constant-level definition at start-up and then finds a
    value, not an operator, under an INIT or NEXT that reads no variable
    (`SpecProcessor.processConfigInitAndNext`): ``Init == FALSE`` is "The initial
    predicate Init cannot be a constant." (exit 151), not a model without states.
    A definition whose evaluation fails stays an operator, as in TLC."""
    if sym.defn.params or sym.defn.fn_bounds is not None:
        return
    info = model.compiler.def_info(sym)
    if info.vars or info.action:
        return
    code, size = model.compiler.compile_unit(A.Name(sym.defn.loc, entry.name), model.scope)
    try:
        code(None, None, [None] * size)
    except TlaError:
        return
    raise TlaError("config", f"The {what} {entry.name} cannot be a constant.", entry.loc)


def _compile_behaviour(model: Model) -> None:
    cfg = model.config
    if cfg.specification is not None:
        if cfg.init is not None or cfg.next is not None:
            raise TlaError("config", "The configuration file specifies both SPECIFICATION and INIT/NEXT.",
                           cfg.specification.loc)
        init, nxt = _split_spec(model, cfg.specification)
    elif cfg.init is None and cfg.next is None:
        # No behaviour: TLC only evaluates the ASSUMEs and reports 0 states.
        model._init = model._next = lambda s, t, L: None
        return
    else:
        if cfg.init is None:
            raise TlaError("config", "The configuration file did not specify the initial state predicate.",
                           Loc(cfg.file, 1, 1))
        if cfg.next is None:
            raise TlaError("config", "The configuration file did not specify the next state predicate.",
                           Loc(cfg.file, 1, 1))
        _lookup_def(model, cfg.init, "initial predicate")
        _lookup_def(model, cfg.next, "next-state relation")
        init = A.Name(cfg.init.loc, cfg.init.name)
        nxt = A.Name(cfg.next.loc, cfg.next.name)
    model.next_name = nxt.name if isinstance(nxt, A.Name) else "Next"
    model.init_expr, model.next_expr = init, nxt
    ac = ActionCompiler(model.compiler)
    sink = model.sink

    init_frame = Frame()

    def emit_init(s: Any, t: list, L: list) -> None:
        sink[0](tuple(t), -1, L)
    model._init = ac.action(init, Env(model.scope, init_frame, init_mode=True), emit_init)
    model._init_size = init_frame.size

    next_frame = Frame()

    def make_k(leaf: Leaf) -> Callable:
        index = len(model.leaves)
        model.leaves.append(leaf)

        def emit(s: Any, t: list, L: list) -> None:
            sink[0](tuple(t), index, L)
        return emit
    model._next = ac.split(nxt, Env(model.scope, next_frame), model.next_name, nxt.loc, [], make_k)
    model._next_size = next_frame.size
    if cfg.specification is None and cfg.init is not None and cfg.next is not None:
        # After compiling them: the analysis must not be the first to meet a LET's
        # INSTANCE (it would fix the instance's scope without the names bound there).
        _not_constant(model, _lookup_def(model, cfg.init, "initial predicate"), cfg.init, "initial predicate")
        _not_constant(model, _lookup_def(model, cfg.next, "next-state relation"), cfg.next, "next state action")


def _split_spec(model: Model, entry: ConfigEntry) -> tuple[A.Expr, A.Expr]:
    """SPECIFICATION Spec with Spec == Init /\\ [][Next]_vars /\\ fairness."""
    sym = _lookup_def(model, entry, "specification")
    tc = TemporalCompiler(model)
    inits: list[A.Expr] = []
    nexts: list[A.Expr] = []

    def visit(e: A.Expr, depth: int) -> None:
        if isinstance(e, A.And):
            for i in e.items:
                visit(i, depth)
            return
        if isinstance(e, A.Name) and depth < 20:
            s = model.scope.lookup(e.name)
            if isinstance(s, DefSym) and not s.defn.params and tc.is_temporal(s.defn.body, s.scope):
                visit(s.defn.body, depth + 1)
                return
        if isinstance(e, A.Unary) and e.op == "[]":
            if isinstance(e.arg, A.StepAction) and e.arg.stutter:
                nexts.append(e.arg.action)
                return
            raise UnsupportedError("only [][Next]_vars is supported as the box formula of a specification", e.loc)
        if tc.is_temporal(e, model.scope):
            # Fairness (checked by TemporalCompiler.fairness, which refuses anything else):
            # it does not affect safety checking.
            model.fairness_exprs.append(e)
            return
        inits.append(e)

    visit(sym.defn.body, 0)
    if not nexts:
        cfg = model.config
        # TLC: with an invariant or property to check, TLC_CONFIG_MISSING_NEXT (151);
        # without, TLC_STATES_AND_NO_NEXT_ACTION after the initial states (75).
        kind = "config" if cfg.invariants or cfg.properties else "eval"
        raise TlaError(kind, f"The specification {entry.name} has no [][Next]_vars conjunct: no next-state "
                       f"action to generate successor states from.", sym.defn.loc)
    if len(nexts) > 1:
        raise UnsupportedError("a specification with several [][Next]_v conjuncts", sym.defn.loc)
    if not inits:
        raise TlaError("config", f"The specification {entry.name} has no initial predicate.", sym.defn.loc)
    init = inits[0] if len(inits) == 1 else A.And(inits[0].loc, inits)
    return init, nexts[0]


def _symmetry(model: Model, entry: ConfigEntry) -> SymmetryReduction:
    sym = _lookup_def(model, entry, "symmetry")
    fn = model.compiler.evaluator(A.Name(sym.defn.loc, entry.name), model.scope)
    perms = []
    value = fn(None, None)
    try:
        elements = as_set(value)
    except TlaError:
        # TLC: Assert.fail("The symmetry operator must specify a set of functions."), exit 255.
        raise TlaError("general", f"The symmetry operator {entry.name} must specify a set of functions "
                       f"(permutations of model values); it is {fmt(value)}", sym.defn.loc) from None
    for p in elements:
        if type(p) is FnValue:
            perms.append(dict(p.d))
        elif type(p) is tuple and not p:
            perms.append({})
        else:
            raise TlaError("config", f"The symmetry set {entry.name} must contain permutations (functions "
                           f"between model values); found {fmt(p)}", entry.loc)
    return SymmetryReduction(permutation_group(perms))


__all__ = ["Model", "Transition", "load_model", "BuiltinSym", "VarSym"]
