"""Comments made invisible to the parser, as SANY's lexer makes them.

tree-sitter-tlaplus parses some comments itself: a ``(* --algorithm ... *)`` or
``--fair algorithm`` comment becomes a PlusCal subtree, and a PlusCal construct the
translator accepts but the grammar does not (C-syntax ``if (...) s; else ...``,
``RECURSIVE`` in a ``define`` block, a comma after the last variable) is then a
spurious syntax error in a spec that SANY and TLC accept.  So every comment is
replaced by spaces before tree-sitter sees the text.  Each character becomes one
space and line breaks are kept, so every line and column -- and hence every error
location -- is unchanged.

The rules are those of SANY's lexer (``tla+.jj``): from the module header on, ``\\*``
comments to the end of the line, ``(*`` opens a comment that nests and closes at the
matching ``*)``, and inside a comment nothing else is special (a ``"`` or a ``\\*``
there is plain text).  Outside comments a string literal is skipped, so a ``(*`` or
``\\*`` in a string starts no comment.  Text before the first module header is not
lexed by SANY and is left alone.  A comment that never closes is left as it is, for
the parser to report ("EOF reached, possibly open comment ...", `syntax_hints.py`).
"""

from __future__ import annotations

import re

_MODULE_START = re.compile(r"-{4,}\s*MODULE\b")
_NEXT = re.compile(r'"|\\\*|\(\*')
_STRING = re.compile(r'"(?:[^"\\\n]|\\.)*"?')
_NESTING = re.compile(r"\(\*|\*\)")
_NON_BREAK = re.compile(r"[^\n\r]")


def blank_comments(text: str) -> str:
    """`text` with every comment's characters (delimiters included) replaced by
    spaces, line breaks kept; an unclosed comment and what follows it unchanged."""
    start = _MODULE_START.search(text)
    if start is None:
        return text
    out: list[str] = [text[:start.start()]]
    pos = done = start.start()
    n = len(text)
    while True:
        m = _NEXT.search(text, pos)
        if m is None:
            break
        tok = m.group()
        if tok == '"':
            pos = _STRING.match(text, m.start()).end()  # type: ignore[union-attr]
            continue
        if tok == "\\*":
            nl = text.find("\n", m.start())
            end = n if nl < 0 else nl
            if end > 0 and text[end - 1:end] == "\r":
                end -= 1
        else:
            end = _block_end(text, m.end())
            if end < 0:
                break
        out.append(text[done:m.start()])
        out.append(_NON_BREAK.sub(" ", text[m.start():end]))
        pos = done = end
    out.append(text[done:])
    return "".join(out)


def _block_end(text: str, pos: int) -> int:
    """End of the block comment whose ``(*`` ends at `pos`, or -1 if it never closes."""
    depth = 1
    for m in _NESTING.finditer(text, pos):
        depth += 1 if m.group() == "(*" else -1
        if depth == 0:
            return m.end()
    return -1
