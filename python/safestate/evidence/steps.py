"""The evidence steps of one system and of the test suites: which command, which
inputs (for the cache key and the manifest), which outputs."""

from __future__ import annotations

import os
import re
from concurrent.futures import Future
from dataclasses import dataclass, field
from pathlib import Path

from .. import mutants as mutants_mod
from ..systems.registry import System
from ..checker.native import native_core_sources
from .collect import Runner, StepResult, files_under, safestate_argv

PKG = Path(__file__).resolve().parents[1]   # python/safestate
# The tool sources each step depends on (its "version" in the cache key).
TOOL = {"check": ("checker", "tla"), "prove": ("prove", "checker", "tla"),
        "conform": ("conform", "checker", "tla", "systems")}


def tool_files(step: str) -> list[Path]:
    files = files_under([PKG / d for d in TOOL[step]], (".py",))
    # The model mutants run with `--engine auto`: the native core is part of the checker.
    return [*files, *native_core_sources()] if "checker" in TOOL[step] else files


def model_files(model: Path) -> list[Path]:
    """The model and every module of its folder it EXTENDS or INSTANCEs, transitively."""
    out: list[Path] = []
    todo = [model]
    while todo:
        m = todo.pop()
        if m in out or not m.is_file():
            continue
        out.append(m)
        text = m.read_text(encoding="utf-8")
        names = re.findall(r"\bINSTANCE\s+([A-Za-z_]\w*)", text)
        for ext in re.findall(r"^EXTENDS\s+([^\n]+)", text, re.M):
            names += [n.strip() for n in ext.split(",")]
        todo += [m.parent / f"{n}.tla" for n in names]
    return sorted(out)


def cpp_files(system: System) -> list[Path]:
    pats = system.extra.get("cpp_sources", [])
    found: list[Path] = []
    for p in pats:
        found += sorted(system.root.glob(p)) if any(c in p for c in "*?[") else [system.root / p]
    return files_under(found, (".hpp", ".cpp", ".h"))


def mutants_file(system: System) -> Path | None:
    if system.mutants:
        return system.mutants
    p = system.root / "models" / "mutants" / f"{system.model.stem}.toml"
    return p if p.is_file() else None


def proof_files(system: System) -> list[Path]:
    if system.proofs is None:
        return []
    return [system.proofs, *sorted(system.proofs.parent.glob(f"{system.model.stem}Proofs*.tla"))]


def system_inputs(system: System) -> list[Path]:
    """Every input of the system's evidence: what the manifest hashes."""
    files = [system.manifest, system.design, *model_files(system.model), *system.configs, *proof_files(system),
             *cpp_files(system)]
    mf = mutants_file(system)
    if mf:
        files.append(mf)
    if system.conformance:
        files.append(system.conformance.adapter)
    return sorted(set(f for f in files if f.is_file()))


@dataclass
class MutantRun:
    mutant: mutants_mod.Mutant
    step: StepResult
    killed: bool


@dataclass
class SystemRuns:
    system: System
    check: StepResult
    prove: StepResult | None
    conform: StepResult | None
    mutants: list[MutantRun] = field(default_factory=list)
    mutant_error: str | None = None


@dataclass
class PendingRuns:
    """A system's steps, submitted to the runner; `result()` waits for them."""
    system: System
    check: Future[StepResult]
    prove: Future[StepResult] | None
    conform: Future[StepResult] | None
    mutants: list[tuple[mutants_mod.Mutant, Future[StepResult]]] = field(default_factory=list)
    mutant_error: str | None = None

    def result(self) -> SystemRuns:
        runs = SystemRuns(self.system, self.check.result(), self.prove.result() if self.prove else None,
                          self.conform.result() if self.conform else None, mutant_error=self.mutant_error)
        for m, fut in self.mutants:
            step = fut.result()
            killed = step.returncode == 12 if m.expect == "violated" else step.returncode == 0
            runs.mutants.append(MutantRun(m, step, killed))
        return runs


def submit_conform(runner: Runner, system: System, conform_args: list[str]) -> Future[StepResult] | None:
    """The system's conformance run (None: it has no C++ adapter)."""
    if not system.conformance:
        return None
    mfiles = [*model_files(system.model), system.ci_config]
    return runner.submit(f"{system.name}-conform", safestate_argv("conform", system.name, "--json", *conform_args),
                         [*mfiles, system.manifest, system.conformance.adapter, *cpp_files(system),
                          *tool_files("conform")])


def submit_system(runner: Runner, system: System, conform: Future[StepResult] | None) -> PendingRuns:
    """Queues the system's check, proofs and model mutants beside its (already queued)
    conformance run."""
    model, cfg = system.model, system.ci_config
    mfiles = [*model_files(model), cfg]
    check = runner.submit(f"{system.name}-check", safestate_argv("check", str(model), "--config", str(cfg), "--json"),
                          [*mfiles, *tool_files("check")])
    prove = None
    if system.expected_violation:  # a defective reference: BMC must refute its invariant (exit 12)
        prove = runner.submit(f"{system.name}-prove",
                              safestate_argv("prove", str(model), "--config", str(cfg), "--engine", "bmc", "--depth",
                                             "6", "--invariant", system.expected_violation, "--json"),
                              [*mfiles, *tool_files("prove")])
    elif system.proofs:
        prove = runner.submit(f"{system.name}-prove",
                              safestate_argv("prove", str(model), "--config", str(cfg), "--proofs", str(system.proofs),
                                             "--json"),
                              [*mfiles, *proof_files(system), *tool_files("prove")])
    pending = PendingRuns(system, check, prove, conform)
    _submit_mutants(runner, pending)
    return pending


def _submit_mutants(runner: Runner, pending: PendingRuns) -> None:
    """Each model mutant checked on its own (materialised by safestate.mutants), with
    its counterexample written as ITF."""
    system = pending.system
    mf = mutants_file(system)
    if mf is None:
        return
    try:
        muts = mutants_mod.load(mf)
    except mutants_mod.MutationError as e:
        pending.mutant_error = str(e)
        return
    for m in muts:
        dest = runner.cache / "mutant-models" / system.name / m.name
        try:
            tla = mutants_mod.materialise(m, system.model.parent, dest)
        except mutants_mod.MutationError as e:
            pending.mutant_error = str(e)
            continue
        # --engine auto: the native core where it accepts the model (the same verdict, counts
        # and trace as the Python engine: test_checker_native_engine.py), Python elsewhere.
        step = runner.submit(f"{system.name}-mutant-{m.name}",
                             safestate_argv("check", str(tla), "--json", "--engine", "auto",
                                            "--itf", "{out}/trace.itf.json"),
                             [*files_under([dest], (".tla", ".cfg")), *tool_files("check")],
                             outputs=["trace.itf.json"])
        pending.mutants.append((m, step))


def submit_ctest(runner: Runner, root: Path, regex: str | None) -> Future[StepResult]:
    build = root / "build" / "cpp"
    argv = ["ctest", "--test-dir", str(build), "--output-junit", "{out}/ctest.xml", "-j1"]
    if regex:
        argv += ["-R", regex]
    inputs = files_under([root / "include", root / "src", root / "tests" / "cpp"], (".hpp", ".cpp", ".h", ".txt"))
    # The built test executables too: a cached result of an older build is not reused.
    inputs += sorted(f for f in build.rglob("test_*") if f.is_file() and os.access(f, os.X_OK))
    return runner.submit("ctest", argv, inputs, outputs=["ctest.xml"])


def submit_coverage(runner: Runner, root: Path, flagship: System, build: Path) -> Future[StepResult]:
    """gcovr branch coverage of src/ under the flagship's conformance replay
    (conform/coverage.sh builds the coverage variant in `build`); keyed, like every step,
    by what decides it: the C++ and its binding, the flagship's model, cfgs and adapter,
    the conformance tool and the coverage build's own scripts."""
    argv = ["bash", "conform/coverage.sh", str(build), "--report", "{out}"]
    inputs = [*files_under([root / "include", root / "src", root / "bindings", root / "conform" / "coverage.sh",
                            root / "conform" / "wrong_variant"], (".hpp", ".cpp", ".h", ".txt", ".sh", ".def")),
              *model_files(flagship.model), *flagship.configs, flagship.manifest, *tool_files("conform")]
    if flagship.conformance:
        inputs.append(flagship.conformance.adapter)
    return runner.submit("coverage", argv, inputs, outputs=["index.html", "summary.json"])


def submit_pytest(runner: Runner, root: Path, node_ids: list[str]) -> Future[StepResult] | None:
    if not node_ids:
        return None
    argv = [*safestate_argv()[:2], "pytest", "-q", "-p", "no:cacheprovider", "--junitxml", "{out}/pytest.xml",
            *node_ids]
    inputs = [*files_under([root / "tests" / "python"], (".py",)), *files_under([PKG], (".py",))]
    inputs = [f for f in inputs if "evidence" not in f.parts]
    # the long proofs too (the press's: ~2 min CPU, left out of the default test run)
    return runner.submit("pytest", argv, inputs, outputs=["pytest.xml"], env={SLOW_PROOFS: "1"}, timeout=3600)


SLOW_PROOFS = "SAFESTATE_SLOW_PROOFS"  # set: tests/python/test_prove_press.py runs
