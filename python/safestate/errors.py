"""The one base class of every error the safestate package reports to a user.

Subcommands catch `SafestateError` (and the checker's own located errors) and print
one line with the documented exit code (`safestate --help`), never a traceback.
"""

from __future__ import annotations

import argparse
import json
import os
import sys
from collections.abc import Callable


class SafestateError(Exception):
    """An error with a message fit for one line of output (file:line:col when known)."""


class UsageError(SafestateError):
    """A bad argument or an unusable input file (exit code 2)."""


def check_writable_file(path: str, option: str) -> None:
    """Fail before any work when the output file `path` (of `option`) cannot be written:
    opened for appending (and removed again if this created it), so the search that
    would fill it is not run in vain."""
    if os.path.isdir(path):
        raise UsageError(f"{path}: {option} must be a file, this is a directory")
    existed = os.path.exists(path)
    try:
        with open(path, "a", encoding="utf-8"):
            pass
    except OSError as e:
        raise UsageError(f"{path}: {option} file is not writable ({e.strerror or e})") from None
    if not existed:
        os.remove(path)


def one_line(e: BaseException) -> str:
    """The message of `e` on one line, located when it carries a location."""
    loc = getattr(e, "loc", None)
    msg = getattr(e, "message", None) or str(e) or type(e).__name__
    text = f"{loc}: {msg}" if loc else msg
    return " ".join(text.split())


def whole_number(minimum: int) -> Callable[[str], int]:
    """An argparse type: a whole number of at least `minimum` (a usage error, exit 2,
    otherwise)."""
    def parse(text: str) -> int:
        try:
            n = int(text)
        except ValueError:
            raise argparse.ArgumentTypeError(f"expected a whole number, not {text!r}") from None
        if n < minimum:
            raise argparse.ArgumentTypeError(f"must be at least {minimum}, not {n}")
        return n
    return parse


SIGPIPE_EXIT = 128 + 13  # what a shell reports for a process ended by SIGPIPE


def closed_stdout_exit() -> int:
    """The reader of our output went away (``safestate check X | head -1``): stop quietly
    like a Unix tool.  stdout is pointed at /dev/null so that the interpreter's final
    flush of the buffered rest cannot raise again."""
    devnull = os.open(os.devnull, os.O_WRONLY)
    os.dup2(devnull, sys.stdout.fileno())
    os.close(devnull)
    return SIGPIPE_EXIT


def run_guarded(fn: Callable[[], int], what: str, usage_code: int) -> int:
    """Run a subcommand body; a user's error becomes one line on stderr and
    `usage_code`, an internal error one line naming it -- never a traceback."""
    from .tla.errors import TlaError

    try:
        return fn()
    except KeyboardInterrupt:
        print("interrupted", file=sys.stderr)
        return 130
    except BrokenPipeError:
        return closed_stdout_exit()
    except (SafestateError, TlaError) as e:
        print(f"error: {one_line(e)}", file=sys.stderr)
        return usage_code
    except json.JSONDecodeError as e:
        print(f"error: {what}: malformed JSON at line {e.lineno} column {e.colno}: {e.msg}", file=sys.stderr)
        return usage_code
    except OSError as e:
        print(f"error: {e.filename or what}: {e.strerror or e}", file=sys.stderr)
        return usage_code
    except Exception as e:  # noqa: BLE001 - the boundary: never a traceback
        print(f"error: internal error ({type(e).__name__}: {one_line(e)}) while processing {what}; "
              f"please report it", file=sys.stderr)
        return usage_code
