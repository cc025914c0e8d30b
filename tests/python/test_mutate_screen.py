"""Issue 28, Speed: whole sets within the budget by a screening cfg (docs/mutate.md
"Screening"). Every mutant is checked on the screening cfg (smaller constants) first; a
kill there is final and names that cfg; only the others are checked on the CI cfg,
which decides every other verdict.

A planted model with a constant Limit: the CI cfg has Limit = 3, the screening cfg
Limit = 1.  `count < Limit` -> `count <= Limit` lets count pass Limit under either
constant (killed on the screening cfg); `count >= 1` -> `count >= 2` breaks Seen only
once count can reach 2, which Limit = 1 never allows (killed on the CI cfg only)."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from safestate.cli import main

SCREENED = r"""---- MODULE Screened ----
EXTENDS Naturals
CONSTANT Limit
VARIABLES inp, count, seen
Init == inp = 0 /\ count = 0 /\ seen = FALSE
Next == \E i \in {0, 1} :
    /\ inp' = i
    /\ count' = IF count < Limit THEN count + i ELSE count
    /\ seen' = (seen \/ (i = 1 /\ count >= 1))
Bounded == count <= Limit
Seen == count >= 2 => seen
====
"""
BODY = "INIT Init\nNEXT Next\nINVARIANTS\n    Bounded\n    Seen\n"


@pytest.fixture
def screened(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> Path:
    d = tmp_path / "model"
    d.mkdir()
    (d / "Screened.tla").write_text(SCREENED)
    (d / "Screened.cfg").write_text("CONSTANT Limit = 3\n" + BODY)
    (d / "Screened_small.cfg").write_text("CONSTANT Limit = 1\n" + BODY)
    monkeypatch.setenv("SAFESTATE_CACHE_DIR", str(tmp_path / "cache"))
    return d / "Screened.tla"


def _mutate(model: Path, capsys: pytest.CaptureFixture[str], *extra: str) -> tuple[int, dict]:
    code = main(["mutate", str(model), "--inputs", "inp", "--observables", "count,seen", "--json",
                 "--workers", "1", *extra])
    return code, json.loads(capsys.readouterr().out)


def _find(report: dict, operator: str, replacement_part: str) -> dict:
    hits = [m for m in report["mutants"] if m["operator"] == operator and replacement_part in m["replacement"]]
    assert len(hits) == 1, [(m["operator"], m["replacement"]) for m in report["mutants"]]
    return hits[0]


def test_speed_screening_cfg_kill_is_final_and_a_ci_only_kill_names_the_ci_cfg(
        screened: Path, capsys: pytest.CaptureFixture[str]) -> None:
    small = screened.with_name("Screened_small.cfg")
    code, report = _mutate(screened, capsys, "--screen-config", str(small))
    assert code == 0
    assert report["screen_config"] == "Screened_small.cfg"
    on_screen = _find(report, "boundary", "count <= Limit")
    assert (on_screen["status"], on_screen["by"], on_screen["cfg"]) == ("killed", "property", "Screened_small.cfg")
    assert on_screen["violated"] == "Bounded"
    on_ci = _find(report, "literal", "count >= 2)")
    assert (on_ci["status"], on_ci["by"], on_ci["cfg"]) == ("killed", "property", "Screened.cfg")
    assert on_ci["violated"] == "Seen"
    # Every verdict other than a kill (or an error) there is the CI cfg's.
    assert all(m["cfg"] == "Screened.cfg" for m in report["mutants"] if m["status"] != "killed" and
               m["status"] != "error")
    assert report["counts"]["decided_on_screen"] == sum(m["cfg"] == "Screened_small.cfg" for m in report["mutants"])


def test_speed_screened_outcomes_are_cached_apart_from_unscreened_ones(
        screened: Path, capsys: pytest.CaptureFixture[str]) -> None:
    small = screened.with_name("Screened_small.cfg")
    _mutate(screened, capsys, "--screen-config", str(small))
    code, report = _mutate(screened, capsys, "--no-screen")
    assert code == 0 and report["cached"] == 0 and report["screen_config"] is None
    m = _find(report, "boundary", "count <= Limit")
    assert (m["status"], m["cfg"]) == ("killed", "Screened.cfg")
    _code, again = _mutate(screened, capsys, "--screen-config", str(small))
    assert again["cached"] == again["classified"]
    assert _find(again, "boundary", "count <= Limit")["cfg"] == "Screened_small.cfg"


def test_speed_screening_cfg_with_a_property_the_ci_cfg_lacks_is_an_input_error(
        screened: Path, capsys: pytest.CaptureFixture[str]) -> None:
    extra = screened.with_name("Extra.cfg")
    extra.write_text("CONSTANT Limit = 1\n" + BODY + "    TypeOK\n")
    code = main(["mutate", str(screened), "--inputs", "inp", "--observables", "count,seen",
                 "--screen-config", str(extra)])
    err = capsys.readouterr().err
    assert code == 2 and "TypeOK" in err and "Extra.cfg" in err


def test_speed_screening_cfg_the_original_violates_is_an_input_error(
        tmp_path: Path, capsys: pytest.CaptureFixture[str], monkeypatch: pytest.MonkeyPatch) -> None:
    # LargeLimit holds with Limit = 3 and fails with Limit = 1: a kill on such a
    # screening cfg would not be the mutant's.
    d = tmp_path / "m"
    d.mkdir()
    (d / "Screened.tla").write_text(SCREENED.replace("====", "LargeLimit == Limit >= 2 \\/ count = 0\n===="))
    body = BODY + "    LargeLimit\n"
    (d / "Screened.cfg").write_text("CONSTANT Limit = 3\n" + body)
    (d / "Small.cfg").write_text("CONSTANT Limit = 1\n" + body)
    monkeypatch.setenv("SAFESTATE_CACHE_DIR", str(tmp_path / "cache"))
    code = main(["mutate", str(d / "Screened.tla"), "--inputs", "inp", "--observables", "count,seen",
                 "--screen-config", str(d / "Small.cfg")])
    err = capsys.readouterr().err
    assert code == 2 and "Small.cfg" in err and "LargeLimit" in err


def test_speed_a_witness_lost_on_the_screening_cfg_is_a_kill_there(
        tmp_path: Path, capsys: pytest.CaptureFixture[str], monkeypatch: pytest.MonkeyPatch) -> None:
    # Witness_Seen: the original reaches seen under either constant.  `count >= 1` ->
    # `count >= 2` passes every property with Limit = 1 (count never reaches 2), but seen
    # is then never reached there: killed by the witness on the screening cfg, without
    # the CI cfg's check (which would kill it by Seen).
    d = tmp_path / "m"
    d.mkdir()
    (d / "Screened.tla").write_text(SCREENED.replace("====", "Witness_Seen == ~seen\n===="))
    (d / "Screened.cfg").write_text("CONSTANT Limit = 3\n" + BODY)
    (d / "Screened_small.cfg").write_text("CONSTANT Limit = 1\n" + BODY)
    monkeypatch.setenv("SAFESTATE_CACHE_DIR", str(tmp_path / "cache"))
    code, report = _mutate(d / "Screened.tla", capsys, "--screen-config", str(d / "Screened_small.cfg"))
    assert code == 0
    m = _find(report, "literal", "count >= 2)")
    assert (m["status"], m["by"], m["cfg"], m["witnesses"]) == ("killed", "witness", "Screened_small.cfg",
                                                                 ["Witness_Seen"])
    _code, unscreened = _mutate(d / "Screened.tla", capsys, "--no-screen")
    m = _find(unscreened, "literal", "count >= 2)")
    assert (m["status"], m["by"], m["cfg"]) == ("killed", "property", "Screened.cfg")
