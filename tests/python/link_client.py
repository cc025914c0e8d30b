"""A test client of the operator link (docs/operator-link-schema.json), over websocket-client.

Every frame the bridge sends is validated against the schema as it arrives.
"""

from __future__ import annotations

import json
import socket
import time
from pathlib import Path
from typing import Any, Callable

import jsonschema
import websocket

SCHEMA = json.loads((Path(__file__).resolve().parents[2] / "docs" / "operator-link-schema.json").read_text())
VALIDATOR = jsonschema.Draft202012Validator(SCHEMA)

Message = dict[str, Any]


class LinkClient:
    def __init__(self, ws_url: str, timeout: float = 10.0, receive_buffer: int | None = None) -> None:
        """`receive_buffer`: a fixed socket receive buffer in bytes (the kernel's automatic
        sizing off), for a client that must not read and see the bridge's backlog grow."""
        self.timeout = timeout
        opts = ((socket.SOL_SOCKET, socket.SO_RCVBUF, receive_buffer),) if receive_buffer else ()
        self.ws = websocket.create_connection(ws_url, timeout=timeout, sockopt=opts)
        self.hello = self.next()
        assert self.hello["type"] == "hello"
        self._id = 100

    def next(self) -> Message:
        m: Message = json.loads(self.ws.recv())
        VALIDATOR.validate(m)
        return m

    def until(self, pred: Callable[[Message], bool], timeout: float = 10.0) -> Message:
        end = time.monotonic() + timeout
        while time.monotonic() < end:
            m = self.next()
            if pred(m):
                return m
        raise AssertionError("no matching message from the bridge in time")

    def answer(self, request_id: int, timeout: float = 10.0) -> Message:
        return self.until(lambda m: m.get("id") == request_id, timeout)

    def send(self, msg: Message) -> int:
        self._id += 1
        VALIDATOR.validate(dict(msg, id=self._id))
        self.ws.send(json.dumps(dict(msg, v=1, id=self._id)))
        return self._id

    def request(self, msg: Message) -> Message:
        return self.answer(self.send(msg))

    def claim(self, token: str) -> Message:
        return self.request({"type": "request_control", "token": token})

    def command(self, kind: str, **args: int) -> Message:
        return self.request({"type": "command", "command": kind, **args})

    def plant(self, **switches: Any) -> Message:
        return self.request({"type": "plant", "set": switches})

    def heartbeat(self) -> None:
        self.ws.send(json.dumps({"v": 1, "type": "heartbeat"}))

    def status(self, pred: Callable[[Message], bool] = lambda s: True, timeout: float = 10.0) -> Message:
        """The next status frame whose status satisfies `pred` (its 'status' and 'link' parts merged)."""
        m = self.until(lambda m: m["type"] == "status" and pred(dict(m["status"], link=m["link"])), timeout)
        return dict(m["status"], link=m["link"])

    def latest_status(self) -> Message:
        """The newest status frame: every frame already received is read, the last status kept."""
        latest = self.status()
        self.ws.settimeout(0.005)
        try:
            while True:
                m = json.loads(self.ws.recv())
                if m["type"] == "status":
                    latest = dict(m["status"], link=m["link"])
        except websocket.WebSocketTimeoutException:
            pass
        finally:
            self.ws.settimeout(self.timeout)
        return latest

    def close(self) -> None:
        self.ws.close()
