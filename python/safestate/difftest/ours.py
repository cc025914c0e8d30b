"""Our checker on one spec, in a forked child process: a fresh interpreter state
per spec (the checker keeps TLC's string order in a module-level table), a hard
time limit, and no effect of a crash on the run."""

from __future__ import annotations

import json
import os
import signal
import sys
import time
import traceback

from ..checker import exit_codes
# Imported before any fork, so that every spec of a run is checked by the same code.
from ..checker.model import load_model
from ..checker.native.engine_choice import check
from ..tla.errors import TlaError

REFUSED = "refused"  # our checker says the construct is unsupported: acceptable, never a wrong number


def summary_of(tla_path: str, cfg_path: str, engine: str = "python") -> dict:
    """Check in this process with `engine` (`safestate check --engine`); the summary
    has TLC's fields plus `exit_code`.  With ``native`` a model outside the core's
    subset is refused; with ``auto`` it is checked by the Python engine, as a user
    without ``--engine`` gets it."""
    try:
        model = load_model(tla_path, cfg_path)
        r = check(model, engine)
    except TlaError as e:
        result = REFUSED if e.kind == "unsupported" else "error"
        return {"result": result, "distinct_states": None, "states_generated": None, "depth": None,
                "violated": None, "exit_code": exit_codes.BY_KIND.get(e.kind, exit_codes.ERROR),
                "message": str(e)}
    code = exit_codes.BY_RESULT.get(r.result)
    msg = None
    if code is None:
        assert r.error is not None
        code = exit_codes.BY_KIND.get(r.error.kind, exit_codes.ERROR)
        msg = f"{r.error.loc}: {r.error.message}"
        if r.error.kind == "unsupported":
            return {"result": REFUSED, "distinct_states": None, "states_generated": None, "depth": None,
                    "violated": None, "exit_code": code, "message": msg}
    initial = r.initial_violation
    # TLC prints a behaviour for a safety violation, a deadlock or an evaluation error
    # after the initial states; a liveness lasso is compared by verdict only (see
    # docs/tla-subset.md: the lassos may differ).
    trace = None
    if r.trace and not initial and r.result not in ("liveness failure", "temporal safety failure", "success"):
        trace = [model.format_state(step.state) for step in r.trace]
    return {"result": r.result, "distinct_states": None if initial else r.distinct_states,
            "states_generated": None if initial else r.states_generated, "depth": None if initial else r.depth,
            "violated": r.violated, "exit_code": code, "message": msg, "trace": trace}


def run_ours(tla_path: str, cfg_path: str, timeout: float = 120, engine: str = "python") -> dict:
    """`summary_of` in a forked child; a crash or a time-out is a result too."""
    rfd, wfd = os.pipe()
    pid = os.fork()
    if pid == 0:  # the child
        os.close(rfd)
        try:
            # The engine's fallback notices would interleave with the run's progress lines.
            sys.stderr = open(os.devnull, "w")  # noqa: SIM115 - the child exits right after
            out = summary_of(tla_path, cfg_path, engine)
        except BaseException:  # noqa: BLE001 - reported to the parent as a crash
            out = {"result": "crash", "exit_code": exit_codes.ERROR, "message": traceback.format_exc()[-2000:]}
        with os.fdopen(wfd, "w") as f:
            json.dump(out, f)
        os._exit(0)
    os.close(wfd)
    deadline = time.monotonic() + timeout
    with os.fdopen(rfd) as f:
        data = ""
        import select
        while True:
            left = deadline - time.monotonic()
            ready, _, _ = select.select([f], [], [], max(left, 0))
            if not ready:
                os.kill(pid, signal.SIGKILL)
                os.waitpid(pid, 0)
                return {"result": "timeout", "exit_code": -1, "message": f"no result after {timeout:.0f} s"}
            chunk = f.read()
            data += chunk
            if not chunk or data:
                break
    os.waitpid(pid, 0)
    try:
        return json.loads(data)
    except ValueError:
        return {"result": "crash", "exit_code": exit_codes.ERROR, "message": "the checker process died"}
