"""The scan-cycle clock of the processes: the k-th cycle starts at start + k * interval
(no drift), a late cycle is run at once and counted, never skipped; SIGTERM and SIGINT
end the loop after the current cycle."""

from __future__ import annotations

import select
import signal
import socket
import sys
import time
from collections.abc import Callable
from types import FrameType


class Ticker:
    def __init__(self, interval_s: float) -> None:
        self.interval = interval_s
        self.start = time.monotonic()
        self.cycle = 0
        self.late = 0
        self.stop_signal: int | None = None
        for sig in (signal.SIGTERM, signal.SIGINT):
            signal.signal(sig, self._stop)

    def _stop(self, signum: int, _frame: FrameType | None) -> None:
        self.stop_signal = signum

    @property
    def running(self) -> bool:
        return self.stop_signal is None

    def wait(self, on_line: Callable[[str], None] | None = None, sock: socket.socket | None = None,
             on_readable: Callable[[], None] | None = None) -> None:
        """Sleeps until the next cycle; with `on_line`, stdin lines that arrive meanwhile
        are handed to it (the simulators' commands); with `sock`, `on_readable` runs as soon
        as a datagram waits (the subsystem answers on arrival, as a real one would)."""
        self.cycle += 1
        deadline = self.start + self.cycle * self.interval
        while self.running:
            remaining = deadline - time.monotonic()
            if remaining <= 0:
                if remaining < -self.interval:
                    self.late += 1
                return
            watched: list[int] = []
            if on_line is not None:
                watched.append(sys.stdin.fileno())
            if sock is not None and on_readable is not None:
                watched.append(sock.fileno())
            if not watched:
                time.sleep(remaining)
                continue
            try:
                ready, _, _ = select.select(watched, [], [], remaining)
            except InterruptedError:
                continue
            if sock is not None and sock.fileno() in ready and on_readable is not None:
                on_readable()
            if on_line is not None and sys.stdin.fileno() in ready:
                line = sys.stdin.readline()
                if line == "":  # stdin closed: no more commands
                    on_line = None
                    continue
                on_line(line.strip())
