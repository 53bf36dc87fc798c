"""Chapter 4's constructions one step at a time, like a construction protocol (thesis 4.2–4.7).

A menu picks a construction of :mod:`planargeo.scenes.construction`; a *step* slider draws it
up to that step, captioned with the step's equation.  Every input has a slider and, where it is
a point, a drag handle; :meth:`ConstructionExplorer.export_layers` writes an SVG with one layer
per step, for slides.

Examples
--------
>>> ex = ConstructionExplorer("twist_sum", display="agg", x1=0.0, y1=0.0, w1=1.0,
...                           x2=4.0 - 1.0, y2=0.0, w2=3.0)
>>> ex.readout_values["pole of v₃"]                 # β = 3/4 of the way from Q₁ to Q₂ (4.12)
(2.25, 0.0)
>>> _ = ex.drag("v₂", (3.0, 0.0), (3.0, 1.0), steps=2)   # the whole construction follows
>>> ex.readout_values["pole of v₃"]
(2.25, 0.75)
"""
from __future__ import annotations

import io
import re
from pathlib import Path

import ipywidgets as W

from planargeo.draw.pictures._words import subscript
from planargeo.draw.pictures.construction import construction_picture
from planargeo.errors import InputError
from planargeo.scenes.construction import CONSTRUCTIONS, construct, parameters
from planargeo.geometry.projective import is_ideal, to_xy
from planargeo.widgets._explorer import arrow_handle, explorer_data, shown, xy_handle
from planargeo.widgets.base import Explorer, Handle, Step
from planargeo.widgets.controls import widen

__all__ = ["ConstructionExplorer"]

#: the parameters' sliders: name pattern -> (lo, hi, step, unit)
_RANGES = {
    "x": (-3.0, 3.0, 0.05, "m"), "y": (-3.0, 3.0, 0.05, "m"),
    "w": (-3.0, 3.0, 0.05, "rad/s"), "qd": (-3.0, 3.0, 0.05, "rad/s"),
    "qdd": (-3.0, 3.0, 0.05, "rad/s²"), "alpha": (-3.0, 3.0, 0.05, "rad/s²"),
    "u": (-3.0, 3.0, 0.05, "m/s"), "angle": (-180.0, 180.0, 5.0, "deg"),
    "F": (-3.0, 3.0, 0.05, "N"), "tau": (-3.0, 3.0, 0.05, "N·m"),
    "m": (0.1, 5.0, 0.1, "kg"), "r": (0.05, 2.0, 0.05, "m"),
    "h": (-3.0, 3.0, 0.05, "m"), "k": (0.1, 3.0, 0.05, "rad/s"),
}

#: every construction the scene knows, in its order: the menu's (title, key) options
CHOICES = [(title, key) for key, (title, _) in CONSTRUCTIONS.items()]

ARM = 1.0

#: the construction's words, kept as data: slider labels, readout units, meanings
_DATA = explorer_data("construction")
_LABELS = _DATA["labels"]


def _label(kind: str, name: str) -> str:
    """The slider label of parameter ``name`` in construction ``kind``."""
    table = _LABELS[kind]
    if name in table:
        return table[name]
    m = re.fullmatch(r"([a-zA-Z]+)([12])", name)
    if m and f"{m.group(1)}{{k}}" in table:
        return table[f"{m.group(1)}{{k}}"].format(s=subscript(m.group(2)))
    unit = _range(name)[3]
    return name if unit == "—" else f"{name} ({unit})"


#: what a slider means where its label cannot say it all (its hover text), per construction; twist
#: addition's sliders set the centre of the rotation, the pole drawn (and its handle) is that centre
#: shifted by the translation (4.16): the two differ while u ≠ 0
_TIPS = {
    "twist_sum": {
        f"{c}{k}": (f"centre of ω{s}: the point the rotation ω{s} of v{s} turns about (4.10). The pole Q{s} "
                    f"drawn, where the handle v{s} sits, is this centre shifted by ρ = u{s}/ω{s} across u{s} "
                    f"(4.16): the same point while u{s} = 0")
        for k, s in (("1", "₁"), ("2", "₂")) for c in "xy"},
}

#: what dragging a handle does (its hover text), per construction; the others: "drag to move <name>"
_HANDLE_TIPS = {
    "twist_sum": {f"v{s}": (f"pole Q{s} of v{s}: drag it to move v{s}; the centre of ω{s} moves with it, "
                            f"ρ = u{s}/ω{s} away (4.16)") for s in "₁₂"},
    "wrench_sum": {**{f"f{s}": f"a point of f{s}'s line of action: drag it to move the line" for s in "₁₂"},
                   **{f"f{s} direction": f"direction of F{s}: drag it to turn the force (and set its size)"
                      for s in "₁₂"}},
}

#: draggable points per construction: (handle name, x parameter, y parameter); a handle is named as
#: the picture labels what it moves (v₁, f₂, vᵢ₋₁), since a refused drag names its handle
_POINTS = {
    "twist_sum": [("v₁", "x1", "y1"), ("v₂", "x2", "y2")],
    "wrench_sum": [("f₁", "x1", "y1"), ("f₂", "x2", "y2")],
    "velocity": [("vᵢ₋₁", "xv", "yv"), ("joint", "xj", "yj")],
    "acceleration": [("vᵢ₋₁", "xv", "yv"), ("aᵢ₋₁", "xa", "ya"), ("joint", "xj", "yj")],
    "newton_euler": [("centre of mass", "xc", "yc"), ("v", "xv", "yv"), ("a", "xa", "ya"),
                     ("joint", "xj", "yj")],
    "through_infinity": [("v₁", "x1", "y1"), ("h", "hx", "hy")],
}
#: direction handles: (handle name, x, y, angle parameter, size parameter)
_DIRECTIONS = {
    "wrench_sum": [("f₁ direction", "x1", "y1", "angle1", "F1"),
                   ("f₂ direction", "x2", "y2", "angle2", "F2")],
}

#: readout units by key (a vector: one per component)
_UNITS = {k: tuple(u) if isinstance(u, list) else u for k, u in _DATA["units"].items()}


def _short_case(text: str) -> str:
    """A special case in a few words: the name before its colon, and its equation."""
    first = text.split("; ")[0]
    eq = re.search(r"\(([^()]*)\)\s*$", first)
    head = first.split(":")[0].split(" (")[0].strip()
    return f"{head} ({eq.group(1)})" if eq else head


def _range(name: str):
    for key in sorted(_RANGES, key=len, reverse=True):
        if name.startswith(key) and (name[len(key):].isdigit() or name[len(key):] in ("", "v", "a",
                                                                                          "j", "c", "x", "y")):
            return _RANGES[key]
    return (-3.0, 3.0, 0.05, "—")


class ConstructionExplorer(Explorer):
    """Chapter 4's constructions drawn step by step, with their captions and equations.

    Parameters
    ----------
    construction : str
        The construction shown first, a key of :data:`planargeo.scenes.construction.CONSTRUCTIONS`.
    **kwargs
        As :class:`~planargeo.widgets.base.Explorer`: ``display`` and initial control values.

    Raises
    ------
    InputError
        An unknown construction or control, or a value a control does not take.
    PlanargeoError
        Initial values the construction cannot be built from (e.g. a zero twist).
    """

    slug = "construction"
    title = "Step by step: chapter 4's constructions"
    figsize = (5.6, 5.6)
    limits = (-4.0, 4.0, -4.0, 4.0)
    #: ("earlier" only changes the drawing too, but stays a plain control: a recompute is cheap)
    display_controls = ("step",)
    scale = 3.0
    units = _UNITS

    def __init__(self, construction: str = "twist_sum", **kwargs):
        if construction not in CONSTRUCTIONS:
            raise InputError(f"construction must be one of {list(CONSTRUCTIONS)}, got {construction!r}")
        self._first = construction
        #: every parameter of every construction, with the first construction's defaults
        self._all_params: dict[str, float] = {}
        for kind in CONSTRUCTIONS:
            for name, default in parameters(kind).items():
                self._all_params.setdefault(name, default)
        self._all_params.update(parameters(construction))
        self._shown_kind: str | None = None
        super().__init__(construction=construction, **kwargs)
        self.controls["construction"].observe(
            self.guarded(lambda ch: self._follow_kind(ch["new"])), names="value")
        self._follow_kind(self.values["construction"])

    @property
    def construction(self) -> str:
        """The construction shown (a key of :data:`~planargeo.scenes.construction.CONSTRUCTIONS`)."""
        return self._shown_kind or self._first

    @property
    def params(self) -> dict[str, float]:
        """The parameters of the construction shown and their defaults."""
        return parameters(self.construction)

    @property
    def n_steps(self) -> int:
        """Number of steps of the construction shown."""
        if self.state is not None:
            return len(self.state["c"].steps)
        return len(construct(self.construction).steps)

    def _follow_kind(self, kind: str, n: int | None = None) -> None:
        """The step slider's range (``n`` steps) and the sliders shown follow ``kind``."""
        if kind not in CONSTRUCTIONS:
            return
        if n is None:
            n = len(self.state["c"].steps) if self.state is not None and self.state["kind"] == kind \
                else len(construct(kind).steps)
        w = self.controls["step"]
        # (In the page, the End key on the slider still goes to the max the slider was first shown
        # with (3 for twist addition): ipywidgets 8.1's noUiSlider takes Home / End from its creation
        # range, a bare IntSlider whose max grows does the same; mouse and arrows use the new range.)
        with self._quietly():
            if w.max < n:          # ahead of the value, or the page pulls it back to the old range's end
                widen(w, n)
            elif w.max != n:
                w.max = n
        used = set(parameters(kind))
        tips = _TIPS.get(kind, {})
        for name in self._all_params:
            c = self.controls[name]
            label = _label(kind, name) if name in used else c.description
            if c.description != label:
                c.description = label
            if name in used and hasattr(self, "_tooltips"):    # the hover text of this construction
                self._tooltips[name] = tips.get(name)
                if not c.disabled and c.tooltip != tips.get(name):
                    c.tooltip = tips.get(name)
            display = None if name in used else "none"
            if c.layout.display != display:
                c.layout.display = display

    def make_controls(self):
        n = len(construct(self._first).steps)
        # (the label at its own width: in the page's default 80 px it read "constructi…")
        c = {"construction": W.Dropdown(options=CHOICES, value=self._first, description="construction",
                                        style={"description_width": "initial"},
                                        layout=W.Layout(width="310px")),
             "step": Step(1, n, 1, n, "step", integer=True),
             "earlier": W.ToggleButtons(options=("faded", "shown", "hidden"), value="faded",
                                        description="earlier steps",
                                        style={"description_width": "initial"})}
        for name, default in self._all_params.items():
            lo, hi, st, _unit = _range(name)
            c[name] = Step(lo, hi, st, default, _label(self._first, name))
        return c

    def adjust(self, values, changed):
        # a new construction starts from its own defaults (those not set with it), every step shown
        kind = values["construction"]
        if self._shown_kind is None or kind == self._shown_kind:
            return {}
        self._follow_kind(kind)
        out = {k: v for k, v in parameters(kind).items() if k not in changed}
        if "step" not in changed:
            out["step"] = len(construct(kind).steps)
        return out

    def disabled(self, values):
        kind = values["construction"]
        used = set(parameters(kind))
        title = CONSTRUCTIONS[kind][0].split(" (")[0].lower()
        out = {k: f"{title} has no such input" for k in self._all_params if k not in used}
        if int(values["step"]) <= 1:
            out["earlier"] = "step 1 has no earlier steps: move the step slider on"
        if kind == "twist_sum":
            for k in "12":
                s = subscript(k)
                if values[f"u{k}"] == 0:
                    out[f"angle{k}"] = f"u{s} = 0: no translation, so no direction; set u{s} first"
                if values[f"w{k}"] == 0:
                    out[f"x{k}"] = out[f"y{k}"] = (f"ω{s} = 0: v{s} is a translation, its pole at "
                                                   f"infinity; a centre counts only while ω{s} ≠ 0")
        return out

    def explain(self):
        kind = self.values["construction"] if self.state is None else self.construction
        return {**_DATA[kind], **_DATA["common"]}

    def compute(self, values, changed):
        kind = values["construction"]
        return {"kind": kind, "c": construct(kind, **{k: values[k] for k in parameters(kind)})}

    def readout_of(self, state):
        # the step's full caption is drawn on the picture; the sliders shown follow the construction
        c = state["c"]
        self._shown_kind = state["kind"]
        n = len(c.steps)
        self._follow_kind(state["kind"], n)
        k = min(int(self.values["step"]), n)
        step = c.steps[k - 1]
        self.caption = f"Step {k}/{n}: {step.caption}"
        out = {"step": f"{k}/{n}", "equation": step.equation}
        out.update(c.values)
        out["case"] = _short_case(c.case)
        return out

    #: the view: the sliders' reach (±3 m) and a margin; ±4 m where a direction handle reaches 1 m
    #: beyond a force's point, and for twist addition (a sum shifted by ρ = u/ω lands beyond ±3 m);
    #: a band for the caption is added below
    VIEW = (-3.4, 3.4, -3.4, 3.4)
    VIEWS = {"wrench_sum": (-4.0, 4.0, -4.0, 4.0), "twist_sum": (-4.0, 4.0, -4.0, 4.0)}

    def scene_picture(self, state, view=None, *, all_steps: bool = False, caption=None):
        """The state's picture (:func:`planargeo.draw.pictures.construction.construction_picture`).

        Parameters
        ----------
        state : dict
        view : (x0, x1, y0, y1), optional
            The view (default: :attr:`VIEWS` of the construction, or :attr:`VIEW`).
        all_steps : bool
            Every step at full strength (the layered export).
        caption : str, optional
            Instead of the step's caption.

        Returns
        -------
        Picture
        """
        return construction_picture(state["c"], step=int(self.values["step"]), earlier=self.values["earlier"],
                                    view=view or self.VIEWS.get(state["kind"], self.VIEW), size=self.figure_px,
                                    all_steps=all_steps, caption=caption, band_below=view is None)

    def _pole_handle(self, name: str, kx: str, ky: str) -> Handle:
        """Twist addition's handle ``v₁`` / ``v₂``: on the pole drawn (the centre shifted by the
        translation, 4.16), moving the centre with it; none while the pole is at infinity or outside
        the construction's view (a slow rotation's pole is far off: the sliders still reach it)."""
        k = kx[1:]
        x0, x1, y0, y1 = self.VIEWS["twist_sum"]

        def pole():
            if self.state is None or self.state["kind"] != "twist_sum":
                return None
            q = {e.name: e.value for e in self.state["c"].steps[0].elements}.get(f"Q{k}")
            if q is None or bool(is_ideal(q)):
                return None
            p = to_xy(q)
            return p if x0 <= p[0] <= x1 and y0 <= p[1] <= y1 else None

        def where():
            p = pole()
            return None if p is None else (float(p[0]), float(p[1]))

        def drag(x, y):
            p, v = pole(), shown(self)
            if p is None:
                return {}
            return {kx: x - (float(p[0]) - v[kx]), ky: y - (float(p[1]) - v[ky])}

        return Handle(name, where, drag)

    def handle_words(self, name: str) -> str:
        """What dragging handle ``name`` of the construction shown does, in words (its hover text).

        Parameters
        ----------
        name : str
            The handle's name (as the picture labels what it moves).

        Returns
        -------
        str

        Examples
        --------
        >>> ConstructionExplorer("wrench_sum", display="agg").handle_words("f₁ direction")
        'direction of F₁: drag it to turn the force (and set its size)'
        """
        return _HANDLE_TIPS.get(self.construction, {}).get(name, f"drag to move {name}")

    def handles(self) -> list[Handle]:
        if self.construction == "twist_sum":
            return [self._pole_handle(*p) for p in _POINTS["twist_sum"]]
        return ([xy_handle(self, *p) for p in _POINTS[self.construction]]
                + [arrow_handle(self, *d, arm=ARM, flip=True) for d in _DIRECTIONS.get(self.construction, [])])

    def export_layers(self, path=None) -> Path:
        """Write the construction as an SVG, each step at full strength in ``<g id="step-K-name">``.

        Parameters
        ----------
        path : str or Path, optional
            Default: ``planargeo-construction-<kind>-layers.svg`` in the export folder.

        Returns
        -------
        Path

        Raises
        ------
        InputError
            ``path`` is not a path.
        OutputError
            The file cannot be written.
        """
        name = f"planargeo-construction-{self.construction}-layers.svg"
        path = self._export_path(Path(self.export_dir or Path.cwd()) / name if path is None else path, "svg")
        pic = self.scene_picture(self.state, None, all_steps=True, caption=self.state["c"].title).to_dict()
        return self._write(path, layered_svg(pic, self.step_ids()))

    def step_ids(self) -> list[str]:
        """The SVG group ids of the steps of the construction shown, in order (``step-K-name``).

        Returns
        -------
        list of str
        """
        if self.state is None:
            return []
        return [f"step-{k + 1}-{s.id}" for k, s in enumerate(self.state["c"].steps)]


def layered_svg(pic: dict, step_ids: list[str]) -> bytes:
    """The picture ``pic`` (its elements carry their 1-based ``step``) as SVG, every step's elements in
    one group ``<g id="step-K-name">`` of ``step_ids``."""
    import xml.etree.ElementTree as ET

    from planargeo.draw.render import figure
    from planargeo.draw.style import rc_context

    ns = "http://www.w3.org/2000/svg"
    ET.register_namespace("", ns)
    ET.register_namespace("xlink", "http://www.w3.org/1999/xlink")
    step_of = {el["id"]: el["step"] for el in pic["elements"] if "step" in el}
    buf = io.BytesIO()
    with rc_context():                       # fixed fonts, and SVG ids from a fixed salt
        figure(pic).savefig(buf, format="svg", metadata={"Date": None})
    root = ET.fromstring(buf.getvalue())
    groups = {k: ET.Element(f"{{{ns}}}g", {"id": gid}) for k, gid in enumerate(step_ids, start=1)}
    home = None       # (parent, index) of the first element of a step: the groups go there, in step order
    for parent in list(root.iter()):
        for child in list(parent):
            gid = (child.get("id") or "").split(":")[0]
            if child.tag != f"{{{ns}}}g" or gid not in step_of:
                continue
            if home is None:
                home = (parent, list(parent).index(child))
            parent.remove(child)
            groups[step_of[gid]].append(child)     # within a step, the picture's drawing order
    parent, at = home if home is not None else (root, len(root))
    for k in sorted(groups, reverse=True):
        parent.insert(at, groups[k])
    return ET.tostring(root, xml_declaration=True, encoding="utf-8")
