"""The console script: subcommands listed, unknown ones rejected with a one-line message."""
import re
import shutil
import subprocess
import sys
from pathlib import Path

#: The subcommands the issues ask for (issue 2: report, gallery, bench), written out, not read from cli.
EXPECTED_COMMANDS = {"report", "gallery", "bench"}


def run(*args):
    return subprocess.run([sys.executable, "-m", "planargeo.cli", *args],
                          capture_output=True, text=True, timeout=120)


def _listed_commands(help_text: str) -> set[str]:
    """The subcommand names of argparse's help: the indented ``name   help`` lines under ``COMMAND``."""
    block = help_text.split("COMMAND\n", 1)[1].split("\n\n", 1)[0]
    return {m.group(1) for m in re.finditer(r"^ {4}([a-z][a-z-]*) {2,}\S", block, re.M)}


def _console_script() -> str:
    """The installed ``planargeo`` script: next to this interpreter (the venv's bin), else on PATH."""
    here = Path(sys.executable).parent / "planargeo"
    if here.is_file():
        return str(here)
    found = shutil.which("planargeo")
    assert found, f"the planargeo console script is not installed (looked in {here.parent} and on PATH)"
    return found


def test_help_lists_every_available_subcommand():
    r = run("--help")
    assert r.returncode == 0
    assert _listed_commands(r.stdout) == EXPECTED_COMMANDS
    assert "report    print a scene's parameters, state and solved quantities" in r.stdout


def test_installed_console_script_help():
    r = subprocess.run([_console_script(), "--help"], capture_output=True, text=True, timeout=120)
    assert r.returncode == 0, r.stderr
    assert r.stdout.startswith("usage: planargeo ")
    assert _listed_commands(r.stdout) == EXPECTED_COMMANDS
    assert r.stderr == ""


def test_unknown_command_exits_nonzero_with_one_line_message():
    r = run("frobnicate")
    assert r.returncode == 2
    assert "unknown command 'frobnicate'" in r.stderr
    assert "Traceback" not in r.stderr


# --------------------------------------------------------------------------- package errors behind the CLI messages
def test_malformed_set_is_a_package_input_error_and_exits_2():
    import pytest

    from planargeo import report
    from planargeo.errors import InputError

    for item in ("phi", "=3", " =1"):
        with pytest.raises(InputError, match=rf"^--set expects NAME=VALUE, got {item!r}$"):
            report.parse_sets([item])
    r = run("report", "two-body", "--set", "phi")
    assert r.returncode == 2
    assert r.stderr.strip() == "planargeo report: error: --set expects NAME=VALUE, got 'phi'"
    assert r.stdout == ""


def test_check_param_unknown_kind_is_a_package_input_error():
    import pytest

    from planargeo.errors import InputError, SceneError
    from planargeo.scenes import check_param

    with pytest.raises(InputError, match=r"^kind must be 'float', 'int' or 'choice', got 'complex'$") as e:
        check_param("x", 1, "complex")
    assert not isinstance(e.value, SceneError)     # a scene-module mistake, not a bad user parameter


def test_bench_out_never_overwrites_other_files(tmp_path):
    """`planargeo bench --out` into a folder of the user's files is refused (one line, status 1) before
    anything runs; a file, /dev/full or a missing parent too."""
    (tmp_path / "notes.md").write_text("mine")
    (tmp_path / "afile").write_text("x")
    for out, words in ((tmp_path, "not a benchmark result"), (tmp_path / "afile", "not a folder"),
                       ("/dev/full", "not a folder"), (tmp_path / "no" / "such", "does not exist")):
        r = subprocess.run([sys.executable, "-m", "planargeo.cli", "bench", "--out", str(out), "--only", "nothing"],
                           capture_output=True, text=True, timeout=120, cwd=Path(__file__).resolve().parents[1])
        assert r.returncode == 1 and "Traceback" not in r.stderr, r.stderr
        assert r.stderr.strip().splitlines() == [r.stderr.strip()] and words in r.stderr, r.stderr
    assert sorted(p.name for p in tmp_path.iterdir()) == ["afile", "notes.md"]
    assert (tmp_path / "notes.md").read_text() == "mine"
