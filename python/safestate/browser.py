"""Headless system Chromium (Debian `chromium` + `chromium-driver`) under Selenium,
for the browser tests of the HTML reports.  Never downloads a browser or a driver:
`system_chromium()` returns None when either is missing, so a test can skip.

    with system_chromium() as driver:   # a selenium.webdriver.Chrome
        driver.get(path.as_uri())
"""

from __future__ import annotations

import os
import shutil
from collections.abc import Iterator
from contextlib import contextmanager
from typing import Any

# Debian's paths; $CHROMIUM / $CHROMEDRIVER override them.
CHROMIUM = ("chromium", "/usr/bin/chromium")
CHROMEDRIVER = ("chromedriver", "/usr/bin/chromedriver")


def _which(env: str, names: tuple[str, ...]) -> str | None:
    given = os.environ.get(env)
    if given:
        return given if os.path.isfile(given) else None
    for n in names:
        found = shutil.which(n) or (n if os.path.isfile(n) else None)
        if found:
            return found
    return None


def missing() -> str | None:
    """Why the system browser cannot be started (None when it can)."""
    try:
        import selenium  # noqa: F401
    except ImportError:
        return "selenium is not installed (pip install selenium)"
    if _which("CHROMIUM", CHROMIUM) is None:
        return "no system chromium (apt-get install chromium)"
    if _which("CHROMEDRIVER", CHROMEDRIVER) is None:
        return "no system chromedriver (apt-get install chromium-driver)"
    return None


@contextmanager
def system_chromium(width: int = 1280, height: int = 900) -> Iterator[Any]:
    """A headless Chrome driver on the system chromium; the browser's console log is
    readable with `driver.get_log("browser")`."""
    reason = missing()
    if reason:
        raise RuntimeError(reason)
    from selenium import webdriver
    from selenium.webdriver.chrome.service import Service

    os.environ.setdefault("SE_OFFLINE", "true")  # Selenium Manager: never fetch anything
    opts = webdriver.ChromeOptions()
    opts.binary_location = str(_which("CHROMIUM", CHROMIUM))
    for a in ("--headless=new", "--no-sandbox", "--disable-dev-shm-usage", "--disable-gpu",
              f"--window-size={width},{height}"):
        opts.add_argument(a)
    opts.set_capability("goog:loggingPrefs", {"browser": "ALL"})
    driver = webdriver.Chrome(service=Service(executable_path=_which("CHROMEDRIVER", CHROMEDRIVER)), options=opts)
    try:
        yield driver
    finally:
        driver.quit()
