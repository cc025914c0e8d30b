"""SAF-01..04: every reachable transition of models/SafetyService.tla replayed through the
C++ Safety service (safestate._saf) on the codec path: each step's inbox is encoded into
datagrams (docs/design/safety-service.md §12), some steps get an extra garbage datagram,
and after each step the C++ observable state must equal the model's variables.

This is a direct replay over the checker's state graph, written before the generic
conformance adapter exists; the adapter will take it over."""

from __future__ import annotations

import json
from collections import deque
from pathlib import Path

import pytest

from conftest import REPO, run_safestate

_saf = pytest.importorskip("safestate._saf")

MODEL = REPO / "models" / "SafetyService.tla"
PROJECTED = ("state", "estop", "estop_age", "health", "health_age", "control",
             "control_age", "out_request", "out_set_state")
# Garbage of several reject reasons, appended to every 7th step: it must change nothing.
GARBAGE = (b"", b"\x01", bytes(100), b"\x3c\x01\x00\x00\x01\x00\x00\x00\x01\x00\x07")


def _plain(value: object) -> object:
    """ITF values -> Python: {"#bigint": "3"} -> 3, records stay dicts."""
    if isinstance(value, dict):
        if "#bigint" in value:
            return int(value["#bigint"])
        return {k: _plain(v) for k, v in value.items()}
    return value


def _constants() -> tuple[int, int, int]:
    cfg = MODEL.with_suffix(".cfg").read_text()
    values = {}
    for line in cfg.splitlines():
        parts = line.split("=")
        if len(parts) == 2 and parts[0].strip().endswith("Cycles"):
            values[parts[0].strip()] = int(parts[1])
    return (values["EstopTimeoutCycles"], values["ReportDataTimeoutCycles"],
            values["MessageIntervalCycles"])


@pytest.fixture(scope="module")
def graph(tmp_path_factory: pytest.TempPathFactory) -> dict:
    path = tmp_path_factory.mktemp("saf") / "graph.json"
    proc = run_safestate("check", str(MODEL), "--graph", str(path))
    assert proc.returncode == 0, proc.stdout + proc.stderr
    return json.loads(path.read_text())


def _index(graph: dict) -> tuple[dict[int, dict], dict[int, list[dict]]]:
    """The graph's states by id (plain values) and its edges by source."""
    states = {s["id"]: _plain(s["state"]) for s in graph["states"]}
    out_edges: dict[int, list[dict]] = {}
    for e in graph["edges"]:
        out_edges.setdefault(e["from"], []).append(e)
    return states, out_edges


def _replay(graph: dict, et: int, rdt: int, mi: int, stop_after: int) -> tuple[int, int, list[str]]:
    """Replays every edge through C++ services built with these timers.
    Returns (edges replayed, C++ states, the first `stop_after` mismatches)."""
    states, out_edges = _index(graph)
    [init] = graph["initial"]
    root = _saf.SafetyService(et, rdt, mi, 3)
    # BFS over the graph: one C++ service per model state, reached by a tree path;
    # every edge is replayed from a copy of its source's service.
    services = {init: root}
    queue = deque([init])
    replayed = 0
    mismatches: list[str] = []
    while queue and len(mismatches) < stop_after:
        src = queue.popleft()
        for e in out_edges.get(src, []):
            inbox = _plain(e["params"]["in"])
            datagrams = _saf.encode_inbox(inbox)
            if replayed % 7 == 0:
                datagrams = datagrams + [GARBAGE[replayed // 7 % len(GARBAGE)]]
            svc = services[src].copy()
            svc.cycle_raw(datagrams, inbox["hw_fault"])
            replayed += 1
            want = {k: states[e["to"]][k] for k in PROJECTED}
            if svc.observe() != want and len(mismatches) < stop_after:
                mismatches.append(f"{states[src]} --{inbox}--> C++ {svc.observe()} model {want}")
            if e["to"] not in services:
                services[e["to"]] = svc
                queue.append(e["to"])
    return replayed, len(services), mismatches


def test_saf_every_model_transition_replayed_through_the_cpp_codec_path(graph: dict) -> None:
    replayed, reached, mismatches = _replay(graph, *_constants(), stop_after=5)
    assert not mismatches, "\n".join(mismatches)
    want = json.loads((REPO / "models" / "expected.json").read_text())["SafetyService"]
    assert replayed == len(graph["edges"]) == want["states_generated"] - 1  # all but Init
    assert reached == len(graph["states"]) == want["distinct_states"]


def test_saf_replay_catches_a_wrong_estop_timeout(graph: dict) -> None:
    et, rdt, mi = _constants()
    _, _, mismatches = _replay(graph, et + 1, rdt, mi, stop_after=1)
    assert mismatches, "a C++ service with ESTOPTIMEOUT one cycle longer must disagree"


def test_saf_binding_observe_keys_are_the_model_variables(graph: dict) -> None:
    model_vars = set(graph["vars"]) - {"inbox", "ever_faulted"}
    assert set(_saf.SafetyService(2, 3, 2).observe()) == model_vars == set(PROJECTED)


def test_saf_binding_rejects_bad_inbox_with_a_clear_error() -> None:
    svc = _saf.SafetyService(2, 3, 2)
    with pytest.raises(ValueError, match="inbox.estop: unknown value 'PRESSED'"):
        svc.cycle({"estop": "PRESSED", "health": "NONE", "control": "NONE", "hw_fault": False})
    with pytest.raises(ValueError, match="at least 1 cycle"):
        _saf.SafetyService(0, 3, 2)
    assert _saf.decode_error(b"\x01") == "TRUNCATED"


# Lockstep random walks over the model's graph: the C++ service is driven along whole
# paths (not from per-state copies), so hidden C++ state (cycle counter, periodic queries,
# the re-send rule) accumulates as in a real run. 120 walks x 100 steps = 12,000 steps.
WALKS, STEPS = 120, 100


def test_saf_hypothesis_lockstep_walks(graph: dict) -> None:
    from hypothesis import HealthCheck, given, settings
    from hypothesis import strategies as st

    states, out_edges = _index(graph)
    et, rdt, mi = _constants()
    [init] = graph["initial"]
    steps_done = [0]

    @settings(max_examples=WALKS, deadline=None, derandomize=True,
              suppress_health_check=list(HealthCheck))
    @given(st.lists(st.integers(min_value=0, max_value=10**6), min_size=STEPS, max_size=STEPS),
           st.lists(st.sampled_from(GARBAGE), min_size=0, max_size=3))
    def walk(choices: list[int], garbage: list[bytes]) -> None:
        svc = _saf.SafetyService(et, rdt, mi, 3)
        node = init
        for i, c in enumerate(choices):
            edges = out_edges[node]
            e = edges[c % len(edges)]
            inbox = _plain(e["params"]["in"])
            extra = garbage if i % 10 == 0 else []
            svc.cycle_raw(_saf.encode_inbox(inbox) + extra, inbox["hw_fault"])
            node = e["to"]
            assert svc.observe() == {k: states[node][k] for k in PROJECTED}, (i, inbox)
            steps_done[0] += 1

    walk()
    assert steps_done[0] >= 10_000
