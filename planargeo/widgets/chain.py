"""Chain explorer: an N-link planar chain with its geometric overlays (thesis ch. 4, 6, 7).

Controls set the number of links (1-20), the joint types (all revolute, all
prismatic, or alternating), the joint angles (first joint and a common bend
for the others), the joint speeds, a torque (on all joints, the first or the
last), the position of the base, and per joint (lists typed as ``30, -20, 10``
override those patterns joint by joint), and toggle overlays drawn with
:mod:`planargeo.draw`, each element labelled with its thesis symbol:

* velocity poles ``v_i`` (points, 4.5) and acceleration poles ``a_i`` (4.6),
* bias terms: the bias accelerations ``κ_i`` (points) and bias forces ``p_i`` (lines),
* internal (joint) force lines ``f_i = A_i a_i + d_i`` (3.13),
* the per-joint T/U split: the force ``f_i = T_i Q_i + R_i μ_i`` (6.38, 6.104)
  into the active part ``TQ_i`` along the percussion axis and the reaction
  ``Rμ_i`` through the joint, and the acceleration ``a_i = s_i ψ_i + U_i γ_i``
  (6.44) into the part ``sψ_i`` along the joint's motion space
  (``ψ_i = T_iᵀ a_i``, 6.100) and the reactive part ``Uγ_i`` (``γ_i = R_iᵀ a_i``,
  6.101) in the quake space ``U_i = A_i⁻¹ R_i (R_iᵀ A_i⁻¹ R_i)⁻¹`` (6.45),
* the articulated inertias ``A_i`` (3.38) as conics.

The overlay checkboxes change the drawing only: toggling one re-renders the
last computed state (the split is derived from it once, when first shown).
Labels are placed where they fit (none overlaps another or leaves the axes);
the *focus* control picks one link (its poles, bias terms and articulated
inertia) or one joint (its force and T/U split): those are drawn labelled, in
bold, the rest faded, and the view zooms to them.

By hand: drag the end of link ``i`` to set joint ``i`` (its angle, or its
slide for a prismatic joint), keeping the others; drag the base to move the
whole chain.  Play integrates the motion frame by frame with
:func:`planargeo.simulate.simulate` (the ``frame`` slider replays the frames
computed so far); the readout shows the energy, the work of the (constant)
joint forces since the first frame and the energy drift ``E − E₀ − W`` (zero
but for the integration error; the chain is a tree: it has no constraint to
drift from).

Each state is solved once, by the articulated-body algorithm through the
scene (:func:`planargeo.scenes.chain.chain_workspace`: one kinematics pass);
the energies are read off that workspace.
"""
from __future__ import annotations

import itertools
import math

import ipywidgets as W
import numpy as np
from matplotlib.lines import Line2D

from planargeo.draw.artists import ConicArtist, LineArtist, PointArtist, clip_line, conic_geometry
from planargeo.draw.mechanism import LabelPlacer, ScaleBar
from planargeo.draw.style import COLORS, LABEL_PT
from planargeo.errors import InputError, SingularConfigurationError
from planargeo.mechanics.model import Body, Joint, Model
from planargeo.mechanics.subspaces import T_of
from planargeo.scenes.chain import chain_workspace
from planargeo.simulate.integrate import energy
from planargeo.widgets.base import Explorer, Handle, Step

__all__ = ["ChainExplorer", "chain_for", "parse_list"]

NMAX = 20
OVERLAYS = ("velocity poles", "acceleration poles", "bias terms", "internal forces",
            "T/U split", "articulated inertias")
JOINT_SETS = ("revolute", "prismatic", "alternating")
TORQUE_ON = ("all joints", "first joint", "last joint")
LIST_Q = "joint values (deg / m)"
#: controls that set the initial state (a change discards the simulated trajectory)
INITIAL = ("links", "joints", "angle", "bend", "slide", "speed", "torque", "torque on", "gravity",
           "base x (m)", "base y (m)", LIST_Q, "joint speeds", "joint torques")
#: slide range of a prismatic joint (m), the slide slider's
SLIDE = (-0.5, 1.0)
#: the ground under the base: a line and its hatching (NaN-separated strokes), relative to the base
_GROUND = np.vstack([[[-0.4, -0.1], [0.4, -0.1], [np.nan, np.nan]]]
                    + [[[x, -0.1], [x - 0.1, -0.2], [np.nan, np.nan]] for x in np.linspace(-0.35, 0.4, 6)])
#: unit of a joint's acceleration by joint kind
QDD_UNIT = {"revolute": "rad/s²", "prismatic": "m/s²"}
#: labels shown at most without a focus (each costs ~0.3 ms to draw; the focus labels the rest)
MAX_LABELS = 24
#: overlay artists made at the start, per overlay (more when a longer chain is shown)
POOL0 = 4
#: opacity of the elements outside the focus
FADED = 0.18
#: mathtext of each overlay symbol (thesis notation)
_TEX = {"f": "f", "v": "v", "a": "a", "TQ": "TQ", "Rμ": r"R\mu", "sψ": r"s\psi", "Uγ": r"U\gamma",
        "κ": r"\kappa", "p": "p", "A": "A"}


def _sym(symbol: str, i: int) -> str:
    """``symbol`` with the subscript ``i`` as mathtext (``$f_{3}$``; cheaper to draw than plain text)."""
    return f"${_TEX[symbol]}_{{{i}}}$"


def _fade(art, alpha) -> None:
    """Set the opacity of one of :mod:`planargeo.draw.artists`' artists and of its parts."""
    art.set_alpha(alpha)
    for child in art.get_children():
        child.set_alpha(alpha)


def chain_for(n: int, joints: str = "revolute", gravity: bool = True, length: float = 1.0,
              mass: float = 1.0, base=(0.0, 0.0)) -> Model:
    """The explorer's chain: ``n`` uniform slender links (mass ``mass``, length ``length``).

    Parameters
    ----------
    n : int
        Number of links, 1 to 20.
    joints : {"revolute", "prismatic", "alternating"}
        Joint kinds (alternating: revolute, prismatic, revolute...).  A
        prismatic joint slides along the parent link's axis.
    gravity : bool
        Gravity ``(0, -9.81)`` or none.
    length, mass : float
        Length (m) and mass (kg) of every link.
    base : (float, float)
        Position of the first joint (m).

    Returns
    -------
    Model
        Bodies ``link1``... on joints ``joint1``...

    Raises
    ------
    InputError
        ``n`` out of range or an unknown joint set.

    Examples
    --------
    >>> m = chain_for(3, "alternating")
    >>> [j.kind for j in m.joints], m.gravity
    (['revolute', 'prismatic', 'revolute'], (0.0, -9.81))
    """
    n = int(n)
    if not 1 <= n <= NMAX:
        raise InputError(f"n must be between 1 and {NMAX}, got {n}")
    if joints not in JOINT_SETS:
        raise InputError(f"joints must be one of {JOINT_SETS}, got {joints!r}")
    kinds = {"revolute": ["revolute"] * n, "prismatic": ["prismatic"] * n,
             "alternating": ["revolute" if i % 2 == 0 else "prismatic" for i in range(n)]}[joints]
    L, m = float(length), float(mass)
    bx, by = (float(v) for v in base)
    bodies = [Body(m, (L / 2, 0.0), m * L * L / 12, name=f"link{i + 1}") for i in range(n)]
    js = [Joint(k, (bx, by, 0.0) if i == 0 else (L, 0.0, 0.0), name=f"joint{i + 1}")
          for i, k in enumerate(kinds)]
    return Model(bodies, js, list(range(-1, n - 1)), (0.0, -9.81) if gravity else (0.0, 0.0))


def _list_text(description: str, placeholder: str) -> W.Text:
    return W.Text(value="", placeholder=placeholder, description=description,
                  continuous_update=False, style={"description_width": "initial"},
                  layout=W.Layout(width="310px"))


def parse_list(text: str, name: str) -> list[float]:
    """Numbers from ``"1, -2.5, 3"`` (empty text: no numbers).

    Parameters
    ----------
    text : str
        Numbers separated by commas or semicolons.
    name : str
        What the list is (named in the error).

    Returns
    -------
    list of float

    Raises
    ------
    InputError
        A part is not a finite number.

    Examples
    --------
    >>> parse_list("30, -20,0.5", "joint values")
    [30.0, -20.0, 0.5]
    >>> parse_list("  ", "joint values")
    []
    """
    items = [t for t in text.replace(";", ",").split(",") if t.strip()]
    try:
        out = [float(t) for t in items]
    except ValueError:
        raise InputError(f"{name} must be numbers separated by commas, got {text!r}") from None
    if not all(math.isfinite(x) for x in out):
        raise InputError(f"{name} must be finite numbers, got {text!r}")
    return out


def _num(x: float) -> str:
    """A list entry: short, and exact enough to round-trip a dragged value (10 digits)."""
    return f"{x:.10g}"


class ChainExplorer(Explorer):
    """Interactive N-link chain with velocity/acceleration poles, forces and inertias.

    Parameters
    ----------
    duration : float
        Seconds of motion Play integrates before it stops (or loops).
    fps : int
        Frames per second of Play (at speed 1×, each frame is ``1 / fps`` s of
        motion) and of :meth:`simulate`.
    **kw
        :class:`~planargeo.widgets.base.Explorer` options and initial control values.

    Raises
    ------
    InputError
        An unknown control or a value it does not take.
    """

    title = "Chain: poles, forces and articulated inertias"
    slug = "chain"
    figsize = (6.4, 5.6)
    limits = (-4.5, 4.5, -4.5, 4.5)
    grid = False
    display_controls = OVERLAYS
    scale = 1.0
    units = {"links": "—", "frame": "—", "t (s)": "s", "kinetic energy (J)": "J",
             "potential energy (J)": "J", "total energy (J)": "J", "energy drift (J)": "J",
             "work of the joint forces (J)": "J",
             "|base force| (N)": "N"}

    def make_controls(self):
        """The controls: chain, state, load, base, per-joint lists, overlays and the frame.

        Returns
        -------
        dict
            ``{name: widget}``.
        """
        c = {
            "links": Step(1, NMAX, 1, 4, "links", integer=True).make("links"),
            "joints": W.Dropdown(options=JOINT_SETS, value="revolute", description="joints"),
            "angle": Step(-180, 180, 1, -30, "angle (deg)").make("angle"),
            "bend": Step(-90, 90, 1, 20, "bend (deg)").make("bend"),
            "slide": Step(*SLIDE, 0.05, 0.2, "slide (m)").make("slide"),
            "speed": Step(-5, 5, 0.1, 1.0, "speed (rad/s, m/s)").make("speed"),
            "torque": Step(-50, 50, 0.5, 0.0, "torque (N·m, N)").make("torque"),
            "torque on": W.Dropdown(options=TORQUE_ON, value="all joints", description="torque on"),
            "gravity": W.Checkbox(value=True, description="gravity"),
            "base x (m)": Step(-3, 3, 0.1, 0.0, "base x (m)").make("base x (m)"),
            "base y (m)": Step(-3, 3, 0.1, 0.0, "base y (m)").make("base y (m)"),
            LIST_Q: _list_text(LIST_Q, "e.g. 30, -20, 0.4"),
            "joint speeds": _list_text("joint speeds", "e.g. 1, 0, -2"),
            "joint torques": _list_text("joint torques", "e.g. 0, 5"),
        }
        for name in OVERLAYS:
            c[name] = W.Checkbox(value=name in ("velocity poles", "internal forces"), description=name,
                                 indent=False)
        c["frame"] = Step(0, 0, 1, 0, "frame", integer=True).make("frame")
        c["frame"].disabled = True
        return c

    def __init__(self, *, duration: float = 10.0, fps: int = 25, **kw):
        self.duration, self.fps = float(duration), int(fps)
        self.play_fps = self.fps             # Play at 1×: one frame of 1 / fps s per tick
        self._model_key = None
        self._model = None
        self._traj = None  # the shown state's trajectory: dict t, q, qd (lists), e0, tau
        super().__init__(**kw)

    @property
    def player(self):
        """The frame slider (what the former Play widget was linked to; Play is now the base's)."""
        return self.controls["frame"]

    # -- figure ------------------------------------------------------------------
    def setup_axes(self, ax):
        """Equal-aspect axes without ticks (a 1 m scale bar instead: cheaper and clearer).

        Parameters
        ----------
        ax : matplotlib.axes.Axes
            The explorer's axes.
        """
        from planargeo.draw.style import setup_axes

        setup_axes(ax, self.limits, axis_off=True)

    def make_artists(self, ax):
        """Create every artist once: links, base, the overlay pools, focus marks and labels.

        Parameters
        ----------
        ax : matplotlib.axes.Axes
            The explorer's axes.
        """
        self.links_line = Line2D([], [], color=COLORS["ground"], lw=2.5, marker="o", ms=4,
                                 mfc="white", zorder=5)
        ax.add_line(self.links_line)
        self.focus_line = Line2D([], [], color=COLORS["ground"], lw=6.0, alpha=0.35,
                                 solid_capstyle="round", zorder=4.5, visible=False)
        ax.add_line(self.focus_line)
        self.focus_joint = Line2D([], [], marker="o", ms=12, mfc="none", mec="black", mew=2.0,
                                  ls="none", zorder=6, visible=False)
        ax.add_line(self.focus_joint)
        # the ground under the base, moved with it
        self.ground = Line2D([], [], color=COLORS["ground"], lw=1.2, zorder=4)
        ax.add_line(self.ground)
        z = np.array([0.0, 0.0, 1.0])
        zl = np.array([1.0, 0.0, 0.0])

        self._factories = []

        def pool(factory):
            # a pool of artists per overlay, grown (never shrunk) to the longest chain shown:
            # invisible artists still cost a draw call each
            out = []
            self._factories.append((out, factory))
            return out

        self.v_art = pool(lambda i: PointArtist(z, role="twist", glyph_scale=4.0))
        self.a_art = pool(lambda i: PointArtist(z, role="accel", glyph_scale=1.0))
        self.kappa_art = pool(lambda i: PointArtist(z, role="accel", glyph=False, markersize=4,
                                                    color=COLORS["momentum"]))
        self.p_art = pool(lambda i: LineArtist(zl, role="momentum", scale=None, linewidth=1.0))
        self.f_art = pool(lambda i: LineArtist(zl, role="wrench", scale=0.02))
        self.t_art = pool(lambda i: LineArtist(zl, role="wrench", scale=None, linestyle=":",
                                               linewidth=1.2))
        self.r_art = pool(lambda i: LineArtist(zl, role="reaction", scale=0.02))
        # acceleration split (6.44): s ψ (along the joint) and U γ (reactive part)
        self.spsi_art = pool(lambda i: PointArtist(z, role="accel", glyph=False, markersize=5))
        self.ugam_art = pool(lambda i: PointArtist(z, role="accel", glyph=False, markersize=5,
                                                   color=COLORS["reaction"]))
        self.A_art = pool(lambda i: ConicArtist(np.eye(3), role="inertia", linewidth=0.8))
        self._scaled = set()
        self._grow(POOL0)
        # label colour and the glyph clearance (points) of each layer's labels
        self._layers = [
            # artists, overlay, symbol, kind, per ("link" or "joint"), colour, clearance
            (self.f_art, "internal forces", "f", "line", "joint", COLORS["wrench"], 4.0),
            (self.v_art, "velocity poles", "v", "point", "link", COLORS["twist"], 12.0),
            (self.a_art, "acceleration poles", "a", "point", "link", COLORS["accel"], 9.0),
            (self.t_art, "T/U split", "TQ", "line", "joint", COLORS["wrench"], 4.0),
            (self.r_art, "T/U split", "Rμ", "line", "joint", COLORS["reaction"], 4.0),
            (self.spsi_art, "T/U split", "sψ", "point", "joint", COLORS["accel"], 5.0),
            (self.ugam_art, "T/U split", "Uγ", "point", "joint", COLORS["reaction"], 5.0),
            (self.kappa_art, "bias terms", "κ", "point", "link", COLORS["momentum"], 5.0),
            (self.p_art, "bias terms", "p", "line", "link", COLORS["momentum"], 4.0),
            (self.A_art, "articulated inertias", "A", "conic", "link", COLORS["inertia"], 4.0),
        ]
        for arts, _flag, sym, *_ in self._layers:     # a key entry per layer (the base's legend)
            arts[0].set_label(f"${_TEX[sym]}_i$")
        self.scale_bar = ScaleBar(ax, fontsize=LABEL_PT + 1.5)          # in the margin, under the axes
        self.time_text = self.fig.text(0.0, 0.0, "", va="center", ha="right", fontsize=LABEL_PT + 1.5)
        self.labels = LabelPlacer(ax, size=MAX_LABELS + 16, fontsize=LABEL_PT + 1.5)
        self._shown_labels = []
        self._edge_text = {}          # artists whose own label marks their edge arrow (focus)

    def _grow(self, n: int) -> None:
        """Make every overlay pool hold at least ``n`` artists (new ones hidden)."""
        for out, factory in self._factories:
            while len(out) < n:
                art = self.ax.add_artist(factory(len(out)))
                art.set_visible(False)
                out.append(art)
        self._scaled = set(self.f_art + self.r_art)

    # -- model / state -------------------------------------------------------------
    def model_for(self, v) -> Model:
        """The chain of the control values ``v`` (kept while they do not change).

        Parameters
        ----------
        v : dict
            Control values.

        Returns
        -------
        Model
        """
        key = (v["links"], v["joints"], v["gravity"], v["base x (m)"], v["base y (m)"])
        if key != self._model_key:
            self._model = chain_for(*key[:3], base=key[3:])
            self._model_key = key
        return self._model

    def initial_state(self, v):
        """``(model, q, qd, tau)`` the control values ``v`` describe (lists override patterns).

        Parameters
        ----------
        v : dict
            Control values.

        Returns
        -------
        tuple
            The model and the joint values, speeds and forces (arrays).

        Raises
        ------
        InputError
            A per-joint list that is not a list of numbers.
        """
        model = self.model_for(v)
        q = np.empty(model.nq)
        for i, j in enumerate(model.joints):
            if j.kind == "revolute":
                q[i] = math.radians(v["angle"] if i == 0 else v["bend"])
            else:
                q[i] = v["slide"]
        qd = np.full(model.nq, float(v["speed"]))
        tau = np.zeros(model.nq)
        sel = {"all joints": slice(None), "first joint": slice(0, 1),
               "last joint": slice(model.nq - 1, None)}[v["torque on"]]
        tau[sel] = float(v["torque"])
        # per-joint values typed as lists override the patterns, joint by joint
        for i, x in enumerate(parse_list(v[LIST_Q], "joint values")[:model.nq]):
            q[i] = math.radians(x) if model.joints[i].kind == "revolute" else x
        for i, x in enumerate(parse_list(v["joint speeds"], "joint speeds")[:model.nq]):
            qd[i] = x
        for i, x in enumerate(parse_list(v["joint torques"], "joint torques")[:model.nq]):
            tau[i] = x
        return model, q, qd, tau

    def adjust(self, values, changed):
        """Controls that follow a change: the frame, and the per-joint list against the sliders.

        A new initial state starts at frame 0 (its trajectory is not simulated
        yet).  While joint values are typed (or dragged) per joint, the
        ``angle`` slider still moves joint 1 (the list's first entry follows it),
        and ``bend`` / ``slide`` return every joint to the common pattern (the
        list is emptied), so that no slider is ever dead.

        Parameters
        ----------
        values : dict
            The control values asked for.
        changed : set of str
            The controls that changed.

        Returns
        -------
        dict
            Values of the controls that follow.
        """
        out = {}
        if changed & set(INITIAL) and values["frame"] != 0:
            out["frame"] = 0
        text = values[LIST_Q]
        if text.strip() and LIST_Q not in changed:
            if changed & {"bend", "slide"}:
                out[LIST_Q] = ""
            elif "angle" in changed and values["joints"] != "prismatic":
                items = [t.strip() for t in text.replace(";", ",").split(",") if t.strip()]
                items[0] = _num(values["angle"])
                out[LIST_Q] = ", ".join(items)
        return out

    def compute(self, v, changed):
        """The state of the controls: the chain solved by the ABA, at the frame shown.

        Parameters
        ----------
        v : dict
            Control values.
        changed : set of str
            Controls that changed (an initial-state change discards the trajectory).

        Returns
        -------
        dict
            ``model``, ``w`` (the ABA workspace), ``t``, ``tau``, ``traj``, ``ke``, ``pe``.

        Raises
        ------
        InputError
            A per-joint list that is not a list of numbers.
        """
        traj = None if changed & set(INITIAL) else self._traj
        model, q, qd, tau = self.initial_state(v)
        t = 0.0
        frame = int(v["frame"])
        if traj is not None and 0 < frame < len(traj["t"]):
            t, q, qd = traj["t"][frame], traj["q"][frame], traj["qd"][frame]
        w = chain_workspace(model, q, qd, tau)
        st = {"model": model, "w": w, "t": t, "tau": tau, "traj": traj}
        st["ke"], st["pe"] = (float(e) for e in energy(model, data=w))
        return st

    @staticmethod
    def tu_split(st) -> dict:
        """The per-joint T/U split of a computed state (derived once, kept in ``st``).

        The force split 6.38 with ``Q = sᵀ f`` (6.49), ``R μ = f − T Q``, and
        the acceleration split 6.44 with ``ψ = Tᵀ a`` (6.100), ``U γ = a − s ψ``,
        ``T = A s (sᵀ A s)⁻¹`` (6.105) from each body's articulated inertia.

        Parameters
        ----------
        st : dict
            A state of :meth:`compute`.

        Returns
        -------
        dict
            ``{"active": T Q, "reaction": R μ, "active_on": Q ≠ 0, "motion": s ψ,
            "reactive": U γ}`` (arrays of shape ``(N, 3)``, ``active_on`` ``(N,)``).
        """
        if "split" not in st:
            model, w = st["model"], st["w"]
            s = w.S.T.reshape(model.N, 3, 1)  # one-dof joints: column i is s_i
            T = T_of(w.A, s)[..., 0]
            Q = np.einsum("ij,ij->i", s[..., 0], w.f)
            active = T * Q[:, None]
            psi = np.einsum("ij,ij->i", T, w.a)
            motion = s[..., 0] * psi[:, None]
            st["split"] = {
                "active": active, "reaction": w.f - active,
                # an active part that is zero up to rounding (no joint torque) has no line to draw
                "active_on": np.abs(Q) > 1e-9 * np.maximum(1.0, np.abs(w.f).max(axis=1)),
                "motion": motion, "reactive": w.a - motion,
            }
        return st["split"]

    def figure_message(self, exc: Exception) -> str:
        """The refusal drawn on the figure, wrapped to stay inside the axes.

        Parameters
        ----------
        exc : Exception
            Why the update was refused.

        Returns
        -------
        str
        """
        import textwrap

        return textwrap.fill(super().figure_message(exc), 40)

    # -- focus, handles, play ------------------------------------------------------
    def focus_options(self) -> list[str]:
        """Bodies and joints the focus can pick: ``link1``..., ``joint1``... (all 20).

        Returns
        -------
        list of str
        """
        return [f"link{i}" for i in range(1, NMAX + 1)] + [f"joint{i}" for i in range(1, NMAX + 1)]

    def _focus(self, n: int):
        """``("link" | "joint", index)`` of the focus, or None (all; or beyond the chain)."""
        focus = self.controls.get("focus")
        name = "all" if focus is None else str(focus.value)
        for kind in ("link", "joint"):
            if name.startswith(kind) and name[len(kind):].isdigit():
                i = int(name[len(kind):]) - 1
                return (kind, i) if 0 <= i < n else None
        return None

    def _ends(self, w) -> np.ndarray:
        """World positions of the links' far ends (N, 2)."""
        return w.pose[:, :2] + np.column_stack([np.cos(w.pose[:, 2]), np.sin(w.pose[:, 2])])

    def handles(self) -> list:
        """Draggable handles: the base, and the end of every link.

        Dragging ``link i end`` sets joint ``i`` (the angle of the link's
        direction relative to its parent, or the slide of a prismatic joint
        along the parent's axis) and keeps every other joint; it writes the
        per-joint list (for link 1 with no list, the ``angle`` slider).

        Returns
        -------
        list of Handle
        """
        out = [Handle("base", lambda: (self.values["base x (m)"], self.values["base y (m)"]),
                      lambda x, y: {"base x (m)": float(x), "base y (m)": float(y)})]
        for i in range(NMAX):
            out.append(Handle(f"link {i + 1} end", self._end_where(i), self._end_drag(i)))
        return out

    def _end_where(self, i: int):
        def where():
            st = self.state
            if st is None or i >= st["model"].N:
                return None
            x, y = self._ends(st["w"])[i]
            return (float(x), float(y))
        return where

    def _end_drag(self, i: int):
        def drag(x: float, y: float) -> dict:
            st = self.state
            model, w = st["model"], st["w"]
            if i >= model.N:
                raise InputError(f"link {i + 1} is not in a chain of {model.N} links")
            px, py, th = (float(c) for c in w.pose[i])
            q = [float(c) for c in w.q]
            if model.joints[i].kind == "revolute":
                dx, dy = float(x) - px, float(y) - py
                if math.hypot(dx, dy) < 1e-9:
                    raise InputError(f"link {i + 1}'s end cannot be dragged onto joint {i + 1} "
                                     "(no direction for the link)")
                parent = th - q[i]
                new = math.atan2(dy, dx) - parent
                new = math.atan2(math.sin(new), math.cos(new))        # (-π, π]
                if i == 0 and not self.values[LIST_Q].strip() and not self.values["frame"]:
                    return {"angle": math.degrees(new)}
                q[i] = new
            else:
                e = np.array([math.cos(th), math.sin(th)])              # slides along the parent's axis
                foot = np.array([px, py]) - q[i] * e
                s = float((np.array([x, y], float) - e - foot) @ e)
                if not SLIDE[0] <= s <= SLIDE[1]:
                    raise InputError(f"joint {i + 1} slides between {SLIDE[0]:g} and {SLIDE[1]:g} m, "
                                     f"the drag asks for {s:.3g} m")
                q[i] = s
            shown = [math.degrees(v) if j.kind == "revolute" else v for v, j in zip(q, model.joints)]
            return {LIST_Q: ", ".join(_num(v) for v in shown)}
        return drag

    def play_step(self, values: dict, dt: float):
        """One Play frame: the motion integrated ``dt`` seconds further.

        The trajectory of the shown initial state is kept on the explorer and
        extended frame by frame with :func:`planargeo.simulate.simulate`
        (DOP853, ``rtol = 1e-8``) over exactly ``dt`` (so Play's speed control
        gives slow motion too); frames already computed are replayed (the first
        stored frame at least ``dt`` later).

        Parameters
        ----------
        values : dict
            The control values shown.
        dt : float
            Seconds of motion per Play frame.

        Returns
        -------
        dict or None
            ``{"frame": k}``, or None once ``duration`` seconds are shown.

        Raises
        ------
        SingularConfigurationError
            The integrator stopped (a singular configuration).
        """
        from planargeo.simulate.integrate import simulate

        if self._traj is None:
            model, q0, qd0, tau = self.initial_state(values)
            self._traj = {"t": [0.0], "q": [np.array(q0, float)], "qd": [np.array(qd0, float)],
                          "tau": tau, "model": model, "e0": self.state["ke"] + self.state["pe"]}
        traj = self._traj
        times = traj["t"]
        frame = min(int(values["frame"]), len(times) - 1)
        if times[frame] >= self.duration - 1e-9:
            return None
        goal = min(times[frame] + float(dt), self.duration)
        for j in range(frame + 1, len(times)):               # a stored frame: replayed
            if times[j] >= goal - 1e-9:
                return {"frame": j}
        while times[-1] < goal - 1e-9:
            r = simulate(traj["model"], traj["q"][-1], traj["qd"][-1], goal - times[-1],
                         tau=traj["tau"], progress=False)
            if r.status != "ok":
                raise SingularConfigurationError(f"simulation stopped at t = {times[-1]:.3g} s: "
                                                 f"{r.message}")
            times.append(goal)
            traj["q"].append(np.array(r.q[-1]))
            traj["qd"].append(np.array(r.qd[-1]))
        fr = self.controls["frame"]
        if fr.max < len(times) - 1:
            fr.max = len(times) - 1
            fr.disabled = False
        return {"frame": len(times) - 1}

    def simulate(self, duration: float | None = None) -> None:
        """Integrate the motion from the current state ahead of time (the frames Play and ``frame`` show).

        Parameters
        ----------
        duration : float, optional
            Seconds to integrate (default: the explorer's ``duration``).
        """
        try:
            d = self.duration if duration is None else float(duration)
            frame = self.values["frame"]
            old, self.duration = self.duration, max(self.duration, d)
            try:
                vals = dict(self.values, frame=0)
                while True:                                  # frames 1 / fps apart up to d
                    new = self.play_step(vals, 1.0 / self.fps)
                    if new is None or self._traj["t"][new["frame"]] >= d - 1e-9:
                        break
                    vals["frame"] = new["frame"]
            finally:
                self.duration = old
            self._changed.add("frame")       # show the trajectory's range (the frame is unchanged)
            self.controls["frame"].value = frame
            self._update()
        except Exception as exc:  # noqa: BLE001 - a button callback must never raise
            self._set_message(f"simulation failed: {exc}")

    # -- drawing ---------------------------------------------------------------------
    def _view(self, st, focus) -> tuple[float, float, float, float]:
        """The view: the whole chain's reach about the ground origin, or fitted to the focused element.

        Centred on the fixed origin, not on the base: a view that followed the base would move
        under the mouse while the base is dragged (and the drag would run away).  While any
        handle is dragged the view stays as it is.
        """
        if getattr(self, "_drag_active", None) is not None:
            x0, x1 = self.ax.get_xlim()
            y0, y1 = self.ax.get_ylim()
            return (x0, x1, y0, y1)
        model, w = st["model"], st["w"]
        chain = np.vstack([np.asarray(w.origin[0], float)[None, :], w.pose[:, :2], self._ends(w)])
        if focus is None:
            reach = max(model.N + 0.4, float(np.max(np.hypot(*chain.T))) + 0.4)
            return (-reach, reach, -reach, reach)
        kind, i = focus
        pts = [w.pose[i, :2], self._ends(w)[i]]
        mid = 0.5 * (pts[0] + pts[1])
        pts += [mid + (1.2, 1.2), mid - (1.2, 1.2)]          # at least a 2.4 m view
        v = self.values
        for arts, flag, _sym, kind_, per, *_ in self._layers:
            if per != kind or not v[flag] or not arts[i].get_visible():
                continue
            if kind_ == "point":
                xy = arts[i].get_xy()
                if xy is not None:
                    pts.append(xy)
            elif kind_ == "line":
                seg = arts[i].get_arrow()
                if seg is not None:
                    pts += list(seg)
            else:
                g = conic_geometry(arts[i].get_conic())
                if "affine" in g and g["kind"] == "ellipse":
                    aff = g["affine"]
                    pts += [(aff @ [c, s, 1.0])[:2] for c, s in ((1, 0), (-1, 0), (0, 1), (0, -1))]
        P = np.asarray(pts, float)
        # poles far from the focused link do not pull the view away (they get an edge arrow)
        P = P[np.hypot(*(P - mid).T) <= 4.0]
        lo, hi = P.min(axis=0), P.max(axis=0)
        m = 0.15 * float(np.max(hi - lo))
        lo, hi = lo - m, hi + m
        c, half = 0.5 * (lo + hi), 0.5 * float(np.max(hi - lo))
        return (c[0] - half, c[0] + half, c[1] - half, c[1] + half)

    def render(self, st):
        """Update links, overlays, focus, labels and view to the state ``st``; return the readout.

        Parameters
        ----------
        st : dict
            A state of :meth:`compute`.

        Returns
        -------
        dict
            The readout values.
        """
        model, w = st["model"], st["w"]
        n = model.N
        v = self.values
        if n > len(self.v_art):
            self._grow(n)
        focus = self._focus(n)
        split = self.tu_split(st) if v["T/U split"] else {}
        ends = self._ends(w)
        chain = np.empty((2 * n + 1, 2))
        chain[0] = w.origin[0]
        chain[1::2] = w.pose[:, :2]
        chain[2::2] = ends
        self.links_line.set_data(chain[:, 0], chain[:, 1])
        bx, by = w.origin[0]
        self.ground.set_data(bx + _GROUND[:, 0], by + _GROUND[:, 1])
        if focus is not None and focus[0] == "joint":    # the focused joint's force 0.6 m long
            big = [w.f[focus[1]]] + ([split["reaction"][focus[1]]] if split else [])
            fscale = 0.6 / max(1e-9, max(float(np.hypot(*b[:2])) for b in big))
        else:
            fscale = 0.5 / max(1.0, float(np.max(np.abs(w.f[:, :2]))))
        data = {"f": w.f, "v": w.v, "a": w.a, "TQ": split.get("active"), "Rμ": split.get("reaction"),
                "sψ": split.get("motion"), "Uγ": split.get("reactive"), "κ": w.kappa, "p": w.p,
                "A": w.A}
        anchors = {"joint": w.pose[:, :2], "link": w.com}
        setters = {"point": PointArtist.set_point, "line": LineArtist.set_line,
                   "conic": ConicArtist.set_conic}
        # first pass: the artists' data and visibility, the line arrows at their joint / centre
        for arts, flag, sym, kind, per, _color, _clear in self._layers:
            arr = data[sym]
            on = bool(v[flag]) and arr is not None
            setter = setters[kind]
            for i, art in enumerate(arts):
                show = on and i < n
                if show:
                    setter(art, arr[i])
                    if kind == "line":
                        art.set_anchor(anchors[per][i])
                        if art in self._scaled:
                            art.set_scale(fscale)
                    if arts is self.t_art:
                        show = bool(split["active_on"][i])
                    fade = focus is not None and not (focus == (per, i))
                    alpha = FADED if fade else None
                    if art.get_alpha() != alpha:
                        _fade(art, alpha)
                if art.get_visible() != show:
                    art.set_visible(show)
        # the view (all: the chain's reach; focus: the focused element) and the focus marks
        box = self._view(st, focus)
        if tuple(self.ax.get_xlim()) + tuple(self.ax.get_ylim()) != box:
            self.ax.set_xlim(box[0], box[1])
            self.ax.set_ylim(box[2], box[3])
        self.ax.apply_aspect()
        self.focus_line.set_visible(focus is not None)
        self.focus_joint.set_visible(focus is not None)
        if focus is not None:
            i = focus[1]
            self.focus_line.set_data([w.pose[i, 0], ends[i, 0]], [w.pose[i, 1], ends[i, 1]])
            self.focus_joint.set_data([w.pose[i, 0]], [w.pose[i, 1]])
            self.focus_line.set_linewidth(8.0 if focus[0] == "link" else 3.0)
            self.focus_joint.set_markersize(14 if focus[0] == "joint" else 8)
        self.scale_bar.update(1.0)                         # a 1 m scale bar under the axes
        pos = self.ax.get_position()                       # the time: in the margin, lower right
        self.time_text.set_position((pos.x1, pos.y0 - 14.0 / self.fig.bbox.height))
        self._label(st, focus, box)
        self._show_trajectory(st["traj"])
        self.time_text.set_text(f"t = {st['t']:.2f} s" if st["traj"] is not None else "")
        e = st["ke"] + st["pe"]
        out = {"links": n, "frame": int(v["frame"]), "t (s)": st["t"],
               "kinetic energy (J)": st["ke"], "potential energy (J)": st["pe"],
               "total energy (J)": e}
        if st["traj"] is not None:             # the joint forces are constant: work τ·(q - q₀)
            work = float(np.dot(st["tau"], w.q - st["traj"]["q"][0]))
            out["work of the joint forces (J)"] = work
            out["energy drift (J)"] = e - st["traj"]["e0"] - work
        out["qdd[1]"] = float(w.qdd[0])
        out[f"qdd[{n}]"] = float(w.qdd[-1])
        # a joint's acceleration: angular (revolute) or linear (prismatic)
        self.units = {**type(self).units, **{f"qdd[{k + 1}]": QDD_UNIT[model.joints[k].kind]
                                             for k in (0, n - 1)}}
        out["|base force| (N)"] = float(np.hypot(*w.f[0, :2]))
        return out

    def _label(self, st, focus, box) -> None:
        """Place the labels: the focused element's first (bold), then every other where it fits."""
        n = st["model"].N
        w = st["w"]
        v = {flag: self.controls[flag].value for flag in OVERLAYS}
        anchors = {"joint": w.pose[:, :2], "link": w.com}
        edge = {}

        def requests(focused_only: bool):
            """Label requests, round-robin over the layers (every kind is labelled early)."""
            for i in range(n):
                for arts, flag, sym, kind, per, color, clear in self._layers:
                    if not v[flag]:
                        continue
                    art = arts[i]
                    if not art.get_visible():
                        continue
                    focused = focus == (per, i)
                    if focused_only != focused:
                        continue                           # with a focus, the rest is faded: no label
                    xy = self._label_anchor(art, kind, box, anchors[per][i])
                    if kind == "point" and focused and xy is None:
                        # a focused pole off the view (or at infinity): its edge arrow is labelled
                        edge[art] = _sym(sym, i + 1)
                    if xy is None:
                        continue
                    c = clear
                    if kind == "point" and arts in (self.v_art, self.a_art):
                        gs = 4.0 if arts is self.v_art else 1.0
                        c = float(np.clip(gs * abs(art.get_point()[2]), 4.0, 16.0)) + 3.0
                    yield (_sym(sym, i + 1), xy, {"color": color, "clear": c, "bold": focused})

        obstacles = []
        if focus is not None:                  # the focused element's labels (few): all of them
            kind, i = focus
            mid = w.pose[i, :2] if kind == "joint" else 0.5 * (w.pose[i, :2] + self._ends(w)[i])
            reqs = [(f"{kind} {i + 1}", mid, {"bold": True, "clear": 9.0}), *requests(True)]
            limit = None
        else:                                  # everything: as many as MAX_LABELS (from the first few)
            reqs, limit = list(itertools.islice(requests(False), 3 * MAX_LABELS)), MAX_LABELS
        shown = self.labels.place(reqs, obstacles, limit=limit)
        for art in set(self._edge_text) | set(edge):
            if self._edge_text.get(art) != edge.get(art):
                art.set_text(edge.get(art, ""))
        self._edge_text = edge
        self._shown_labels = [t.get_text() for t, _ in zip(self.labels.texts, range(sum(shown)))]

    @staticmethod
    def _label_anchor(art, kind, box, near=None):
        """Where an element's label goes (data), or None when it has no place in the view.

        A point: its pole; a line: the middle of its arrow, or the foot of
        ``near`` on it (no arrow), or a third along its visible part when
        those are out of view; a conic: its curve at 45° from the centre.
        """
        x0, x1, y0, y1 = box

        def inside(xy):
            return xy is not None and x0 <= xy[0] <= x1 and y0 <= xy[1] <= y1

        if kind == "point":
            xy = art.get_xy()
            return xy if inside(xy) else None
        if kind == "line":
            line = art.get_line()
            seg = clip_line(line, box)
            if seg is None:
                return None
            arrow = art.get_arrow()
            if arrow is not None:
                mid = 0.5 * (arrow[0] + arrow[1])
            else:
                fx, fy, tz = line
                e = np.array([fx, fy]) / math.hypot(fx, fy)
                p0 = np.array([fy * tz, -fx * tz]) / (fx * fx + fy * fy)
                mid = p0 + e * ((np.asarray(near, float) - p0) @ e)
            return mid if inside(mid) else seg[0] + (seg[1] - seg[0]) / 3.0
        g = art.geometry()
        if "affine" not in g:
            return None
        xy = (g["affine"] @ [0.7071, 0.7071, 1.0])[:2]
        return xy if inside(xy) else None

    # -- simulation -----------------------------------------------------------------
    def _show_trajectory(self, traj) -> None:
        """The frame slider spans the shown state's trajectory (none: frame 0 only)."""
        self._traj = traj
        last = 0 if traj is None else len(traj["t"]) - 1
        fr = self.controls["frame"]
        if fr.max != last:
            fr.max = last
        fr.disabled = traj is None
