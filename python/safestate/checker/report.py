"""TLC-style text output of a check."""

from __future__ import annotations

from typing import TextIO

from ..tla.errors import TlaError
from ..tla.tlcget import RUNTIME
from .explore import CheckResult, Step
from .model import Model


def format_error(e: TlaError) -> str:
    where = f"{e.loc}: " if e.loc else ""
    return f"Error: {where}{e.message}"


def write_trace(out: TextIO, model: Model, trace: list[Step],
                header: str = "Error: The behavior up to this point is:") -> None:
    print(header, file=out)
    for i, step in enumerate(trace, 1):
        label = "<Initial predicate>" if i == 1 else _step_label(model, step)
        print(f"State {i}: {label}", file=out)
        RUNTIME.level = i  # an ALIAS may show TLCGet("level")
        print(model.format_state(step.state), file=out)
        print(file=out)


def _step_label(model: Model, step: Step) -> str:
    leaf = next((lf for lf in model.leaves if lf.name == step.action), None)
    where = f" line {leaf.loc.line}, col {leaf.loc.column} of module {model.module.name}" if leaf else ""
    params = ", ".join(f"{k} = {_fmt(v)}" for k, v in step.params.items())
    return f"<{step.action}{'(' + params + ')' if params else ''}{where}>"


def write_lasso(out: TextIO, model: Model, r: CheckResult) -> None:
    """A liveness counterexample in TLC's words: the states, then "Back to state N"
    or "Stuttering" (nothing after a finite counterexample: "temporal safety failure")."""
    assert r.trace is not None
    names = r.violated_properties or [str(r.violated)]
    if len(names) == 1:
        print(f"Error: Temporal property {names[0]} was violated.", file=out)
    else:
        listed = " and ".join(names) if len(names) == 2 else ", ".join(names[:-1]) + ", and " + names[-1]
        print(f"Error: Temporal properties {listed} were violated.", file=out)
    print(file=out)
    write_trace(out, model, r.trace, "Error: The following behavior constitutes a counter-example:\n")
    if r.loop is None:
        return  # a finite counterexample: TLC prints the states only
    if r.loop_step is None:
        print(f"State {len(r.trace) + 1}: Stuttering", file=out)
    else:
        print(f"Back to state {r.loop + 1}: {_step_label(model, r.loop_step)}", file=out)
    print(file=out)


def _fmt(v: object) -> str:
    from ..tla.values import fmt
    return fmt(v)


def write_result(out: TextIO, model: Model, r: CheckResult) -> None:
    if r.result == "success":
        print("Model checking completed. No error has been found.", file=out)
        print("  States are compared exactly (no fingerprints): the probability that a distinct state\n"
              "  was missed because of a fingerprint collision is 0.", file=out)
    elif r.result == "safety failure":
        if r.initial_violation:
            print(f"Error: Invariant {r.violated} is violated by the initial state:", file=out)
            assert r.trace
            print(model.format_state(r.trace[-1].state), file=out)
            print(file=out)
            return  # TLC prints no statistics after an initial-state violation
        print(f"Error: Invariant {r.violated} is violated.", file=out)
        if r.trace:
            write_trace(out, model, r.trace)
    elif r.result == "init property failure":
        assert r.trace
        print(f"Error: Property {r.violated} is violated by the initial state:", file=out)
        print(model.format_state(r.trace[-1].state), file=out)
        print(file=out)
        return
    elif r.result == "action property failure":
        print(f"Error: Action property {r.violated} is violated.", file=out)
        if r.trace:
            write_trace(out, model, r.trace)
    elif r.result in ("liveness failure", "temporal safety failure"):
        write_lasso(out, model, r)
    elif r.result == "deadlock failure":
        print("Error: Deadlock reached.", file=out)
        if r.trace:
            write_trace(out, model, r.trace)
    else:
        assert r.error is not None
        print(format_error(r.error), file=out)
        if r.trace:
            write_trace(out, model, r.trace)
    print(f"{r.states_generated} states generated, {r.distinct_states} distinct states found, "
          f"{r.left_on_queue} states left on queue.", file=out)
    print(f"The depth of the complete state graph search is {r.depth}.", file=out)
    print(f"Finished in {r.seconds:.2f}s.", file=out)
