"""The servers ``make lab`` and ``make app`` start send kernel messages at once (TCP_NODELAY).

The effect is measured, not asserted here: ``benchmarks/page_ab.py`` A/B's it against Jupyter's
default connection (JupyterLab, 10-link chain, 2026-11-27: empty round trip 26 → 19 ms, drag step
60 → 38 ms). These tests check that both servers are configured with it.
"""
from __future__ import annotations

import runpy
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
    assert "argv=[PROMPT, *argv" in (ROOT / "scripts" / "lab.py").read_text()


def test_make_app_configures_voila_with_it(monkeypatch):
    from traitlets.config import Config

    monkeypatch.setenv("JUPYTER_PATH", "")        # the configuration extends it: undone after the test
    c = Config()
    runpy.run_path(str(ROOT / "app" / "config" / "voila.py"), init_globals={"get_config": lambda: c})
    assert c.Voila.kernel_websocket_connection_class == NAME
