"""The flagship: every invariant of models/SystemStateManager.tla proved for all
reachable states and all parameter values (proofs/SystemStateManager.toml)."""

from __future__ import annotations

import os

import pytest

from prove_specs.helpers import MODELS, ROOT, by_invariant, prove  # noqa: I001 (puts python/ on sys.path)

MODEL = os.path.join(MODELS, "SystemStateManager.tla")
PLAN = os.path.join(ROOT, "proofs", "SystemStateManager.toml")

pytestmark = pytest.mark.skipif(not os.path.exists(MODEL), reason="models/SystemStateManager.tla not written yet")


def test_every_invariant_proved_for_all_parameters(capsys) -> None:
    code, rep, err = prove(capsys, MODEL, "--proofs", PLAN)
    assert rep is not None, err
    res = by_invariant(rep)
    from safestate.checker.cfg import parse_config
    cfg_invariants = [e.name for e in parse_config(os.path.join(MODELS, "SystemStateManager.cfg")).invariants]
    assert set(cfg_invariants) <= set(res), "the proof plan must cover every invariant of the .cfg"
    not_proved = {n: (r["status"], r["note"]) for n, r in res.items() if r["status"] != "proved"}
    assert not not_proved
    assert code == 0
    # the timing parameters stay symbolic: the proof covers D = 50 and every other value
    for c in ("DiscrepancyCycles", "ArmingTimeoutCycles", "MaxStopCycles", "T1SpeedLimit", "QueueCapacity"):
        assert rep["constants"][c].startswith("symbolic"), c
    assert res["INV_DISCREPANCY"]["engine"] == "kind"


def test_bmc_finds_no_short_counterexample(capsys) -> None:
    code, rep, err = prove(capsys, MODEL, "--proofs", PLAN, "--engine", "bmc", "--depth", "3", "--cfg-constants")
    assert rep is not None, err
    assert all(r["status"] == "unknown" and r["trace"] is None for r in rep["results"])
    assert code == 1


def test_plcopen_axis_proved(capsys) -> None:
    model = os.path.join(MODELS, "PLCopenAxis.tla")
    if not os.path.exists(model):
        pytest.skip("models/PLCopenAxis.tla not written yet")
    code, rep, err = prove(capsys, model, "--proofs", os.path.join(ROOT, "proofs", "PLCopenAxis.toml"))
    assert rep is not None, err
    assert code == 0 and all(r["status"] == "proved" for r in rep["results"])
