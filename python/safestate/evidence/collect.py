"""Running the evidence steps (check, prove, conform, mutants, C++ and Python tests) as
subprocesses, each cached under a key that hashes the step's command and every input
file it reads: `--reuse` takes a cached result whose inputs are unchanged, so a package
is rebuilt in seconds when nothing changed, and a changed model reruns its steps only."""

from __future__ import annotations

import hashlib
import json
import os
import shutil
import subprocess
import sys
import time
from collections.abc import Callable, Iterable
from concurrent.futures import Future, ThreadPoolExecutor
from dataclasses import dataclass, field
from pathlib import Path


@dataclass
class StepResult:
    name: str
    argv: list[str]
    returncode: int
    stdout: str
    stderr: str
    seconds: float
    cached: bool
    key: str
    files: dict[str, Path] = field(default_factory=dict)   # output name -> file in the cache

    def json(self) -> object | None:
        """stdout parsed as JSON (the last JSON line), or None."""
        for line in reversed(self.stdout.strip().splitlines()):
            if line.startswith("{"):
                try:
                    return json.loads(line)
                except json.JSONDecodeError:
                    break
        try:
            return json.loads(self.stdout)
        except json.JSONDecodeError:
            return None


def sha256_file(path: Path) -> str:
    h = hashlib.sha256()
    with open(path, "rb") as f:
        for chunk in iter(lambda: f.read(1 << 20), b""):
            h.update(chunk)
    return h.hexdigest()


def files_under(paths: Iterable[Path], suffixes: tuple[str, ...] = ()) -> list[Path]:
    """Every file of `paths` (folders walked), sorted; only `suffixes` when given."""
    out: set[Path] = set()
    for p in paths:
        if p.is_dir():
            out.update(f for f in p.rglob("*") if f.is_file() and "__pycache__" not in f.parts
                       and (not suffixes or f.suffix in suffixes))
        elif p.is_file():
            out.add(p)
    return sorted(out)


def input_key(argv: list[str], inputs: Iterable[Path], root: Path) -> str:
    h = hashlib.sha256()
    h.update("\0".join(argv).encode())
    for f in sorted(set(inputs)):
        h.update(b"\0" + str(f.resolve()).replace(str(root.resolve()), "").encode() + b"\0")
        h.update(sha256_file(f).encode() if f.is_file() else b"missing")
    return h.hexdigest()[:24]


class Runner:
    """Runs steps in `root`, caching each under `cache/<name>-<key>/`, up to `jobs` at
    once: the steps are independent subprocesses, each single-threaded, so on a machine
    with two cores two of them run side by side."""

    def __init__(self, root: Path, cache: Path, reuse: bool, log: Callable[[str], None], jobs: int = 1) -> None:
        self.root, self.cache, self.reuse, self.log = root, cache, reuse, log
        self.pool = ThreadPoolExecutor(max_workers=max(1, jobs), thread_name_prefix="evidence-step")

    def close(self) -> None:
        self.pool.shutdown(wait=True, cancel_futures=True)

    def submit(self, name: str, argv: list[str], inputs: Iterable[Path], outputs: Iterable[str] = (),
               env: dict[str, str] | None = None, timeout: float | None = None) -> Future[StepResult]:
        """The step, queued to run when a job slot is free.  Its input key is taken now,
        so a file changed while the step waits is not silently taken as the input."""
        key = input_key(argv, inputs, self.root)
        return self.pool.submit(self._run, name, argv, key, list(outputs), env, timeout)

    def run(self, name: str, argv: list[str], inputs: Iterable[Path], outputs: Iterable[str] = (),
            env: dict[str, str] | None = None, timeout: float | None = None) -> StepResult:
        """`argv` may contain `{out}`: the step's output folder; `outputs` are the file names
        the step writes there (kept in the cache with the result)."""
        return self.submit(name, argv, inputs, outputs, env, timeout).result()

    def _run(self, name: str, argv: list[str], key: str, outputs: list[str], env: dict[str, str] | None,
             timeout: float | None) -> StepResult:
        folder = self.cache / f"{name}-{key}"
        meta = folder / "result.json"
        if self.reuse and meta.is_file():
            d = json.loads(meta.read_text(encoding="utf-8"))
            files = {n: folder / n for n in d["files"] if (folder / n).is_file()}
            self.log(f"evidence: {name}: cached result (inputs unchanged, key {key})")
            return StepResult(name, d["argv"], d["returncode"], d["stdout"], d["stderr"], d["seconds"], True, key, files)
        if folder.exists():
            shutil.rmtree(folder)
        folder.mkdir(parents=True)
        real = [a.replace("{out}", str(folder)) for a in argv]
        self.log(f"evidence: {name}: {' '.join(os.path.basename(real[0]) if i == 0 else a for i, a in enumerate(real))}")
        t0 = time.monotonic()
        try:
            p = subprocess.run(real, cwd=self.root, capture_output=True, text=True, timeout=timeout,
                               env={**os.environ, **(env or {})})
            rc, out, err = p.returncode, p.stdout, p.stderr
        except subprocess.TimeoutExpired as e:
            rc, out, err = 124, _text(e.stdout), _text(e.stderr) + f"\ntimed out after {timeout} s"
        seconds = round(time.monotonic() - t0, 3)
        files = {n: folder / n for n in outputs if (folder / n).is_file()}
        meta.write_text(json.dumps({"argv": argv, "returncode": rc, "stdout": out, "stderr": err, "seconds": seconds,
                                    "files": sorted(files)}, indent=1), encoding="utf-8")
        return StepResult(name, argv, rc, out, err, seconds, False, key, files)


def _text(b: bytes | str | None) -> str:
    if b is None:
        return ""
    return b if isinstance(b, str) else b.decode(errors="replace")


def safestate_argv(*args: str) -> list[str]:
    """The safestate CLI of this interpreter (the .venv's)."""
    return [sys.executable, "-m", "safestate.cli", *args]
