"""Issue 28: a mutant that passes every property but no longer reaches one of the model's
reachability witnesses (`Witness_X`) is killed by that witness -- a category of its own
in the report and the JSON, counted as killed in the score (docs/mutate.md)."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from mutate_specs import WITNESS_READS_BEHAVIOUR, WITNESSED

from safestate.cli import main

CFG = "INIT Init\nNEXT Next\nINVARIANTS\n    TypeOK\n    Safe\n"
ENGINES = ["native", "python"]


def _model(tmp_path: Path, monkeypatch: pytest.MonkeyPatch, name: str, text: str) -> Path:
    d = tmp_path / "model"
    d.mkdir()
    (d / f"{name}.tla").write_text(text)
    (d / f"{name}.cfg").write_text(CFG)
    monkeypatch.setenv("SAFESTATE_CACHE_DIR", str(tmp_path / "cache"))
    return d / f"{name}.tla"


def _mutate(model: Path, capsys: pytest.CaptureFixture[str], engine: str, *extra: str) -> dict:
    code = main(["mutate", str(model), "--inputs", "inp", "--observables", "alarm", "--json", "--workers", "1",
                 "--engine", engine, *extra])
    assert code == 0
    return json.loads(capsys.readouterr().out)


def _one(report: dict, operator: str, part: str) -> dict:
    hits = [m for m in report["mutants"] if m["operator"] == operator and part in m["replacement"]]
    assert len(hits) == 1, [(m["operator"], m["replacement"]) for m in report["mutants"]]
    return hits[0]


@pytest.mark.parametrize("engine", ENGINES)
def test_mutant_losing_a_witness_is_killed_by_it_and_counted(tmp_path: Path, monkeypatch: pytest.MonkeyPatch,
                                                              capsys: pytest.CaptureFixture[str], engine: str) -> None:
    report = _mutate(_model(tmp_path, monkeypatch, "Witnessed", WITNESSED), capsys, engine)
    # The alarm never raised: Safe (alarm => input 2) holds, the alarm situation is lost.
    m = _one(report, "unchanged", "alarm' = alarm")
    assert (m["status"], m["by"], m["witnesses"]) == ("killed", "witness", ["Witness_Alarm"])
    # Input 2 never offered: the same witness lost.
    m = _one(report, "drop-input-value", "{0, 1}")
    assert (m["status"], m["by"], m["witnesses"]) == ("killed", "witness", ["Witness_Alarm"])
    # A property's kill stays the property's.
    m = _one(report, "boundary", "(i # 2)")
    assert (m["status"], m["by"], m["violated"]) == ("killed", "property", "Safe")
    # Input 1 never offered: every witness still reached, a survivor.
    assert _one(report, "drop-input-value", "{0, 2}")["status"] == "survived"
    c = report["counts"]
    by_witness = [x for x in report["mutants"] if x.get("by") == "witness"]
    assert c["killed_by_witness"] == len(by_witness) >= 2
    assert report["score"] == round(c["killed"] / (c["killed"] + c["survived"]), 4)
    assert sum(k["killed_by_witness"] for k in report["operators"].values()) == len(by_witness)


@pytest.mark.parametrize("engine", ENGINES)
def test_witness_the_original_never_reaches_is_reported_and_never_kills(
        tmp_path: Path, monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str], engine: str) -> None:
    report = _mutate(_model(tmp_path, monkeypatch, "Witnessed", WITNESSED), capsys, engine)
    assert report["witnesses"] == ["Witness_Alarm"]
    assert report["witnesses_not_reached"] == ["Witness_Never"]
    assert all("Witness_Never" not in m.get("witnesses", []) for m in report["mutants"])


@pytest.mark.parametrize("engine", ENGINES)
def test_witness_is_evaluated_as_the_original_defines_it(tmp_path: Path, monkeypatch: pytest.MonkeyPatch,
                                                          capsys: pytest.CaptureFixture[str], engine: str) -> None:
    """`Hot(i) == i = 3`: the mutant never raises the alarm, but input 2 (the original's
    Hot) is still read, so Witness_Hot is reached: a survivor, not a witness kill (with
    the mutant's Hot the witness would never hold)."""
    report = _mutate(_model(tmp_path, monkeypatch, "HotWitness", WITNESS_READS_BEHAVIOUR), capsys, engine,
                     "--operator", "literal", "--operator", "drop-input-value")
    m = _one(report, "literal", "i = 3")
    assert m["status"] == "survived", m
    # The witness itself still kills where the situation is really lost.
    m = _one(report, "drop-input-value", "{0, 1}")
    assert (m["status"], m["witnesses"]) == ("killed", ["Witness_Hot"])


def test_text_report_lists_witness_kills_apart(tmp_path: Path, monkeypatch: pytest.MonkeyPatch,
                                               capsys: pytest.CaptureFixture[str]) -> None:
    model = _model(tmp_path, monkeypatch, "Witnessed", WITNESSED)
    assert main(["mutate", str(model), "--inputs", "inp", "--observables", "alarm", "--operator", "unchanged"]) == 0
    out = capsys.readouterr().out
    assert "KILLED BY A WITNESS" in out and "Witness_Alarm no longer reached" in out
    assert "of them by a witness" in out and "Witness_Never" in out
