"""Building the evidence package: runs (or reuses) every step, then writes the pages,
diagrams, raw artefacts and the manifest into one self-contained folder."""

from __future__ import annotations

import json
import os
import re
import shutil
from collections.abc import Callable
from dataclasses import dataclass, field
from html import escape
from pathlib import Path
from typing import Any

from ..errors import UsageError
from ..systems.registry import System, load_all, scan
from . import diagrams, junit, manifest, model_mutation, render, sources, traces
from .collect import Runner, StepResult
from .matrix import (INVARIANT_GAP_KINDS, REQUIREMENT_GAP_KINDS, SystemFacts, build as build_matrix, check_ok,
                     check_verdict, conform_summary, proofs_by_invariant)
from .render import SystemPage
from ..checker.cfg import parse_config
from .steps import (SystemRuns, cpp_files, model_files, submit_conform, submit_coverage, submit_ctest, submit_pytest,
                    submit_system,
                    system_inputs)

REQUIREMENTS_ENV = "SAFESTATE_REQUIREMENTS"
CACHE_ENV = "SAFESTATE_EVIDENCE_CACHE"
MUTATION_SCORE = Path("build") / "cpp-mutation" / "score.json"
# The last measured score, committed (conform/cpp_mutants/README.md), when no run of the
# main job has written MUTATION_SCORE.
STORED_MUTATION_SCORE = Path("conform") / "cpp_mutants" / "score.json"
COVERAGE_DIR = Path("build") / "coverage"
COVERAGE_MODEL = "SystemStateManager"  # conform/coverage.sh replays the flagship


@dataclass
class Options:
    out: Path
    root: Path
    requirements: Path
    systems: list[str] = field(default_factory=list)      # empty: every registered system
    reuse: bool = False
    conform_args: list[str] = field(default_factory=lambda: ["--input-complete", "--seed", "0"])
    pytest: bool = True
    screenshots: bool = True
    coverage: bool = False
    log: Callable[[str], None] = print
    jobs: int = field(default_factory=lambda: min(2, os.cpu_count() or 1))   # steps run side by side


@dataclass
class Result:
    out: Path
    gaps: int
    failures: list[str]
    steps: list[dict[str, Any]] = field(default_factory=list)   # name, returncode, seconds, cached, key


def cache_dir(root: Path) -> Path:
    """Where step results are cached: $SAFESTATE_EVIDENCE_CACHE, else build/evidence-cache
    (the tests use their own, so that a main job beside them never rewrites their steps)."""
    return Path(os.environ.get(CACHE_ENV) or root / "build" / "evidence-cache")


# The repository's copy of the maintainers' REQUIREMENTS.md, so that a clone anywhere
# (CI's clean clone) builds and tests the package; tests/python/test_evidence.py checks
# it is identical to ../shared/REQUIREMENTS.md wherever that exists.
REQUIREMENTS_COPY = Path("docs") / "requirements" / "REQUIREMENTS.md"


def shared_requirements(root: Path) -> Path | None:
    """../shared/REQUIREMENTS.md of the repository or of a folder above it (a worktree
    sits deeper than the main clone)."""
    for d in (root, *root.parents):
        p = d / "shared" / "REQUIREMENTS.md"
        if p.is_file():
            return p
    return None


def find_requirements(root: Path) -> Path | None:
    """REQUIREMENTS.md: $SAFESTATE_REQUIREMENTS, else ../shared/REQUIREMENTS.md, else the
    repository's copy (docs/requirements/)."""
    env = os.environ.get(REQUIREMENTS_ENV)
    if env:
        return Path(env)
    shared = shared_requirements(root)
    if shared is not None:
        return shared
    copy = root / REQUIREMENTS_COPY
    return copy if copy.is_file() else None


def select_systems(root: Path, names: list[str]) -> list[System]:
    # The package covers every system: an unreadable manifest stops the build (exit 2)
    # rather than leaving its system out of the evidence unnoticed.
    every, broken = scan(root / "systems")
    if broken:
        raise broken[0]
    if not names:
        return every
    known = {s.name: s for s in every}
    bad = [n for n in names if n not in known]
    if bad:
        raise UsageError(f"--system {', '.join(bad)}: not a registered system (registered: {', '.join(known)})")
    return [known[n] for n in names]


def build(opts: Options) -> Result:
    root, out = opts.root, opts.out
    systems = select_systems(root, opts.systems)
    if not opts.requirements.is_file():
        raise UsageError(f"{opts.requirements}: REQUIREMENTS.md not found (give --requirements FILE or set "
                         f"{REQUIREMENTS_ENV})")
    if out.exists():
        if not (out / manifest.NAME).is_file() and any(out.iterdir()):
            raise UsageError(f"{out}: exists and is not an evidence package; refusing to overwrite it")
        shutil.rmtree(out)
    out.mkdir(parents=True)
    reqs = sources.read_requirements(opts.requirements, root)
    known = {r.id for r in reqs}
    pages = sorted((root / "docs" / "design").glob("*.md"))
    try:
        tests = [t for d in [root / "tests" / "cpp", *sorted((root / "src").rglob("tests"))]
                 for t in sources.gtests(d, root, known)] + sources.pytests(root / "tests" / "python", root, known)
        reasons = [g for p in pages for g in sources.gap_reasons(p, root, known, REQUIREMENT_GAP_KINDS,
                                                                  INVARIANT_GAP_KINDS)]
    except sources.RequirementLinkError as e:
        raise UsageError(str(e)) from None
    corpus = sources.Corpus(reqs, [r for p in pages for r in sources.design_rows(p, root, known)], tests,
                            [u for p in pages for u in sources.unreachable_rows(p, root)], reasons)
    runner = Runner(root, cache_dir(root), opts.reuse, opts.log, opts.jobs)
    figures = tlc_figures(root)
    try:
        facts, selected, ctest, pyt, coverage = _run_steps(runner, root, systems, corpus, opts, figures)
    finally:
        runner.close()
    elsewhere = _elsewhere(root, systems)
    results = {**junit.results(ctest.files.get("ctest.xml"), "gtest"),
               **(junit.results(pyt.files.get("pytest.xml"), "pytest") if pyt else {})}
    m = build_matrix(corpus, facts, results, elsewhere)

    extras: list[tuple[str, str]] = []
    _copy_junit(out, ctest, pyt, extras)
    test_counts = {f.runs.system.name: junit.counts({t.name: results.get(t.name, "not run") for t in selected
                                                      if set(t.requirements) & set(_ids_of(f))})
                   for f in facts}
    sys_pages = [_system_page(out, f, corpus) for f in facts]
    if coverage is not None:
        _write_coverage(out, coverage, extras)
    _mutation_score(out, root, extras)
    mutation_gaps = model_mutation.write(out, systems, sys_pages, extras)
    header = {"date": manifest.now(), "tools": manifest.tool_versions(root), "machine": manifest.machine()}
    (out / "index.html").write_text(render.index_html(sys_pages, m, header, extras, test_counts), encoding="utf-8")
    for p in sys_pages:
        _write(out, p.href, render.system_html(p))
    if opts.screenshots:
        _screenshots(out, sys_pages, opts.log)

    failures = _failures(facts, ctest, pyt, figures)
    inputs = sorted({f for s in systems for f in system_inputs(s)} | {opts.requirements, *pages}
                    | {root / t.loc.file for t in selected})
    checks = [_check_record(f.runs, root) for f in facts]
    steps = [{"name": st.name, "returncode": st.returncode, "seconds": st.seconds, "cached": st.cached, "key": st.key}
             for st in _all_steps(facts, ctest, pyt)]
    manifest.write(out, root, inputs, {"systems": [s.name for s in systems], "requirements_file": str(opts.requirements),
                                       "gaps": len(m.gaps), "gap_kinds": _kinds(m.gaps), "failures": failures,
                                       "unreachable_rows": [f"{u.why.page} {u.why.id}" for u in m.unreachable],
                                       "checks": checks, "steps": steps, "model_mutation_gaps": mutation_gaps})
    return Result(out, len(m.gaps), failures, steps)


def _run_steps(runner: Runner, root: Path, systems: list[System], corpus: sources.Corpus,
               opts: Options, figures: dict[str, Any]) -> tuple[list[SystemFacts], list[sources.TestCase], StepResult, StepResult | None,
                                       StepResult | None]:
    """Every step of the package queued at once (opts.jobs run side by side), then
    waited for: the systems' checks, proofs, conformance and mutants, the tests, and the
    flagship's coverage."""
    known = {r.id for r in corpus.requirements}
    # Longest first, so that the two job slots end together: the conformance runs (the
    # largest state space first), the pytest run and the coverage replay, then the rest.
    by_size = sorted(systems, key=lambda s: -_states_generated(figures, s))
    conform = {s.name: submit_conform(runner, s, opts.conform_args) for s in by_size}
    defs = {s.name: [d for f in model_files(s.model) for d in sources.model_defs(f, root, known)] for s in systems}
    invariants = {s.name: [e.name for e in parse_config(str(s.ci_config)).invariants] for s in systems}
    elsewhere = _elsewhere(root, systems)
    owned = {rid for s in systems for rid in s.requirements} | {
        rid for s in systems for d in defs[s.name] if d.name in invariants[s.name] for rid in d.requirements}
    selected = _tests_of(corpus, owned, known, elsewhere)
    pyt = submit_pytest(runner, root, [t.name for t in selected if t.kind == "pytest"]) if opts.pytest else None
    flagship = next((s for s in systems if s.model.stem == COVERAGE_MODEL), None)
    coverage = submit_coverage(runner, root, flagship, COVERAGE_DIR) if opts.coverage and flagship else None
    pending = [submit_system(runner, s, conform[s.name]) for s in systems]
    ctest = submit_ctest(runner, root, None if not opts.systems else
                         "^([^/ ]*/)?(" + "|".join(re.escape(t.name) for t in selected if t.kind == "gtest") + ")(/.*)?$")
    facts: list[SystemFacts] = []
    for s, p in zip(systems, pending):
        runs = p.result()
        facts.append(SystemFacts(runs, defs[s.name], invariants[s.name], sources.cpp_row_locations(cpp_files(s), root)))
        opts.log(_one_line(runs))
    return facts, selected, ctest.result(), pyt.result() if pyt else None, coverage.result() if coverage else None


def _tests_of(corpus: sources.Corpus, owned: set[str], known: set[str],
              elsewhere: dict[str, list[str]]) -> list[sources.TestCase]:
    """The tests of this package's requirements and of those no registered system
    covers (listed in every package); not those of the systems left out."""
    wanted = owned | (known - set(elsewhere))
    return [t for t in corpus.tests if set(t.requirements) & wanted]


def _one_line(r: SystemRuns) -> str:
    """What a system's steps gave, for the main job's log."""
    c = r.check.json()
    parts = [f"== {r.system.name}: check {check_verdict(r)}" + (
        f" ({c['distinct_states']:,} distinct, {c['states_generated']:,} generated, depth {c['depth']})"
        if isinstance(c, dict) and "distinct_states" in c else "")]
    if r.prove:
        proofs = proofs_by_invariant(r)
        parts.append(f"proofs {sum(1 for x in proofs.values() if x.get('status') == 'proved')}/{len(proofs)} proved")
    conf = conform_summary(r)
    if conf:
        parts.append(f"conformance {conf.get('transitions_covered'):,}/{conf.get('transitions_total'):,} transitions, "
                     f"{conf.get('mismatches')} mismatches, {len(conf.get('rows_taken', []))} rows taken")
    elif r.conform:
        parts.append(f"conformance exit {r.conform.returncode}")
    if r.mutants:
        parts.append(f"mutants {sum(1 for m in r.mutants if m.killed)}/{len(r.mutants)} killed")
    return "; ".join(parts)


def _elsewhere(root: Path, packaged: list[System]) -> dict[str, list[str]]:
    """Requirement -> the registered systems not in this package that cover it (listed
    in their manifest, or an invariant of their CI cfg named after it)."""
    from ..checker.cfg import parse_config
    names = {s.name for s in packaged}
    out: dict[str, list[str]] = {}
    for s in load_all(root / "systems"):
        if s.name in names:
            continue
        ids = set(s.requirements)
        ids |= {"INV-" + e.name[4:].replace("_", "-") for e in parse_config(str(s.ci_config)).invariants
                if e.name.startswith("INV_")}
        for rid in ids:
            out.setdefault(rid, []).append(s.name)
    return out


def _ids_of(f: SystemFacts) -> list[str]:
    return list(f.runs.system.requirements) + [r for d in f.defs if d.name in f.invariants for r in d.requirements]


def _kinds(gaps: list[Any]) -> dict[str, int]:
    out: dict[str, int] = {}
    for g in gaps:
        out[g.kind] = out.get(g.kind, 0) + 1
    return out


def _all_steps(facts: list[SystemFacts], ctest: StepResult, pyt: StepResult | None) -> list[StepResult]:
    out: list[StepResult] = []
    for f in facts:
        r = f.runs
        out += [x for x in (r.check, r.prove, r.conform) if x is not None] + [m.step for m in r.mutants]
    return out + [ctest] + ([pyt] if pyt else [])


def _failures(facts: list[SystemFacts], ctest: StepResult, pyt: StepResult | None,
              figures: dict[str, Any]) -> list[str]:
    """Steps that did not succeed: these make `safestate evidence` exit non-zero."""
    out = []
    for f in facts:
        r, n = f.runs, f.runs.system.name
        if not check_ok(r):
            out.append(f"{n}: model check {check_verdict(r)}")
        elif (differ := tlc_difference(figures, r.system.ci_config, r.system.model, r.check.json())):
            out.append(f"{n}: model check {differ}")
        if r.prove and r.prove.returncode != (12 if r.system.expected_violation else 0):
            out.append(f"{n}: prove exit {r.prove.returncode}")
        if r.conform and r.conform.returncode != 0:
            out.append(f"{n}: conform exit {r.conform.returncode}")
        out += [f"{n}: mutant {m.mutant.name} not killed" for m in r.mutants if not m.killed]
        if r.mutant_error:
            out.append(f"{n}: {r.mutant_error}")
    if ctest.returncode != 0:
        out.append(f"ctest exit {ctest.returncode}")
    if pyt and pyt.returncode != 0:
        out.append(f"pytest exit {pyt.returncode}")
    return out


# TLC's figures for the CI cfgs, recorded with TLC 1.8.0 (tests/python/test_models.py pins them too).
TLC_FIGURES = Path("models") / "expected.json"
_COUNTS = ("distinct_states", "states_generated", "depth")


def tlc_figures(root: Path) -> dict[str, Any]:
    path = root / TLC_FIGURES
    return json.loads(path.read_text(encoding="utf-8")) if path.is_file() else {}


def _states_generated(figures: dict[str, Any], system: System) -> int:
    """TLC's states generated for the system's CI cfg (0: not recorded): the size of
    the search its check and conformance run make."""
    want = figures.get(system.ci_config.stem)
    return int(want.get("states_generated", 0)) if isinstance(want, dict) else 0


def tlc_difference(table: dict[str, Any], cfg: Path, model: Path, got: object) -> str | None:
    """How a check's counts differ from TLC's figures recorded for `cfg` in `table`
    (models/expected.json: keyed by the cfg's stem, with "model" when it is not the
    model's own cfg), or None: equal, or nothing recorded for that cfg of that model."""
    want = table.get(cfg.stem)
    if not isinstance(want, dict) or want.get("model", cfg.stem) != model.stem or not isinstance(got, dict):
        return None
    bad = [f"{k} {got.get(k)} (TLC: {want[k]})" for k in _COUNTS if k in want and got.get(k) != want[k]]
    return f"counts differ from TLC's in {TLC_FIGURES}: {', '.join(bad)}" if bad else None


def _check_record(r: SystemRuns, root: Path) -> dict[str, Any]:
    j = r.check.json()
    j = j if isinstance(j, dict) else {}
    return {"system": r.system.name, "model": sources.rel(root, r.system.model),
            "cfg": sources.rel(root, r.system.ci_config),
            **{k: j.get(k) for k in ("result", "distinct_states", "states_generated", "depth")}}


def _write(out: Path, rel: str, text: str) -> str:
    p = out / rel
    p.parent.mkdir(parents=True, exist_ok=True)
    p.write_text(text, encoding="utf-8")
    return rel


def _copy_junit(out: Path, ctest: StepResult, pyt: StepResult | None, extras: list[tuple[str, str]]) -> None:
    for step, name in ((ctest, "ctest.xml"), (pyt, "pytest.xml")):
        if step is not None and name in step.files:
            (out / "junit").mkdir(exist_ok=True)
            shutil.copyfile(step.files[name], out / "junit" / name)
            extras.append((f"JUnit XML: {name}", f"junit/{name}"))
            _write(out, f"junit/{name}.log", step.stdout + step.stderr)
            extras.append((f"log of the run that wrote {name}", f"junit/{name}.log"))


def _system_page(out: Path, f: SystemFacts, corpus: sources.Corpus) -> SystemPage:
    r = f.runs
    s = r.system
    p = SystemPage(r, f"systems/{s.name}.html")
    p.figures["invariants"] = f.invariants
    base = f"raw/{s.name}"
    for step, stem in ((r.check, "check"), (r.prove, "prove"), (r.conform, "conform")):
        if step is None:
            continue
        p.raw.append((f"{stem} output (JSON)", "../" + _write(out, f"{base}/{stem}.json", step.stdout)))
        p.raw.append((f"{stem} log (stderr, exit {step.returncode}, {step.seconds} s)",
                      "../" + _write(out, f"{base}/{stem}.log", step.stderr)))
    table = None
    try:
        table = diagrams.cpp_table_dot(s)
    except diagrams.DiagramError as e:
        p.diagrams.append(("C++ transition table", "", f"not drawn: {e}"))
    ids = set(_ids_of(f))
    page = sources.rel(s.root, s.design)
    if table is None:
        rows = [row for row in corpus.rows if row.page == page and set(row.requirements) & ids]
        table = (diagrams.design_rows_dot(f"{s.name} rows", rows),
                 f"from the {len(rows)} rows of {page} (no DOT export in the binding)") if rows else None
    if table is None:
        p.diagrams.append(("C++ transition table", "", f"not drawn: no DOT export in the binding and no design-page "
                           f"row with an ID for {', '.join(sorted(ids))} in {page}"))
    else:
        try:
            rel = _write(out, f"diagrams/{s.name}-table.svg", diagrams.svg(table[0]))
            p.diagrams.append(("C++ transition table (row IDs on the edges)", "../" + rel, f"source: {table[1]}"))
        except diagrams.DiagramError as e:
            p.diagrams.append(("C++ transition table", "", f"not drawn: {e}"))
    control = str(s.extra.get("control_state", "state"))
    try:
        dot, figures = diagrams.model_states_dot(s, control)
        p.figures.update(figures)
        rel = _write(out, f"diagrams/{s.name}-model.svg", diagrams.svg(dot))
        p.diagrams.append((f"model control states ({control})", "../" + rel,
                           f"{figures['states']:,} states, {figures['transitions']:,} transitions of the CI cfg; "
                           "edges: the model's actions" + (" and the rows RowsFiredBy gives on a sample of each "
                                                           "edge's transitions" if s.conformance else "")))
    except Exception as e:  # noqa: BLE001 - a diagram that cannot be drawn is said in the page, not hidden
        p.diagrams.append(("model control states", "", f"not drawn: {type(e).__name__}: {e}"))
    for mr in r.mutants:
        p.mutant_html.append(_mutant_html(out, s, mr, control))
    return p


def _mutant_html(out: Path, s: System, mr: Any, control: str) -> str:
    m = mr.mutant
    status = "killed" if mr.killed else "SURVIVES"
    head = (f'<h3 id="mutant-{escape(m.name)}">{escape(m.name)} — <span class="{"ok" if mr.killed else "bad"}">'
            f'{status}</span></h3><p>{escape(m.requirement)} · target <code>{escape(m.invariant)}</code> '
            f'(expect {escape(m.expect)}) · {escape(m.why)}</p>')
    trace = mr.step.files.get("trace.itf.json")
    if trace is None:
        return head + ("<p class=muted>no counterexample: the mutant removes a witness situation (the check "
                       "succeeds without reaching it)</p>" if m.expect == "holds" else "<p class=bad>no trace</p>")
    itf = json.loads(trace.read_text(encoding="utf-8"))
    base = f"mutants/{s.name}/{m.name}"
    (out / "mutants" / s.name).mkdir(parents=True, exist_ok=True)
    shutil.copyfile(trace, out / f"{base}.itf.json")
    ss = traces.steps(itf)
    _write(out, f"{base}.svg", traces.sequence_svg(ss, s.name, control, f"{m.invariant} violated"))
    return (head + f'<p><a href="../{base}.itf.json">ITF trace</a> ({len(ss)} states)</p>'
            f'<img class="diagram" src="../{base}.svg" alt="sequence diagram of {escape(m.name)}">'
            + traces.step_table_html(ss, control))


def _mutation_score(out: Path, root: Path, extras: list[tuple[str, str]]) -> None:
    src = next((p for p in (root / MUTATION_SCORE, root / STORED_MUTATION_SCORE) if p.is_file()), None)
    if src is None:
        extras.append(("C++ mutation score: not measured yet (conform/cpp_mutants/score.py)", "index.html#artefacts"))
        return
    (out / "mutation").mkdir(exist_ok=True)
    shutil.copyfile(src, out / "mutation" / "score.json")
    d = json.loads(src.read_text(encoding="utf-8"))
    lo, hi = d.get("confidence_95_percent") or ("?", "?")
    extras.append((f"C++ mutation score: {d.get('score_percent')}% (95% interval {lo}-{hi}%; {d.get('killed')} killed "
                   f"of {d.get('evaluated', '?')} evaluated, {d.get('stillborn')} stillborn, {d.get('sampled')} "
                   f"sampled of {d.get('generated')} generated; {d.get('date')})", "mutation/score.json"))
    surv = "".join(f"<tr><td><code>{escape(x.get('file', ''))}:{x.get('line')}</code></td>"
                   f"<td><code>{escape(x.get('original', ''))}</code></td><td><code>{escape(x.get('mutant', ''))}</code></td>"
                   f"<td>{escape(x.get('note', ''))}</td></tr>" for x in d.get("survivors", []))
    html = render.page("C++ mutation score", f'<p><a href="../index.html">← summary</a></p><h1>C++ mutation score</h1>'
                       f"<pre>{escape(json.dumps({k: v for k, v in d.items() if k != 'survivors'}, indent=1))}</pre>"
                       f"<h2>Survivors</h2><table><tr><th>where</th><th>original</th><th>mutant</th><th>note</th></tr>"
                       f"{surv}</table>")
    _write(out, "mutation/index.html", html)
    extras.append(("C++ mutation survivors", "mutation/index.html"))


def _write_coverage(out: Path, p: StepResult, extras: list[tuple[str, str]]) -> None:
    _write(out, "coverage/summary.txt", p.stdout + p.stderr)
    extras.append((f"gcovr branch coverage of src/ under the flagship's conformance (exit {p.returncode})",
                   "coverage/summary.txt"))
    for name, title in (("index.html", "gcovr HTML report"), ("summary.json", None)):
        f = p.files.get(name)
        if p.returncode == 0 and f is not None:
            shutil.copyfile(f, out / "coverage" / name)
            if title:
                extras.append((title, f"coverage/{name}"))


def _screenshots(out: Path, pages: list[SystemPage], log: Callable[[str], None]) -> None:
    from .. import browser
    why = browser.missing()
    if why:
        log(f"evidence: no screenshots: {why}")
        return
    (out / "screenshots").mkdir(exist_ok=True)
    with browser.system_chromium(1400, 1000) as d:
        d.get((out / "index.html").resolve().as_uri())
        d.save_screenshot(str(out / "screenshots" / "summary.png"))
        if pages:
            d.get((out / pages[0].href).resolve().as_uri())
            d.save_screenshot(str(out / "screenshots" / f"{pages[0].runs.system.name}.png"))
