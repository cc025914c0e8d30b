"""One line per event on stdout for the three processes: text for a person, or with
--json one JSON object per line with the monotonic time `t` (CLOCK_MONOTONIC, the same
clock in every process of the host, so the three logs can be compared)."""

from __future__ import annotations

import json
import sys
import threading
import time
from typing import Any


class EventLog:
    def __init__(self, who: str, as_json: bool) -> None:
        self.who, self.as_json = who, as_json
        self.lock = threading.Lock()  # whole lines from the service's writer thread too

    def emit(self, event: str, text: str, **fields: Any) -> None:
        t = time.monotonic()
        if self.as_json:
            line = json.dumps({"t": round(t, 6), "who": self.who, "event": event, **fields}, sort_keys=True)
        else:
            stamp = time.strftime("%Y-%m-%dT%H:%M:%S", time.gmtime()) + f".{int(time.time() * 1000) % 1000:03d}Z"
            line = f"{stamp} {self.who} {event}: {text}"
        with self.lock:
            try:
                sys.stdout.write(line + "\n")
                sys.stdout.flush()
            except BrokenPipeError:
                pass
