"""Trace generation: the cover takes every edge of a graph, from initial nodes, and
is deterministic; the input mapping makes the C++ classify speeds as the model."""

from safestate.conform.cover import Graph, UnreachableEdges, cover, steps

import pytest


def small_graph() -> Graph:
    # 0 -> 1 -> 2 -> 0, a self-loop on 1, a branch 1 -> 3 into an absorbing node 3
    # with a self-loop, parallel edges 2 -> 0, and 4 = a second initial node -> 2.
    edges = [(0, 1), (1, 2), (2, 0), (1, 1), (1, 3), (3, 3), (2, 0), (4, 2), (0, 3)]
    return Graph(5, [0, 4], [s for s, _ in edges], [d for _, d in edges])


def check_cover(g: Graph, traces) -> None:
    taken = set()
    for t in traces:
        assert t.start in g.initial
        node = t.start
        for e in t.edges:
            assert g.src[e] == node, "each edge leaves where the previous one ended"
            node = g.dst[e]
            taken.add(e)
    assert taken == set(range(len(g.src)))


@pytest.mark.parametrize("max_len", [1, 2, 3, 1000])
def test_trace_generation_covers_every_edge_of_a_small_graph(max_len):
    g = small_graph()
    traces = cover(g, max_len=max_len)
    check_cover(g, traces)
    assert steps(traces) >= len(g.src)


def test_trace_generation_is_deterministic():
    g = small_graph()
    assert cover(g) == cover(g)


@pytest.mark.parametrize("max_len,expected", [
    # Worked by hand from the module's description: trace 1 prefers edges that stay in
    # the cycle {0, 1, 2}, leaves it for node 3 last and ends there; trace 2 starts at the
    # shallowest node with an untaken edge (4), detours 0 -> 1 and takes the rest.
    (1000, [(0, [0, 1, 2, 8, 5]), (4, [7, 6, 0, 3, 4])]),
    (2, [(0, [0, 1]), (0, [8, 5]), (4, [7, 2]), (0, [0, 3]), (0, [0, 4]), (4, [7, 6])]),
])
def test_trace_generation_walks_as_documented(max_len, expected):
    assert [(t.start, t.edges) for t in cover(small_graph(), max_len=max_len)] == expected


@pytest.mark.parametrize("seed", range(40))
def test_trace_generation_covers_every_edge_of_random_graphs(seed):
    import random

    rng = random.Random(seed)
    n = rng.randint(1, 30)
    src, dst = [], []
    for v in range(1, n):  # a random tree from node 0 keeps every node reachable
        src.append(rng.randrange(v))
        dst.append(v)
    for _ in range(rng.randint(0, 4 * n)):
        src.append(rng.randrange(n))
        dst.append(rng.randrange(n))
    g = Graph(n, [0], src, dst)
    for max_len, detour in ((1000, 256), (rng.randint(1, 5), rng.randint(1, 4))):
        traces = cover(g, max_len=max_len, detour_nodes=detour)
        check_cover(g, traces)
        assert all(len(t.edges) <= max(max_len, n) + n for t in traces)


def test_absorbing_node_is_entered_once_per_trace():
    g = small_graph()
    for t in cover(g):
        assert sum(1 for e in t.edges if g.dst[e] == 3 and g.src[e] != 3) <= 1


def test_unreachable_edges_are_an_error():
    g = Graph(3, [0], [0, 2], [1, 1])  # node 2 is not reachable
    with pytest.raises(UnreachableEdges):
        cover(g)


def _flagship_adapter_module():
    from pathlib import Path

    from safestate.systems.registry import _load_module, find

    system = find("SystemStateManager", Path(__file__).resolve().parents[2] / "systems")
    return _load_module("flagship_adapter_for_test", system.conformance.adapter)


def test_speed_vectors_and_threshold_probes_classify_as_the_model_levels():
    from safestate import _core as core

    mod = _flagship_adapter_module()
    for limit in (250, 100):
        cfg = core.Config(t1_speed_limit_mm_s=limit)
        vectors = mod.speed_vectors(core, cfg)
        for level in ("ZERO", "MOVING", "OVER_T1", "OVER_T2"):
            assert core.speed_level(mod.POSE, vectors[level][0], cfg) == level
        for label, level, qd in vectors["probes"]:
            assert core.speed_level(mod.POSE, qd, cfg) == level, label
        at = [qd for label, _, qd in vectors["probes"] if label == "TCP exactly at the T1 limit"][0]
        assert core.tcp_speed_mm_s(mod.POSE, at, cfg) == limit


def test_reference_kinematics_agrees_with_the_cpp_tcp_speed():
    from safestate import _core as core

    mod = _flagship_adapter_module()
    cfg = core.Config()
    dh = [tuple(r) for r in cfg.dh]
    for joint in range(6):
        qd = [0.0] * 6
        qd[joint] = 1.0
        ref = mod.tcp_speed_per_rad_s(dh, mod.POSE, joint)
        assert abs(core.tcp_speed_mm_s(mod.POSE, qd, cfg) - ref) <= 1e-9 * max(ref, 1.0)


def test_diff_marks_the_differing_fields():
    from safestate.conform.diff import report

    text = report(3, "Cycle(...)", {"state": "IDLE", "jog_axis": 0}, {"state": "ARMING", "jog_axis": 0})
    assert "step 3" in text and "state" in text.splitlines()[0]
    marked = [line for line in text.splitlines()[1:] if line.startswith("!")]
    assert len(marked) == 1 and "ARMING" in marked[0]
