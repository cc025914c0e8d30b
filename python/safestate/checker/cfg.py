"""Parser for TLC model configuration files (``.cfg``).

Supported statements: INIT, NEXT, SPECIFICATION, INVARIANT(S), PROPERTY/PROPERTIES,
CONSTANT(S) (``N = 3``, ``S = {a, b}``, ``a = a`` for model values, ``C <- Op``),
CONSTRAINT(S), ACTION_CONSTRAINT(S), CHECK_DEADLOCK TRUE/FALSE, SYMMETRY, VIEW,
ALIAS and POSTCONDITION.  Comments ``\\*`` and ``(* *)``.
Constant values are integers, strings, TRUE/FALSE, model values (identifiers),
and sets / tuples of those.
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field
from typing import Any

from ..tla.errors import Loc, TlaError
from ..tla.values import ModelValue

_KEYWORDS = {
    "CONSTANT", "CONSTANTS", "INIT", "NEXT", "SPECIFICATION", "INVARIANT", "INVARIANTS", "PROPERTY",
    "PROPERTIES", "CONSTRAINT", "CONSTRAINTS", "ACTION_CONSTRAINT", "ACTION_CONSTRAINTS", "SYMMETRY",
    "VIEW", "CHECK_DEADLOCK", "POSTCONDITION", "ALIAS",
}
_TOKEN = re.compile(r'\s+|\\\*[^\n]*|\(\*.*?\*\)|"(?:[^"\\]|\\.)*"|<-|<<|>>|-?\d+|[A-Za-z0-9_]+|\|->|->|[{}(),=\[\]:]',
                    re.S)


@dataclass
class ConfigEntry:
    name: str
    loc: Loc


@dataclass
class Config:
    file: str
    init: ConfigEntry | None = None
    next: ConfigEntry | None = None
    specification: ConfigEntry | None = None
    invariants: list[ConfigEntry] = field(default_factory=list)
    properties: list[ConfigEntry] = field(default_factory=list)
    constraints: list[ConfigEntry] = field(default_factory=list)
    action_constraints: list[ConfigEntry] = field(default_factory=list)
    symmetry: ConfigEntry | None = None
    view: ConfigEntry | None = None
    alias: ConfigEntry | None = None
    postcondition: ConfigEntry | None = None
    check_deadlock: bool = True
    # CONSTANT name -> (value, loc); substitutions name -> (operator name, loc)
    constants: dict[str, tuple[Any, Loc]] = field(default_factory=dict)
    substitutions: dict[str, tuple[str, Loc]] = field(default_factory=dict)
    # Op <- [M] Def: (Op, M, Def, loc), in .cfg order.
    module_substitutions: list[tuple[str, str, str, Loc]] = field(default_factory=list)
    # identifiers and strings in order of appearance (TLC interns them first)
    tokens: list[str] = field(default_factory=list)


@dataclass
class _Tok:
    text: str
    loc: Loc


def _tokenize(text: str, file: str) -> list[_Tok]:
    toks: list[_Tok] = []
    pos, line, line_start = 0, 1, 0
    while pos < len(text):
        m = _TOKEN.match(text, pos)
        if m is None:
            what = ("a byte that is not UTF-8 text" if text[pos] == "\ufffd"
                    else f"unexpected character {text[pos]!r}")
            raise TlaError("config", f"{what} in configuration file (expected a keyword, a name, a number, "
                           f"a string or one of = <- {{ }} , )", Loc(file, line, pos - line_start + 1))
        s = m.group(0)
        if not (s.isspace() or s.startswith("\\*") or s.startswith("(*")):
            toks.append(_Tok(s, Loc(file, line, pos - line_start + 1)))
        nl = s.count("\n")
        if nl:
            line += nl
            line_start = pos + s.rfind("\n") + 1
        pos = m.end()
    return toks


# TLC's ints are Java ints: ModelConfig reads a number with Integer.parseInt, which
# throws for anything larger (TLC: "TLC threw an unexpected exception", exit 255).
TLC_MAX_INT = 2**31 - 1


def parse_config(path: str) -> Config:
    try:
        with open(path, "rb") as f:
            data = f.read()
    except OSError as e:
        raise TlaError("config", f"cannot read configuration file: {e.strerror}", Loc(path, 0, 0)) from None
    # As TLC's reader (a UTF-8 InputStreamReader): a byte that is not UTF-8 becomes
    # U+FFFD, harmless in a comment, an unexpected character elsewhere.
    return parse_config_text(data.decode("utf-8", errors="replace"), path)


def parse_config_text(text: str, file: str) -> Config:
    toks = _tokenize(text, file)
    cfg = Config(file)
    for t in toks:
        if re.match(r"[A-Za-z]", t.text) and t.text not in _KEYWORDS:
            cfg.tokens.append(t.text)
        elif t.text.startswith('"'):
            cfg.tokens.append(t.text[1:-1])
    i = 0
    section = None

    def need_name(j: int) -> ConfigEntry:
        if j >= len(toks) or not re.match(r"[A-Za-z0-9_]+$", toks[j].text) or toks[j].text in _KEYWORDS:
            where = toks[j].loc if j < len(toks) else toks[-1].loc
            raise TlaError("config", f"expected an identifier after {section}", where)
        return ConfigEntry(toks[j].text, toks[j].loc)

    while i < len(toks):
        tok = toks[i]
        word = tok.text
        if word in _KEYWORDS:
            section = word
            i += 1
            if word in ("INIT", "NEXT", "SPECIFICATION", "SYMMETRY", "VIEW", "ALIAS", "POSTCONDITION"):
                entry = need_name(i)
                setattr(cfg, word.lower(), entry)
                i += 1
                section = None
            elif word == "CHECK_DEADLOCK":
                if i >= len(toks) or toks[i].text not in ("TRUE", "FALSE"):
                    raise TlaError("config", "CHECK_DEADLOCK must be followed by TRUE or FALSE", tok.loc)
                cfg.check_deadlock = toks[i].text == "TRUE"
                i += 1
                section = None
            continue
        if section is None:
            raise TlaError("config", f"unexpected {word!r} in configuration file", tok.loc)
        if section in ("INVARIANT", "INVARIANTS"):
            cfg.invariants.append(need_name(i))
            i += 1
        elif section in ("PROPERTY", "PROPERTIES"):
            cfg.properties.append(need_name(i))
            i += 1
        elif section in ("CONSTRAINT", "CONSTRAINTS"):
            cfg.constraints.append(need_name(i))
            i += 1
        elif section in ("ACTION_CONSTRAINT", "ACTION_CONSTRAINTS"):
            cfg.action_constraints.append(need_name(i))
            i += 1
        elif section in ("CONSTANT", "CONSTANTS"):
            name = need_name(i)
            i += 1
            if i < len(toks) and toks[i].text == "(":
                raise TlaError("unsupported", "operator-valued constants in the .cfg (C(x) = ...) are not "
                               "supported; use C <- Op", toks[i].loc)
            if i >= len(toks) or toks[i].text not in ("=", "<-"):
                raise TlaError("config", f"expected = or <- after constant {name.name}", name.loc)
            if toks[i].text == "<-":
                i += 1
                if i < len(toks) and toks[i].text == "[":
                    # Op <- [M] Def: Op as defined in module M means the spec's Def.
                    module = need_name(i + 1)
                    if i + 2 >= len(toks) or toks[i + 2].text != "]":
                        raise TlaError("config", "expected ] after the module name of <- [M]", module.loc)
                    target = need_name(i + 3)
                    cfg.module_substitutions.append((name.name, module.name, target.name, name.loc))
                    i += 4
                    continue
                target = need_name(i)
                cfg.substitutions[name.name] = (target.name, name.loc)
                i += 1
            else:
                i += 1
                value, i = _value(toks, i, name.name)
                cfg.constants[name.name] = (value, name.loc)
    return cfg


def _value(toks: list[_Tok], i: int, const: str, inside: str | None = None) -> tuple[Any, int]:
    """The value at toks[i]; `inside` is the closing bracket of the enclosing set."""
    if i >= len(toks):
        raise TlaError("config", f"missing value for constant {const}", toks[-1].loc)
    t = toks[i]
    s = t.text
    if s == "<<" or s.startswith("-"):
        # TLC 1.8.0's cfg grammar has neither tuples nor negative numbers: it stops there
        # (a ConfigFileException, exit 255) expecting the next statement or the set's end.
        expected = "= or <-" if inside is None else inside
        raise TlaError("config", f"TLC found an error in the configuration file at line {t.loc.line}\n"
                       f"It was expecting {expected}, but did not find it. (TLC 1.8.0 reads no tuple or negative "
                       f"number in a .cfg: define the value in the spec and write {const} <- ItsName)", t.loc)
    if re.match(r"\d+$", s):
        if len(s.lstrip("0")) > 10 or int(s) > TLC_MAX_INT:
            raise TlaError("config", f"the number {s} in the value of constant {const} is too big for TLC, whose "
                           f"integers are 32-bit (at most {TLC_MAX_INT}); TLC stops with "
                           f"NumberFormatException: For input string: \"{s}\"", t.loc)
        return int(s), i + 1
    if s.startswith('"'):
        return re.sub(r"\\(.)", r"\1", s[1:-1]), i + 1
    if s in ("TRUE", "FALSE"):
        return s == "TRUE", i + 1
    if s == "{":
        items = []
        i += 1
        while i < len(toks) and toks[i].text != "}":
            v, i = _value(toks, i, const, "}")
            items.append(v)
            if i < len(toks) and toks[i].text == ",":
                i += 1
        if i >= len(toks):
            raise TlaError("config", f"unterminated {s} in the value of {const}", t.loc)
        return frozenset(items), i + 1
    if re.match(r"[A-Za-z_][A-Za-z0-9_]*$", s) and s not in _KEYWORDS:
        return ModelValue(s), i + 1
    if s == "[":
        raise TlaError("config", f"a record or function value [...] cannot be given in a .cfg (TLC 1.8.0 rejects it "
                       f"too): define it in the spec and write {const} <- ItsName", t.loc)
    raise TlaError("config", f"unexpected {s!r} in the value of constant {const}", t.loc)
