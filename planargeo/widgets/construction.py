"""Chapter 4's constructions one step at a time, like a construction protocol (thesis 4.2–4.7).

A *step* slider draws the construction up to that step; the caption above the
figure names the step and its equation, earlier steps stay (faded, at full
strength or hidden: the *earlier steps* buttons), later ones are hidden.  Every input (poles, rates, force lines, the joint, the
centre of mass) has a slider and, where it is a point, a drag handle:
dragging redoes the whole construction.  The steps come from
:func:`planargeo.scenes.construction.construct`; this module only draws them.

For slides, :meth:`ConstructionExplorer.export_layers` writes an SVG with
every step in its own layer, ``<g id="step-K-name">``, to reveal one by one.

Examples
--------
>>> ex = ConstructionExplorer("twist_sum", display="agg", x1=0.0, y1=0.0, w1=1.0,
...                           x2=4.0 - 1.0, y2=0.0, w2=3.0)
>>> ex.readout_values["pole of v3"]                 # β = 3/4 of the way from Q₁ to Q₂ (4.12)
(2.25, 0.0)
>>> ex.set(step=1).caption
'Step 1/3: Q₁, Q₂: the poles of v₁ and v₂ (4.10)'
>>> _ = ex.drag("v2", (3.0, 0.0), (3.0, 1.0), steps=2)   # the whole construction follows
>>> ex.readout_values["pole of v3"]
(2.25, 0.75)
"""
from __future__ import annotations

import io
import math
import textwrap
from pathlib import Path

import matplotlib
import matplotlib.artist as martist
import numpy as np
import ipywidgets as W
from matplotlib.lines import Line2D
from matplotlib.text import Text

from planargeo.draw.artists import ConicArtist, LineArtist, PointArtist
from planargeo.draw.style import COLORS, STYLES, sum_style
from planargeo.errors import InputError
from planargeo.files import atomic_write
from planargeo.scenes.construction import CONSTRUCTIONS, construct, parameters
from planargeo.widgets.base import Explorer, Handle, Step

__all__ = ["ConstructionExplorer"]

#: the parameters' sliders: name pattern -> (lo, hi, step, unit)
_RANGES = {
    "x": (-3.0, 3.0, 0.05, "m"), "y": (-3.0, 3.0, 0.05, "m"),
    "w": (-3.0, 3.0, 0.05, "rad/s"), "qd": (-3.0, 3.0, 0.05, "rad/s"),
    "qdd": (-3.0, 3.0, 0.05, "rad/s²"), "alpha": (-3.0, 3.0, 0.05, "rad/s²"),
    "u": (-3.0, 3.0, 0.05, "m/s"), "angle": (-180.0, 180.0, 5.0, "deg"),
    "F": (-3.0, 3.0, 0.05, "N"), "tau": (-3.0, 3.0, 0.05, "N·m"),
    "m": (0.1, 5.0, 0.1, "kg"), "r": (0.05, 2.0, 0.05, "m"),
    "h": (-3.0, 3.0, 0.05, "m"), "k": (0.1, 3.0, 0.05, "—"),
}

#: draggable points per construction: (handle name, x parameter, y parameter)
_POINTS = {
    "twist_sum": [("v1", "x1", "y1"), ("v2", "x2", "y2")],
    "wrench_sum": [("f1", "x1", "y1"), ("f2", "x2", "y2")],
    "velocity": [("v_prev", "xv", "yv"), ("joint", "xj", "yj")],
    "acceleration": [("v_prev", "xv", "yv"), ("a_prev", "xa", "ya"), ("joint", "xj", "yj")],
    "newton_euler": [("centre of mass", "xc", "yc"), ("v", "xv", "yv"), ("a", "xa", "ya"),
                     ("joint", "xj", "yj")],
    "through_infinity": [("v1", "x1", "y1"), ("h", "hx", "hy")],
}
#: direction handles: (handle name, x, y, angle parameter, size parameter)
_DIRECTIONS = {
    "wrench_sum": [("f1 direction", "x1", "y1", "angle1", "F1"),
                   ("f2 direction", "x2", "y2", "angle2", "F2")],
}

#: readout units by key
_UNITS = {"ω₁": "rad/s", "ω₂": "rad/s", "ω₃ = ω₁ + ω₂": "rad/s", "ρ": "m", "β": "—",
          "pole of v3": "m", "F₁": "N", "F₂": "N", "F₃": "N", "meet P": "m", "f3": "—",
          "ωᵢ₋₁": "rad/s", "q̇ᵢ": "rad/s", "ωᵢ": "rad/s", "kᵢ": "m", "βᵢ": "—",
          "pole of vᵢ": "m", "q̈ᵢ": "rad/s²", "|κᵢ|": "m/s²", "ρᵢ": "m", "pole of aᵢ": "m",
          "aᵢ": "—", "m": "kg", "|Ia|": "N", "|p|": "N", "F_net": "N", "τ": "N·m",
          "ρ = τ/F": "m", "f_net": "—", "power of f_net on v": "W", "step": "—",
          "construction step": "—", "equation": "—", "special case": "—",
          "weight of v₂": "—", "v₂": "—", "pole of v2": "m", "v3": "—"}

ARM = 1.0
FADED = 0.4


def _range(name: str):
    for key in sorted(_RANGES, key=len, reverse=True):
        if name.startswith(key) and (name[len(key):].isdigit() or name[len(key):] in ("", "v", "a",
                                                                                          "j", "c", "x", "y")):
            return _RANGES[key]
    return (-3.0, 3.0, 0.05, "—")


class StepLayer(martist.Artist):
    """A container artist: its children are drawn inside one SVG group ``<g id=gid>``.

    The children (planargeo artists, lines, texts) are owned by the layer, not
    by the axes, so that a step's elements stay together in the SVG output.

    Parameters
    ----------
    ax : matplotlib.axes.Axes
        The axes the children draw in.
    gid : str
        The group's id in SVG output.

    Examples
    --------
    >>> import matplotlib; matplotlib.use("Agg")
    >>> import matplotlib.pyplot as plt
    >>> fig, ax = plt.subplots()
    >>> layer = StepLayer(ax, "step-1")
    >>> _ = layer.add(Line2D([0, 1], [0, 1]))
    >>> buf = io.StringIO(); fig.savefig(buf, format="svg")
    >>> 'id="step-1"' in buf.getvalue()
    True
    >>> plt.close(fig)
    """

    def __init__(self, ax, gid: str):
        super().__init__()
        self.set_gid(gid)
        self.set_in_layout(False)
        self.children: list = []
        ax.add_artist(self)

    def add(self, artist):
        """Adopt ``artist`` (set its axes, figure and data transform); return it.

        Parameters
        ----------
        artist : matplotlib.artist.Artist

        Returns
        -------
        matplotlib.artist.Artist
        """
        ax = self.axes
        artist.axes = ax
        artist.set_figure(ax.figure)
        if not artist.is_transform_set():
            artist.set_transform(ax.transData)
        if hasattr(artist, "set_clip_path") and not isinstance(artist, Text):
            artist.set_clip_path(ax.patch)
        self.children.append(artist)
        self.stale = True
        return artist

    def get_children(self):
        """The adopted artists.

        Returns
        -------
        list
        """
        return list(self.children)

    @martist.allow_rasterization
    def draw(self, renderer):
        """Draw the children inside one group named by the layer's gid.

        Parameters
        ----------
        renderer : matplotlib.backend_bases.RendererBase
        """
        if not self.get_visible():
            return
        renderer.open_group("step", gid=self.get_gid())
        for c in sorted(self.children, key=lambda a: a.get_zorder()):
            if c.get_visible():
                c.draw(renderer)
        renderer.close_group("step")
        self.stale = False


class ConstructionExplorer(Explorer):
    """One of chapter 4's constructions drawn step by step, with its caption and equation.

    Parameters
    ----------
    construction : str
        A key of :data:`planargeo.scenes.construction.CONSTRUCTIONS`:
        ``"twist_sum"``, ``"wrench_sum"``, ``"velocity"``, ``"acceleration"`` or
        ``"newton_euler"``.
    **kwargs
        As :class:`~planargeo.widgets.base.Explorer`: ``display``, and initial
        control values (the construction's parameters, ``step``).

    Raises
    ------
    InputError
        An unknown construction or control, or a value a control does not take.
    PlanargeoError
        Initial values the construction cannot be built from (e.g. a zero twist).
    """

    slug = "construction"
    figsize = (5.6, 5.6)
    limits = (-4.0, 4.0, -4.0, 4.0)
    #: ("earlier" only changes the drawing too, but stays a plain control: a recompute is cheap)
    display_controls = ("step",)
    scale = 3.0

    def __init__(self, construction: str = "twist_sum", **kwargs):
        if construction not in CONSTRUCTIONS:
            raise InputError(f"construction must be one of {list(CONSTRUCTIONS)}, got {construction!r}")
        self.construction = construction
        self.params = parameters(construction)
        self.n_steps = len(construct(construction).steps)
        self.title = f"Step by step: {CONSTRUCTIONS[construction][0]}"
        self.units = dict(_UNITS)
        self._all_steps = False
        super().__init__(**kwargs)

    # ------------------------------------------------------------------ explorer
    def make_controls(self):
        """The step slider, how earlier steps look, and one slider per parameter of the construction.

        Returns
        -------
        dict
        """
        c = {"step": Step(1, self.n_steps, 1, self.n_steps, "step", integer=True).make("step"),
             "earlier": W.ToggleButtons(options=("faded", "shown", "hidden"), value="faded",
                                        description="earlier steps",
                                        style={"description_width": "initial"})}
        for name, default in self.params.items():
            lo, hi, st, unit = _range(name)
            label = name if unit == "—" else f"{name} ({unit})"
            c[name] = Step(lo, hi, st, default, label).make(name)
        return c

    def setup_axes(self, ax):
        """Equal-aspect axes over :attr:`limits` with a light grid.

        Parameters
        ----------
        ax : matplotlib.axes.Axes
        """
        from planargeo.draw.style import setup_axes

        from matplotlib.ticker import MultipleLocator

        setup_axes(ax, self.limits, grid=True, axis_off=False)
        for axis in (ax.xaxis, ax.yaxis):      # ticks every 2 m: drawing ticks is half a redraw
            axis.set_major_locator(MultipleLocator(2.0))
        ax.grid(True, lw=0.4, alpha=0.4)
        ax.figure.subplots_adjust(top=0.86)

    def make_artists(self, ax):
        """One :class:`StepLayer` per step (children made when an element first appears).

        Parameters
        ----------
        ax : matplotlib.axes.Axes
        """
        self.layers = [StepLayer(ax, f"step-{k + 1}") for k in range(self.n_steps)]
        self.element_artists: dict[str, object] = {}
        self.caption_text = ax.set_title("", fontsize=9, loc="left")

    def compute(self, values, changed):
        """The construction for the parameter values (may raise a named PlanargeoError).

        Parameters
        ----------
        values : dict
        changed : set

        Returns
        -------
        dict
            ``{"c": Construction}``.
        """
        return {"c": construct(self.construction, **{k: values[k] for k in self.params})}

    # ------------------------------------------------------------------ drawing
    def _artist(self, k: int, e):
        key = f"{k}:{e.name}"
        art = self.element_artists.get(key)
        if art is not None:
            return art
        layer = self.layers[k]
        if e.kind == "point":
            if e.role in ("twist", "accel"):
                kw = dict(role=e.role, **(sum_style("point") if e.emphasis else {}))
            else:
                kw = dict(role="twist", glyph=False, color=COLORS.get(e.role, COLORS["text"]))
            art = layer.add(PointArtist(e.value, text=e.label or None, **kw))
        elif e.kind == "line":
            scale = None if e.role == "construct" else 0.6
            art = layer.add(LineArtist(e.value, role=e.role, scale=scale, text=e.label or None,
                                       **(sum_style("line") if e.emphasis else {})))
        elif e.kind == "conic":
            art = layer.add(ConicArtist(e.value, role=e.role, text=e.label or None))
        else:
            st = STYLES.get(e.role, STYLES["construct"])
            line = layer.add(Line2D([0, 1], [0, 1], color=st["color"],
                                    linewidth=1.2 if e.role == "construct" else 1.6,
                                    linestyle=st["linestyle"] if e.role == "construct" else "-"))
            text = layer.add(Text(0, 0, e.label, fontsize=9, color=st["color"], ha="center",
                                  va="center")) if e.label else None
            art = (line, text)
        self.element_artists[key] = art
        return art

    def _update_artist(self, art, e, alpha: float, centre):
        if e.kind == "segment":
            line, text = art
            (x0, y0), (x1, y1) = e.value
            line.set_data([x0, x1], [y0, y1])
            line.set_alpha(alpha)
            line.set_visible(True)
            if text is not None:
                d = np.array([x1 - x0, y1 - y0])
                n = np.array([-d[1], d[0]]) / max(np.hypot(*d), 1e-300) * 0.22
                text.set_position(tuple((np.array([x0, y0]) + np.array([x1, y1])) / 2 + n))
                text.set_alpha(alpha)
                text.set_visible(True)
            return
        if e.kind == "point":
            art.set_point(e.value)
            xy = (np.array([-e.value[1] / e.value[2], e.value[0] / e.value[2]])
                  if e.value[2] != 0 else None)
            (x0, x1), (y0, y1) = self.ax.get_xlim(), self.ax.get_ylim()
            if xy is not None and x0 < xy[0] < x1 and y0 < xy[1] < y1:
                n = centre[1]
                u = tuple(-n) if e.emphasis else tuple(n)
                if np.hypot(*(xy - centre[0])) > 1e-9 and not e.emphasis:
                    away = (xy - centre[0]) / np.hypot(*(xy - centre[0]))
                    u = tuple(away) if abs(away @ n) < 0.3 else u
                # the rotation glyph's radius (PointArtist: 6 pt per unit rate, in [4, 16] pt)
                glyph = (min(max(6.0 * abs(e.value[2]), 4.0), 16.0)
                         if e.role in ("twist", "accel") else 0.0)
                u = self._inward(xy, u)
                taken = [d for q, d in self._placed if np.hypot(*(q - xy)) < 0.15]
                if taken:          # poles on one spot (coincident): spread their labels round it
                    spare = [d for d in ((-0.7, 0.7), (0.7, 0.7), (0.7, -0.7), (-0.7, -0.7))
                             if d not in taken]
                    u = spare[0] if spare else u
                self._placed.append((xy, u))
                art.set_text_beside(u, 7.0 + glyph)
                art.set_text(e.label or None)
            else:                  # ideal or out of view: the artist's own arrow and label at the edge
                art.set_text(e.label or None)
                art.set_text_offset(None)
        elif e.kind == "line":
            art.set_line(e.value)
            if e.label and np.any(e.value[:2]):
                # labelled lines' arrows (and labels) spread along them, so that lines that
                # coincide or cross near the centre keep their labels apart
                k = len(self._lines_placed)
                f = e.value[:2] / np.hypot(*e.value[:2])
                foot = np.array([e.value[2] * f[1], -e.value[2] * f[0]]) / np.hypot(*e.value[:2])
                foot = foot + ((self._view_centre - foot) @ f) * f
                art.set_anchor(foot + (1.1 * k - 0.8) * f)
                self._lines_placed.append(e.name)
        else:
            art.set_conic(e.value)
        art.set_alpha(alpha)
        art.set_visible(True)

    @staticmethod
    def _label_frame(c):
        """``(centroid, n)``: the finite poles' centroid and the upward normal of their main axis.

        Labels of a construction's points go on the ``n`` side of the line the
        poles lie along (a lever line), the sum's label on the other side.
        """
        P = np.array([[-e.value[1] / e.value[2], e.value[0] / e.value[2]] for e in c.elements()
                      if e.kind == "point" and e.value[2] != 0] or [[0.0, 0.0]])
        m = P.mean(axis=0)
        if len(P) > 1 and np.ptp(P, axis=0).max() > 0:
            _, _, vt = np.linalg.svd(P - m)
            d = vt[0]
        else:
            d = np.array([1.0, 0.0])
        n = np.array([-d[1], d[0]])
        if n[1] < 0 or (n[1] == 0 and n[0] < 0):
            n = -n
        return m, n

    def _inward(self, xy, u):
        """``u`` turned toward the centre of the view for a point near its side."""
        x0, x1 = self.ax.get_xlim()
        off = (xy[0] - (x0 + x1) / 2) / ((x1 - x0) / 2)
        if abs(off) > 0.45 and u[0] * off >= -0.35:
            return (-0.75 if off > 0 else 0.75, 0.66 if u[1] >= 0 else -0.66)
        return u

    def render(self, state):
        """Show steps ``1 … step`` (the last one at full strength) and the caption; the readout.

        Parameters
        ----------
        state : dict

        Returns
        -------
        dict
            The readout: step, its caption and equation, the construction's
            numbers and the special case.
        """
        c = state["c"]
        k = int(self.values["step"])
        shown = self.n_steps if self._all_steps else k
        centre = self._label_frame(c)
        self._placed: list = []
        self._lines_placed: list = []
        (x0, x1), (y0, y1) = self.ax.get_xlim(), self.ax.get_ylim()
        self._view_centre = np.array([(x0 + x1) / 2, (y0 + y1) / 2])
        used = set()
        for i, step in enumerate(c.steps[:self.n_steps]):
            layer = self.layers[i]
            layer.set_gid(f"step-{i + 1}-{step.id}")
            earlier = "shown" if self._all_steps else self.values["earlier"]
            layer.set_visible(i < shown and (earlier != "hidden" or i == shown - 1))
            alpha = 1.0 if (earlier == "shown" or i == shown - 1) else FADED
            for e in step.elements:
                art = self._artist(i, e)
                used.add(f"{i}:{e.name}")
                self._update_artist(art, e, alpha, centre)
        for key, art in self.element_artists.items():
            if key not in used:
                for a in (art if isinstance(art, tuple) else (art,)):
                    if a is not None:
                        a.set_visible(False)
        step = c.steps[k - 1]
        self.caption = f"Step {k}/{self.n_steps}: {step.caption}"
        self.caption_text.set_text("\n".join(textwrap.wrap(self.caption, 62)))
        out = {"step": f"{k}/{self.n_steps}", "construction step": step.title,
               "equation": step.equation}
        out.update(c.values)
        out["special case"] = c.case
        return out

    # ------------------------------------------------------------------ handles
    def handles(self) -> list[Handle]:
        """Drag handles: the construction's input points, and force directions by their arrow tip.

        Returns
        -------
        list of Handle
        """
        out = []
        for name, px, py in _POINTS[self.construction]:
            out.append(Handle(name, self._where(px, py), self._move(px, py)))
        for name, px, py, pa, pf in _DIRECTIONS.get(self.construction, []):
            out.append(Handle(name, self._tip(px, py, pa, pf), self._turn(px, py, pa, pf)))
        return out

    def handle_position(self, name: str):
        """Current data position of handle ``name``.

        Parameters
        ----------
        name : str

        Returns
        -------
        (float, float) or None

        Raises
        ------
        InputError
            No handle of that name.
        """
        for h in self.handles():
            if h.name == name:
                return h.where()
        raise InputError(f"name must name a handle of this construction "
                         f"({', '.join(h.name for h in self.handles())}), got {name!r}")

    def _shown(self):
        return self.shown_values or self.values

    def _where(self, px, py):
        return lambda: (self._shown()[px], self._shown()[py])

    def _move(self, px, py):
        return lambda x, y: {px: x, py: y}

    def _tip(self, px, py, pa, pf):
        def where():
            v = self._shown()
            a = math.radians(v[pa])
            s = -1.0 if v[pf] < 0 else 1.0
            return (v[px] + s * ARM * math.cos(a), v[py] + s * ARM * math.sin(a))
        return where

    def _turn(self, px, py, pa, pf):
        def drag(x, y):
            v = self._shown()
            dx, dy = x - v[px], y - v[py]
            if dx == 0 and dy == 0:
                raise InputError(f"{pa}: the direction handle is on the force's point, "
                                 f"which gives no direction")
            if v[pf] < 0:
                dx, dy = -dx, -dy
            return {pa: math.degrees(math.atan2(dy, dx))}
        return drag

    # ------------------------------------------------------------------ export
    def step_ids(self) -> list[str]:
        """The SVG group ids of the steps, in order (``step-K-name``).

        Returns
        -------
        list of str
        """
        return [layer.get_gid() for layer in self.layers]

    def export_layers(self, path=None) -> Path:
        """Write the whole construction as an SVG with one ``<g id="step-K-name">`` per step.

        Every step is drawn at full strength, each in its own group, for slides
        that reveal the construction step by step; the view on screen is not
        changed.  The file is written atomically.

        Parameters
        ----------
        path : str or Path, optional
            Where to write (default: ``planargeo-construction-<kind>-layers.svg``
            in the export folder or the current folder).

        Returns
        -------
        Path
            The file written.

        Raises
        ------
        InputError
            ``path`` is not a path.
        OutputError
            The file cannot be written.
        """
        if path is None:
            d = self.export_dir or Path.cwd()
            path = Path(d) / f"planargeo-construction-{self.construction}-layers.svg"
        try:
            path = Path(path)
        except TypeError:
            raise InputError(f"path must be a str or os.PathLike naming a file, got {path!r}") from None
        c = self.state["c"]
        self._all_steps = True
        saved = self.caption_text.get_text()
        try:
            self.render(self.state)
            self.caption_text.set_text(c.title)
            buf = io.BytesIO()
            with matplotlib.rc_context({"svg.hashsalt": "planargeo"}):
                self.fig.savefig(buf, format="svg", metadata={"Date": None})
            written = atomic_write(path, buf.getvalue()).resolve()
        finally:
            self._all_steps = False
            self.render(self.state)
            self.caption_text.set_text(saved)
            self._safe_redraw()
        self.last_export = written
        return written

