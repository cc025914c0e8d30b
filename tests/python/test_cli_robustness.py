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


def _start(*args: str, env_extra: dict[str, str] | None = None, new_session: bool = False) -> subprocess.Popen:
    env = dict(os.environ)
    env["PYTHONPATH"] = str(PYTHON_DIR) + os.pathsep + env.get("PYTHONPATH", "")
    env.update(env_extra or {})
    return subprocess.Popen([sys.executable, "-m", "safestate.cli", *args], stdout=subprocess.PIPE,
                            stderr=subprocess.PIPE, text=True, env=env, start_new_session=new_session,
                            preexec_fn=_as_from_a_terminal)


def _as_from_a_terminal() -> None:
    """The child starts as a foreground job does: SIGINT at its default, unblocked. A
    process started with SIGINT ignored keeps ignoring Ctrl-C (Python installs no
    handler), and a pytest worker may have inherited it ignored or blocked."""
    signal.signal(signal.SIGINT, signal.SIG_DFL)
    signal.pthread_sigmask(signal.SIG_UNBLOCK, {signal.SIGINT, signal.SIGTERM})


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
@pytest.mark.parametrize("group", [False, True], ids=["to the coordinator", "to the process group (Ctrl-C)"])
def test_the_parallel_search_leaves_no_shared_memory_behind_when_stopped(tla_dir, tmp_path, sig, code,
                                                                          group) -> None:
    shm = tmp_path / "shm"
    shm.mkdir()
    # The Python engine's parallel search (worker processes, shared memory).
    p = _start("check", str(_parallel_spec(tla_dir)), "--workers", "2", "--engine", "python",
               env_extra={"SAFESTATE_SHM_DIR": str(shm)}, new_session=group)
    _wait_for(p, "under way")
    assert list(shm.iterdir()), "the parallel search should have its folder while it runs"
    if group:
        os.killpg(p.pid, sig)
    else:
        p.send_signal(sig)
    out, err = p.communicate(timeout=120)
    assert p.returncode == code, err
    assert "Traceback" not in err
    assert "searching again with one worker" not in err  # the workers leave stopping to the coordinator
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
    p = _start("check", str(tla), "--workers", "2", "--engine", "python", env_extra=env)
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


# ---------------------------------------------------------------- 6/7: located errors, TLC's codes
# The exit codes are TLC 1.8.0's, measured (tla2tools.jar built from tlaplus/tlaplus):
# 75 "In evaluation, the identifier x is either undefined..." (primed Init, action
# CONSTRAINT), 76 "The invariant Inv is not a state predicate", 75 "TLC encountered a
# temporal formula" (temporal CONSTRAINT), 75 "No next state actions defined",
# 255 "The symmetry operator must specify a set of functions" (RuntimeException).
LEVEL_CASES = {
    # name: (definitions, cfg, TLC's exit code, text of the one error line)
    "PrimedInit": ("Init == x' = 0\nNext == x' = x", "INIT Init\nNEXT Next\n", 75, "PrimedInit.tla:4:9:"),
    "ActionInvariant": ("Init == x = 0\nNext == x' = 1 - x\nInv == x' = x", "INIT Init\nNEXT Next\nINVARIANT Inv\n",
                        76, "is an action"),
    "TemporalInvariant": ("Init == x = 0\nNext == x' = 1 - x\nInv == [](x = 0)",
                          "INIT Init\nNEXT Next\nINVARIANT Inv\n", 76, "is a temporal formula"),
    "ActionConstraint": ("Init == x = 0\nNext == x' = 1 - x\nC == x' = x", "INIT Init\nNEXT Next\nCONSTRAINT C\n",
                         75, "is an action"),
    "TemporalConstraint": ("Init == x = 0\nNext == x' = 1 - x\nC == [](x = 0)",
                           "INIT Init\nNEXT Next\nCONSTRAINT C\n", 75, "is a temporal formula"),
    "SpecIsInit": ("Init == x = 0\nNext == x' = 1 - x", "SPECIFICATION Init\n", 75, "no next-state action"),
    "SymmetryNotASet": ("Init == x = 0\nNext == x' = 1 - x\nSym == 3", "INIT Init\nNEXT Next\nSYMMETRY Sym\n",
                        255, "must specify a set of functions"),
}


@pytest.mark.parametrize("name", sorted(LEVEL_CASES))
def test_an_ill_levelled_or_ill_typed_cfg_entry_gives_tlcs_exit_code(tla_dir, name: str) -> None:
    defs, cfg, code, text = LEVEL_CASES[name]
    tla = tla_dir(name, f"---- MODULE {name} ----\nEXTENDS Naturals\nVARIABLE x\n{defs}\n====\n", cfg)
    p = run_safestate("check", str(tla))
    assert p.returncode == code, p.stdout + p.stderr
    errors = [x for x in lines(p.stderr) if "error:" in x]
    assert len(errors) == 1 and text in errors[0] and f"{name}.tla:" in errors[0], p.stderr


def test_a_latin1_comment_in_the_cfg_is_accepted_as_tlc_does_and_a_binary_cfg_is_located(tla_dir) -> None:
    tla = counter(tla_dir, "Latin")
    cfg = tla.with_suffix(".cfg")
    cfg.write_bytes(b"INIT Init \\* caf\xe9\nNEXT Next\nCONSTANT N = 3\nINVARIANT Inv\n")
    p = run_safestate("check", str(tla), "--json")
    assert p.returncode == 0, p.stderr
    assert json.loads(p.stdout)["distinct_states"] == 3
    cfg.write_bytes(b"INIT Init\nNEXT \x00\xff\xfe\n")
    p = run_safestate("check", str(tla))
    assert p.returncode == 255 and "Latin.cfg:2:6:" in p.stderr and "Traceback" not in p.stderr, p.stderr


def test_a_missing_file_is_named_without_a_fake_position(tla_dir, tmp_path) -> None:
    p = run_safestate("check", str(tmp_path / "NoSuch.tla"))
    assert p.returncode == 150 and ":0:0" not in p.stderr and "NoSuch.tla" in p.stderr, p.stderr
    p = run_safestate("check", str(counter(tla_dir)), "--config", str(tmp_path / "none.cfg"), "--json")
    assert p.returncode == 151 and ":0:0" not in p.stderr, p.stderr
    err = json.loads(p.stdout)["error"]
    assert err["file"].endswith("none.cfg") and err["line"] is None


def test_a_negative_max_memory_is_a_usage_error(tla_dir) -> None:
    p = run_safestate("check", str(counter(tla_dir)), "--max-memory", "-5")
    assert p.returncode == 2 and "--max-memory" in p.stderr, p.stderr


def test_a_tla2tools_jar_that_is_not_tlc_is_its_own_error_not_a_disagreement(tla_dir, tmp_path) -> None:
    bogus = tmp_path / "tla2tools.jar"
    bogus.write_text("not a jar")
    env = dict(os.environ, TLA2TOOLS_JAR=str(bogus))
    env["PYTHONPATH"] = str(PYTHON_DIR) + os.pathsep + env.get("PYTHONPATH", "")
    p = subprocess.run([sys.executable, "-m", "safestate.cli", "check", str(counter(tla_dir)), "--tlc"],
                       capture_output=True, text=True, env=env, timeout=300)
    assert p.returncode == 3, p.stderr
    assert "DISAGREES" not in p.stderr and "not a jar" in p.stderr


# ---------------------------------------------------------------- 6: the registry and the evidence manifest
REPO = Path(__file__).resolve().parents[2]
AXIS = f'''name = "Axis"
design = "{REPO}/docs/design/system-state-manager.md"
model = "{REPO}/models/PLCopenAxis.tla"
configs = ["{REPO}/models/PLCopenAxis.cfg"]
'''
BROKEN = {
    "toml": ('name = "Broken"\nmodel = [\n', "system.toml:3:1: malformed TOML"),
    "wrong type": ('name = "Broken"\ndesign = "d"\nmodel = 3\nconfigs = ["c.cfg"]\n', "system.toml:3: 'model' must be a str"),
    "no configs": ('name = "Broken"\ndesign = "d"\nmodel = "m.tla"\nconfigs = []\n', "'configs' is empty"),
    "steps not a number": ('name = "Broken"\ndesign = "d"\nmodel = "m.tla"\nconfigs = ["c.cfg"]\n'
                           '[conformance]\nbinding = "b"\nadapter = "a.py"\nclass = "A"\nhypothesis_steps = "many"\n',
                           "malformed manifest"),
    "not UTF-8": ('name = "Br\udcffoken"\n', "system.toml:1: the manifest is not UTF-8"),
}


def _registry(tmp: Path, broken: str) -> Path:
    d = tmp / "systems"
    (d / "Axis").mkdir(parents=True)
    (d / "Axis" / "system.toml").write_text(AXIS, encoding="utf-8")
    (d / "Broken").mkdir()
    (d / "Broken" / "system.toml").write_bytes(broken.encode("utf-8", "surrogateescape"))
    return d


@pytest.mark.parametrize("case", sorted(BROKEN))
def test_a_malformed_manifest_breaks_only_its_own_system(case, tmp_path, capsys, monkeypatch) -> None:
    from safestate.cli import main
    text, located = BROKEN[case]
    monkeypatch.setenv("SAFESTATE_SYSTEMS", str(_registry(tmp_path, text)))
    assert main(["check", "Axis"]) == 0, capsys.readouterr().err
    capsys.readouterr()
    for argv in (["check", "Broken"], ["prove", "Broken"], ["conform", "Broken"]):
        code = main(argv)
        err = capsys.readouterr().err
        assert code == 2, f"{argv}: {err}"
        assert "Traceback" not in err
        errors = [x for x in lines(err) if x.startswith("error:")]
        assert len(errors) == 1 and located in errors[0] and "Broken" in errors[0], f"{argv}: {err}"
    assert main(["systems"]) == 2
    out, err = capsys.readouterr()
    assert "Axis" in out and located in err


def _package(tmp: Path, manifest: str) -> Path:
    pkg = tmp / "pkg"
    pkg.mkdir()
    (pkg / "manifest.json").write_text(manifest, encoding="utf-8")
    return pkg


@pytest.mark.parametrize("manifest, text", [
    ("[1, 2]", "not an object"),
    ('{"inputs": {}, "outputs": {}}', "'root'"),
    ('{"root": "/", "inputs": [], "outputs": {}}', "'inputs'"),
    ('{"root": "/", "inputs": {}, "outputs": {}, "checks": [{"system": 1}]}', "checks[0]"),
    ("[" * 100000 + "]" * 100000, "not a JSON manifest"),
])
def test_a_malformed_evidence_manifest_is_a_located_difference_not_a_traceback(manifest, text, tmp_path, capsys) -> None:
    from safestate.cli import main
    code = main(["evidence", "--verify", str(_package(tmp_path, manifest))])
    out, err = capsys.readouterr()
    assert code == 1, out + err
    assert "manifest.json" in out and text in out and "internal error" not in out + err


def test_evidence_verify_stops_a_check_at_its_time_limit_and_says_so(tmp_path, capsys) -> None:
    spec = tmp_path / "Endless.tla"
    spec.write_text("---- MODULE Endless ----\nEXTENDS Naturals\nVARIABLE x\nInit == x = 0\nNext == x' = x + 1\n====\n")
    (tmp_path / "Endless.cfg").write_text("INIT Init\nNEXT Next\n")
    doc = {"root": str(tmp_path), "inputs": {}, "outputs": {},
           "checks": [{"system": "Endless", "model": "Endless.tla", "cfg": "Endless.cfg", "result": "success"}]}
    from safestate.cli import main
    code = main(["evidence", "--verify", str(_package(tmp_path, json.dumps(doc))), "--check-timeout", "3"])
    out, err = capsys.readouterr()
    assert code == 124, out + err
    assert "TIMEOUT: check Endless: timed out after 3 s" in out and "not verified" in out


def test_conform_of_a_system_without_conformance_is_a_usage_error(capsys, monkeypatch) -> None:
    from safestate.cli import main
    monkeypatch.chdir(REPO)
    assert main(["conform", "PLCopenAxis"]) == 2
    err = capsys.readouterr().err
    assert "no [conformance] section" in err and "AssertionError" not in err


def test_conform_refuses_deeply_nested_json_with_a_located_line(tmp_path, capsys, monkeypatch) -> None:
    from safestate.cli import main
    deep = tmp_path / "deep.json"
    deep.write_text("[" * 100000 + "]" * 100000)
    monkeypatch.chdir(REPO)
    assert main(["conform", "SystemStateManager", "--replay", str(deep)]) == 2
    err = capsys.readouterr().err
    assert "deep.json: malformed" in err and "nested too deeply" in err and "internal error" not in err


def test_prove_rejects_a_negative_depth_as_a_usage_error(capsys) -> None:
    from safestate.cli import main
    with pytest.raises(SystemExit) as e:
        main(["prove", str(REPO / "models" / "PLCopenAxis.tla"), "--depth", "-1"])
    assert e.value.code == 2 and "--depth" in capsys.readouterr().err


# ---------------------------------------------------------------- 7: parse errors that say what was expected
# Positions are SANY's (TLC 1.8.0's "Encountered ... at line L, column C"), but for the
# empty file (SANY: line 0, column 0).
HEAD = "---- MODULE E ----\nEXTENDS Naturals\nVARIABLE x\n"
PARSE_CASES = {
    # name: (module text, position, text the message must contain)
    "missing ====": (HEAD + "Init == x = 0\nNext == x' = x\n", "5:15", "expected a line ===="),
    "empty body before a definition": (HEAD + "Init ==\nNext == x' = x\n====\n", "5:1",
                                       "definition of Init (line 4) has no body"),
    "empty body at the end": (HEAD + "Init == x = 0\nNext == x' = x\nInv ==\n====\n", "6:1",
                              "definition of Inv (line 6) has no body"),
    "empty file": ("", "1:1", "the file is empty"),
    "no module header": ("VARIABLE x\nInit == x = 0\n====\n", "1:1", "expected a module header"),
    "operator without operand at the end": (HEAD + "Init == x = 0\nNext == x' = x\nInv == x \\in\n====\n", "7:1",
                                            "expected an expression after '\\in' (line 6, column 10)"),
    "operand missing before a definition": (HEAD + "Init == x = 0 +\nNext == x' = x\n====\n", "5:1",
                                            "expected an operand after '+'"),
    "stray closing bracket": (HEAD + "Init == x = 0\nNext == x' = x )\n====\n", "5:16",
                              "')' without a matching opening bracket"),
    "trailing comma": (HEAD + "Init == x \\in {1, }\nNext == x' = x\n====\n", "4:19",
                       "expected an expression after ',', found '}'"),
    "two operands in the last definition": (HEAD + "Init == x = 0\nNext == x' = x x\n====\n", "5:16",
                                            "unexpected 'x' after 'x'"),
}


@pytest.mark.parametrize("name", sorted(PARSE_CASES))
def test_a_parse_error_says_what_was_expected_where_the_parse_stops(tmp_path, name: str) -> None:
    text, where, says = PARSE_CASES[name]
    (tmp_path / "E.tla").write_text(text, encoding="utf-8")
    (tmp_path / "E.cfg").write_text("INIT Init\nNEXT Next\n")
    p = run_safestate("check", str(tmp_path / "E.tla"))
    assert p.returncode == 150, p.stderr
    errors = [x for x in lines(p.stderr) if "error:" in x]
    assert len(errors) == 1, p.stderr
    assert f"E.tla:{where}: error: parse error:" in errors[0] and says in errors[0], errors[0]
    assert "unexpected input" not in errors[0]


@pytest.mark.parametrize("expr, shown", [("x + 1", "2147483647+1"), ("x * 2", "2147483647*2"),
                                         ("0 - x - 10", "-2147483647-10"), ("2 ^ 40", "2^40"),
                                         ("-(-x - 1)", "--2147483648"),
                                         ("(-x - 1) \\div (-1)", "-2147483648 \\div -1")])
def test_arithmetic_beyond_tlcs_32_bit_ints_is_tlcs_overflow_error(tla_dir, expr: str, shown: str) -> None:
    """TLC's Naturals/Integers: "Overflow when computing a+b" (EC.TLC_MODULE_OVERFLOW), exit 255
    while computing successors -- never a number TLC cannot hold (messages as TLC 1.8.0
    prints them, unary minus and \\div of the least int included)."""
    tla = tla_dir("Over", f"""---- MODULE Over ----
EXTENDS Integers
VARIABLE x
Init == x = 2147483640
Next == x' = IF x < 2147483647 THEN x + 1 ELSE {expr}
====
""", "INIT Init\nNEXT Next\n")
    p = run_safestate("check", str(tla), "--json")
    assert p.returncode == 255, p.stdout + p.stderr
    doc = json.loads(p.stdout)
    assert doc["result"] == "error" and doc["error"]["message"] == f"Overflow when computing {shown}"


def test_the_evidence_package_is_not_built_without_a_system_whose_manifest_is_broken(tmp_path) -> None:
    """Tolerating a broken manifest must not leave its system out of the evidence unnoticed."""
    from safestate.evidence.build import select_systems
    from safestate.systems.registry import RegistryError
    d = _registry(tmp_path, BROKEN["toml"][0])
    with pytest.raises(RegistryError, match="system.toml:3:1"):
        select_systems(d.parent, [])
