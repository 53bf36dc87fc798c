"""Slider-crank explorer: a closed kinematic loop (thesis 9.4-9.6, Fig 9.3).

The crank angle and speed set the state; the loop closure gives the rod and
piston angles.  The constrained algorithm (scene ``"slider-crank"``,
:func:`planargeo.algorithms.loops.loop_solve`) gives the contact force
``F3 = B3 ξ3`` of the slider (a line: the wrench that keeps the piston on its
guide) and the closed-loop accelerations (points), with the crank free or
driven at constant speed.

A dead-centre position (crank in line with the slider) is flagged on the
figure; a configuration that cannot be assembled (rod too short) or whose loop
closure is singular (rod along the horizontal when ``l = r``) shows a message
and keeps the last good drawing.  The loop is closed and solved by
:func:`planargeo.scenes.slider_crank.slider_crank_solve`, the scene's own solve
(so the widget reports the folded dead centre, ``l = r`` at ``ψ = 180°``, as the
scene does).

The model is kept per rod length and gravity (a crank move only re-solves the
loop), and the pole checkboxes only redraw.
"""
from __future__ import annotations

import math

import ipywidgets as W
import numpy as np
from matplotlib.lines import Line2D
from matplotlib.patches import Rectangle

from planargeo import scenes
from planargeo.scenes.slider_crank import slider_crank_model, slider_crank_solve
from planargeo.draw.artists import LineArtist, PointArtist
from planargeo.draw.mechanism import draw_ground
from planargeo.draw.style import COLORS
from planargeo.widgets.base import Explorer, Step, cached

__all__ = ["SliderCrankExplorer"]

#: |cos ψ| below which the crank is said to be at a dead centre
DEAD_CENTRE_TOL = 0.02


class SliderCrankExplorer(Explorer):
    """Slider-crank of thesis 9.6: contact force line and closed-loop accelerations."""

    title = "Slider-crank: a closed loop"
    slug = "slider-crank"
    figsize = (5.4, 6.0)
    limits = (-4.5, 4.5, -3.5, 9.0)
    display_controls = ("velocity poles", "acceleration poles")

    def __init__(self, **kw):
        p = scenes.parameters("slider-crank")     # the thesis 9.6 masses and lengths
        self.params = {k: p[k] for k in ("m1", "m2", "m3", "r", "t")}
        self._models: dict = {}
        super().__init__(**kw)

    def model_for(self, l: float, g: float):
        """The slider-crank model for rod length ``l`` and gravity ``g`` (kept per pair)."""
        return cached(self._models, (l, g), lambda: slider_crank_model(l=l, g=g, **self.params))

    def make_controls(self):
        return {
            "crank angle (deg)": Step(-180, 180, 1, math.degrees(0.4),
                                      "crank angle (deg)").make("crank angle (deg)"),
            "crank speed": Step(-40, 40, 0.5, 20.0, "crank speed (rad/s)").make("crank speed"),
            "drive": W.ToggleButtons(options=("free", "constant-speed"), value="free",
                                     description="crank"),
            "rod length": Step(1.0, 8.0, 0.01, 5.0, "rod length l").make("rod length"),
            "gravity": Step(0.0, 20.0, 0.1, 9.81, "g").make("gravity"),
            "velocity poles": W.Checkbox(value=False, description="velocity poles", indent=False),
            "acceleration poles": W.Checkbox(value=True, description="acceleration poles",
                                             indent=False),
        }

    def make_artists(self, ax):
        self.guide = Line2D([-0.35, -0.35, np.nan, 0.35, 0.35], [-20, 20, np.nan, -20, 20],
                            color=COLORS["ground"], lw=1.0, ls="--", zorder=1)
        ax.add_line(self.guide)
        draw_ground((0.0, -0.15), ax, width=0.9, zorder=1)
        self.crank = Line2D([], [], color=COLORS["ground"], lw=4, solid_capstyle="round", zorder=5)
        self.rod = Line2D([], [], color=COLORS["body"], lw=3, solid_capstyle="round", zorder=5)
        self.pins = Line2D([], [], ls="none", marker="o", ms=5, mfc="white", mec="black", zorder=6)
        for a in (self.crank, self.rod, self.pins):
            ax.add_line(a)
        self.piston = Rectangle((-0.3, 0), 0.6, 1.0, fc=COLORS["body"], ec="black", alpha=0.6,
                                zorder=4)
        ax.add_patch(self.piston)
        z = np.array([0.0, 0.0, 1.0])
        self.contact = ax.add_artist(LineArtist([1.0, 0.0, 0.0], role="reaction", scale=0.02,
                                                text="F3", corner="lower left"))
        self.v_art = [ax.add_artist(PointArtist(z, role="twist", glyph_scale=0.5, text=f"v{i + 1}"))
                      for i in range(3)]
        self.a_art = [ax.add_artist(PointArtist(z, role="accel", glyph_scale=0.05, text=f"a{i + 1}"))
                      for i in range(3)]

    def compute(self, v, changed):
        psi = math.radians(v["crank angle (deg)"])
        l, g = float(v["rod length"]), float(v["gravity"])
        r, t = self.params["r"], self.params["t"]
        model = self.model_for(l, g)
        q, qd, sol, h = slider_crank_solve(model, psi, float(v["crank speed"]), r, l, t, v["drive"])
        st = {"sol": sol, "q": q, "qd": qd, "r": r, "l": l, "t": t, "h": h,
              "v": sol.data.v, "a": sol.a.reshape(3, 3), "F3": np.asarray(sol.F, dtype=float),
              "message": ""}
        if abs(math.cos(psi)) < DEAD_CENTRE_TOL:
            st["message"] = ("dead centre: the crank is in line with the slider, so a force on the "
                             "piston cannot turn the crank here")
        return st

    def render(self, st):
        sol = st["sol"]
        d = sol.data
        r, l, t = st["r"], st["l"], st["t"]
        pose = d.pose
        pin = pose[1, :2]
        wrist = pose[2, :2]
        self.crank.set_data([0.0, pin[0]], [0.0, pin[1]])
        self.rod.set_data([pin[0], wrist[0]], [pin[1], wrist[1]])
        self.pins.set_data([0.0, pin[0], wrist[0]], [0.0, pin[1], wrist[1]])
        self.piston.set_xy((wrist[0] - 0.3, wrist[1]))
        self.piston.set_height(2 * t)
        F = st["F3"]
        if np.any(F):
            self.contact.set_line(F)
            self.contact.set_anchor(d.com[2])
            self.contact.set_visible(True)
        else:
            self.contact.set_visible(False)
        vals = self.values
        vel, acc = st["v"], st["a"]
        for i in range(3):
            self.v_art[i].set_visible(bool(vals["velocity poles"]))
            self.v_art[i].set_point(vel[i])
            self.a_art[i].set_visible(bool(vals["acceleration poles"]))
            self.a_art[i].set_point(acc[i])
        top = max(9.0, r + l + 2 * t + 1.0)
        if self.ax.get_ylim()[1] != top:
            self.ax.set_ylim(-r - 1.2, top)
        qq, qdd = st["q"], sol.qdd
        return {
            "crank angle (deg)": vals["crank angle (deg)"],
            "θ (rod, rad)": qq[1], "φ (piston, rad)": qq[2],
            "piston height h": st["h"],
            "piston speed": vel[2][1],
            "piston acceleration": acc[2][1],
            "ψ̈ crank": qdd[0],
            "contact force Fx": F[0], "contact moment (origin)": F[2],
            "drive torque": sol.tau_drive[0],
            "dead centre": abs(math.cos(qq[0])) < DEAD_CENTRE_TOL,
        }

    def figure_message(self, exc):
        text = str(exc)
        if "rod too short" in text:
            return "rod too short: it cannot reach the slider at this crank angle"
        if "piston pin on the crank pivot" in text:
            return "singular configuration: folded dead centre, the piston pin is on the crank pivot"
        if "singular" in text:
            return "singular configuration: the rod lies along the horizontal"
        return super().figure_message(exc)
