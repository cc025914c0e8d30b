"""CLI errors a CI can trust: 20 bad arguments or malformed inputs to `conform` and
`prove` each give a one-line error naming the file (and line:col where the input has
lines) and exit code 2 -- never a traceback, never the mismatch code 20 -- and fail
before any exploration.  Also `--version` and the exit-code table in `--help`."""

import json
import os
from pathlib import Path

import pytest

from safestate import __version__
from safestate.cli import main

REPO = Path(__file__).resolve().parents[2]
FLAGSHIP = "SystemStateManager"


def write(tmp: Path, name: str, text: str) -> str:
    p = tmp / name
    p.parent.mkdir(parents=True, exist_ok=True)
    p.write_text(text, encoding="utf-8")
    return str(p)


def registry(tmp: Path, manifest: str, adapter: str | None = None) -> Path:
    """A registry folder with one system `Bad` (for malformed-manifest cases)."""
    d = tmp / "reg" / "systems"
    write(d, "Bad/system.toml", manifest)
    if adapter is not None:
        write(d, "Bad/adapter.py", adapter)
    return d


GOOD_MANIFEST = f'''name = "Bad"
design = "{REPO}/docs/design/system-state-manager.md"
model = "{REPO}/models/SystemStateManager.tla"
configs = ["{REPO}/models/SystemStateManager.cfg"]
[conformance]
binding = "safestate._core"
adapter = "adapter.py"
class = "Adapter"
'''


def cases(tmp: Path) -> list[tuple[str, list[str], dict[str, str], str]]:
    """(name, argv, environment, text the one-line error must contain)."""
    itf_no_states = write(tmp, "empty.itf.json", json.dumps({"vars": ["x"], "states": []}))
    itf_wrong_vars = write(tmp, "wrongvars.itf.json", json.dumps({"vars": ["x"], "states": [{"x": 1}]}))
    graph_not_graph = write(tmp, "list.json", "[1, 2, 3]")
    graph_wrong_vars = write(tmp, "vars.json", json.dumps({"vars": ["x"], "states": [], "edges": [], "initial": []}))
    bad_json = write(tmp, "bad.json", '{"vars": [\n  "x",\n  oops\n]}')
    bad_tla = write(tmp, "Broken.tla", "---- MODULE Broken ----\nVARIABLE x\nInit == x = \nNext == x' = x\n====\n")
    write(tmp, "Broken.cfg", "INIT Init\nNEXT Next\n")
    a_file = write(tmp, "plainfile", "not a directory")
    good_tla = write(tmp, "Good.tla", "---- MODULE Good ----\nVARIABLE x\nInit == x = 0\nNext == x' = x\n====\n")
    write(tmp, "Good.cfg", "INIT Init\nNEXT Next\n")
    bad_plan = write(tmp, "plan.toml", "engine = [unclosed\n")
    return [
        ("unknown system", ["conform", "NoSuchSystem"], {}, "not a registered system"),
        ("missing model file", ["conform", "models/NoSuch.tla"], {}, "models/NoSuch.tla"),
        ("model not in the registry", ["conform", bad_tla], {}, "no system in the registry"),
        ("missing --config", ["conform", FLAGSHIP, "--config", str(tmp / "none.cfg")], {}, "none.cfg"),
        ("missing --graph", ["conform", FLAGSHIP, "--graph", str(tmp / "none.json")], {}, "none.json"),
        ("malformed --graph JSON", ["conform", FLAGSHIP, "--graph", bad_json], {}, "bad.json:3:3"),
        ("--graph not a graph", ["conform", FLAGSHIP, "--graph", graph_not_graph], {}, "not a state graph"),
        ("--graph of other variables", ["conform", FLAGSHIP, "--graph", graph_wrong_vars], {}, "variables"),
        ("missing --replay", ["conform", FLAGSHIP, "--replay", str(tmp / "none.itf.json")], {}, "none.itf.json"),
        ("--replay without states", ["conform", FLAGSHIP, "--replay", itf_no_states], {}, "not an ITF trace"),
        ("--replay of other variables", ["conform", FLAGSHIP, "--replay", itf_wrong_vars], {}, "variables"),
        ("--out is a file", ["conform", FLAGSHIP, "--out", a_file], {}, "must be a directory"),
        ("--out unwritable", ["conform", FLAGSHIP, "--out", "/proc/safestate-out"], {}, "not writable"),
        ("unknown binding module", ["conform", FLAGSHIP, "--core-module", "no_such_pkg._core"], {}, "no_such_pkg"),
        ("negative --max-len", ["conform", FLAGSHIP, "--max-len", "0"], {}, "--max-len"),
        ("malformed manifest TOML", ["conform", "Bad"], {"SAFESTATE_SYSTEMS": "toml"}, "system.toml"),
        ("manifest without model", ["conform", "Bad"], {"SAFESTATE_SYSTEMS": "nomodel"}, "missing key 'model'"),
        ("adapter class missing", ["conform", "Bad"], {"SAFESTATE_SYSTEMS": "noclass"}, "no class Adapter"),
        ("prove: missing model", ["prove", str(tmp / "NoSuch.tla")], {}, "NoSuch.tla"),
        ("prove: syntax error in the model", ["prove", bad_tla], {}, "Broken.tla:"),
        ("prove: malformed proof plan", ["prove", good_tla, "--proofs", bad_plan], {}, "plan.toml"),
    ]


@pytest.fixture(scope="module")
def bad_inputs(tmp_path_factory):
    tmp = tmp_path_factory.mktemp("bad")
    regs = {
        "toml": registry(tmp / "t", 'name = "Bad"\nmodel = [\n'),
        "nomodel": registry(tmp / "m", 'name = "Bad"\ndesign = "x"\nconfigs = []\n'),
        "noclass": registry(tmp / "c", GOOD_MANIFEST, "X = 1\n"),
    }
    return tmp, regs, cases(tmp)


def test_there_are_at_least_20_bad_inputs(bad_inputs):
    assert len(bad_inputs[2]) >= 20


@pytest.mark.parametrize("index", range(21))
def test_bad_input_gives_one_located_line_and_exit_code_2(bad_inputs, index, capsys, monkeypatch):
    tmp, regs, all_cases = bad_inputs
    name, argv, env, must = all_cases[index]
    for k, v in env.items():
        monkeypatch.setenv(k, str(regs[v]))
    monkeypatch.chdir(REPO)
    code = main(argv)
    err = capsys.readouterr().err
    lines = [x for x in err.splitlines() if x.strip() and not x.startswith("conform: ")
             and not x.startswith("[prove")]
    assert code == 2, f"{name}: exit {code}\n{err}"
    assert "Traceback" not in err, name
    assert len(lines) == 1, f"{name}: {lines}"
    assert lines[0].startswith("error: "), f"{name}: {lines[0]}"
    assert must in lines[0], f"{name}: '{must}' not in {lines[0]!r}"


@pytest.mark.parametrize("option", ["--itf", "--graph"])
@pytest.mark.parametrize("where", ["/proc/no-such-dir/out.json", "a directory"])
def test_check_to_an_unwritable_output_path_fails_before_the_search(option, where, tmp_path, capsys, monkeypatch):
    """The flagship's search takes minutes: an output path that cannot be written is
    refused before it starts, with one line and exit code 2."""
    import safestate.checker.cli as check_cli

    def no_search(*a, **k):
        raise AssertionError("the search ran")
    monkeypatch.setattr(check_cli, "explore_states", no_search)
    path = str(tmp_path) if where == "a directory" else where
    code = main(["check", str(REPO / "models" / f"{FLAGSHIP}.tla"), option, path])
    err = capsys.readouterr().err
    assert code == 2, err
    assert "Traceback" not in err
    lines = [x for x in err.splitlines() if x.strip()]
    assert len(lines) == 1 and lines[0].startswith("error: ") and path in lines[0] and option in lines[0], lines


def test_check_to_a_writable_output_path_leaves_no_empty_file(tmp_path, capsys):
    out = tmp_path / "trace.itf.json"
    code = main(["check", str(REPO / "models" / "PLCopenAxis.tla"), "--itf", str(out)])
    assert code == 0, capsys.readouterr().err
    assert not out.exists()  # no counterexample: nothing written, and the probe left nothing behind


def test_version_and_help_list_the_exit_codes(capsys):
    with pytest.raises(SystemExit) as e:
        main(["--version"])
    assert e.value.code == 0 and __version__ in capsys.readouterr().out
    with pytest.raises(SystemExit):
        main(["--help"])
    out = capsys.readouterr().out
    for sub in ("systems", "check", "prove", "conform"):
        assert sub in out
    for code in ("0 ", "2 ", "12 ", "20 ", "21 "):
        assert f"\n  {code}" in out


def test_systems_lists_the_flagship_and_the_plcopen_axis(capsys, monkeypatch):
    monkeypatch.chdir(REPO)
    assert main(["systems"]) == 0
    out = capsys.readouterr().out
    assert "SystemStateManager" in out and "PLCopenAxis" in out
    assert main(["systems", "--json"]) == 0
    doc = json.loads(capsys.readouterr().out)
    flagship = [s for s in doc["systems"] if s["name"] == FLAGSHIP][0]
    assert flagship["model"] == flagship["adapter"] == flagship["binding"] == "ok"
    assert os.path.isabs(doc["registry"])
