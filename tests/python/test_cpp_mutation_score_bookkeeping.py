"""The C++ mutation score's bookkeeping (issue 15, conform/cpp_mutants/score.py and
merge_scores.py): mutant ids that cannot collide, a broken mutants' tree that is an error
rather than a column of "stillborn" mutants, survivors re-evaluated after new tests, and
runs with different seeds merged into one sample."""

from __future__ import annotations

import argparse
import subprocess
import sys
from pathlib import Path

import pytest

REPO = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(REPO / "conform" / "cpp_mutants"))

import merge_scores  # noqa: E402
import score  # noqa: E402
from mutate import Mutant  # noqa: E402

# an equivalent mutant listed in equivalent.toml (a comment wrapped in a block comment)
EQUIV = {"where": "include/safestate/arm_kinematics.hpp:26", "file": "include/safestate/arm_kinematics.hpp",
         "line": 26, "original": "/// frame, metres.", "mutant": "/*/// frame, metres.*/"}


def _row(where: str, status: str, **kw: object) -> dict:
    file, line = where.rsplit(":", 1)
    return {"id": f"um_{where}", "where": where, "file": file, "line": int(line), "original": f"a{line}",
            "mutant": f"b{line}", "status": status} | kw


def _run(seed: int, rows: list[dict]) -> dict:
    return {"tool": "universalmutator 1.14.1", "targets": list(score.TARGETS), "generated": 9516,
            "generated_per_file": {}, "seed": seed, "mutants": rows, **score.counts(rows)}


def test_a_header_and_a_source_sharing_a_name_get_distinct_mutant_ids(tmp_path):
    """src/machine_state.cpp and include/safestate/machine_state.hpp: equal ids became two
    CMake targets of one name, the tree stopped configuring, and every mutant after that
    was counted stillborn."""
    files = [REPO / "src" / "machine_state.cpp", REPO / "include" / "safestate" / "machine_state.hpp"]
    mutants = score.generate(files, tmp_path)
    ids = [m.id for m in mutants]
    assert len(ids) == len(set(ids)) > 100
    assert {m.id.rsplit("_", 1)[0] for m in mutants} == {"um_machine_state_cpp", "um_machine_state_hpp"}


def _ninja_fails(monkeypatch: pytest.MonkeyPatch, stdout: str) -> None:
    monkeypatch.setattr(score.subprocess, "run",
                        lambda *a, **k: subprocess.CompletedProcess(a[0], 1, stdout=stdout, stderr=""))


MUT = Mutant("um_config_7", "include/safestate/config.hpp:3", "a  =>  b", "include/safestate/config.hpp", "a", "b")


def test_a_mutated_unit_that_does_not_compile_is_a_stillborn_mutant(monkeypatch, tmp_path):
    _ninja_fails(monkeypatch, "[1/2] Building CXX\nFAILED: CMakeFiles/m_um_config_7_test_invariants.dir/x.cpp.o\n")
    assert score._build(tmp_path, MUT, ["gt_um_config_7_test_invariants"]) is False


@pytest.mark.parametrize("failed", ["build.ninja", "CMakeFiles/orig_src_machine_state.dir/src/machine_state.cpp.o"])
def test_a_failure_outside_the_mutated_units_is_an_error_not_a_stillborn_mutant(monkeypatch, tmp_path, failed):
    _ninja_fails(monkeypatch, f"FAILED: {failed}\nninja: build stopped\n")
    with pytest.raises(score.TreeError, match=f"outside the mutant um_config_7: {failed}"):
        score._build(tmp_path, MUT, ["gt_um_config_7_test_invariants"])


def test_the_score_without_equivalent_mutants_leaves_them_out_of_the_denominator():
    rows = [_row("src/a.cpp:1", "killed", killed_by="GoogleTest: t"), _row("src/a.cpp:2", "stillborn"),
            EQUIV | {"id": "e", "status": "survived", "note": "equivalent: same program"},
            _row("src/a.cpp:3", "survived", note="not yet killed by a test nor justified as equivalent")]
    c = score.counts(rows)
    assert (c["sampled"], c["stillborn"], c["evaluated"], c["killed"], c["survived_equivalent"]) == (4, 1, 3, 1, 1)
    assert (c["score_percent"], c["score_without_equivalent_percent"]) == (33.3, 50.0)
    assert c["confidence_95_percent_without_equivalent"] == score.wilson(1, 2)
    assert [r["where"] for r in c["survivors"]] == [EQUIV["where"], "src/a.cpp:3"]


def test_a_reevaluated_survivor_replaces_its_row_and_says_when():
    prior = _run(1, [_row("src/a.cpp:1", "killed", killed_by="GoogleTest: t"), _row("src/a.cpp:3", "survived")])
    again = _row("src/a.cpp:3", "killed", killed_by="GoogleTest: test_x (RSM09_Manual.New)") | {"id": "new"}
    d = score.rerun(prior, [again], argparse.Namespace(commit="abc1234", passes="gtest", gtest_tests=["test_x"]))
    assert (d["killed"], d["survivors"]) == (2, [])
    assert d["mutants"][1]["id"] == "new"
    assert d["mutants"][1]["reevaluated"] | {"date": 0} == {"commit": "abc1234", "date": 0, "passes": "gtest",
                                                          "gtest_tests": ["test_x"]}


def test_merged_runs_count_a_mutant_sampled_twice_once_with_the_later_row(tmp_path):
    a = _run(1, [_row("src/a.cpp:1", "killed", killed_by="GoogleTest: t"), _row("src/a.cpp:3", "survived"),
                 EQUIV | {"id": "e", "status": "survived", "note": "?"}])
    b = _run(2, [_row("src/a.cpp:3", "killed", killed_by="conformance replay: x"), _row("src/a.cpp:4", "stillborn")])
    d = merge_scores.merge([a, b])
    assert (d["sampled"], d["sampled_twice"], d["evaluated"], d["killed"]) == (4, 1, 3, 2)
    assert (d["killed_by_gtest"], d["killed_by_conformance"], d["survived_equivalent"]) == (1, 1, 1)
    assert d["survivors"][0]["note"].startswith("equivalent: a comment line")  # re-read from equivalent.toml
    assert [r["seed"] for r in d["runs"]] == [1, 2]


def test_runs_of_different_populations_are_not_merged():
    a, b = _run(1, []), _run(2, [])
    b["generated"] = 9000
    with pytest.raises(ValueError, match="different populations"):
        merge_scores.merge([a, b])


def test_an_equivalence_with_a_line_justifies_that_line_only():
    """`break;` -> `/*break;*/` is equivalent at the end of a switch's last case, not
    before the next case label (equivalent.toml's transition_table.hpp:304 entry)."""
    justified = score.equivalents()
    last = {"file": "include/safestate/transition_table.hpp", "original": "break;", "mutant": "/*break;*/"}
    assert score.note(last | {"line": 304}, justified).startswith("equivalent: the break of the last case")
    assert score.note(last | {"line": 298}, justified).startswith("not yet killed")
    assert score.note(EQUIV, justified).startswith("equivalent: a comment line")  # no line: any line


def test_every_equivalent_mutant_names_its_line_as_the_code_has_it():
    """An equivalence justifies one line of code: when an edit or a reformat moves or changes
    that line, equivalent.toml must follow, or it excuses a different mutant (or none)."""
    for (file, original, _mutant, line), _why in score.equivalents().items():
        lines = [text.strip() for text in (REPO / file).read_text(encoding="utf-8").splitlines()]
        if line is None:
            assert original in lines, f"{file}: no line {original!r}"
        else:
            assert lines[line - 1] == original, f"{file}:{line} is {lines[line - 1]!r}, not {original!r}"
