"""The front end of an explorer: its picture (:meth:`FrontMixin.picture`, the one description of
what is shown, drawn by the page's :class:`~planargeo.widgets.canvas.PictureCanvas` or as a PNG),
its page widgets, readout and messages.
"""
from __future__ import annotations

import contextlib
import html
import textwrap
from typing import Any

import ipywidgets as W
import numpy as np

from planargeo.draw.picture import FONT_PX
from planargeo.draw.style import EXPLORER_MIN_WIDTH_PX
from planargeo.errors import PlanargeoError
from planargeo.widgets.controls import marks_bold
from planargeo.widgets.readout import explain_html, value_texts

__all__ = ["FrontMixin"]

#: width of a character of a label, in font sizes (the estimate the picture's label placer makes)
_CHAR_EM = 0.6
#: height of a line of text, in pixels
_LINE_PX = 1.25 * FONT_PX


def _inside(xy: np.ndarray, step: float) -> np.ndarray:
    """Points ``step`` apart inside the polygon ``xy`` (even-odd rule)."""
    (u0, v0), (u1, v1) = xy.min(0), xy.max(0)
    gx, gy = np.meshgrid(np.arange(u0, u1, step) + step / 2, np.arange(v0, v1, step) + step / 2)
    px, py = gx.ravel()[:, None], gy.ravel()[:, None]
    (ax, ay), (bx, by) = xy.T, np.roll(xy, -1, 0).T
    with np.errstate(divide="ignore", invalid="ignore"):
        cross = ((ay > py) != (by > py)) & (px < ax + (py - ay) * (bx - ax) / (by - ay))
    return np.column_stack([px[:, 0], py[:, 0]])[np.count_nonzero(cross, axis=1) % 2 == 1]


def _ink(pic) -> np.ndarray:
    """Points (pixels from the plot's lower left) along what the picture draws, a few px apart, and
    over the area of a filled shape (a body covered weighs more than a line crossed)."""
    x0, _x1, y0, _y1 = pic.box
    pts = []
    for el in pic.elements:
        for q in el["parts"]:
            if "xy" in q:
                xy = np.asarray(q["xy"], float).reshape(-1, 2)
                for a, b in zip(xy[:-1], xy[1:]):
                    n = int(min(400, np.hypot(*((b - a) * (pic.kx, pic.ky))) / 4.0)) + 2
                    pts.append(a + np.linspace(0.0, 1.0, n)[:, None] * (b - a))
                if q.get("closed") and el.get("fill") not in (None, "none") and len(xy) > 2 \
                        and not el["id"].startswith("key"):
                    px = _inside((xy - (x0, y0)) * (pic.kx, pic.ky), 4.0)
                    pts.append(px / (pic.kx, pic.ky) + (x0, y0))
            elif q["p"] == "ellipse":
                t = np.linspace(0.0, 2 * np.pi, 48)
                a, b, c, d = q["m"]
                pts.append(np.column_stack([q["x"] + a * np.cos(t) + b * np.sin(t),
                                            q["y"] + c * np.cos(t) + d * np.sin(t)]))
            elif "x" in q:
                pts.append(np.full((4, 2), (q["x"], q["y"]), float))   # a mark, arrow or label
    if not pts:
        return np.zeros((0, 2))
    xy = np.concatenate(pts)
    return np.column_stack([(xy[:, 0] - x0) * pic.kx, (xy[:, 1] - y0) * pic.ky])


#: roles whose paths are bodies (their outline and area): the key never covers them
_BODY_ROLES = ("body", "ground")
#: pixels kept between the key's panel and what it must not cover
_KEY_CLEAR_PX = 3.0
#: radius of a handle's circle in the page (px)
_HANDLE_PX = 8.0


def _keep_clear(pic) -> tuple[np.ndarray, np.ndarray]:
    """What the key must never cover, as points (pixels from the plot's lower left) and a radius
    (px) for each: the handles, the bodies (outline and area), every mark (pins, poles, centres),
    every pole glyph and the arrows' heads."""
    x0, _x1, y0, _y1 = pic.box
    k = np.array([pic.kx, pic.ky])
    pts: list[np.ndarray] = []
    rad: list[np.ndarray] = []

    def add(xy_px, r):
        xy_px = np.asarray(xy_px, float).reshape(-1, 2)
        pts.append(xy_px)
        rad.append(np.full(len(xy_px), float(r)))

    def along(xy_px, step=3.0):
        out = [xy_px[:1]]
        for a, b in zip(xy_px[:-1], xy_px[1:]):
            n = int(min(2000, np.hypot(*(b - a)) / step)) + 2
            out.append(a + np.linspace(0.0, 1.0, n)[:, None] * (b - a))
        return np.concatenate(out)

    for h in pic.handles:
        add((np.array([h["x"], h["y"]], float) - (x0, y0)) * k, _HANDLE_PX + 1.0)
    for el in pic.elements:
        if el["id"].startswith("key ") or el["id"] == "figure message":
            continue
        body = el.get("role") in _BODY_ROLES
        for q in el["parts"]:
            if "xy" in q and body:
                xy = (np.asarray(q["xy"], float).reshape(-1, 2) - (x0, y0)) * k
                if len(xy) > 1:
                    add(along(xy), 0.5 * float(el.get("width") or 2.0) + 1.0)
                if q.get("closed") and len(xy) > 2:
                    add(_inside(xy, 4.0), 3.0)
            elif q["p"] == "mark":
                add((np.array([q["x"], q["y"]], float) - (x0, y0)) * k, 0.5 * float(q.get("size", 6.0)) + 1.0)
            elif q["p"] == "glyph":
                add((np.array([q["x"], q["y"]], float) - (x0, y0)) * k, float(q["r"]) + 2.0)
            elif q["p"] == "arrow":
                foot = (np.array([q["x"], q["y"]], float) - (x0, y0)) * k
                add(along(np.array([foot, foot + (q["dx"], q["dy"])])), 3.0)
    if not pts:
        return np.zeros((0, 2)), np.zeros(0)
    return np.concatenate(pts), np.concatenate(rad)


def _covers(box, pts: np.ndarray, rad: np.ndarray) -> int:
    """How many of the points (with their radii) the box ``(left, bottom, right, top)`` (px) touches."""
    left, bottom, right, top = box
    r = rad + _KEY_CLEAR_PX
    return int(np.count_nonzero((pts[:, 0] > left - r) & (pts[:, 0] < right + r)
                                & (pts[:, 1] > bottom - r) & (pts[:, 1] < top + r)))


class FrontMixin:
    """The front end of :class:`~planargeo.widgets.base.Explorer` (picture, widgets, readout)."""

    def _make_widgets(self) -> None:
        """The readout, message line, buttons and "what is shown" panel (fixed widths and heights)."""
        fig_w = f"{self.figure_px[0]}px"
        self.readout = W.HTML(layout=W.Layout(width=fig_w, max_width="100%", overflow="hidden"))
        self.readout_strings: dict[str, str] = {}
        # two lines reserved (a refusal of two lines moves nothing); a longer one grows the line
        self.message_box = W.HTML(layout=W.Layout(width=fig_w, max_width="100%", min_height="2.8em"))

        def button(description, icon, tooltip, click):
            b = W.Button(description=description, icon=icon, tooltip=tooltip, layout=W.Layout(width="auto"))
            b.on_click(self.guarded(lambda _b: click()))
            return b

        self.reset_button = button("Reset", "undo", "Return every control to its default", self.reset)
        self.export_button, self.export_png_button, self.export_gif_button, self.export_mp4_button = (
            button(kind.upper(), icon, f"Export {what} as {kind.upper()} (downloads the file)",
                   lambda kind=kind: self._export_clicked(kind))
            for kind, icon, what in (("svg", "download", "the current view"),
                                     ("png", "download", "the current view"),
                                     ("gif", "film", "an animation"), ("mp4", "film", "an animation")))
        self.export_label = W.HTML(layout=W.Layout(width="310px", height="1.8em", overflow="hidden"))
        self.explain_box = W.HTML(layout=W.Layout(width=fig_w, max_width="100%"))
        self.explain_box.add_class("planargeo-explain")

    def _figure_inches(self, figsize) -> tuple[float, float]:
        """The picture's size in inches: at least the notebook column's width, same aspect."""
        w, h = (float(v) for v in figsize)
        min_w = EXPLORER_MIN_WIDTH_PX / self.dpi
        if w < min_w:
            w, h = min_w, h * min_w / w
        return w, h

    @property
    def figure_px(self) -> tuple[int, int]:
        """Size of the picture in pixels (``figsize`` × ``dpi``; as shown at 100 % zoom)."""
        w, h = self._figsize
        return int(round(w * self.dpi)), int(round(h * self.dpi))

    def _layout(self):
        wpx, _ = self.figure_px
        if self.display_mode == "image":
            # shown at its native size (text sizes as designed), shrinking with a narrow output area
            self.image = W.Image(format="png", layout=W.Layout(width=f"{wpx}px", height="auto",
                                                               max_width="100%"))
            fig_widget = self.image
        elif self.display_mode == "page":
            self.image = None
            self.canvas = self._make_canvas()
            fig_widget = self.canvas
        else:
            self.image = None
            fig_widget = W.HTML("<i>(picture built off-screen)</i>")
        buttons = W.HBox([self.reset_button, W.HTML("<span style='padding:0 4px'>export</span>"),
                          self.export_button, self.export_png_button]
                         + ([self.export_gif_button] if self.has_play else [])
                         + ([self.export_mp4_button] if self.has_play and self.has_mp4 else []),
                         # the buttons keep their names: a row that does not fit wraps
                         layout=W.Layout(flex_flow="row wrap", width="330px"))
        for b in buttons.children:
            if isinstance(b, W.Button):
                b.layout.flex = "0 0 auto"
        play = ([W.HBox([self.play_control, self.play_speed, self.play_scale, self.play_loop],
                         layout=W.Layout(flex_flow="row wrap", align_items="center"))]
                if self.has_play else [])
        controls = W.VBox(list(self.controls.values()) + play + [buttons, self.export_label],
                          layout=W.Layout(width="330px", min_width="330px", overflow="visible"))
        # controls on the left; on the right a reserved message line and the picture, the readout
        # below them: fixed sizes above the readout, so nothing moves when a message appears.
        # In a column too narrow for both (the explorer's own width: a container query) the
        # picture first, then the controls, then the readout: the figure and its sliders in sight
        # together (the figure scales down to the column, canvas.js)
        figure = W.VBox([self.message_box, fig_widget],
                        layout=W.Layout(align_items="flex-start", overflow="visible", grid_area="figure",
                                        min_width="0"))
        below = W.VBox([self.readout, self.explain_box],
                       layout=W.Layout(align_items="flex-start", overflow="visible", grid_area="readout",
                                       min_width="0"))
        controls.layout.grid_area = "controls"
        head = W.HTML(f"<h4 style='margin:2px'>{html.escape(self.title)}</h4>")
        # (placed by their grid areas: the readout's column second, as before, for code that finds it)
        body = W.HBox([controls, below, figure],
                      layout=W.Layout(display="grid", grid_template_columns="330px minmax(0, max-content)",
                                      grid_template_rows="auto 1fr",
                                      grid_template_areas='"controls figure" "controls readout"',
                                      align_items="flex-start", justify_content="flex-start"))
        body.add_class("planargeo-body")
        body.add_class(f"planargeo-body-{wpx}")
        root = W.VBox([head, body, W.HTML(self._layout_css(wpx), layout=W.Layout(display="none"))])
        root.add_class("planargeo-explorer")
        self.readout.add_class("planargeo-readout")
        self.message_box.add_class("planargeo-message")
        fig_widget.add_class("planargeo-figure")
        return root

    @staticmethod
    def _layout_css(wpx: int) -> str:
        """The stylesheet of the narrow layout: below the controls' and the figure's widths side by
        side (the explorer's width, a container query) one column: figure, controls, readout."""
        narrow = 330 + int(wpx) + 8
        return ("<style>.planargeo-explorer{container-type:inline-size}"
                f"@container (max-width:{narrow - 1}px){{.planargeo-body.planargeo-body-{int(wpx)}{{"
                "grid-template-columns:minmax(0,1fr) !important;grid-template-rows:auto auto auto !important;"
                "grid-template-areas:'figure' 'controls' 'readout' !important}}</style>")

    def _make_canvas(self):
        from planargeo.widgets.canvas import PictureCanvas

        # the controls', readout's and message's syncs leave after each reply (the picture first)
        return PictureCanvas(on_drag=self._page_drag, on_view=self._page_view_to, around=self._page_after,
                             on_release=self._page_release, said=lambda text: bool(text) and text == self._message)

    def redraw(self) -> None:
        """Send the shown state's picture to the front end (the page's canvas, or a PNG)."""
        if self.display_mode == "page":
            self.canvas.picture = self.picture()
        elif self.display_mode == "image":
            self.image.value = self._png_bytes()

    def picture(self) -> dict:
        """What is shown, as a picture's plain data: the scene, handles, key and refusal message.

        Returns
        -------
        dict

        Raises
        ------
        PlanargeoError
            No state shown yet.
        """
        if self.state is None:
            raise PlanargeoError(f"{type(self).__name__} has no state to draw yet")
        pic = self.scene_picture(self.state, self._page_view)
        for h in self._handle_list():
            pic.handle(h["id"], (h["x"], h["y"]), symbol=h["id"], desc=self.handle_words(h["id"]))
        if self.controls["key"].value:
            self._add_key(pic)
        if self._figure_text:
            self._add_banner(pic)
        return pic.to_dict()

    def handle_words(self, name: str) -> str:
        """What dragging handle ``name`` does, in words: its hover text (explorers say more).

        Parameters
        ----------
        name : str
            The handle's name.

        Returns
        -------
        str

        Examples
        --------
        >>> from planargeo.widgets import ChainExplorer
        >>> ChainExplorer(display="agg").handle_words("link 2 end")
        'drag to change link 2 end'
        """
        return f"drag to change {name}"

    @staticmethod
    def _key_entries(pic) -> list[tuple[str, str, str]]:
        """``(symbols, meaning, colour)`` of the described elements of the picture, one per meaning."""
        groups: dict[tuple[str, str], list[str]] = {}
        for el in pic.elements:
            sym = el.get("symbol") or ""
            if not sym or el["id"] == "figure message" or el["id"].startswith("key "):
                continue
            meaning = str(el.get("desc") or "").split(":")[0].split("(")[0].strip()
            syms = groups.setdefault((meaning, el.get("color") or "#222"), [])
            if sym not in syms:
                syms.append(sym)
        return [(", ".join(syms) if len(syms) <= 2 else f"{syms[0]}…{syms[-1]}", meaning, color)
                for (meaning, color), syms in groups.items()]

    def _note_shown(self) -> bool:
        """Whether the message shown is the shown state's note (not a refusal)."""
        st = self.state
        note = st.get("message", "") if isinstance(st, dict) else getattr(st, "message", "")
        return bool(note) and note == self._figure_text == self._message

    def _add_banner(self, pic) -> None:
        """The message on the picture (kept in stored pictures and exports): a banner along the
        top edge of the plot area, the plot's full width, wrapped, on a white panel, so that the
        mechanism stays in sight.  A refusal in red; a state's note in dark blue.  Written with
        ``obstacle=False``: no label moves for it."""
        (x0, x1, y0, y1) = pic.box
        text = self._figure_text
        pw = (x1 - x0) * pic.kx
        lines = textwrap.wrap(text, max(20, int((pw - 24.0) / (_CHAR_EM * FONT_PX)))) or [text]
        tall = _LINE_PX * len(lines) + 8.0                    # px, from the plot's top edge
        top = y1 - 1.0 / pic.ky
        bottom = y1 - tall / pic.ky
        cx = (x0 + x1) / 2
        note = self._note_shown()
        pic.text("figure message", (cx, top), lines[0], role="text",
                 color="#1a4f8a" if note else "#b00020", ha="center", va="top", z=100,
                 desc=f"message: {text}", obstacle=False, dy=-4.0)
        el = pic.elements[-1]                # the panel: a part of the message, drawn first
        el["parts"] += [{**el["parts"][0], "text": line, "dy": el["parts"][0]["dy"] - _LINE_PX * k}
                        for k, line in enumerate(lines[1:], 1)]
        el["parts"].insert(0, {"p": "path", "closed": True, "xy": np.array(
            [[x0, bottom], [x1, bottom], [x1, y1], [x0, y1]])})
        el.update(fill="white", alpha=0.92, width=0.8)

    def _add_key(self, pic) -> None:
        """The key: one entry per meaning drawn, in its colour, wrapped at half the figure's
        width (40 characters at least), on a white panel in a corner of the plot area that
        covers no handle, body, mark, pole glyph or arrow head (of those, where least is drawn);
        when no corner is clear, below the plot's x tick labels, outside the plot, wrapped at
        the plot's width (:meth:`~planargeo.draw.picture.Picture.below`: the figure grows, the
        plot and its view stay)."""
        x0, x1, y0, y1 = pic.box
        entries = self._key_entries(pic)[:12]
        if not entries:
            return
        pw, ph = (x1 - x0) * pic.kx, (y1 - y0) * pic.ky
        chars = max(40, int(0.5 * pw / (_CHAR_EM * FONT_PX)))
        texts = [f"{sym}: {meaning}" if meaning else sym for sym, meaning, _c in entries]
        lines = [textwrap.wrap(t, chars, subsequent_indent="  ") or [t] for t in texts]
        wide = _CHAR_EM * FONT_PX * max(len(li) for ls in lines for li in ls) + 8.0
        tall = 8.0 + 14.0 * sum(map(len, lines))
        ink = _ink(pic)
        corners = ((2.0, ph - 1.0), (pw - 2.0 - wide, ph - 1.0), (2.0, tall + 1.0),
                   (pw - 2.0 - wide, tall + 1.0))      # upper left first when ties
        pts, rad = _keep_clear(pic)
        clear = [c for c in corners if _covers((c[0], c[1] - tall, c[0] + wide, c[1]), pts, rad) == 0]
        if not clear:     # below the plot, outside it: the figure grows by the key's height
            chars = max(40, int(pw / (_CHAR_EM * FONT_PX)))
            for k, ((_s, _m, color), text) in enumerate(zip(entries, texts)):
                pic.below(f"key {k + 1}", textwrap.wrap(text, chars, subsequent_indent="  ") or [text],
                          color=color, desc=f"key: {text}")
            return
        left, top = min(clear, key=lambda c: int(np.count_nonzero(
            (ink[:, 0] > c[0]) & (ink[:, 0] < c[0] + wide)
            & (ink[:, 1] < c[1]) & (ink[:, 1] > c[1] - tall))))
        u0, u1 = x0 + left / pic.kx, x0 + (left + wide) / pic.kx
        v0, v1 = y0 + (top - tall) / pic.ky, y0 + top / pic.ky
        pic.path("key panel", [[u0, v0], [u1, v0], [u1, v1], [u0, v1]], role="text",
                 closed=True, fill="white", alpha=0.9, color="#888888", width=0.8, z=89,
                 desc="the key: each symbol drawn, in its colour, and its meaning")
        row = 0
        for k, ((_s, _m, color), text, ls) in enumerate(zip(entries, texts, lines)):
            pic.text(f"key {k + 1}", (u0, v1), ls[0], role="text", color=color, ha="left",
                     va="top", dx=4.0, dy=-4.0 - 14.0 * row, z=90, desc=f"key: {text}")
            el = pic.elements[-1]            # an entry's further lines: parts of the same element
            el["parts"] += [{**el["parts"][0], "text": li, "dy": -4.0 - 14.0 * (row + j)}
                            for j, li in enumerate(ls[1:], 1)]
            row += len(ls)

    def _page_view_to(self, box) -> None:
        """The user zoomed or panned in the page (None: back to the explorer's own view)."""
        self._page_view = None if box is None else tuple(box)
        self._safe_redraw()

    def _set_message(self, text: str) -> None:
        self._message = text
        st = getattr(self, "state", None)
        note = st.get("message", "") if isinstance(st, dict) else getattr(st, "message", "")
        if text and text == note:     # the shown state's note: said, not an error
            self.message_box.value = (f"<div style='color:#1a4f8a;line-height:1.3'>"
                                      f"ℹ {html.escape(text)}</div>")
        elif text:
            self.message_box.value = (f"<div style='color:#b00020;font-weight:bold;line-height:1.3'>"
                                      f"⚠ {html.escape(text)}</div>")
        else:
            self.message_box.value = ""

    @property
    def figure_text(self) -> str:
        """The message written on the picture ("" when none is shown)."""
        return self._figure_text

    def _readout_html(self, values: dict[str, Any]) -> str:
        zero = float(self.zero_tol) * float(self.scale)
        self.readout_strings = {}
        rows = []
        for k, v in values.items():
            if str(k).startswith("_"):
                continue
            # the numbers alone (bare) and with their unit (full); a common unit goes in its own
            # column (HTML-safe)
            bare, full = value_texts(v, self.units.get(k, ""), zero=zero)
            self.readout_strings[str(k)] = html.unescape(full)
            text, unit = (bare, full[len(bare) + 1:]) if full.startswith(bare + " ") else (full, "")
            said = f" ({html.unescape(unit)})"          # a name's unit is said once, in its column
            name = html.escape(str(k)[:-len(said)] if unit and str(k).endswith(said) else str(k))
            rows.append(
                f"<tr><td style='padding-right:6px;line-height:1.25;white-space:nowrap;"
                f"overflow:hidden;text-overflow:ellipsis;max-width:300px' title='{name}'>{marks_bold(name)}</td>"
                f"<td style='text-align:right;font-family:monospace;line-height:1.25;"
                f"white-space:nowrap'>{text}</td>"
                f"<td style='padding-left:3px;line-height:1.25;white-space:nowrap;color:#555'>"
                f"{unit}</td></tr>")
        return (f"<b>Readout</b><table class='planargeo-readout' style='font-size:12px;"
                f"table-layout:auto;border-collapse:collapse'>{''.join(rows)}</table>")

    def show(self):
        """Display the explorer (in a notebook) and return it.

        Returns
        -------
        Explorer
        """
        from IPython.display import display

        display(self.widget)
        return self

    def _follow_shown(self) -> None:
        """Focus options, disabled controls and the "what is shown" panel, for the shown state."""
        w = self.controls.get("focus")
        if self._base_focus:
            with contextlib.suppress(Exception):
                options = ("all", *self.focus_options())
                if tuple(w.options) != options:
                    value = w.value if w.value in options else "all"
                    with self._quietly():
                        w.options = options
                        w.value = value
        try:
            off = dict(self.disabled(dict(self.shown_values or self.values)))
        except Exception as exc:  # noqa: BLE001 - a faulty rule disables nothing
            off = {}
            self._message = self._message or f"internal error in disabled(): {exc}"
        if "key" not in off and not self.controls["key"].value and self.state is None:
            off["key"] = "nothing drawn now has an entry in the key"
        for k, w in self.controls.items():
            reason = off.get(k)
            if bool(w.disabled) != (reason is not None):
                w.disabled = reason is not None
            tip = str(reason) if reason is not None else self._tooltips.get(k)
            if getattr(w, "tooltip", tip) != tip:      # (a widget without a tooltip: nothing to do)
                w.tooltip = tip
        try:
            meanings = dict(self.explain())
            last = getattr(self, "_explained_html", None)     # the same meanings: the same text
            if last is not None and last[0] == meanings:
                text = last[1]
            else:
                text = explain_html(meanings)
                self._explained_html = (meanings, text)
        except Exception as exc:  # noqa: BLE001
            text = f"<i>no explanation: {html.escape(str(exc))}</i>"
        if self.explain_box.value != text:
            self.explain_box.value = text
