"""The servers ``make lab`` and ``make app`` start send kernel messages at once (TCP_NODELAY).

The effect is measured, not asserted here: ``benchmarks/page_ab.py`` A/B's it against Jupyter's
default connection (JupyterLab, 10-link chain, 2026-11-27: empty round trip 26 → 19 ms, drag step
60 → 38 ms). These tests check that both servers are configured with it, and that ``make lab``
switches off JupyterLab's busy icon in the browser tab.
"""
from __future__ import annotations

import json
import os
import runpy
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
NAME = "planargeo.widgets.server.PromptKernelConnection"

jupyter_server = pytest.importorskip("jupyter_server")


def test_the_connection_is_jupyters_with_connect_overridden():
    from jupyter_server.services.kernels.connection.channels import ZMQChannelsWebsocketConnection
    from traitlets.utils.importstring import import_item

    cls = import_item(NAME)                       # the name the configurations give resolves
    assert issubclass(cls, ZMQChannelsWebsocketConnection)
    assert cls.connect is not ZMQChannelsWebsocketConnection.connect


def test_make_lab_passes_it_first_so_the_caller_can_override_it():
    lab = runpy.run_path(str(ROOT / "scripts" / "lab.py"), run_name="lab")
    assert lab["PROMPT"] == f"--ServerApp.kernel_websocket_connection_class={NAME}"


def _make_lab_server(tmp_path, *argv) -> dict:
    """What ``scripts/lab.py``'s server (built, not started, in a fresh process) is configured with."""
    tmp_path.mkdir(exist_ok=True)
    code = ("import json, runpy, sys; lab = runpy.run_path(sys.argv[1], run_name='lab')\n"
            "app = lab['make_server'](sys.argv[3:], 'a' * 48)\n"
            "hook = app.web_app.settings.get('page_config_hook')\n"
            "print(json.dumps({'connection': app.kernel_websocket_connection_class.__module__ + '.' +\n"
            "                  app.kernel_websocket_connection_class.__name__, 'ip': app.ip,\n"
            "                  'page': hook(None, {'disabledExtensions': ['x']}) if hook else None}))\n")
    env = {k: v for k, v in os.environ.items() if not k.startswith("JUPYTER")}
    env.update(JUPYTER_CONFIG_DIR=str(tmp_path / "config"), JUPYTER_RUNTIME_DIR=str(tmp_path / "runtime"),
               JUPYTER_DATA_DIR=str(tmp_path / "data"))
    r = subprocess.run([sys.executable, "-c", code, str(ROOT / "scripts" / "lab.py"), str(tmp_path),
                        f"--ServerApp.root_dir={tmp_path}", "--ServerApp.port=0", "--no-browser", *argv],
                       capture_output=True, text=True, timeout=120, env=env, cwd=ROOT)
    assert r.returncode == 0, r.stderr[-3000:]
    return json.loads(r.stdout.strip().splitlines()[-1])


def test_make_lab_serves_prompt_messages_and_no_busy_icon(tmp_path):
    got = _make_lab_server(tmp_path)
    assert got["connection"] == NAME and got["ip"] == "127.0.0.1"
    # JupyterLab swaps and fetches the tab's icon at every busy and idle message (twice per step)
    assert got["page"]["disabledExtensions"] == ["x", "@jupyterlab/application-extension:faviconbusy"]
    # the caller may still choose Jupyter's own connection (PROMPT comes first on the command line)
    own = "jupyter_server.services.kernels.connection.channels.ZMQChannelsWebsocketConnection"
    assert _make_lab_server(tmp_path / "own", f"--ServerApp.kernel_websocket_connection_class={own}")[
        "connection"] == own


def test_quiet_page_config_adds_the_busy_icon_once():
    from planargeo.widgets.server import QUIET_LAB, quiet_page_config

    assert quiet_page_config(None, {})["disabledExtensions"] == list(QUIET_LAB)
    again = quiet_page_config(None, {"disabledExtensions": list(QUIET_LAB), "other": 1})
    assert again == {"disabledExtensions": list(QUIET_LAB), "other": 1}


def test_make_app_configures_voila_with_it(monkeypatch):
    from traitlets.config import Config

    monkeypatch.setenv("JUPYTER_PATH", "")        # the configuration extends it: undone after the test
    c = Config()
    runpy.run_path(str(ROOT / "app" / "config" / "voila.py"), init_globals={"get_config": lambda: c})
    assert c.Voila.kernel_websocket_connection_class == NAME
