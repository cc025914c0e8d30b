"""Issue 16: the operator panel in a real browser (headless Chromium from Debian, Selenium).

The demo scenario is played by clicking the page: E-stop, release, Reset; a T1 jog
requested at 400 mm/s and clamped to 250; the safety gate opened in AUTO; an E-stop
channel stuck open latching ERROR_LOCKOUT. After each step what the page shows is compared
with the C++ status as an independent observer client reads it from the bridge.
Screenshots go to build/panel-screenshots/ (not committed); the browser console must stay
free of errors.
"""

from __future__ import annotations

import shutil
import time
from collections.abc import Callable, Iterator
from pathlib import Path
from typing import Any

import pytest

from safestate.panel.server import DEFAULT_BUILD, PanelServer

from link_client import LinkClient

CHROMIUM = Path("/usr/bin/chromium")
CHROMEDRIVER = Path("/usr/bin/chromedriver")
SHOTS = Path(__file__).resolve().parents[2] / "build" / "panel-screenshots"

webdriver = pytest.importorskip("selenium.webdriver")
pytestmark = pytest.mark.skipif(
    not (CHROMIUM.is_file() and CHROMEDRIVER.is_file() and (DEFAULT_BUILD / "safestate_link").is_file()
         and shutil.which("dot")),
    reason="needs Debian chromium + chromium-driver, Graphviz and build/cpp/safestate_link")

# Page element id -> how to read the same value from a status frame.
FIELDS: dict[str, Callable[[dict[str, Any]], str]] = {
    "state": lambda s: s["state"],
    "mode": lambda s: s["selector"],
    "session": lambda s: s["session_mode"],
    "stop": lambda s: s["stop_category"],
    "fault": lambda s: s["fault_code"],
    "reject": lambda s: s["last_reject_reason"],
    "out-contactor": lambda s: "ON" if s["outputs"]["contactor_closed"] else "off",
    "out-drive": lambda s: "ON" if s["outputs"]["drive_enable"] else "off",
    "out-brake": lambda s: "ON" if s["outputs"]["brake_release"] else "off",
    "out-lamp": lambda s: "ON" if s["outputs"]["reset_lamp"] else "off",
    "out-speed": lambda s: str(s["outputs"]["commanded_speed_mm_s"]),
    **{f"axis-{i + 1}": (lambda s, i=i: s["outputs"]["axes"][i]) for i in range(6)},
}


@pytest.fixture
def browser() -> Iterator[Any]:
    from selenium.webdriver.chrome.options import Options
    from selenium.webdriver.chrome.service import Service

    opts = Options()
    opts.binary_location = str(CHROMIUM)
    for arg in ("--headless=new", "--no-sandbox", "--disable-gpu", "--disable-dev-shm-usage", "--window-size=1700,1000"):
        opts.add_argument(arg)
    opts.set_capability("goog:loggingPrefs", {"browser": "ALL"})
    driver = webdriver.Chrome(service=Service(str(CHROMEDRIVER)), options=opts)
    yield driver
    driver.quit()


class Panel:
    def __init__(self, driver: Any, observer: LinkClient) -> None:
        self.driver = driver
        self.observer = observer
        self.step = 0

    def text(self, element_id: str) -> str:
        return str(self.driver.find_element("id", element_id).text)

    def click(self, element_id: str) -> None:
        self.driver.find_element("id", element_id).click()

    def choose(self, group: str, value: str) -> None:
        self.driver.find_element("css selector", f"input[name={group}][value={value}]").click()

    def shows(self, name: str, timeout: float = 10.0, **expected: str) -> dict[str, Any]:
        """Waits until the page shows `expected` and agrees with the C++ status on every field."""
        end = time.monotonic() + timeout
        page: dict[str, str] = {}
        cpp: dict[str, str] = {}
        while time.monotonic() < end:
            status = self.observer.latest_status()
            cpp = {k: f(status) for k, f in FIELDS.items()}
            page = {k: self.text(k) for k in FIELDS}
            if page == cpp and all(cpp[k] == v for k, v in expected.items()):
                self.step += 1
                SHOTS.mkdir(parents=True, exist_ok=True)
                self.driver.save_screenshot(str(SHOTS / f"{self.step:02d}-{name}.png"))
                return status
        raise AssertionError(f"step {name}: page {page} vs C++ {cpp}, expected {expected}")


# Graphviz node labels are 14 pt in the SVG's user units (diagram_dot.py); at the page's
# scale they must come out at least this many CSS pixels high to be read without zooming.
MIN_LABEL_PX = 10


def assert_diagram_readable_without_zoom(browser: Any) -> None:
    """The whole state diagram fits its box and the window (no scrolling), its labels readable."""
    box = browser.execute_script("""
        const d = document.getElementById('diagram'), svg = d.querySelector('svg');
        const r = svg.getBoundingClientRect(), vb = svg.viewBox.baseVal;
        return {scale: Math.min(r.width / vb.width, r.height / vb.height), height: r.height,
                window: window.innerHeight, overflowX: d.scrollWidth - d.clientWidth,
                overflowY: d.scrollHeight - d.clientHeight};""")
    assert box["scale"] * 14 >= MIN_LABEL_PX, box
    assert box["height"] <= box["window"], box
    assert box["overflowX"] <= 0 and box["overflowY"] <= 0, box


def test_the_demo_scenario_played_by_clicking_matches_the_cpp_status(browser: Any) -> None:
    with PanelServer() as link:
        observer = LinkClient(link.ws_url)
        browser.get(link.panel_url)
        p = Panel(browser, observer)
        deadline = time.monotonic() + 10
        while p.text("control") != "in control" and time.monotonic() < deadline:
            time.sleep(0.05)
        assert p.text("control") == "in control"
        assert browser.find_element("id", "diagram").get_attribute("data-loaded") == "true"
        assert_diagram_readable_without_zoom(browser)
        p.shows("boot", state="IDLE")

        p.click("plant-estop")
        p.shows("estop", state="ESTOP_ACTIVE", stop="CAT0", **{"out-contactor": "off"})
        p.click("plant-estop")
        p.shows("released", state="ESTOP_RESET_NEEDED", **{"out-lamp": "ON"})
        p.click("cmd-RESET")
        p.shows("reset", state="IDLE", **{"out-lamp": "off"})

        p.choose("selector", "T1")
        p.choose("enabling", "MIDDLE")
        p.shows("t1", mode="T1")
        p.click("cmd-SERVO_ON")
        p.shows("t1-servo-on", state="MANUAL_IDLE", session="T1")
        speed = browser.find_element("id", "jog-speed")
        speed.clear()
        speed.send_keys("400")
        p.click("cmd-JOG_START")
        st = p.shows("t1-jog-clamped", state="MANUAL_JOGGING", **{"out-speed": "250", "axis-2": "ContinuousMotion"})
        assert st["jog"]["speed_mm_s"] == 250
        highlighted = browser.find_elements("css selector", "#diagram g.node.current title")
        assert [h.get_attribute("textContent") for h in highlighted] == ["MANUAL_JOGGING"]
        fired = browser.find_elements("css selector", "#diagram g.edge.fired text")
        assert fired and all(f.get_attribute("textContent").startswith("K29") for f in fired)
        p.click("cmd-JOG_STOP")
        p.shows("jog-stop", state="MANUAL_IDLE", **{"out-speed": "0"})
        p.choose("enabling", "RELEASED")
        p.shows("enabling-released", state="IDLE", stop="CAT1")

        p.choose("selector", "AUTO")
        p.click("cmd-SERVO_ON")
        p.shows("auto-servo-on", state="AUTO_IDLE", session="AUTO")
        p.click("cmd-START")
        p.shows("auto-running", state="AUTO_RUNNING")
        p.click("plant-gate")
        p.shows("gate-open-in-auto", state="IDLE", stop="CAT1", **{"out-contactor": "off"})
        p.click("plant-gate")

        p.click("plant-stuck")
        p.shows("stuck-channel", state="ERROR_LOCKOUT", fault="DISCREPANCY_ESTOP", stop="CAT0")
        p.click("cmd-RESET")
        p.shows("locked-out", state="ERROR_LOCKOUT", reject="LOCKED_OUT")

        errors = [e for e in browser.get_log("browser") if e["level"] == "SEVERE"]
        assert errors == [], errors
