"""The evidence package shows the C++ mutation score (issue 15): from the main job's last
run (build/cpp-mutation/score.json) or, without one, the committed measurement
(conform/cpp_mutants/score.json), with its interval, counts and every survivor."""

import json
from pathlib import Path

from safestate.evidence.build import MUTATION_SCORE, STORED_MUTATION_SCORE, _mutation_score

SCORE = {"generated": 9482, "sampled": 12, "stillborn": 2, "evaluated": 10, "killed": 9, "score_percent": 90.0,
         "confidence_95_percent": [59.6, 98.2], "date": "2026-11-30T02:00:00+00:00",
         "survivors": [{"file": "src/x.cpp", "line": 7, "original": "a > b", "mutant": "a >= b",
                        "note": "equivalent: a == b is unreachable"}]}


def _package(root: Path, rel: Path) -> tuple[Path, list[tuple[str, str]]]:
    (root / rel).parent.mkdir(parents=True)
    (root / rel).write_text(json.dumps(SCORE), encoding="utf-8")
    out = root / "pkg"
    out.mkdir()
    extras: list[tuple[str, str]] = []
    _mutation_score(out, root, extras)
    return out, extras


def test_evidence_shows_the_stored_cpp_mutation_score_with_interval_and_survivors(tmp_path):
    out, extras = _package(tmp_path, STORED_MUTATION_SCORE)
    line = extras[0][0]
    assert "90.0%" in line and "59.6-98.2%" in line and "9 killed of 10 evaluated" in line and "2 stillborn" in line
    assert json.loads((out / "mutation" / "score.json").read_text(encoding="utf-8")) == SCORE
    page = (out / "mutation" / "index.html").read_text(encoding="utf-8")
    assert "src/x.cpp:7" in page and "equivalent: a == b is unreachable" in page


def test_evidence_prefers_the_main_jobs_last_mutation_run(tmp_path):
    _, extras = _package(tmp_path, MUTATION_SCORE)
    assert "90.0%" in extras[0][0]


def test_evidence_says_the_mutation_score_is_not_measured_without_one(tmp_path):
    extras: list[tuple[str, str]] = []
    _mutation_score(tmp_path, tmp_path, extras)
    assert extras and "not measured yet" in extras[0][0]
