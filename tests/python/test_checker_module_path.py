"""The module search path (issue 9): a model EXTENDS or INSTANCEs a module kept in
another folder, found through SAFESTATE_MODULE_PATH (the equivalent of TLC's
-DTLA-Library); without it the error names the module and the folders searched."""

from __future__ import annotations

import os
from pathlib import Path

from conftest import run_safestate

SHARED = """---- MODULE Shared ----
EXTENDS Naturals
Step(x, n) == (x + 1) % n
====
"""

MODEL = """---- MODULE UsesShared ----
EXTENDS Shared
S == INSTANCE Shared
VARIABLE x
Init == x = 0
Next == x' = S!Step(x, 5) /\\ x' = Step(x, 5)
Inv == x < 4
====
"""


def _layout(tmp_path: Path) -> tuple[Path, Path]:
    lib = tmp_path / "lib"
    model = tmp_path / "model"
    lib.mkdir()
    model.mkdir()
    (lib / "Shared.tla").write_text(SHARED)
    (model / "UsesShared.tla").write_text(MODEL)
    (model / "UsesShared.cfg").write_text("INIT Init\nNEXT Next\nINVARIANT Inv\n")
    return lib, model / "UsesShared.tla"


def test_model_extends_a_module_from_another_folder(tmp_path: Path, monkeypatch) -> None:
    lib, tla = _layout(tmp_path)
    monkeypatch.setenv("SAFESTATE_MODULE_PATH", os.pathsep.join([str(tmp_path / "nowhere"), str(lib)]))
    p = run_safestate("check", str(tla))
    out = p.stdout + p.stderr
    # The shared step is really used: x counts 0..4 and Inv (x < 4) fails at x = 4.
    assert p.returncode == 12, out
    assert "Invariant Inv is violated" in out
    assert "x = 4" in out


def test_missing_shared_module_names_the_folders_searched(tmp_path: Path, monkeypatch) -> None:
    _, tla = _layout(tmp_path)
    monkeypatch.delenv("SAFESTATE_MODULE_PATH", raising=False)
    p = run_safestate("check", str(tla))
    out = p.stdout + p.stderr
    assert p.returncode != 0
    assert "Traceback" not in out
    assert "Cannot find source file for module Shared" in out
    assert str(tla.parent) in out and "SAFESTATE_MODULE_PATH" in out
    assert "UsesShared.tla:2:" in out
