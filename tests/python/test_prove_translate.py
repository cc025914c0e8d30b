"""The translation of each construct of the subset (tests/python/prove_specs/Constructs.tla):
bounded sequences of records, functions over 1..3, records with EXCEPT and @,
strings, CASE, LET, IF, \\E over finite sets, UNCHANGED, symbolic constants."""

from __future__ import annotations

import os

import pytest
import z3

from prove_specs.helpers import ROOT, by_invariant, prove, spec  # noqa: I001 (puts python/ on sys.path)
from safestate.prove.system import build
from safestate.prove.values import SeqV, Fn, Rec


@pytest.fixture(scope="module")
def constructs():
    return build(spec("Constructs.tla"), None, proofs_module=spec("ConstructsProofs.tla"))


def test_domains_from_typeok(constructs) -> None:
    s = constructs
    assert isinstance(s.cur["queue"], SeqV) and s.cur["queue"].cap == 4  # Cap \in 1..4: 4 slots
    assert isinstance(s.cur["f"], Fn) and s.cur["f"].keys == (1, 2, 3)
    assert isinstance(s.cur["rec"], Rec) and set(s.cur["rec"].fields) == {"mode", "level"}
    assert s.constants_report["Cap"].startswith("symbolic")
    assert s.constants_report["Ids"].startswith("symbolic")


def test_init_is_the_single_initial_state(constructs) -> None:
    s = constructs
    sol = s.solver()
    sol.add(s.assumptions, s.init_at(0))
    assert sol.check() == z3.sat
    st = s.state_values(sol.model(), 0)
    assert st["queue"] == () and st["phase"] == "idle" and st["rec"] == {"mode": "off", "level": 0}
    assert dict(st["f"]) == {1: "a", 2: "a", 3: "a"}


def test_send_appends_a_record_from_ids(constructs) -> None:
    s = constructs
    sol = s.solver()
    sol.add(s.assumptions, s.init_at(0), s.trans_at(0))
    sol.add(s.state(1)[0] == 1)  # the first state term of `queue` is its length
    assert sol.check() == z3.sat
    st = s.state_values(sol.model(), 1)
    params = s.param_values(sol.model())
    assert len(st["queue"]) <= 1
    for m in st["queue"]:
        assert m["id"] in params["Ids"] and 0 <= m["n"] <= 3


def test_proved_and_violated(capsys) -> None:
    code, rep, _ = prove(capsys, spec("Constructs.tla"), "--proofs", spec("Constructs.toml"), "--depth", "10")
    res = by_invariant(rep)
    assert res["TypeOK"]["status"] == "proved"
    assert res["FValues"]["status"] == "proved"
    lv = res["LevelBelow5"]
    assert lv["status"] == "violated" and lv["k"] == 10
    states = lv["trace"]["states"]
    assert len(states) == 11
    assert states[-1]["rec"]["level"] == {"#bigint": "5"}
    assert code == 12


def test_fvalues_needs_its_strengthening(capsys) -> None:
    code, rep, _ = prove(capsys, spec("Constructs.tla"), "--proofs", "/dev/null", "--invariant", "FValues",
                         "--engine", "kind", "--depth", "2")
    r = by_invariant(rep)["FValues"]
    assert r["status"] == "unknown" and r["cti"] is not None and len(r["cti"]["states"]) == 2
    assert code == 1


CORPUS = os.path.join(ROOT, "tests", "tla", "corpus")


def test_set_valued_variables_and_pdr(capsys) -> None:
    """TwoPhase: msgs \\subseteq Messages (a set of records) is a bitset; PDR finds Consistent's invariant."""
    code, rep, err = prove(capsys, os.path.join(CORPUS, "TwoPhase.tla"), "--proofs", "/dev/null", "--engine", "pdr")
    assert rep is not None, err
    assert code == 0 and all(r["status"] == "proved" for r in rep["results"])


def test_instance_substitution_types_the_variable(capsys) -> None:
    """BoundedFifo: TypeOK == Chan!ChanTypeOK with q <- buf types buf as a bounded sequence."""
    code, rep, err = prove(capsys, os.path.join(CORPUS, "BoundedFifo.tla"), "--proofs", "/dev/null",
                           "--invariant", "TypeOK")
    assert rep is not None, err
    assert code == 0 and rep["untracked"] == []
