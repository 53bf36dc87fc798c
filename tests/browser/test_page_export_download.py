"""One click on an explorer's SVG or PNG button saves the file, in Voila and in JupyterLab.

A real kernel draws a :class:`~planargeo.widgets.ProjectiveExplorer` in the page; the test clicks
its SVG and PNG buttons once each and waits for chromium's download: its name is the one the
explorer's link shows, and its bytes are a whole SVG document (parsed) or PNG image (opened, of
the figure's size).  No request leaves 127.0.0.1 (the file travels through the widget's own
channel and a Blob).
"""
from __future__ import annotations

import io
import re
import xml.etree.ElementTree as ET

import nbformat
import pytest

from .conftest import ARTIFACTS, VoilaServer, open_in_lab

pytestmark = pytest.mark.browser

CODE = "from planargeo.widgets import ProjectiveExplorer\nProjectiveExplorer()"


def _notebook(path):
    nb = nbformat.v4.new_notebook(cells=[nbformat.v4.new_code_cell(CODE)])
    nb.metadata["kernelspec"] = {"name": "python3", "display_name": "Python 3", "language": "python"}
    nbformat.write(nb, path)


def _local(url: str) -> bool:
    return bool(re.match(r"^(https?|wss?)://127\.0\.0\.1(:\d+)?/", url)) or url.startswith(
        ("data:", "blob:", "about:"))


def _downloads(page, where: str, tmp_path) -> None:
    from PIL import Image

    from planargeo.widgets import ProjectiveExplorer

    slug, size = ProjectiveExplorer.slug, ProjectiveExplorer(display="agg").figure_px
    ex = page.locator(".planargeo-explorer").first
    ex.locator("svg .pg-frame").first.wait_for(state="attached", timeout=240_000)
    ex.scroll_into_view_if_needed()
    try:
        for kind in ("svg", "png"):
            button = ex.locator("button", has_text=re.compile(rf"^\s*{kind.upper()}\s*$")).first
            with page.expect_download(timeout=60_000) as info:
                button.click()
            d = info.value
            assert d.suggested_filename == f"planargeo-{slug}.{kind}", (where, d.suggested_filename)
            path = tmp_path / f"{where}-{d.suggested_filename}"
            d.save_as(path)
            data = path.read_bytes()
            if kind == "svg":
                assert ET.fromstring(data).tag.endswith("svg"), where
            else:
                img = Image.open(io.BytesIO(data))
                assert img.format == "PNG" and abs(img.size[0] - size[0]) <= 2, (where, img.size, size)
    except Exception:
        ARTIFACTS.mkdir(exist_ok=True)
        page.screenshot(path=str(ARTIFACTS / f"export-download-{where}.png"))
        raise


def test_one_click_downloads_in_voila(browser, tmp_path):
    nb = tmp_path / "export.ipynb"
    _notebook(nb)
    server = VoilaServer(nb, tmp_path / "voila")
    page = browser.new_page(viewport={"width": 1400, "height": 1000}, accept_downloads=True)
    requests: list[str] = []
    page.on("request", lambda r: requests.append(r.url))
    try:
        page.goto(server.url, wait_until="domcontentloaded", timeout=120_000)
        _downloads(page, "voila", tmp_path)
    finally:
        page.close()
        server.stop()
    assert requests and not [u for u in requests if not _local(u)]


def test_one_click_downloads_in_jupyterlab(lab, browser, tmp_path):
    _notebook(lab.root / "export.ipynb")
    page = browser.new_page(viewport={"width": 1400, "height": 1000}, accept_downloads=True)
    requests: list[str] = []
    page.on("request", lambda r: requests.append(r.url))
    try:
        open_in_lab(page, lab, "export.ipynb")
        _downloads(page, "jupyterlab", tmp_path)
    finally:
        page.close()
    assert requests and not [u for u in requests if not _local(u)]
