"""The order in which TLC interns the words and strings of the loaded modules.

TLC's order of strings (and so of sets of strings, CHOOSE witnesses, ...) is the
order in which its parser meets them.  That is SANY's order of files: the parse
order for the words, the semantic-analysis order for the string literals.  Kept
apart from `modules.py` because it models SANY's file order, not name resolution.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from . import ast as A
from .stdlib_tokens import STANDARD_TOKENS

if TYPE_CHECKING:
    from .modules import ModuleLoader


def tlc_intern_order(loader: ModuleLoader) -> list[str]:
    """The words and string contents of the loaded modules in the order TLC interns
    them (which is TLC's order of strings): first the words of every file in SANY's parse order (the root
    file, then the first unresolved EXTENDS found from the root, else the first
    unresolved INSTANCE: `SpecObj.findNextUnresolvedExtention/Instantiation`), then
    the contents of the string literals of every file in semantic-analysis order
    (dependencies first: `SpecObj.calculateDependencies`).  Call it after the root
    scope is built, so that every user module is in `loader.cache`."""
    order = _SanyFileOrder(loader)
    parse_files = order.parse_files()
    by_file = order.tokens_by_file()
    out: list[str] = []
    for f in parse_files:
        out.extend(by_file.get(f, ([], []))[0])
    for f in order.semantic_files(parse_files[0]):
        out.extend(by_file.get(f, ([], []))[1])
    return out


class _SanyFileOrder:
    """SANY's resolution of the modules named from the root, and the two orders of
    files it implies.  `resolved` (in order of resolution) grows while
    `parse_files` runs; the other steps read it afterwards."""

    def __init__(self, loader: ModuleLoader) -> None:
        self.cache = loader.cache
        self.root = loader.root.name
        self.resolved: dict[str, None] = {}

    def deps(self, name: str) -> tuple[list[str], list[str], list[str]]:
        """The EXTENDS, INSTANCEs and nested modules of module `name`."""
        m = self.cache.get(name)
        if m is not None:
            insts: list[str] = []
            for u in m.units:
                if isinstance(u, A.InstanceDef) and u.module not in insts:
                    insts.append(u.module)
            return [n for n, _ in m.extends], insts, list(m.submodules)
        if name in STANDARD_TOKENS:
            ext, inst, _ = STANDARD_TOKENS[name]
            return list(ext), list(inst), []
        return [], [], []

    def file_of(self, name: str) -> str:
        m = self.cache.get(name)
        return m.file if m is not None else "<standard>/" + name

    def resolve(self, name: str) -> None:
        """Mark `name` resolved, and its nested modules (parsed with its file)."""
        self.resolved[name] = None
        m = self.cache.get(name)
        if m is not None:
            for sub in m.submodules:
                self.resolve(sub)

    def find_next(self, extension: bool) -> str | None:
        """The first unresolved EXTENDS (or INSTANCE) module found from the root."""
        visited: set[str] = set()
        resolved = self.resolved

        def body(name: str) -> str | None:
            if name in visited:
                return None
            visited.add(name)
            exts, insts, inners = self.deps(name)
            for n in (exts if extension else insts):
                if n not in resolved:
                    return n
            for n in exts:
                r = body(n)
                if r is not None:
                    return r
            for n in insts:
                if n in resolved:
                    r = body(n)
                    if r is not None:
                        return r
            for n in inners:
                r = body(n)
                if r is not None:
                    return r
            return None
        return body(self.root)

    def parse_files(self) -> list[str]:
        """The files in SANY's parse order, the root's first; resolves every module."""
        root = self.root
        self.resolve(root)
        parse_files = [self.file_of(root)]
        while True:
            nxt = self.find_next(True) or self.find_next(False)
            if nxt is None:
                break
            self.resolve(nxt)
            if nxt in self.cache or nxt in STANDARD_TOKENS:
                f = self.file_of(nxt)
                if f not in parse_files:
                    parse_files.append(f)
        return parse_files

    def names_in_file(self) -> dict[str, list[str]]:
        out: dict[str, list[str]] = {}
        for name in self.resolved:
            out.setdefault(self.file_of(name), []).append(name)
        return out

    def tokens_by_file(self) -> dict[str, tuple[list[str], list[str]]]:
        """Per file: its words and its string contents, each in order of appearance."""
        by_file: dict[str, tuple[list[str], list[str]]] = {}
        for name in self.resolved:
            f = self.file_of(name)
            m = self.cache.get(name)
            if m is not None:
                by_file.setdefault(f, (m.token_order, m.string_order))
            elif name in STANDARD_TOKENS:
                by_file.setdefault(f, (list(STANDARD_TOKENS[name][2]), []))
        return by_file

    def semantic_files(self, root_file: str) -> list[str]:
        """The files in SANY's semantic-analysis order: each file after the files it
        EXTENDS, then those it INSTANCEs (dependencies first)."""
        names_in_file = self.names_in_file()
        resolved, file_of = self.resolved, self.file_of
        semantic: list[str] = []
        visiting: set[str] = set()

        def calc(f: str) -> None:
            if f in visiting:
                return
            visiting.add(f)
            ext_files: list[str] = []
            inst_files: list[str] = []
            for name in names_in_file.get(f, []):
                exts, insts, _ = self.deps(name)
                for n in exts:
                    if n in resolved and file_of(n) != f and file_of(n) not in ext_files:
                        ext_files.append(file_of(n))
                for n in insts:
                    if n in resolved and file_of(n) != f and file_of(n) not in inst_files:
                        inst_files.append(file_of(n))
            for g in ext_files + inst_files:
                calc(g)
            if f not in semantic:
                semantic.append(f)
        calc(root_file)
        return semantic
