"""Parsing of TLC .cfg files."""

from __future__ import annotations

import pytest

from safestate.checker.cfg import parse_config_text
from safestate.tla.errors import TlaError
from safestate.tla.values import ModelValue


def test_checker_cfg_parses_every_statement() -> None:
    cfg = parse_config_text("""\\* comment
CONSTANTS N = 3  S = {a, b}  a = a  Name = "x"
CONSTANT C <- Op
(* block
   comment *)
SPECIFICATION Spec
INVARIANTS Inv1 Inv2
INVARIANT Inv3
PROPERTY Live
CONSTRAINT Bound
ACTION_CONSTRAINT Step
SYMMETRY Sym
VIEW View
CHECK_DEADLOCK FALSE
""", "m.cfg")
    assert cfg.constants["N"][0] == 3
    assert cfg.constants["S"][0] == frozenset({ModelValue("a"), ModelValue("b")})
    assert cfg.constants["a"][0] is ModelValue("a")
    assert cfg.constants["Name"][0] == "x"
    assert cfg.substitutions["C"][0] == "Op"
    assert cfg.specification.name == "Spec"
    assert [i.name for i in cfg.invariants] == ["Inv1", "Inv2", "Inv3"]
    assert [p.name for p in cfg.properties] == ["Live"]
    assert cfg.constraints[0].name == "Bound" and cfg.action_constraints[0].name == "Step"
    assert cfg.symmetry.name == "Sym" and cfg.view.name == "View"
    assert cfg.check_deadlock is False
    assert cfg.invariants[1].loc.line == 7


def test_checker_cfg_init_next_and_default_deadlock_check() -> None:
    cfg = parse_config_text("INIT Init NEXT Next", "m.cfg")
    assert cfg.init.name == "Init" and cfg.next.name == "Next" and cfg.check_deadlock


@pytest.mark.parametrize("text,line", [("CONSTANT N 3", 1), ("INIT\n", 1), ("\nCHECK_DEADLOCK maybe", 2),
                                       ("FOO Bar", 1), ("CONSTANT N = {1, 2", 1)])
def test_checker_cfg_errors_have_positions(text: str, line: int) -> None:
    with pytest.raises(TlaError) as err:
        parse_config_text(text, "m.cfg")
    assert err.value.loc.file == "m.cfg" and err.value.loc.line == line


@pytest.mark.parametrize("text,expecting,column", [("CONSTANT T = <<1, 2>>", "= or <-", 14),
                                                   ("CONSTANT Neg = -3", "= or <-", 16),
                                                   ("CONSTANT S = {1, -3}", "}", 18),
                                                   ("CONSTANT S = {<<1, 2>>}", "}", 15)])
def test_checker_cfg_rejects_tuples_and_negative_numbers_as_tlc(text: str, expecting: str, column: int) -> None:
    """TLC 1.8.0's cfg grammar has no tuples and no negative numbers (measured: exit 255,
    "It was expecting = or <-, but did not find it.", or "}" inside a set)."""
    with pytest.raises(TlaError) as err:
        parse_config_text(text, "m.cfg")
    assert f"It was expecting {expecting}, but did not find it." in err.value.message
    assert (err.value.loc.line, err.value.loc.column) == (1, column)


def test_checker_cfg_module_specific_substitution_is_parsed() -> None:
    """`Op <- [M] Def` (checked against TLC by the corpus spec ModuleOverride)."""
    cfg = parse_config_text("CONSTANTS\n  MaxSpeed <- [PumpLimits] TestMax\n  N = 2\n", "m.cfg")
    assert [s[:3] for s in cfg.module_substitutions] == [("MaxSpeed", "PumpLimits", "TestMax")]
    assert cfg.module_substitutions[0][3].line == 2 and cfg.constants["N"][0] == 2


@pytest.mark.parametrize("value", ["[a |-> 1, b |-> 2]", "[1, 2]", "{[a |-> 1]}", "[a : {1}]"])
def test_checker_cfg_record_or_function_value_is_refused_as_by_tlc(value: str) -> None:
    """TLC 1.8.0 rejects `[...]` values in a .cfg (ConfigFileException); so do we,
    saying how to write it instead."""
    with pytest.raises(TlaError) as err:
        parse_config_text(f"INIT Init\nNEXT Next\nCONSTANT C = {value}\n", "m.cfg")
    assert err.value.loc.line == 3 and "record or function value" in err.value.message
    assert "C <- ItsName" in err.value.message
