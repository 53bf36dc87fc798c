"""``make app`` for a class: the seat limit turns the next visitor away, and the page cannot run code.

The server is configured as ``make app`` configures it (``app/config/voila.py``), with one
seat, on a small notebook with a widget (the app itself takes tens of seconds to load):

* visitor 1 opens the page in Chromium and gets the widget (a kernel, one seat taken);
* visitor 2 (another browser context) gets HTTP 503 and the page "The class is full";
* visitor 1 closes the page (the page asks Voila to shut its kernel down), and visitor 2,
  reloading, gets the notebook;
* a client that sends an ``execute_request`` on a visitor's kernel channel gets nothing
  executed (a marker file is never written), while an allowed request on the same
  channel is answered.
"""
from __future__ import annotations

import asyncio
import concurrent.futures
import json
import re
import time
import urllib.error
import urllib.request
import uuid
from pathlib import Path

import nbformat
import pytest

from .conftest import CHROMIUM

pytestmark = pytest.mark.browser

SLIDER = "import ipywidgets as w\nw.IntSlider(value=3, description='seat test')"


def _seat_notebook(tmp_path) -> Path:
    nb = nbformat.v4.new_notebook()
    nb.cells = [nbformat.v4.new_code_cell(SLIDER)]
    nb.metadata["kernelspec"] = {"name": "python3", "display_name": "Python 3", "language": "python"}
    root = tmp_path / "nb"
    root.mkdir()
    nbformat.write(nb, root / "seat.ipynb")
    return root / "seat.ipynb"


@pytest.fixture()
def one_seat(tmp_path):
    if not Path(CHROMIUM).exists():
        pytest.skip(f"{CHROMIUM} not found")
    pytest.importorskip("playwright.sync_api", reason="playwright is not installed")
    from classroom import serve_app

    server = serve_app(tmp_path, seats=1, notebook=_seat_notebook(tmp_path))
    try:
        yield server
    finally:
        server.stop()


def _status(url: str) -> int:
    try:
        with urllib.request.urlopen(url, timeout=45) as r:
            r.read()
            return r.status
    except urllib.error.HTTPError as e:
        return e.code


def test_an_idle_visitor_seat_is_culled_and_comes_back(tmp_path):
    """With 1 seat and a 3-s idle time: visitor 1 in, visitor 2 turned away, then (culled) let in."""
    from classroom import serve_app

    server = serve_app(tmp_path, seats=1, idle=3, cull_interval=1, notebook=_seat_notebook(tmp_path))
    try:
        url = server.url + "/"
        assert _status(url) == 200           # a kernel, the seat taken (no page keeps it busy)
        assert _status(url) == 503
        deadline = time.monotonic() + 30
        while (got := _status(url)) == 503 and time.monotonic() < deadline:
            time.sleep(1.0)
        assert got == 200, "the idle kernel was not culled"
        assert "Culling 'idle' kernel" in Path(server.log.name).read_text()
    finally:
        server.stop()


def _visit(browser, url):
    ctx = browser.new_context()
    page = ctx.new_page()
    resp = page.goto(url, wait_until="domcontentloaded", timeout=45_000)
    return ctx, page, resp


def test_visitor_beyond_the_seats_gets_the_class_is_full_page(one_seat, browser):
    url = one_seat.url + "/"
    b = browser                           # the session's chromium (conftest.py)
    ctx1, page1, resp1 = _visit(b, url)
    assert resp1.status == 200
    page1.locator(".widget-slider").filter(has_text="seat test").wait_for(timeout=45_000)

    ctx2, page2, resp2 = _visit(b, url)
    assert resp2.status == 503
    assert resp2.headers.get("retry-after") == "60"
    assert page2.locator("h1").inner_text() == "The class is full"
    body = page2.locator("body").inner_text()
    assert "1 visitor," in body and "reload" in body
    assert page2.locator(".widget-slider").count() == 0

    page1.close(run_before_unload=True)   # Voila's page shuts its kernel down on leaving
    deadline = time.monotonic() + 25
    while True:
        resp2 = page2.reload(wait_until="domcontentloaded", timeout=45_000)
        if resp2.status == 200 or time.monotonic() > deadline:
            break
        time.sleep(1.0)
    assert resp2.status == 200, "the seat did not come back after visitor 1 left"
    page2.locator(".widget-slider").filter(has_text="seat test").wait_for(timeout=45_000)
    ctx1.close()
    ctx2.close()


def _message(msg_type: str, content: dict) -> str:
    return json.dumps({"header": {"msg_id": uuid.uuid4().hex, "username": "visitor", "session": uuid.uuid4().hex,
                                  "msg_type": msg_type, "version": "5.3", "date": "2026-01-01T00:00:00Z"},
                       "parent_header": {}, "metadata": {}, "content": content, "channel": "shell",
                       "buffers": []})


async def _talk(ws_url: str, marker: Path) -> list[str]:
    from tornado.websocket import websocket_connect

    ws = await websocket_connect(ws_url)
    code = f"open({str(marker)!r}, 'w').write('executed')"
    ws.write_message(_message("execute_request", {"code": code, "silent": False, "store_history": False,
                                                  "user_expressions": {}, "allow_stdin": False,
                                                  "stop_on_error": True}))
    ws.write_message(_message("kernel_info_request", {}))
    replies = []
    t0 = time.monotonic()
    while time.monotonic() - t0 < 15 and "kernel_info_reply" not in replies:
        msg = await asyncio.wait_for(ws.read_message(), 15)
        if msg is None:
            break
        if isinstance(msg, str):
            replies.append(json.loads(msg)["header"]["msg_type"])
    await asyncio.sleep(2.0)            # time for an execute_request to run, had it been let through
    ws.close()
    return replies


def test_messages_from_the_page_cannot_execute_code(one_seat, tmp_path):
    with urllib.request.urlopen(one_seat.url + "/", timeout=45) as r:   # a visitor: one kernel
        html = r.read().decode()
    kernel = re.search(r'"kernelId": *"([0-9a-f-]+)"', html).group(1)
    marker = tmp_path / "executed.txt"
    ws = one_seat.url.replace("http", "ws") + f"/api/kernels/{kernel}/channels"
    # its own thread: the session's Playwright keeps an event loop in this one
    with concurrent.futures.ThreadPoolExecutor(1) as pool:
        replies = pool.submit(asyncio.run, _talk(ws, marker)).result()
    assert "kernel_info_reply" in replies          # the channel works: allowed requests are answered
    assert "execute_reply" not in replies and "execute_input" not in replies
    assert not marker.exists()


def test_make_app_passes_the_configuration_the_seats_and_a_token_off_loopback():
    """``make app`` runs Voila with app/config (the seat limit tested above), and a token unless on 127.0.0.1."""
    import shlex
    import subprocess
    import sys

    root = Path(__file__).resolve().parents[2]

    def dry(*extra):
        out = subprocess.run(["make", "-s", "-n", "app", f"BIN={Path(sys.executable).parent}", "STAMP=Makefile",
                              *extra], cwd=root, capture_output=True, text=True, check=True).stdout
        return shlex.split(out.replace("\\\n", " "))

    local = dry()
    assert "--Voila.config_file_paths=app/config" in local
    assert (root / "app" / "config" / "voila.py").is_file()
    assert "--Voila.ip=127.0.0.1" in local and "--token" not in local
    lan = dry("APP_IP=0.0.0.0", "APP_VISITORS=3", "APP_IDLE=60")
    assert "--Voila.ip=0.0.0.0" in lan and "--token" in lan
    assert "--ClassroomKernelManager.max_kernels=3" in lan
    assert "--MappingKernelManager.cull_idle_timeout=60" in lan
