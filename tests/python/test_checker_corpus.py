"""The corpus (tests/tla/corpus): verdict and counts must equal TLC's exactly."""

from __future__ import annotations

import json

import pytest

from conftest import CORPUS, load_expected, run_safestate
from safestate.checker.explore import explore_states
from safestate.checker.model import load_model

EXPECTED = load_expected(CORPUS)
FIELDS = ("result", "distinct_states", "states_generated", "depth", "violated")


def _compare(got: dict, want: dict) -> None:
    for f in FIELDS:
        # TLC prints no statistics after an initial-state violation: nothing to compare.
        if want.get(f) is None and f != "violated":
            continue
        assert got[f] == want[f], f"{f}: ours {got[f]!r}, TLC {want[f]!r}"


@pytest.mark.parametrize("name", sorted(EXPECTED))
def test_checker_matches_tlc_on_corpus_spec(name: str) -> None:
    r = explore_states(load_model(str(CORPUS / f"{name}.tla")))
    _compare(vars(r), EXPECTED[name])


@pytest.mark.parametrize("name", sorted(EXPECTED)[:: max(1, len(EXPECTED) // 5)])
def test_checker_cli_with_two_workers_matches_tlc(name: str) -> None:
    p = run_safestate("check", str(CORPUS / f"{name}.tla"), "--workers", "2", "--json")
    got = json.loads(p.stdout)
    _compare(got, EXPECTED[name])
    assert p.returncode == EXPECTED[name]["exit_code"]
    assert "Traceback" not in p.stderr
