"""`safestate saf serve`: the Safety service as a process. The C++ ServiceHost (sockets,
intake, core) runs one scan cycle per CYCLEINTERVAL; this loop logs every state change
and every rejected datagram (one line each) and stops cleanly on SIGTERM or SIGINT,
printing its counters. A stopped service holds the subsystem in nothing: the subsystem
notices the silence (design §14) and goes to EMERGENCY. With `[security] sequence_file`
the replay state (the highest accepted Set Estop and subsystem sequences, our own next
link sequence) is read at start and stored whenever it moved, by a writer thread outside
the scan cycle (its fsyncs take milliseconds), and once more at a clean stop (design §15):
a datagram captured before a restart is stale after it."""

from __future__ import annotations

import argparse
import threading
import time
from pathlib import Path
from typing import Any

from ..errors import UsageError
from .config import SafConfig, load, load_key
from .events import EventLog
from .ticker import Ticker


Sequences = dict[str, int | None]


def load_sequences(path: Path) -> Sequences | None:
    """The sequence file's state, None when it does not exist (the first start); a file
    that exists but is not exactly a sequence file stops the service (exit 2): never a
    silent reset of the replay window."""
    from .._saf_net import load_sequence_file  # type: ignore[import-not-found]

    try:
        state: Sequences | None = load_sequence_file(str(path))
    except ValueError as e:
        raise UsageError(f"{e} (delete the file to start with an empty replay window)") from None
    return state


def store_sequences(path: Path, state: Sequences) -> None:
    from .._saf_net import store_sequence_file  # type: ignore[import-not-found]

    store_sequence_file(str(path), state["estop"], state["subsystem"], state["service"])


class SequenceWriter:
    """Stores the latest posted replay state in its own thread: the scan cycle only posts
    (a dict), the thread writes whatever is newest when it is done with the previous one.
    A failing store is logged once, retried with the next state, and never stops the
    service (its window across a restart is then the last stored one)."""

    def __init__(self, path: Path, log: EventLog) -> None:
        self.path, self.log = path, log
        self.cond = threading.Condition()
        self.pending: Sequences | None = None
        self.stopping = False
        self.failing = False
        self.thread = threading.Thread(target=self._run, name="sequence-writer", daemon=True)
        self.thread.start()

    def post(self, state: Sequences) -> None:
        with self.cond:
            self.pending = state
            self.cond.notify()

    def store(self, state: Sequences) -> bool:
        try:
            store_sequences(self.path, state)
        except ValueError as e:
            if not self.failing:
                self.failing = True
                self.log.emit("sequence-store-failed", str(e), file=str(self.path))
            return False
        if self.failing:
            self.failing = False
            self.log.emit("sequences", f"stored again in {self.path}", file=str(self.path), restored=False)
        return True

    def _run(self) -> None:
        while True:
            with self.cond:
                while self.pending is None and not self.stopping:
                    self.cond.wait()
                if self.pending is None:
                    return
                state, self.pending = self.pending, None
            self.store(state)

    def close(self, final: Sequences) -> None:
        """Stops the thread and stores `final` (a clean stop leaves the exact state)."""
        with self.cond:
            self.stopping = True
            self.pending = None
            self.cond.notify()
        self.thread.join()
        self.store(final)


def make_host(cfg: SafConfig) -> Any:
    from .._saf_net import ServiceHost, validate_parameters  # type: ignore[import-not-found]

    verdict = validate_parameters(cfg.binding_parameters())
    if verdict != "NONE":
        raise UsageError(f"{cfg.path}: [parameters]: {verdict} (each time > 0 and at most 65,535 cycles)")
    host = ServiceHost(
        address=cfg.service.address,
        client_port=cfg.service.port,
        subsystem_port=cfg.service_subsystem_port,
        component_id=cfg.service.component_id,
        client_address=cfg.client.address,
        client_peer_port=cfg.client.port,
        client_component_id=cfg.client.component_id,
        subsystem_address=cfg.subsystem.address,
        subsystem_peer_port=cfg.subsystem.port,
        parameters=cfg.binding_parameters(),
        require_sequence=cfg.require_sequence,
        replay_window=cfg.replay_window,
        key=load_key(cfg),
        # Our sealed messages to the subsystem start above anything sent before a restart
        # (the stored next sequence, restored below, can only raise it).
        link_sequence_start=time.time_ns() // 1000,
    )
    try:
        host.open()
    except ValueError as e:
        raise UsageError(
            f"{cfg.path}: [service] {cfg.service.address} ports {cfg.service.port}/{cfg.service_subsystem_port}: {e}"
        ) from None
    return host


def run(args: argparse.Namespace) -> int:
    cfg = load(args.config)
    stored = load_sequences(cfg.sequence_file) if cfg.sequence_file else None
    host = make_host(cfg)
    log = EventLog("service", args.json)
    writer: SequenceWriter | None = None
    if cfg.sequence_file is not None:
        if stored is not None:
            host.restore(stored["estop"], stored["subsystem"], stored["service"])
            log.emit("sequences", f"restored from {cfg.sequence_file}: Set Estop above {stored['estop']}, "
                     f"subsystem above {stored['subsystem']}", file=str(cfg.sequence_file), restored=True,
                     **stored)
        else:
            log.emit("sequences", f"{cfg.sequence_file} does not exist: first start, created",
                     file=str(cfg.sequence_file), restored=False)
        stored = host.sequences()
        try:  # at once: a folder the service cannot write is a startup error, not a later surprise
            store_sequences(cfg.sequence_file, stored)
        except ValueError as e:
            raise UsageError(str(e)) from None
        writer = SequenceWriter(cfg.sequence_file, log)

    # SIGTERM/SIGINT handlers before "started": a supervisor that stops the service as
    # soon as it reports itself started must get the clean stop and its counters.
    ticker = Ticker(cfg.parameters["CYCLEINTERVAL"])
    auth = "HMAC-SHA256" if cfg.key_file else ("sequence" if cfg.require_sequence else "none")
    log.emit(
        "started",
        f"client port {host.client_port}, subsystem socket {host.subsystem_port} -> "
        f"{cfg.subsystem.address}:{cfg.subsystem.port}, Set Estop accepted from "
        f"{cfg.client.address}:{cfg.client.port} id {cfg.client.component_id:#010x}, freshness {auth}",
        client_port=host.client_port, subsystem_port=host.subsystem_port, state=host.state, freshness=auth,
    )
    cycles = args.cycles
    while ticker.running and (cycles is None or ticker.cycle < cycles):
        c = host.step()
        if c["before"] != c["after"]:
            log.emit("state", f"{c['before']} -> {c['after']} (row {c['state_row']})",
                     before=c["before"], after=c["after"], row=c["state_row"], sent=c["sent"])
        for r in c["rejected"]:
            what = f" {r['message']}" if r["message"] else ""
            log.emit("rejected", f"{r['reason']}{what} from {r['source']} on the {r['socket']} socket", **r)
        if c["kernel_dropped"]:
            log.emit("dropped", f"the kernel dropped {c['kernel_dropped']} datagrams (receive buffer full)",
                     count=c["kernel_dropped"])
        if writer is not None:
            now = host.sequences()
            if now != stored:
                writer.post(now)
                stored = now
        ticker.wait()
    if writer is not None:
        writer.close(host.sequences())
    counters = host.counters()
    rejected = {k: v for k, v in counters["rejected"].items() if v}
    log.emit("stopped", f"state {host.state}, {counters['cycles']} cycles ({ticker.late} late), "
             f"accepted {counters['accepted']}, rejected {rejected or 'none'}, "
             f"kernel drops {counters['kernel_dropped']}",
             state=host.state, late_cycles=ticker.late, **counters)
    return 0
