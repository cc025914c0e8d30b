"""The native core's op table has one source (issue 32): bindings/python/tla_native/ops.def.
The C++ core reads it as an X-macro; checker/native/ops.py is generated from it and must
not drift from it (a drifted table makes the translator emit the wrong ops)."""

from __future__ import annotations

import importlib.util
import subprocess
import sys
from pathlib import Path
from types import ModuleType

import pytest

from conftest import REPO

SCRIPT = REPO / "scripts" / "gen_native_ops.py"


def _generator() -> ModuleType:
    spec = importlib.util.spec_from_file_location("gen_native_ops", SCRIPT)
    assert spec and spec.loader
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return mod


def test_checked_in_ops_py_is_what_ops_def_generates() -> None:
    p = subprocess.run([sys.executable, str(SCRIPT), "--check"], capture_output=True, text=True)
    assert p.returncode == 0, p.stderr


def test_ops_def_changed_without_regenerating_is_reported(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    gen = _generator()
    ops_def, ops_py = tmp_path / "ops.def", tmp_path / "ops.py"
    text = gen.DEF.read_text()
    ops_def.write_text(text)
    ops_py.write_text(gen.render(text))
    monkeypatch.setattr(gen, "DEF", ops_def)
    monkeypatch.setattr(gen, "OPS_PY", ops_py)
    monkeypatch.setattr(gen, "REPO", tmp_path)
    monkeypatch.setattr(sys, "argv", ["gen_native_ops.py", "--check"])
    assert gen.main() == 0
    # A new op inserted before the last one renumbers it: the check must fail.
    lines = text.splitlines()
    last = max(i for i, line in enumerate(lines) if line.startswith("TLA_OP("))
    lines.insert(last, 'TLA_OP(NEW_OP, 0, "an op added in the middle")')
    ops_def.write_text("\n".join(lines) + "\n")
    assert gen.main() == 1


def test_the_compiled_core_numbers_the_ops_as_the_translator() -> None:
    from safestate import _tla_native
    from safestate.checker.native.ops import Op
    assert tuple(_tla_native.OP_NAMES) == tuple(Op.__members__)
    assert _tla_native.OP_COUNT == len(Op)
    assert [int(op) for op in Op] == list(range(len(Op)))


def test_a_malformed_ops_def_line_names_its_line() -> None:
    gen = _generator()
    with pytest.raises(gen.DefError, match=r"ops.def:2: expected TLA_OP"):
        gen.parse('TLA_OP(CONST, 0, "a constant")\nTLA_OP(VAR, 2, "bad fold flag")\n')
    with pytest.raises(gen.DefError, match="defined twice: CONST"):
        gen.parse('TLA_OP(CONST, 0, "a")\nTLA_OP(CONST, 0, "b")\n')
