"""Chapter 4's constructions one step at a time, like a construction protocol (thesis 4.2–4.7).

A *construction* menu offers every construction that
:mod:`planargeo.scenes.construction` knows: twist addition, wrench addition,
velocity and acceleration kinematics across a joint, the Newton–Euler balance
of one body, and a pole dragged through infinity.  A *step* slider draws the
construction up to that step; the caption under the drawing names the step and
its equation, earlier steps stay (faded, at full strength or hidden: the
*earlier steps* buttons), later ones are hidden.  Every input (poles, rates,
force lines, the joint, the centre of mass) has a slider and, where it is a
point, a drag handle: dragging redoes the whole construction.  The sliders of
inputs the chosen construction does not use are disabled (and hidden).  The
*key* shows what each colour and mark stands for (a pole, a force line, a
construction line...).  The steps come from
:func:`planargeo.scenes.construction.construct`;
:func:`planargeo.draw.pictures.construction.construction_picture` draws them.

For slides, :meth:`ConstructionExplorer.export_layers` writes an SVG with
every step in its own layer, ``<g id="step-K-name">``, to reveal one by one.

Examples
--------
>>> ex = ConstructionExplorer("twist_sum", display="agg", x1=0.0, y1=0.0, w1=1.0,
...                           x2=4.0 - 1.0, y2=0.0, w2=3.0)
>>> ex.readout_values["pole of v₃"]                 # β = 3/4 of the way from Q₁ to Q₂ (4.12)
(2.25, 0.0)
>>> ex.set(step=1).caption
'Step 1/3: Q₁, Q₂: the poles of v₁ and v₂ (4.10)'
>>> _ = ex.drag("v2", (3.0, 0.0), (3.0, 1.0), steps=2)   # the whole construction follows
>>> ex.readout_values["pole of v₃"]
(2.25, 0.75)
>>> ex.set(construction="velocity").readout_values["pole of vᵢ"]   # every construction, one menu
(0.0, 0.4)
"""
from __future__ import annotations

import io
import re
from pathlib import Path

import ipywidgets as W

from planargeo.draw.pictures.construction import construction_picture
from planargeo.errors import InputError
from planargeo.files import atomic_write
from planargeo.scenes.construction import CONSTRUCTIONS, construct, parameters
from planargeo.widgets._explorer import arrow_handle, xy_handle
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
    "h": (-3.0, 3.0, 0.05, "m"), "k": (0.1, 3.0, 0.05, "rad/s"),
}

#: every construction the scene knows, in its order: the menu's (title, key) options
CHOICES = [(title, key) for key, (title, _) in CONSTRUCTIONS.items()]

_SUB = {"1": "₁", "2": "₂"}

ARM = 1.0
FADED = 0.4

#: what each parameter's slider says, per construction (symbol and unit; no code names)
_LABELS = {
    "twist_sum": {"x{k}": "pole of v{s}: x (m)", "y{k}": "pole of v{s}: y (m)",
                  "w{k}": "ω{s} (rad/s)", "u{k}": "translation u{s} (m/s)",
                  "angle{k}": "direction of u{s} (deg)"},
    "wrench_sum": {"x{k}": "point of f{s}: x (m)", "y{k}": "point of f{s}: y (m)",
                   "F{k}": "force F{s} (N)", "angle{k}": "direction of F{s} (deg)",
                   "tau{k}": "couple τ{s} (N·m)"},
    "velocity": {"xv": "pole of vᵢ₋₁: x (m)", "yv": "pole of vᵢ₋₁: y (m)", "w": "ωᵢ₋₁ (rad/s)",
                 "xj": "joint: x (m)", "yj": "joint: y (m)", "qd": "q̇ᵢ (rad/s)"},
    "acceleration": {"xv": "pole of vᵢ₋₁: x (m)", "yv": "pole of vᵢ₋₁: y (m)", "w": "ωᵢ₋₁ (rad/s)",
                     "xa": "pole of aᵢ₋₁: x (m)", "ya": "pole of aᵢ₋₁: y (m)",
                     "alpha": "αᵢ₋₁ (rad/s²)", "xj": "joint: x (m)", "yj": "joint: y (m)",
                     "qd": "q̇ᵢ (rad/s)", "qdd": "q̈ᵢ (rad/s²)"},
    "newton_euler": {"m": "mass m (kg)", "xc": "centre of mass: x (m)", "yc": "centre of mass: y (m)",
                     "r": "radius of gyration r (m)", "xv": "pole of v: x (m)", "yv": "pole of v: y (m)",
                     "w": "ω (rad/s)", "xa": "pole of a: x (m)", "ya": "pole of a: y (m)",
                     "alpha": "α (rad/s²)", "xj": "joint: x (m)", "yj": "joint: y (m)"},
    "through_infinity": {"x1": "pole of v₁: x (m)", "y1": "pole of v₁: y (m)", "w1": "ω₁ (rad/s)",
                         "hx": "handle h: x (m)", "hy": "handle h: y (m)", "k": "size k of v₂ (rad/s)"},
}


def _label(kind: str, name: str) -> str:
    """The slider label of parameter ``name`` in construction ``kind``."""
    table = _LABELS[kind]
    if name in table:
        return table[name]
    m = re.fullmatch(r"([a-zA-Z]+)([12])", name)
    if m and f"{m.group(1)}{{k}}" in table:
        return table[f"{m.group(1)}{{k}}"].format(s=_SUB[m.group(2)])
    unit = _range(name)[3]
    return name if unit == "—" else f"{name} ({unit})"


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

#: a twist [vx, vy, ω], an acceleration [ax, ay, α], a wrench [fx, fy, τ]: one unit per component
TWIST_UNITS = ("m/s", "m/s", "rad/s")
ACCEL_UNITS = ("m/s²", "m/s²", "rad/s²")
WRENCH_UNITS = ("N", "N", "N·m")

#: readout units by key
_UNITS = {"ω₁": "rad/s", "ω₂": "rad/s", "ω₃ = ω₁ + ω₂": "rad/s", "ρ": "m", "β": "—",
          "pole of v₃": "m", "F₁": "N", "F₂": "N", "F₃": "N", "meet P": "m", "f₃": WRENCH_UNITS,
          "ωᵢ₋₁": "rad/s", "q̇ᵢ": "rad/s", "ωᵢ": "rad/s", "kᵢ": "m", "βᵢ": "—",
          "pole of vᵢ": "m", "q̈ᵢ": "rad/s²", "|κᵢ|": "m/s²", "ρᵢ": "m", "pole of aᵢ": "m",
          "aᵢ": ACCEL_UNITS, "m": "kg", "|Ia|": "N", "|p|": "N", "|fⁿᵉᵗ|": "N", "τ": "N·m",
          "ρ = τ/|fⁿᵉᵗ|": "m", "fⁿᵉᵗ": WRENCH_UNITS, "power of fⁿᵉᵗ on v": "W", "step": "—",
          "equation": "—", "case": "—", "weight of v₂": "—", "v₂": "—", "pole of v₂": "m",
          "v₃": TWIST_UNITS}

#: the meaning of every symbol each construction shows (figure labels and readout rows)
_EXPLAIN_COMMON = {
    "∞": "a point at infinity (a direction), drawn at the edge of the view as an arrow its way (5.5)",
    "step": "the step shown, of all the construction's steps",
    "equation": "the thesis equation the step uses",
    "case": "the special case reached, by name and equation (10.2.4)",
}
EXPLAIN = {
    "twist_sum": {
        "v₁": "the first twist: a rotation ω₁ about its pole Q₁, plus a translation u₁ (4.10)",
        "v₂": "the second twist: ω₂ about Q₂, plus a translation u₂ (4.10)",
        "v₃ = v₁ + v₂": "their sum, whose pole lies on the line Q₁Q₂ (4.11)",
        "Q₁, Q₂": "the poles of v₁ and v₂, the points that do not move (4.10)",
        "ω₁": "angular velocity of v₁ (4.10)", "ω₂": "angular velocity of v₂ (4.10)",
        "ω₃ = ω₁ + ω₂": "angular velocity of the sum (4.11)",
        "β": "lever ratio: v₃'s pole is at Q₁ + β (Q₂ − Q₁), β = ω₂/(ω₁+ω₂) (4.12)",
        "ρ": "shift of a rotation by a translation, ρ = u/ω (4.16)",
        "pole of v₃": "the pole of the sum (4.12–4.13)",
    },
    "wrench_sum": {
        "f₁": "the first wrench: a force F₁ on its line, plus a couple τ₁ (4.27, 4.46)",
        "f₂": "the second wrench: a force F₂ on its line, plus a couple τ₂ (4.27, 4.46)",
        "f₃ = f₁ + f₂": "their sum, on a line through the meet P (4.33)",
        "f₃": "the sum's components [fx, fy, τ]: force and moment about the origin (4.27)",
        "P": "the meet P = L₁ × L₂ of the two lines of action (5.34)",
        "meet P": "where the lines of f₁ and f₂ meet (5.34)",
        "F₁": "magnitude of the force f₁ (4.27)", "F₂": "magnitude of the force f₂ (4.27)",
        "F₃": "magnitude of the summed force (4.39)",
        "β": "lever ratio of parallel forces, β = F₂/(F₁+F₂) (4.43)",
        "ρ": "shift of a force by a couple, ρ = τ/F (4.46)",
    },
    "velocity": {
        "vᵢ₋₁": "the velocity twist of the previous body, a rotation ωᵢ₋₁ about its pole (4.47)",
        "sᵢq̇ᵢ": "the joint's relative rotation: unit rotation sᵢ about the joint times q̇ᵢ (2.1)",
        "vᵢ": "the body's velocity twist vᵢ = vᵢ₋₁ + sᵢ q̇ᵢ (4.47)",
        "ωᵢ₋₁": "angular velocity of the previous body (4.47)",
        "q̇ᵢ": "the joint's rate (4.47)", "ωᵢ": "angular velocity of the body, ωᵢ₋₁ + q̇ᵢ (4.49)",
        "kᵢ": "distance from the pole of vᵢ₋₁ to the joint (4.48)",
        "βᵢ": "lever ratio βᵢ = q̇ᵢ/(q̇ᵢ + ωᵢ₋₁): vᵢ's pole is βᵢ kᵢ along the lever (4.48)",
        "pole of vᵢ": "the pole of the body's velocity (4.48)",
    },
    "acceleration": {
        "aᵢ₋₁": "the acceleration twist of the previous body, α about its pole (4.52)",
        "vᵢ": "the body's velocity twist vᵢ = vᵢ₋₁ + sᵢ q̇ᵢ (4.47)",
        "sᵢq̈ᵢ": "the joint's relative acceleration about the joint (4.52)",
        "κᵢ": "the bias acceleration κᵢ = vᵢ × sᵢ q̇ᵢ, a translation (4.53)",
        "sᵢq̈ᵢ + κᵢ": "what the joint adds: a rotation ρᵢ from the joint (4.54)",
        "aᵢ": "the body's acceleration aᵢ = aᵢ₋₁ + sᵢ q̈ᵢ + κᵢ, components [ax, ay, α] (4.52)",
        "ωᵢ₋₁": "angular velocity of the previous body (4.47)", "q̇ᵢ": "the joint's rate (4.47)",
        "q̈ᵢ": "the joint's acceleration (4.52)",
        "kᵢ": "distance from the pole of vᵢ₋₁ to the joint (4.48)",
        "|κᵢ|": "size of the bias acceleration, ωᵢ₋₁ q̇ᵢ kᵢ (4.53)",
        "ρᵢ": "distance of the pole of sᵢq̈ᵢ + κᵢ from the joint, ωᵢ₋₁ q̇ᵢ kᵢ / q̈ᵢ (4.54)",
        "pole of aᵢ": "the acceleration pole of the body (4.52)",
    },
    "newton_euler": {
        "I": "the body's inertia, drawn as its circle of gyration about the centre of mass (4.58)",
        "v": "the body's velocity twist, ω about its pole (4.47)",
        "a": "the body's acceleration twist, α about its pole (4.52)",
        "Ia": "I a: the force that gives the acceleration a, on the axis of percussion of a (5.64)",
        "p": "the bias force p = −(v×)ᵀ I v, through the centre of mass (4.56)",
        "fⁿᵉᵗ": "the net force fⁿᵉᵗ = I a + p, components [fx, fy, τ] (4.55)",
        "joint": "the joint about which the torque is taken (4.57)",
        "m": "mass of the body (4.58)", "|Ia|": "magnitude of the force I a (5.64)",
        "|p|": "magnitude of the bias force, m l ω² (4.56)",
        "|fⁿᵉᵗ|": "magnitude of the net force (4.55)",
        "τ": "the joint torque: the net force's moment about the joint (4.57)",
        "ρ": "distance of the net force's line from the joint, τ/|fⁿᵉᵗ| (4.57)",
        "ρ = τ/|fⁿᵉᵗ|": "distance of the net force's line from the joint (4.57)",
        "r": "radius of gyration of the body about its centre of mass (4.58)",
        "power of fⁿᵉᵗ on v": "the power vᵀ fⁿᵉᵗ of the net force on the motion (5.73)",
    },
    "through_infinity": {
        "horizon": "the line at infinity drawn as a circle |h| = 2 m: a handle on it is a point at "
                   "infinity (10.2.4)",
        "h": "the handle that places v₂'s pole, inside the horizon or on it (10.2.4)",
        "v₁": "the first twist, ω₁ about its pole (4.10)",
        "v₂": "the twist v₂ = k [h_y, −h_x, 1 − |h|/R]: a rotation, or on the horizon a "
              "translation (10.2.4)",
        "v₃ = v₁ + v₂": "the sum, which moves on smoothly as v₂'s pole passes infinity (4.11)",
        "v₃": "the sum's components [vx, vy, ω] (4.10)",
        "weight of v₂": "the weight 1 − |h|/R of v₂'s pole: 0 on the horizon (10.2.4)",
        "pole of v₂": "the pole of v₂ (4.10)", "pole of v₃": "the pole of the sum (4.12)",
    },
}


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
        The construction shown first, a key of
        :data:`planargeo.scenes.construction.CONSTRUCTIONS`: ``"twist_sum"``,
        ``"wrench_sum"``, ``"velocity"``, ``"acceleration"``, ``"newton_euler"`` or
        ``"through_infinity"``.  The *construction* menu offers all of them.
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

    # ------------------------------------------------------------------ the chosen construction
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
        """The step slider's range (``n`` steps, default the construction's) and the sliders shown follow ``kind``."""
        if kind not in CONSTRUCTIONS:
            return
        if n is None:
            n = len(self.state["c"].steps) if self.state is not None and self.state["kind"] == kind \
                else len(construct(kind).steps)
        w = self.controls["step"]
        with self._quietly():
            if w.max != n:
                w.max = n
        used = set(parameters(kind))
        for name in self._all_params:
            c = self.controls[name]
            label = _label(kind, name) if name in used else c.description
            if c.description != label:
                c.description = label
            display = None if name in used else "none"
            if c.layout.display != display:
                c.layout.display = display

    # ------------------------------------------------------------------ explorer
    def make_controls(self):
        # The construction menu, the step slider, how earlier steps look, one slider per parameter.
        n = len(construct(self._first).steps)
        c = {"construction": W.Dropdown(options=CHOICES, value=self._first, description="construction",
                                        layout=W.Layout(width="310px")),
             "step": Step(1, n, 1, n, "step", integer=True).make("step"),
             "earlier": W.ToggleButtons(options=("faded", "shown", "hidden"), value="faded",
                                        description="earlier steps",
                                        style={"description_width": "initial"})}
        for name, default in self._all_params.items():
            lo, hi, st, _unit = _range(name)
            c[name] = Step(lo, hi, st, default, _label(self._first, name)).make(name)
        return c

    def adjust(self, values, changed):
        # A new construction starts from its own defaults (those not set with it), showing every step.
        kind = values["construction"]
        if self._shown_kind is None or kind == self._shown_kind:
            return {}
        self._follow_kind(kind)
        out = {k: v for k, v in parameters(kind).items() if k not in changed}
        if "step" not in changed:
            out["step"] = len(construct(kind).steps)
        return out

    def disabled(self, values):
        # The sliders of parameters the chosen construction does not use, with the reason.
        kind = values["construction"]
        used = set(parameters(kind))
        title = CONSTRUCTIONS[kind][0].split(" (")[0].lower()
        out = {k: f"{title} has no such input" for k in self._all_params if k not in used}
        if int(values["step"]) <= 1:
            out["earlier"] = "step 1 has no earlier steps: move the step slider on"
        return out

    def explain(self):
        # The meaning of every symbol the chosen construction shows, with its thesis equation.
        kind = self.values["construction"] if self.state is None else self.construction
        return {**EXPLAIN[kind], **_EXPLAIN_COMMON}

    def compute(self, values, changed):
        # The construction for the parameter values (may raise a named PlanargeoError).
        kind = values["construction"]
        return {"kind": kind, "c": construct(kind, **{k: values[k] for k in parameters(kind)})}

    def readout_of(self, state):
        # The readout of ``state``: the step, its equation, the construction's numbers, the special case.
        # The step's full caption (:attr:`caption`) is drawn above the picture; the step
        # slider's range and the sliders shown follow the construction.
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
            The view the user zoomed or panned to (default: :attr:`VIEWS` of the construction, or
            :attr:`VIEW`).
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

    # ------------------------------------------------------------------ handles
    def handles(self) -> list[Handle]:
        # Drag handles: the construction's input points, and force directions by their arrow tip.
        return ([xy_handle(self, *p) for p in _POINTS[self.construction]]
                + [arrow_handle(self, *d, arm=ARM, flip=True) for d in _DIRECTIONS.get(self.construction, [])])

    # ------------------------------------------------------------------ export
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
        pic = self.scene_picture(self.state, None, all_steps=True, caption=c.title).to_dict()
        written = atomic_write(path, layered_svg(pic, self.step_ids())).resolve()
        self.last_export = written
        return written

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
    """The picture ``pic`` as SVG, every step's elements in one group ``<g id="step-K-name">``.

    Parameters
    ----------
    pic : dict
        A construction's picture (:func:`~planargeo.draw.pictures.construction.construction_picture`),
        whose elements carry their ``step`` (1-based).
    step_ids : list of str
        The group id of each step.

    Returns
    -------
    bytes
        The SVG document (the same bytes for the same picture).
    """
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
