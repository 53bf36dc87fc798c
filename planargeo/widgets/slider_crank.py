"""Slider-crank explorer: a closed kinematic loop and every force inside it (thesis 9.3-9.6, 9.61, Fig 9.3).

The crank angle ``ψ`` and speed ``ψ̇`` at ``t = 0`` set the motion; the constrained algorithm
(:func:`planargeo.scenes.slider_crank.slider_crank_solve`) gives the closed-loop accelerations and
every pin and bearing force of the loop (9.61, 9.71), drawn as lines of action.  *Play* advances
the scene time in slow motion, free or with the crank driven; the readout names the dead centres
passed.
"""
from __future__ import annotations

import math
from functools import partial

import ipywidgets as W
import numpy as np

from planargeo import scenes
from planargeo.draw.pictures.slider_crank import slider_crank_picture, slider_crank_view
from planargeo.errors import InputError, PlanargeoError, SceneError
from planargeo.scenes.slider_crank import (DEAD_CENTRE_TOL, dead_centre_at, slider_crank_advance,
                                           slider_crank_model, slider_crank_reactions, slider_crank_solve)
from planargeo.simulate.integrate import energy
from planargeo.widgets._explorer import SceneTime, explorer_data, state_handle
from planargeo.widgets.base import Explorer, Step, Toggle, cached

__all__ = ["SliderCrankExplorer"]

#: controls that set the state at t = 0 (a change starts the time again)
INITIAL = ("crank angle (deg)", "crank speed", "drive", "rod length", "gravity")
#: scene seconds between the checkpoints of a run
CHECKPOINT = 0.02
#: end of the time slider (scene seconds; about 1800 dynamics evaluations per scene second)
T_END = 10.0
#: evaluations of the loop's dynamics one update may spend (~0.8 ms each: the chain explorer's
#: MAX_EVALS in the same seconds; about 2.4 scene seconds of the default crank)
UPDATE_EVALS = 6_000
#: its symbols and readout rows, kept as data: ``symbol = meaning``, ``row = [unit, meaning]``
_WORDS = explorer_data("slider-crank")["explain"]


def wrap_message(text: str, width: int = 38) -> str:
    """``text`` broken into lines of at most ``width`` characters (a refusal inside the picture).

    Examples
    --------
    >>> print(wrap_message("singular configuration: the rod lies along the horizontal"))
    singular configuration: the rod lies
    along the horizontal
    """
    import textwrap

    return "\n".join(textwrap.wrap(text, width)) or text


def wrapped_degrees(rad: float) -> float:
    """The angle ``rad`` (radians) in degrees, wrapped to (−180°, 180°] (a joint angle as read).

    Examples
    --------
    >>> [round(wrapped_degrees(math.radians(a)), 6) for a in (-387.4, -180.0, 180.0, 190.0, 23.0)]
    [-27.4, 180.0, 180.0, -170.0, 23.0]
    """
    return 180.0 - (180.0 - math.degrees(rad)) % 360.0


class SliderCrankExplorer(SceneTime, Explorer):
    """Slider-crank of thesis 9.6: every pin and bearing force (9.61), Play through ``simulate_loops``.

    Parameters
    ----------
    **kw
        Passed to :class:`~planargeo.widgets.base.Explorer`.

    Raises
    ------
    InputError
        An unknown control or a bad initial value.
    PlanargeoError
        The initial values describe a configuration that cannot be assembled.

    Examples
    --------
    >>> ex = SliderCrankExplorer(display="agg")
    >>> round(ex.readout_values["piston height h"], 3), ex.units["piston height h"]
    (5.929, 'm')
    >>> _ = ex.advance(3)                                 # three Play frames of the free crank
    >>> abs(ex.readout_values["energy drift ΔE/E₀"]) < 1e-6
    True
    """

    title = "Slider-crank: a closed loop and its pin and bearing forces"
    slug = "slider-crank"
    figsize = (5.6, 6.2)
    display_controls = ("reaction forces", "velocity poles", "acceleration poles")
    initial, t_end = INITIAL, T_END
    #: scene seconds per second of Play at speed 1× (slow motion: the crank turns at ~20 rad/s)
    time_scale = 0.1
    #: relative tolerance of the Play integration (DOP853; energy drift ~1e-6 per crank turn)
    play_rtol = 1e-7
    #: readout units, from its words (``[explorer."slider-crank".explain]``)
    units = {k: m[0] for k, m in _WORDS.items() if isinstance(m, list)}

    def __init__(self, **kw):
        p = scenes.parameters("slider-crank")     # the thesis 9.6 masses and lengths
        self.params = {k: p[k] for k in ("m1", "m2", "m3", "r", "t")}
        self.scale = float(p["l"])
        super().__init__(**kw)

    def model_for(self, l: float, g: float):
        """The slider-crank model for rod length ``l`` and gravity ``g`` (kept per pair).

        Parameters
        ----------
        l, g : float
            Rod length (m) and gravity (m/s²).

        Returns
        -------
        Model
        """
        return cached(self._cache("_models"), (l, g), lambda: slider_crank_model(l=l, g=g, **self.params))

    def make_controls(self):
        return {
            # short labels (symbol and unit: the slider keeps its length), the meaning on hover
            "crank angle (deg)": Step(-180, 180, 1, 23.0, "ψ₀ (°)",
                                      tip="crank angle ψ₀ at t = 0 (°): where Play starts"),
            "crank speed": Step(-100, 100, 0.5, 20.0, "ψ̇₀ (rad/s)", tip="crank speed ψ̇₀ at t = 0 (rad/s)"),
            "t (s)": self.time_control(),
            "drive": W.ToggleButtons(options=("free", "constant-speed"), value="free", description="crank"),
            "rod length": Step(1.0, 8.0, 0.01, 5.0, "rod length l (m)"),
            "gravity": Step(0.0, 20.0, 0.01, 9.81, "g (m/s²)"),
            "reaction forces": Toggle(True, "pin and bearing forces"),
            "velocity poles": Toggle(False, "velocity poles"),
            "acceleration poles": Toggle(False, "acceleration poles"),
        }

    def handles(self):
        # the crank pin sets ψ; the piston sets its height, the crank keeps its side
        def drag_pin(x, y):
            if math.hypot(x, y) < 1e-9:
                raise InputError("the crank pin cannot be dragged onto the crank pivot: no crank angle there")
            return {"crank angle (deg)": math.degrees(math.atan2(y, x))}

        def drag_piston(x, y):
            r, l = self.params["r"], float(self.values["rod length"])
            if abs(y) < 1e-9:
                raise SceneError("the wrist pin cannot be on the crank pivot's level here (the rod would lie "
                                 "along the slide's normal)")
            # crank pin p on |p| = r and |p - (0, y)| = l
            py = (r * r - l * l + y * y) / (2 * y)
            if abs(py) > r:
                raise SceneError(f"the piston cannot reach height {y:.4g} m: the wrist pin must stay between "
                                 f"{abs(l - r):.4g} and {l + r:.4g} m from the crank pivot")
            side = 1.0 if math.cos(float(self.state["q"][0])) >= 0 else -1.0    # the crank as shown
            px = side * math.sqrt(max(r * r - py * py, 0.0))
            return {"crank angle (deg)": math.degrees(math.atan2(py, px))}

        return [state_handle(self, "crank pin", lambda st: st["sol"].data.pose[1, :2], drag_pin),
                state_handle(self, "piston", lambda st: st["sol"].data.pose[2, :2], drag_piston)]

    def _step(self, model, l, drive, budget, state, h, t0):
        """A step of a run (:func:`run_to`): ``(state, residual, dead centres passed)``."""
        psi, psidot = state
        try:
            out = slider_crank_advance(model, psi, psidot, h, self.params["r"], l, drive, rtol=self.play_rtol,
                                       atol=self.play_rtol * 1e-2)
        except PlanargeoError as exc:     # its times are the step's own: say where the step began
            exc.args = (f"the motion stopped in its step from t = {t0:.4g} s (computed up to there, kept): "
                        f"{exc}",)
            raise
        budget.charge(out["nfev"])
        turn = out["psi"] - psi
        passed = [(t0 + (h * (a - psi) / turn if turn else 0.0), name) for name, a in out["dead_centres"]]
        return (out["psi"], out["psidot"]), out["position_residual"], passed

    def compute(self, values, changed):
        # the state at t of the run from the initial crank state, the loop closed (9.5, 9.61)
        psi0, speed = math.radians(values["crank angle (deg)"]), float(values["crank speed"])
        l, g = float(values["rod length"]), float(values["gravity"])
        r, thick = self.params["r"], self.params["t"]
        model = self.model_for(l, g)
        drive = values["drive"]
        first = None

        def start():
            nonlocal first
            first = slider_crank_solve(model, psi0, speed, r, l, thick, drive)
            return {"ck": [(psi0, speed)], "drift": [0.0], "events": [],
                    "E0": float(sum(energy(model, data=first[2].data)))}

        run, t, (psi, psidot), drift, passed = self.run_at(
            (psi0, speed, drive, l, g), start, values["t (s)"],
            lambda budget: partial(self._step, model, l, drive, budget), CHECKPOINT, UPDATE_EVALS)
        if first is not None and (psi, psidot) == run["ck"][0]:    # at the start (a drag): solved above
            q, qd, sol, h = first
        else:
            q, qd, sol, h = slider_crank_solve(model, psi, psidot, r, l, thick, drive)
        E = float(sum(energy(model, data=sol.data)))
        st = {"sol": sol, "reactions": slider_crank_reactions(sol), "q": q, "qd": qd, "r": r, "l": l, "t": thick,
              "h": h, "v": sol.data.v, "a": sol.a.reshape(3, 3), "F3": np.asarray(sol.F, dtype=float), "E": E,
              "message": "", "drive": drive, "time": t, "E0": run["E0"], "drift": drift, "passed": passed}
        # ψ as read: at t = 0 the slider's ψ₀ itself (its −180° is not turned into 180°), then in (−180°, 180°]
        st["psi_deg"] = float(values["crank angle (deg)"]) if t == 0.0 else wrapped_degrees(psi)
        name = dead_centre_at(psi, DEAD_CENTRE_TOL)
        st["configuration"] = name
        if name and t == 0.0:
            st["message"] = f"dead centre ({name}): a force on the piston cannot turn the crank here"
        return st

    @staticmethod
    def _banner(st) -> str:
        """The dead centre named on the picture: passing one now, or at one ("" between them)."""
        passed, now = st["passed"], st["time"]
        recent = bool(passed) and now - passed[-1][0] < 0.02
        conf = st["configuration"]
        return f"passing {passed[-1][1]}" if recent else (f"at {conf}" if conf else "")

    def scene_picture(self, state, view=None):
        vals = self.values
        overlays = {k: bool(vals[k]) for k in ("reaction forces", "velocity poles", "acceleration poles")}
        return slider_crank_picture(state["sol"].data.pose, r=state["r"], t=state["t"], q=state["q"], reactions=state["reactions"],
                                    v=state["v"], a=state["a"], h=state["h"], overlays=overlays,
                                    view=view or slider_crank_view(state["r"], state["l"], state["t"]),
                                    banner=self._banner(state), psi=state["psi_deg"], size=self.figure_px)

    def readout_of(self, state):
        sol = state["sol"]
        vel, acc = state["v"], state["a"]
        reactions = state["reactions"]
        force = {k: float(np.hypot(x.wrench[0], x.wrench[1])) for k, x in reactions.items()}
        passed, now = state["passed"], state["time"]
        conf = state["configuration"]
        qq, qdd = state["q"], sol.qdd
        E0 = state["E0"]
        driven = state["drive"] == "constant-speed"
        drift = (state["E"] - E0) / abs(E0) if E0 else 0.0
        out = {
            "t": now, "crank angle ψ": state["psi_deg"],
            "crank speed ψ̇": state["qd"][0], "rod joint angle θ": wrapped_degrees(qq[1]),
            "wrist joint angle φ": wrapped_degrees(qq[2]),
            "piston height h": state["h"], "piston speed": vel[2][1], "piston acceleration": acc[2][1],
            "ψ̈ crank": qdd[0],
            "|f₁| crank pivot": force["f_1"], "|f₂| crank pin": force["f_2"],
            "|f₃| wrist pin": force["f_3"], "|F₃| slider bearing": force["F_1"],
            "bearing couple": reactions["F_1"].moment, "drive torque Q₁": sol.tau_drive[0],
            "energy E": state["E"],
            "energy drift ΔE/E₀": drift if not driven else "none stated: the drive does work",
            "closure drift": state["drift"],
            "configuration": conf or "between dead centres",
            "last dead centre passed": (f"{passed[-1][1]} at t = {passed[-1][0]:.3f} s" if passed else "none yet"),
        }
        return out

    def explain(self):
        # every symbol and readout row, in the order of the data
        return {k: m[1] if isinstance(m, list) else m for k, m in _WORDS.items()}

    def figure_message(self, exc):
        text = str(exc)
        short = next((s for key, s in _SHORT if key in text), None)
        return wrap_message(short or super().figure_message(exc))


#: the short text drawn for a refused state, by a part of its message (the first that matches)
_SHORT = (("rod too short", "rod too short: it cannot reach the slider at this crank angle"),
          ("cannot reach height", "the piston cannot reach that height"),
          ("piston pin on the crank pivot",
           "singular configuration: folded dead centre, the piston pin is on the crank pivot"),
          ("singular", "singular configuration: the rod lies along the horizontal"))
