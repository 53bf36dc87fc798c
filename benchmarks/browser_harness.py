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
                          "open_browser": False,       # as make lab (scripts/lab.py):
                          "kernel_websocket_connection_class":
                              "planargeo.widgets.server.PromptKernelConnection"},
        }))
        # as make lab: the tab's busy icon off (planargeo.widgets.server.quiet_page_config)
        (cfg / "jupyter_server_config.py").write_text(
            "from planargeo.widgets.server import quiet_page_config\n"
            "c.ServerApp.tornado_settings = {'page_config_hook': quiet_page_config}\n")
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


# --------------------------------------------------------------------------- the page renderer alone
_HARNESS_HTML = """<!doctype html>
<html><head><meta charset="utf-8"><title>planargeo canvas harness</title>
<style>body {{ margin: 0; background: white; }} {css}</style></head>
<body><div id="host"></div>
<script type="module">
import mod from "/canvas.js";
let handlers = {{}}, data = {{}}, cleanup = null;
window.sent = [];
const model = {{
  get: (k) => data[k],
  set: (k, v) => {{ data[k] = v; }},
  save_changes: () => {{}},
  on: (ev, cb) => {{ (handlers[ev] = handlers[ev] || []).push(cb); }},
  off: (ev, cb) => {{ handlers[ev] = (handlers[ev] || []).filter((f) => f !== cb); }},
  send: (m) => {{ window.sent.push(m); }},
}};
function rel(n, r0) {{
  const r = n.getBoundingClientRect();
  return [r.left - r0.left, r.top - r0.top, r.right - r0.left, r.bottom - r0.top];
}}
function advance(t) {{
  // the text's extent along the baseline from its characters' advances (no glyph ink),
  // in the SVG's pixels: [left, right]
  const n = t.getNumberOfChars();
  if (!n) return null;
  const a = t.getExtentOfChar(0), b = t.getExtentOfChar(n - 1), m = t.getCTM();
  return [m.a * a.x + m.e, m.a * (b.x + b.width) + m.e];
}}
window.measure = () => {{
  const svg = document.querySelector(".pg-canvas svg");
  const r0 = svg.getBoundingClientRect();
  const els = [...svg.querySelectorAll(".pg-el")].map((g) => ({{
    id: g.dataset.id, role: g.dataset.role === undefined ? null : g.dataset.role,
    nodes: [...g.children].map((n) => ({{
      tag: n.tagName, box: rel(n, r0), text: n.tagName === "text" ? n.textContent : null,
      advance: n.tagName === "text" ? advance(n) : null,
      fill: n.getAttribute("fill"), stroke: n.getAttribute("stroke"),
    }})),
  }}));
  const frame = svg.querySelector(".pg-frame");
  return {{ size: [r0.width, r0.height], plot: frame ? rel(frame, r0) : null, elements: els,
           handles: [...svg.querySelectorAll("circle.pg-handle")].map((c) => ({{
             id: c.dataset.handle, box: rel(c, r0) }})) }};
}};
// a new view of a widget whose synced state is `state` (what a page gets when it opens)
window.openView = (state) => {{
  if (cleanup) cleanup();
  handlers = {{}};
  data = {{ ...state }};
  window.sent = [];
  const host = document.getElementById("host");
  host.textContent = "";
  cleanup = mod.render({{ model, el: host }}) || null;
  return window.measure();
}};
// a message from the kernel (a picture's update, an ack): what the view then shows
window.deliver = (msg) => {{
  for (const cb of handlers["msg:custom"] || []) cb(msg, []);
  return window.measure();
}};
window.harnessReady = true;
</script></body></html>
"""


def serve_files(files: dict):
    """A threaded HTTP server on 127.0.0.1 (a free port) answering GETs from ``files``: path -> (bytes, type)."""
    import http.server
    import threading

    class Handler(http.server.BaseHTTPRequestHandler):
        def do_GET(self):  # noqa: N802 - http.server's name
            body, kind = files.get(self.path.split("?")[0], (None, None))
            if body is None:
                self.send_error(404)
                return
            self.send_response(200)
            self.send_header("Content-Type", kind + "; charset=utf-8")
            self.send_header("Content-Length", str(len(body)))
            self.end_headers()
            self.wfile.write(body)

        def log_message(self, *args):
            pass

    server = http.server.ThreadingHTTPServer(("127.0.0.1", 0), Handler)
    threading.Thread(target=server.serve_forever, daemon=True).start()
    return server


class CanvasHarness:
    """The page renderer (``canvas.js``) alone, in a static page served from 127.0.0.1.

    The page loads the package's own ``canvas.js`` with a tiny stand-in for the
    anywidget model (``get``/``set``/``on``/``off``/``send``; what the page sends is
    kept in ``window.sent``) and the widget's CSS, so that pictures can be drawn
    without a kernel, many in one page, through the widget's own protocol:
    ``window.openView(state)`` opens a view of a widget whose synced state is ``state``
    (``PictureCanvas.get_state()``), ``window.deliver(msg)`` hands it a message from
    the kernel (``{"type": "update", **canvas.last_update}``).  Both answer what the
    page then shows (``window.measure()``): for every
    element (``.pg-el``) its id, role and each SVG node's tag, box (pixels from the
    SVG's top left), text (with its advance: left and right ends along the baseline)
    and colours; the plot area's box; the handles' boxes.

    Use as a context manager; ``url`` is the page's address.
    """

    def __init__(self):
        from planargeo.widgets.canvas import PictureCanvas

        # anywidget turns the class's _esm / _css into file contents (str() is the text)
        js = str(PictureCanvas._esm).encode()
        html = _HARNESS_HTML.format(css=str(PictureCanvas._css)).encode()
        files = {"/": (html, "text/html"), "/canvas.js": (js, "text/javascript")}

        self.server = serve_files(files)
        self.url = f"http://127.0.0.1:{self.server.server_address[1]}/"

    def open(self, browser, width: int = 1200, height: int = 900):
        """A new page of ``browser`` (playwright) showing the harness, ready for ``window.show``."""
        page = browser.new_page(viewport={"width": width, "height": height})
        page.goto(self.url)
        page.wait_for_function("window.harnessReady === true", timeout=30_000)
        return page

    def close(self) -> None:
        self.server.shutdown()
        self.server.server_close()

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()
