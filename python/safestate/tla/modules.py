"""Module loading and name resolution scopes.

`load_module(path)` parses a ``.tla`` file into a `Module`.  `ModuleLoader` finds
modules named in EXTENDS / INSTANCE: nested modules of the same file first, then
``NAME.tla`` in the same folder, then the native standard modules.

A `Scope` maps the names visible in one module instance to symbols: state
variables (`VarSym`), CONSTANTs (`ConstSym`, valued by the .cfg), definitions
(`DefSym`), standard-library operators (`BuiltinSym`), INSTANCE substitutions
(`SubstSym`) and named instances (`InstanceSym`).  EXTENDS merges the extended
module's names into the same scope; INSTANCE builds a new scope whose constants
and variables are replaced by expressions of the instantiating scope.
"""

from __future__ import annotations

import os
from dataclasses import dataclass, field
from typing import Union

from . import ast as A
from .errors import Loc, TlaError, UnsupportedError
from .intern_order import tlc_intern_order  # noqa: F401  (its import path for checker/model.py)
from .parser import parse_text
from .stdlib import STANDARD_MODULES, UNSUPPORTED_MODULES, Builtin


def decode_source(raw: bytes) -> str:
    """A module's text: UTF-8, or else Latin-1 (TLC reads any bytes; non-ASCII can only
    appear in comments and strings, e.g. an accented name in a header comment)."""
    try:
        return raw.decode("utf-8")
    except UnicodeDecodeError:
        return raw.decode("latin-1")


def load_module(path: str) -> A.Module:
    """Parse the .tla file at `path`; returns its (first) module."""
    try:
        with open(path, "rb") as f:
            raw = f.read()
    except OSError as e:
        raise TlaError("semantic", f"cannot read module file: {e.strerror}", Loc(path, 0, 0)) from None
    modules = parse_text(decode_source(raw), path)
    root = modules[0]
    for extra in modules[1:]:
        root.submodules.setdefault(extra.name, extra)
    return root


# Folders searched for a module after the root module's own folder, like TLC's
# -DTLA-Library: os.pathsep-separated, so that a model can EXTEND or INSTANCE a module
# shared from another folder.
MODULE_PATH_ENV = "SAFESTATE_MODULE_PATH"


def module_search_path(root_folder: str) -> list[str]:
    extra = [p for p in os.environ.get(MODULE_PATH_ENV, "").split(os.pathsep) if p]
    return [root_folder] + [os.path.abspath(p) for p in extra]


class ModuleLoader:
    """Finds modules by name: the root module's folder first, then the folders of
    SAFESTATE_MODULE_PATH, then the standard modules."""

    def __init__(self, root: A.Module) -> None:
        self.root = root
        self.folder = os.path.dirname(os.path.abspath(root.file))
        self.search_path = module_search_path(self.folder)
        self.cache: dict[str, A.Module] = {root.name: root}
        self._register_submodules(root)

    def _register_submodules(self, m: A.Module) -> None:
        for name, sub in m.submodules.items():
            self.cache.setdefault(name, sub)
            self._register_submodules(sub)

    def find(self, name: str, loc: Loc) -> A.Module | dict[str, Builtin]:
        if name in self.cache:
            return self.cache[name]
        path = next((p for p in (os.path.join(d, name + ".tla") for d in self.search_path)
                     if os.path.exists(p)), None)
        if path is not None:
            mod = load_module(path)
            if mod.name != name:
                raise TlaError("semantic", f"file {name}.tla contains module {mod.name}, not {name}", loc)
            self.cache[name] = mod
            self._register_submodules(mod)
            return mod
        if name in STANDARD_MODULES:
            return STANDARD_MODULES[name]
        if name in UNSUPPORTED_MODULES:
            raise UnsupportedError(f"the standard module {name} is not supported", loc)
        raise TlaError("semantic", f"Cannot find source file for module {name} (searched "
                       f"{os.pathsep.join(self.search_path)}; more folders: {MODULE_PATH_ENV})", loc)

    def files(self) -> list[str]:
        """The files of every module loaded so far (the root's included)."""
        return sorted({m.file for m in self.cache.values() if m.file})


# ----------------------------------------------------------------- symbols


@dataclass(eq=False)
class VarSym:
    index: int
    name: str
    loc: Loc


@dataclass(eq=False)
class ConstSym:
    name: str
    arity: int
    loc: Loc


@dataclass(eq=False)
class DefSym:
    defn: A.OpDef
    scope: "Scope"
    recursive: bool
    # Filled in by the compiler (cache of the compiled form and of its level).
    compiled: object = None
    info: object = None


@dataclass(eq=False)
class BuiltinSym:
    builtin: Builtin


@dataclass(eq=False)
class SubstSym:
    """A constant or variable of an instantiated module, replaced by `expr` in `scope`."""

    name: str
    expr: A.Expr
    scope: "Scope"
    instance_params: tuple[str, ...] = ()
    variable: bool = False  # a VARIABLE (not a CONSTANT) of the instanced module


@dataclass(eq=False)
class InstanceSym:
    inst: A.InstanceDef
    scope: "Scope"  # the instantiated module's scope
    module: A.Module
    # An INSTANCE inside LET: the names bound where it is defined, which its
    # substitutions may use; they are passed on at each use (``I!Op``).
    let_locals: tuple[str, ...] = ()


Symbol = Union[VarSym, ConstSym, DefSym, BuiltinSym, SubstSym, InstanceSym]


@dataclass(eq=False)
class Scope:
    module: A.Module
    loader: ModuleLoader
    names: dict[str, Symbol] = field(default_factory=dict)
    # True for `M(p) == INSTANCE ...` scopes: definitions are expanded at each use.
    parameterised: bool = False
    instance_params: tuple[str, ...] = ()

    def lookup(self, name: str) -> Symbol | None:
        return self.names.get(name)


def build_root_scope(root: A.Module, loader: ModuleLoader) -> tuple[Scope, list[VarSym]]:
    """The scope of the module being checked; returns it and its variables in order."""
    scope = Scope(root, loader)
    variables: list[VarSym] = []
    _fill(scope, root, None, variables, set())
    return scope, variables


def _enclosing_names(scope: Scope, mod: A.Module, outer: Scope | None) -> None:
    """A module nested in another sees what the enclosing module declares, defines and
    EXTENDS before it (SANY): the standard modules the enclosing modules extend, and,
    when the nested module is instanced from its enclosing module (`outer`), that
    module's definitions, constants and variables.  The nested module's own names,
    filled in after these, take precedence."""
    enclosing = _enclosing_module(scope.loader, mod)
    if enclosing is None:
        return
    if outer is not None and outer.module is enclosing:
        for name, sym in outer.names.items():
            scope.names.setdefault(name, sym)
    seen: set[str] = set()
    while enclosing is not None and enclosing.name not in seen:
        seen.add(enclosing.name)
        for name, loc in enclosing.extends:
            ext = scope.loader.find(name, loc)
            if isinstance(ext, dict):
                _add_builtins(scope, ext)
        enclosing = _enclosing_module(scope.loader, enclosing)


def _enclosing_module(loader: ModuleLoader, mod: A.Module) -> A.Module | None:
    for m in loader.cache.values():
        if m.submodules.get(mod.name) is mod:
            return m
    return None


def _fill(scope: Scope, mod: A.Module, substs: dict[str, SubstSym] | None,
          variables: list[VarSym], visiting: set[str], outer: Scope | None = None) -> None:
    if mod.name in visiting:
        raise TlaError("semantic", f"circular EXTENDS/INSTANCE of module {mod.name}", A.Loc(mod.file, 1, 1))
    visiting = visiting | {mod.name}
    _enclosing_names(scope, mod, outer)
    for name, loc in mod.extends:
        ext = scope.loader.find(name, loc)
        if isinstance(ext, dict):
            _add_builtins(scope, ext)
        else:
            _fill(scope, ext, substs, variables, visiting)
    for c in mod.constants:
        if substs is not None:
            scope.names[c.name] = substs[c.name]
        else:
            scope.names[c.name] = ConstSym(c.name, c.arity, c.loc)
    declared: set[str] = set()
    for v in mod.variables:
        if v.name in declared:
            continue  # declared again: the same variable (SANY only warns)
        declared.add(v.name)
        if substs is not None:
            scope.names[v.name] = substs[v.name]
        else:
            sym = VarSym(len(variables), v.name, v.loc)
            variables.append(sym)
            scope.names[v.name] = sym
    for unit in mod.units:
        if isinstance(unit, A.OpDef):
            scope.names[unit.name] = DefSym(unit, scope, unit.name in mod.recursive or unit.fn_bounds is not None)
        else:
            _instance(scope, unit, visiting)
    # A named ASSUME or THEOREM (``ASSUME A1 == N > 0``) is an operator without
    # arguments whose body is its statement: TLC evaluates ``A1`` in an expression.
    statements = [(a.name, a.expr, a.loc) for a in mod.assumes] + list(mod.theorems)
    for label, expr, at in statements:
        if label is not None and label not in scope.names:
            scope.names[label] = DefSym(A.OpDef(label, [], expr, at), scope, False)


def _add_builtins(scope: Scope, module: dict[str, Builtin]) -> None:
    for name, b in module.items():
        scope.names.setdefault(name, BuiltinSym(b))


def instance_parameters(mod: A.Module, loader: ModuleLoader, variables_only: bool = False) -> list[A.Param]:
    """CONSTANTs and VARIABLEs of `mod` (only its VARIABLEs if `variables_only`),
    including those of modules it EXTENDS."""
    out: list[A.Param] = []
    for name, loc in mod.extends:
        ext = loader.find(name, loc)
        if not isinstance(ext, dict):
            out.extend(instance_parameters(ext, loader, variables_only))
    return out + ([] if variables_only else mod.constants) + mod.variables


def let_instance_scope(scope: Scope, inst: A.InstanceDef, let_locals: tuple[str, ...]) -> Scope:
    """The scope of a LET body that defines ``I == INSTANCE M ...``: `scope` plus I.  The
    instance is parameterised by the names bound at the LET (`let_locals`)."""
    inner = Scope(scope.module, scope.loader, dict(scope.names), scope.parameterised, scope.instance_params)
    _instance(inner, inst, set(), let_locals)
    return inner


def _instance(scope: Scope, inst: A.InstanceDef, visiting: set[str], let_locals: tuple[str, ...] = ()) -> None:
    target = scope.loader.find(inst.module, inst.loc)
    if isinstance(target, dict):
        if inst.name is None:
            _add_builtins(scope, target)
        else:
            raise UnsupportedError(f"named INSTANCE of the standard module {inst.module}", inst.loc)
        return
    params = tuple(p.name for p in inst.params) + let_locals
    explicit = dict(inst.substs)
    substs: dict[str, SubstSym] = {}
    variables = {p.name for p in instance_parameters(target, scope.loader, variables_only=True)}
    for p in instance_parameters(target, scope.loader):
        if p.name in explicit:
            substs[p.name] = SubstSym(p.name, explicit[p.name], scope, params, p.name in variables)
        elif p.name in params or scope.lookup(p.name) is not None:
            substs[p.name] = SubstSym(p.name, A.Name(inst.loc, p.name), scope, params, p.name in variables)
        else:
            raise TlaError("semantic", f"INSTANCE of {inst.module} has no substitution for {p.name} and "
                           f"the instantiating module declares no {p.name}", inst.loc)
    unknown = set(explicit) - set(substs)
    if unknown:
        raise TlaError("semantic", f"INSTANCE substitutes {', '.join(sorted(unknown))}, which "
                       f"{inst.module} does not declare", inst.loc)
    inner = Scope(target, scope.loader, parameterised=bool(params) or scope.parameterised,
                  instance_params=params + scope.instance_params)
    _fill(inner, target, substs, [], visiting, scope)
    if inst.name is None:
        for name, sym in inner.names.items():
            if isinstance(sym, (DefSym, BuiltinSym, InstanceSym)) and not (
                    isinstance(sym, DefSym) and sym.defn.local):
                scope.names[name] = sym
    else:
        scope.names[inst.name] = InstanceSym(inst, inner, target, let_locals)
