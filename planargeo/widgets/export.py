"""Exports of what an explorer shows: SVG and PNG files, GIF and MP4 animations, download links.

Every file is the explorer's picture drawn by :func:`planargeo.draw.render.picture_bytes`, written
atomically; the same view gives the same file.
"""
from __future__ import annotations

import base64
import html
import io
import itertools
import os
import re
import shutil
import subprocess
import tempfile
from pathlib import Path

import numpy as np
from PIL import Image

from planargeo.errors import InputError, OutputError
from planargeo.files import atomic_write
from planargeo.widgets.play import MAX_ANIMATION_FRAMES, check_count

__all__ = ["ExportMixin"]

_export_counter = itertools.count(1)


class ExportMixin:
    """Exports for :class:`~planargeo.widgets.base.Explorer` (files, animations, links, the stored PNG)."""

    def _export_path(self, path, ext: str) -> Path:
        if path is None:
            d = self.export_dir or Path.cwd()
            path = Path(d) / f"planargeo-{self.slug}-{os.getpid()}-{next(_export_counter)}.{ext}"
        try:
            path = Path(path)
            special = path.exists() and not path.is_file()
        except TypeError:
            raise InputError(f"path must be a str or os.PathLike naming a file, got {path!r}") from None
        except OSError as e:                             # e.g. a name too long for the file system
            raise OutputError(f"cannot write {path}: {e.strerror or e}") from None
        if special:
            raise OutputError(f"cannot write {path}: it exists and is not a regular file")
        return path

    def _svg_bytes(self) -> bytes:
        from planargeo.draw.render import picture_bytes   # matplotlib, loaded when a file is made

        # fixed element ids (the package's svg.hashsalt) and no date: the same view, the same file
        return re.sub(rb"<dc:date>[^<]*</dc:date>", b"", picture_bytes(self.picture(), "svg"))

    def _png_bytes(self, dpi: float | None = None) -> bytes:
        from planargeo.draw.render import picture_bytes

        # the picture's size is the explorer's in pixels: drawn at 100 dpi
        return picture_bytes(self.picture(), "png", dpi=100.0 * (dpi or self.dpi) / self.dpi)

    def export_svg(self, path=None) -> Path:
        """Write the current view to an SVG file, atomically, and return its path.

        Parameters
        ----------
        path : str or os.PathLike, optional
            The file; default ``planargeo-<slug>-<pid>-<n>.svg`` in ``export_dir`` (or here).

        Returns
        -------
        pathlib.Path
            The file written (absolute).

        Raises
        ------
        InputError
            ``path`` names no file.
        OutputError
            The file cannot be written (no space, no permission, a folder or a device).
        """
        return self._write(self._export_path(path, "svg"), self._svg_bytes())

    def _write(self, path: Path, data: bytes) -> Path:
        """``data`` written to ``path`` atomically; the file is :attr:`last_export`."""
        self.last_export = atomic_write(path, data).resolve()
        return self.last_export

    def export_png(self, path=None) -> Path:
        return self._write(self._export_path(path, "png"), self._png_bytes())

    export_png.__doc__ = (export_svg.__doc__.replace("an SVG file", "a PNG file (at the picture's size)")
                          .replace(".svg", ".png"))

    def _frames_rgb(self, frames: int, fps: int | None = None) -> list[np.ndarray]:
        """RGB images of ``frames`` Play frames at ``fps`` in real time from the shown state (kept)."""
        seconds = self.play_dt * self.play_fps / float(fps or self.play_fps)
        start = dict(self.shown_values)
        state, readout = self.state, dict(self.readout_values)
        out = []
        self._exporting = True
        try:
            for k in range(frames):
                if k and not self._frame(seconds):
                    break
                out.append(np.asarray(Image.open(io.BytesIO(self._png_bytes())).convert("RGB")))
        finally:
            self._exporting = False
            self.set(**start)
            if self.values == start and self._message == "":
                self._safe_redraw()
            else:  # pragma: no cover - the start state is always showable
                self.state, self.readout_values = state, readout
        return out

    def export_animation(self, path=None, *, format: str = "gif", frames: int = 60,
                         fps: int = 20, allow_long: bool = False) -> Path:
        """Write ``frames`` Play frames from the shown state as a GIF or MP4 file, atomically.

        The file plays in real time; the explorer returns to the shown state.  MP4 needs ``ffmpeg``.

        Parameters
        ----------
        path : str or os.PathLike, optional
            The file; default ``planargeo-<slug>-<pid>-<n>.<format>`` in ``export_dir``.
        format : {"gif", "mp4"}
            File format.
        frames : int
            Number of frames (fewer if Play ends first), at most
            :data:`~planargeo.widgets.play.MAX_ANIMATION_FRAMES`.
        fps : int
            Frames per second of the file.
        allow_long : bool
            Opt in to more frames than the limit.

        Returns
        -------
        pathlib.Path
            The animation written (absolute).

        Raises
        ------
        InputError
            No Play, an unknown format, frames / fps not positive integers or beyond the limit.
        OutputError
            The file cannot be written, or MP4 without ffmpeg.
        """
        data = self._animation_bytes(format, frames, fps, allow_long)
        return self._write(self._export_path(path, format), data)

    def _animation_bytes(self, format: str, frames: int, fps: int, allow_long: bool = False) -> bytes:
        if format not in ("gif", "mp4"):
            raise InputError(f"format must be 'gif' or 'mp4', got {format!r}")
        frames = check_count("frames", frames, MAX_ANIMATION_FRAMES, allow_long)
        fps = check_count("fps", fps, 1000, allow_long=None)
        if not self.has_play:
            raise InputError(f"{type(self).__name__} has no animation (it does not define play_step)")
        ffmpeg = shutil.which("ffmpeg")
        if format == "mp4" and ffmpeg is None:
            raise OutputError("mp4 export needs the ffmpeg program, which is not installed "
                              "(install Debian's ffmpeg, or use format='gif')")
        imgs = self._frames_rgb(frames, fps)
        if format == "gif":
            pics = [Image.fromarray(a).quantize(colors=128, method=Image.Quantize.MEDIANCUT)
                    for a in imgs]
            buf = io.BytesIO()
            pics[0].save(buf, format="GIF", save_all=True, append_images=pics[1:],
                         duration=max(1, int(round(1000 / fps))), loop=0)
            return buf.getvalue()
        h, w = imgs[0].shape[:2]
        with tempfile.TemporaryDirectory() as d:
            out = Path(d) / "movie.mp4"
            cmd = [ffmpeg, "-loglevel", "error", "-y", "-f", "rawvideo", "-pix_fmt", "rgb24",
                   "-s", f"{w}x{h}", "-r", str(fps), "-i", "-",
                   "-vf", "pad=ceil(iw/2)*2:ceil(ih/2)*2", "-pix_fmt", "yuv420p",
                   "-vcodec", "libx264", str(out)]
            try:
                r = subprocess.run(cmd, input=b"".join(a.tobytes() for a in imgs),
                                   capture_output=True, timeout=300)
            except (OSError, subprocess.SubprocessError) as e:
                raise OutputError(f"ffmpeg failed: {e}") from None
            if r.returncode != 0 or not out.exists():
                raise OutputError(f"ffmpeg failed: {r.stderr.decode(errors='replace')[-300:]}")
            return out.read_bytes()

    @property
    def has_mp4(self) -> bool:
        """True when MP4 export works here (the ``ffmpeg`` program is installed)."""
        return shutil.which("ffmpeg") is not None

    def _export_clicked(self, kind: str = "svg") -> None:
        """Export button: the file downloaded in the page at once (a page canvas), a link to it
        (to save it again, or where the page cannot), and the file in ``export_dir`` if set."""
        mime = {"svg": "image/svg+xml", "png": "image/png", "gif": "image/gif",
                "mp4": "video/mp4"}[kind]
        try:
            data = {"svg": self._svg_bytes, "png": self._png_bytes}.get(
                kind, lambda: self._animation_bytes(kind, 60, self.play_fps))()
            name, saved = f"planargeo-{self.slug}.{kind}", ""
            if self.export_dir is not None:
                p = self._write(self._export_path(None, kind), data)
                name, saved = p.name, f"saved <code>{html.escape(str(p))}</code> "
            # in the page the file is saved at once (one click); the link stays to save it again
            from planargeo.widgets.canvas import PictureCanvas

            canvas = getattr(self, "canvas", None)
            sent = isinstance(canvas, PictureCanvas)
            if sent:
                canvas.download(name, mime, data)
            href = f"data:{mime};base64,{base64.b64encode(data).decode('ascii')}"
            again = "downloaded; again: " if sent else ""
            self.export_label.value = (
                f"<div style='white-space:nowrap;overflow:hidden;text-overflow:ellipsis'>{again}"
                f"<a download='{html.escape(name)}' href='{href}' class='planargeo-download' "
                f"style='font-weight:bold'>⬇ {html.escape(name)}</a> {saved}</div>")
        except Exception as exc:  # noqa: BLE001
            self.export_label.value = (f"<span style='color:#b00020'>export failed: "
                                       f"{html.escape(str(exc))}</span>")

    def snapshot(self):
        """The shown picture as a still PNG image, stored in a notebook's output (no kernel needed).

        Returns
        -------
        IPython.display.Image

        Examples
        --------
        >>> from planargeo.widgets import ProjectiveExplorer
        >>> img = ProjectiveExplorer(display="agg").snapshot()
        >>> img.format, img.data[:4]
        ('png', b'\x89PNG')
        """
        from IPython.display import Image

        return Image(data=self._png_bytes(), format="png")

    def _repr_mimebundle_(self, **kwargs):
        """The widget view, plus a static PNG of the picture (shown where widgets are not, e.g. GitHub)."""
        bundle = self.widget._repr_mimebundle_(**kwargs)
        data = bundle[0] if isinstance(bundle, tuple) else bundle     # (data, metadata)
        if isinstance(data, dict):
            try:
                data["image/png"] = base64.b64encode(self._png_bytes()).decode("ascii")
            except Exception:  # noqa: BLE001 - the picture is a courtesy, never an error
                pass
        return bundle
