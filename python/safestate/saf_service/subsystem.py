"""`safestate saf subsystem`: the subsystem simulator as a process: the Subsystem State
service with its access control and the health summary the Safety service queries. It
expects the Safety service's messages (its Query Health Summary every MESSAGEINTERVAL is
the heartbeat): when nothing came from the service's socket for [subsystem]
service_timeout it goes to EMERGENCY on its own (design §14, a dead Safety service must
not leave the subsystem running), and only the control holder's Set Subsystem State
(OPERATIONAL) releases it. With a key file the link is authenticated (design §15): only
the service's sealed, fresh datagrams are handled and count as its heartbeat (a process
that took over the dead service's port is rejected and counted, and the watchdog still
fires); every answer is sealed. Commands on stdin: `health NORMAL|WARNING|ERROR|FATAL`,
`quit`."""

from __future__ import annotations

import argparse
import socket
import time

from ..errors import UsageError
from . import wire
from .config import load, load_key
from .events import EventLog
from .ticker import Ticker


class Subsystem:
    def __init__(self, sock: socket.socket, service: tuple[str, int], timeout_s: float, log: EventLog,
                 key: bytes | None = None, window: int = 64) -> None:
        self.sock, self.service, self.timeout, self.log = sock, service, timeout_s, log
        self.key = key
        self.rx = wire.LinkReceiver(window=window)
        # Started from the wall clock in microseconds: a restarted simulator stays above what
        # the service accepted from it.
        self.sequence = time.time_ns() // 1000
        self.rejected: dict[str, int] = {}
        self.state = "OPERATIONAL"
        self.health = "NORMAL"
        self.holder, self.holder_authority = 0, 0
        self.holder_addr: tuple[str, int] | None = None
        self.last_heard = time.monotonic()  # the grace of one timeout from the start
        self.silent = False

    def set_state(self, new: str, why: str) -> None:
        if new != self.state:
            old, self.state = self.state, new
            self.log.emit("state", f"{old} -> {new} ({why})", before=old, after=new, why=why)

    def reply(self, datagram: bytes, to: tuple[str, int]) -> None:
        if self.key is not None:
            self.sequence += 1
        self.sock.sendto(wire.seal(datagram, self.sequence, wire.TO_SERVICE, self.key), to)

    def reject(self, reason: str, data: bytes, sender: tuple[str, int]) -> None:
        self.rejected[reason] = self.rejected.get(reason, 0) + 1
        claimed = wire.decode_outgoing(data)
        what = f" {claimed.kind}" if claimed else ""
        self.log.emit("rejected", f"{reason}{what} from {sender[0]}:{sender[1]}", reason=reason,
                      message=claimed.kind if claimed else "", source=f"{sender[0]}:{sender[1]}")

    def handle(self, data: bytes, sender: tuple[str, int]) -> None:
        if self.key is not None:
            verdict, opened = wire.open_sealed(data, wire.TO_SUBSYSTEM, self.key, self.rx)
            if verdict != "OK":
                self.reject(verdict, data, sender)
                return
            data = opened
        if sender == self.service:
            self.last_heard = time.monotonic()
            if self.silent:
                self.silent = False
                self.log.emit("service-back", "the Safety service is heard again")
        m = wire.decode_outgoing(data)
        if m is None:
            return
        if m.kind == "REQUEST_CONTROL":
            if m.action == wire.ACTION_RELEASE:
                if self.holder == m.component_id:
                    self.holder, self.holder_authority, self.holder_addr = 0, 0, None
                    self.log.emit("control", f"released by {m.component_id:#010x}", holder=0)
                return
            if self.holder in (0, m.component_id) or m.authority >= self.holder_authority:
                if self.holder != m.component_id:
                    self.log.emit("control", f"granted to {m.component_id:#010x} ({m.authority})",
                                  holder=m.component_id, authority=m.authority)
                self.holder, self.holder_authority, self.holder_addr = m.component_id, m.authority, sender
                self.reply(wire.confirm_control(wire.CONTROL_ACCEPTED), sender)
            else:
                self.reply(wire.confirm_control(wire.INSUFFICIENT_AUTHORITY), sender)
        elif m.kind == "QUERY_CONTROL":
            self.reply(wire.report_control(self.holder, self.holder_authority), sender)
        elif m.kind == "QUERY_HEALTH_SUMMARY":
            self.reply(wire.report_health(self.health), sender)
        elif m.kind == "SET_SUBSYSTEM_STATE":
            if self.holder != 0 and sender == self.holder_addr and m.state in ("OPERATIONAL", "EMERGENCY"):
                self.set_state(m.state, f"Set Subsystem State from {sender[0]}:{sender[1]}")
                self.reply(wire.report_subsystem_state(self.state), sender)

    def receive(self) -> None:
        """Handles every waiting datagram."""
        while True:
            try:
                data, sender = self.sock.recvfrom(256)
            except BlockingIOError:
                break
            except OSError:  # an ICMP error of an earlier send (the service is gone)
                continue
            try:
                self.handle(data, (sender[0], sender[1]))
            except OSError:
                pass  # the answer could not be sent: the service will ask again

    def step(self) -> None:
        """One cycle: what is waiting, then the watchdog of the service."""
        self.receive()
        silence = time.monotonic() - self.last_heard
        if silence > self.timeout and not self.silent:
            self.silent = True
            self.log.emit("service-silent", f"nothing from the Safety service for {silence:.2f} s", silence=silence)
            self.set_state("EMERGENCY", "the Safety service is silent")


def run(args: argparse.Namespace) -> int:
    cfg = load(args.config)
    log = EventLog("subsystem", args.json)
    sock = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
    try:
        sock.bind((cfg.subsystem.address, cfg.subsystem.port))
    except OSError as e:
        raise UsageError(
            f"{cfg.path}: [subsystem] {cfg.subsystem.address}:{cfg.subsystem.port}: {e.strerror or e}"
        ) from None
    sock.setblocking(False)
    sub = Subsystem(sock, (cfg.service.address, cfg.service_subsystem_port), cfg.service_timeout_s, log,
                    key=load_key(cfg), window=cfg.replay_window)
    quit_requested = False

    def command(line: str) -> None:
        nonlocal quit_requested
        words = line.split()
        if words == ["quit"]:
            quit_requested = True
        elif len(words) == 2 and words[0] == "health" and words[1].upper() in wire.HEALTH:
            sub.health = words[1].upper()
            log.emit("health", sub.health, health=sub.health)
        elif words:
            log.emit("error", f"unknown command {line!r} (health NORMAL|WARNING|ERROR|FATAL, quit)", command=line)

    ticker = Ticker(cfg.parameters["CYCLEINTERVAL"])  # the stop signals' handlers before "started"
    link = "HMAC-SHA256" if sub.key is not None else "none"
    log.emit("started", f"{cfg.subsystem.address}:{cfg.subsystem.port}, state {sub.state}, expects the service "
             f"from {sub.service[0]}:{sub.service[1]} at least every {sub.timeout:.2f} s, link authentication "
             f"{link}", state=sub.state, link=link)
    while ticker.running and not quit_requested:
        sub.step()
        ticker.wait(command, sock, sub.receive)
    log.emit("stopped", f"state {sub.state}, rejected {sub.rejected or 'none'}", state=sub.state,
             rejected=sub.rejected)
    return 0
