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
