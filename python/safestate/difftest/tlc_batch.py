"""TLC on many specs from one JVM: `TlcBatch.java` (beside this file) is compiled
at run time into a temporary folder and fed one job per line; each spec runs in a
fresh class loader.  Without a jar nothing here is used."""

from __future__ import annotations

import os
import select
import shutil
import subprocess
import tempfile
from pathlib import Path

from ..checker.tlc import TlcSummary, parse_tlc_output

SOURCE = Path(__file__).with_name("TlcBatch.java")
# A JVM serves this many specs, then is replaced (each class loader leaves some garbage).
SPECS_PER_JVM = 300


class TlcBatch:
    def __init__(self, jar: str, timeout: float = 120) -> None:
        if shutil.which("java") is None or shutil.which("javac") is None:
            raise RuntimeError("java and javac must be on PATH to run TLC")
        self.jar = os.path.abspath(jar)
        self.timeout = timeout
        self.tmp = tempfile.mkdtemp(prefix="difftest-tlc-")
        p = subprocess.run(["javac", "-nowarn", "-d", self.tmp, str(SOURCE)], capture_output=True, text=True)
        if p.returncode != 0:
            raise RuntimeError(f"cannot compile {SOURCE.name}: {p.stderr.strip()}")
        self.proc: subprocess.Popen | None = None
        self.served = 0
        self.jobs = 0

    def _start(self) -> subprocess.Popen:
        # C1 only: each spec loads TLC's classes afresh, so the C2 compiler rarely pays off.
        cmd = ["java", "-XX:+UseSerialGC", "-XX:TieredStopAtLevel=1", "-Djava.security.manager=allow",
               "-cp", self.tmp, "TlcBatch", self.jar, str(int(self.timeout))]
        self.served = 0
        return subprocess.Popen(cmd, stdin=subprocess.PIPE, stdout=subprocess.PIPE, stderr=subprocess.DEVNULL,
                                text=True, bufsize=1)

    def run(self, tla_path: str, cfg_path: str) -> tuple[TlcSummary, str]:
        """TLC's summary and full output for one spec."""
        if self.proc is None or self.proc.poll() is not None or self.served >= SPECS_PER_JVM:
            self.close_jvm()
            self.proc = self._start()
        self.jobs += 1
        self.served += 1
        job = str(self.jobs)
        out_file = os.path.join(self.tmp, f"out{job}.txt")
        meta = tempfile.mkdtemp(prefix="meta", dir=self.tmp)
        folder = os.path.dirname(os.path.abspath(tla_path))
        line = "\t".join([job, folder, os.path.basename(tla_path), os.path.abspath(cfg_path), out_file, meta])
        assert self.proc.stdin is not None and self.proc.stdout is not None
        try:
            self.proc.stdin.write(line + "\n")
            self.proc.stdin.flush()
            code = self._await(job)
        finally:
            shutil.rmtree(meta, ignore_errors=True)
        try:
            with open(out_file, encoding="utf-8", errors="replace") as f:
                text = f.read()
            os.unlink(out_file)
        except OSError:
            text = ""
        if code is None:
            self.close_jvm()
            return TlcSummary("timeout", None, None, None, None, -1), text
        return parse_tlc_output(text, code), text

    def _await(self, job: str) -> int | None:
        assert self.proc is not None and self.proc.stdout is not None
        while True:
            ready, _, _ = select.select([self.proc.stdout], [], [], self.timeout + 10)
            if not ready:
                return None
            line = self.proc.stdout.readline()
            if not line:
                return None
            parts = line.split()
            if parts[:2] == ["DONE", job]:
                return int(parts[2])
            if parts[:2] == ["TIMEOUT", job]:
                return None

    def close_jvm(self) -> None:
        if self.proc is not None:
            try:
                self.proc.stdin.close()  # type: ignore[union-attr]
                self.proc.wait(timeout=10)
            except (OSError, subprocess.TimeoutExpired):
                self.proc.kill()
                self.proc.wait()
            self.proc = None

    def close(self) -> None:
        self.close_jvm()
        shutil.rmtree(self.tmp, ignore_errors=True)
