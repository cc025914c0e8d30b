"""Issue 27, items 5-7: `safestate check` under hostile conditions a CI meets -- too many
workers, numbers beyond TLC's 32-bit ints, a full disk or stdout, Ctrl-C and SIGTERM,
malformed registry and evidence files, and the exit codes TLC gives for ill-levelled
configurations.  Every case ends with a verdict or one located line and a documented
exit code, never a hang, a traceback or leftover shared memory."""

from __future__ import annotations

import json
import os
import signal
import subprocess
import sys
from pathlib import Path

import pytest

from conftest import PYTHON_DIR, run_safestate

COUNTER = """---- MODULE {name} ----
EXTENDS Naturals
CONSTANT N
VARIABLE x
Init == x = 0
Next == x' = (x + 1) % 3
Inv == x < N
====
"""


def counter(tla_dir, name: str = "Counter", n: str = "3"):  # noqa: ANN001, ANN201
    return tla_dir(name, COUNTER.format(name=name), f"INIT Init\nNEXT Next\nCONSTANT N = {n}\nINVARIANT Inv\n")


def lines(text: str) -> list[str]:
    return [x for x in text.splitlines() if x.strip()]


# ---------------------------------------------------------------- 5: hangs
def test_too_many_workers_are_capped_at_the_cores_available_with_a_warning(tla_dir, tmp_path) -> None:
    tla = counter(tla_dir)
    cores = len(os.sched_getaffinity(0))
    p = run_safestate("check", str(tla), "--workers", "1000", "--json")
    assert p.returncode == 0, p.stderr
    assert f"--workers 1000 is more than the {cores} core" in p.stderr
    assert json.loads(p.stdout)["distinct_states"] == 3


@pytest.mark.parametrize("bad", ["0", "-3", "many"])
def test_a_workers_value_that_is_not_a_positive_number_is_a_usage_error(tla_dir, bad: str) -> None:
    p = run_safestate("check", str(counter(tla_dir)), "--workers", bad)
    assert p.returncode == 2, p.stderr
    assert lines(p.stderr) == [lines(p.stderr)[0]] and "--workers" in p.stderr and "Traceback" not in p.stderr


def test_a_cfg_number_beyond_tlcs_32_bit_ints_is_refused_at_once_as_tlc_does(tla_dir) -> None:
    """TLC reads a cfg number with Integer.parseInt: NumberFormatException, exit 255."""
    p = run_safestate("check", str(counter(tla_dir, n="99999999999")))
    assert p.returncode == 255, p.stderr
    assert "Counter.cfg:3:14:" in p.stderr and "99999999999" in p.stderr and "32-bit" in p.stderr
    p = run_safestate("check", str(counter(tla_dir, n="2147483647")), "--json")
    assert p.returncode == 0 and json.loads(p.stdout)["distinct_states"] == 3


def test_a_tla_numeral_beyond_tlcs_32_bit_ints_is_tlcs_integer_too_big_error(tla_dir) -> None:
    """TLC: "TLC can't handle a number this big." (EC.TLC_INTEGER_TOO_BIG, exit 255), even in
    a definition the model never uses."""
    text = COUNTER.format(name="Big").replace("Inv == x < N", "Inv == x < N\nUnused == 2147483648")
    tla = tla_dir("Big", text, "INIT Init\nNEXT Next\nCONSTANT N = 3\nINVARIANT Inv\n")
    p = run_safestate("check", str(tla))
    assert p.returncode == 255, p.stderr
    assert "Big.tla:8:11:" in p.stderr and "can't handle a number this big" in p.stderr


def _parallel_spec(tla_dir):  # noqa: ANN001, ANN202
    """A counter without bound: the search never ends; PrintT says it is under way."""
    return tla_dir("Endless", """---- MODULE Endless ----
EXTENDS Naturals, TLC
VARIABLE x, y
Init == x = 0 /\\ y = 0
Next == /\\ x' = x + 1
        /\\ y' \\in 0..3
        /\\ (x = 300 => PrintT("under way"))
====
""", "INIT Init\nNEXT Next\n")


def _start(*args: str, env_extra: dict[str, str] | None = None) -> subprocess.Popen:
    env = dict(os.environ)
    env["PYTHONPATH"] = str(PYTHON_DIR) + os.pathsep + env.get("PYTHONPATH", "")
    env.update(env_extra or {})
    return subprocess.Popen([sys.executable, "-m", "safestate.cli", *args], stdout=subprocess.PIPE,
                            stderr=subprocess.PIPE, text=True, env=env)


def _wait_for(p: subprocess.Popen, text: str) -> list[str]:
    seen = []
    assert p.stderr is not None
    for line in p.stderr:
        seen.append(line)
        if text in line:
            return seen
    raise AssertionError(f"the process ended before printing {text!r}: {''.join(seen)}")


def test_ctrl_c_with_json_still_writes_one_json_object_with_the_counts_so_far(tla_dir) -> None:
    p = _start("check", str(_parallel_spec(tla_dir)), "--json")
    _wait_for(p, "under way")
    p.send_signal(signal.SIGINT)
    out, err = p.communicate(timeout=120)
    assert p.returncode == 130, err
    doc = json.loads(out)
    assert doc["result"] == "interrupted"
    assert doc["distinct_states"] >= 300 * 4 and doc["states_generated"] >= doc["distinct_states"]
    assert doc["depth"] >= 300
    assert "Traceback" not in err


@pytest.mark.skipif(len(os.sched_getaffinity(0)) < 2, reason="one core: --workers 2 is capped at one worker")
@pytest.mark.parametrize("sig, code", [(signal.SIGINT, 130), (signal.SIGTERM, 143)])
def test_the_parallel_search_leaves_no_shared_memory_behind_when_stopped(tla_dir, tmp_path, sig, code) -> None:
    shm = tmp_path / "shm"
    shm.mkdir()
    p = _start("check", str(_parallel_spec(tla_dir)), "--workers", "2", env_extra={"SAFESTATE_SHM_DIR": str(shm)})
    _wait_for(p, "under way")
    assert list(shm.iterdir()), "the parallel search should have its folder while it runs"
    p.send_signal(sig)
    out, err = p.communicate(timeout=120)
    assert p.returncode == code, err
    assert "Traceback" not in err
    assert list(shm.iterdir()) == []


def test_the_parallel_search_leaves_no_shared_memory_behind_after_an_error(tla_dir, tmp_path) -> None:
    shm = tmp_path / "shm"
    shm.mkdir()
    tla = tla_dir("Fails", """---- MODULE Fails ----
EXTENDS Naturals
VARIABLE x
Init == x = 0
Next == x' = IF x = 5 THEN x \\div 0 ELSE x + 1
====
""", "INIT Init\nNEXT Next\n")
    env = {"SAFESTATE_SHM_DIR": str(shm)}
    p = _start("check", str(tla), "--workers", "2", env_extra=env)
    out, err = p.communicate(timeout=300)
    assert p.returncode == 255 and "The second argument of \\div is 0" in out, out + err  # TLC: 255
    assert "Traceback" not in err and "internal error" not in err
    assert list(shm.iterdir()) == []


# ---------------------------------------------------------------- 6: lost output
@pytest.mark.parametrize("option", ["--itf", "--graph"])
@pytest.mark.parametrize("json_flag", [[], ["--json"]])
def test_a_full_disk_for_an_output_file_still_prints_the_verdict_then_its_own_code(tla_dir, option, json_flag) -> None:
    tla = counter(tla_dir, n="2")  # Inv violated at depth 3
    p = run_safestate("check", str(tla), option, "/dev/full", *json_flag)
    assert p.returncode == 74, p.stderr
    if json_flag:
        assert json.loads(p.stdout)["result"] == "safety failure"
    else:
        assert "Error: Invariant Inv is violated." in p.stdout
    errors = [x for x in lines(p.stderr) if x.startswith("error:")]
    assert len(errors) == 1 and "/dev/full" in errors[0] and option in errors[0], p.stderr
    assert "Traceback" not in p.stderr


def test_json_to_a_full_stdout_is_one_line_and_its_own_exit_code(tla_dir) -> None:
    env = dict(os.environ)
    env["PYTHONPATH"] = str(PYTHON_DIR) + os.pathsep + env.get("PYTHONPATH", "")
    with open("/dev/full", "w") as full:
        p = subprocess.run([sys.executable, "-m", "safestate.cli", "check", str(counter(tla_dir)), "--json"],
                           stdout=full, stderr=subprocess.PIPE, text=True, env=env, timeout=300)
    assert p.returncode == 74, p.stderr
    assert lines(p.stderr) == ["error: cannot write the result to stdout: No space left on device"]


def test_the_exit_code_table_lists_the_output_failure_code(capsys) -> None:
    from safestate.cli import main
    with pytest.raises(SystemExit):
        main(["--help"])
    out = capsys.readouterr().out
    assert "\n  74 " in out and "\n  3 " in out
    docs = (Path(__file__).resolve().parents[2] / "docs" / "index.md").read_text(encoding="utf-8")
    assert "| 74 " in docs or "`74`" in docs
