"""Car cornering explorer (thesis 6.9, Fig 6.6).

The car turns about its instant centre of rotation (ICR) with the steering fixed; the lateral
tyre forces ``R₁μ₁``, ``R₂μ₂`` (6.114, 6.133) are the reactions of that "revolute joint", from
``f = T Q + R μ`` (scene ``"car"``).  Drawn with their thesis symbols: the joint ``s`` at the ICR
(6.115), ``G``, the inertia (6.117), the drive force ``f_A`` (6.120), the bias force ``p`` (6.119)
and the active-force line ``T`` (6.125).  Play drives the car round the corner at the constant
``ω̇`` of 6.131, until it stops or slides out (its centre of gravity needs more than ``μ·g``).
"""
from __future__ import annotations

import math
import textwrap

import numpy as np

from planargeo import scenes
from planargeo.draw.pictures.car import (FORCE_SCALE, HALF_TRACK, NEAR, OVERHANG, car_picture, steer_lever,
                                         moves, view_box)
from planargeo.errors import InputError, SceneError
from planargeo.simulate.integrate import energy
from planargeo.widgets._explorer import Described, HeldView
from planargeo.widgets.base import Explorer, Handle, Step

__all__ = ["CarExplorer", "view_box", "grip"]

SPEED, RADIUS, DRIVE, EPS = "speed (m/s)", "turn radius (m)", "drive force (N)", "centre of mass ε (× L)"
HEADING = "heading (deg)"
FRICTION = "tyre friction μ"
#: gravity (m/s²): the tyres hold a horizontal acceleration of at most μ·G_ROAD at the centre of gravity
G_ROAD = 9.81


def grip(res, mu: float):
    """The acceleration of the centre of gravity and what the tyres hold, ``(r_G √(ω⁴ + ω̇²), μ·g)`` (m/s²).

    Parameters
    ----------
    res : SceneResult
        The scene ``"car"``.
    mu : float
        Tyre-road friction coefficient.

    Returns
    -------
    tuple of float
        The acceleration, then the most the tyres hold; they slip where the first is larger.

    Examples
    --------
    >>> from planargeo.scenes.car import car
    >>> acc, limit = grip(car(omega=0.5, F_A=0.0, outlines=False), 0.9)
    >>> round(acc, 3), round(limit, 3)                 # ω² r_G with r_G = √(8² + 1.43²)
    (2.032, 8.829)
    """
    r_g = float(np.hypot(*res.extra["cg"]))
    w, wd = float(res.params["omega"]), float(res.quantities["omega_dot"])
    return r_g * float(np.hypot(w * w, wd)), float(mu) * G_ROAD


class CarExplorer(HeldView, Described, Explorer):
    """Tyre forces of a car cornering and accelerating (thesis 6.9), dragged and driven round the turn.

    Parameters
    ----------
    **kw
        :class:`~planargeo.widgets.base.Explorer` options and initial control values.
    """

    title = "Car cornering: tyre forces by projective dynamics"
    slug = "car"
    figsize = (6.0, 5.6)

    def __init__(self, **kw):
        # the scene function itself (scenes.build checks parameter names on every call)
        self._scene = scenes.get("car")
        self._held_rear = None          # where the rear tyre was drawn when a drag began: held still too
        super().__init__(**kw)

    def make_controls(self):
        return {
            # the speed of the rear axle's middle (the car turns about the ICR on the rear axle's line):
            # G, ahead of it, moves faster (ω times its distance from the ICR)
            SPEED: Step(0.0, 30.0, 0.5, 4.0, "rear-axle speed V (m/s)",
                        tip="speed V of the rear axle's middle, V = ω d (6.115); the centre of gravity G, "
                            "farther from the ICR, moves faster: ω times its distance from the ICR"),
            # 5 cm steps: at a 2 m radius a step turns the wheel by 0.7° (a dragged radius is not jumpy)
            RADIUS: Step(2.0, 60.0, 0.05, 8.0, RADIUS),
            DRIVE: Step(-6000, 6000, 100, 0, DRIVE),
            FRICTION: Step(0.1, 1.2, 0.05, 0.9, FRICTION),
            # a short label (symbol and unit: the slider keeps its length), the meaning on hover
            EPS: Step(0.0, 1.0, 0.01, 0.45, "ε (× L)",
                      tip="centre of mass ε L behind the front axle, in wheelbases L: 0 on the front "
                          "axle, 1 on the rear axle (6.114)"),
            "radius of gyration (m)": Step(0.3, 3.0, 0.05, 1.2, "radius of gyration (m)"),
            "mass (kg)": Step(400, 3000, 50, 1200, "mass (kg)"),
            HEADING: Step(0.0, 360.0, 1.0, 0.0, HEADING,
                          tip="heading θ: how far the car has turned about the ICR, counter-clockwise; "
                              "at 0° the car points up the page (+y), at 90° to the left (−x). (Angles of "
                              "blows and forces in the other explorers start from +x instead.)"),
        }

    def _scene_of(self, values):
        """The scene ``"car"`` of the control values (the outlines are drawn by gallery Fig 6.6, not here)."""
        d = float(values[RADIUS])
        return self._scene(m=float(values["mass (kg)"]), rho=float(values["radius of gyration (m)"]), d=d,
                           eps=float(values[EPS]), omega=float(values[SPEED]) / d, F_A=float(values[DRIVE]),
                           outlines=False)

    def compute(self, values, changed):
        self.drag_or_fit()              # a slider, Play or reset: the view fits the state again
        d = float(values[RADIUS])
        V = float(values[SPEED])
        if d <= 0:
            raise SceneError(f"turn radius must be positive, got {d}")
        res = self._scene_of(values)
        ke = float(energy(res.model, [0.0], [V / d])[0])
        acc, limit = grip(res, float(values[FRICTION]))
        return {"res": res, "ke": ke, "acc": acc, "limit": limit, "slides": acc >= limit * (1 - 1e-9),
                "speed": values[SPEED], "heading": values[HEADING]}

    def play_step(self, values: dict, dt: float):
        # ω̇ (6.131) is constant: ω ← ω + ω̇ dt, θ ← θ + ω dt + ω̇ dt²/2, exact; the step ends at
        # the exact time the car stops or r_G √(ω⁴ + ω̇²) reaches μ·g (it slides out)
        res = self._scene_of(values)
        d = res.params["d"]
        w0 = res.params["omega"]
        wd = res.quantities["omega_dot"]
        acc, limit = grip(res, float(values[FRICTION]))
        if acc >= limit * (1 - 1e-12) or (w0 <= 0.0 and wd <= 0.0):
            return None                                  # sliding out, or stopped
        r_g = float(np.hypot(*res.extra["cg"]))
        tau = float(dt)
        if wd < 0.0:                                     # braking: stops at ω = 0
            tau = min(tau, -w0 / wd)
        w_lim2 = (limit / r_g) ** 2 - wd * wd            # ω² at which G reaches μ·g (ω̇ fixed)
        if wd > 0.0 and w_lim2 > 0.0:
            tau = min(tau, (math.sqrt(math.sqrt(w_lim2)) - w0) / wd)
        tau = max(tau, 0.0)
        w1 = max(w0 + wd * tau, 0.0)
        turn = w0 * tau + 0.5 * wd * tau * tau
        return {SPEED: w1 * d, HEADING: (float(values[HEADING]) + math.degrees(turn)) % 360.0}

    def _car_frame(self):
        """``(R, t, res)`` of the state shown: the drawing's placement (:func:`_moves`) and the scene."""
        res = self.state["res"]
        th = math.radians(float(self.shown_values.get(HEADING, self.values[HEADING])))
        R, t, _V, _W = moves(th, res.params["d"], self._shift(res.params["d"], th))
        return R, t, res

    def _shift(self, d, th):
        """How far the drawing is moved (m) so that a drag holds the rear tyre where it was drawn: the
        car is drawn turned by the heading about the ICR, which a drag of the radius moves."""
        if self._held_rear is None:
            return (0.0, 0.0)
        R, t, _V, _W = moves(th, d)
        return tuple(float(v) for v in self._held_rear - (R @ [d, 0.0] + t))

    def _to_scene(self, x, y):
        R, t, res = self._car_frame()
        return R.T @ (np.array([x, y], float) - t), res

    def _drawn(self, p):
        R, t, _res = self._car_frame()
        return tuple(float(c) for c in R @ np.asarray(p, float) + t)

    def handles(self) -> list:
        # G along the car (ε); the steering lever's end on the front axle line (d = L / tan δ); the ICR along the
        # rear axle line (d); the tip of the f_A arrow along the front wheel (F_A)
        return [Handle("centre of gravity", self._cg_where, self.holding(self._cg_drag)),
                Handle("steering", self._steer_where, self.holding(self._steer_drag)),
                Handle("ICR", self._icr_where, self.holding(self._icr_drag)),
                Handle("drive", self._drive_where, self.holding(self._drive_drag))]

    def _hold_view(self, state):
        super()._hold_view(state)
        self._held_rear = np.array(self._drawn(state["res"].extra["rear_contact"]))

    def _unhold_view(self):
        super()._unhold_view()
        self._held_rear = None

    def _cg_where(self):
        return self._drawn(self.state["res"].extra["cg"])

    def _cg_drag(self, x, y):
        p, res = self._to_scene(x, y)
        eps = 1.0 - float(p[1]) / res.params["L"]
        if not 0.0 <= eps <= 1.0:
            raise InputError(f"the centre of gravity must lie between the axles (ε from 0 to 1), "
                             f"the drag asks for ε = {eps:.3g}")
        return {EPS: eps}

    def _steer_where(self):
        return self._drawn(steer_lever(self.state["res"].extra))

    def _steer_drag(self, x, y):
        # the lever lies along the front axle line towards the ICR: at a steering angle δ (to the left)
        # it points along −(cos δ, sin δ) in the car's frame; the turn radius is L / tan δ (6.114),
        # held at the slider's ends (a drag beyond them holds there)
        R, t, res = self._car_frame()
        front = np.array(self._drawn(res.extra["front_contact"]))
        r = R.T @ (np.array([x, y], float) - front)          # along the front axle line, car frame
        delta = math.atan2(-r[1], -r[0])                      # steering angle, to the left
        if not 0.0 < delta < math.pi / 2:
            raise InputError(f"the steering angle must turn the car left, between 0 and 90°, got "
                             f"{math.degrees(delta):.3g}°: keep the lever's end left of the front wheel and "
                             f"behind it (straight ahead the ICR is at infinity)")
        w = self.controls[RADIUS]
        return {RADIUS: float(np.clip(res.params["L"] / math.tan(delta), w.min, w.max))}

    def _icr_where(self):
        return self._drawn((0.0, 0.0))

    def _icr_drag(self, x, y):
        R, t, res = self._car_frame()
        rear = np.array(self._drawn(res.extra["rear_contact"]))
        d = -float((np.array([x, y], float) - rear) @ (R @ [1.0, 0.0]))
        if d <= 0.0:
            raise InputError(f"the ICR must lie left of the rear tyre on its axle line (a left turn), "
                             f"the drag puts it {-d:.3g} m to its right")
        return {RADIUS: d}

    def _drive_where(self):
        res = self.state["res"]
        x = res.extra
        return self._drawn(x["front_contact"] + FORCE_SCALE * res.params["F_A"] * x["front_rolling"])

    def _drive_drag(self, x, y):
        p, res = self._to_scene(x, y)
        ex = res.extra
        return {DRIVE: float((p - ex["front_contact"]) @ ex["front_rolling"]) / FORCE_SCALE}

    def figure_message(self, exc: Exception) -> str:
        return textwrap.fill(super().figure_message(exc), 40)

    def view_of(self, st):
        """The explorer's own view ``(x0, x1, y0, y1)`` of the state ``st`` (m).

        Parameters
        ----------
        st : dict

        Returns
        -------
        tuple of float
        """
        p = st["res"].params
        return view_box(p["d"], p["L"], math.radians(float(st["heading"])), p["F_A"])

    _fitted_view = view_of                  # (HeldView)

    def scene_picture(self, state, view=None):
        th = math.radians(float(state["heading"]))
        return car_picture(state["res"], heading=th, view=view or self.held_view or self.view_of(state),
                           slides=state["slides"], limit=state["limit"], size=self.figure_px,
                           shift=self._shift(state["res"].params["d"], th))

    def readout_of(self, state):
        res = state["res"]
        q, x, p = res.quantities, res.extra, res.params
        mu = q["mu"]
        omega, wdot = p["omega"], q["omega_dot"]
        inertia_icr = p["m"] * (p["rho"] ** 2 + float(np.hypot(*x["cg"])) ** 2)
        power = float(q["f_A"][2]) * omega           # the drive's moment about the ICR times ω
        return {
            "speed V": state["speed"],
            "heading θ": state["heading"],
            "yaw rate ω": omega,
            "yaw acceleration ω̇": wdot,
            "rear tyre force μ₁": mu[0],
            "front tyre force μ₂": mu[1],
            "steering angle": math.degrees(x["steer"]),
            "lateral acceleration at G": omega ** 2 * float(np.hypot(*x["cg"])) / G_ROAD,
            "acceleration of G": state["acc"],
            "friction limit μ·g": state["limit"],
            "tyres": ("slide: the car slides out" if state["slides"]
                      else f"hold ({100 * state['acc'] / state['limit']:.0f}% of μ·g used)"),
            "kinetic energy K": state["ke"],
            "drive power": power,
            "rate of change of K": inertia_icr * omega * wdot,
        }

    def mechanism_points(self):
        # the car's corners, G, the steering and drive handles, and the ICR when NEAR
        if self.state is None:
            return np.zeros((0, 2))
        res = self.state["res"]
        d, L = res.params["d"], res.params["L"]
        body = [(d - HALF_TRACK, -OVERHANG), (d + HALF_TRACK, -OVERHANG), (d + HALF_TRACK, L + OVERHANG),
                (d - HALF_TRACK, L + OVERHANG)] + ([(0.0, 0.0)] if d <= NEAR else [])
        pts = [self._drawn(c) for c in body]
        pts += [self._cg_where(), self._steer_where(), self._drive_where()]
        return np.array(pts, dtype=float)
