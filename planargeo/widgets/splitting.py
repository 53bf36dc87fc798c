"""Constrained chain: articulated mobility and chain splitting (thesis sections 7.4-7.6, corrected 7.38a).

A chain of ``n`` identical bodies pinned to the ground, every further joint bent by ``φ``, at rest
under a couple on the tip (7.44) and gravity.  Split at a joint, bodies ``1..i`` form the constrained chain with articulated mobility ``Λ_i⁻¹`` and bias ``b_i``
(7.4.1, the corrected sign of 7.38a, ``docs/errata.md``), the rest the free-floating chain.
Shown: the acceleration of body ``i`` from the split (7.54), the split joint's force (7.56),
every body's acceleration pole (7.6), the centre of ``Λ_i⁻¹`` (7.5) and, for ``n = 2``, thesis
example 7.5 beside its closed form (7.48).  A single instant: no Play.
"""
from __future__ import annotations

import math

import ipywidgets as W
import numpy as np

from planargeo.draw.pictures.articulated import fit_box
from planargeo.draw.pictures.splitting import splitting_picture
from planargeo.draw.pictures._words import subscript
from planargeo.scenes.splitting import splitting_state, twist_pole
from planargeo.widgets._explorer import ChainBodies, Described, state_handle
from planargeo.widgets.articulated import bend_for_tip
from planargeo.widgets.base import Explorer, Step, point_text

__all__ = ["SplittingExplorer", "NMAX", "x_over_L_7_48"]

#: Most bodies the explorer shows.
NMAX = 8


def x_over_L_7_48(rho: float, L: float, phi: float) -> float:
    """Closed form of thesis 7.48: the pole of ``a_2`` of example 7.5 at ``x / L`` on ``y = 0``.

    ``x / L = 1 + 2 η² cos φ / (4 + 5 η²)`` with ``η = L / ρ`` (7.49).

    Parameters
    ----------
    rho, L : float
        Radius of gyration and length of each body (> 0).
    phi : float
        Angle of body 2 relative to body 1 [rad].

    Returns
    -------
    float

    Examples
    --------
    >>> x_over_L_7_48(0.5, 1.0, 0.0)
    1.3333333333333333
    """
    eta2 = (L / rho) ** 2
    return 1.0 + 2.0 * eta2 * math.cos(phi) / (4.0 + 5.0 * eta2)


class SplittingExplorer(Described, ChainBodies, Explorer):
    """A pinned chain split at a chosen joint: mobilities, accelerations of both halves, the split force.

    Examples
    --------
    Thesis example 7.5 (``ρ = L/2``, ``φ = 45°``): the couple turns body 2 about ``x = 1.2357 L``.

    >>> ex = SplittingExplorer(display="agg")
    >>> round(ex.readout_values["x/L of aₙ's pole (7.48)"], 4), round(ex.readout_values["x/L closed form"], 4)
    (1.2357, 1.2357)
    """

    title = "Constrained chain: articulated mobility and chain splitting"
    slug = "splitting"
    figsize = (7.6, 5.2)
    display_controls = ("mobility centres",)
    #: lengths in m (L = 1); below ``zero_tol × scale`` is round-off (real values are above 1e-4)
    scale = 1.0
    zero_tol = 1e-6

    spans = ("split at joint", 0, NMAX)

    def make_controls(self):
        return {
            "bodies n": Step(2, NMAX, 1, 2, "bodies n", integer=True),
            "split at joint": Step(2, NMAX, 1, 2, "split at joint i+1", integer=True),
            "ρ (m)": Step(0.05, 2.0, 0.01, 0.5, "ρ (m), L = 1"),
            "bend φ (deg)": Step(-180.0, 180.0, 0.5, 45.0, "bend φ (deg)"),
            "couple τ (N·m)": Step(-5.0, 5.0, 0.05, 1.0, "couple τ on the tip (N·m)",
                                   tip="the couple on the tip, counter-clockwise positive; 0: no couple"),
            "g (m/s²)": Step(0.0, 9.81, 0.01, 0.0, "g (m/s²)"),
            "mobility centres": W.Checkbox(value=True, description="mobility centres"),
            # the focus made here: an ordinary control, not a display control of the base
            "focus": W.Dropdown(options=["all", *self.focus_options()], value="all", description="focus",
                                layout=W.Layout(width="310px")),
        }

    def adjust(self, values, changed):
        n = int(values["bodies n"])
        return {"split at joint": n} if values["split at joint"] > n else {}

    def disabled(self, values):
        if int(values["bodies n"]) == 2:
            return {"split at joint": "two bodies: joint 2 is the only joint to split at (add bodies to move it)"}
        return {}

    def explain(self):
        n = int(self.values["bodies n"])
        i = min(int(self.values["split at joint"]), n) - 1
        return {
            **self.symbols,
            "−fₙ₊₁ on the tip": "the couple τ on the tip (counter-clockwise positive), from a fictitious joint n+1 "
                                "(eq. 7.44: it pushes the tip with −fₙ₊₁ = [0, 0, τ]); in the figure: "
                                f"−f{subscript(n + 1)} on the tip: couple (line at ∞)",
            "aⱼ": ("acceleration of body j, drawn as its pole: the point with no acceleration (eq. 4.6); in the "
                   "figure: " + ", ".join(f"a{subscript(j)}" for j in range(1, n + 1))),
            "fᵢ₊₁": "force of the split joint i+1 on body i+1, drawn as its line of action (eq. 7.56); in the "
                    f"figure: f{subscript(i + 1)}",
            "centre of Λᵢ⁻¹": "where a couple on body i alone turns it: the pole of −Λᵢ⁻¹ [0, 0, 1] (section 7.5); "
                              f"in the figure: centre of Λ{subscript(i)}⁻¹",
            **self.meanings,
        }

    def focus_options(self):
        return ["constrained part", "free-floating part"]

    def handles(self):
        # the split marker (snaps to the nearest joint) and the tip (bend φ)
        def split_drag(x, y):
            st = self.state
            d = np.hypot(*(st["joints"][1:st["n"]] - [x, y]).T)
            return {"split at joint": int(np.argmin(d)) + 2}

        def split_at(st):             # two bodies: nowhere else to split (disabled)
            return st["joints"][st["split"]] if st["n"] >= 3 else None

        return [state_handle(self, "split", split_at, split_drag), self._tip_handle(bend_for_tip)]

    def compute(self, values, changed):
        n, split = int(values["bodies n"]), int(values["split at joint"]) - 1
        rho, phi, tau = float(values["ρ (m)"]), math.radians(values["bend φ (deg)"]), float(values["couple τ (N·m)"])
        q = np.array([0.0] + [phi] * (n - 1))
        # the slider's τ is the couple on the tip, counter-clockwise positive: the fictitious joint n+1
        # pushes the tip with −f_{n+1} (3.1, 7.44), so f_{n+1} = [0, 0, −τ].  τ = 0 (and g = 0) is an
        # ordinary state: no load, the chain stays at rest, its mobilities are still those shown.
        st = splitting_state(self._model(n, rho, float(values["g (m/s²)"])), q, split, -tau)
        st.update(n=n, split=split, rho=rho, phi=phi, tau=tau)
        return st

    def _view(self, st) -> tuple[float, float, float, float]:
        """The view: every joint, the split force's arrow, the poles at the split and the centre."""
        i = st["split"]
        pts = st["joints"]
        f = st["f_split"]
        fxy = math.hypot(f[0], f[1])
        mech = [pts] + ([[pts[i] + 0.6 * np.array(f[:2]) / fxy]] if fxy > 0 else [])
        extra = [[p] for p in (twist_pole(st["a"][b]) for b in (i - 1, i)) if p is not None]
        c = st["centres"][i - 1]
        if bool(self.values["mobility centres"]) and bool(np.all(np.isfinite(c))):
            extra.append([c])
        return fit_box(np.vstack(mech), np.vstack(extra) if extra else (), margin=0.15)

    def scene_picture(self, state, view=None):
        v = self.values
        return splitting_picture(state, view=view or self._view(state), focus=v.get("focus", "all"),
                                 centres=bool(v["mobility centres"]), size=self.figure_px)

    def readout_of(self, state):
        n, i = state["n"], state["split"]
        f = state["f_split"]
        self._span(n)                                 # the split slider spans the chain's joints 2..n
        Lam = state["Lambda_inv"][i - 1]
        out = {
            "split at joint": i + 1,
            "aᵢ (7.54)": _vec(state["a_split"]),
            "aᵢ₊₁": _vec(state["a"][i]),
            "fᵢ₊₁ (7.56)": _vec(f),
            "pole of aᵢ": _pole_text(state["a"][i - 1]),
            "pole of aᵢ₊₁": _pole_text(state["a"][i]),
            "row 1 of Λᵢ⁻¹": _vec(Lam[0]), "row 2 of Λᵢ⁻¹": _vec(Lam[1]), "row 3 of Λᵢ⁻¹": _vec(Lam[2]),
            "bᵢ": _vec(state["b"][i - 1]),
            "aₙ (tip)": _vec(state["a"][-1]),
            "q̈ (6.110)": _vec(state["qdd"]),
        }
        a_n = state["a"][-1]
        if n == 2 and float(self.values["g (m/s²)"]) == 0.0:
            if twist_pole(a_n) is not None:                # τ = 0: no acceleration, no pole
                out["x/L of aₙ's pole (7.48)"] = float(-a_n[1] / a_n[2])
            out["x/L closed form"] = x_over_L_7_48(state["rho"], 1.0, state["phi"])
            out["η = L/ρ (7.49)"] = 1.0 / state["rho"]
        return out


def _vec(a) -> tuple:
    """A vector as a tuple of plain floats (the readout's; no "−0": a zero load gives zeros)."""
    return tuple(float(x) + 0.0 for x in np.asarray(a, dtype=float))


def _pole_text(a) -> str:
    """The readout text of an acceleration's pole; a pure translation (as drawn: :func:`twist_pole`) is at infinity.

    The acceleration ``[a_x, a_y, α]`` is the pole's homogeneous point (thesis 5.49); an ``α`` that
    is round-off of the others (the drawing's own test) is the exact zero of a translation.
    """
    p = np.array(a, dtype=float)
    if not np.any(np.abs(p) > SplittingExplorer.zero_tol * SplittingExplorer.scale):
        return "none: no acceleration"
    if twist_pole(p) is None:
        p[2] = 0.0
    return point_text(p, zero=SplittingExplorer.zero_tol * SplittingExplorer.scale)
