"""Second opinion: run the real TLC (``TLA2TOOLS_JAR``) on the same model and
compare its verdict and counts with ours."""

from __future__ import annotations

import os
import re
import shutil
import subprocess
import tempfile
from dataclasses import dataclass


@dataclass
class TlcSummary:
    result: str
    distinct_states: int | None
    states_generated: int | None
    depth: int | None
    violated: str | None
    exit_code: int
    # A liveness counterexample: {"length": states printed, "loop": 0-based index the
    # last state goes back to, "stuttering": bool}.
    lasso: dict | None = None
    # Every property TLC names as violated by its liveness counterexample.
    violated_properties: list[str] | None = None
    # The states of a safety/deadlock/evaluation-error trace ("The behavior up to this
    # point is:"), each as its `/\ x = v` lines.
    trace: list[str] | None = None
    # "N states left on queue": where TLC stopped its search.
    left_on_queue: int | None = None


def tlc_jar() -> str | None:
    jar = os.environ.get("TLA2TOOLS_JAR")
    return jar if jar and os.path.isfile(jar) else None


def run_tlc(jar: str, tla_path: str, cfg_path: str, timeout: float = 3600, workers: int = 1) -> TlcSummary:
    if shutil.which("java") is None:
        raise RuntimeError("java is not on PATH")
    meta = tempfile.mkdtemp(prefix="tlc-meta-")
    folder = os.path.dirname(os.path.abspath(tla_path))
    cmd = ["java", "-XX:+UseParallelGC", "-cp", jar, "tlc2.TLC", "-workers", str(workers), "-metadir", meta,
           "-noGenerateSpecTE", "-config", os.path.abspath(cfg_path), os.path.basename(tla_path)]
    try:
        p = subprocess.run(cmd, cwd=folder, capture_output=True, text=True, timeout=timeout)
    finally:
        shutil.rmtree(meta, ignore_errors=True)
    return parse_tlc_output(p.stdout + p.stderr, p.returncode)


def parse_tlc_output(out: str, exit_code: int) -> TlcSummary:
    stats = re.findall(r"^(\d+) states generated, (\d+) distinct states found", out, re.M)
    queue = re.findall(r"distinct states found, (\d+) states left on queue", out)
    depth = re.findall(r"^The depth of the complete state graph search is (\d+)", out, re.M)
    viol = re.search(r"^Error: Invariant (\S+) is violated", out, re.M)
    # "Temporal properties were violated." names none: TLC's own check of its lasso found
    # no violated property (docs/tla-subset.md).
    temporal = re.search(r"^Error: Temporal propert(?:y|ies) ((?!were violated)\w+|(?=were violated))", out, re.M)
    action = re.search(r"^Error: Action property (\S+) is violated", out, re.M)
    initial = re.search(r"^Error: Property (\S+) is violated by the initial state", out, re.M)
    if "Model checking completed. No error has been found." in out:
        result = "success"
    elif viol:
        result = "safety failure"
    elif temporal or action or initial:
        # TLC exits with 12 where it stops at a finite counterexample of a temporal property.
        result = (("temporal safety failure" if exit_code == 12 else "liveness failure") if temporal
                  else "action property failure" if action else "init property failure")
        viol = temporal or action or initial
    elif "Error: Deadlock reached." in out:
        result = "deadlock failure"
    else:
        result = "error"
    return TlcSummary(result,
                      int(stats[-1][1]) if stats else None, int(stats[-1][0]) if stats else None,
                      int(depth[-1]) if depth else None, (viol.group(1) or None) if viol else None, exit_code,
                      _lasso(out) if temporal else None, _temporal_names(out) if temporal else None,
                      None if temporal else _trace(out), int(queue[-1]) if queue else None)


def _trace(out: str) -> list[str] | None:
    """The states TLC prints after "The behavior up to this point is:"."""
    at = out.find("Error: The behavior up to this point is:")
    if at < 0:
        return None
    states = []
    for block in re.split(r"^State \d+: .*$", out[at:], flags=re.M)[1:]:
        lines = []
        for line in block.splitlines()[1:]:
            if not line.strip():
                break
            lines.append(line.rstrip())
        states.append("\n".join(lines))
    return states


def _temporal_names(out: str) -> list[str]:
    m = re.search(r"^Error: Temporal propert(?:y (\w+) was|ies (.+) were) violated", out, re.M)
    if m is None:
        return []
    return [m.group(1)] if m.group(1) else re.split(r",? and |, ", m.group(2))


def _lasso(out: str) -> dict | None:
    states = re.findall(r"^State (\d+): <", out, re.M)
    back = re.search(r"^Back to state (\d+)", out, re.M)
    stutter = re.search(r"^State (\d+): Stuttering", out, re.M)
    if not states or not (back or stutter):
        return None
    length = int(states[-1])
    loop = int(back.group(1)) - 1 if back else length - 1
    return {"length": length, "loop": loop, "stuttering": back is None}


def compare(ours: dict, tlc: TlcSummary) -> list[str]:
    """Differences between our JSON summary and TLC's (fields TLC did not print are skipped)."""
    diffs = []
    for name in ("result", "distinct_states", "states_generated", "depth", "violated"):
        theirs = getattr(tlc, name)
        if theirs is None and name != "violated" and name != "result":
            continue
        if ours.get(name) != theirs:
            diffs.append(f"{name}: ours {ours.get(name)!r}, TLC {theirs!r}")
    return diffs
