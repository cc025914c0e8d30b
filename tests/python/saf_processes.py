"""The three processes of `safestate saf` (serve, client, subsystem) for the tests: one
configuration with free ports, each process's JSON event lines collected by a thread,
waiting for an event with a deadline (the deadlines only bound a hang; no test passes or
fails on a time)."""

from __future__ import annotations

import json
import os
import signal
import socket
import subprocess
import sys
import threading
import time
from collections.abc import Callable
from pathlib import Path
from typing import Any

Event = dict[str, Any]

CLIENT_ID = 0x00010300
SERVICE_ID = 0x00010203
KEY_HEX = "8f2d4c1a9b7e3f5061d2c4b8a7e9f0132435465768798a9bacbdcedfe0f10213"


def free_ports(n: int) -> list[int]:
    socks = [socket.socket(socket.AF_INET, socket.SOCK_DGRAM) for _ in range(n)]
    for s in socks:
        s.bind(("127.0.0.1", 0))
    ports = [s.getsockname()[1] for s in socks]
    for s in socks:
        s.close()
    return ports


def write_config(folder: Path, *, key: bool = True, service_timeout: float = 1.0, sequence_file: bool = False,
                 replay_window: int = 64) -> tuple[Path, dict[str, int]]:
    names = ["service", "service_subsystem", "client", "subsystem"]
    ports = dict(zip(names, free_ports(len(names))))
    key_line = ""
    if key:
        key_path = folder / "saf.key"
        key_path.write_text(KEY_HEX + "\n", encoding="utf-8")
        key_path.chmod(0o600)
        key_line = 'key_file = "saf.key"'
    if sequence_file:
        key_line += '\nsequence_file = "saf.seq"'
    text = f"""\
[service]
address = "127.0.0.1"
client_port = {ports['service']}
subsystem_port = {ports['service_subsystem']}
component_id = {SERVICE_ID:#010x}

[client]
address = "127.0.0.1"
port = {ports['client']}
component_id = {CLIENT_ID:#010x}

[subsystem]
address = "127.0.0.1"
port = {ports['subsystem']}
service_timeout = {service_timeout}

[parameters]
CYCLEINTERVAL = 0.05
ESTOPTIMEOUT = 0.1
REPORTDATATIMEOUT = 2.0
MESSAGEINTERVAL = 0.5
CHECKINTERVAL = 1.0
AUTHORITYCODE = 225

[security]
require_sequence = true
replay_window = {replay_window}
{key_line}
"""
    path = folder / "saf.toml"
    path.write_text(text, encoding="utf-8")
    return path, ports


class Process:
    """One `safestate saf ROLE --json` process and its events."""

    def __init__(self, role: str, config: Path, *extra: str) -> None:
        self.role = role
        self.proc = subprocess.Popen(
            [sys.executable, "-m", "safestate.cli", "saf", role, "--config", str(config), "--json", *extra],
            stdin=subprocess.PIPE, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
            env={**os.environ, "PYTHONUNBUFFERED": "1"},
        )
        self.events: list[Event] = []
        self.lock = threading.Lock()
        self.reader = threading.Thread(target=self._read, daemon=True)
        self.reader.start()

    def _read(self) -> None:
        assert self.proc.stdout is not None
        for line in self.proc.stdout:
            try:
                e = json.loads(line)
            except json.JSONDecodeError:
                e = {"event": "unparsed", "line": line, "t": time.monotonic()}
            with self.lock:
                self.events.append(e)

    def send(self, command: str) -> None:
        assert self.proc.stdin is not None
        self.proc.stdin.write(command + "\n")
        self.proc.stdin.flush()

    def snapshot(self) -> list[Event]:
        with self.lock:
            return list(self.events)

    def wait_for(self, pred: Callable[[Event], bool], after: float = 0.0, deadline_s: float = 10.0) -> Event:
        end = time.monotonic() + deadline_s
        while time.monotonic() < end:
            for e in self.snapshot():
                if e.get("t", 0.0) >= after and pred(e):
                    return e
            if self.proc.poll() is not None and not self.reader.is_alive():
                break
            time.sleep(0.01)
        err = self.proc.stderr.read() if self.proc.poll() is not None and self.proc.stderr else ""
        raise AssertionError(f"{self.role}: no such event (exit {self.proc.poll()}, stderr {err!r}); "
                             f"last events: {self.snapshot()[-5:]}")

    def state_events(self, after: float, before: float = float("inf")) -> list[Event]:
        return [e for e in self.snapshot() if e.get("event") == "state" and after <= e["t"] <= before]

    def stop(self, sig: int = signal.SIGTERM) -> int:
        if self.proc.poll() is None:
            self.proc.send_signal(sig)
        try:
            rc = self.proc.wait(timeout=10)
        except subprocess.TimeoutExpired:
            self.proc.kill()
            rc = self.proc.wait()
        self.reader.join(timeout=5)
        return rc
