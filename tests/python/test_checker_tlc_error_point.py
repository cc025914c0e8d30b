"""Where and how the checker stops on an evaluation error, as TLC 1.8.0 does: the
exit code (75 or 255, by the kind of error and whether the liveness check meets it
too), the counts at that moment, and the trace (ending with the successor whose
constraint failed).  The specs are minimised difftest disagreements (corpus)."""

from __future__ import annotations

import pytest

from conftest import CORPUS, load_expected
from safestate.difftest.ours import summary_of

EXPECTED = load_expected(CORPUS)
SPECS = ["FairEnabledJavaError", "FairEnabledJavaErrorSafety", "PropertyPredicateError",
         "ActionConstraintError", "ComparisonNonInteger", "IntervalNonInteger",
         "PropertyAssert"]


@pytest.mark.parametrize("name", SPECS)
def test_evaluation_error_stops_where_tlc_stops_with_its_exit_code(name: str) -> None:
    got = summary_of(str(CORPUS / f"{name}.tla"), str(CORPUS / f"{name}.cfg"))
    want = EXPECTED[name]
    assert (got["result"], got["exit_code"]) == ("error", want["exit_code"]), got.get("message")
    assert (got["distinct_states"], got["states_generated"], got["depth"]) == \
        (want["distinct_states"], want["states_generated"], want["depth"])
    assert len(got["trace"]) == want["trace_length"]


def test_error_in_a_fairness_enabled_exits_255_but_75_without_liveness() -> None:
    """The same Next error: TLC's liveness check meets it again in WF's ENABLED."""
    codes = [summary_of(str(CORPUS / f"{n}.tla"), str(CORPUS / f"{n}.cfg"))["exit_code"]
             for n in ("FairEnabledJavaError", "FairEnabledJavaErrorSafety")]
    assert codes == [255, 75]
