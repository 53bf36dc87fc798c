"""Articulated inertias along a chain, drawn as conics (thesis sections 7.1-7.3, 10.2.2, 10.2.3).

A chain of ``n`` identical bodies (mass 1, joints ``L = 1`` apart, radius of gyration
``ρ = L / λ``) hangs from the ground; every joint after the first bends it by ``φ``.
For every body the explorer draws

* its rigid inertia ``I_i`` (grey) and its articulated inertia ``A_i`` (7.7a, purple) as
  conics.  Inertias are imaginary conics: what is drawn is the real conic with the sign of
  the homogeneous part flipped (10.2.3), an ellipse about the (effective) centre of mass;
* for the focused body, the axes of percussion ``I_k a`` and ``A_k a`` of the acceleration
  pole ``a`` (5.64-5.68): the force that gives body ``k`` that acceleration alone, and with
  the bodies outboard attached; and the polar of ``a`` with respect to the drawn real conic,
  the point reflection of ``A_k a`` through the centre (the point symmetry of 10.2.3);
* how ``A_i`` changes as bodies are added outboard: the *outboard bodies* slider truncates
  the recursion (:func:`planargeo.algorithms.articulated_inertia.articulated_recursion`
  with ``steps=``; thesis 10.2.2, "three iterations are almost as precise as six"), and
  the chart on the right plots each component of the focused body's ``A_k`` (at its own
  joint) against the number of recursion steps, with its error against the full recursion.

*Play* (or the time slider) lets the chain swing under gravity ``g`` from the configuration
of the sliders, at rest, with viscous damping ``c`` at every joint; the conics follow the
motion, and the readout shows the energy ``T + V``, the energy the damping removed ``W``
and their sum, which stays at the initial energy within the integrator's tolerance.  The
swing is integrated once per configuration in chunks of one second (DOP853, dense output:
:class:`planargeo.widgets._motion.Motion`), so the state at a time depends on that time
and the other controls alone, whatever Play's steps were.

Handles (mouse under ``%matplotlib widget``, or :meth:`Explorer.drag` in scripts): the
acceleration pole ``a``, the tip of the chain (sets the bend ``φ``) and the end of the
first body (sets the base angle ``θ₁``).
"""
from __future__ import annotations

import math

import ipywidgets as W
import numpy as np
from matplotlib.lines import Line2D

from planargeo.draw.artists import ConicArtist, LineArtist, PointArtist, clip_line
from planargeo.draw.layout import fit_view
from planargeo.draw.pictures.articulated import MARGIN, articulated_picture, chain_view, fit_box
from planargeo.draw.style import COLORS, OKABE_ITO
from planargeo.geometry.conics import drawable_conic
from planargeo.scenes.articulated import COMPONENTS, articulated_state, bent_chain_model, joint_points
from planargeo.widgets._motion import Motion
from planargeo.widgets.base import Explorer, Handle, Step, cached, point_text

__all__ = ["ArticulatedExplorer", "NMAX", "bend_for_tip", "place_labels", "label_artist", "curve_candidates",
           "line_candidates", "point_candidates", "fit_mechanism"]

#: Most bodies the explorer shows.
NMAX = 8
#: Longest swing [s] (the range of the time slider).
T_MAX = 60.0
#: chart legend of each component of ``A_k`` at joint ``k`` (``A[0, 2]``, ``A[1, 2]``: ``A_xz``, ``A_yz``)
_LABELS = {"m_x": "xx", "m_y": "yy", "A_z": "zz", "m_xy": "xy", "c_x": "xz", "c_y": "yz"}
#: the readout's time control
TIME = "time (s)"
#: the readout row that shows the damping at rest (what c means: the power it takes when every joint turns
#: at 1 rad/s)
C_ROW = "damping power at 1 rad/s in every joint"
_ART = OKABE_ITO["purple"]
#: controls that define the chain or its swing: a change restarts the swing at t = 0
_CHAIN = ("bodies n", "λ = L/ρ", "bend φ (deg)", "base θ₁ (deg)", "g (m/s²)", "damping c")


def bend_for_tip(xy, n: int, base: float, L: float = 1.0) -> float:
    """The bend ``φ`` [rad] that brings the tip of the chain nearest to ``xy`` (base angle ``base``).

    Every joint after the first bends by ``φ``; searched on a 0.01° grid, then refined
    by golden-section search (no snapping to a slider grid).

    Parameters
    ----------
    xy : (float, float)
        Where the tip is dragged to.
    n : int
        Number of bodies (for ``n = 1`` the bend does not move the tip: returns 0).
    base : float
        Angle of the first body [rad].
    L : float
        Distance between joints.

    Returns
    -------
    float
        ``φ`` in ``[-π, π]``.

    Examples
    --------
    >>> round(math.degrees(bend_for_tip((1.0, 1.0), 2, 0.0)), 6)    # an elbow of 90 degrees
    90.0
    """
    if n < 2:
        return 0.0
    target = np.asarray(xy, dtype=float)
    k = np.arange(n)

    def dist(phi):
        th = base + np.multiply.outer(np.atleast_1d(phi), k)
        tip = L * np.stack([np.cos(th).sum(-1), np.sin(th).sum(-1)], axis=-1)
        return np.hypot(*(tip - target).T)

    grid = np.linspace(-math.pi, math.pi, 36001)
    j = int(np.argmin(dist(grid)))
    lo, hi = grid[max(j - 1, 0)], grid[min(j + 1, len(grid) - 1)]
    g = (math.sqrt(5) - 1) / 2
    for _ in range(40):                            # golden-section refinement inside the bracket
        a, b = hi - g * (hi - lo), lo + g * (hi - lo)
        if dist(a)[0] < dist(b)[0]:
            hi = b
        else:
            lo = a
    phi = 0.5 * (lo + hi)
    # near its best the distance is flat to rounding (it grows as φ²): a round angle (1e-4°) that is
    # as near counts as the answer, so that a drag along the straight chain gives φ = 0, not 2e-6°
    rounded = math.radians(round(math.degrees(phi), 4))
    if dist(rounded)[0] <= dist(phi)[0] + 1e-12 * (1.0 + float(np.hypot(*target))):
        phi = rounded
    return float(phi)


def fit_mechanism(ax, mechanism, extra=(), margin: float = 0.15, reach: float = 3.0, least: float = 1.0):
    """Fit the view to every point of the mechanism, and to the ``extra`` points near it.

    Every finite point of ``mechanism`` stays in view, however many of them coincide (a folded
    chain); an ``extra`` point (a pole, a centre) is kept when it lies within ``reach`` times the
    mechanism's size of its middle (a farther one gets its edge arrow).  The view spans at least
    ``least`` (the mechanism's own length scale).  Only the box's corners reach
    :func:`planargeo.draw.layout.fit_view`, so no point of the mechanism is taken for an outlier.

    Parameters
    ----------
    ax : matplotlib.axes.Axes
    mechanism : array_like (m, 2)
        Points that must be in view.
    extra : array_like (k, 2)
        Points kept in view when near the mechanism.
    margin : float
        Margin, a fraction of the box's larger side.
    reach : float
        How far (in mechanism sizes) an extra point may lie and still be kept in view.
    least : float
        Smallest span of the box (m).

    Returns
    -------
    tuple
        The limits ``(x0, x1, y0, y1)`` set.

    Examples
    --------
    >>> import matplotlib.pyplot as plt
    >>> fig, ax = plt.subplots()
    >>> x0, x1, y0, y1 = fit_mechanism(ax, [[0, 0], [1, 0], [0, 0]], margin=0.0)
    >>> bool(x0 <= 0.0 and x1 >= 1.0 and x1 - x0 >= 1.0)
    True
    """
    M = np.asarray(mechanism, dtype=float).reshape(-1, 2)
    M = M[np.all(np.isfinite(M), axis=1)]
    lo, hi = M.min(axis=0), M.max(axis=0)
    size = max(float(np.max(hi - lo)), least)
    E = np.asarray(extra, dtype=float).reshape(-1, 2)
    E = E[np.all(np.isfinite(E), axis=1)]
    if len(E):
        mid = 0.5 * (lo + hi)
        E = E[np.hypot(*(E - mid).T) <= reach * size]
        if len(E):
            lo, hi = np.minimum(lo, E.min(axis=0)), np.maximum(hi, E.max(axis=0))
    c, half = 0.5 * (lo + hi), 0.5 * max(float(np.max(hi - lo)), least)    # a square: no side below the size
    fit_view(ax, np.array([c - half, c + half]), margin=margin)
    return tuple(float(x) for x in (*ax.get_xlim(), *ax.get_ylim()))


def place_labels(ax, items) -> list:
    """Place labels next to their anchors without overlaps (greedy, in order of priority).

    Each item is ``(annotation, candidates)``: an annotation made by :func:`label_artist` and a
    list of ``((x, y) data anchor, (dx, dy) offset in points)`` tried in turn; the first
    position whose text lies inside the axes and clear of the labels placed before wins (else
    the one that overlaps least).  Hidden annotations are skipped; an annotation whose anchors
    all lie outside the view is hidden.

    Parameters
    ----------
    ax : matplotlib.axes.Axes
        The axes (its limits already set).
    items : list of (Annotation, list)
        Labels in order of priority.

    Returns
    -------
    list of matplotlib.transforms.Bbox
        The placed labels' boxes (display pixels).
    """
    renderer = ax.figure.canvas.get_renderer()
    frame = ax.get_window_extent(renderer)
    (x0, x1), (y0, y1) = sorted(ax.get_xlim()), sorted(ax.get_ylim())
    placed = []
    for ann, cands in items:
        cands = [(xy, off) for xy, off in cands if np.all(np.isfinite(xy))
                 and x0 <= xy[0] <= x1 and y0 <= xy[1] <= y1]       # a label only for what is in view
        if not cands:
            ann.set_visible(False)
        if not ann.get_visible() or not ann.get_text():
            continue
        best, best_cost = None, math.inf
        for xy, off in cands:
            if not np.all(np.isfinite(xy)):
                continue
            ann.xy = (float(xy[0]), float(xy[1]))
            ann.set_position((float(off[0]), float(off[1])))
            ann.set_horizontalalignment("left" if off[0] > 1 else "right" if off[0] < -1 else "center")
            ann.set_verticalalignment("bottom" if off[1] > 1 else "top" if off[1] < -1 else "center")
            bb = ann.get_window_extent(renderer)
            out = (max(0.0, frame.x0 + 2 - bb.x0) + max(0.0, bb.x1 - frame.x1 + 2)
                   + max(0.0, frame.y0 + 2 - bb.y0) + max(0.0, bb.y1 - frame.y1 + 2))
            cost = 1e3 * out + sum(max(0.0, min(bb.x1, o.x1) - max(bb.x0, o.x0) + 2)
                                   * max(0.0, min(bb.y1, o.y1) - max(bb.y0, o.y0) + 2) for o in placed)
            if cost < best_cost:
                best, best_cost = (xy, off), cost
            if cost == 0:
                break
        if best is None:
            ann.set_visible(False)
            continue
        xy, off = best
        ann.xy = (float(xy[0]), float(xy[1]))
        ann.set_position((float(off[0]), float(off[1])))
        ann.set_horizontalalignment("left" if off[0] > 1 else "right" if off[0] < -1 else "center")
        ann.set_verticalalignment("bottom" if off[1] > 1 else "top" if off[1] < -1 else "center")
        placed.append(ann.get_window_extent(renderer))
    return placed


def label_artist(ax, text: str = "", color: str = "black", fontsize: float = 11.0):
    """An annotation (text offset in points from a data point) for :func:`place_labels`.

    Parameters
    ----------
    ax : matplotlib.axes.Axes
    text : str
    color : str
    fontsize : float

    Returns
    -------
    matplotlib.text.Annotation
    """
    return ax.annotate(text, xy=(0.0, 0.0), xytext=(0.0, 0.0), textcoords="offset points", color=color,
                       fontsize=fontsize, zorder=20, annotation_clip=False)


def curve_candidates(xy, offset: float = 4.0) -> list:
    """Label positions around a closed curve: its right, top, left and bottom points, offset outward.

    Parameters
    ----------
    xy : (m, 2) points of the curve (NaN allowed)
    offset : float
        Distance from the curve in points.

    Returns
    -------
    list of ((x, y), (dx, dy))
    """
    P = np.asarray(xy, dtype=float)
    P = P[np.all(np.isfinite(P), axis=1)]
    if not len(P):
        return []
    out = []
    for k, d in ((int(np.argmax(P[:, 0] + P[:, 1])), (offset, offset)), (int(np.argmax(P[:, 1])), (0.0, offset)),
                 (int(np.argmax(P[:, 0])), (offset, 0.0)), (int(np.argmin(P[:, 0] - P[:, 1])), (-offset, offset)),
                 (int(np.argmin(P[:, 1])), (0.0, -offset)), (int(np.argmin(P[:, 0])), (-offset, 0.0)),
                 (int(np.argmin(P[:, 0] + P[:, 1])), (-offset, -offset)),
                 (int(np.argmax(P[:, 0] - P[:, 1])), (offset, -offset))):
        out.append((P[k], d))
    return out


def line_candidates(line, box, fracs=(0.1, 0.9, 0.3, 0.7, 0.5), offset: float = 5.0) -> list:
    """Label positions along a line inside ``box`` (x0, x1, y0, y1), on either side of it.

    Parameters
    ----------
    line : (3,) homogeneous line
    box : (x0, x1, y0, y1)
    fracs : fractions along the visible segment, in order of preference
    offset : float
        Distance from the line in points.

    Returns
    -------
    list of ((x, y), (dx, dy))
    """
    seg = clip_line(line, box)
    if seg is None:
        return []
    seg = seg[np.argsort(seg[:, 0])]
    n = np.array([-line[1], line[0]], dtype=float)          # the line's normal (direction (fx, fy))
    n = n / max(np.hypot(*n), 1e-300)
    if n[1] < 0:
        n = -n
    out = []
    for f in fracs:
        p = seg[0] + f * (seg[1] - seg[0])
        out += [(p, tuple(offset * n)), (p, tuple(-offset * n))]
    return out


def point_candidates(xy, offset: float = 6.0) -> list:
    """Label positions around a point (up-right first; then farther out, for crowded places).

    Parameters
    ----------
    xy : (x, y)
    offset : float
        Distance in points.

    Returns
    -------
    list of ((x, y), (dx, dy))
    """
    p = np.asarray(xy, dtype=float)
    return [(p, (r * offset * a, r * offset * b)) for r in (1.0, 2.5, 4.0)
            for a, b in ((1, 1), (1, -1), (-1, 1), (-1, -1), (0, 1.4), (0, -1.4), (1.4, 0), (-1.4, 0))]


class ArticulatedExplorer(Explorer):
    """Rigid and articulated inertias of a chain as conics, their axes of percussion and convergence.

    Parameters
    ----------
    **kw
        As for :class:`planargeo.widgets.base.Explorer` (``display``, ``figsize``, initial
        control values by name).

    Examples
    --------
    >>> ex = ArticulatedExplorer(display="agg")
    >>> ex.set(**{"bodies n": 3, "λ = L/ρ": 2.0, "bend φ (deg)": 0.0, "outboard bodies": 1})
    ArticulatedExplorer(...)
    >>> round(ex.readout_values["effective centre d/L (7.27)"], 6)     # lambda = 2: 2/3 after one step
    0.666667
    """

    title = "Articulated inertias along a chain: conics, percussion and convergence"
    slug = "articulated"
    figsize = (9.6, 5.0)
    display_controls = ("rigid inertias", "percussion axes")
    units = {
        "bodies": "—", "outboard included": "—", "Aₖ: mass along x": "kg", "Aₖ: mass along y": "kg",
        "Aₖ: inertia about joint k": "kg·m²", "effective centre d/L (7.27)": "—",
        "truncation error of Aₖ": "—", "distance from a to the centre": "m",
        "axis Aₖa: distance from the centre": "m",
        "t": "s", "energy T + V": "J", "dissipated W": "J", "T + V + W": "J", "initial energy E₀": "J",
        C_ROW: "W",
    }

    def __init__(self, **kw):
        self._models: dict = {}
        self._motions: dict = {}     # the swing of each configuration (Motion of (q, q̇, W))
        super().__init__(**kw)

    def __repr__(self) -> str:
        return "ArticulatedExplorer(...)"

    # ------------------------------------------------------------------ controls
    def make_controls(self):
        """The explorer's controls (sliders, checkboxes).

        Returns
        -------
        dict
            ``{name: widget}``.
        """
        return {
            "bodies n": Step(1, NMAX, 1, 4, "bodies n", integer=True).make("bodies n"),
            "λ = L/ρ": Step(0.5, 8.0, 0.05, 3.0, "λ = L/ρ").make("lam"),
            "bend φ (deg)": Step(-180.0, 180.0, 0.5, 25.0, "bend φ (deg)").make("phi"),
            "base θ₁ (deg)": Step(-180.0, 180.0, 0.5, 0.0, "base θ₁ (deg)").make("base"),
            "outboard bodies": Step(0, NMAX - 1, 1, NMAX - 1, "outboard bodies", integer=True).make("outboard"),
            "pole x": Step(-4.0, 6.0, 0.01, 0.0, "pole a: x (m)").make("pole x"),
            "pole y": Step(-5.0, 5.0, 0.01, -0.8, "pole a: y (m)").make("pole y"),
            "g (m/s²)": Step(0.0, 9.81, 0.01, 9.81, "g (m/s²) for Play").make("g"),
            "damping c": Step(0.0, 3.0, 0.01, 0.3, "damping c (N·m·s/rad)").make("c"),
            "time (s)": Step(0.0, T_MAX, 0.01, 0.0, "time (s)").make("time"),
            "rigid inertias": W.Checkbox(value=True, description="rigid inertias I_i"),
            "percussion axes": W.Checkbox(value=True, description="percussion axes"),
        }

    def adjust(self, values, changed):
        """Controls that follow: the outboard bodies stay on the chain, a new chain swings from ``t = 0``.

        ``outboard bodies`` never exceeds the ``n − 1`` bodies outboard of body 1 (its slider
        spans 0 to ``n − 1`` once the state is shown); at its largest ("all of them") it stays at the largest
        when ``n`` changes.  A change of the chain or its swing restarts the time at 0 unless the
        time is set with it.  A focus on a body that is gone falls back to "all" (the base).

        Parameters
        ----------
        values : dict
            The control values about to be shown.
        changed : set of str
            The controls that changed.

        Returns
        -------
        dict
            Controls that follow: ``outboard bodies`` and ``time (s)``.
        """
        out = {}
        n = int(values["bodies n"])
        k = int(values["outboard bodies"])
        before = self.shown_values
        if "bodies n" in changed and "outboard bodies" not in changed and before and \
                k >= int(before["bodies n"]) - 1:
            k = n - 1                                     # it was "all": it stays "all"
        k = min(k, n - 1)
        if k != values["outboard bodies"]:
            out["outboard bodies"] = k
        w = self.controls["outboard bodies"]
        if w.max < k:                          # widened here, narrowed to n − 1 once the state is shown
            with self._quietly():
                w.max = k
        if changed & set(_CHAIN) and TIME not in changed and values[TIME] != 0.0:
            out[TIME] = 0.0
        return out

    def disabled(self, values):
        """Controls that would change nothing in the state ``values`` describe, with the reason.

        Parameters
        ----------
        values : dict

        Returns
        -------
        dict
            ``{control: reason}``.
        """
        out = {}
        n = int(values["bodies n"])
        if n == 1:
            out["outboard bodies"] = "one body: there is no body outboard of it (add bodies)"
            out["bend φ (deg)"] = "one body: the bend is the angle between bodies (add bodies)"
        return out

    def explain(self):
        """Every symbol and readout name on screen: one-line meaning and thesis equation.

        Returns
        -------
        dict
        """
        focus = str(self.values.get("focus", "all"))
        kk = _sub(int(focus.split()[1]) if focus.startswith("body ") else 1)
        return {
            "n": "number of bodies in the chain (1 kg each, joints L = 1 m apart)",
            "i": "index of any body of the chain",
            "k": "the focused body (body 1 when the focus is 'all'): its Aₖ, Iₖ, axes and chart are shown",
            "L": "distance between joints, 1 m",
            "ρ": "radius of gyration of each body, ρ = L/λ (m)",
            "λ": "size ratio λ = L/ρ (eq. 7.21)",
            "φ": "bend: the angle of every body relative to the one before it",
            "θ₁": "angle of the first body from the x axis",
            "g": "gravity along −y for the swing (m/s²)",
            "c": "viscous damping at every joint: joint torque −c q̇ (N·m·s/rad)",
            "t": "time of the swing since it started from rest (s)",
            "Iᵢ": "rigid inertia of body i, drawn as a conic about its centre of mass (section 10.2.3)",
            "Aᵢ": "articulated inertia of body i with the bodies outboard of it (eq. 7.7a), drawn as a conic",
            "Aₖ": f"articulated inertia of the focused body k (eq. 7.7a); in the figure: A{kk}",
            "Iₖ": f"rigid inertia of the focused body k; in the figure: I{kk}",
            "a": "the acceleration pole: the point about which body k is made to accelerate (eq. 4.6)",
            "Aₖa": ("axis of percussion: the force that gives body k the acceleration a with the outboard bodies "
                    f"attached (eq. 5.64-5.68); in the figure: A{kk} a"),
            "Iₖa": f"axis of percussion of body k alone (eq. 5.64-5.68); in the figure: I{kk} a",
            "polar of a (real conic)": ("polar of a with respect to the drawn real conic of Aₖ: Aₖa reflected "
                                        "through the centre (section 10.2.3)"),
            "entries of Aₖ at joint k / full value": "the chart: each entry of Aₖ (at joint k) after so many "
                                                     "recursion steps, over its value with every outboard body; "
                                                     f"in the figure: entries of A{kk} at joint "
                                                     f"{focus.split()[1] if focus.startswith('body ') else 1} "
                                                     "/ full value",
            "xx": "entry xx of Aₖ at joint k: the mass felt pushing along x (eq. 7.26)",
            "yy": "entry yy of Aₖ at joint k: the mass felt pushing along y (eq. 7.26)",
            "zz": "entry zz of Aₖ at joint k: the rotational inertia about joint k (eq. 7.26)",
            "xy, xz, yz": "entries xy, xz, yz of Aₖ at joint k: the couplings between pushing and turning",
            "recursion steps (outboard bodies)": "the chart's axis: how many outboard bodies the recursion for Aₖ includes (section 10.2.2)",
            "error": "‖Aₖ after so many steps − Aₖ‖ / ‖Aₖ‖ (the chart; section 10.2.2)",
            "E₀": "energy T + V of the chain at rest at t = 0",
            "T": "kinetic energy of the chain (eq. 1.9)",
            "V": "potential energy of the chain in gravity g",
            "W": "energy the joint damping has removed since t = 0: ∫ c q̇ᵀq̇ dt",
            "bodies": "number of bodies n",
            "outboard included": "bodies outboard of k the recursion for Aₖ includes, of all there are (section 10.2.2)",
            "Aₖ: mass along x": "mass felt pushing body k along x at its joint: entry xx of Aₖ (eq. 7.26)",
            "Aₖ: mass along y": "mass felt pushing body k along y at its joint: entry yy of Aₖ (eq. 7.26)",
            "Aₖ: inertia about joint k": "rotational inertia of Aₖ about joint k: entry zz (eq. 7.26)",
            "effective centre of Aₖ": "the point where Aₖ has no coupling of force and turning: its conic's centre (eq. 7.26)",
            "centre of mass of body k": "the centre of Iₖ",
            "effective centre d/L (7.27)": "distance of body 1's effective centre from its joint, over L (straight chain; eq. 7.27)",
            "truncation error of Aₖ": "‖Aₖ with the shown outboard bodies − Aₖ‖ / ‖Aₖ‖ (section 10.2.2)",
            "pole a": "the acceleration pole a (draggable)",
            "distance from a to the centre": "distance from the pole a to the effective centre of Aₖ",
            "axis Aₖa: distance from the centre": "distance of the axis of percussion Aₖa from the effective centre (eq. 5.64-5.68)",
            "energy T + V": "energy of the chain at time t",
            "dissipated W": "energy the damping removed up to t",
            "T + V + W": "stays E₀ but for the integration error",
            "initial energy E₀": "energy at t = 0 (at rest: V alone)",
            C_ROW: "n c × (1 rad/s)²: the power the damping takes when every joint turns at 1 rad/s",
        }

    # ------------------------------------------------------------------ figure
    def setup_axes(self, ax):
        """Main axes for the chain (left) and the convergence chart (right).

        Parameters
        ----------
        ax : matplotlib.axes.Axes
        """
        super().setup_axes(ax)
        ax.set_position([0.085, 0.1, 0.53, 0.85])
        ax.set_xlabel("x (m)")
        ax.set_ylabel("y (m)")
        self.chart = ax.figure.add_axes([0.71, 0.12, 0.27, 0.78])
        self.chart.grid(True, lw=0.3, alpha=0.5)
        self.chart.set_xlabel("recursion steps (outboard bodies)")
        self.chart.set_title("entries of $A_k$ at joint $k$ / full value", fontsize=11)

    def make_artists(self, ax):
        """Create every artist once (links, pins, conics, axes, pole; chart lines).

        Parameters
        ----------
        ax : matplotlib.axes.Axes
        """
        self.links = Line2D([], [], color=COLORS["body"], lw=7, alpha=0.55, solid_capstyle="round", zorder=1)
        self.pins = Line2D([], [], marker="o", ms=6, mfc="white", mec="black", ls="none", zorder=4)
        self.ground = Line2D([0.0], [0.0], marker="s", ms=9, color=COLORS["ground"], ls="none", zorder=3)
        for a in (self.links, self.pins, self.ground):
            ax.add_line(a)
        e = np.diag([1.0, 1.0, 1.0])
        self.rigid = [ax.add_artist(ConicArtist(e, role="inertia", color="#9a9a9a", linewidth=1.0))
                      for _ in range(NMAX)]
        self.art = [ax.add_artist(ConicArtist(e, role="inertia", color=_ART, linewidth=1.3))
                    for _ in range(NMAX)]
        self.pole_art = ax.add_artist(PointArtist([0.0, 0.0, 1.0], role="accel", glyph=False, markersize=8))
        self.axis_A = ax.add_artist(LineArtist([0.0, 1.0, 0.0], role="wrench", scale=None))
        self.axis_I = ax.add_artist(LineArtist([0.0, 1.0, 0.0], role="momentum", scale=None,
                                               linestyle=(0, (6, 3))))
        self.polar = ax.add_artist(LineArtist([0.0, 1.0, 0.0], role="construct", scale=None))
        # labels, placed clear of each other at every update (place_labels)
        self.lab = {name: label_artist(ax, "", color) for name, color in (
            ("a", COLORS["accel"]), ("A", _ART), ("I", "#6a6a6a"), ("Aa", COLORS["wrench"]),
            ("Ia", COLORS["momentum"]), ("polar", COLORS["construct"]))}
        self.curves = [self.chart.plot([], [], marker="o", ms=3, lw=1.5, label=_LABELS[c])[0] for c in COMPONENTS]
        self.err_curve = self.chart.plot([], [], color="black", lw=1.2, ls=":", marker="s", ms=3,
                                         label="error")[0]
        self.now = self.chart.axvline(0.0, color=_ART, lw=1.0, alpha=0.7)
        self.chart.legend(loc="lower right", fontsize=10, ncol=2, handlelength=1.2, columnspacing=0.8,
                          borderaxespad=0.3, frameon=True, framealpha=0.85)

    # ------------------------------------------------------------------ handles and Play
    def handles(self):
        """The draggable handles: the pole ``a``, the chain's tip (bend ``φ``), the first body's end (``θ₁``).

        Returns
        -------
        list of Handle
        """
        def pole_where():
            v = self.shown_values or self.values
            return (float(v["pole x"]), float(v["pole y"]))

        def pole_drag(x, y):
            return {"pole x": float(x), "pole y": float(y)}

        def tip_where():
            pts = self._joints()
            return None if pts is None or len(pts) < 3 else tuple(pts[-1])

        def tip_drag(x, y):
            v = self.values
            phi = bend_for_tip((x, y), int(v["bodies n"]), math.radians(v["base θ₁ (deg)"]))
            return {"bend φ (deg)": float(np.clip(math.degrees(phi), -180.0, 180.0))}

        def base_where():
            pts = self._joints()
            return None if pts is None else tuple(pts[1])

        def base_drag(x, y):
            if x == 0 and y == 0:
                return {}
            return {"base θ₁ (deg)": float(math.degrees(math.atan2(y, x)))}

        return [Handle("pole a", pole_where, pole_drag), Handle("tip", tip_where, tip_drag),
                Handle("first body", base_where, base_drag)]

    def focus_options(self):
        """The bodies to focus on: the focused body's conics, axes and chart are shown, the rest fade.

        Returns
        -------
        list of str
            ``"body 1"`` ... ``"body n"`` (the base adds ``"all"``: body 1 labelled, nothing faded);
            before the first state is shown, every body of the longest chain (so that a focus given
            to the constructor with ``n`` is taken).
        """
        w = getattr(self, "controls", {}).get("bodies n")
        n = NMAX if w is None or getattr(self, "state", None) is None else int(w.value)
        return [f"body {i}" for i in range(1, n + 1)]

    def set(self, **values):
        """Set several controls at once (the base's :meth:`~planargeo.widgets.base.Explorer.set`).

        With ``bodies n`` among them, ``outboard bodies`` takes any value its widest range allows
        (checked against the new ``n`` by :meth:`adjust`); its slider spans the shown chain after.

        Parameters
        ----------
        **values
            ``name=value`` for each control to set.

        Returns
        -------
        Explorer
            ``self``.
        """
        if "bodies n" not in values:
            return super().set(**values)
        w = self.controls["outboard bodies"]
        with self._quietly():
            w.max = NMAX - 1
        try:
            return super().set(**values)
        finally:
            n = int((self.shown_values or self.values)["bodies n"])
            if w.max != n - 1 and w.value <= n - 1:
                with self._quietly():
                    w.max = n - 1

    def mechanism_points(self):
        """Points the view must hold: every joint of the chain and the tip (the base's rule tests).

        Returns
        -------
        numpy.ndarray
            ``(n + 1, 2)``.
        """
        st = self.state
        return np.zeros((0, 2)) if st is None else np.asarray(st["joints"], dtype=float).reshape(-1, 2)

    def _joints(self):
        st = self.state
        return None if st is None else st["joints"]

    def play_step(self, values, dt):
        """The time ``dt`` seconds on (Play); the swing itself is read in :meth:`compute`.

        The state at a time depends on that time alone (module docstring), so any ``dt`` is exact.

        Parameters
        ----------
        values : dict
            The shown control values.
        dt : float
            Seconds of the step (> 0).

        Returns
        -------
        dict or None
            ``{"time (s)": t + dt}`` (at most the end of the range); None at its end (Play stops).
        """
        t = float(values[TIME])
        if t >= T_MAX:
            return None
        return {TIME: min(t + float(dt), T_MAX)}

    # ------------------------------------------------------------------ physics
    def _key(self, v):
        return (int(v["bodies n"]), float(v["λ = L/ρ"]), float(v["bend φ (deg)"]), float(v["base θ₁ (deg)"]),
                float(v["g (m/s²)"]), float(v["damping c"]))

    def _model(self, n, lam, g=0.0):
        return cached(self._models, (n, lam, g), lambda: bent_chain_model(n, 1.0 / lam, 1.0, 1.0, g))

    def _q0(self, v):
        n = int(v["bodies n"])
        return np.array([math.radians(v["base θ₁ (deg)"])] + [math.radians(v["bend φ (deg)"])] * (n - 1))

    def motion(self, v) -> Motion:
        """The swing of the configuration ``v`` from rest: ``y = (q, q̇, W)`` at any time (kept per configuration).

        Parameters
        ----------
        v : dict
            Control values.

        Returns
        -------
        Motion
        """
        from planargeo.scenes.chain import chain_accelerations as forward_dynamics

        key = self._key(v)
        n, c = key[0], key[5]
        model = self._model(n, key[1], key[4])

        def rhs(_t, y):
            qd = y[n:2 * n]
            qdd = forward_dynamics(model, y[:n], qd, -c * qd)
            return np.concatenate([qd, qdd, [c * float(qd @ qd)]])

        y0 = np.concatenate([self._q0(v), np.zeros(n), [0.0]])
        return cached(self._motions, key, lambda: Motion(rhs, y0, chunk=1.0))

    def compute(self, v, changed):
        """The shown configuration's inertias, axes, convergence chart and (when swinging) energies.

        Parameters
        ----------
        v : dict
            Control values.
        changed : set of str
            Controls that changed.

        Returns
        -------
        dict
            The state :meth:`render` draws.

        Raises
        ------
        PlanargeoError
            A configuration that cannot be computed (kept out of view: the last good state stays).
        """
        from planargeo.simulate.integrate import energy

        n, lam = int(v["bodies n"]), float(v["λ = L/ρ"])
        t = float(v[TIME])
        motion = self.motion(v)
        y = motion.at(t)
        q, qd, W = y[:n], y[n:2 * n], float(y[2 * n])
        model_g = self._model(n, lam, float(v["g (m/s²)"]))
        T, V = energy(model_g, q, qd)
        E0 = float(sum(energy(model_g, self._q0(v), np.zeros(n))))
        out_k = int(v["outboard bodies"])
        outboard = None if out_k >= n - 1 else out_k
        st = articulated_state(self._model(n, lam), q, outboard=outboard,
                               pole=(float(v["pole x"]), float(v["pole y"])))
        st.update(n=n, lam=lam, q=q, outboard=out_k, t=t, energy=(float(T + V), W, E0), c=float(v["damping c"]))
        return st

    # ------------------------------------------------------------------ drawing
    def render(self, st):
        """Update the artists and the chart in place; return the readout.

        Parameters
        ----------
        st : dict
            A state from :meth:`compute`.

        Returns
        -------
        dict
            Readout values (units in :attr:`units`).
        """
        v = self.values
        n = st["n"]
        focus = v.get("focus", "all")
        k = 0 if focus == "all" else min(int(focus.split()[1]), n) - 1     # labels and chart: body 1 for "all"
        pts = st["joints"]
        self.links.set_data(pts[:, 0], pts[:, 1])
        self.pins.set_data(pts[:-1, 0], pts[:-1, 1])
        show_rigid = bool(v["rigid inertias"])
        for i in range(NMAX):
            on = i < n
            self.art[i].set_visible(on)
            self.rigid[i].set_visible(on and show_rigid)
            if not on:
                continue
            self.art[i].set_conic(st["A"][i])
            self.rigid[i].set_conic(st["I"][i])
            bold = focus == "all" or i == k
            _fade(self.art[i], 1.0 if bold else 0.3)
            _fade(self.rigid[i], 0.9 if bold else 0.25)
        a = st["pole"]
        self.pole_art.set_point(a)
        axes_on = bool(v["percussion axes"])
        for art in (self.axis_A, self.axis_I, self.polar):
            art.set_visible(axes_on)
        self.axis_A.set_line(st["axis"][k])
        self.axis_I.set_line(st["axis_rigid"][k])
        self.axis_I.set_visible(axes_on and show_rigid)
        self.polar.set_line(drawable_conic(st["A"][k]) @ a)            # 10.2.3: reflection of A_k a through the centre
        # chart: the focused body's components against the recursion steps, each over its full value
        comps, errs = st["components"][k], st["error"][k]
        steps = np.arange(len(comps))
        full = comps[-1]
        scale = np.linalg.norm(st["A_full"][k])
        for j, line in enumerate(self.curves):
            meaningful = abs(full[j]) > 1e-9 * scale
            line.set_visible(meaningful)
            line.set_data(steps, comps[:, j] / full[j] if meaningful else np.zeros(len(steps)))
        self.err_curve.set_data(steps, errs)
        shown_k = min(st["outboard"], len(comps) - 1)
        self.now.set_xdata([shown_k, shown_k])
        self.chart.set_xlim(-0.3, max(len(comps) - 1, 1) + 0.3)
        vis = [c.get_ydata() for c in self.curves if c.get_visible()] + [errs]
        lo = min(0.0, float(np.min(np.concatenate(vis))))
        hi = max(1.05, float(np.max(np.concatenate(vis))))
        self.chart.set_ylim(lo - 0.05, hi + 0.1)
        self.chart.set_xticks(range(len(comps)))
        # the view: chain, centres, pole
        view = [pts, st["centre"], st["centre_rigid"], [[v["pole x"], v["pole y"]]]]
        view += [c.get_xy() for c in self.art[:n]]               # the drawn conics stay in view
        if show_rigid:
            view += [c.get_xy() for c in self.rigid[:n]]
        fit_mechanism(self.ax, np.vstack(view), margin=0.1)
        # labels: thesis symbols next to the focused body's elements, clear of each other
        x0, x1 = self.ax.get_xlim()
        y0, y1 = self.ax.get_ylim()
        box = (x0, x1, y0, y1)
        lab = self.lab
        lab["a"].set_text("$a$")
        lab["A"].set_text(f"$A_{{{k + 1}}}$")
        lab["I"].set_text(f"$I_{{{k + 1}}}$")
        lab["Aa"].set_text(f"$A_{{{k + 1}}}\\,a$")
        lab["Ia"].set_text(f"$I_{{{k + 1}}}\\,a$")
        lab["polar"].set_text("polar of $a$ (real conic)")
        lab["I"].set_visible(show_rigid)
        lab["Ia"].set_visible(axes_on and show_rigid)
        for name in ("Aa", "polar"):
            lab[name].set_visible(axes_on)
        place_labels(self.ax, [
            (lab["a"], point_candidates((v["pole x"], v["pole y"]))),
            (lab["A"], curve_candidates(self.art[k].get_xy())),
            (lab["I"], curve_candidates(self.rigid[k].get_xy())),
            (lab["Aa"], line_candidates(st["axis"][k], box)),
            (lab["Ia"], line_candidates(st["axis_rigid"][k], box, fracs=(0.9, 0.1, 0.7, 0.3, 0.5))),
            (lab["polar"], line_candidates(self.polar.get_line(), box, fracs=(0.5, 0.3, 0.7, 0.1, 0.9))),
        ])
        return self.readout_of(st)

    def _focus_k(self, n: int) -> int:
        """The focused body (0-based; body 1 for "all")."""
        focus = self.values.get("focus", "all")
        return 0 if focus == "all" else min(int(focus.split()[1]), n) - 1

    def view_box(self, st) -> tuple[float, float, float, float]:
        """The view: the chain, the centres, the pole and the drawn conics on the left, the chart on the right.

        Parameters
        ----------
        st : dict
            A state from :meth:`compute`.

        Returns
        -------
        tuple
            ``(x0, x1, y0, y1)``.
        """
        from planargeo.draw.geometry import conic_geometry

        v = self.values
        n = st["n"]
        pts = [st["joints"], st["centre"], st["centre_rigid"], [[v["pole x"], v["pole y"]]]]
        for C in list(st["A"][:n]) + (list(st["I"][:n]) if v["rigid inertias"] else []):
            g = conic_geometry(C)
            if "affine" in g:                  # the drawn ellipse's box: centre ± the affine's row norms
                A = g["affine"]
                half = np.hypot(A[:2, 0], A[:2, 1])
                pts.append([A[:2, 2] - half, A[:2, 2] + half])
        box = fit_box(np.vstack(pts), margin=0.1)
        return chain_view(box, self.figure_px, MARGIN)

    def scene_picture(self, st, view=None):
        """The state's picture, built natively (:func:`planargeo.draw.pictures.articulated.articulated_picture`).

        Parameters
        ----------
        st : dict
            A state from :meth:`compute`.
        view : (x0, x1, y0, y1), optional
            The view the user zoomed or panned to (default: :meth:`view_box`).

        Returns
        -------
        Picture
        """
        v = self.values
        return articulated_picture(st, k=self._focus_k(st["n"]), focus_all=v.get("focus", "all") == "all",
                                   rigid=bool(v["rigid inertias"]), axes=bool(v["percussion axes"]),
                                   view=view or self.view_box(st), size=self.figure_px)

    def readout_of(self, st):
        """The readout of the state ``st`` (the focused body's ``Aₖ``, its centre, the pole, the energies).

        Parameters
        ----------
        st : dict
            A state from :meth:`compute`.

        Returns
        -------
        dict
            Readout values (units in :attr:`units`).
        """
        v = self.values
        n = st["n"]
        k = self._focus_k(n)
        pts = st["joints"]
        w = self.controls["outboard bodies"]          # the slider spans the bodies outboard of body 1
        if w.max != n - 1:
            with self._quietly():
                w.max = n - 1
        # readout
        Ak = st["A"][k]
        from planargeo.scenes.articulated import inertia_at

        zero = float(self.zero_tol) * float(self.scale)
        Aj = inertia_at(Ak, pts[k])
        c = st["centre"][k]
        P = np.array([v["pole x"], v["pole y"]])
        dist = float(np.hypot(*(P - c)))
        line = st["axis"][k]
        axis_from_c = abs(line[2] + c[1] * line[0] - c[0] * line[1]) / max(math.hypot(line[0], line[1]), 1e-300)
        out = {
            "bodies": n,
            "outboard included": f"{min(st['outboard'], n - 1 - k)} of {n - 1 - k}",
            "Aₖ: mass along x": float(Aj[0, 0]), "Aₖ: mass along y": float(Aj[1, 1]),
            "Aₖ: inertia about joint k": float(Aj[2, 2]),
            "effective centre of Aₖ": point_text([c[1], -c[0], 1.0], zero=zero),
            "centre of mass of body k": point_text([st["centre_rigid"][k][1], -st["centre_rigid"][k][0], 1.0],
                                                   zero=zero),
            "truncation error of Aₖ": float(st["truncation_error"][k]),
            "pole a": point_text([P[1], -P[0], 1.0], zero=zero), "distance from a to the centre": dist,
            "axis Aₖa: distance from the centre": float(axis_from_c),
        }
        if k == 0 and abs(math.remainder(float(v["bend φ (deg)"]), 360.0)) < 1e-12 and st["t"] == 0:
            from planargeo.scenes.horizontal_chain import effective_centre

            out["effective centre d/L (7.27)"] = effective_centre(
                inertia_at(st["A"][0], (0.0, 0.0)) if v["base θ₁ (deg)"] == 0 else
                _rotate_back(st["A"][0], math.radians(v["base θ₁ (deg)"])))[0]
        E, Wd, E0 = st["energy"]
        out.update({"t": st["t"], "energy T + V": E, "dissipated W": Wd, "T + V + W": E + Wd,
                    "initial energy E₀": E0, C_ROW: st["n"] * st["c"]})
        return out


def _sub(i: int) -> str:
    """``i`` in subscript digits."""
    return str(i).translate(str.maketrans("0123456789", "₀₁₂₃₄₅₆₇₈₉"))


def _fade(artist, alpha):
    """Set the opacity of a composite artist and of its children."""
    artist.set_alpha(alpha)
    for c in artist.get_children():
        c.set_alpha(alpha)
    artist.stale = True


def _rotate_back(A, theta):
    """The inertia ``A`` (at the origin) seen in a frame turned by ``theta`` (so the chain lies along x)."""
    c, s = math.cos(theta), math.sin(theta)
    X = np.array([[c, s, 0.0], [-s, c, 0.0], [0.0, 0.0, 1.0]])        # twists into the turned frame
    Xi = np.linalg.inv(X)
    return Xi.T @ A @ Xi
