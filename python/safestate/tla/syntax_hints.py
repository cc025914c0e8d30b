"""Where a syntax error is when tree-sitter cannot say.

On an unclosed comment, an unclosed bracket or an IF without ELSE, tree-sitter's
error recovery wraps the whole module in one ERROR node, which would be reported
at 1:1.  This scan over the raw text finds the cause and reports it where SANY
does: an open comment at its start ("EOF reached, possibly open comment starting
around line N"), a missing closing bracket or ELSE at the token where the parser
gives up (the module's closing ``====``).
"""

from __future__ import annotations

import re

from .errors import Loc

_OPEN = {b"(": b")", b"[": b"]", b"{": b"}", b"<<": b">>"}
_CLOSE = {v: k for k, v in _OPEN.items()}
_WORD = re.compile(rb"[A-Za-z0-9_]+")


def _loc(file: str, data: bytes, pos: int) -> Loc:
    line = data.count(b"\n", 0, pos) + 1
    col = len(data[data.rfind(b"\n", 0, pos) + 1:pos].decode("utf-8", "replace")) + 1
    return Loc(file, line, col)


def locate(file: str, data: bytes) -> tuple[str, Loc] | None:
    """(message, position) of the first unbalanced comment, bracket or IF, if any."""
    end = _module_end(data)
    stack: list[tuple[bytes, int]] = []
    ifs: list[int] = []
    pos, n = _module_start(data), len(data)
    while pos < end:
        c = data[pos:pos + 2]
        if c == b"(*":
            close = _comment_end(data, pos)
            if close < 0:
                line = data.count(b"\n", 0, pos) + 1
                return (f"EOF reached, possibly open comment starting around line {line}",
                        _loc(file, data, pos))
            pos = close
        elif c == b"\\*":
            nl = data.find(b"\n", pos)
            pos = n if nl < 0 else nl
        elif data[pos:pos + 1] == b'"':
            pos = _string_end(data, pos)
        elif c in (b"<<", b">>") and not (c == b">>" and data[pos - 1:pos] == b"-"):
            if c == b"<<":
                stack.append((c, pos))
            elif not stack or stack.pop()[0] != b"<<":
                return "parse error: '>>' without a matching '<<'", _loc(file, data, pos)
            pos += 2
        elif data[pos:pos + 1] in _OPEN:
            stack.append((data[pos:pos + 1], pos))
            pos += 1
        elif data[pos:pos + 1] in _CLOSE:
            closer = data[pos:pos + 1]
            if not stack or _OPEN[stack.pop()[0]] != closer:
                return f"parse error: {closer.decode()!r} without a matching opening bracket", _loc(file, data, pos)
            pos += 1
        else:
            m = _WORD.match(data, pos)
            if m:
                if m.group() == b"IF":
                    ifs.append(pos)
                elif m.group() == b"ELSE" and ifs:
                    ifs.pop()
                pos = m.end()
            else:
                pos += 1
    if stack:
        opener, at = stack[-1]
        o = _loc(file, data, at)
        return (f"parse error: '{opener.decode()}' opened at line {o.line}, column {o.column} is never closed",
                _loc(file, data, end))
    if ifs:
        o = _loc(file, data, ifs[-1])
        return (f"parse error: IF at line {o.line}, column {o.column} has no ELSE", _loc(file, data, end))
    return None


def _module_start(data: bytes) -> int:
    m = re.search(rb"-{4,}\s*MODULE\s+\w+\s*-{4,}", data)
    return m.end() if m else 0


def _module_end(data: bytes) -> int:
    ends = list(re.finditer(rb"^={4,}", data, re.M))
    return ends[-1].start() if ends else len(data)


def _comment_end(data: bytes, pos: int) -> int:
    """End of the (nested) comment opening at `pos`, or -1 if it never closes."""
    depth, pos = 0, pos
    while pos < len(data):
        c = data[pos:pos + 2]
        if c == b"(*":
            depth += 1
            pos += 2
        elif c == b"*)":
            depth -= 1
            pos += 2
            if depth == 0:
                return pos
        else:
            pos += 1
    return -1


def _string_end(data: bytes, pos: int) -> int:
    pos += 1
    while pos < len(data) and data[pos:pos + 1] not in (b'"', b"\n"):
        pos += 2 if data[pos:pos + 1] == b"\\" else 1
    return pos + 1


# ------------------------------------------------------------ "unexpected input"
# What tree-sitter calls an ERROR node says only where its recovery gave up.  These
# rules read the text around it for the usual causes -- a module never closed by ====,
# a definition without a body, an operator without its right operand -- and say what
# was expected, at the place SANY points to (the token where the parse stops).

_DEF = re.compile(rb"^([A-Za-z_][A-Za-z0-9_]*)\s*(?:\([^()\n]*\))?\s*==(?!=)", re.M)
_BINARY_TAIL = re.compile(rb"(/\\|\\/|=>|<=>|=|#|/=|<|>|<=|>=|\\in|\\notin|\\subseteq|\\cup|\\cap|\\union|"
                          rb"\\intersect|\\X|\\times|\+|-|\*|\\div|%|\^|\.\.|:|,|\(|\[|\{|<<|->|\|->|~|\\lnot|"
                          rb"\\land|\\lor|\\E|\\A|==|IF|THEN|ELSE|LET|IN|CASE|OTHER|\[\]|<>|'|@@|:>|\\o|\\circ)$")
_TOKEN_BEFORE = re.compile(rb"(\S+)\s*$")


def explain_unexpected(file: str, data: bytes, start: int, snippet: str, whole_module: bool) -> tuple[str, Loc]:
    """(message, position) for tree-sitter's ERROR node starting at byte `start`."""
    if not data.strip():
        return ("parse error: the file is empty: expected a module, ---- MODULE Name ---- ... ====",
                Loc(file, 1, 1))
    header = re.search(rb"-{4,}\s*MODULE\s+\w+\s*-{4,}", data)
    if header is None:
        return ("parse error: expected a module header ---- MODULE Name ---- before the first definition",
                _loc(file, data, _first_token(data, 0)))
    if not re.search(rb"^={4,}", data[header.end():], re.M):
        return ("parse error: the module is not closed: expected a line ==== after its last definition, "
                "found the end of the file", _loc(file, data, len(data.rstrip())))
    empty = _empty_definition(data, header.end())
    if empty is not None and (whole_module or empty[1] <= start):
        name, at, nxt = empty
        o = _loc(file, data, at)
        at_end = data.startswith(b"====", nxt)
        what = "the end of the module (====)" if at_end else _q(_word_at(data, nxt))
        # SANY points at the next definition, or at the empty one itself before ====.
        where = _loc(file, data, data.rfind(b"\n", 0, at) + 1) if at_end else _loc(file, data, nxt)
        return (f"parse error: the definition of {name} (line {o.line}) has no body: expected an expression "
                f"after '==', found {what}", where)
    if whole_module:
        end = _module_end(data)
        last = _TOKEN_BEFORE.search(data[:end].rstrip())
        tail = _BINARY_TAIL.search(last.group(1)) if last else None
        if last is not None and tail is not None:
            p = _loc(file, data, last.start(1) + tail.start(1))
            return (f"parse error: expected an expression after {_q(tail.group(1).decode('utf-8', 'replace'))} "
                    f"(line {p.line}, column {p.column}), found the end of the module (====)", _loc(file, data, end))
        inner = _localise(data, end)
        if inner is not None:
            return explain_unexpected(file, data, inner, _word_at(data, inner), False)
        return f"parse error: unexpected input {_q(snippet)}", _loc(file, data, start)
    if data[start - 1:start + 1] == b"==":
        start -= 1  # recovery split the `==` of the next definition
    before = data[:start].rstrip()
    prev = _TOKEN_BEFORE.search(before)
    found = _word_at(data, start) or snippet
    end_of_module = data.startswith(b"====", start) or not data[start:].strip()
    if prev is not None and _BINARY_TAIL.search(prev.group(1)):
        p = _loc(file, data, prev.start(1))
        tail = _BINARY_TAIL.search(prev.group(1))
        assert tail is not None
        op = tail.group(1).decode("utf-8", "replace")
        return (f"parse error: expected an expression after {_q(op)} (line {p.line}, column {p.column}), "
                f"found {'the end of the module' if end_of_module else _q(found)}", _loc(file, data, start))
    new_def = _DEF.match(data, data.rfind(b"\n", 0, start) + 1)
    if found.startswith("==") and new_def is not None:
        # `Op ==` read as the operand of the line before: that line's expression is unfinished.
        line_start = data.rfind(b"\n", 0, start) + 1
        prev_end = data[:line_start].rstrip()
        last = _TOKEN_BEFORE.search(prev_end)
        if last is None:
            return f"parse error: unexpected {_q(found)}", _loc(file, data, start)
        where = _loc(file, data, last.start(1))
        return (f"parse error: the expression ending at line {where.line} is unfinished: expected an operand "
                f"after {_q(last.group(1).decode('utf-8', 'replace'))} before the definition of "
                f"{new_def.group(1).decode()} starts", _loc(file, data, line_start))
    if found[:1] in (")", "]", "}") or found.startswith(">>"):
        return (f"parse error: {_q(found[:2] if found.startswith('>>') else found[:1])} without a matching "
                f"opening bracket", _loc(file, data, start))
    if found.startswith(","):
        nxt = _skip_blank(data, start + 1)
        if data[nxt:nxt + 1] in (b")", b"]", b"}") or data.startswith(b">>", nxt):
            return (f"parse error: expected an expression after ',', found {_q(_word_at(data, nxt)[:2])}",
                    _loc(file, data, nxt))
    after = f" after {_q(prev.group(1).decode('utf-8', 'replace')[-20:])}" if prev is not None else ""
    return (f"parse error: unexpected {_q(found)}{after}: expected an operator, a closing bracket or the next "
            f"definition", _loc(file, data, start))


def _q(text: str) -> str:
    """`text` quoted as written in the module (repr would double its backslashes)."""
    return f"'{text}'"


def _first_token(data: bytes, pos: int) -> int:
    m = re.compile(rb"\S").search(data, pos)
    return m.start() if m else 0


def _word_at(data: bytes, pos: int) -> str:
    m = re.compile(rb"\S+").match(data, pos)
    return m.group().decode("utf-8", "replace")[:40] if m else ""


def _empty_definition(data: bytes, start: int) -> tuple[str, int, int] | None:
    """(name, position of its ==, position of the next token) of the first top-level
    definition whose body is empty: the next token starts another definition or ends
    the module."""
    for m in _DEF.finditer(data, start):
        nxt = _skip_blank(data, m.end())
        if nxt >= len(data) or data.startswith(b"====", nxt) or _DEF.match(data, nxt) and \
                data.rfind(b"\n", 0, nxt) + 1 == nxt:
            return m.group(1).decode(), m.end() - 2, nxt
    return None


def next_token_loc(file: str, data: bytes, pos: int) -> Loc:
    """Where the next token after `pos` starts (past whitespace and comments)."""
    return _loc(file, data, _skip_blank(data, pos))


def _skip_blank(data: bytes, pos: int) -> int:
    """The next position after whitespace and comments."""
    while pos < len(data):
        if data[pos:pos + 1].isspace():
            pos += 1
        elif data.startswith(b"\\*", pos):
            nl = data.find(b"\n", pos)
            pos = len(data) if nl < 0 else nl
        elif data.startswith(b"(*", pos):
            end = _comment_end(data, pos)
            pos = len(data) if end < 0 else end
        else:
            break
    return pos


def _localise(data: bytes, end: int) -> int | None:
    """Where the parse really fails when tree-sitter's recovery gave up on the whole
    module: the error in the last definition (before ====) recovers once another
    definition follows it, so parse again with a dummy one inserted there."""
    try:
        import tree_sitter
        import tree_sitter_tlaplus
    except ImportError:
        return None
    probe = data[:end] + b"\nSafestateProbe__ == TRUE\n" + data[end:]
    root = tree_sitter.Parser(tree_sitter.Language(tree_sitter_tlaplus.language())).parse(probe).root_node
    stack = [root]
    while stack:
        n = stack.pop()
        if (n.type == "ERROR" or n.is_missing) and n.start_byte < end:
            return None if n.start_point == root.start_point else n.start_byte
        if n.has_error:
            stack.extend(reversed(n.children))
    return None
