"""`make lab` prints a URL that works when pasted, token included (issue 23.7), and serves
JupyterLab without the tab's busy icon (issue 21).

The test takes the command line `make lab` runs from `make -n lab`, starts it headless (a free
port, --no-browser, Jupyter's configuration and runtime folders in a temporary folder), reads the
URL from what it prints, opens it in headless chromium and checks that JupyterLab shows the tour
notebook, not the login page; the same URL without the token gets the login page.  Then it stops
the server (SIGTERM, as a closed terminal does).
"""
from __future__ import annotations

import json
import os
import re
import shlex
import signal
import socket
import subprocess
import time
import urllib.error
import urllib.request
from pathlib import Path

import pytest

from browser_harness import CHROMIUM  # noqa: F401 - where the tests look for chromium

ROOT = Path(__file__).resolve().parents[2]
#: What a pasted URL looks like: this server, 48 hexadecimal digits of token (secrets.token_hex(24)).
URL = r"http://127\.0\.0\.1:{port}/\S*\?token=([0-9a-f]{{48}})"


def _free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def lab_command() -> list[str]:
    """The command `make lab` runs (its last line in `make -n lab`, which runs nothing)."""
    r = subprocess.run(["make", "-n", "lab"], cwd=ROOT, capture_output=True, text=True, timeout=60)
    assert r.returncode == 0, r.stderr
    lines = [ln for ln in r.stdout.splitlines() if "notebooks/00-tour.ipynb" in ln]
    assert len(lines) == 1, r.stdout
    return shlex.split(lines[0])


class MakeLab:
    """`make lab`'s command, started headless on ``port`` with Jupyter's folders under ``tmp``."""

    def __init__(self, tmp: Path, port: int, config: dict | None = None):
        settings = tmp / "lab-settings" / "@jupyterlab" / "apputils-extension"
        for d in (tmp / "config", settings, tmp / "runtime", tmp / "workspaces", tmp / "data"):
            d.mkdir(parents=True, exist_ok=True)
        if config is not None:
            (tmp / "config" / "jupyter_server_config.json").write_text(json.dumps(config))
        (settings / "notification.jupyterlab-settings").write_text(
            json.dumps({"fetchNews": "false", "checkForUpdates": False}))
        env = {k: v for k, v in os.environ.items() if not k.startswith("JUPYTER")}
        env.update(JUPYTER_CONFIG_DIR=str(tmp / "config"), JUPYTER_RUNTIME_DIR=str(tmp / "runtime"),
                   JUPYTER_DATA_DIR=str(tmp / "data"), JUPYTERLAB_SETTINGS_DIR=str(tmp / "lab-settings"),
                   JUPYTERLAB_WORKSPACES_DIR=str(tmp / "workspaces"), PYDEVD_DISABLE_FILE_VALIDATION="1")
        self.port = port
        self.log = tmp / "make-lab.log"
        self._fh = open(self.log, "w")
        self.proc = subprocess.Popen([*lab_command(), "--no-browser", f"--ServerApp.port={port}"], cwd=ROOT,
                                     env=env, stdout=self._fh, stderr=subprocess.STDOUT, start_new_session=True)

    def output(self) -> str:
        return self.log.read_text(errors="replace")

    def url(self, timeout: float = 240) -> str:
        """The last URL with a token the command printed (what a newcomer would copy)."""
        deadline = time.monotonic() + timeout
        while time.monotonic() < deadline:
            found = [m.group(0) for m in re.finditer(URL.format(port=self.port), self.output())]
            if found and "JupyterLab is running" in self.output():
                return found[-1]
            assert self.proc.poll() is None, f"make lab's command exited with {self.proc.returncode}:\n{self.output()}"
            time.sleep(0.3)
        raise AssertionError(f"no URL with a token within {timeout} s:\n{self.output()}")

    def stop(self) -> int:
        if self.proc.poll() is None:
            os.killpg(self.proc.pid, signal.SIGTERM)
            try:
                self.proc.wait(timeout=30)
            except subprocess.TimeoutExpired:
                os.killpg(self.proc.pid, signal.SIGKILL)
                self.proc.wait()
        self._fh.close()
        return self.proc.returncode


def _tracked_state() -> str:
    """`git status` of the notebooks folder: starting and stopping the lab must change nothing there."""
    return subprocess.run(["git", "status", "--porcelain", "--untracked-files=all", "notebooks"], cwd=ROOT,
                          capture_output=True, text=True, timeout=60).stdout


def test_make_lab_command_keeps_the_token_off_its_command_line():
    cmd = lab_command()
    assert "scripts/lab.py" in cmd[1] and cmd[-1] == "notebooks/00-tour.ipynb"
    assert not any("token" in a.lower() for a in cmd)                  # made at start, not visible in `ps`


def test_make_lab_prints_a_url_that_opens_jupyterlab(tmp_path, browser):
    # ``browser``: the session's chromium (conftest.py); a second Playwright in this thread would clash
    before = _tracked_state()
    port = _free_port()
    lab = MakeLab(tmp_path / "first", port)
    try:
        url = lab.url()
        out = lab.output()
        assert "token=..." not in out, out                                # no masked URL left to mislead
        token = re.fullmatch(URL.format(port=port), url).group(1)
        assert url.startswith(f"http://127.0.0.1:{port}/lab/tree/00-tour.ipynb?")
        # loopback only: the same port on another address of this machine is closed
        try:
            other = {a[4][0] for a in socket.getaddrinfo(socket.gethostname(), None, socket.AF_INET)} - {"127.0.0.1"}
        except OSError:
            other = set()
        for ip in other:
            with socket.socket() as s:
                s.settimeout(2)
                assert s.connect_ex((ip, port)) != 0, f"the lab answers on {ip}"
        ctx, other_ctx = browser.new_context(), browser.new_context()
        try:
            page = ctx.new_page()
            page.goto(url, wait_until="domcontentloaded", timeout=60_000)
            page.wait_for_selector("#jp-main-dock-panel", timeout=180_000)     # JupyterLab's shell
            page.wait_for_selector(".jp-Notebook", timeout=180_000)            # the tour, open
            assert page.locator("input[name=password]").count() == 0
            assert "00-tour.ipynb" in page.locator(".lm-DockPanel-tabBar .lm-TabBar-tabLabel").all_inner_texts()
            # the tab's busy icon is off (planargeo.widgets.server.quiet_page_config): JupyterLab
            # would swap it at every kernel message, twice per drag step
            off = page.evaluate("JSON.parse(document.getElementById('jupyter-config-data').textContent)"
                                ".disabledExtensions")
            assert "@jupyterlab/application-extension:faviconbusy" in off, off
            page.close()
            # without the token: the login page, not the lab
            stranger = other_ctx.new_page()
            stranger.goto(url.split("?")[0], wait_until="domcontentloaded", timeout=60_000)
            stranger.wait_for_selector("input[name=password]", timeout=30_000)
            assert stranger.locator("#jp-main-dock-panel").count() == 0
        finally:
            ctx.close()
            other_ctx.close()
    finally:
        rc = lab.stop()
    # stopped on request: a clean exit, or (its server extensions' shutdown can hang on a loaded
    # machine, then it is killed after 30 s) at least the stop begun on the signal
    assert rc == 0 or (rc == -signal.SIGKILL and "received signal 15, stopping" in lab.output()), \
        lab.output()[-3000:]
    with socket.socket() as s:                                            # stopped: the port is closed
        assert s.connect_ex(("127.0.0.1", port)) != 0
    # a fresh token at every start, and a configuration file cannot switch it off or open the port
    hostile = {"IdentityProvider": {"token": ""}, "ServerApp": {"token": "", "password": "", "ip": "0.0.0.0",
                                                               "allow_remote_access": True}}
    again = MakeLab(tmp_path / "second", _free_port(), config=hostile)
    try:
        token2 = re.fullmatch(URL.format(port=again.port), again.url()).group(1)
        status = f"http://127.0.0.1:{again.port}/api/status"
        with pytest.raises(urllib.error.HTTPError) as refused:
            urllib.request.urlopen(status, timeout=10)
        assert refused.value.code == 403
        with urllib.request.urlopen(f"{status}?token={token2}", timeout=10) as ok:
            assert ok.status == 200
        assert "Serving notebooks" in again.output() and "0.0.0.0" not in again.output(), again.output()
    finally:
        again.stop()
    assert token2 != token
    assert _tracked_state() == before
