"""Whole-module name resolution, as SANY does before TLC checks anything.

The compiler resolves only what Init, Next, the invariants and the ASSUMEs reach.
SANY resolves every definition, ASSUME and THEOREM statement of every module, in
source order, so TLC rejects (exit code 150) a module in which

* a name is used that is not declared or defined *before* the use
  (``Unknown operator: `X'.``),
* an operator is applied to the wrong number of arguments
  (``The operator X requires N arguments.``),
* a name is defined or declared twice (``Operator X already defined or declared.``),
* a bound variable, operator parameter or LET definition reuses a name that is
  already visible there (``Multiply-defined symbol 'X'``),
* a LET operator refers to itself without a RECURSIVE declaration in its LET
  (``Unknown operator``: SANY makes a LET definition visible only after it),
* a record constructor names a field twice (``Non-unique fields in constructor.``),
* the root module's name differs from its file's name.

`check_modules` reports the first such error with its file:line:column.  Operator
symbols (``+``, ``\\cup``, user infix operators) are left to the compiler.
"""

from __future__ import annotations

import os
from typing import Any

from . import ast as A
from .errors import Loc, TlaError
from .modules import ModuleLoader

# name -> number of arguments (None: unknown, e.g. an operator parameter's argument)
Names = dict[str, "int | None"]

_ALWAYS = {"BOOLEAN": 0, "STRING": 0, "TRUE": 0, "FALSE": 0}


def check_modules(root: A.Module, loader: ModuleLoader) -> None:
    """Resolve every user module loaded for `root` (SANY's semantic analysis)."""
    stem = os.path.splitext(os.path.basename(root.file))[0]
    if stem != root.name and root.file.endswith(".tla"):
        raise TlaError("semantic", f"File name '{stem}' does not match the name '{root.name}' of the top "
                       f"level module it contains.", Loc(root.file, 1, 1))
    _Resolver(loader).module(root)


class _Resolver:
    def __init__(self, loader: ModuleLoader) -> None:
        self.loader = loader
        self.exported: dict[str, Names] = {}
        self.done: set[str] = set()
        # Where each name of the module being resolved was declared (for messages).
        self.declared: dict[str, Loc] = {}
        # A module nested in another sees the enclosing module's names.
        self.enclosing: dict[str, A.Module] = {}
        for m in list(loader.cache.values()):
            for sub in m.submodules.values():
                self.enclosing.setdefault(sub.name, m)

    # ------------------------------------------------------------ modules
    def imports(self, mod: A.Module) -> Names:
        """The names a module gets from EXTENDS (and standard modules)."""
        names: Names = dict(_ALWAYS)
        for name, loc in mod.extends:
            names.update(self.exports(name, loc))
        return names

    def exports(self, name: str, loc: Loc) -> Names:
        """The names a module makes visible to a module that EXTENDS it."""
        if name in self.exported:
            return self.exported[name]
        target = self.loader.find(name, loc)
        if isinstance(target, dict):
            out: Names = {n: b.arity for n, b in target.items()}
        else:
            self.exported[name] = {}  # circular EXTENDS is reported elsewhere
            self.module(target)
            out = self.imports(target)
            for c in target.constants + target.variables:
                out[c.name] = c.arity
            for u in target.units:
                if isinstance(u, A.OpDef) and not u.local:
                    out[u.name] = _arity(u)
                elif isinstance(u, A.InstanceDef) and not u.local:
                    if u.name is None:
                        out.update(self.exports(u.module, u.loc))
                    else:
                        out[u.name] = len(u.params)
        self.exported[name] = out
        return out

    def module(self, mod: A.Module) -> None:
        if mod.name in self.done:
            return
        self.done.add(mod.name)
        visible = self.imports(mod)
        outer = self.enclosing.get(mod.name)
        while outer is not None:
            visible.update(self.imports(outer))
            visible.update({p.name: p.arity for p in outer.constants + outer.variables})
            visible.update({u.name: None for u in outer.units if u.name is not None})
            outer = self.enclosing.get(outer.name)
        for name in mod.recursive:
            visible[name] = None
        own: dict[str, Loc] = {}
        # VARIABLE and CONSTANT names declared so far: SANY only warns when one is
        # declared again as the same kind ("Multiple declarations or definitions for
        # symbol x"), and TLC checks the module with one such variable or constant.
        params: dict[str, tuple[str, int]] = {}

        def declare(name: str, arity: int | None, loc: Loc) -> None:
            if name in own and name not in mod.recursive:
                raise TlaError("semantic", f"Operator {name} already defined or declared.", loc)
            own[name] = loc
            self.declared[name] = loc
            visible[name] = arity

        for item in sorted(_items(mod), key=lambda it: (it[0].line, it[0].column)):
            loc, kind, node = item
            if kind in ("variable", "constant"):
                if params.get(node.name) == (kind, node.arity):
                    continue
                params[node.name] = (kind, node.arity)
                declare(node.name, node.arity, loc)
            elif kind == "def":
                if node.fn_bounds is not None:
                    visible.setdefault(node.name, 0)  # a recursive function refers to itself
                self.definition(node, visible)
                declare(node.name, _arity(node), loc)
            elif kind == "instance":
                self.instance(node, visible)
                if node.name is None:
                    visible.update(self.exports(node.module, node.loc))
                else:
                    declare(node.name, len(node.params), loc)
            else:  # an ASSUME or THEOREM statement, possibly named
                name, expr = node
                self.expr(expr, visible, {})
                if name is not None:
                    declare(name, 0, loc)

    def definition(self, d: A.OpDef, visible: Names, bound: Names | None = None) -> None:
        inner = dict(bound or {})
        for p in d.params:
            self.fresh(p.name, p.loc, visible, inner)
            inner[p.name] = p.arity or None
        for b in d.fn_bounds or []:
            self.expr(b.set, visible, inner)
        for b in d.fn_bounds or []:
            for n in b.names:
                self.fresh(n, b.set.loc, visible, inner)
                inner[n] = 0
        self.expr(d.body, visible, inner)

    def fresh(self, name: str, loc: Loc, visible: Names, bound: Names) -> None:
        """SANY: a bound variable, parameter or LET definition may not reuse a name
        that is visible where it is introduced (a definition, a declaration, a
        standard-module operator, an enclosing bound variable)."""
        if name in bound or name in visible:
            earlier = self.declared.get(name)
            where = f" with the one at {earlier}" if earlier is not None and name not in bound else ""
            raise TlaError("semantic", f"Multiply-defined symbol '{name}': this definition or declaration "
                           f"conflicts{where}.", loc)

    def instance(self, inst: A.InstanceDef, visible: Names, bound: Names | None = None) -> None:
        inner = dict(bound or {})
        for p in inst.params:
            self.fresh(p.name, p.loc, visible, inner)
            inner[p.name] = p.arity or None
        for _, e in inst.substs:
            if not isinstance(e, A.OpRef):
                self.expr(e, visible, inner)
        target = self.loader.find(inst.module, inst.loc)
        if isinstance(target, A.Module):
            self.module(target)

    # ------------------------------------------------------------ expressions
    def expr(self, e: Any, visible: Names, bound: Names) -> None:
        if isinstance(e, (A.Name, A.Apply)):
            self.name(e, visible, bound)
            for a in getattr(e, "args", []):
                self.expr(a, visible, bound)
            return
        if isinstance(e, A.Prefixed):
            first = e.path[0].name if e.path else e.name
            if first not in bound and first not in visible:
                raise _unknown(first, e.loc)
            for step in e.path:
                for a in step.args:
                    self.expr(a, visible, bound)
            for a in e.args:
                self.expr(a, visible, bound)
            return
        if isinstance(e, A.Let):
            inner = dict(bound)
            recursive = set(e.recursive)
            for name in recursive:
                inner[name] = None
            for d in e.defs:
                if isinstance(d, A.InstanceDef):
                    if d.name is not None:
                        self.fresh(d.name, d.loc, visible, inner)
                    self.instance(d, visible, inner)
                    if d.name is not None:
                        inner[d.name] = len(d.params)
                    continue
                if d.name not in recursive:
                    self.fresh(d.name, d.loc, visible, inner)
                if d.fn_bounds is not None:
                    inner[d.name] = 0  # a function definition may refer to itself
                self.definition(d, visible, inner)
                inner[d.name] = _arity(d)
            self.expr(e.body, visible, inner)
            return
        if isinstance(e, A.RecLit):
            names = [n for n, _ in e.fields]
            for i, n in enumerate(names):
                if n in names[:i]:
                    raise TlaError("semantic", "Non-unique fields in constructor.", e.loc)
        binders = _binders(e)
        if binders is not None:
            sets, names, bodies = binders
            for s in sets:
                self.expr(s, visible, bound)
            inner = dict(bound)
            for n in names:
                self.fresh(n, e.loc, visible, inner)
                inner[n] = 0
            for b in bodies:
                self.expr(b, visible, inner)
            return
        if isinstance(e, A.Lambda):
            inner = dict(bound)
            for p in e.params:
                self.fresh(p, e.loc, visible, inner)
                inner[p] = 0
            self.expr(e.body, visible, inner)
            return
        for c in _children(e):
            self.expr(c, visible, bound)

    def name(self, e: A.Name | A.Apply, visible: Names, bound: Names) -> None:
        name = e.name
        if name == "\\X" or name.startswith("$"):
            return
        if name in bound:
            arity = bound[name]
        elif name in visible:
            arity = visible[name]
        else:
            raise _unknown(name, e.loc)
        args = getattr(e, "args", [])
        if args and arity is not None and arity != len(args):
            # SANY points at the argument list: the column after the name.
            at = Loc(e.loc.file, e.loc.line, e.loc.column + len(name))
            raise TlaError("semantic", f"The operator {name} requires {arity} arguments.", at)


def _arity(d: A.OpDef) -> int:
    return 0 if d.fn_bounds is not None else len(d.params)


def _unknown(name: str, loc: Loc) -> TlaError:
    return TlaError("semantic", f"Unknown operator: `{name}'.", loc)


def _items(mod: A.Module) -> list[tuple[Loc, str, Any]]:
    """The module's declarations, definitions and statements, each with its position."""
    out: list[tuple[Loc, str, Any]] = [(p.loc, "constant", p) for p in mod.constants]
    out += [(p.loc, "variable", p) for p in mod.variables]
    for u in mod.units:
        out.append((u.loc, "def" if isinstance(u, A.OpDef) else "instance", u))
    for a in mod.assumes:
        out.append((a.loc, "statement", (a.name, a.expr)))
    for name, expr, loc in mod.theorems:
        out.append((loc, "statement", (name, expr)))
    return out


def _binders(e: Any) -> tuple[list[Any], list[str], list[Any]] | None:
    """(bound sets, bound names, bodies) of a binding construct, else None."""
    if isinstance(e, (A.Quant, A.FnLit)):
        return [b.set for b in e.bounds], [n for b in e.bounds for n in b.names], [e.body]
    if isinstance(e, A.SetMap):
        return [b.set for b in e.bounds], [n for b in e.bounds for n in b.names], [e.expr]
    if isinstance(e, A.SetFilter):
        return [e.bound.set], list(e.bound.names), [e.pred]
    if isinstance(e, A.Choose):
        return ([e.set] if e.set is not None else []), list(e.names), [e.body]
    if isinstance(e, A.UnboundedQuant):
        return [], list(e.names), [e.body]
    return None


def _children(e: Any) -> list:
    from .compiler import _children as children
    return children(e)
