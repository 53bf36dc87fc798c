"""A throw-away Jupyter server (JupyterLab or Voila) and Debian's headless chromium.

Shared by the real-browser tests (``tests/browser``), the browser latency benchmark
(``benchmarks/browser_latency.py``) and the screenshot command (``make screens``).
Everything a server writes (config, settings, workspaces, runtime files) lives in a
temporary directory; news fetching, update checks and the extension manager's network
calls are switched off, and the server listens on 127.0.0.1 only.
"""
from __future__ import annotations

import json
import os
import shutil
import socket
import subprocess
import sys
import time
import urllib.error
import urllib.request
from pathlib import Path

CHROMIUM = "/usr/bin/chromium"
CHROMIUM_ARGS = ["--headless", "--no-sandbox", "--disable-gpu", "--disable-background-networking",
                 "--disable-component-update", "--disable-sync", "--no-first-run",
                 "--disable-dev-shm-usage"]


def _free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


class LabServer:
    """A JupyterLab server on a free port serving ``root`` (token disabled, 127.0.0.1 only).

    Parameters
    ----------
    root : Path
        The folder served (notebooks are copied or written there).
    tmp : Path
        A scratch folder for the server's configuration, settings and log.
    mpl_backend : str
        The kernel's ``MPLBACKEND`` (inline images by default).
    """

    def __init__(self, root: Path, tmp: Path,
                 mpl_backend: str = "module://matplotlib_inline.backend_inline"):
        self.root = root
        self.port = _free_port()
        self.url = f"http://127.0.0.1:{self.port}"
        cfg = tmp / "config"
        settings = tmp / "lab-settings" / "@jupyterlab" / "apputils-extension"
        for d in (cfg, settings, tmp / "runtime", tmp / "workspaces", tmp / "data"):
            d.mkdir(parents=True, exist_ok=True)
        (cfg / "jupyter_server_config.json").write_text(json.dumps({
            "LabApp": {"news_url": None,
                       "check_for_updates_class": "jupyterlab.handlers.announcements.NeverCheckForUpdate",
                       "extension_manager": "readonly",
                       "expose_app_in_browser": True},
            "ServerApp": {"token": "", "password": "", "disable_check_xsrf": True,
                          "open_browser": False},
        }))
        (settings / "notification.jupyterlab-settings").write_text(
            json.dumps({"fetchNews": "false", "checkForUpdates": False}))
        env = dict(os.environ)
        env.update(JUPYTER_CONFIG_DIR=str(cfg), JUPYTER_RUNTIME_DIR=str(tmp / "runtime"),
                   JUPYTERLAB_SETTINGS_DIR=str(tmp / "lab-settings"),
                   JUPYTERLAB_WORKSPACES_DIR=str(tmp / "workspaces"),
                   MPLBACKEND=mpl_backend,
                   PYDEVD_DISABLE_FILE_VALIDATION="1")
        env.pop("JUPYTER_PLATFORM_DIRS", None)
        cmd = [str(Path(sys.executable).parent / "jupyter"), "lab", "--no-browser",
               f"--port={self.port}", "--ip=127.0.0.1", f"--ServerApp.root_dir={root}",
               "--ServerApp.token=", "--ServerApp.password=", "--LabApp.expose_app_in_browser=True"]
        if os.geteuid() == 0:
            cmd.append("--allow-root")
        self.log = open(tmp / "lab.log", "w")
        self.proc = subprocess.Popen(cmd, env=env, stdout=self.log, stderr=subprocess.STDOUT,
                                     cwd=root)
        self._wait()

    def _wait(self, path: str = "/api/status", timeout: float = 60.0) -> None:
        t0 = time.time()
        while time.time() - t0 < timeout:
            if self.proc.poll() is not None:
                raise RuntimeError(f"{type(self).__name__} exited with {self.proc.returncode}; see {self.log.name}")
            try:
                with urllib.request.urlopen(self.url + path, timeout=5) as r:
                    if r.status == 200:
                        return
            except urllib.error.HTTPError:   # the server answers (e.g. Voila redirects the API)
                return
            except OSError:
                time.sleep(0.3)
        raise RuntimeError(f"{type(self).__name__} did not start within {timeout} s; see {self.log.name}")

    def stop(self) -> None:
        self.proc.terminate()
        try:
            self.proc.wait(timeout=15)
        except subprocess.TimeoutExpired:
            self.proc.kill()
            self.proc.wait()
        self.log.close()




class VoilaServer(LabServer):
    """Voila serving one notebook as a web app (no code cells) on a free port, 127.0.0.1 only.

    Parameters
    ----------
    notebook : Path
        The app notebook.
    tmp : Path
        Scratch folder for configuration and the log.
    """

    def __init__(self, notebook: Path, tmp: Path, app_config: bool = True):
        self.root = notebook.parent
        self.port = _free_port()
        self.url = f"http://127.0.0.1:{self.port}"
        for d in (tmp / "config", tmp / "runtime", tmp / "data"):
            d.mkdir(parents=True, exist_ok=True)
        env = dict(os.environ)
        env.update(JUPYTER_CONFIG_DIR=str(tmp / "config"), JUPYTER_RUNTIME_DIR=str(tmp / "runtime"),
                   MPLBACKEND="module://matplotlib_inline.backend_inline",
                   PYDEVD_DISABLE_FILE_VALIDATION="1")
        env.pop("JUPYTER_PLATFORM_DIRS", None)
        cmd = voila_command(notebook, self.port, app_config=app_config)
        self.log = open(tmp / "voila.log", "w")
        self.proc = subprocess.Popen(cmd, env=env, stdout=self.log, stderr=subprocess.STDOUT,
                                     cwd=self.root)
        self._wait(path="/api/status", timeout=90.0)


def voila_command(notebook: Path, port: int | None = None, app_config: bool = True) -> list[str]:
    """The command line ``make app`` runs: Voila on ``notebook``, 127.0.0.1 only, no browser.

    With ``app_config``, the app's configuration (``app/config/voila.py``: seats, culling,
    the offline page template); without it, the caller's own (``JUPYTER_CONFIG_DIR``).
    """
    cmd = [str(Path(sys.executable).parent / "voila"), str(notebook), "--no-browser",
           "--Voila.ip=127.0.0.1", "--theme=light"]
    if app_config:
        cmd.append(f"--Voila.config_file_paths={Path(__file__).resolve().parents[1] / 'app' / 'config'}")
    if port is not None:
        cmd.append(f"--port={port}")
    return cmd


def launch_chromium(playwright):
    """Debian's headless chromium with the flags this closed network needs."""
    return playwright.chromium.launch(executable_path=CHROMIUM, args=CHROMIUM_ARGS)
