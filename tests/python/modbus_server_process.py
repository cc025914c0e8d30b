"""pro_modbus_serve (the C++ ao_modbus_server in a tick loop) as a subprocess for the Modbus
tests: started on an ephemeral loopback port, its stdout lines collected by a thread so a test
can wait for `clear request taken at tick N` without blocking the server."""

from __future__ import annotations

import queue
import signal
import subprocess
import threading
import time
from pathlib import Path

REPO = Path(__file__).resolve().parents[2]
SERVE = REPO / "build" / "cpp" / "src" / "pro" / "modbus" / "pro_modbus_serve"


class ModbusServerProcess:
    """A running pro_modbus_serve; `port` is the port it bound on 127.0.0.1."""

    def __init__(self, *options: str) -> None:
        self.proc = subprocess.Popen([str(SERVE), "--port", "0", "--tick-ms", "5", *options],
                                     stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
        self.lines: queue.Queue[str] = queue.Queue()
        self.seen: list[str] = []
        threading.Thread(target=self._read, daemon=True).start()
        first = self.next_line(10.0)
        if first is None or not first.startswith("listening 127.0.0.1:"):
            self.proc.kill()
            raise RuntimeError(f"pro_modbus_serve did not start: {first!r} {self.proc.stderr.read() if self.proc.stderr else ''}")
        self.port = int(first.rsplit(":", 1)[1])

    def _read(self) -> None:
        assert self.proc.stdout is not None
        for line in self.proc.stdout:
            self.lines.put(line.rstrip("\n"))

    def next_line(self, timeout: float) -> str | None:
        """The next stdout line, or None if none came within `timeout` seconds."""
        try:
            line = self.lines.get(timeout=timeout)
        except queue.Empty:
            return None
        self.seen.append(line)
        return line

    def drain(self, settle: float = 0.1) -> list[str]:
        """The lines printed so far (waiting `settle` seconds for late ones)."""
        time.sleep(settle)
        out = []
        while (line := self.next_line(0.0)) is not None:
            out.append(line)
        return out

    def stop(self) -> tuple[int, list[str]]:
        """Controlled shutdown (SIGTERM): the exit code and the remaining stdout lines."""
        if self.proc.poll() is None:
            self.proc.send_signal(signal.SIGTERM)
        code = self.proc.wait(timeout=10)
        return code, self.drain(0.2)
