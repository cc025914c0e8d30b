"""`safestate saf client`: the Safety Client simulator as a process. Sends Set Estop every
CYCLEINTERVAL from the configured address and port to the service, in the extension's
form (design §14: its component id, a sequence number started from the wall clock in
microseconds so that a restarted client keeps rising, the HMAC when a key file is
configured). Commands on stdin, one per line: `set` (press), `clear` (release),
`silent` (stop sending: the E-stop times out), `replay HEX` (send these bytes once from
the client's own socket: what a process that forges the client's address could send, for
the tests' replay of a captured datagram), `quit`."""

from __future__ import annotations

import argparse
import socket
import time

from ..errors import UsageError
from . import wire
from .config import load, load_key
from .events import EventLog
from .ticker import Ticker

MODES = ("set", "clear", "silent")


def run(args: argparse.Namespace) -> int:
    cfg = load(args.config)
    key = load_key(cfg)
    log = EventLog("client", args.json)
    sock = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
    try:
        sock.bind((cfg.client.address, cfg.client.port))
    except OSError as e:
        raise UsageError(f"{cfg.path}: [client] {cfg.client.address}:{cfg.client.port}: {e.strerror or e}") from None
    sock.setblocking(False)
    target = (cfg.service.address, cfg.service.port)
    sequence = time.time_ns() // 1000
    last_sent: float | None = None
    mode = args.mode
    announce = True  # log the first datagram of each mode (the press time of the latency)
    quit_requested = False

    def command(line: str) -> None:
        nonlocal mode, announce, quit_requested
        word = line.lower()
        if word.startswith("replay "):
            try:
                raw = bytes.fromhex(word.split(None, 1)[1])
                sock.sendto(raw, target)
                log.emit("replayed", f"{len(raw)} bytes sent once", datagram=raw.hex())
            except (ValueError, OSError) as e:
                log.emit("error", f"replay: {e}", command=line)
        elif word == "quit":
            quit_requested = True
        elif word in MODES:
            if word != mode:
                mode, announce = word, True
        elif word:
            log.emit("error", f"unknown command {line!r} (one of {', '.join(MODES)}, replay HEX, quit)",
                     command=line)

    ticker = Ticker(cfg.parameters["CYCLEINTERVAL"])
    log.emit("started", f"{cfg.client.address}:{cfg.client.port} -> {target[0]}:{target[1]}, mode {mode}",
             mode=mode, port=cfg.client.port)
    while ticker.running and not quit_requested:
        if mode != "silent":
            sequence += 1
            datagram = wire.set_estop(mode == "set", cfg.client.component_id, sequence, key)
            try:
                sock.sendto(datagram, target)
                last_sent = time.monotonic()
            except OSError as e:  # the service is not there (ICMP): keep sending, as a real client
                log.emit("send-failed", str(e.strerror or e))
            if announce:
                log.emit("mode", f"{mode.upper()} (sequence {sequence})", mode=mode, sequence=sequence,
                         datagram=datagram.hex())
                announce = False
        elif announce:
            # the time of the last datagram sent: a late cycle must not skew a timeout measured from it
            log.emit("mode", "SILENT (no more Set Estop)", mode=mode, last_sequence=sequence,
                     last_sent=None if last_sent is None else round(last_sent, 6))
            announce = False
        ticker.wait(command)
    log.emit("stopped", f"last sequence {sequence}", last_sequence=sequence)
    return 0
