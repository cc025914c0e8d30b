"""The real-world corpus (tests/tla/realworld): specs in the style of published TLA+
specifications must give TLC's verdict, counts, depth and exit code exactly, and
the modules SANY rejects must be rejected with its message at its position."""

from __future__ import annotations

import json

import pytest

from conftest import REPO, load_expected, run_safestate
from safestate.checker.explore import explore_states
from safestate.checker.model import load_model

SPECS = REPO / "tests" / "tla" / "realworld" / "specs"
ERRORS = REPO / "tests" / "tla" / "realworld" / "errors"
EXPECTED = load_expected(SPECS)
EXPECTED_ERRORS = load_expected(ERRORS)
FIELDS = ("distinct_states", "states_generated", "depth", "violated")


@pytest.mark.parametrize("name", sorted(EXPECTED))
def test_realworld_spec_matches_tlc(name: str) -> None:
    want = EXPECTED[name]
    r = explore_states(load_model(str(SPECS / f"{name}.tla")))
    got = "error" if r.result == "error" else r.result
    assert got == want["result"], r.error
    for f in FIELDS:
        assert getattr(r, f) == want[f], f"{f}: ours {getattr(r, f)!r}, TLC {want[f]!r}"


@pytest.mark.parametrize("name", ["TLCStats", "AliasTrace", "AssumeOnly", "MCMemory", "Barrier", "DieHard"])
def test_realworld_cli_exit_code_matches_tlc(name: str) -> None:
    p = run_safestate("check", str(SPECS / f"{name}.tla"), "--json")
    got = json.loads(p.stdout)
    assert p.returncode == EXPECTED[name]["exit_code"], p.stdout + p.stderr
    assert got["distinct_states"] == EXPECTED[name]["distinct_states"]


def test_alias_replaces_the_variables_in_the_counterexample() -> None:
    p = run_safestate("check", str(SPECS / "AliasTrace.tla"))
    assert p.returncode == 12
    assert "/\\ step = 1\n/\\ sum = 1\n/\\ x = 0" in p.stdout, p.stdout
    assert "/\\ step = 4" in p.stdout  # TLCGet("level") is the step number in a trace
    assert "/\\ y = " not in p.stdout


def test_assume_only_cfg_evaluates_the_assumptions() -> None:
    p = run_safestate("check", str(SPECS / "AssumeOnly.tla"))
    assert p.returncode == 0
    assert "gcd(12, 18) =" in p.stderr and "6" in p.stderr
    assert "0 states generated, 0 distinct states found" in p.stdout


@pytest.mark.parametrize("name", sorted(EXPECTED_ERRORS))
def test_realworld_error_reported_as_tlc_does(name: str) -> None:
    want = EXPECTED_ERRORS[name]
    p = run_safestate("check", str(ERRORS / f"{name}.tla"), "--json")
    got = json.loads(p.stdout)
    assert p.returncode == want["tlc_exit_code"], p.stdout + p.stderr
    assert "Traceback" not in p.stderr
    err = got["error"]
    assert want["tlc_message"] in err["message"]
    assert (err["line"], err["column"]) == (want["line"], want["column"])
    assert err["file"].endswith(want["file"])


def test_theorem_and_proof_blocks_are_parsed_and_ignored() -> None:
    r = explore_states(load_model(str(SPECS / "TheoremsAndProofs.tla")))
    assert r.result == "success" and r.distinct_states == EXPECTED["TheoremsAndProofs"]["distinct_states"]
