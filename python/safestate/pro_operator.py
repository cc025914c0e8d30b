"""The operator of `safestate demo protection`: a Modbus TCP client in its own process
(pymodbus) against the demo's ao_modbus_server (docs/design/protection.md, "Modbus
register map").

It first writes the latch clear coil without the write-enable handshake (refused with
exception 01), then polls the input registers and, whenever the controller is in RUN and
latched in PROTECTION, asks for a clear the way the server demands it: coil 1 := 1 (the
write enable), then coil 0 := 1. It prints each new clear outcome and ends when the server
has gone (the controlled shutdown stops the communications unit).

    python -m safestate.pro_operator --port N [--period S] [--deadline S]
exit codes: 0 the server went away after the operator was served; 1 never served;
2 usage error or pymodbus missing."""

from __future__ import annotations

import argparse
import sys
import time
from typing import Any

UNIT = 1
OUTCOMES = {0: "none", 1: "accepted", 2: "denied (LATCH_BLOCKED)", 3: "refused (not RUN)"}
PROTECTION, RUN = 1, 1


def say(text: str) -> None:
    print(f"   operator (Modbus client): {text}", flush=True)


def connect(client_class: Any, port: int, timeout_s: float) -> Any | None:
    """A connected client, or None once `timeout_s` passed without a server."""
    end = time.monotonic() + timeout_s
    while True:
        client = client_class("127.0.0.1", port=port, timeout=2, retries=0)
        if client.connect():
            return client
        client.close()
        if time.monotonic() >= end:
            return None
        time.sleep(0.05)


def session(client: Any, period: float, last: list[int]) -> None:
    """Poll and clear until the connection fails (raises)."""
    while True:
        regs = client.read_input_registers(0, count=6, device_id=UNIT)
        if regs.isError():
            raise OSError(f"read refused: {regs}")
        protection, supervisor, outcome = regs.registers[3], regs.registers[4], regs.registers[5]
        if outcome != last[0]:
            say(f"last clear result: {OUTCOMES.get(outcome, outcome)}")
            last[0] = outcome
        if protection == PROTECTION and supervisor == RUN:
            arm = client.write_coil(1, True, device_id=UNIT)
            if not arm.isError():
                client.write_coil(0, True, device_id=UNIT)
        time.sleep(period)


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(prog="python -m safestate.pro_operator", description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--port", type=int, required=True, help="the server's port on 127.0.0.1")
    parser.add_argument("--period", type=float, default=0.02, help="seconds between polls (default 0.02)")
    parser.add_argument("--deadline", type=float, default=300.0, help="give up after this many seconds")
    args = parser.parse_args(argv)
    try:
        from pymodbus.client import ModbusTcpClient
        from pymodbus.exceptions import ModbusException
    except ImportError:
        print("pro_operator: pymodbus is not installed (pip install pymodbus)", file=sys.stderr)
        return 2
    client = connect(ModbusTcpClient, args.port, 10.0)
    if client is None:
        print(f"pro_operator: no server on 127.0.0.1:{args.port}", file=sys.stderr)
        return 1
    refused = client.write_coil(0, True, device_id=UNIT)
    code = getattr(refused, "exception_code", None) if refused.isError() else None
    say(f"coil 0 without the write enable: {'exception %02X' % code if code is not None else 'accepted?!'}")
    last = [-1]
    served = False
    end = time.monotonic() + args.deadline
    while time.monotonic() < end:
        try:
            session(client, args.period, last)
        except (ModbusException, OSError):
            served = served or last[0] >= 0
            client.close()
            # Degraded (the server is not dispatched: no reply) or gone (shut down).
            client = connect(ModbusTcpClient, args.port, 1.0)
            if client is None:
                say("the server has stopped (controlled shutdown)")
                return 0 if served else 1
    return 1


if __name__ == "__main__":
    sys.exit(main())
