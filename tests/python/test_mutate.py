"""Issue 28: `safestate mutate`, the mutation score of a model's properties.

A planted model: its invariant Safe pins `out` down, nothing pins `latch` down (a
deliberately weak property set), and `i > 5` can never hold for an input in {0, 1, 2}
(mutating that boundary changes nothing observable)."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from mutate_specs import VIEWED

from safestate.cli import main
from safestate.mutate.generate import generate

PLANTED = r"""---- MODULE Planted ----
EXTENDS Naturals
VARIABLES inp, out, latch
Init == inp = 0 /\ out = 0 /\ latch = FALSE
Next == \E i \in {0, 1, 2} :
    /\ inp' = i
    /\ out' = IF i > 5 THEN 2 ELSE i
    /\ latch' = (latch \/ i = 2)
TypeOK == inp \in 0..2 /\ out \in 0..2 /\ latch \in BOOLEAN
Safe == inp = out
====
"""
CFG = "INIT Init\nNEXT Next\nINVARIANTS\n    TypeOK\n    Safe\n"


@pytest.fixture
def planted(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> Path:
    d = tmp_path / "model"
    d.mkdir()
    (d / "Planted.tla").write_text(PLANTED)
    (d / "Planted.cfg").write_text(CFG)
    monkeypatch.setenv("SAFESTATE_CACHE_DIR", str(tmp_path / "cache"))
    return d / "Planted.tla"


def _mutate(model: Path, capsys: pytest.CaptureFixture[str], *extra: str) -> tuple[int, dict]:
    code = main(["mutate", str(model), "--inputs", "inp", "--observables", "out,latch", "--json",
                 "--workers", "2", *extra])
    out = capsys.readouterr().out
    return code, json.loads(out)


def _find(report: dict, operator: str, replacement_part: str) -> dict:
    hits = [m for m in report["mutants"] if m["operator"] == operator and replacement_part in m["replacement"]]
    assert len(hits) == 1, [(m["operator"], m["replacement"]) for m in report["mutants"]]
    return hits[0]


def test_weak_invariant_shows_a_survivor_and_its_difference_trace(planted: Path,
                                                                   capsys: pytest.CaptureFixture[str]) -> None:
    code, report = _mutate(planted, capsys)
    assert code == 0
    m = _find(report, "unchanged", "latch' = latch")
    assert m["status"] == "survived"
    # The shortest input trace that tells them apart: one step with input 2.
    last = m["table"][-1]
    assert len(m["table"]) == 2 and last["inputs"] == {"inp": "2"}
    assert last["original"]["latch"] == "TRUE" and last["mutant"]["latch"] == "FALSE"
    assert m["itf"]["vars"] == ["inp", "original.out", "original.latch", "mutant.out", "mutant.latch"]
    assert m["itf"]["states"][-1]["mutant.latch"] is False


def test_equivalent_mutant_is_recognised_and_not_counted(planted: Path, capsys: pytest.CaptureFixture[str]) -> None:
    code, report = _mutate(planted, capsys)
    m = _find(report, "boundary", "IF i >= 5")
    assert m["status"] == "equivalent"
    c = report["counts"]
    assert report["score"] == round(c["killed"] / (c["killed"] + c["survived"]), 4)
    assert c["equivalent"] >= 1


def test_killed_mutant_names_its_invariant_and_trace_length(planted: Path,
                                                            capsys: pytest.CaptureFixture[str]) -> None:
    _, report = _mutate(planted, capsys)
    m = _find(report, "swap-if", "THEN i ELSE 2")
    assert m["status"] == "killed" and m["violated"] == "Safe" and m["trace_length"] == 2


def test_text_report_prints_score_and_survivor_table(planted: Path, capsys: pytest.CaptureFixture[str]) -> None:
    code = main(["mutate", str(planted), "--inputs", "inp", "--observables", "out,latch", "--operator", "unchanged"])
    out = capsys.readouterr().out
    assert code == 0
    assert "mutation score" in out and "SURVIVED" in out and "latch (orig | mutant)" in out


def test_input_never_offered_shows_the_step_one_side_cannot_take(planted: Path,
                                                                  capsys: pytest.CaptureFixture[str]) -> None:
    code = main(["mutate", str(planted), "--inputs", "inp", "--observables", "out,latch",
                 "--operator", "drop-input-value"])
    out = capsys.readouterr().out
    assert code == 0 and "input value 2 never offered" in out
    assert "takes the step (orig | mutant)" in out and "yes | no" in out


def test_second_run_is_served_from_the_cache(planted: Path, capsys: pytest.CaptureFixture[str]) -> None:
    _, first = _mutate(planted, capsys, "--operator", "boundary")
    _, second = _mutate(planted, capsys, "--operator", "boundary")
    assert first["cached"] == 0 and second["cached"] == second["classified"] > 0
    assert [m["status"] for m in first["mutants"]] == [m["status"] for m in second["mutants"]]


def test_second_run_with_every_outcome_cached_checks_not_even_the_original(
        planted: Path, capsys: pytest.CaptureFixture[str], monkeypatch: pytest.MonkeyPatch) -> None:
    import safestate.mutate.classify as classify
    _, first = _mutate(planted, capsys, "--operator", "boundary")
    checks: list[str] = []

    def counted(name: str) -> object:
        real = getattr(classify, name)

        def call(*a: object, **k: object) -> object:
            checks.append(name)
            return real(*a, **k)
        return call
    for name in ("check_model", "native_labelled"):
        monkeypatch.setattr(classify, name, counted(name))
    _, second = _mutate(planted, capsys, "--operator", "boundary")
    assert checks == [] and second["cached"] == second["classified"] > 0
    assert (second["score"], second["not_used_invariants"]) == (first["score"], first["not_used_invariants"])
    # One byte of the original changed: it is checked again (and so is every mutant).
    planted.write_text(planted.read_text().replace("Safe == inp = out", "Safe == out = inp"))
    _, third = _mutate(planted, capsys, "--operator", "boundary")
    assert "check_model" in checks and third["cached"] == 0


def test_cached_outcomes_survive_a_change_to_another_model_of_the_folder_not_to_a_module_the_spec_loads(
        planted: Path, capsys: pytest.CaptureFixture[str]) -> None:
    other = planted.parent / "Other.tla"
    other.write_text("---- MODULE Other ----\nEXTENDS Naturals\nK == 1\n====\n")
    _, first = _mutate(planted, capsys, "--operator", "boundary")
    other.write_text(other.read_text().replace("K == 1", "K == 2"))
    _, second = _mutate(planted, capsys, "--operator", "boundary")
    assert first["cached"] == 0 and second["cached"] == second["classified"] > 0
    # Now the spec extends Other: a change to Other is a change to the spec's meaning.
    planted.write_text(planted.read_text().replace("EXTENDS Naturals", "EXTENDS Naturals, Other"))
    _, third = _mutate(planted, capsys, "--operator", "boundary")
    other.write_text(other.read_text().replace("K == 2", "K == 3"))
    _, fourth = _mutate(planted, capsys, "--operator", "boundary")
    assert third["cached"] == 0 and fourth["cached"] == 0


def test_min_score_fails_below_and_usage_errors_exit_2(planted: Path, capsys: pytest.CaptureFixture[str]) -> None:
    code, _ = _mutate(planted, capsys, "--operator", "unchanged", "--min-score", "0.99")
    assert code == 3
    assert main(["mutate", "NoSuchSystem"]) == 2
    assert main(["mutate", str(planted), "--inputs", "inp", "--observables", "nope"]) == 2
    assert "nope" in capsys.readouterr().err


def test_sample_is_stratified_by_operator(planted: Path, capsys: pytest.CaptureFixture[str]) -> None:
    _, full = _mutate(planted, capsys, "--no-cache")
    _, sample = _mutate(planted, capsys, "--sample", "6", "--seed", "1")
    assert sample["classified"] == 6 and sample["generated"] == full["generated"] and sample["sampled"]
    assert len({m["operator"] for m in sample["mutants"]}) >= 5


SMALL = r"""---- MODULE Small ----
EXTENDS Naturals
VARIABLES x, y
Init == x = 0 /\ y = [a |-> 1, b |-> 2]
Next == \/ /\ x < 3 /\ x' = x + 1 /\ y' = [y EXCEPT !.a = 3, !.b = 4]
        \/ /\ x' = IF x = 1 THEN 2 ELSE IF x # 2 THEN 1 ELSE 0
           /\ y' = y
        \/ /\ x' = CASE x = 1 -> 2 [] OTHER -> 0
           /\ \E v \in BOOLEAN : y' = [y EXCEPT !.a = IF v THEN 1 ELSE 0]
Unused == x > 100
====
"""

EXPECTED = {
    "drop-conjunct": ["TRUE /\\ x' = x + 1"],
    "negate": ["IF ~(x = 1) THEN", "CASE ~(x = 1) ->"],
    "boundary": ["x <= 3", "IF x # 1", "IF x = 2"],
    "literal": ["x < 4", "x < 2", "x' = x + 2"],
    "swap-if": ["IF x = 1 THEN IF x # 2 THEN 1 ELSE 0 ELSE 2"],
    "delete-arm": ["x' = IF x # 2 THEN 1 ELSE 0", "x' = CASE x = 1 -> 2\n"],
    "swap-steps": ["IF x # 2 THEN 1 ELSE IF x = 1 THEN 2 ELSE 0"],
    "unchanged": ["x' = x /\\ y'", "x' = x + 1 /\\ y' = y\n"],
    "drop-except": ["[y EXCEPT !.b = 4]", "[y EXCEPT !.a = 3]"],
    "drop-disjunct": ["Next == \\/ FALSE"],
    "drop-input-value": ["\\E v \\in {TRUE}", "\\E v \\in {FALSE}"],
}


@pytest.mark.parametrize("operator", sorted(EXPECTED))
def test_each_operator_generates_its_mutants(tmp_path: Path, operator: str) -> None:
    (tmp_path / "Small.tla").write_text(SMALL)
    text = SMALL.encode()
    mutants = generate(tmp_path / "Small.tla", "Init", "Next", operators=[operator])
    assert mutants and all(m.operator == operator for m in mutants)
    texts = [m.apply(text).decode() for m in mutants]
    for want in EXPECTED[operator]:
        assert any(want in t for t in texts), (want, [m.what for m in mutants])
    # Only behaviour definitions: `Unused` (no INIT/NEXT use) is never mutated.
    assert all(m.definition in ("Init", "Next") for m in mutants)
    # The declarative form (models/mutants/*.toml) substitutes to the same text.
    for m, t in zip(mutants, texts):
        assert text.decode().count(m.original) == 1 and text.decode().replace(m.original, m.patched) == t


TRAILING = r"""---- MODULE Trailing ----
EXTENDS Naturals
VARIABLES x
Ok(v) ==
    /\ v >= 0
    /\ \/ v = 1
       \/ v = 2

\* a comment between two definitions
Init == x = 0
Next == /\ Ok(x) \/ x = 0
        /\ x' = IF x < 2 THEN x + 1 ELSE 0
===="""


def test_every_mutant_of_a_definition_followed_by_comments_still_parses(tmp_path: Path) -> None:
    # The grammar lets a list's last item run on over the comments after it: an edit
    # there must not glue the next definition to its replacement (`TRUEInit ==`).
    from safestate.tla.parser import parse_text
    (tmp_path / "Trailing.tla").write_text(TRAILING)
    mutants = generate(tmp_path / "Trailing.tla", "Init", "Next")
    dropped = [m for m in mutants if m.operator == "drop-conjunct" and "v = 1" in m.what]
    assert dropped and dropped[0].original.rstrip().endswith("v = 2")
    for m in mutants:
        parse_text(m.apply(TRAILING.encode()).decode(), "Trailing.tla")  # raises on a syntax error


def test_every_operator_is_documented_in_docs_mutate() -> None:
    from safestate.mutate.operators import OPERATORS
    doc = (Path(__file__).resolve().parents[2] / "docs" / "mutate.md").read_text()
    for name, op in OPERATORS.items():
        assert f"| `{name}` |" in doc, name
        assert op.doc, name


def test_every_registered_system_declares_inputs_and_observables_of_its_model() -> None:
    """Issue 28: observables and inputs are declared once per system (system.toml
    [mutate]); a renamed model variable must fail here, not in a mutation run."""
    from safestate.checker.model import load_model
    from safestate.systems.registry import load_all
    systems = load_all()
    assert systems
    for s in systems:
        decl = s.extra.get("mutate")
        assert decl and decl.get("inputs") and decl.get("observables"), s.name
        variables = load_model(str(s.model), str(s.ci_config)).variables
        for name in decl["inputs"] + decl["observables"]:
            assert name in variables, (s.name, name)
        assert not set(decl["inputs"]) & set(decl["observables"]), s.name


def test_view_hidden_sticky_variable_gives_no_false_survivor(tmp_path: Path, capsys: pytest.CaptureFixture[str],
                                                              monkeypatch: pytest.MonkeyPatch) -> None:
    """`note` is outside the VIEW and kept from state to state: the original's state
    (0, 0, "b") shares its fingerprint with the initial (0, 0, "a").  The mutant
    `THEN 1` changes only the unobserved h (to 1 after the first input 1), so it is
    equivalent; taking the successors of the pair (0, 0, "b") / (0, 1, "b") from the
    initial state, which has the same fingerprint, would show a false difference in note."""
    (tmp_path / "Viewed.tla").write_text(VIEWED)
    (tmp_path / "Viewed.cfg").write_text("INIT Init\nNEXT Next\nVIEW View\nINVARIANT TypeOK\n")
    monkeypatch.setenv("SAFESTATE_CACHE_DIR", str(tmp_path / "cache"))
    code = main(["mutate", str(tmp_path / "Viewed.tla"), "--inputs", "inp", "--observables", "note",
                 "--operator", "literal", "--json"])
    report = json.loads(capsys.readouterr().out)
    assert code == 0
    m = _find(report, "literal", "THEN 1 ELSE h")
    assert m["status"] == "equivalent", m


def test_only_selects_mutants_by_id_and_an_unmatched_text_exits_2(planted: Path,
                                                                  capsys: pytest.CaptureFixture[str]) -> None:
    _, report = _mutate(planted, capsys, "--only", "unchanged@Next")
    assert report["classified"] >= 1
    assert all(m["mutant"].startswith("unchanged@Next") for m in report["mutants"])
    assert main(["mutate", str(planted), "--inputs", "inp", "--observables", "out,latch", "--only", "nope@X"]) == 2
    assert "nope@X" in capsys.readouterr().err


CHAINED = r"""---- MODULE Chained ----
EXTENDS Naturals
VARIABLES x, y
Row(a, b) ==
    IF a = 0 THEN 1
    ELSE IF \/ a = 1 /\ b = 0
            \/ a = 2 /\ b = 1 THEN 2
    ELSE IF a = 2 THEN [r |-> 3, s |-> 4].r
    ELSE 0
Init == x = 0 /\ y = 0
Next == /\ x' = (x + 1) % 3
        /\ y' = Row(x, y) % 2
===="""


def test_every_mutant_that_moves_a_junction_list_keeps_it_aligned(tmp_path: Path) -> None:
    """A condition written as a junction list of several lines, moved by deleting,
    swapping or negating a priority step, keeps its bullets aligned: every mutant loads
    (before, five of the Safety service's were errors, "Precedence conflict between ops
    \\/ and /\\"), and deleting the first step gives the same disjunction."""
    from safestate.checker.model import load_model
    (tmp_path / "Chained.cfg").write_text("INIT Init\nNEXT Next\n")
    (tmp_path / "Chained.tla").write_text(CHAINED)
    mutants = [m for m in generate(tmp_path / "Chained.tla", "Init", "Next") if m.definition == "Row"]
    moved = {m.operator for m in mutants if "\\/ a = 1" in m.original}
    assert {"delete-arm", "swap-if", "swap-steps", "negate"} <= moved
    for m in mutants:
        d = tmp_path / m.id.replace("@", "_").replace(":", "_").replace("#", "_")
        d.mkdir()
        (d / "Chained.tla").write_text(m.apply(CHAINED.encode()).decode())
        (d / "Chained.cfg").write_text("INIT Init\nNEXT Next\n")
        load_model(str(d / "Chained.tla"), str(d / "Chained.cfg"))  # raises on a precedence conflict
    first = next(m for m in mutants if m.operator == "delete-arm" and "a = 0" in m.what)
    text = first.apply(CHAINED.encode()).decode().split("\n")
    one, two = (next(x for x in text if f"\\/ a = {k}" in x) for k in (1, 2))
    assert one.index("\\/") == two.index("\\/")
