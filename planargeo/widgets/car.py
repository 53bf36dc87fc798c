"""Car cornering explorer (thesis 6.9, Fig 6.6).

The car turns about its instant centre of rotation (ICR) with the steering
fixed; the two lateral tyre forces are the reactions of that "revolute joint"
and follow from the projective decomposition ``f = T Q + R μ`` (scene
``"car"``).  Controls: speed, turn radius, drive force, position of the
centre of gravity and radius of gyration.  The tyre forces are drawn as lines
(through the tyre contacts, along the axles) and listed in the readout.
"""
from __future__ import annotations

import math

import numpy as np
from matplotlib.lines import Line2D
from matplotlib.patches import Polygon as MplPolygon

from planargeo import scenes
from planargeo.draw.artists import ConicArtist, LineArtist, PointArtist
from planargeo.draw.style import COLORS
from planargeo.errors import SceneError
from planargeo.widgets.base import Explorer, Step

__all__ = ["CarExplorer"]


class CarExplorer(Explorer):
    """Tyre forces of a car cornering and accelerating (thesis 6.9)."""

    title = "Car cornering: tyre forces by projective dynamics"
    slug = "car"
    figsize = (6.0, 5.4)
    limits = (-2, 12, -5, 8)

    def __init__(self, **kw):
        # the scene function itself (scenes.build checks parameter names on every call)
        self._scene = scenes.get("car")
        super().__init__(**kw)

    def make_controls(self):
        return {
            "speed (m/s)": Step(0.0, 30.0, 0.5, 4.0, "speed (m/s)").make("speed"),
            "turn radius (m)": Step(2.0, 60.0, 0.5, 8.0, "turn radius (m)").make("radius"),
            "drive force (N)": Step(-6000, 6000, 100, 2000, "drive force (N)").make("drive"),
            "COM behind front (ε)": Step(0.0, 1.0, 0.01, 0.45, "COM behind front (ε)").make("eps"),
            "radius of gyration (m)": Step(0.3, 3.0, 0.05, 1.2, "radius of gyration (m)").make("rho"),
            "mass (kg)": Step(400, 3000, 50, 1200, "mass (kg)").make("m"),
        }

    def make_artists(self, ax):
        self.body = MplPolygon(np.zeros((4, 2)), closed=True, fc=COLORS["body"], ec="black",
                               alpha=0.5, zorder=2)
        ax.add_patch(self.body)
        self.wheels = [Line2D([], [], color="black", lw=4, solid_capstyle="butt", zorder=3)
                       for _ in range(2)]
        for w in self.wheels:
            ax.add_line(w)
        self.axles = Line2D([], [], color=COLORS["construct"], lw=0.8, ls="--", zorder=1)
        ax.add_line(self.axles)
        z = np.array([0.0, 0.0, 1.0])
        self.icr = ax.add_artist(PointArtist(z, role="twist", text="ICR"))
        self.accel = ax.add_artist(PointArtist(z, role="accel", glyph=False, text="a"))
        self.cg = Line2D([], [], marker="o", ms=7, mfc="white", mec="black", ls="none", zorder=6)
        ax.add_line(self.cg)
        self.inertia = ax.add_artist(ConicArtist(np.eye(3), role="inertia"))
        self.rear = ax.add_artist(LineArtist([1.0, 0, 0], role="reaction", scale=1e-3, text="rear"))
        self.front = ax.add_artist(LineArtist([1.0, 0, 0], role="reaction", scale=1e-3, text="front"))
        self.drive = ax.add_artist(LineArtist([1.0, 0, 0], role="wrench", scale=1e-3, text="drive"))

    def compute(self, v, changed):
        d = float(v["turn radius (m)"])
        V = float(v["speed (m/s)"])
        if d <= 0:
            raise SceneError(f"turn radius must be positive, got {d}")
        res = self._scene(m=float(v["mass (kg)"]), rho=float(v["radius of gyration (m)"]),
                          d=d, eps=float(v["COM behind front (ε)"]), omega=V / d,
                          F_A=float(v["drive force (N)"]),
                          outlines=False)   # the outlines are drawn by gallery Fig 6.6, not here
        return {"res": res}

    def render(self, st):
        res = st["res"]
        q, x, p = res.quantities, res.extra, res.params
        L, d = p["L"], p["d"]
        rear, front, cg = x["rear_contact"], x["front_contact"], x["cg"]
        hw = 0.8  # half track, drawing only
        self.body.set_xy(np.array([[d - hw, -0.7], [d + hw, -0.7], [d + hw, L + 0.7],
                                   [d - hw, L + 0.7]]))
        self.wheels[0].set_data([d, d], [-0.35, 0.35])
        roll = x["front_rolling"]
        self.wheels[1].set_data([d - 0.35 * roll[0], d + 0.35 * roll[0]],
                                [L - 0.35 * roll[1], L + 0.35 * roll[1]])
        self.axles.set_data([0.0, rear[0], np.nan, 0.0, front[0]], [0.0, rear[1], np.nan, 0.0, front[1]])
        self.icr.set_point(q["v"])
        self.accel.set_point(q["a"])
        self.cg.set_data([cg[0]], [cg[1]])
        self.inertia.set_conic(q["I"])
        tw = x["tyre_wrenches"]
        self.rear.set_line(tw[:, 0])
        self.rear.set_anchor(rear)
        self.front.set_line(tw[:, 1])
        self.front.set_anchor(front)
        fA = np.asarray(q["f_A"])
        self.drive.set_visible(bool(np.any(fA)))
        if np.any(fA):
            self.drive.set_line(fA)
            self.drive.set_anchor(front)
        # view: the ICR and the car
        x0, x1 = min(-2.0, d - 4), max(d + 4, 4.0)
        span = x1 - x0
        lims = (x0, x1, L / 2 - 0.55 * span, L / 2 + 0.55 * span)
        if tuple(self.ax.get_xlim()) != lims[:2]:
            self.ax.set_xlim(*lims[:2])
            self.ax.set_ylim(*lims[2:])
        mu = q["mu"]
        return {
            "speed (m/s)": self.values["speed (m/s)"],
            "yaw rate ω (rad/s)": p["omega"],
            "yaw acceleration ω̇ (rad/s²)": q["omega_dot"],
            "rear tyre force (N)": mu[0],
            "front tyre force (N)": mu[1],
            "steering angle (deg)": math.degrees(x["steer"]),
            "lateral accel. at CG (g)": p["omega"] ** 2 * float(np.hypot(*cg)) / 9.81,
        }
