"""Issue 28, "where it shows": a system's last mutation score in `safestate systems`, and
the evidence page that lists its survivors -- a survivor the design page justifies
carries the justification and is not a gap.

A planted registry (systems/Planted/system.toml in a temporary repository): the model's
invariant pins `out` down and nothing pins `latch` down, so the mutant that freezes the
latch survives; the manifest justifies the survivors of `Next` that freeze it, pointing
at a section of the design page."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from safestate.cli import main
from safestate.evidence import model_mutation
from safestate.mutate import results
from safestate.systems.registry import find

PLANTED = r"""---- MODULE Planted ----
EXTENDS Naturals
VARIABLES inp, out, latch
Init == inp = 0 /\ out = 0 /\ latch = FALSE
Next == \E i \in {0, 1, 2} :
    /\ inp' = i
    /\ out' = i
    /\ latch' = (latch \/ i = 2)
TypeOK == inp \in 0..2 /\ out \in 0..2 /\ latch \in BOOLEAN
Safe == inp = out
====
"""
DESIGN = "# Planted\n\n## Why the latch may stay open\n\nThe latch is a display only.\n"
MANIFEST = """name = "Planted"
design = "docs/design/planted.md"
model = "models/Planted.tla"
configs = ["models/Planted.cfg"]
[mutate]
inputs = ["inp"]
observables = ["out", "latch"]
"""
JUSTIFIED = """[[mutate.justified]]
definition = "Next"
operator = "unchanged"
contains = "latch' = latch"
design = "docs/design/planted.md#why-the-latch-may-stay-open"
why = "the latch is a display only"
"""


def _repo(tmp_path: Path, monkeypatch: pytest.MonkeyPatch, manifest: str) -> Path:
    root = tmp_path / "repo"
    for d in ("models", "docs/design", "systems/Planted"):
        (root / d).mkdir(parents=True)
    (root / "models" / "Planted.tla").write_text(PLANTED)
    (root / "models" / "Planted.cfg").write_text("INIT Init\nNEXT Next\nINVARIANTS\n    TypeOK\n    Safe\n")
    (root / "docs" / "design" / "planted.md").write_text(DESIGN)
    (root / "systems" / "Planted" / "system.toml").write_text(manifest)
    monkeypatch.setenv("SAFESTATE_SYSTEMS", str(root / "systems"))
    monkeypatch.setenv("SAFESTATE_CACHE_DIR", str(tmp_path / "cache"))
    return root


def _latch_survivor(report: dict) -> dict:
    hits = [m for m in report["mutants"] if m["operator"] == "unchanged" and "latch' = latch" in m["replacement"]]
    assert len(hits) == 1
    return hits[0]


def test_systems_shows_the_last_mutation_score_with_its_sample_and_date(
        tmp_path: Path, monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str]) -> None:
    _repo(tmp_path, monkeypatch, MANIFEST)
    assert main(["systems", "--json"]) == 0
    assert json.loads(capsys.readouterr().out)["systems"][0]["mutation"] is None  # never measured
    assert main(["mutate", "Planted", "--sample", "4", "--seed", "3", "--json"]) == 0
    report = json.loads(capsys.readouterr().out)
    assert main(["systems", "--json"]) == 0
    shown = json.loads(capsys.readouterr().out)["systems"][0]["mutation"]
    assert shown["score"] == report["score"] and shown["counts"] == report["counts"]
    assert shown["sampled"] is True and shown["seed"] == 3 and shown["classified"] == 4
    assert shown["when"] == report["when"]
    assert main(["systems"]) == 0
    table = capsys.readouterr().out
    assert "sample 4 seed 3" in table


def test_evidence_page_lists_each_survivor_with_its_trace_and_counts_it_as_a_gap(
        tmp_path: Path, monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str]) -> None:
    _repo(tmp_path, monkeypatch, MANIFEST)
    assert main(["mutate", "Planted", "--json"]) == 0
    report = json.loads(capsys.readouterr().out)
    m = _latch_survivor(report)
    assert m["status"] == "survived" and "justified" not in m
    system = find("Planted")
    assert system is not None
    out = tmp_path / "package"
    extras: list[tuple[str, str]] = []
    gaps = model_mutation.write(out, [system], [], extras)
    assert gaps == {"Planted": report["counts"]["survived"]}
    page = (out / "mutation" / "model" / "Planted.html").read_text()
    assert "latch&#x27; = latch" in page and "unchanged" in page
    assert "TRUE | FALSE" in page  # the difference trace: the original latches, the mutant does not
    assert any("Planted model mutation score" in t for t, _ in extras)


def test_justified_survivor_carries_the_design_reason_and_is_not_a_gap(
        tmp_path: Path, monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str]) -> None:
    _repo(tmp_path, monkeypatch, MANIFEST + JUSTIFIED)
    assert main(["mutate", "Planted", "--json"]) == 0
    report = json.loads(capsys.readouterr().out)
    m = _latch_survivor(report)
    assert m["status"] == "survived"
    assert m["justified"] == {"design": "docs/design/planted.md#why-the-latch-may-stay-open",
                              "why": "the latch is a display only"}
    assert report["gaps"] == report["counts"]["survived"] - report["justified"]
    system = find("Planted")
    assert system is not None
    gaps = model_mutation.write(tmp_path / "package", [system], [], [])
    assert gaps["Planted"] == report["gaps"]
    page = (tmp_path / "package" / "mutation" / "model" / "Planted.html").read_text()
    assert "justified</span>" in page and "the latch is a display only" in page


def test_justification_naming_a_missing_design_anchor_is_an_input_error(
        tmp_path: Path, monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str]) -> None:
    _repo(tmp_path, monkeypatch, MANIFEST + JUSTIFIED.replace("#why-the-latch-may-stay-open", "#no-such-section"))
    assert main(["mutate", "Planted"]) == 2
    err = capsys.readouterr().err
    assert "system.toml: [[mutate.justified]] entry 1" in err and "no anchor #no-such-section" in err
    system = find("Planted")
    assert system is not None
    with pytest.raises(results.JustificationError):
        results.justifications(system)


def test_every_registered_justification_names_an_existing_design_anchor() -> None:
    """A renamed design heading must fail here, not exit 2 in the main job's mutate run."""
    from safestate.systems.registry import load_all
    systems = load_all()
    entries = {s.name: results.justifications(s) for s in systems}  # raises on a bad entry
    assert entries["Protection"] and entries["RuntimeSupervisor"]
