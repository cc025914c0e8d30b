"""The certification evidence package (`safestate evidence`, issue 15) on one small
system (PLCopenAxis: a 104-state model, its proofs, 3 mutants, 16 GoogleTest tests),
built once per session with --reuse (build/evidence-cache): the matrix lists every
requirement ID of REQUIREMENTS.md, gaps are shown and counted, --verify passes on a
fresh package and fails after one byte of a model changes (on a copy of the inputs),
and the report works in a real browser (headless system Chromium)."""

from __future__ import annotations

import json
import os
import re
import shutil
import sys
from collections.abc import Iterator
from pathlib import Path
from urllib.parse import unquote, urlparse

import pytest

from conftest import REPO, run_safestate
from safestate import browser
from safestate.evidence.build import CACHE_ENV, REQUIREMENTS_COPY, find_requirements, shared_requirements
from safestate.evidence.collect import Runner
from safestate.evidence.sources import read_requirements

REQUIREMENTS = find_requirements(REPO)


def test_the_repositorys_requirements_copy_is_the_maintainers_file() -> None:
    """The package reads ../shared/REQUIREMENTS.md where it exists, else the repository's
    copy (a clean clone elsewhere, CI): the two must not drift apart."""
    copy = REPO / REQUIREMENTS_COPY
    assert copy.is_file() and REQUIREMENTS is not None
    shared = shared_requirements(REPO)
    if shared is None:
        pytest.skip("../shared/REQUIREMENTS.md not here (a clone elsewhere): the copy is what is read")
    assert copy.read_bytes() == shared.read_bytes(), f"{copy} differs from {shared}: copy the maintainers' file"


@pytest.fixture(scope="module")
def package(tmp_path_factory: pytest.TempPathFactory) -> Iterator[Path]:
    out = tmp_path_factory.mktemp("evidence") / "pkg"
    # A cache of the tests' own: a main job running beside them never rewrites these steps.
    old = os.environ.get(CACHE_ENV)
    os.environ[CACHE_ENV] = str(REPO / "build" / "evidence-cache-tests")
    r = run_safestate("evidence", "--system", "PLCopenAxis", "--reuse", "--no-pytest", "--out", str(out), cwd=REPO)
    assert r.returncode == 0, r.stdout + r.stderr
    assert f"evidence package: {out}/index.html" in r.stdout
    yield out
    if old is None:
        del os.environ[CACHE_ENV]
    else:
        os.environ[CACHE_ENV] = old


def _manifest(pkg: Path) -> dict:
    return json.loads((pkg / "manifest.json").read_text())


def test_evidence_matrix_has_one_row_per_requirement_id_in_order(package: Path) -> None:
    assert REQUIREMENTS is not None
    ids = [r.id for r in read_requirements(REQUIREMENTS, REPO)]
    html = (package / "index.html").read_text()
    rows = re.findall(r'<tr class="req"><td id="([^"]+)"', html)
    assert rows == ids
    assert {"RSM-01", "INV-RESET", "SAF-04", "INV-SAF-EMERGENCY", "SCH-05", "INV-PRESS", "PRO-05"} <= set(rows)


def test_evidence_gaps_are_counted_and_shown_in_red(package: Path) -> None:
    man = _manifest(package)
    html = (package / "index.html").read_text()
    assert f'id="gap-count">{man["gaps"]} gaps<' in html
    # PLCopenAxis has no conformance adapter: a gap; each of its 8 invariants has a killing mutant.
    assert man["gap_kinds"]["no conformance"] == 1
    assert "invariant without a mutant" not in man["gap_kinds"]
    # RSM-17's rows: the gap stays counted, with the design page's reason (not a stale one:
    # the reasons of requirements outside this package are not checked).
    assert re.search(r'<td class="gap">no design row</td><td><code>RSM-17</code></td><td>§8&#x27;s two axis tables '
                     r'have no row IDs.*\(docs/design/system-state-manager.md:\d+\)</td>', html)
    assert "stale gap reason" not in man["gap_kinds"]
    assert html.count('<td class="gap">') >= man["gaps"]
    # SCH-05 is covered by the press systems, left out of this package: listed as such, not a gap.
    for rid in ("SCH-05", "INV-PRESS"):
        assert re.search(rf'<td id="{rid}">.*?not in this package: covered by HydraulicPress, HydraulicPressFlat', html)
    assert not re.search(r'<td class="gap">not in a registered system</td><td><code>SCH-0[1-5]</code>', html)


def test_evidence_chain_of_a_requirement_has_proof_check_tests_and_locations(package: Path) -> None:
    html = (package / "index.html").read_text()
    row = html[html.index('<td id="RSM-17">'):]
    row = row[: row.index("</tr>")]
    assert "INV_LEGAL" in row and "models/PLCopenAxis.tla:" in row
    assert "proved (kind, k=1" in row
    assert "PLCopenAxis: success" in row
    assert "RSM17_PlcopenAxis." in row and "tests/cpp/test_plcopen_axis.cpp:" in row and ">passed<" in row


def test_evidence_package_has_diagrams_counterexamples_and_raw_artefacts(package: Path) -> None:
    # No C++ table diagram: the axis table of the design page has no row IDs -- said, not drawn empty.
    assert not (package / "diagrams" / "PLCopenAxis-table.svg").exists()
    assert "not drawn: no DOT export in the binding and no design-page row with an ID for RSM-17" in \
        (package / "systems" / "PLCopenAxis.html").read_text()
    for rel in ("diagrams/PLCopenAxis-model.svg", "junit/ctest.xml",
                "raw/PLCopenAxis/check.json", "raw/PLCopenAxis/prove.json", "raw/PLCopenAxis/prove.log"):
        assert (package / rel).is_file(), rel
    itfs = sorted((package / "mutants" / "PLCopenAxis").glob("*.itf.json"))
    assert len(itfs) == 8
    for itf in itfs:
        assert json.loads(itf.read_text())["states"]
        assert "<svg" in itf.with_name(itf.name.replace(".itf.json", ".svg")).read_text()
    assert "<svg" in (package / "diagrams" / "PLCopenAxis-model.svg").read_text()
    man = _manifest(package)
    assert "models/PLCopenAxis.tla" in man["inputs"] and "index.html" in man["outputs"]
    assert man["tools"]["z3"] and man["tools"]["compiler"] and man["checks"][0]["distinct_states"] == 104


def _input_copy(pkg: Path, dest: Path) -> Path:
    """The package's inputs copied under `dest` (never edit the repository's models)."""
    for rel in _manifest(pkg)["inputs"]:
        if not Path(rel).is_absolute():
            (dest / rel).parent.mkdir(parents=True, exist_ok=True)
            shutil.copyfile(REPO / rel, dest / rel)
    return dest


def test_evidence_verify_passes_fresh_and_fails_after_one_model_byte_changes(package: Path, tmp_path: Path) -> None:
    root = _input_copy(package, tmp_path / "repo")
    ok = run_safestate("evidence", "--verify", str(package), "--root", str(root))
    assert ok.returncode == 0, ok.stdout + ok.stderr
    assert "verified, no difference" in ok.stdout
    model = root / "models" / "PLCopenAxis.tla"
    data = bytearray(model.read_bytes())
    i = data.index(b"RSM-17")
    data[i + 5] = ord("8")          # "RSM-17" -> "RSM-18" in a comment: one byte
    model.write_bytes(bytes(data))
    bad = run_safestate("evidence", "--verify", str(package), "--root", str(root))
    assert bad.returncode == 1
    assert "input models/PLCopenAxis.tla: SHA-256 differs from the manifest" in bad.stdout


def test_evidence_verify_reports_a_changed_output_and_a_changed_count(package: Path, tmp_path: Path) -> None:
    copy = tmp_path / "pkg"
    shutil.copytree(package, copy)
    (copy / "junit" / "ctest.xml").write_text((copy / "junit" / "ctest.xml").read_text().replace("passed", "passes", 1)
                                              + " ")
    man = _manifest(copy)
    man["checks"][0]["distinct_states"] = 105
    (copy / "manifest.json").write_text(json.dumps(man))
    bad = run_safestate("evidence", "--verify", str(copy), "--root", str(REPO))
    assert bad.returncode == 1
    assert "output junit/ctest.xml: SHA-256 differs from the manifest" in bad.stdout
    assert "check PLCopenAxis: distinct_states is 104, the package says 105" in bad.stdout


def test_evidence_bad_inputs_give_one_line_and_exit_2(tmp_path: Path) -> None:
    r = run_safestate("evidence", "--verify", str(tmp_path))
    assert r.returncode == 2 and r.stderr.count("\n") == 1 and "not an evidence package" in r.stderr
    r = run_safestate("evidence", "--system", "NoSuchSystem", "--out", str(tmp_path / "x"), cwd=REPO)
    assert r.returncode == 2 and "not a registered system" in r.stderr and "Traceback" not in r.stderr
    (tmp_path / "keep.txt").write_text("mine")
    r = run_safestate("evidence", "--system", "PLCopenAxis", "--out", str(tmp_path), cwd=REPO)
    assert r.returncode == 2 and "refusing to overwrite" in r.stderr and (tmp_path / "keep.txt").is_file()


@pytest.mark.skipif(browser.missing() is not None, reason=str(browser.missing()))
def test_evidence_report_in_headless_chromium_loads_clean_with_every_link_and_image(package: Path) -> None:
    assert REQUIREMENTS is not None
    ids = [r.id for r in read_requirements(REQUIREMENTS, REPO)]
    pages = [package / "index.html", *sorted((package / "systems").glob("*.html"))]
    with browser.system_chromium() as d:
        for page in pages:
            d.get(page.resolve().as_uri())
            errors = [e for e in d.get_log("browser") if e.get("level") == "SEVERE"]
            assert errors == [], (page, errors)
            for img in d.find_elements("tag name", "img"):
                src = img.get_attribute("src")
                assert d.execute_script("return arguments[0].complete && arguments[0].naturalWidth > 0", img), src
            for a in d.find_elements("tag name", "a"):
                url = urlparse(a.get_attribute("href"))
                assert url.scheme == "file", url      # no external resource
                target = Path(unquote(url.path))
                assert target.is_file(), target
                if url.fragment and target.suffix == ".html":
                    assert f'id="{url.fragment}"' in target.read_text(), url.geturl()
            if page.name == "index.html":
                rows = d.find_elements("css selector", "#matrix-table tr.req")
                assert [r.find_element("css selector", "td").get_attribute("id") for r in rows] == ids
    for shot in ("summary.png", "PLCopenAxis.png"):
        assert (package / "screenshots" / shot).stat().st_size > 10_000


def test_evidence_requirement_ids_are_read_from_names_as_code_spells_them() -> None:
    from safestate.evidence.sources import code_ids
    known = {"RSM-05", "SAF-02", "INV-POWER", "INV-PRESS", "INV-NOJOG-AUTO"}
    assert code_ids("RSM05_Estop.ResetIsRejected", known) == ("RSM-05",)
    assert code_ids("test_estop_release_needs_reset_rsm05", known) == ("RSM-05",)
    assert code_ids("INV_NOJOG_AUTO", known) == ("INV-NOJOG-AUTO",)
    assert code_ids("HydraulicPress.INV_PRESS_MotorOffSwitchesEveryOutputOff", known) == ("INV-PRESS",)
    assert code_ids("INV_POWER_OFF", known) == ()          # another invariant, not INV-POWER
    assert code_ids("SAF02_InvSafEmergency.HoldsOnRandomMessageSequences", known | {"INV-SAF-EMERGENCY"}) == \
        ("INV-SAF-EMERGENCY", "SAF-02")
    assert code_ids("| P01 | PAIRING | ... | A, SAF-02 |", known) == ("SAF-02",)


def _known() -> set[str]:
    assert REQUIREMENTS is not None
    return {r.id for r in read_requirements(REQUIREMENTS, REPO)}


def test_evidence_req_marker_links_a_test_and_an_unknown_id_is_a_located_error(tmp_path: Path) -> None:
    from safestate.evidence.sources import RequirementLinkError, pytests
    (tmp_path / "test_a.py").write_text(
        'import pytest\n\n\n@pytest.mark.req("RSM-05", "INV-RESET")\n@pytest.mark.parametrize("x", [1])\n'
        "def test_reset_is_refused(x):\n    assert x\n\n\ndef test_unlinked():\n    pass\n\n\n"
        '@pytest.mark.req("SAF-02")\nclass TestPairing:\n    def test_first_estop_pairs(self):\n        pass\n')
    got = {t.name.split("::", 1)[1]: (t.requirements, t.declared) for t in pytests(tmp_path, tmp_path, _known())}
    assert got == {"test_reset_is_refused": (("INV-RESET", "RSM-05"), ("RSM-05", "INV-RESET")),
                   "test_unlinked": ((), ()),
                   "TestPairing::test_first_estop_pairs": (("SAF-02",), ("SAF-02",))}
    (tmp_path / "test_a.py").write_text('import pytest\n\n\n@pytest.mark.req("RSM-99")\ndef test_x():\n    pass\n')
    with pytest.raises(RequirementLinkError, match=r"test_a.py:4:19: RSM-99: not a requirement ID"):
        pytests(tmp_path, tmp_path, _known())
    (tmp_path / "test_a.py").write_text('import pytest\n\n\n@pytest.mark.req(\n    "RSM-05")\ndef test_x():\n    pass\n')
    with pytest.raises(RequirementLinkError, match=r'test_a.py:4:2: expected @pytest.mark.req\("ID", ...\) on one line'):
        pytests(tmp_path, tmp_path, _known())


def test_evidence_gtest_req_comment_links_the_test_right_below(tmp_path: Path) -> None:
    from safestate.evidence.sources import RequirementLinkError, gtests
    (tmp_path / "t.cpp").write_text("// req: INV-POWER RSM-16\n// what it asserts\nTEST(Outputs, LockoutIsUnpowered) {}\n"
                                    "\nTEST(Outputs, Unlinked) {}\n")
    got = {t.name: t.requirements for t in gtests(tmp_path, tmp_path, _known())}
    assert got == {"Outputs.LockoutIsUnpowered": ("INV-POWER", "RSM-16"), "Outputs.Unlinked": ()}
    (tmp_path / "t.cpp").write_text("// req: INV-POWERS\nTEST(A, B) {}\n")
    with pytest.raises(RequirementLinkError, match=r"t.cpp:1:9: INV-POWERS: not a requirement ID"):
        gtests(tmp_path, tmp_path, _known())


def test_evidence_unknown_req_marker_fails_pytest_collection() -> None:
    import conftest

    class Item:
        def __init__(self, nodeid: str, *ids: str) -> None:
            self.nodeid, self.mark = nodeid, pytest.mark.req(*ids).mark

        def iter_markers(self, name: str) -> Iterator[pytest.Mark]:
            return iter([self.mark] if name == "req" else [])

    conftest.pytest_collection_modifyitems(None, [Item("t.py::ok", "RSM-05", "INV-POWER")])  # type: ignore[arg-type]
    with pytest.raises(pytest.UsageError, match=r"t.py::bad: @pytest.mark.req: RSM-99 is not a requirement ID"):
        conftest.pytest_collection_modifyitems(None, [Item("t.py::bad", "RSM-05", "RSM-99")])  # type: ignore[arg-type]


def test_evidence_rows_unreachable_by_construction_have_the_design_pages_reason() -> None:
    """The rows the flagship's conformance declares unreachable are exactly those the design
    page gives a reason for: the package shows them apart, not as gaps."""
    from safestate.evidence.sources import unreachable_rows
    from safestate.systems.registry import load_all
    page = REPO / "docs" / "design" / "system-state-manager.md"
    rows = unreachable_rows(page, REPO)
    assert [u.id for u in rows] == ["K17", "K22", "K23", "K28"]
    assert all("C1" in u.reason and "answers first" in u.reason for u in rows)
    flagship = next(s for s in load_all(REPO / "systems") if s.name == "SystemStateManager")
    src = flagship.conformance.adapter.read_text()
    assert re.search(r'unreachable_rows = \("K17", "K22", "K23", "K28"\)', src)


def test_evidence_parametrised_gtest_cases_fold_into_their_test(tmp_path: Path) -> None:
    from safestate.evidence.junit import results
    xml = tmp_path / "ctest.xml"
    xml.write_text('<testsuite><testcase name="PoweredStates/RSM05_EstopPriority.Enters/0" status="run"/>'
                   '<testcase name="PoweredStates/RSM05_EstopPriority.Enters/1" status="run"><failure/></testcase>'
                   '<testcase name="Inputs/RSM04_Discrepancy.Latches/Estop  # GetParam() = Estop" status="run"/>'
                   '</testsuite>')
    assert results(xml, "gtest") == {"RSM05_EstopPriority.Enters": "failed", "RSM04_Discrepancy.Latches": "passed"}


def test_evidence_gap_reasons_keep_the_gap_counted_and_a_stale_one_is_shown(tmp_path: Path) -> None:
    from safestate.evidence.matrix import REQUIREMENT_GAP_KINDS, Gap, _explained, _stale_reasons
    from safestate.evidence.sources import RequirementLinkError, gap_reasons
    page = tmp_path / "p.md"
    page.write_text("- RSM-15 (no design row, no C++ row): a property of the whole C++, not a row.\n")
    reasons = gap_reasons(page, tmp_path, _known(), REQUIREMENT_GAP_KINDS)
    gaps = _explained([Gap("no design row", "RSM-15", "generic"), Gap("no test", "RSM-15", "generic")], reasons)
    assert gaps == [Gap("no design row", "RSM-15", "a property of the whole C++, not a row. (p.md:1)"),
                    Gap("no test", "RSM-15", "generic")]
    assert _stale_reasons(reasons, gaps) == [Gap("stale gap reason", "RSM-15",
                                                 "p.md:1 explains 'no C++ row', which is not a gap of it")]
    page.write_text("- RSM-15 (no row): x\n")
    with pytest.raises(RequirementLinkError, match=r"p.md:1:11: no row: not a gap kind"):
        gap_reasons(page, tmp_path, _known(), REQUIREMENT_GAP_KINDS)


def test_evidence_an_invariant_gap_carries_its_design_page_reason(tmp_path: Path) -> None:
    # The flat press violates INV_PRESS by design: no mutant can kill it, the page says why.
    from safestate.evidence.matrix import (INVARIANT_GAP_KINDS, REQUIREMENT_GAP_KINDS, Gap, _explained,
                                           _stale_reasons)
    from safestate.evidence.sources import RequirementLinkError, gap_reasons
    page = tmp_path / "p.md"
    page.write_text("- HydraulicPressFlat.INV_PRESS (invariant without a mutant): the defective reference.\n")
    reasons = gap_reasons(page, tmp_path, _known(), REQUIREMENT_GAP_KINDS, INVARIANT_GAP_KINDS)
    gap = Gap("invariant without a mutant", "HydraulicPressFlat.INV_PRESS", "no model mutant targets it")
    assert _explained([gap], reasons) == [Gap("invariant without a mutant", "HydraulicPressFlat.INV_PRESS",
                                              "the defective reference. (p.md:1)")]
    assert _stale_reasons(reasons, []) == [Gap("stale gap reason", "HydraulicPressFlat.INV_PRESS",
                                               "p.md:1 explains 'invariant without a mutant', which is not a gap of it")]
    page.write_text("- HydraulicPressFlat.INV_PRESS (no test): x\n")  # a requirement's kind, not an invariant's
    with pytest.raises(RequirementLinkError, match=r"p.md:1:33: no test: not a gap kind"):
        gap_reasons(page, tmp_path, _known(), REQUIREMENT_GAP_KINDS, INVARIANT_GAP_KINDS)


def _waits_for(mine: Path, other: Path) -> list[str]:
    """A step that announces itself and then waits (up to 60 s) for the other one."""
    code = (f"import pathlib, time; pathlib.Path({str(mine)!r}).touch(); t = time.monotonic()\n"
            f"while not pathlib.Path({str(other)!r}).exists() and time.monotonic() - t < 60: time.sleep(0.01)\n"
            f"raise SystemExit(0 if pathlib.Path({str(other)!r}).exists() else 1)")
    return [sys.executable, "-c", code]


def test_evidence_steps_run_side_by_side_on_two_job_slots(tmp_path: Path) -> None:
    # Each step succeeds only if the other is running at the same time: with one slot
    # the first would wait out its minute and fail.
    a, b = tmp_path / "a", tmp_path / "b"
    runner = Runner(tmp_path, tmp_path / "cache", reuse=False, log=lambda _: None, jobs=2)
    try:
        first = runner.submit("first", _waits_for(a, b), [])
        second = runner.submit("second", _waits_for(b, a), [])
        assert (first.result().returncode, second.result().returncode) == (0, 0)
    finally:
        runner.close()


def test_evidence_step_reused_only_while_its_inputs_are_unchanged(tmp_path: Path) -> None:
    model = tmp_path / "M.tla"
    model.write_text("one")
    argv = [sys.executable, "-c", f"print(open({str(model)!r}).read())"]
    runner = Runner(tmp_path, tmp_path / "cache", reuse=True, log=lambda _: None)
    try:
        fresh = runner.run("step", argv, [model])
        again = runner.run("step", argv, [model])
        model.write_text("two")
        changed = runner.run("step", argv, [model])
    finally:
        runner.close()
    assert (fresh.cached, again.cached, changed.cached) == (False, True, False)
    assert (again.stdout.strip(), changed.stdout.strip()) == ("one", "two")


def test_evidence_fails_a_check_whose_counts_differ_from_tlcs_recorded_figures() -> None:
    from safestate.evidence.build import tlc_difference
    table = {"M": {"distinct_states": 10, "states_generated": 30, "depth": 4},
             "M_small": {"model": "M", "distinct_states": 5, "states_generated": 9, "depth": 2}}
    ok = {"result": "success", "distinct_states": 10, "states_generated": 30, "depth": 4}
    assert tlc_difference(table, Path("models/M.cfg"), Path("models/M.tla"), ok) is None
    off = dict(ok, states_generated=31)
    assert tlc_difference(table, Path("models/M.cfg"), Path("models/M.tla"), off) == \
        "counts differ from TLC's in models/expected.json: states_generated 31 (TLC: 30)"
    # a cfg with no figures, or figures of another model's cfg of that name: nothing to compare
    assert tlc_difference(table, Path("models/Other.cfg"), Path("models/Other.tla"), off) is None
    assert tlc_difference(table, Path("models/M_small.cfg"), Path("models/N.tla"), off) is None


def test_evidence_coverage_replay_is_a_step_keyed_by_the_flagships_cpp_model_and_adapter() -> None:
    # The coverage replay is reused on a second run only while nothing it replays changed:
    # the C++ under test, the binding, the model and its cfgs, the adapter, the scripts.
    from concurrent.futures import Future

    from safestate.evidence.steps import submit_coverage
    from safestate.systems.registry import load_all

    class Recorder:
        def submit(self, name: str, argv: list[str], inputs: list[Path], outputs: list[str]) -> Future[None]:
            self.name, self.argv, self.inputs, self.outputs = name, argv, set(inputs), outputs
            return Future()

    flagship = next(s for s in load_all(REPO / "systems") if s.model.stem == "SystemStateManager")
    rec = Recorder()
    submit_coverage(rec, REPO, flagship, Path("build/coverage"))  # type: ignore[arg-type]
    assert rec.argv[:2] == ["bash", "conform/coverage.sh"] and "{out}" in rec.argv
    assert set(rec.outputs) == {"index.html", "summary.json"}
    for rel in ("src/transition_table.cpp", "models/SystemStateManager.tla", "models/SystemStateManager.cfg",
                "conform/coverage.sh", "conform/wrong_variant/CMakeLists.txt", "python/safestate/conform/__main__.py"):
        assert REPO / rel in rec.inputs, rel
    assert flagship.conformance and flagship.conformance.adapter in rec.inputs
