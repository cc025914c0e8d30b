"""ITF counterexamples (validated against a JSON schema of Apalache ADR-015) and the
--graph output (complete and deterministic)."""

from __future__ import annotations

import json

import jsonschema

from conftest import CORPUS, run_safestate

VALUE = {"$ref": "#/$defs/value"}
ITF_SCHEMA = {
    "$schema": "https://json-schema.org/draft/2020-12/schema",
    "type": "object",
    "required": ["#meta", "vars", "states"],
    "properties": {
        "#meta": {"type": "object"},
        "params": {"type": "array", "items": {"type": "string"}},
        "vars": {"type": "array", "items": {"type": "string"}},
        "loop": {"type": "integer"},
        "states": {"type": "array", "minItems": 1, "items": {
            "type": "object",
            "required": ["#meta"],
            "properties": {"#meta": {"type": "object", "required": ["index", "action", "params"],
                                     "properties": {"index": {"type": "integer"}, "action": {"type": "string"},
                                                    "params": {"type": "object", "additionalProperties": VALUE}}}},
            "additionalProperties": VALUE}},
    },
    "$defs": {"value": {"anyOf": [
        {"type": "boolean"}, {"type": "string"}, {"type": "integer"},
        {"type": "array", "items": VALUE},
        {"type": "object", "required": ["#bigint"], "properties": {"#bigint": {"type": "string",
                                                                            "pattern": "^-?[0-9]+$"}},
         "additionalProperties": False},
        {"type": "object", "required": ["#tup"], "properties": {"#tup": {"type": "array", "items": VALUE}},
         "additionalProperties": False},
        {"type": "object", "required": ["#set"], "properties": {"#set": {"type": "array", "items": VALUE}},
         "additionalProperties": False},
        {"type": "object", "required": ["#map"], "properties": {"#map": {"type": "array", "items": {
            "type": "array", "minItems": 2, "maxItems": 2, "items": VALUE}}}, "additionalProperties": False},
        {"type": "object", "required": ["#unserializable"], "additionalProperties": False},
        {"type": "object", "propertyNames": {"pattern": "^[^#]"}, "additionalProperties": VALUE},
    ]}},
}


def _violating_specs() -> list[str]:
    exp = json.loads((CORPUS / "expected.json").read_text())
    return [n for n, e in sorted(exp.items()) if e["result"] in ("safety failure", "deadlock failure")]


def test_checker_itf_counterexamples_validate_against_schema(tmp_path) -> None:
    specs = _violating_specs()
    assert specs
    for name in specs:
        out = tmp_path / f"{name}.itf.json"
        p = run_safestate("check", str(CORPUS / f"{name}.tla"), "--itf", str(out))
        assert p.returncode in (11, 12), p.stdout + p.stderr
        trace = json.loads(out.read_text())
        jsonschema.validate(trace, ITF_SCHEMA)
        assert trace["states"][0]["#meta"]["action"] == "Init"
        assert [s["#meta"]["index"] for s in trace["states"]] == list(range(len(trace["states"])))
        assert set(trace["vars"]) <= set(trace["states"][-1])


def test_checker_json_output_contains_the_itf_trace() -> None:
    name = _violating_specs()[0]
    p = run_safestate("check", str(CORPUS / f"{name}.tla"), "--json")
    got = json.loads(p.stdout)
    jsonschema.validate(got["trace"], ITF_SCHEMA)
    assert got["seconds"] >= 0


def test_checker_graph_is_complete_and_deterministic(tmp_path) -> None:
    for name in ("TwoPhase", "TrafficView", "Peterson"):
        if not (CORPUS / f"{name}.tla").exists():
            continue
        a, b = tmp_path / "a.json", tmp_path / "b.json"
        run_safestate("check", str(CORPUS / f"{name}.tla"), "--graph", str(a))
        p = run_safestate("check", str(CORPUS / f"{name}.tla"), "--graph", str(b), "--json")
        assert a.read_bytes() == b.read_bytes()
        g = json.loads(a.read_text())
        summary = json.loads(p.stdout)
        assert len(g["states"]) == summary["distinct_states"]
        ids = {s["id"] for s in g["states"]}
        assert set(g["initial"]) <= ids
        assert all(e["from"] in ids and e["to"] in ids and e["action"] for e in g["edges"])
        # Without constraints every generated successor is an edge.
        exp = json.loads((CORPUS / "expected.json").read_text())[name]
        if summary["result"] == "success":
            assert len(g["edges"]) + len(g["initial"]) <= exp["states_generated"]
