"""Parses TLA+ text with tree-sitter-tlaplus into the typed AST of `ast.py`.

tree-sitter recovers from errors, so before converting we look for ERROR and
MISSING nodes and report the first one as a syntax error with its position.
Constructs outside the supported subset become `Unsupported` nodes (reported when
evaluated) or an immediate `UnsupportedError` for declarations we cannot handle.
"""

from __future__ import annotations

import re
import warnings
from typing import cast

import tree_sitter_tlaplus
from tree_sitter import Language, Parser

from . import ast as A
from .comments import blank_comments
from .errors import Loc, TlaError, UnsupportedError
from .syntax_tree import Node

with warnings.catch_warnings():
    # tree-sitter-tlaplus 1.5 still hands over the language as an int pointer.
    warnings.simplefilter("ignore", DeprecationWarning)
    _LANGUAGE = Language(tree_sitter_tlaplus.language())

# tree-sitter node type of an operator symbol -> its ASCII spelling.
_SYMBOLS = {
    "implies": "=>", "plus_arrow": "-+->", "equiv": "\\equiv", "iff": "<=>", "leads_to": "~>",
    "land": "/\\", "lor": "\\/", "assign": ":=", "bnf_rule": "::=", "eq": "=", "neq": "/=",
    "lt": "<", "gt": ">", "leq": "<=", "geq": ">=", "approx": "\\approx", "rs_ttile": "|-",
    "rd_ttile": "|=", "ls_ttile": "-|", "ld_ttile": "=|", "asymp": "\\asymp", "cong": "\\cong",
    "doteq": "\\doteq", "gg": "\\gg", "ll": "\\ll", "in": "\\in", "notin": "\\notin",
    "prec": "\\prec", "succ": "\\succ", "preceq": "\\preceq", "succeq": "\\succeq",
    "propto": "\\propto", "sim": "\\sim", "simeq": "\\simeq", "sqsubset": "\\sqsubset",
    "sqsupset": "\\sqsupset", "sqsubseteq": "\\sqsubseteq", "sqsupseteq": "\\sqsupseteq",
    "subset": "\\subset", "supset": "\\supset", "subseteq": "\\subseteq", "supseteq": "\\supseteq",
    "compose": "@@", "map_to": ":>", "map_from": "<:", "setminus": "\\", "cap": "\\cap",
    "cup": "\\cup", "dots_2": "..", "dots_3": "...", "plus": "+", "plusplus": "++",
    "oplus": "(+)", "ominus": "(-)", "mod": "%", "modmod": "%%", "vert": "|", "vertvert": "||",
    "minus": "-", "minusminus": "--", "amp": "&", "ampamp": "&&", "odot": "(.)",
    "oslash": "(/)", "otimes": "(\\X)", "mul": "*", "mulmul": "**", "slash": "/",
    "slashslash": "//", "bigcirc": "\\bigcirc", "bullet": "\\bullet", "div": "\\div",
    "circ": "\\o", "star": "\\star", "excl": "!!", "hashhash": "##", "dol": "$", "doldol": "$$",
    "qq": "??", "sqcap": "\\sqcap", "sqcup": "\\sqcup", "uplus": "\\uplus", "times": "\\X",
    "wr": "\\wr", "cdot": "\\cdot", "pow": "^", "powpow": "^^",
    # prefix
    "lnot": "~", "union": "UNION", "powerset": "SUBSET", "domain": "DOMAIN", "negative": "-.",
    "enabled": "ENABLED", "unchanged": "UNCHANGED", "always": "[]", "eventually": "<>",
    # postfix
    "sup_plus": "^+", "asterisk": "^*", "sup_hash": "^#", "prime": "'",
}

# Precedence ranges of infix operators (Specifying Systems, p. 271).
_PRECEDENCE: dict[str, tuple[int, int]] = {}
for _ops, _rng in (
    ("=>", (1, 1)), ("<=> \\equiv ~> -+->", (2, 2)), ("/\\ \\/", (3, 3)),
    ("= /= < > <= >= \\in \\notin \\subseteq \\subset \\supseteq \\supset \\prec \\succ \\preceq "
     "\\succeq \\sqsubset \\sqsupset \\sqsubseteq \\sqsupseteq \\sim \\simeq \\approx \\cong "
     "\\asymp \\doteq \\ll \\gg \\propto := ::= |- -| |= =|", (5, 5)),
    ("@@", (6, 6)), (":> <:", (7, 7)), ("\\cup \\cap \\", (8, 8)), (".. ...", (9, 9)),
    ("+ ++ (+)", (10, 10)), ("% %% | ||", (10, 11)), ("- -- (-)", (11, 11)),
    ("* ** (.) (/) (\\X) & && \\o \\star \\bullet \\div / // \\sqcap \\sqcup \\uplus ## $ $$ ?? !!",
     (13, 13)), ("\\X", (10, 13)), ("^ ^^", (14, 14)), ("\\wr", (9, 14)), ("\\cdot", (5, 14)),
):
    for _op in _ops.split():
        _PRECEDENCE[_op] = _rng
# The ranges with which SANY (TLC 1.8.0) rejects a prefix operator next to an
# unparenthesised infix operator (`UNION S \X T`, `ENABLED A = B`, `- a \X b`): a
# conflict when the two ranges overlap.  Measured by running SANY on every pair;
# for SUBSET, UNION and DOMAIN they are not the book's 8-8 / 9-9 (SANY accepts
# `SUBSET S \cup T` and `SUBSET S .. T`, binding the prefix operator tighter).
_PREFIX_CONFLICT: dict[str, tuple[int, int]] = {
    "SUBSET": (10, 13), "UNION": (10, 13), "DOMAIN": (10, 13), "-.": (12, 12), "~": (4, 4),
    "ENABLED": (4, 15), "UNCHANGED": (4, 15), "[]": (4, 15), "<>": (4, 15),
}
_LEFT_ASSOC = {"/\\", "\\/", "@@", "\\cup", "\\cap", "+", "++", "(+)", "-", "--", "(-)", "*", "**", "(.)",
               "&", "&&", "\\o", "\\sqcap", "\\sqcup", "\\uplus", "##", "$", "$$", "??", "!!", "%%", "||",
               "\\X"}

_BUILTIN_SETS = {
    "nat_number_set": "Nat", "int_number_set": "Int", "string_set": "STRING",
    "boolean_set": "BOOLEAN", "real_number_set": "Real",
}

_TOKEN_RE = re.compile(r'"(?:[^"\\\n]|\\.)*"|\\[A-Za-z]+|[A-Za-z0-9_]*[A-Za-z][A-Za-z0-9_]*')
_MODULE_START_RE = re.compile(r"-{4,}\s*MODULE\b")
_ESCAPES = {"n": "\n", "t": "\t", "r": "\r", "f": "\f", '"': '"', "\\": "\\"}


def parse_text(text: str, file: str) -> list[A.Module]:
    """Parse a file's text; returns its top-level modules (normally exactly one)."""
    parser = Parser(_LANGUAGE)
    text = blank_comments(text)
    data = text.encode("utf-8")
    tree = parser.parse(data)
    root = cast(Node, tree.root_node)  # converted only once check_errors passes it: see syntax_tree.py
    conv = _Converter(data, file)
    conv.check_errors(root)
    modules = [conv.module(n) for n in root.named_children if n.type == "module"]
    if not modules:
        raise TlaError("syntax", "no MODULE found (expected '---- MODULE Name ----')", Loc(file, 1, 1))
    words, strings = _token_order(text)
    for m in modules:
        m.token_order = words
        m.string_order = strings
    return modules


def _token_order(text: str) -> tuple[list[str], list[str]]:
    """The words (identifiers and keywords) and the string contents of a file, each in
    order of first appearance, skipping the text before the first module (comments
    are already blanked out).

    TLC's string order is the order in which names are interned: SANY interns every
    word while parsing a file, but the content of a string literal only when the
    module is semantically analysed (`StringNode`), after all files have been parsed."""
    start = _MODULE_START_RE.search(text)
    if start is not None:
        text = text[start.start():]
    words: dict[str, None] = {}
    strings: dict[str, None] = {}
    for tok in _TOKEN_RE.findall(text):
        if tok.startswith('"'):
            strings.setdefault(_unescape(tok[1:-1]), None)
        elif not tok.startswith("\\"):
            words.setdefault(tok, None)
    return list(words), list(strings)


def _unescape(s: str) -> str:
    return re.sub(r"\\(.)", lambda m: _ESCAPES.get(m.group(1), m.group(1)), s)


class _Converter:
    def __init__(self, data: bytes, file: str) -> None:
        self.data = data
        self.file = file

    # ------------------------------------------------------------ helpers
    def loc(self, n: Node) -> Loc:
        row, col_bytes = n.start_point
        line_start = self.data.rfind(b"\n", 0, n.start_byte) + 1
        col = len(self.data[line_start:line_start + col_bytes].decode("utf-8", "replace")) + 1
        return Loc(self.file, row + 1, col)

    def text(self, n: Node) -> str:
        return self.data[n.start_byte:n.end_byte].decode("utf-8")

    def syntax(self, msg: str, n: Node) -> TlaError:
        return TlaError("syntax", msg, self.loc(n))

    def check_errors(self, root: Node) -> None:
        """Report the first ERROR or MISSING node (tree-sitter recovers silently)."""
        if not root.has_error:
            return
        stack = [root]
        while stack:
            n = stack.pop()
            if n.is_missing:
                # Report where the parser stopped: the next token after the gap (as SANY does).
                raise TlaError("syntax", f"parse error: expected {n.type.replace('_', ' ')} before this token",
                               self.next_token_loc(n.start_byte))
            if n.type == "ERROR":
                if n.start_point == root.start_point:
                    # The whole module failed to parse: find the cause in the text.
                    from .syntax_hints import locate
                    hint = locate(self.file, self.data)
                    if hint is not None:
                        raise TlaError("syntax", hint[0], hint[1])
                snippet = self.text(n).strip().splitlines()[0][:40] if self.text(n).strip() else ""
                from .syntax_hints import explain_unexpected
                msg, where = explain_unexpected(self.file, self.data, n.start_byte, snippet,
                                                n.start_point == root.start_point)
                raise TlaError("syntax", msg, where)
            if n.has_error:
                stack.extend(reversed(n.children))
        raise TlaError("syntax", "parse error", self.loc(root))

    def next_token_loc(self, pos: int) -> Loc:
        from .syntax_hints import next_token_loc
        return next_token_loc(self.file, self.data, pos)

    def check_precedence(self, n: Node, sym: str) -> None:
        """SANY rejects ``a op1 b op2 c`` when the precedence ranges of op1 and op2
        overlap, unless op1 = op2 is associative; tree-sitter does not."""
        outer = _PRECEDENCE.get(sym)
        if outer is None:
            return
        lhs = n.child_by_field_name("lhs")
        if lhs is not None and lhs.type == "bound_prefix_op":  # tree-sitter's (SUBSET a) + b
            self.check_prefix_precedence(lhs, n)
        rhs = n.child_by_field_name("rhs")
        if rhs is not None and rhs.type == "bound_prefix_op" and outer[0] > 12 \
                and _SYMBOLS.get(rhs.child_by_field_name("symbol").type) == "-.":
            # SANY: `7 \div -2`, `2 * -3`, `2 ^ -3` (a prefix minus, precedence 12, as the
            # right operand of an operator binding tighter) need parentheses; `2 + -3` not.
            raise TlaError("syntax", f"Precedence conflict between ops {sym} and -; add parentheses",
                           self.loc(rhs))
        for side in ("lhs", "rhs"):
            child = n.child_by_field_name(side)
            if child is None or child.type != "bound_infix_op":
                continue
            sym_node = child.child_by_field_name("symbol")
            inner_sym = _SYMBOLS.get(sym_node.type)
            inner = _PRECEDENCE.get(inner_sym or "")
            if inner is None:
                continue
            if side == "lhs" and inner_sym == sym and sym in _LEFT_ASSOC:
                continue
            if inner[0] > outer[1]:
                continue  # the inner operator binds tighter: no parentheses needed
            first, second = (inner_sym, sym) if side == "lhs" else (sym, inner_sym)
            where = sym_node if side == "lhs" else n.child_by_field_name("symbol")
            raise TlaError("syntax", f"Precedence conflict between ops {first} and {second}; "
                           f"add parentheses", self.loc(where))

    def check_prefix_precedence(self, prefix: Node, infix: Node) -> None:
        """SANY's conflict between a prefix operator and an infix operator in its
        operand (or applied to its result), e.g. ``UNION S \\X T``."""
        outer = _PREFIX_CONFLICT.get(_SYMBOLS.get(prefix.child_by_field_name("symbol").type, ""))
        sym_node = infix.child_by_field_name("symbol")
        inner_sym = _SYMBOLS.get(sym_node.type, "")
        inner = _PRECEDENCE.get(inner_sym)
        if outer is None or inner is None or inner[1] < outer[0] or inner[0] > outer[1]:
            return
        first = prefix.child_by_field_name("symbol")
        raise TlaError("syntax", f"Precedence conflict between ops {_SYMBOLS[first.type].rstrip('.')} and "
                       f"{inner_sym}; add parentheses", self.loc(first))

    @staticmethod
    def named(n: Node) -> list[Node]:
        return [c for c in n.named_children if c.type not in ("comment", "block_comment")]

    # ------------------------------------------------------------ module level
    def module(self, n: Node) -> A.Module:
        name = self.text(n.child_by_field_name("name"))
        mod = A.Module(name=name, file=self.file, extends=[])
        for c in self.named(n):
            t = c.type
            if t in ("header_line", "double_line", "single_line", "identifier"):
                continue
            if t == "extends":
                mod.extends = [(self.text(i), self.loc(i)) for i in self.named(c)]
            elif t == "constant_declaration":
                mod.constants.extend(self.decl(i) for i in self.named(c))
            elif t == "variable_declaration":
                mod.variables.extend(A.Param(self.text(i), 0, self.loc(i)) for i in self.named(c))
            elif t == "recursive_declaration":
                mod.recursive.update(self.decl(i).name for i in self.named(c))
            elif t in ("operator_definition", "function_definition", "module_definition", "instance"):
                mod.units.append(self.definition(c, False))
            elif t == "local_definition":
                mod.units.append(self.definition(self.named(c)[0], True))
            elif t == "assumption" and self.text(c).lstrip().startswith("AXIOM"):
                continue  # an AXIOM is proof material: TLC does not evaluate it
            elif t == "assumption":
                nm = c.child_by_field_name("name")
                body = [x for x in self.named(c) if x.type not in ("identifier", "def_eq")][-1]
                mod.assumes.append(A.Assume(self.expr(body), self.loc(c), self.text(nm) if nm else None))
            elif t == "theorem":
                # Proofs are not checked by TLC either, but SANY resolves the statement.
                nm, stmt = c.child_by_field_name("name"), c.child_by_field_name("statement")
                if stmt is not None:
                    mod.theorems.append((self.text(nm) if nm else None, self.expr(stmt), self.loc(c)))
            elif t == "use_or_hide":
                continue
            elif t == "module":
                sub = self.module(c)
                mod.submodules[sub.name] = sub
            else:
                raise UnsupportedError(f"unsupported module-level construct {t}", self.loc(c))
        return mod

    def decl(self, n: Node) -> A.Param:
        if n.type == "identifier":
            return A.Param(self.text(n), 0, self.loc(n))
        # operator_declaration: F(_, _) or prefix/infix/postfix forms
        name_node = n.child_by_field_name("name")
        name = self.symbol_name(name_node)
        arity = sum(1 for c in self.named(n) if c.type == "placeholder")
        return A.Param(name, arity, self.loc(n))

    def symbol_name(self, n: Node) -> str:
        if n.type == "identifier" or n.type == "identifier_ref":
            return self.text(n)
        if n.type in _BUILTIN_SETS:
            return _BUILTIN_SETS[n.type]
        if n.type in ("infix_op_symbol", "prefix_op_symbol", "postfix_op_symbol"):
            inner = self.named(n)[0]
            sym = _SYMBOLS.get(inner.type)
            if sym is None:
                raise UnsupportedError(f"unsupported operator symbol {self.text(n)!r}", self.loc(n))
            return sym
        raise self.syntax(f"unexpected {n.type}", n)

    def definition(self, n: Node, local: bool) -> A.OpDef | A.InstanceDef:
        t = n.type
        if t == "operator_definition":
            name_node = n.child_by_field_name("name")
            params = [self.decl(p) for p in n.children_by_field_name("parameter") if p.is_named]
            name = self.symbol_name(name_node)
            if name_node.type == "prefix_op_symbol" and name == "-.":
                name = "-."
            return A.OpDef(name, params, self.expr(n.child_by_field_name("definition")), self.loc(n), local)
        if t == "function_definition":
            bounds = [self.bound(b) for b in self.named(n) if b.type == "quantifier_bound"]
            return A.OpDef(self.text(n.child_by_field_name("name")), [],
                           self.expr(n.child_by_field_name("definition")), self.loc(n), local, bounds)
        if t == "instance":
            return self.instance(n, None, [], local)
        if t == "module_definition":
            params = [self.decl(p) for p in n.children_by_field_name("parameter") if p.is_named]
            name = self.text(n.child_by_field_name("name"))
            return self.instance(n.child_by_field_name("definition"), name, params, local)
        raise self.syntax(f"unexpected {t}", n)

    def instance(self, n: Node, name: str | None, params: list[A.Param], local: bool) -> A.InstanceDef:
        kids = self.named(n)
        substs = []
        for s in kids[1:]:
            if s.type != "substitution":
                continue
            parts = self.named(s)
            target = self.symbol_name(parts[0])
            substs.append((target, self.op_or_expr(parts[2])))
        return A.InstanceDef(name, params, self.text(kids[0]), substs, self.loc(n), local)

    def op_or_expr(self, n: Node) -> A.Expr:
        if n.type in ("infix_op_symbol", "prefix_op_symbol", "postfix_op_symbol"):
            return A.OpRef(self.loc(n), self.symbol_name(n))
        if n.type == "lambda":
            ids = [self.text(i) for i in self.named(n) if i.type == "identifier"]
            body = self.named(n)[-1]
            return A.Lambda(self.loc(n), ids, self.expr(body))
        return self.expr(n)

    def bound(self, n: Node) -> A.Bound:
        intro = n.children_by_field_name("intro")
        s = self.expr(n.child_by_field_name("set"))
        if len(intro) == 1 and intro[0].type == "tuple_of_identifiers":
            return A.Bound([self.text(i) for i in self.named(intro[0]) if i.type == "identifier"], True, s)
        return A.Bound([self.text(i) for i in intro if i.is_named], False, s)  # not the commas

    # ------------------------------------------------------------ expressions
    def expr(self, n: Node) -> A.Expr:
        method = getattr(self, "x_" + n.type, None)
        loc = self.loc(n)
        if method is None:
            if n.type in _BUILTIN_SETS:
                if n.type == "real_number_set":
                    return A.Unsupported(loc, "the set Real (real numbers)")
                return A.Name(loc, _BUILTIN_SETS[n.type])
            return A.Unsupported(loc, n.type.replace("_", " "))
        return method(n, loc)

    def x_nat_number(self, n: Node, loc: Loc) -> A.Expr:
        return A.Num(loc, int(self.text(n)))

    def _based(self, n: Node, loc: Loc, base: int) -> A.Expr:
        return A.Num(loc, int(self.text(self.named(n)[-1]), base))

    def x_binary_number(self, n: Node, loc: Loc) -> A.Expr:
        return self._based(n, loc, 2)

    def x_octal_number(self, n: Node, loc: Loc) -> A.Expr:
        return self._based(n, loc, 8)

    def x_hex_number(self, n: Node, loc: Loc) -> A.Expr:
        return self._based(n, loc, 16)

    def x_real_number(self, n: Node, loc: Loc) -> A.Expr:
        return A.Unsupported(loc, "real number literal")

    def x_string(self, n: Node, loc: Loc) -> A.Expr:
        raw = self.text(n)[1:-1]
        bad = re.search(r'\\[^nrtf"\\]', raw.replace("\\\\", "  "))
        if bad is not None:
            # SANY's lexer knows only these escapes: "a\qb" is a lexical error at the q
            raise TlaError("syntax", f"Lexical error: unknown escape sequence \\{raw[bad.start() + 1]} in a string "
                           f"(known: \\\" \\\\ \\n \\t \\r \\f)",
                           Loc(loc.file, loc.line, loc.column + bad.start() + 2))
        return A.Str(loc, _unescape(raw))

    def x_boolean(self, n: Node, loc: Loc) -> A.Expr:
        return A.Bool(loc, self.text(n) == "TRUE")

    def x_parentheses(self, n: Node, loc: Loc) -> A.Expr:
        return self.expr(self.named(n)[0])

    def x_label(self, n: Node, loc: Loc) -> A.Expr:
        return self.expr(n.child_by_field_name("expression"))

    def x_identifier_ref(self, n: Node, loc: Loc) -> A.Expr:
        return A.Name(loc, self.text(n))

    def x_bound_op(self, n: Node, loc: Loc) -> A.Expr:
        name = self.text(n.child_by_field_name("name"))
        args = [self.op_or_expr(a) for a in n.children_by_field_name("parameter")
                if a.type not in ("(", ")", ",")]
        return A.Apply(loc, name, args)

    def x_bound_nonfix_op(self, n: Node, loc: Loc) -> A.Expr:
        sym = self.symbol_name(n.child_by_field_name("symbol"))
        args = [self.expr(a) for a in self.named(n)[1:]]
        return self._operator(loc, sym, args)

    def x_prefixed_op(self, n: Node, loc: Loc) -> A.Expr:
        prefix = n.child_by_field_name("prefix")
        path: list[A.InstanceStep] = []
        for comp in self.named(prefix):
            if comp.type != "subexpr_component":
                raise UnsupportedError("subexpression navigation (!<<, !1, !@ ...)", self.loc(comp))
            inner = self.named(comp)[0]
            if inner.type == "identifier_ref":
                path.append(A.InstanceStep(self.text(inner), []))
            elif inner.type == "bound_op":
                app = self.x_bound_op(inner, self.loc(inner))
                assert isinstance(app, A.Apply)
                path.append(A.InstanceStep(app.name, app.args))
            else:
                raise UnsupportedError("operator-symbol instance prefix", self.loc(comp))
        op = n.child_by_field_name("op")
        if op.type == "bound_op":
            app = self.x_bound_op(op, self.loc(op))
            assert isinstance(app, A.Apply)
            return A.Prefixed(loc, path, app.name, app.args)
        if op.type == "bound_nonfix_op":
            sym = self.symbol_name(op.child_by_field_name("symbol"))
            return A.Prefixed(loc, path, sym, [self.expr(a) for a in self.named(op)[1:]])
        return A.Prefixed(loc, path, self.symbol_name(op), [])

    def x_subexpression(self, n: Node, loc: Loc) -> A.Expr:
        return A.Unsupported(loc, "subexpression reference")

    def _operator(self, loc: Loc, sym: str, args: list[A.Expr]) -> A.Expr:
        if len(args) == 2:
            return self._binary(loc, sym, args[0], args[1])
        if sym == "'":
            return A.Prime(loc, args[0])
        if sym == "-.":
            return A.Unary(loc, "-", args[0])
        return A.Unary(loc, sym, args[0])

    def _binary(self, loc: Loc, sym: str, lhs: A.Expr, rhs: A.Expr) -> A.Expr:
        if sym == "/\\":
            return A.And(loc, _flatten(A.And, lhs) + _flatten(A.And, rhs))
        if sym == "\\/":
            return A.Or(loc, _flatten(A.Or, lhs) + _flatten(A.Or, rhs))
        return A.Binary(loc, sym, lhs, rhs)

    def x_bound_infix_op(self, n: Node, loc: Loc) -> A.Expr:
        sym = self.symbol_name_of(n.child_by_field_name("symbol"))
        self.check_precedence(n, sym)
        lhs_node = n.child_by_field_name("lhs")
        lhs = self.expr(lhs_node)
        rhs = self.expr(n.child_by_field_name("rhs"))
        if sym == "\\X":
            # A \X B \X C is one 3-fold product; (A \X B) \X C (parenthesised) is not.
            if lhs_node.type == "bound_infix_op" and isinstance(lhs, A.Apply) and lhs.name == "\\X":
                return A.Apply(loc, "\\X", lhs.args + [rhs])
            return A.Apply(loc, "\\X", [lhs, rhs])
        return self._binary(loc, sym, lhs, rhs)

    def symbol_name_of(self, n: Node) -> str:
        sym = _SYMBOLS.get(n.type)
        if sym is None:
            raise UnsupportedError(f"unsupported operator {self.text(n)!r}", self.loc(n))
        return sym

    def x_bound_prefix_op(self, n: Node, loc: Loc) -> A.Expr:
        sym = self.symbol_name_of(n.child_by_field_name("symbol"))
        rhs = n.child_by_field_name("rhs")
        if rhs.type == "bound_infix_op":  # tree-sitter's - (a \X b)
            self.check_prefix_precedence(n, rhs)
        arg = self.expr(rhs)
        if sym == "-.":
            sym = "-"
        return A.Unary(loc, sym, arg)

    def x_bound_postfix_op(self, n: Node, loc: Loc) -> A.Expr:
        sym = self.symbol_name_of(n.child_by_field_name("symbol"))
        arg = self.expr(n.child_by_field_name("lhs"))
        if sym == "'":
            return A.Prime(loc, arg)
        return A.Unary(loc, sym, arg)

    def x_bounded_quantification(self, n: Node, loc: Loc) -> A.Expr:
        kind = "\\A" if n.child_by_field_name("quantifier").type == "forall" else "\\E"
        bounds = [self.bound(b) for b in n.children_by_field_name("bound") if b.type == "quantifier_bound"]
        return A.Quant(loc, kind, bounds, self.expr(n.child_by_field_name("expression")))

    def x_unbounded_quantification(self, n: Node, loc: Loc) -> A.Expr:
        q = n.child_by_field_name("quantifier").type
        names = [self.text(i) for i in n.children_by_field_name("intro") if i.type == "identifier"]
        body = self.expr(n.child_by_field_name("expression"))
        if q in ("temporal_forall", "temporal_exists"):
            return A.Unsupported(loc, "temporal quantifier \\AA/\\EE")
        return A.UnboundedQuant(loc, "\\A" if q == "forall" else "\\E", names, body)

    def x_choose(self, n: Node, loc: Loc) -> A.Expr:
        intro = n.child_by_field_name("intro")
        s = n.child_by_field_name("set")
        body = self.expr(n.child_by_field_name("expression"))
        if intro.type == "tuple_of_identifiers":
            names = [self.text(i) for i in self.named(intro) if i.type == "identifier"]
            return A.Choose(loc, names, True, self.expr(s) if s else None, body)
        return A.Choose(loc, [self.text(intro)], False, self.expr(s) if s else None, body)

    def x_finite_set_literal(self, n: Node, loc: Loc) -> A.Expr:
        return A.SetEnum(loc, [self.expr(e) for e in self.named(n)])

    def x_set_filter(self, n: Node, loc: Loc) -> A.Expr:
        return A.SetFilter(loc, self.bound(n.child_by_field_name("generator")),
                           self.expr(n.child_by_field_name("filter")))

    def x_set_map(self, n: Node, loc: Loc) -> A.Expr:
        bounds = [self.bound(b) for b in n.children_by_field_name("generator") if b.type == "quantifier_bound"]
        return A.SetMap(loc, self.expr(n.child_by_field_name("map")), bounds)

    def x_function_evaluation(self, n: Node, loc: Loc) -> A.Expr:
        kids = self.named(n)
        return A.FnApp(loc, self.expr(kids[0]), [self.expr(k) for k in kids[1:]])

    def x_function_literal(self, n: Node, loc: Loc) -> A.Expr:
        kids = self.named(n)
        bounds = [self.bound(b) for b in kids if b.type == "quantifier_bound"]
        return A.FnLit(loc, bounds, self.expr(kids[-1]))

    def x_set_of_functions(self, n: Node, loc: Loc) -> A.Expr:
        kids = [k for k in self.named(n) if k.type != "maps_to"]
        return A.FnSet(loc, self.expr(kids[0]), self.expr(kids[1]))

    def _fields(self, n: Node) -> list[tuple[str, A.Expr]]:
        kids = [k for k in self.named(n) if k.type != "all_map_to"]
        return [(self.text(kids[i]), self.expr(kids[i + 1])) for i in range(0, len(kids), 2)]

    def x_record_literal(self, n: Node, loc: Loc) -> A.Expr:
        return A.RecLit(loc, self._fields(n))

    def x_set_of_records(self, n: Node, loc: Loc) -> A.Expr:
        return A.RecSet(loc, self._fields(n))

    def x_record_value(self, n: Node, loc: Loc) -> A.Expr:
        kids = self.named(n)
        return A.Dot(loc, self.expr(kids[0]), self.text(kids[1]))

    def x_except(self, n: Node, loc: Loc) -> A.Expr:
        base = self.expr(n.child_by_field_name("expr_to_update"))
        updates = []
        for u in self.named(n):
            if u.type != "except_update":
                continue
            spec = [c for c in u.children_by_field_name("update_specifier") if c.is_named][0]
            path: list[tuple[str, object]] = []
            for p in self.named(spec):
                if p.type == "except_update_record_field":
                    path.append(("field", self.text(self.named(p)[0])))
                else:
                    path.append(("index", [self.expr(e) for e in self.named(p)]))
            updates.append(A.ExceptUpdate(path, self.expr(u.child_by_field_name("new_val"))))
        return A.Except(loc, base, updates)

    def x_prev_func_val(self, n: Node, loc: Loc) -> A.Expr:
        return A.At(loc)

    def x_tuple_literal(self, n: Node, loc: Loc) -> A.Expr:
        return A.TupleLit(loc, [self.expr(e) for e in self.named(n)
                                if e.type not in ("langle_bracket", "rangle_bracket")])

    def x_step_expr_or_stutter(self, n: Node, loc: Loc) -> A.Expr:
        kids = self.named(n)
        return A.StepAction(loc, self.expr(kids[0]), self.expr(kids[1]), True)

    def x_step_expr_no_stutter(self, n: Node, loc: Loc) -> A.Expr:
        kids = [k for k in self.named(n) if k.type not in ("langle_bracket", "rangle_bracket_sub")]
        return A.StepAction(loc, self.expr(kids[0]), self.expr(kids[1]), False)

    def x_fairness(self, n: Node, loc: Loc) -> A.Expr:
        kids = self.named(n)
        kind = "WF" if self.text(n).startswith("WF_") else "SF"
        return A.Fairness(loc, kind, self.expr(kids[0]), self.expr(kids[1]))

    def x_if_then_else(self, n: Node, loc: Loc) -> A.Expr:
        return A.If(loc, self.expr(n.child_by_field_name("if")), self.expr(n.child_by_field_name("then")),
                    self.expr(n.child_by_field_name("else")))

    def x_case(self, n: Node, loc: Loc) -> A.Expr:
        arms, other = [], None
        for c in self.named(n):
            if c.type == "case_arm":
                k = [x for x in self.named(c) if x.type != "case_arrow"]
                arms.append((self.expr(k[0]), self.expr(k[1])))
            elif c.type == "other_arm":
                other = self.expr(self.named(c)[-1])
        return A.Case(loc, arms, other)

    def x_let_in(self, n: Node, loc: Loc) -> A.Expr:
        defs: list[A.OpDef | A.InstanceDef] = []
        recursive: list[str] = []
        for d in n.children_by_field_name("definitions"):
            if d.type == "recursive_declaration":
                recursive.extend(self.decl(i).name for i in self.named(d))
            elif d.type in ("operator_definition", "function_definition", "module_definition"):
                defs.append(self.definition(d, False))
        return A.Let(loc, defs, self.expr(n.child_by_field_name("expression")), recursive)

    def x_conj_list(self, n: Node, loc: Loc) -> A.Expr:
        return A.And(loc, [self.expr(self.named(i)[-1]) for i in self.named(n) if i.type == "conj_item"])

    def x_disj_list(self, n: Node, loc: Loc) -> A.Expr:
        return A.Or(loc, [self.expr(self.named(i)[-1]) for i in self.named(n) if i.type == "disj_item"])

    def x_lambda(self, n: Node, loc: Loc) -> A.Expr:
        return self.op_or_expr(n)


def _flatten(cls: type, e: A.Expr) -> list[A.Expr]:
    return list(e.items) if isinstance(e, cls) else [e]  # type: ignore[attr-defined]
