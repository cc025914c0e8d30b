"""Starts `safestate_link` (cell simulator + SystemStateManager + bridge) for the operator panel.

One concept: a running link process with its token file, its rendered state diagram and
its URL. Used by `safestate panel` and by the browser and link tests.
"""

from __future__ import annotations

import os
import secrets
import shutil
import subprocess
import tempfile
from dataclasses import dataclass
from pathlib import Path
from types import TracebackType

WWW = Path(__file__).with_name("www")
REPO = Path(__file__).resolve().parents[3]
DEFAULT_BUILD = Path(os.environ.get("SAFESTATE_BUILD_DIR", REPO / "build" / "cpp"))


class PanelError(Exception):
    """The link cannot be started (missing binary or Graphviz, bad token file)."""


def link_binary(build_dir: Path = DEFAULT_BUILD) -> Path:
    exe = build_dir / "safestate_link"
    if not exe.is_file():
        raise PanelError(f"{exe} does not exist; build the C++ tree first (bash scripts/setup.sh)")
    return exe


def render_diagram(dest: Path) -> None:
    """The C++ table (the binding's JSON export) laid out for the panel (diagram_dot.py), rendered
    by Graphviz `dot` into dest/diagram.svg."""
    from safestate.conform.binding import load_core
    from safestate.errors import UsageError
    from safestate.panel.diagram_dot import panel_dot

    try:
        core = load_core("safestate._core")  # the binding: the same table the control cycle runs
    except UsageError as e:
        raise PanelError(str(e)) from None
    dot = shutil.which("dot")
    if dot is None:
        raise PanelError("Graphviz 'dot' not found on PATH (apt-get install graphviz)")
    done = subprocess.run([dot, "-Tsvg"], input=panel_dot(core.transition_table_json()), capture_output=True,
                          text=True, check=False)
    if done.returncode != 0:
        raise PanelError(f"dot -Tsvg failed: {done.stderr.strip()}")
    (dest / "diagram.svg").write_text(done.stdout)


def write_token(path: Path) -> str:
    """A fresh control token in a file only its owner can read (mode 0600)."""
    token = secrets.token_urlsafe(24)
    fd = os.open(path, os.O_WRONLY | os.O_CREAT | os.O_TRUNC, 0o600)
    with os.fdopen(fd, "w") as f:
        f.write(token + "\n")
    return token


@dataclass
class RunningLink:
    process: subprocess.Popen[str]
    url: str
    token: str
    folder: Path

    @property
    def ws_url(self) -> str:
        return self.url.replace("http://", "ws://") + "ws"

    @property
    def panel_url(self) -> str:
        """The page, with the token in the fragment (never sent to the server in a request)."""
        return f"{self.url}#token={self.token}"


class PanelServer:
    """Context manager: the link process with a fresh www folder (panel + diagram) and token."""

    def __init__(self, build_dir: Path = DEFAULT_BUILD, port: int = 0, token_file: Path | None = None,
                 diagram: bool = True) -> None:
        self.build_dir = build_dir
        self.diagram = diagram
        self.port = port
        self.token_file = token_file
        self.link: RunningLink | None = None
        self._tmp: tempfile.TemporaryDirectory[str] | None = None

    def __enter__(self) -> RunningLink:
        exe = link_binary(self.build_dir)
        self._tmp = tempfile.TemporaryDirectory(prefix="safestate-panel-")
        folder = Path(self._tmp.name)
        www = folder / "www"
        shutil.copytree(WWW, www)
        if self.diagram:
            render_diagram(www)
        if self.token_file is None:
            token_file = folder / "operator.token"
            token = write_token(token_file)
        else:
            token_file = self.token_file
            token = token_file.read_text().splitlines()[0].strip() if token_file.is_file() else ""
        proc = subprocess.Popen([str(exe), "--token-file", str(token_file), "--www", str(www),
                                 "--port", str(self.port)],
                                stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
        assert proc.stdout is not None and proc.stderr is not None
        first = proc.stdout.readline().strip()
        prefix = "safestate link: "
        if not first.startswith(prefix):
            proc.wait(timeout=10)
            err = proc.stderr.read().strip() or f"exit status {proc.returncode}"
            self._cleanup()
            raise PanelError(err)
        self.link = RunningLink(proc, first[len(prefix):], token, folder)
        return self.link

    def __exit__(self, exc_type: type[BaseException] | None, exc: BaseException | None,
                 tb: TracebackType | None) -> None:
        if self.link is not None:
            self.link.process.terminate()
            try:
                self.link.process.wait(timeout=10)
            except subprocess.TimeoutExpired:
                self.link.process.kill()
                self.link.process.wait()
        self._cleanup()

    def _cleanup(self) -> None:
        if self._tmp is not None:
            self._tmp.cleanup()
            self._tmp = None
