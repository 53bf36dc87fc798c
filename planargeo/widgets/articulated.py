"""Articulated inertias along a chain, drawn as conics (thesis sections 7.1-7.3, 10.2.2, 10.2.3).

A chain of ``n`` identical bodies (mass 1, joints ``L = 1`` apart, ``ρ = L / λ``), every joint
after the first bent by ``φ``.  Drawn: each body's rigid inertia ``I_i`` and articulated inertia
``A_i`` (7.7a) as the real conics of 10.2.3; for the focused body the axes of percussion ``I_k a``
and ``A_k a`` of the pole ``a`` (5.64-5.68); and, as the *outboard bodies* slider truncates the
recursion (10.2.2), a chart of ``A_k``'s entries against the steps taken.  *Play* lets the chain
swing under gravity with joint damping.
"""
from __future__ import annotations

import math

import ipywidgets as W
import numpy as np

from planargeo._validate import as_array
from planargeo.draw.geometry import conic_geometry
from planargeo.draw.pictures._words import subscript
from planargeo.draw.pictures.articulated import MARGIN, articulated_picture, chain_view, fit_box
from planargeo.errors import ShapeError
from planargeo.scenes.articulated import articulated_state, inertia_at, percussion_axes
from planargeo.widgets._motion import Motion
from planargeo.widgets._explorer import ChainBodies, Described, HeldView, state_handle, time_step, xy_handle
from planargeo.widgets.base import Explorer, Step, cached, point_text
from planargeo.widgets.handles import Handle
from planargeo.widgets.controls import widen

__all__ = ["ArticulatedExplorer", "NMAX", "bend_for_tip"]

#: Most bodies the explorer shows.
NMAX = 8
#: Longest swing [s] (the range of the time slider).
T_MAX = 60.0
#: the readout's time control
TIME = "time (s)"
#: the readout row of the damping (the power it takes when every joint turns at 1 rad/s)
C_ROW = "damping power at 1 rad/s in every joint"
#: controls that define the chain or its swing: a change restarts the swing at t = 0
_CHAIN = ("bodies n", "λ = L/ρ", "bend φ (deg)", "base θ₁ (deg)", "g (m/s²)", "damping c")


#: the grid of bends :func:`bend_for_tip` searches (0.01°) and e^{iφ} on its every 10th point
_GRID = np.linspace(-math.pi, math.pi, 36001)
_COARSE = np.exp(1j * _GRID[::10])


def bend_for_tip(xy, n: int, base: float, L: float = 1.0) -> float:
    """The bend ``φ`` [rad] that brings the tip of the chain nearest to ``xy`` (base angle ``base``).

    Searched on a 0.01° grid, then refined by golden-section search.

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

    Raises
    ------
    NonFiniteError, ShapeError
        ``xy`` is not one finite point.

    Examples
    --------
    >>> round(math.degrees(bend_for_tip((1.0, 1.0), 2, 0.0)), 6)    # an elbow of 90 degrees
    90.0
    """
    target = as_array(xy, "xy", (2,))
    if target.shape != (2,):
        raise ShapeError(f"xy must be one point (x, y), got shape {target.shape}")
    if n < 2:
        return 0.0
    k = np.arange(n, dtype=float)
    tx, ty = float(target[0]), float(target[1])

    def dist(phi):
        th = base + np.asarray(phi, dtype=float)[..., None] * k
        return np.hypot(L * np.cos(th).sum(-1) - tx, L * np.sin(th).sum(-1) - ty)

    grid = _GRID
    # the grid's nearest point without measuring all of it: every 10th point first (the tip as
    # L e^{iθ₁} Σ zᵏ, z = e^{iφ}: two sines per point, not 2n; to ~n² ulps, in the margin); between two of
    # them the distance dips at most the tip's largest speed (L Σk per radian) times half the gap
    # below their mean, so only the stretches that could dip below the best are measured in full
    with np.errstate(over="ignore", invalid="ignore"):   # a tip beyond the float range: no stretch, below
        s = np.ones_like(_COARSE)
        for _ in range(n - 1):
            s = s * _COARSE + 1.0
        coarse = np.abs(L * complex(math.cos(base), math.sin(base)) * s - complex(tx, ty))
        dip = 0.5 * abs(L) * n * (n - 1) / 2 * (grid[10] - grid[0])
        margin = 1e-12 + 1e-9 * (abs(L) * n * n + math.hypot(tx, ty))
        near = np.flatnonzero(0.5 * (coarse[:-1] + coarse[1:]) - dip <= coarse.min() * (1 + 1e-9) + margin)
    # no stretch qualifies only when the distances overflowed: then the whole grid, as it is
    idx = np.unique((10 * near[:, None] + np.arange(11)).ravel()) if len(near) else np.arange(len(grid))
    j = int(idx[np.argmin(dist(grid[idx]))])
    lo, hi = grid[max(j - 1, 0)], grid[min(j + 1, len(grid) - 1)]
    g = (math.sqrt(5) - 1) / 2
    for _ in range(40):                            # golden-section refinement inside the bracket
        a, b = hi - g * (hi - lo), lo + g * (hi - lo)
        da, db = dist((a, b))
        if da < db:
            hi = b
        else:
            lo = a
    phi = 0.5 * (lo + hi)
    # near its best the distance is flat to rounding (it grows as φ²): a round angle (1e-4°) that is
    # as near counts as the answer, so that a drag along the straight chain gives φ = 0, not 2e-6°
    rounded = math.radians(round(math.degrees(phi), 4))
    if dist(rounded) <= dist(phi) + 1e-12 * (1.0 + float(np.hypot(*target))):
        phi = rounded
    return float(phi)


class ArticulatedExplorer(HeldView, Described, ChainBodies, Explorer):
    """Rigid and articulated inertias of a chain as conics, their axes of percussion and convergence.

    Parameters
    ----------
    **kw
        As for :class:`planargeo.widgets.base.Explorer`.

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

    spans = ("outboard bodies", -1, NMAX - 1)

    def make_controls(self):
        return {
            "bodies n": Step(1, NMAX, 1, 4, "bodies n", integer=True),
            "λ = L/ρ": Step(0.5, 8.0, 0.05, 3.0, "λ = L/ρ"),
            "bend φ (deg)": Step(-180.0, 180.0, 0.5, 25.0, "bend φ (deg)"),
            "base θ₁ (deg)": Step(-180.0, 180.0, 0.5, 0.0, "base θ₁ (deg)"),
            "outboard bodies": Step(0, NMAX - 1, 1, NMAX - 1, "outboard bodies", integer=True),
            "pole x": Step(-4.0, 6.0, 0.01, 0.0, "pole a: x (m)"),
            "pole y": Step(-5.0, 5.0, 0.01, -0.8, "pole a: y (m)"),
            "g (m/s²)": Step(0.0, 9.81, 0.01, 9.81, "g (m/s²) for Play"),
            "damping c": Step(0.0, 3.0, 0.01, 0.3, "damping c (N·m·s/rad)"),
            "time (s)": Step(0.0, T_MAX, 0.01, 0.0, "time (s)"),
            "rigid inertias": W.Checkbox(value=True, description="rigid inertias Iᵢ"),
            "percussion axes": W.Checkbox(value=True, description="percussion axes"),
        }

    def adjust(self, values, changed):
        # "outboard bodies" stays within the n − 1 bodies after body 1 (at "all" it stays "all");
        # a change of the chain or its swing restarts the time at 0
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
                widen(w, k)
        if changed & set(_CHAIN) and TIME not in changed and values[TIME] != 0.0:
            out[TIME] = 0.0
        return out

    def disabled(self, values):
        out = {}
        n = int(values["bodies n"])
        if n == 1:
            out["outboard bodies"] = "one body: there is no body outboard of it (add bodies)"
            out["bend φ (deg)"] = "one body: the bend is the angle between bodies (add bodies)"
        return out

    def explain(self):
        focus = str(self.values.get("focus", "all"))
        j = focus.split()[1] if focus.startswith("body ") else 1
        kk = subscript(int(j))
        return {
            **self.symbols,
            "Aₖ": f"articulated inertia of the focused body k (eq. 7.7a); in the figure: A{kk}",
            "Iₖ": f"rigid inertia of the focused body k; in the figure: I{kk}",
            "Aₖa": ("axis of percussion: the force that gives body k the acceleration a with the outboard bodies "
                    f"attached (eq. 5.64-5.68); in the figure: A{kk} a"),
            "Iₖa": f"axis of percussion of body k alone (eq. 5.64-5.68); in the figure: I{kk} a",
            "entries of Aₖ at joint k / full value": "the chart: each entry of Aₖ (at joint k) after so many "
                                                     "recursion steps, over its value with every outboard body; "
                                                     f"in the figure: entries of A{kk} at joint {j} / full value",
            **self.meanings,
        }

    def handles(self):
        def base_drag(x, y):
            if x == 0 and y == 0:
                return {}
            return {"base θ₁ (deg)": float(math.degrees(math.atan2(y, x)))}

        # each held: the view shown when a drag begins stays until its release (re-fitted at each step,
        # it moved under the pointer and the dragged handle ran away from it)
        handles = [xy_handle(self, "pole a", "pole x", "pole y"), self._tip_handle(bend_for_tip, "base θ₁ (deg)"),
                   state_handle(self, "first body", lambda st: st["joints"][1], base_drag)]
        return [Handle(h.name, h.where, self.holding(h.drag)) for h in handles]

    def focus_options(self):
        # before the first state every body of the longest chain (a focus given with "bodies n")
        w = getattr(self, "controls", {}).get("bodies n")
        n = NMAX if w is None or getattr(self, "state", None) is None else int(w.value)
        return [f"body {i}" for i in range(1, n + 1)]

    def play_step(self, values, dt):
        return time_step(values, dt, TIME, T_MAX)

    def _key(self, v):
        return (int(v["bodies n"]), float(v["λ = L/ρ"]), float(v["bend φ (deg)"]), float(v["base θ₁ (deg)"]),
                float(v["g (m/s²)"]), float(v["damping c"]))

    def _q0(self, v):
        n = int(v["bodies n"])
        return np.array([math.radians(v["base θ₁ (deg)"])] + [math.radians(v["bend φ (deg)"])] * (n - 1))

    def _motion(self, v) -> Motion:
        """The swing of the configuration ``v`` from rest: ``y = (q, q̇, W)`` (kept)."""
        from planargeo.scenes.chain import chain_accelerations as forward_dynamics

        key = self._key(v)
        n, c = key[0], key[5]
        model = self._model(n, 1.0 / key[1], key[4])

        def rhs(_t, y):
            qd = y[n:2 * n]
            qdd = forward_dynamics(model, y[:n], qd, -c * qd)
            return np.concatenate([qd, qdd, [c * float(qd @ qd)]])

        y0 = np.concatenate([self._q0(v), np.zeros(n), [0.0]])
        return cached(self._cache("_motions"), key, lambda: Motion(rhs, y0, chunk=1.0))

    def compute(self, values, changed):
        from planargeo.simulate.integrate import energy

        self.drag_or_fit()              # a control, Play or reset: the view fits the state again
        n, lam = int(values["bodies n"]), float(values["λ = L/ρ"])
        t = float(values[TIME])
        motion = self._motion(values)
        y = motion.at(t)
        q, qd, W = y[:n], y[n:2 * n], float(y[2 * n])
        model_g = self._model(n, 1.0 / lam, float(values["g (m/s²)"]))
        # the energies kept per state of the swing (and E₀ per swing): a drag of the pole reuses them
        key = self._key(values)
        T, V = cached(self._cache("_energies"), (key, q.tobytes(), qd.tobytes()), lambda: energy(model_g, q, qd))
        E0 = cached(self._cache("_E0"), key, lambda: float(sum(energy(model_g, self._q0(values), np.zeros(n)))))
        out_k = int(values["outboard bodies"])
        outboard = None if out_k >= n - 1 else out_k
        # the configuration's inertias, kept while only the pole moves (a drag of the pole)
        shape = cached(self._cache("_shapes"), (n, lam, q.tobytes(), outboard),
                       lambda: articulated_state(self._model(n, 1.0 / lam), q, outboard=outboard))
        st = {**shape, **percussion_axes(shape, (float(values["pole x"]), float(values["pole y"])))}
        st.update(n=n, lam=lam, q=q, outboard=out_k, t=t, energy=(float(T + V), W, E0), c=float(values["damping c"]))
        return st

    def _focus_k(self, n: int) -> int:
        """The focused body (0-based; body 1 for "all")."""
        focus = self.values.get("focus", "all")
        return 0 if focus == "all" else min(int(focus.split()[1]), n) - 1

    def _view(self, st) -> tuple[float, float, float, float]:
        """The view: chain, centres, pole and conics on the left, the chart on the right."""
        v = self.values
        n = st["n"]
        pts = [st["joints"], st["centre"], st["centre_rigid"], [[v["pole x"], v["pole y"]]]]

        def boxes(Cs):                         # each drawn ellipse's box: centre ± the affine's row norms
            out = []
            for C in Cs:
                g = conic_geometry(C)
                if "affine" in g:
                    A = g["affine"]
                    half = np.hypot(A[:2, 0], A[:2, 1])
                    out.append([A[:2, 2] - half, A[:2, 2] + half])
            return out

        # kept per set of inertias: a drag of the pole measures the conics once
        for Cs in [st["A"][:n]] + ([st["I"][:n]] if v["rigid inertias"] else []):
            Cs = np.ascontiguousarray(Cs, dtype=float)
            pts += cached(self._cache("_conic_boxes"), Cs.tobytes(), lambda: boxes(Cs))
        box = fit_box(np.vstack(pts), margin=0.1)
        return chain_view(box, self.figure_px, MARGIN)

    _fitted_view = _view                  # (HeldView)

    def scene_picture(self, state, view=None):
        v = self.values
        return articulated_picture(state, k=self._focus_k(state["n"]), focus_all=v.get("focus", "all") == "all",
                                   rigid=bool(v["rigid inertias"]), axes=bool(v["percussion axes"]),
                                   view=view or self.held_view or self._view(state), size=self.figure_px)

    def readout_of(self, state):
        v = self.values
        n = state["n"]
        k = self._focus_k(n)
        pts = state["joints"]
        self._span(n)                                  # the slider spans the bodies outboard of body 1
        Ak = state["A"][k]
        zero = float(self.zero_tol) * float(self.scale)
        Aj = inertia_at(Ak, pts[k])
        c = state["centre"][k]
        P = np.array([v["pole x"], v["pole y"]])
        dist = float(np.hypot(*(P - c)))
        line = state["axis"][k]
        axis_from_c = abs(line[2] + c[1] * line[0] - c[0] * line[1]) / max(math.hypot(line[0], line[1]), 1e-300)
        out = {
            "bodies": n,
            "outboard included": f"{min(state['outboard'], n - 1 - k)} of {n - 1 - k}",
            "Aₖ: mass along x": float(Aj[0, 0]), "Aₖ: mass along y": float(Aj[1, 1]),
            "Aₖ: inertia about joint k": float(Aj[2, 2]),
            "effective centre of Aₖ": point_text([c[1], -c[0], 1.0], zero=zero),
            "centre of mass of body k": point_text([state["centre_rigid"][k][1], -state["centre_rigid"][k][0], 1.0],
                                                   zero=zero),
            "truncation error of Aₖ": float(state["truncation_error"][k]),
            "pole a": point_text([P[1], -P[0], 1.0], zero=zero), "distance from a to the centre": dist,
            "axis Aₖa: distance from the centre": float(axis_from_c),
        }
        if k == 0 and abs(math.remainder(float(v["bend φ (deg)"]), 360.0)) < 1e-12 and state["t"] == 0:
            from planargeo.scenes.horizontal_chain import effective_centre

            out["effective centre d/L (7.27)"] = effective_centre(
                inertia_at(state["A"][0], (0.0, 0.0)) if v["base θ₁ (deg)"] == 0 else
                _rotate_back(state["A"][0], math.radians(v["base θ₁ (deg)"])))[0]
        E, Wd, E0 = state["energy"]
        out.update({"t": state["t"], "energy T + V": E, "dissipated W": Wd, "T + V + W": E + Wd,
                    "initial energy E₀": E0, C_ROW: state["n"] * state["c"]})
        return out


def _rotate_back(A, theta):
    """The inertia ``A`` (at the origin) seen in a frame turned by ``theta`` (so the chain lies along x)."""
    c, s = math.cos(theta), math.sin(theta)
    X = np.array([[c, s, 0.0], [-s, c, 0.0], [0.0, 0.0, 1.0]])        # twists into the turned frame
    Xi = np.linalg.inv(X)
    return Xi.T @ A @ Xi
