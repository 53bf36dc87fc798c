"""Impulse explorer: a bat or a door at rest struck by a short blow (thesis 5.4, 5.7, figure 3.3).

Shown: the velocity pole after the blow, the pole if free (``I⁻¹ĵ``, 5.64–5.68), the reaction
impulse of the grip or hinge (zero through the centre of percussion, 5.67) and the apparent mass
along the blow (figure 3.3); *Play* runs the motion after it (:func:`planargeo.scenes.impulse.impulse`).

Examples
--------
>>> from planargeo.widgets import ImpulseExplorer
>>> ex = ImpulseExplorer(display="agg", body="door")
>>> cop = ex.readout_values["centre of percussion (5.67)"]
>>> round(cop[0], 6)                                # 2L/3 + w²/(6L) for the 0.9 m × 0.04 m door
0.600296
>>> abs(ex.set(**{"strike x": cop[0]}).readout_values["reaction impulse ĵᵣ, across"]) < 1e-12
True
"""
from __future__ import annotations

import math

import ipywidgets as W
import numpy as np

from planargeo.draw.pictures.impulse import impulse_picture, moved_outline
from planargeo.scenes.impulse import BODIES, body_outline, impulse
from planargeo.widgets._explorer import Described, arrow_handle, grown_view, time_step, xy_handle
from planargeo.widgets.base import Explorer, Step, point_text

__all__ = ["ImpulseExplorer"]

#: data length of the blow's arrow per N·s
ARROW = 0.25
#: longest time after the blow that Play runs (s)
T_MAX = 60.0


def pole_text(tw, pole, rest: str = "at rest") -> str:
    """Readout text of the ``pole`` (as the scene gives it) of a twist ``tw = [vx, vy, ω]``: ``"(x, y) m"``,
    ``"at infinity (direction …)"`` or ``rest`` (no motion at all).

    A translation (``pole`` None) has the ideal point ``[vx, vy, 0]`` for its pole (thesis 4.10).

    Examples
    --------
    >>> pole_text([0.0, 2.0, 1.0], [-2.0, 0.0]), pole_text([1.0, 0.0, 0.0], None)
    ('(-2, 0) m', 'at infinity (direction (0, 1))')
    """
    tw = np.asarray(tw, dtype=float)
    if not np.any(tw):
        return rest
    if pole is None:
        return point_text([tw[0], tw[1], 0.0], "m")
    return point_text([pole[1], -pole[0], 1.0], "m", zero=1e-12)


class ImpulseExplorer(Described, Explorer):
    """A body at rest struck by a blow: pole, reaction impulse, apparent mass (thesis 5.4, 6.93)."""

    title = "Impulse and the centre of percussion: a bat or a door struck at rest"
    slug = "impulse"
    figsize = (6.2, 4.6)          # beside the controls in JupyterLab with its file browser open
    limits = (-0.45, 1.2, -0.6, 0.6)
    display_controls = ("t",)

    def make_controls(self):
        return {
            "body": W.Dropdown(options=list(BODIES), value="bat", description="body",
                               tooltip="a bat held at its grip, or a door (top view) held by its hinge"),
            "support": W.ToggleButtons(options=["held", "free"], value="held", description="support",
                                       tooltips=["held at the grip / hinge (a revolute joint)", "nothing holds it"]),
            "m": Step(0.1, 30.0, 0.05, 0.9, "mass m (kg)"),
            "strike x": Step(-0.4, 1.15, 0.005, 0.55, "blow point x (m)"),
            "strike y": Step(-0.55, 0.55, 0.005, 0.0, "blow point y (m)"),
            "strike angle": Step(-180, 180, 1.0, 90.0, "blow angle (deg)"),
            "J": Step(-5.0, 5.0, 0.05, 1.0, "impulse J (N·s)"),
            "t": Step(0.0, T_MAX, 0.01, 0.0, "t (s)", tip="time after the blow t (s)"),
        }

    def handles(self):
        return [xy_handle(self, "blow point", "strike x", "strike y"),
                arrow_handle(self, "blow tip", "strike x", "strike y", "strike angle", "J", per=ARROW / 2)]

    def play_step(self, values, dt):
        return time_step(values, dt, "t", T_MAX)

    def compute(self, values, changed):
        return impulse(body=values["body"], support=values["support"], m=float(values["m"]), x=float(values["strike x"]),
                       y=float(values["strike y"]), angle_deg=float(values["strike angle"]), J=float(values["J"]))

    def _view(self) -> tuple[float, float, float, float]:
        """The view: at ``t = 0`` the fixed frame grown to hold the blow's tip (no side shorter than the
        mechanism); moving (``t > 0``, Play or an animation's export), one view that holds the whole motion.

        Held, the body swings about the grip: the frame grown to the circle its farthest point sweeps.
        Free, its centre of mass moves straight on as it turns: the frame grown to the circle the body sweeps
        about ``c``, carried along with ``c``.
        """
        v = self.values
        tip = self.handle_position("blow tip")
        outline = body_outline(v["body"])
        box = grown_view(self.limits, [tip], 0.1, extra=0.2,
                         sized=np.vstack([outline, [v["strike x"], v["strike y"]], tip]))
        pc = getattr(self, "play_control", None)
        moving = (float(v["t"]) > 0.0 or getattr(self, "_exporting", False)
                  or bool(pc is not None and pc.playing))
        st = self.state
        if not moving or st is None:
            return box
        held = st.params["support"] == "held"
        centre = np.zeros(2) if held else np.asarray(st.quantities["com"], dtype=float)
        reach = float(np.max(np.hypot(*(outline - centre).T))) + 0.1
        x0, x1, y0, y1 = grown_view(box, [centre - reach, centre + reach], 0.0)
        if held:
            return (x0, x1, y0, y1)
        dx, dy = moved_outline(centre, st.extra["dv"], float(v["t"]), com=centre) - centre
        return (x0 + dx, x1 + dx, y0 + dy, y1 + dy)

    def mechanism_points(self):
        pts = super().mechanism_points()
        st = self.state
        if st is None:
            return pts
        outline = np.asarray(st.extra["outline"], dtype=float)
        t = float(self.values["t"])
        if t > 0.0 and st.params["support"] != "held":   # free and moving: the body where it is now
            return moved_outline(outline, st.extra["dv"], t, np.asarray(st.quantities["com"], dtype=float))
        return np.vstack([pts, outline])

    def scene_picture(self, state, view=None):
        return impulse_picture(state, t=float(self.values["t"]), view=view or self._view(), size=self.figure_px)

    def readout_of(self, state):
        r, q = state, state.quantities
        d = float(np.hypot(*q["com"]))
        return {
            "ω after the blow": q["omega"],
            "velocity of c": tuple(q["v_com"]),
            "velocity pole": pole_text(r.extra["dv"], q["pole"]),
            "pole if free (I⁻¹ĵ)": pole_text(r.extra["dv_free"], q["pole_if_free"]),
            "reaction impulse ĵᵣ, across": q["reaction_across"],
            "reaction impulse ĵᵣ, along": q["reaction_along"],
            "|ĵᵣ|": float(np.hypot(*np.array(q["reaction_force"]))),
            "centre of percussion (5.67)": tuple(q["centre_of_percussion"]),
            "l = d + ρ²/d": d + q["rho"] ** 2 / d,
            "apparent mass along ĵ": math.inf if q["apparent_mass"] is None else q["apparent_mass"],
            "apparent mass, held": math.inf if q["apparent_mass_held"] is None else q["apparent_mass_held"],
            "apparent mass, free": q["apparent_mass_free"],
            "mass m": r.params["m"],
            "radius of gyration ρ": q["rho"],
            "kinetic energy": q["kinetic_energy"],
            "t": float(self.values["t"]),
        }
