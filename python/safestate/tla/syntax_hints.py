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
