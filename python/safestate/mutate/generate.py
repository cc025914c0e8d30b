"""Generates the first-order mutants of a model from its syntax tree.

Only the spec's own definitions are mutated: the top-level definitions of the model's
module and of the modules it EXTENDS or INSTANCEs from its own folder (never a standard
module), and of those only the ones the behaviour uses -- reachable by name from the
cfg's INIT and NEXT (or SPECIFICATION).  A definition only an invariant, a property or
the VIEW uses cannot change the behaviour; mutating it would only add equivalents.

A mutant is one textual substitution at an exact byte range, and is also written in the
declarative form of models/mutants/*.toml (`file`, `original`, `replacement`): the
original widened to whole lines, and further to more lines until it occurs exactly once
in the file, so that a survivor can be kept as a regression mutant as it is.
"""

from __future__ import annotations

import hashlib
import re
import warnings
from collections.abc import Iterable
from dataclasses import dataclass
from pathlib import Path

import tree_sitter_tlaplus
from tree_sitter import Language, Node, Parser

from ..errors import SafestateError
from .operators import OPERATORS, Context, Edit

with warnings.catch_warnings():
    warnings.simplefilter("ignore", DeprecationWarning)  # tree-sitter-tlaplus hands over an int pointer
    _LANGUAGE = Language(tree_sitter_tlaplus.language())


class GenerateError(SafestateError):
    """The model's files cannot be read or parsed for mutation."""


@dataclass(frozen=True)
class Mutant:
    operator: str
    definition: str
    file: str            # file name inside the model's folder
    line: int            # 1-based position of the changed range
    column: int
    start: int           # byte range in the file
    end: int
    replacement: str     # the text of the range in the mutant
    what: str            # one line on the change
    original: str        # declarative form: unique original text (whole lines) ...
    patched: str         # ... and its replacement

    @property
    def id(self) -> str:
        h = hashlib.sha256(f"{self.file}\0{self.start}\0{self.end}\0{self.replacement}".encode()).hexdigest()
        return f"{self.operator}@{self.definition}:{self.line}:{self.column}#{h[:6]}"

    def apply(self, text: bytes) -> bytes:
        return text[:self.start] + self.replacement.encode("utf-8") + text[self.end:]

    def toml(self, folder: str = "models") -> str:
        """The mutant in the flat form of models/mutants/*.toml (add `target` once a
        property kills it)."""
        name = re.sub(r"[^A-Za-z0-9_]", "_", f"{self.operator}_{self.definition}_{self.line}_{self.column}")
        return (f"[[mutant]]\nname = \"{name}\"\nfile = \"{folder}/{self.file}\"\n"
                f"original = '''{self.original}'''\nreplacement = '''{self.patched}'''\n")


@dataclass
class _Def:
    name: str
    file: str
    node: Node          # the operator_definition / function_definition
    body: Node
    data: bytes


def parse(data: bytes) -> Node:
    return Parser(_LANGUAGE).parse(data).root_node


def _module_node(root: Node) -> Node | None:
    return next((c for c in root.named_children if c.type == "module"), None)


def _local_modules(model: Path) -> list[Path]:
    """The model's file and every module of its folder it EXTENDS or INSTANCEs (transitively)."""
    out: list[Path] = []
    todo = [model]
    while todo:
        f = todo.pop(0)
        if f in out:
            continue
        out.append(f)
        text = f.read_text(encoding="utf-8")
        names = re.findall(r"\bEXTENDS\s+([\w\s,]+?)\n", text)
        words = [w for grp in names for w in re.split(r"[\s,]+", grp) if w]
        words += re.findall(r"\bINSTANCE\s+(\w+)", text)
        for w in words:
            cand = model.parent / f"{w}.tla"
            if cand.is_file() and cand not in out:
                todo.append(cand)
    return out


def _definitions(files: list[Path]) -> dict[str, _Def]:
    defs: dict[str, _Def] = {}
    for f in files:
        data = f.read_bytes()
        root = parse(data)
        if root.has_error:
            raise GenerateError(f"{f}: the file does not parse (run `safestate check` for the position)")
        mod = _module_node(root)
        if mod is None:
            continue
        for u in mod.named_children:
            if u.type not in ("operator_definition", "function_definition"):
                continue
            name_node = u.child_by_field_name("name") or u.named_children[0]
            body = u.child_by_field_name("definition") or u.named_children[-1]
            name = data[name_node.start_byte:name_node.end_byte].decode()
            defs.setdefault(name, _Def(name, f.name, u, body, data))
    return defs


def _names_in(n: Node, data: bytes) -> set[str]:
    out: set[str] = set()
    stack = [n]
    while stack:
        x = stack.pop()
        if x.type in ("identifier_ref", "identifier"):
            out.add(data[x.start_byte:x.end_byte].decode())
        stack.extend(x.children)
    return out


def _reachable(defs: dict[str, _Def], roots: Iterable[str]) -> list[str]:
    seen: list[str] = []
    todo = [r for r in roots if r in defs]
    while todo:
        name = todo.pop()
        if name in seen:
            continue
        seen.append(name)
        d = defs[name]
        todo.extend(n for n in _names_in(d.body, d.data) if n in defs and n not in seen)
    return seen


def definition_reads(model: Path, names: Iterable[str]) -> dict[str, frozenset[str]]:
    """Per definition of `names`: the spec's own definitions it reads, transitively,
    itself included (what a mutant of one of them can change)."""
    try:
        defs = _definitions(_local_modules(model))
    except OSError as e:
        raise GenerateError(f"{model}: {e}") from None
    return {n: frozenset(_reachable(defs, [n])) for n in names}


def _input_sets(defs: dict[str, _Def], next_name: str) -> dict[str, list[tuple[int, int]]]:
    """Per file: the byte ranges of the sets Next's \\E draws its inputs from, and of the
    bodies of the definitions those sets name (transitively)."""
    out: dict[str, list[tuple[int, int]]] = {}
    d = defs.get(next_name)
    if d is None:
        return out
    named: set[str] = set()
    stack = [d.body]
    while stack:
        x = stack.pop()
        if x.type == "quantifier_bound" and x.parent is not None and any(
                c.type == "exists" for c in x.parent.children):
            s = x.child_by_field_name("set") or x.named_children[-1]
            out.setdefault(d.file, []).append((s.start_byte, s.end_byte))
            named |= {n for n in _names_in(s, d.data) if n in defs}
        stack.extend(x.children)
    for name in _reachable(defs, named):
        e = defs[name]
        out.setdefault(e.file, []).append((e.body.start_byte, e.body.end_byte))
    return out


def _roles(cfg_init: str | None, cfg_next: str | None, spec: str | None,
           defs: dict[str, _Def]) -> tuple[list[str], str | None, str | None]:
    """(root definitions, INIT name, NEXT name); from SPECIFICATION Init /\\ [][Next]_v
    when the cfg names a specification."""
    if spec is not None and spec in defs:
        d = defs[spec]
        names = _names_in(d.body, d.data)
        text = d.data[d.body.start_byte:d.body.end_byte].decode()
        m = re.search(r"\[\]\s*\[\s*(\w+)\s*\]_", text)
        nxt = m.group(1) if m else None
        init = next((n for n in names if n != nxt and n in defs and "Init" in n), None)
        return [n for n in names if n in defs], init, nxt
    roots = [n for n in (cfg_init, cfg_next) if n]
    return roots, cfg_init, cfg_next


def generate(model: Path, init: str | None, nxt: str | None, spec: str | None = None,
             operators: Iterable[str] | None = None, inputs: Iterable[str] = ()) -> list[Mutant]:
    """Every mutant of the model's behaviour definitions, in file and source order."""
    chosen = list(operators) if operators is not None else list(OPERATORS)
    unknown = [o for o in chosen if o not in OPERATORS]
    if unknown:
        raise GenerateError(f"unknown operator(s) {', '.join(unknown)} (known: {', '.join(OPERATORS)})")
    try:
        files = _local_modules(model)
        defs = _definitions(files)
    except OSError as e:
        raise GenerateError(f"{model}: {e}") from None
    roots, init_name, next_name = _roles(init, nxt, spec, defs)
    input_sets = _input_sets(defs, next_name) if next_name else {}
    out: list[Mutant] = []
    seen: set[tuple[str, int, int, str]] = set()
    for name in _reachable(defs, roots):
        d = defs[name]
        ctx = Context(d.data, name, is_next=name == next_name, is_init=name == init_name,
                      input_sets=input_sets.get(d.file, []), inputs=frozenset(inputs))
        for node in _walk(d.body):
            for op in chosen:
                for edit in OPERATORS[op].fn(node, ctx):
                    key = (d.file, edit.start, edit.end, edit.replacement)
                    if key in seen or d.data[edit.start:edit.end].decode() == edit.replacement:
                        continue
                    seen.add(key)
                    out.append(_mutant(op, d, edit))
    out.sort(key=lambda m: (m.file, m.start, m.end, m.operator, m.replacement))
    return out


def _walk(n: Node) -> Iterable[Node]:
    stack = [n]
    while stack:
        x = stack.pop()
        yield x
        stack.extend(reversed(x.children))


def _mutant(op: str, d: _Def, e: Edit) -> Mutant:
    data = d.data
    line = data.count(b"\n", 0, e.start) + 1
    line_start = data.rfind(b"\n", 0, e.start) + 1
    column = len(data[line_start:e.start].decode("utf-8")) + 1
    original, patched = _declarative(data, e)
    return Mutant(op, d.name, d.file, line, column, e.start, e.end, e.replacement, e.what, original, patched)


def _declarative(data: bytes, e: Edit) -> tuple[str, str]:
    """(original, replacement) as whole lines of the file, widened until the original
    occurs exactly once."""
    lo = data.rfind(b"\n", 0, e.start) + 1
    hi = data.find(b"\n", e.end)
    hi = len(data) if hi < 0 else hi
    while True:
        orig = data[lo:hi]
        if data.count(orig) == 1 or (lo == 0 and hi == len(data)):
            break
        nhi = data.find(b"\n", hi + 1)
        hi = len(data) if nhi < 0 else nhi
    patched = data[lo:e.start] + e.replacement.encode("utf-8") + data[e.end:hi]
    return orig.decode("utf-8"), patched.decode("utf-8")


def dedupe(mutants: list[Mutant], folder: Path) -> tuple[list[Mutant], dict[str, str]]:
    """The mutants whose mutated file differs from every earlier one's once runs of
    white space are collapsed, and {id of a left-out duplicate: id of the mutant with
    its text} (two operators may write the same change: a duplicate is the same model,
    classified once and counted once)."""
    texts: dict[str, bytes] = {}
    first: dict[tuple[str, bytes], str] = {}
    unique: list[Mutant] = []
    dups: dict[str, str] = {}
    for m in mutants:
        if m.file not in texts:
            texts[m.file] = (folder / m.file).read_bytes()
        norm = hashlib.sha256(b" ".join(m.apply(texts[m.file]).split())).digest()
        rep = first.setdefault((m.file, norm), m.id)
        if rep == m.id:
            unique.append(m)
        else:
            dups[m.id] = rep
    return unique, dups
