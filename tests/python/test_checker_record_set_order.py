"""The order in which an action enumerates a set of records ``[f : S, g : T]``: TLC's
order of the records (the fields by their names' rank — roughly their first appearance
in the module — the last turning fastest), not the fields as written.  The order
decides which successor is found first, so it shows in a counterexample."""

from __future__ import annotations

from conftest import CORPUS
from safestate.checker.explore import explore_states
from safestate.checker.model import load_model
from safestate.tla.values import FnValue


def test_record_set_is_enumerated_in_tlcs_order_of_records() -> None:
    # TLC 1.8.0 on this spec: the trace's second state is [alpha |-> "a", zeta |-> 6]
    # (the fields as written would find [zeta |-> 3, alpha |-> "c"] first).
    r = explore_states(load_model(str(CORPUS / "RecordAssignment.tla")))
    assert (r.result, r.violated) == ("safety failure", "Fine")
    assert r.trace is not None and len(r.trace) == 2
    assert r.trace[1].state == (FnValue({"alpha": "a", "zeta": 6}), 1)
