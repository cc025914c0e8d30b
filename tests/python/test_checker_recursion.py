"""Recursion: a depth TLC handles is checked; one that never ends is TLC's
StackOverflowError -- a one-line error and TLC's exit code, never a traceback."""

from __future__ import annotations

import pytest

from conftest import run_safestate

SPEC = """---- MODULE Rec ----
EXTENDS Naturals
VARIABLE x
RECURSIVE F(_)
F(n) == IF n = 0 THEN 0 ELSE 1 + F(n - 1)
Init == x = {init}
Next == x' = {next}
====
"""


@pytest.mark.parametrize("where", ["init", "next"])
def test_recursion_two_thousand_deep_is_checked(where: str, tla_dir) -> None:
    init, nxt = ("F(2000)", "x") if where == "init" else ("0", "F(2000) % 2")
    path = tla_dir("Rec", SPEC.format(init=init, next=nxt), "INIT Init\nNEXT Next\n")
    p = run_safestate("check", str(path))
    assert p.returncode == 0, p.stdout + p.stderr


@pytest.mark.parametrize("where, code", [("init", 75), ("next", 255)])
def test_endless_recursion_is_a_clear_error_with_tlc_exit_code(where: str, code: int, tla_dir) -> None:
    init, nxt = ("F(10000000)", "x") if where == "init" else ("0", "F(10000000)")
    path = tla_dir("Rec", SPEC.format(init=init, next=nxt), "INIT Init\nNEXT Next\n")
    p = run_safestate("check", str(path))
    out = p.stdout + p.stderr
    assert p.returncode == code, out
    assert "recursion too deep" in out and "StackOverflowError" in out
    assert "Traceback" not in out and "internal error" not in out
