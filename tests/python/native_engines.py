"""Both engines on one spec, for the native core's tests: the core must accept the spec
(so a test cannot pass by a refusal) and give the Python engine's verdict, counts,
depth, states left, violated invariant, error and trace, and the CLI the same exit code
and --json report."""

from __future__ import annotations

import json
from pathlib import Path

from conftest import run_safestate
from safestate.checker.explore import CheckResult, explore_states
from safestate.checker.model import load_model
from safestate.checker.native.search import explore_native, native_unsupported


def outcome(r: CheckResult) -> tuple:
    trace = [(s.state, s.action, s.params) for s in r.trace or []]
    error = (r.error.kind, r.error.message) if r.error else None
    return (r.result, r.distinct_states, r.states_generated, r.depth, r.left_on_queue, r.violated, error, trace)


def write_spec(tmp_path: Path, name: str, body: str, cfg: str) -> str:
    (tmp_path / f"{name}.tla").write_text(f"---- MODULE {name} ----\n{body}\n====\n")
    (tmp_path / f"{name}.cfg").write_text(cfg)
    return str(tmp_path / f"{name}.tla")


def assert_engines_agree(tla: str, workers: int = 1) -> CheckResult:
    """The core's result (it must accept the spec and not stop at an error) equals the
    Python engine's; returned for further checks."""
    refusal = native_unsupported(load_model(tla))
    assert refusal is None, refusal.message
    native, error = explore_native(load_model(tla), workers=workers)
    assert native is not None, f"the core stopped at an evaluation error: {error}"
    python = explore_states(load_model(tla))
    assert outcome(native) == outcome(python)
    return native


def _report(out: str) -> dict:
    return {k: v for k, v in json.loads(out).items() if k != "seconds"}


def assert_cli_engines_agree(tla: str) -> int:
    """`safestate check --engine native` and `--engine python`: the same exit code and
    --json report, and the native run said nothing about falling back."""
    native = run_safestate("check", tla, "--engine", "native", "--json")
    python = run_safestate("check", tla, "--engine", "python", "--json")
    assert "Python engine" not in native.stderr, native.stderr
    assert native.returncode == python.returncode, (native.stderr, python.stderr)
    assert _report(native.stdout) == _report(python.stdout)
    return native.returncode
