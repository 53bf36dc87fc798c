"""Twist and wrench addition explorer (thesis 4.2 and 4.4).

Two twists add to a twist whose pole lies on the line of their poles at the lever ratio
``β = ω2/(ω1+ω2)`` (4.11-4.13); dually two wrenches add to a wrench through the meet of their
lines (4.4.1) (:func:`planargeo.screws.add_twists`, :func:`~planargeo.screws.add_wrenches`); the
readout names the special case reached, ideal elements included.

Examples
--------
>>> ex = ScrewSumExplorer(display="agg", add="wrenches")
>>> ex.readout_values["case"], ex.controls["kind1"].options     # a wrench is a force or a couple
('concurrent forces (4.4.1)', ('force', 'couple'))
>>> _ = ex.drag("f₂ direction", ex.handle_position("f₂ direction"), (2.5, 0.5))  # turned parallel to f₁
>>> ex.readout_values["case"], ex.readout_values["meet of lines"], ex.message
('parallel forces (4.43)', 'at infinity (direction (1, 0))', '')
"""
from __future__ import annotations

import math

import ipywidgets as W
import numpy as np

from planargeo.draw.pictures.screw_sum import ARM as VELOCITY_ARM, screw_sum_picture
from planargeo.errors import InputError
from planargeo.geometry.projective import is_at_infinity
from planargeo.screws.special import twists_case, wrenches_case
from planargeo.screws.twists import Twist, Wrench, add_twists, add_wrenches
from planargeo.widgets.readout import point_value
from planargeo.widgets._explorer import Described, arrow_handle, shown, xy_handle
from planargeo.widgets.base import Explorer, Handle, Step

__all__ = ["ScrewSumExplorer"]

#: the kinds each mode adds: a twist is a rotation or a translation, a wrench a force or a couple
KINDS = {"twists": ("rotation", "translation"), "wrenches": ("force", "couple")}
#: a kind's counterpart in the other mode (a finite pole / line, or the ideal one)
_OTHER = {"rotation": "force", "translation": "couple", "force": "rotation", "couple": "translation"}
#: each kind's size: its symbol, unit and the word before them in its slider's label
_SIZE = {"rotation": ("ω", "rad/s", ""), "translation": ("u", "m/s", "speed "),
         "force": ("F", "N", "force "), "couple": ("τ", "N·m", "moment ")}
_SUBSCRIPT = {1: "₁", 2: "₂"}
#: the sum's components: a twist [vx, vy, ω], a wrench [fx, fy, τ] (about the origin)
SUM_UNITS = {"twists": ("m/s", "m/s", "rad/s"), "wrenches": ("N", "N", "N·m")}


def _size_label(kind: str, k: int) -> str:
    """The size slider's label of screw ``k`` of ``kind``: ``"speed u₁ (m/s)"``."""
    symbol, unit, word = _SIZE[kind]
    return f"{word}{symbol}{_SUBSCRIPT[k]} ({unit})"


def zero_screw_message(kind: str, k: int) -> str:
    """Why screw ``k`` (1 or 2) of ``kind`` and size 0 is refused, in the symbols its slider and picture show.

    A zero twist is no motion and a zero wrench no load: neither is a point or a line (not even
    one at infinity), so there is nothing to add.  A pure translation or a couple is an ordinary
    value, offered as the other kind of the screw's menu.

    Examples
    --------
    >>> print(zero_screw_message("rotation", 1))
    ω₁ = 0 rad/s makes v₁ the zero twist: no motion, so no pole to add. Choose ω₁ ≠ 0, or screw 1: translation for a pole at infinity.
    >>> print(zero_screw_message("couple", 2))
    τ₂ = 0 N·m makes f₂ the zero wrench: no load, so no line to add. Choose τ₂ ≠ 0.
    """
    s = _SUBSCRIPT[k]
    symbol, unit, _word = _SIZE[kind]
    twist = kind in KINDS["twists"]
    text = (f"{symbol}{s} = 0 {unit} makes {'v' if twist else 'f'}{s} the zero "
            f"{'twist: no motion, so no pole' if twist else 'wrench: no load, so no line'} to add. "
            f"Choose {symbol}{s} ≠ 0")
    if kind == "rotation":
        return f"{text}, or screw {k}: translation for a pole at infinity."
    if kind == "force":
        return f"{text}, or screw {k}: couple for the line at infinity."
    return f"{text}."


def _xy_or_ideal(p):
    if p is None:
        return "none (the sum is zero)"
    return point_value(p)


def _short_case(case) -> str:
    """The special case in a few words, with its equation: ``"opposite rotations (4.13)"``."""
    return f"{case.text.split(':')[0].split(' (')[0]} ({case.equation})"


def _same_line(a, b, rtol: float = 1e-9) -> bool:
    """Two forces (not couples) on one line: proportional wrenches ``a × b = 0`` (5.21)."""
    a, b = np.asarray(a, float), np.asarray(b, float)
    if bool(is_at_infinity(a)) or bool(is_at_infinity(b)):
        return False
    return bool(np.all(np.abs(np.cross(a, b)) <= rtol * np.linalg.norm(a) * np.linalg.norm(b)))


def _meet_label(c):
    """Where the two force lines meet: a point, at infinity (parallel lines) or the common line."""
    if c.P is not None and _same_line(c.f1.array, c.f2.array):
        return "every point of their common line"
    return _xy_or_ideal(c.P)


#: length of a direction handle's arm (data units), from the screw's point (as the picture draws
#: a translation's velocity u)
ARM = VELOCITY_ARM

#: what dragging each handle does (its hover text)
_HANDLE_TIPS = {}
for _k, _s in _SUBSCRIPT.items():
    _HANDLE_TIPS.update({
        f"v{_s}": f"pole of v{_s}: drag it to move the rotation's centre",
        f"v{_s} direction": f"direction of u{_s} (v{_s} a translation): drag the arrow's tip to turn it",
        f"f{_s}": f"a point of f{_s}'s line of action: drag it to move the line",
        f"f{_s} direction": f"direction of F{_s}: drag it to turn the force (and set its size)"})


class ScrewSumExplorer(Described, Explorer):
    """Add two twists (points) or two wrenches (lines) and watch the construction (thesis 4.2, 4.4).

    Parameters
    ----------
    **kwargs
        As :class:`~planargeo.widgets.base.Explorer`.
    """

    title = "Twist and wrench addition"
    slug = "screw-sum"
    figsize = (5.6, 5.0)
    limits = (-4, 4, -4, 4)
    scale = 3.0

    def __init__(self, **kwargs):
        # the kinds offered follow the mode: the first mode decides the first options
        mode = kwargs.get("add", "twists")
        self._first_mode = mode if mode in KINDS else "twists"
        super().__init__(**kwargs)
        self.controls["add"].observe(self.guarded(lambda ch: self._offer_kinds(ch["new"])),
                                     names="value")

    @property
    def units(self):
        """Unit of each readout row (the sum's three components each its own)."""
        return {**self.row_units, "sum": SUM_UNITS.get(getattr(self, "_mode", None) or self._first_mode)}

    def make_controls(self):
        kinds = W.ToggleButtons(options=("twists", "wrenches"), value=self._first_mode,
                                description="add")
        c = {"add": kinds}
        offered = KINDS[self._first_mode]
        for k, (x, y, mag, ang) in ((1, (-1.5, 0.0, 1.0, 0.0)), (2, (1.5, 0.5, 2.0, 90.0))):
            sub = _SUBSCRIPT[k]
            c[f"kind{k}"] = W.Dropdown(options=offered, value=offered[0], description=f"screw {k}")
            c[f"x{k}"] = Step(-3, 3, 0.05, x, f"x{sub} (m)")
            c[f"y{k}"] = Step(-3, 3, 0.05, y, f"y{sub} (m)")
            c[f"size{k}"] = Step(-3, 3, 0.05, mag, _size_label(offered[0], k))
            c[f"angle{k}"] = Step(-180, 180, 5, ang, f"angle{sub} (deg)")
        return c

    def _offer_kinds(self, mode: str) -> None:
        """Offer the kinds of ``mode`` in both menus (a kind of the other mode: its counterpart)."""
        if mode not in KINDS:
            return
        offered = KINDS[mode]
        with self._quietly():
            for k in (1, 2):
                w = self.controls[f"kind{k}"]
                if tuple(w.options) == offered:
                    continue
                value = w.value if w.value in offered else _OTHER.get(w.value, offered[0])
                w.options = offered
                w.value = value

    def set(self, **values):
        # a change of "add" comes first, so that its kinds can be chosen with it
        if "add" in values and len(values) > 1:
            super().set(add=values.pop("add"))
            if self.message:
                return self
        return super().set(**values)

    def adjust(self, values, changed):
        mode = values["add"]
        self._offer_kinds(mode)
        return {f"kind{k}": _OTHER[values[f"kind{k}"]] for k in (1, 2)
                if values[f"kind{k}"] not in KINDS[mode]}

    def disabled(self, values):
        out = {}
        for k in (1, 2):
            kind = values[f"kind{k}"]
            if kind == "rotation":
                out[f"angle{k}"] = "a rotation has no direction: only its pole and ω"
            elif kind == "translation":
                out[f"x{k}"] = out[f"y{k}"] = ("a translation's pole is at infinity: only its "
                                                "direction and speed count")
            elif kind == "couple":
                out[f"x{k}"] = out[f"y{k}"] = out[f"angle{k}"] = (
                    "a couple is on the line at infinity: only its moment τ counts")
        return out

    def _screw(self, v, k):
        kind = v[f"kind{k}"]
        x, y, m = v[f"x{k}"], v[f"y{k}"], v[f"size{k}"]
        a = math.radians(v[f"angle{k}"])
        d = (m * math.cos(a), m * math.sin(a))
        if kind == "rotation":
            return Twist.rotation((x, y), m)
        if kind == "translation":
            return Twist.translation(d)
        if kind == "force":
            return Wrench.force((x, y), d)
        return Wrench.couple(m)

    def compute(self, values, changed):
        mode = values["add"]
        for k in (1, 2):
            if values[f"kind{k}"] not in KINDS[mode]:
                raise InputError(f"kind{k} must be one of {list(KINDS[mode])} when adding {mode}, "
                                 f"got {values[f'kind{k}']!r}")
        for k in (1, 2):
            if values[f"size{k}"] == 0.0:
                raise InputError(zero_screw_message(values[f"kind{k}"], k))
        add = add_twists if mode == "twists" else add_wrenches
        return {"mode": mode, "c": add(self._screw(values, 1), self._screw(values, 2))}

    def readout_of(self, state):
        c = state["c"]
        tw = state["mode"] == "twists"
        self._mode = state["mode"]
        v = self.values
        for k in (1, 2):   # the size slider names what it sets
            w = self.controls[f"size{k}"]
            label = _size_label(v[f"kind{k}"], k)
            if w.description != label:
                w.description = label
        out = {}
        if tw:
            out.update({"ω₁": c.omega1, "ω₂": c.omega2, "ω₃ = ω₁ + ω₂": c.omega3,
                        "pole of sum": _xy_or_ideal(c.P),
                        "case": _short_case(twists_case(c.v1, c.v2))})
        else:
            out.update({"F₁": c.F1, "F₂": c.F2, "|F₃| = |F₁ + F₂|": c.F3,
                        "meet of lines": _meet_label(c), "case": _short_case(wrenches_case(c.f1, c.f2))})
        out.update({"β": "none" if c.beta is None else c.beta,
                    "ρ": "none" if c.rho is None else c.rho,
                    "sum": tuple(float(x) for x in c.sum.array)})
        return out

    def scene_picture(self, state, view=None):
        v = self.shown_values or self.values
        feet = ((v["x1"], v["y1"]), (v["x2"], v["y2"]))
        # a translation's velocity drawn from its point: the arrow whose tip its direction handle is
        arms = tuple(feet[k - 1] if v[f"kind{k}"] == "translation" else None for k in (1, 2))
        return screw_sum_picture(state["mode"], state["c"], anchors=feet, arms=arms,
                                 view=view or self.limits, size=self.figure_px)

    def handle_words(self, name: str) -> str:
        """What dragging handle ``name`` does, in words (for its hover text).

        Parameters
        ----------
        name : str
            The handle's name (``v₁``, ``f₂ direction``).

        Returns
        -------
        str

        Examples
        --------
        >>> ScrewSumExplorer(display="agg").handle_words("v₁ direction")
        "direction of u₁ (v₁ a translation): drag the arrow's tip to turn it"
        """
        return _HANDLE_TIPS.get(name, f"drag to change {name}")

    def handles(self) -> list[Handle]:
        # a handle of a screw of another kind is not draggable now; named as the picture labels
        # the screw (v₁, f₂), since a refused drag names its handle
        out = []
        for k in (1, 2):
            s = _SUBSCRIPT[k]
            def kind_is(kind, k=k):
                return lambda: shown(self).get(f"kind{k}") == kind
            xy = (f"x{k}", f"y{k}")
            turn = (f"angle{k}", f"size{k}")
            out += [xy_handle(self, f"v{s}", *xy, when=kind_is("rotation")),
                    arrow_handle(self, f"v{s} direction", *xy, *turn, arm=ARM, flip=True,
                                 when=kind_is("translation")),
                    xy_handle(self, f"f{s}", *xy, when=kind_is("force")),
                    arrow_handle(self, f"f{s} direction", *xy, *turn, arm=ARM, flip=True, when=kind_is("force"))]
        return out
