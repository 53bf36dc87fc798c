"""The console script: subcommands listed, unknown ones rejected with a one-line message."""
import subprocess
import sys

from planargeo import cli


def run(*args):
    return subprocess.run([sys.executable, "-m", "planargeo.cli", *args],
                          capture_output=True, text=True, timeout=120)


def test_help_lists_every_available_subcommand():
    r = run("--help")
    assert r.returncode == 0
    for name in cli._available():
        assert name in r.stdout


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
