"""Issue 27, item 0: comments are comments, whatever is inside them (SANY's lexer:
block comments nest, a line comment runs to the end of its line, nothing inside a
comment is special, a string outside a comment opens none), and error locations
after a comment stay exact.  The PlusCal forms that tree-sitter-tlaplus's PlusCal
grammar rejects are corpus specs (`tests/tla/corpus/Pcal*.tla`)."""

from __future__ import annotations

import pytest

from safestate.tla.comments import blank_comments
from safestate.tla.errors import TlaError
from safestate.tla.parser import parse_text

HEAD = "---- MODULE M ----\nEXTENDS Naturals\n"


def _error(text: str) -> TlaError:
    with pytest.raises(TlaError) as err:
        parse_text(text, "M.tla")
    return err.value


def test_blanked_text_keeps_every_line_and_column() -> None:
    text = HEAD + "(* caf\u00e9 (* nested *) \"*) *)\nx == 1 \\* (* not opened\n\ty == 2\r\n====\n"
    blank = blank_comments(text)
    assert len(blank) == len(text)
    assert [len(line) for line in blank.splitlines()] == [len(line) for line in text.splitlines()]
    assert "café" not in blank and "nested" not in blank and "not opened" not in blank
    assert "x == 1" in blank and "\ty == 2\r\n" in blank


def test_pluscal_in_a_comment_is_not_parsed() -> None:
    text = HEAD + "(* --algorithm A {\n  { if (TRUE) skip; else skip; }\n} *)\nOp == 1\n====\n"
    [module] = parse_text(text, "M.tla")
    assert [d.name for d in module.units] == ["Op"]


def test_a_nested_comment_hides_its_whole_text() -> None:
    # Without nesting, the first `*)` would close the comment and `Op ==` be garbage.
    [module] = parse_text(HEAD + "(* outer (* inner *) Op == *)\nOp == 1\n====\n", "M.tla")
    assert [d.name for d in module.units] == ["Op"]


def test_a_string_in_a_comment_is_plain_text() -> None:
    # SANY: the `*)` inside the quotes closes the comment; what follows is code.
    err = _error(HEAD + '(* a "*) garbage" *)\nOp == 1\n====\n')
    assert (err.loc.line, err.loc.column) == (3, 10)


def test_comment_delimiters_in_a_string_open_no_comment() -> None:
    [module] = parse_text(HEAD + 'Op == "(* \\\\* no comment"\nOther == 2\n====\n', "M.tla")
    assert [d.name for d in module.units] == ["Op", "Other"]


def test_error_after_a_comment_is_reported_at_its_own_line_and_column() -> None:
    # Columns count characters: the accented letters in the comment count one each.
    text = HEAD + "(* --algorithm A\nvariables x = 0,\nbegin skip; end algorithm *)\n(* \u00e9t\u00e9 *) Op == 1 + ]\n====\n"
    err = _error(text)
    assert (err.loc.line, err.loc.column) == (6, 19)
    err = _error(HEAD + "Op == 1\n(* x *) B == IF 1 THEN 2 ELSE 3 4\n====\n")
    assert (err.loc.line, err.loc.column) == (4, 33)


def test_an_unclosed_comment_is_reported_where_it_opens() -> None:
    err = _error(HEAD + "Op == 1\n(* (* closed *) but not this one\n====\n")
    assert "possibly open comment starting around line 4" in err.message
    assert (err.loc.line, err.loc.column) == (4, 1)
