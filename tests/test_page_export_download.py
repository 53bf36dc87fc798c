"""An export button in the page: one click saves the file (the bytes go to the page in a message).

No browser here: the canvas's messages are caught (the page's side, the Blob and the saved file,
is tests/browser/test_page_student.py).  The message carries the very bytes ``export_svg`` /
``export_png`` write, under the name the link shows; with ``export_dir`` the file is also written
there; only the view that last spoke to the kernel is asked to save it.
"""
from __future__ import annotations

import base64

import pytest

from planargeo.errors import InputError
from planargeo.widgets import ProjectiveExplorer
from planargeo.widgets.canvas import PictureCanvas


def _page_explorer(**kw):
    ex = ProjectiveExplorer(display="page", **kw)
    sent = []
    ex.canvas.send = lambda m, *a, **k: sent.append(m)
    return ex, sent


@pytest.mark.parametrize("kind, mime, magic", [("svg", "image/svg+xml", b"<?xml"),
                                               ("png", "image/png", b"\x89PNG\r\n\x1a\n")])
def test_one_click_sends_the_file_to_the_page(kind, mime, magic, tmp_path):
    ex, sent = _page_explorer()
    ex.canvas._on_msg(None, {"type": "ping", "seq": 1, "client": "view-b"}, None)   # the view last used
    del sent[:]
    {"svg": ex.export_button, "png": ex.export_png_button}[kind].click()
    downloads = [m for m in sent if m["type"] == "download"]
    assert len(downloads) == 1
    m = downloads[0]
    data = base64.b64decode(m["data"])
    assert m["name"] == f"planargeo-{ex.slug}.{kind}" and m["mime"] == mime and m["client"] == "view-b"
    assert data.lstrip().startswith(magic)
    ref = ex.export_svg(tmp_path / "ref.svg") if kind == "svg" else ex.export_png(tmp_path / "ref.png")
    assert data == ref.read_bytes()
    assert "downloaded" in ex.export_label.value and f"⬇ {m['name']}" in ex.export_label.value


def test_with_an_export_dir_the_file_is_also_written_there(tmp_path):
    ex, sent = _page_explorer(export_dir=tmp_path)
    ex.export_button.click()
    (m,) = [m for m in sent if m["type"] == "download"]
    files = list(tmp_path.iterdir())
    assert [p.name for p in files] == [m["name"]]
    assert files[0].read_bytes() == base64.b64decode(m["data"])


def test_without_a_page_canvas_there_is_the_link_only():
    ex = ProjectiveExplorer(display="agg")
    ex.export_button.click()
    assert "downloaded" not in ex.export_label.value and "<a download=" in ex.export_label.value


def test_a_bad_name_or_data_is_refused_by_name():
    c = PictureCanvas()
    with pytest.raises(InputError, match="name must be a file name"):
        c.download("../x.svg", "image/svg+xml", b"<svg/>")
    with pytest.raises(InputError, match="data must be bytes"):
        c.download("x.svg", "image/svg+xml", "<svg/>")
