"""The documentation site (``make docs``) in a real browser: the index and a lesson show figures.

``make test`` builds the site before running the tests; the built pages are served
from ``docs/_build/html`` by a throw-away HTTP server on 127.0.0.1.
"""
from __future__ import annotations

import functools
import http.server
import threading
from pathlib import Path

import pytest

from .conftest import ARTIFACTS

pytestmark = pytest.mark.browser

REPO = Path(__file__).resolve().parents[2]
SITE = REPO / "docs" / "_build" / "html"


@pytest.fixture(scope="module")
def site():
    if not (SITE / "index.html").exists():
        pytest.fail(f"{SITE / 'index.html'} is missing: build the site first (make docs)")
    handler = functools.partial(http.server.SimpleHTTPRequestHandler, directory=str(SITE))
    handler.log_message = lambda *a, **k: None
    srv = http.server.ThreadingHTTPServer(("127.0.0.1", 0), handler)
    t = threading.Thread(target=srv.serve_forever, daemon=True)
    t.start()
    try:
        yield f"http://127.0.0.1:{srv.server_address[1]}"
    finally:
        srv.shutdown()
        srv.server_close()


def _figures_loaded(page) -> int:
    """Images (img or inline svg) on the page that actually rendered with a size."""
    return page.evaluate("""() => {
        const imgs = [...document.querySelectorAll('img')].filter(i => i.complete && i.naturalWidth > 50);
        const svgs = [...document.querySelectorAll('svg')].filter(s => s.getBoundingClientRect().width > 100);
        return imgs.length + svgs.length;
    }""")


def test_index_and_a_lesson_show_figures(site, browser):
    ARTIFACTS.mkdir(exist_ok=True)
    page = browser.new_page(viewport={"width": 1300, "height": 1000})
    try:
        page.goto(site + "/index.html", timeout=30_000)
        assert "planargeo" in page.title().lower()
        links = page.locator("a[href*='lessons/'], a[href*='notebooks/']")
        assert links.count() > 0, "the index links to no lesson"
        href = links.first.get_attribute("href")
        page.goto(site + "/" + href.lstrip("./"), timeout=30_000)
        page.wait_for_load_state("load")
        n = _figures_loaded(page)
        page.screenshot(path=str(ARTIFACTS / "docs-lesson.png"))
        assert n >= 1, f"the lesson {href} shows no figure"
        page.goto(site + "/index.html", timeout=30_000)
        gallery = page.locator("a", has_text="allery").first
        assert gallery.count(), "the index links to no gallery"
        gallery.click()
        page.wait_for_load_state("load")
        assert _figures_loaded(page) >= 10, "the gallery page shows fewer than 10 figures"
    finally:
        page.close()
