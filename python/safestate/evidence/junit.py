"""Test results from JUnit XML (ctest --output-junit, pytest --junitxml), by test name:
GoogleTest `Suite.Name`, pytest node id `tests/python/f.py::name` (parametrised cases
folded into one: failed if any case failed; GoogleTest's value-parametrised cases
likewise)."""

from __future__ import annotations

import xml.etree.ElementTree as ET
from pathlib import Path

RANK = {"passed": 0, "skipped": 1, "failed": 2}


def _outcome(case: ET.Element) -> str:
    if case.find("failure") is not None or case.find("error") is not None:
        return "failed"
    if case.find("skipped") is not None or case.get("status") in ("notrun", "disabled"):
        return "skipped"
    return "passed"


def gtest_name(ctest_name: str) -> str:
    """`Suite.Name` of a ctest name: a value-parametrised case `Prefix/Suite.Name/param`
    (TEST_P, INSTANTIATE_TEST_SUITE_P) folds into its TEST_P."""
    parts = ctest_name.split(" ", 1)[0].split("/")
    return next((p for p in parts if "." in p), ctest_name)


def results(path: Path | None, kind: str) -> dict[str, str]:
    """name -> passed / failed / skipped."""
    if path is None or not path.is_file():
        return {}
    out: dict[str, str] = {}
    for case in ET.parse(path).getroot().iter("testcase"):
        name = case.get("name", "")
        if kind == "pytest":
            cls = case.get("classname", "")
            # classname "tests.python.test_x" or "tests.python.test_x.TestClass"
            parts = cls.split(".")
            i = next((k for k, p in enumerate(parts) if p.startswith("test_")), len(parts) - 1)
            path_part = "/".join(parts[: i + 1]) + ".py"
            inner = parts[i + 1:]
            name = "::".join([path_part, *inner, name.split("[", 1)[0]])
        else:
            name = gtest_name(name)
        o = _outcome(case)
        if RANK[o] >= RANK.get(out.get(name, "passed"), 0) or name not in out:
            out[name] = o if name not in out else max(out[name], o, key=RANK.__getitem__)
    return out


def counts(res: dict[str, str]) -> dict[str, int]:
    c = {"passed": 0, "failed": 0, "skipped": 0, "not run": 0}
    for o in res.values():
        c[o] = c.get(o, 0) + 1
    return c
