"""Reading a JSON input file (ITF trace, state graph) with located errors."""

from __future__ import annotations

import json
from typing import Any

from ..errors import UsageError


def load_json(path: str, what: str) -> Any:
    """A JSON input file; a syntax error is a located one-line UsageError."""
    with open(path, encoding="utf-8") as f:
        try:
            return json.load(f)
        except json.JSONDecodeError as e:
            raise UsageError(f"{path}:{e.lineno}:{e.colno}: malformed {what} JSON: {e.msg}") from None
        except RecursionError:
            # json's decoder recurses per bracket: thousands of them are no trace or graph.
            raise UsageError(f"{path}: malformed {what} JSON: nested too deeply (an ITF trace or state graph "
                             f"is a few levels deep)") from None
        except UnicodeDecodeError as e:
            raise UsageError(f"{path}: {what} is not UTF-8 text ({e.reason})") from None
