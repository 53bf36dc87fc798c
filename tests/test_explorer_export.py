"""Export of an explorer's view (SVG, PNG) and animation (GIF, MP4): valid files, atomic, downloads."""
from __future__ import annotations

import base64
import io
import re
import shutil
import xml.etree.ElementTree as ET
from pathlib import Path

import pytest
from PIL import Image

from planargeo.errors import InputError, OutputError
import planargeo.widgets as widgets
from planargeo.widgets import ProjectiveExplorer

from test_explorer_drag_play import Dot

PNG_MAGIC = b"\x89PNG\r\n\x1a\n"


def test_svg_and_png_files_are_valid_and_at_the_figure_size(tmp_path):
    ex = ProjectiveExplorer(display="agg")
    svg = ex.export_svg(tmp_path / "view.svg")
    assert ET.parse(svg).getroot().tag.endswith("svg")
    png = ex.export_png(tmp_path / "view.png")
    assert png.read_bytes()[:8] == PNG_MAGIC
    with Image.open(png) as im:
        assert im.size == ex.figure_px and im.size[0] >= 560


def test_gif_has_the_frames_and_leaves_the_view_as_it_was(tmp_path):
    ex = Dot(display="agg")
    before = dict(ex.values)
    p = ex.export_animation(tmp_path / "a.gif", frames=5, fps=10)
    with Image.open(p) as im:
        assert im.format == "GIF" and im.n_frames == 5 and im.size == ex.figure_px
        assert im.info["duration"] == 100
    assert ex.values == before and ex.readout_values["x"] == before["x"]


def test_gif_stops_when_play_ends(tmp_path):
    ex = Dot(display="agg", x=0.9)
    p = ex.export_animation(tmp_path / "a.gif", frames=50)
    with Image.open(p) as im:
        assert im.n_frames == 3                        # 0.9, 0.95, 1.0; 1.05 ends Play


@pytest.mark.skipif(shutil.which("ffmpeg") is None, reason="ffmpeg is not installed (MP4 export needs it)")
def test_mp4_is_written_with_ffmpeg(tmp_path):
    ex = Dot(display="agg")
    p = ex.export_animation(tmp_path / "a.mp4", format="mp4", frames=4)
    assert b"ftyp" in p.read_bytes()[:32]


@pytest.mark.skipif(shutil.which("ffmpeg") is not None, reason="ffmpeg is installed")
def test_mp4_without_ffmpeg_is_a_clear_output_error(tmp_path):
    ex = Dot(display="agg")
    with pytest.raises(OutputError, match="ffmpeg"):
        ex.export_animation(tmp_path / "a.mp4", format="mp4", frames=2)
    assert not (tmp_path / "a.mp4").exists()


def test_animation_arguments_are_checked_by_name(tmp_path):
    ex = Dot(display="agg")
    with pytest.raises(InputError, match="format"):
        ex.export_animation(tmp_path / "a.avi", format="avi")
    with pytest.raises(InputError, match="frames"):
        ex.export_animation(tmp_path / "a.gif", frames=0)
    with pytest.raises(InputError, match="has no animation"):
        ProjectiveExplorer(display="agg").export_animation(tmp_path / "a.gif")


def test_a_failed_export_leaves_the_old_file(tmp_path):
    ex = Dot(display="agg")
    target = tmp_path / "a.gif"
    target.write_bytes(b"old")
    with pytest.raises(InputError):
        ex.export_animation(target, frames=-1)
    assert target.read_bytes() == b"old"
    with pytest.raises(OutputError, match="cannot write /dev/full"):
        ex.export_png("/dev/full")
    assert not list(tmp_path.glob(".*.tmp"))          # no temporary file left behind


def _link(label_html):
    m = re.search(r"<a download='([^']+)' href='data:([^;]+);base64,([^']+)'", label_html)
    assert m, label_html[:300]
    return m.group(1), m.group(2), base64.b64decode(m.group(3))


@pytest.mark.parametrize("kind, mime, check", [
    ("svg", "image/svg+xml", lambda b: b.lstrip().startswith(b"<?xml")),
    ("png", "image/png", lambda b: b[:8] == PNG_MAGIC),
    ("gif", "image/gif", lambda b: b[:6] == b"GIF89a"),
])
def test_buttons_give_a_download_link_and_write_nothing_on_the_server(kind, mime, check, tmp_path,
                                                                        monkeypatch):
    monkeypatch.chdir(tmp_path)
    ex = Dot(display="agg")
    button = {"svg": ex.export_button, "png": ex.export_png_button, "gif": ex.export_gif_button}[kind]
    button.click()
    name, got_mime, data = _link(ex.export_label.value)
    assert name == f"planargeo-explorer.{kind}" and got_mime == mime and check(data)
    assert list(Path(tmp_path).iterdir()) == []


def test_button_with_an_export_dir_saves_there_and_links_the_file(tmp_path):
    ex = Dot(display="agg", export_dir=tmp_path)
    ex.export_png_button.click()
    (p,) = tmp_path.glob("*.png")
    assert str(p) in ex.export_label.value
    assert _link(ex.export_label.value)[2] == p.read_bytes()


def test_notebook_output_carries_a_static_picture():
    ex = ProjectiveExplorer(display="image")
    bundle = ex._repr_mimebundle_()
    data = bundle[0] if isinstance(bundle, tuple) else bundle
    assert "application/vnd.jupyter.widget-view+json" in data
    png = base64.b64decode(data["image/png"])
    with Image.open(io.BytesIO(png)) as im:
        assert im.size == ex.figure_px


@pytest.mark.parametrize("name", sorted(widgets.EXPLORERS))
def test_every_explorer_in_the_page_stores_its_picture_as_png(name):
    """Saved notebooks and the docs show every explorer without a kernel: the output of the page's
    widget carries the picture drawn by the matplotlib renderer (draw/render.py), at the picture's size."""
    from planargeo.draw.render import picture_bytes

    ex = getattr(widgets, name)()
    assert ex.display_mode == "page"
    bundle = ex._repr_mimebundle_()
    data = bundle[0] if isinstance(bundle, tuple) else bundle
    assert "application/vnd.jupyter.widget-view+json" in data
    png = base64.b64decode(data["image/png"])
    assert png == picture_bytes(ex.picture(), "png")
    with Image.open(io.BytesIO(png)) as im:      # (matplotlib truncates 4.6 in × 100 dpi to 459 px)
        assert all(abs(a - b) <= 1 for a, b in zip(im.size, ex.figure_px)), (im.size, ex.figure_px)
