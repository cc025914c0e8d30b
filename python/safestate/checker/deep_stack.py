"""Run the search on a thread with a large stack and a high recursion limit.

Recursive TLA+ operators and functions recurse in Python too (several frames per
level); with Python's default limit of 1000 frames a recursion TLC handles easily
(depth 500) failed.  A recursion too deep even for this limit (TLC's
StackOverflowError) becomes an evaluation error, never a Python traceback.
"""

from __future__ import annotations

import sys
import ctypes
import threading
from typing import Callable, TypeVar

T = TypeVar("T")

RECURSION_LIMIT = 120_000
STACK_BYTES = 512 * 1024 * 1024  # reserved address space; only the pages used are allocated


def stack_overflow_message(doing: str) -> str:
    """TLC's StackOverflowError, in one line."""
    return (f"recursion too deep while {doing} (TLC: StackOverflowError): a recursive operator or "
            f"function probably does not terminate")


def _stop_thread(t: threading.Thread, done: threading.Event, exc: type[BaseException]) -> None:
    """Raise `exc` in thread `t` and wait for it to end, so that its `finally` blocks
    run (the parallel search removes its shared memory and stops its workers) before
    the process exits.  The exception arrives when `t` next runs Python code.  (An
    Event, not `t.is_alive()`: after an interrupted `join` Python 3.11 may report the
    thread dead while it runs.)"""
    tid = t.ident
    if tid is None:
        return
    ctypes.pythonapi.PyThreadState_SetAsyncExc(ctypes.c_ulong(tid), ctypes.py_object(exc))
    while not done.is_set():
        try:
            done.wait()
        except BaseException:  # noqa: BLE001 - a second Ctrl-C: keep waiting for the cleanup
            continue


def call_with_deep_stack(fn: Callable[[], T]) -> T:
    if threading.current_thread() is not threading.main_thread():
        return fn()
    box: list = []

    done = threading.Event()

    def run() -> None:
        try:
            box.append((True, fn()))
        except BaseException as e:  # noqa: BLE001 - re-raised in the caller's thread
            box.append((False, e))
        finally:
            done.set()
    old_limit, old_size = sys.getrecursionlimit(), threading.stack_size()
    sys.setrecursionlimit(max(old_limit, RECURSION_LIMIT))
    threading.stack_size(STACK_BYTES)
    try:
        t = threading.Thread(target=run, name="safestate-search")
        t.start()
    finally:
        threading.stack_size(old_size)
    try:
        done.wait()
        t.join()
    except BaseException as stop:  # Ctrl-C or SIGTERM reach this (the main) thread only
        _stop_thread(t, done, type(stop))
        raise
    finally:
        sys.setrecursionlimit(old_limit)
    ok, value = box[0]
    if not ok:
        raise value
    return value
