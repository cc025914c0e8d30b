"""The engines on small specs: k-induction with a symbolic bound, a strengthening
invariant, PDR finding the invariant itself, the shortest BMC trace, bad input."""

from __future__ import annotations

import pytest

from prove_specs.helpers import by_invariant, prove, spec


def test_counter_symbolic_bound_by_kinduction(capsys) -> None:
    code, rep, _ = prove(capsys, spec("Counter.tla"), "--proofs", "/dev/null", "--engine", "kind")
    assert code == 0
    assert rep["constants"]["Bound"].startswith("symbolic (ASSUME Bound \\in Nat")
    assert all(r["status"] == "proved" and r["k"] == 1 for r in rep["results"])


def test_strengthening_needed(capsys) -> None:
    # without Strengthen_SYNC: unknown, with a counterexample to induction, never "violated"
    code, rep, _ = prove(capsys, spec("TwoCounters.tla"), "--proofs", "/dev/null", "--engine", "kind",
                         "--depth", "3")
    r = by_invariant(rep)["YBounded"]
    assert code == 1 and r["status"] == "unknown" and r["trace"] is None
    cti = r["cti"]["states"]
    assert len(cti) == 2 and cti[0]["x"] != cti[0]["y"]
    code, rep, _ = prove(capsys, spec("TwoCounters.tla"), "--proofs", spec("TwoCounters.toml"))
    assert code == 0 and by_invariant(rep)["YBounded"]["status"] == "proved"


def test_pdr_finds_the_invariant(capsys) -> None:
    code, rep, _ = prove(capsys, spec("TwoCounters.tla"), "--proofs", spec("TwoCountersPdr.toml"))
    r = by_invariant(rep)["YBounded"]
    assert code == 0 and r["status"] == "proved" and r["engine"] == "pdr"


def test_bmc_shortest_trace(capsys) -> None:
    code, rep, _ = prove(capsys, spec("Jumps.tla"), "--proofs", "/dev/null", "--engine", "bmc", "--depth", "8")
    r = by_invariant(rep)["NotFive"]
    assert code == 12 and r["status"] == "violated" and r["k"] == 3
    xs = [int(s["x"]["#bigint"]) for s in r["trace"]["states"]]
    assert xs[0] == 0 and xs[-1] == 5 and len(xs) == 4
    assert all(b - a in (1, 2) for a, b in zip(xs, xs[1:]))
    assert r["trace"]["vars"] == ["x"]


def test_kind_confirms_violation_by_bmc(capsys) -> None:
    code, rep, _ = prove(capsys, spec("Jumps.tla"), "--proofs", "/dev/null", "--engine", "kind", "--depth", "6")
    r = by_invariant(rep)["NotFive"]
    assert code == 12 and r["status"] == "violated" and len(r["trace"]["states"]) == 4


def test_pdr_violation(capsys) -> None:
    code, rep, _ = prove(capsys, spec("Jumps.tla"), "--proofs", "/dev/null", "--engine", "pdr", "--depth", "6")
    r = by_invariant(rep)["NotFive"]
    assert code == 12 and r["status"] == "violated" and len(r["trace"]["states"]) == 4


def test_unsupported_construct_is_located(capsys) -> None:
    code, rep, err = prove(capsys, spec("Recursive.tla"), "--proofs", "/dev/null")
    assert code == 2 and rep is None
    assert "Recursive.tla:9:8: unsupported in proofs: recursive operator Fact" in err
    assert "Traceback" not in err


def test_untyped_seq_needs_length_bound(capsys) -> None:
    code, _, err = prove(capsys, spec("Unbounded.tla"), "--proofs", "/dev/null")
    assert code == 2
    assert "Unbounded.tla:8:" in err and "needs a length bound" in err


def test_missing_model_is_bad_input(capsys) -> None:
    code, _, err = prove(capsys, spec("NoSuch.tla"))
    assert code == 2 and "NoSuch.tla" in err


def test_text_output_shows_the_cti_as_tla_states(capsys) -> None:
    from safestate.prove.cli import main
    code = main([spec("TwoCounters.tla"), "--proofs", "/dev/null", "--engine", "kind", "--depth", "2", "--quiet"])
    out = capsys.readouterr().out
    assert code == 1
    assert "YBounded: unknown (kind k=2" in out
    assert "Counterexample to induction (not known to be reachable):" in out
    assert "    /\\ x = " in out and "    /\\ y = " in out
    assert "N: symbolic (ASSUME N \\in Nat)" in out


def test_untyped_variable_is_untracked_until_read(capsys) -> None:
    code, rep, _ = prove(capsys, spec("Untyped.tla"), "--proofs", "/dev/null", "--invariant", "Fine")
    assert code == 0 and rep["untracked"] == ["log"]
    code, _, err = prove(capsys, spec("Untyped.tla"), "--proofs", "/dev/null", "--invariant", "Reads")
    assert code == 2 and "Untyped.tla:8:10: unsupported in proofs: a variable that TypeOK does not type" in err


@pytest.mark.parametrize("invariant,col", [("Equal", 10), ("Differs", 12), ("InTuple", 12)])
def test_untyped_variable_compared_whole_is_refused_not_true(capsys, invariant: str, col: int) -> None:
    """`log = e` over an untracked variable was TRUE in an invariant: BMC missed the
    SafetyService mutant any_sender_accepted (its shadow service was untyped)."""
    code, rep, err = prove(capsys, spec("UntypedCompared.tla"), "--proofs", "/dev/null", "--engine", "bmc",
                           "--depth", "2", "--invariant", invariant)
    assert code == 2 and rep is None
    line = {"Equal": 13, "Differs": 14, "InTuple": 15}[invariant]
    assert f"UntypedCompared.tla:{line}:{col}: unsupported in proofs: a variable that TypeOK does not type" in err


def test_untyped_variable_assigned_is_dropped_read_in_next_is_refused(capsys, tmp_path) -> None:
    code, rep, _ = prove(capsys, spec("UntypedCompared.tla"), "--proofs", "/dev/null", "--invariant", "Fine")
    assert code == 0 and rep is not None and rep["untracked"] == ["log"]
    for nxt, where in (("GuardedNext", "8:16"), ("CopiedNext", "9:20")):
        cfg = tmp_path / f"{nxt}.cfg"
        cfg.write_text(f"INIT Init\nNEXT {nxt}\nINVARIANT Fine\n")
        code, rep, err = prove(capsys, spec("UntypedCompared.tla"), "--config", str(cfg), "--proofs", "/dev/null",
                               "--invariant", "Fine")
        assert code == 2 and f"UntypedCompared.tla:{where}: unsupported in proofs" in err, (nxt, err)


def test_empty_sequence_branch_is_given_the_other_branchs_shape(capsys) -> None:
    code, rep, err = prove(capsys, spec("EmptySeqBranch.tla"), "--proofs", "/dev/null", "--invariant", "ShortOut")
    assert code == 0 and rep is not None, err
    assert by_invariant(rep)["ShortOut"]["status"] == "proved"
    code, rep, err = prove(capsys, spec("EmptySeqBranch.tla"), "--proofs", "/dev/null", "--invariant", "OneOut")
    assert code == 12 and rep is not None, err
    r = by_invariant(rep)["OneOut"]
    assert r["status"] == "violated" and len(r["trace"]["states"]) == 1  # <<>> at x = 0
    assert "Traceback" not in err
