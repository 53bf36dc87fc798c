"""Trees and loops explorer: the nine-link system of thesis Fig 9.1 / 9.2 and every force inside its loops.

Open, the nine links form a tree (Fig 9.1, 9.1-9.2); closed with pins between the tips of bodies
4 and 7 and of 8 and 9 (Fig 9.2), the constrained algorithm (9.4-9.5) adds the contact forces
``F₁``, ``F₂``.  Every pin force ``f₁ … f₉`` (9.61; 9.41 open) and contact force is drawn at its
joint; *focus* picks one.  *Play* advances the scene time
(:func:`planargeo.scenes.trees.tree_advance`), through the poses where a loop lies flat.
"""
from __future__ import annotations

import math
import time
from functools import partial

import ipywidgets as W
import numpy as np

from planargeo import scenes
from planargeo.draw.pictures._words import subscript
from planargeo.draw.pictures.trees import FORCE_LENGTH, symbol_of, trees_picture
from planargeo.errors import InputError, PlanargeoError
from planargeo.scenes.trees import (FIG91_ANGLES, tree_advance, tree_dof, tree_model, tree_pose, tree_reactions,
                                    tree_solve)
from planargeo.simulate.integrate import energy
from planargeo.widgets._explorer import (Described, HeldView, SceneTime, explorer_data, run_to, state_handle,
                                        time_text, time_value)
from planargeo.widgets._motion import Budget
from planargeo.widgets.base import Explorer, Step, Toggle, cached

__all__ = ["TreeExplorer"]

N = 9
#: the pins that close the loops (Fig 9.2), by the bodies whose tips they join
CONTACTS = ("4-7", "8-9")
#: the words of each body, pin and contact (``{i}``: its number, ``{s}``: in subscript digits)
_WORDS = explorer_data("trees")
#: controls that set the state at t = 0 (a change starts the time again)
INITIAL = ("speed", "loops", "gravity", "mass", "body 1 angle (deg)", "body 2 angle (deg)")
#: default gravity (m/s²) and speed (rad/s): the links coast, slowly enough for Play to keep up with
#: real time (under gravity a loop lies flat every fraction of a second: ten times the cost)
DEFAULT_G, DEFAULT_SPEED = 0.0, 0.25
#: relative tolerance of the Play integration (DOP853)
PLAY_RTOL = 1e-7
#: Play's frames per scene second at most: while Play runs, its times fall on the grid of 1/FRAME_RATE s
#: (the clock keeps the rest for the next frame, so the time scale stays true)
FRAME_RATE = 60
#: seconds between the checkpoints of a run (the state at t is integrated from the last one before t);
#: each checkpoint's step also gives the states on Play's grid within it (the integrator's dense output,
#: projected onto the loops), so a frame of Play integrates nothing
CHECKPOINT = 15 / FRAME_RATE
#: end of the time slider (s): Play runs a minute; the state at t costs an integration from 0 to t
T_END = 60.0
#: evaluations of the dynamics one update may spend (~1-2 ms each under load; the default spends about
#: 110 per scene second and ~800 per flat loop passed: one update reaches about 7 scene seconds, 2 under
#: gravity)
UPDATE_EVALS = 2_500
#: room (m) around the links in the view of a pose: the largest force's arrow and its label
ROOM = FORCE_LENGTH + 0.3
#: the step (m) the view of a pose is rounded out to
VIEW_STEP = 0.1


class TreeExplorer(HeldView, Described, SceneTime, Explorer):
    """The tree of Fig 9.1 and the constrained tree of Fig 9.2 with every pin and contact force, and Play.

    The view holds the pose the controls set (at ``t = 0``), with room for the forces; once Play
    has moved the links (``t > 0``, or while Play runs) it is :attr:`limits`, every pose the
    links can reach, so that the motion stays in view.  A drag holds the view it began in.

    Parameters
    ----------
    **kw
        Passed to :class:`~planargeo.widgets.base.Explorer`.

    Examples
    --------
    >>> ex = TreeExplorer(display="agg")
    >>> pic = ex.picture()
    >>> ex.readout_values["degrees of freedom"], sum(e["id"][0] in "fF" for e in pic["elements"])
    (5, 11)
    """

    title = "Trees and loops: Fig 9.2, its pin and contact forces"
    slug = "trees"
    figsize = (5.6, 5.6)
    limits = (-4.3, 4.3, -4.3, 4.3)
    display_controls = ("velocity poles", "acceleration poles", "reaction forces")
    initial, t_end = INITIAL, T_END

    def make_controls(self):
        return {
            "speed": Step(-3, 3, 0.05, DEFAULT_SPEED, "speed (rad/s)"),
            "loops": W.ToggleButtons(options=("closed (Fig 9.2)", "open (Fig 9.1)"), value="closed (Fig 9.2)",
                                     description="loops"),
            "gravity": Step(0, 20, 0.01, DEFAULT_G, "g (m/s²)"),
            "mass": Step(0.1, 5, 0.1, 1.0, "link mass (kg)"),
            "body 1 angle (deg)": Step(-180, 180, 1, FIG91_ANGLES[0], "body 1 angle (°)"),
            "body 2 angle (deg)": Step(-180, 360, 1, FIG91_ANGLES[1], "body 2 angle (°)"),
            "t (s)": self.time_control(),
            "velocity poles": Toggle(False, "velocity poles"),
            "acceleration poles": Toggle(False, "acceleration poles"),
            "reaction forces": Toggle(True, "pin and contact forces"),
        }

    def focus_options(self):
        loops = self.controls["loops"].value if "loops" in getattr(self, "controls", {}) else "closed"
        closed = str(loops).startswith("closed")
        return [symbol_of(f"f_{i + 1}") for i in range(N)] + (["F₁", "F₂"] if closed else [])

    def geometry(self, closed: bool):
        """Contacts, link length and degrees of freedom ``nq − rank J_c`` (9.54, 9.60) of a loop setting (cached).

        Parameters
        ----------
        closed : bool

        Returns
        -------
        tuple
            ``(contacts, length, dof)``.
        """
        def find():
            res = scenes.get("constrained-tree" if closed else "tree")(speed=1.0)
            q = np.array(res.state["q"], dtype=float)
            return tuple(res.model.contacts), float(res.params["length"]), tree_dof(res.model, q)

        return cached(self._cache("_geometry"), closed, find)

    def model_for(self, closed: bool, mass: float, g: float):
        """The nine-link model (with the pins when ``closed``), kept per (mass, g).

        Parameters
        ----------
        closed : bool
        mass, g : float
            Link mass (kg) and gravity (m/s²).

        Returns
        -------
        Model
        """
        def build():
            contacts, L, _dof = self.geometry(closed)
            return tree_model(mass, L, g, contacts)

        return cached(self._cache("_models"), (closed, mass, g), build)

    def handles(self):
        def near(deg, ref):      # turned by whole turns to lie nearest ref
            return deg + 360.0 * round((ref - deg) / 360.0)

        def current():           # the angles shown (Play moves them away from the controls)
            th = np.degrees(self.state["sol"].data.pose[:2, 2])
            return float(th[0]), float(th[1])

        def drag1(x, y):
            if math.hypot(x, y) < 1e-9:
                raise InputError("the tip of body 1 cannot be dragged onto its pivot: no angle there")
            a1, a2 = current()
            new = near(math.degrees(math.atan2(y, x)), a1)
            return {"body 1 angle (deg)": (new + 180.0) % 360.0 - 180.0, "body 2 angle (deg)": a2}

        def drag2(x, y):
            base = self.state["tips"][0]
            if math.hypot(x - base[0], y - base[1]) < 1e-9:
                raise InputError("the tip of body 2 cannot be dragged onto its joint: no angle there")
            a1, a2 = current()
            new = near(math.degrees(math.atan2(y - base[1], x - base[0])), a2)
            return {"body 1 angle (deg)": (a1 + 180.0) % 360.0 - 180.0, "body 2 angle (deg)": new}

        return [state_handle(self, "tip of body 1", lambda st: st["tips"][0], self.holding(drag1)),
                state_handle(self, "tip of body 2", lambda st: st["tips"][1], self.holding(drag2))]

    def mechanism_points(self):
        if self.state is None:
            return np.zeros((0, 2))
        return np.vstack([self.state["sol"].data.pose[:, :2], self.state["tips"]])

    # Play: SceneTime's t from 0 to T_END
    _play_carry = (None, 0.0)       # (the time Play showed last, the clock's seconds past it)

    def play_step(self, values, dt):
        # while Play runs, its time on the grid of FRAME_RATE (the states there are kept with the
        # checkpoints: a frame integrates nothing); the seconds past it are carried to the next step
        pc = self.play_control
        if pc is None or not pc.playing:
            return super().play_step(values, dt)
        text = values["t (s)"]
        held, carry = self._play_carry
        t = time_value(text, T_END) + (carry if held == text else 0.0) + float(dt)
        if t > T_END + 1e-9:
            return None
        j = min(math.floor(t * FRAME_RATE + 1e-9), int(T_END * FRAME_RATE))
        out = time_text(j / FRAME_RATE)
        self._play_carry = (out, t - j / FRAME_RATE)
        return {"t (s)": out}

    @staticmethod
    def _advance(model, budget, state, h, t0, every=None):
        """:func:`tree_advance` from ``state`` at ``t0`` over ``h``: its output, the events at their times."""
        try:
            out = tree_advance(model, *state, h, rtol=PLAY_RTOL, atol=PLAY_RTOL * 1e-2, every=every)
        except PlanargeoError as exc:
            raise PlanargeoError(f"the loops locked at t ≈ {t0:.2f} s: {exc}") from exc
        budget.charge(out["nfev"])
        out["events"] = [(t0 + float(e["t"]), e["kind"]) for e in out["events"]]
        return out

    @classmethod
    def _step(cls, model, budget, run, state, h, t0):
        """A step of a run (:func:`run_to`): ``(state, residual, events)``.

        From a checkpoint: its step to the next (kept in ``run["steps"]``, with the states on Play's
        grid within it); a time on that grid is read off it, any other time integrated from the checkpoint.
        """
        k = round(t0 / CHECKPOINT)
        if abs(t0 - k * CHECKPOINT) <= 1e-9 and h <= CHECKPOINT + 1e-9:
            steps = run.setdefault("steps", {})
            out = steps.get(k)
            if out is None:
                try:
                    out = cls._advance(model, budget, state, CHECKPOINT, t0, every=1.0 / FRAME_RATE)
                except PlanargeoError:
                    if h >= CHECKPOINT - 1e-9:
                        raise
                    out = None              # the loops lock later in this step: the time before, alone
                else:
                    steps[k] = out
            if out is not None:
                if h >= CHECKPOINT - 1e-9:
                    return (out["q"], out["qd"]), out["position_residual"], out["events"]
                j = round(h * FRAME_RATE)
                for ts, q, qd, drift in out["samples"]:
                    if abs(ts - h) <= 1e-9 and abs(h - j / FRAME_RATE) <= 1e-9:
                        return (q, qd), drift, [e for e in out["events"] if e[0] <= t0 + ts]
        out = cls._advance(model, budget, state, h, t0)
        return (out["q"], out["qd"]), out["position_residual"], out["events"]

    def _run_key(self, values):
        """``(closed, model, key)``: the run of ``values`` is ``_runs[key]``."""
        closed = values["loops"].startswith("closed")
        model = self.model_for(closed, float(values["mass"]), float(values["gravity"]))
        a1, a2 = float(values["body 1 angle (deg)"]), float(values["body 2 angle (deg)"])
        return closed, model, (closed, float(values["mass"]), float(values["gravity"]), float(values["speed"]), a1, a2)

    def play_ahead(self, values, seconds: float) -> bool:
        # a frame at t integrates from the last checkpoint before t; the checkpoints up to two
        # frames on are integrated here, while the page draws, one at a time for about `seconds`
        _closed, model, key = self._run_key(values)
        run = self._cache("_runs").get(key)
        if run is None:
            return False
        t = time_value(values["t (s)"], T_END)
        last = min(int(math.floor((t + 2.0 * self.play_dt) / CHECKPOINT + 1e-9)) + 1,
                   int(math.floor(T_END / CHECKPOINT + 1e-9)))
        end = time.perf_counter() + float(seconds)
        budget = Budget(UPDATE_EVALS)
        try:
            while len(run["ck"]) <= last:
                n = len(run["ck"])
                run_to(run, n * CHECKPOINT, CHECKPOINT, partial(self._step, model, budget, run), budget)
                if time.perf_counter() >= end:
                    break
        except PlanargeoError:           # the frame that reaches it says why
            return False
        return len(run["ck"]) <= last

    def view_of(self, state) -> tuple[float, float, float, float]:
        """The view of ``state``: its pose with room for the forces at ``t = 0``, else the reach.

        Parameters
        ----------
        state : dict
            A state of :meth:`compute`.

        Returns
        -------
        tuple
            ``(x0, x1, y0, y1)`` (m) of the plot area's shape; at ``t = 0`` its centre and sizes on
            :data:`VIEW_STEP`.
        """
        pc = getattr(self, "play_control", None)
        moving = (state["t"] > 0.0 or getattr(self, "_exporting", False)
                  or bool(pc is not None and pc.playing))
        if moving:
            return tuple(self.limits)
        pts = np.vstack([[[0.0, 0.0]], state["sol"].data.pose[:, :2], state["tips"]])
        lo, hi = pts.min(axis=0) - ROOM, pts.max(axis=0) + ROOM
        (w, h), (ml, mr, mt, mb) = self.figure_px, (6, 6, 6, 6)     # trees_picture's margins
        ratio = (h - mt - mb) / (w - ml - mr)
        c, half = (lo + hi) / 2, (hi - lo) / 2
        # the centre on the step, the half sizes out to it, then widened to the plot area's shape
        cr = np.round(c / VIEW_STEP) * VIEW_STEP
        half = np.ceil((half + np.abs(c - cr)) / VIEW_STEP - 1e-9) * VIEW_STEP
        half = np.maximum(half, [half[1] / ratio, half[0] * ratio])
        return tuple(round(float(v), 9) + 0.0 for v in (cr[0] - half[0], cr[0] + half[0], cr[1] - half[1],
                                                          cr[1] + half[1]))

    _fitted_view = view_of                  # (HeldView)

    def compute(self, values, changed):
        self.drag_or_fit()              # a control, Play or reset: the view fits the state again
        # one solve (9.5 or 9.39-9.43); the pose at t = 0 depends on the two angles alone
        closed, model, key = self._run_key(values)
        _c, L, dof = self.geometry(closed)
        a1, a2, speed = float(values["body 1 angle (deg)"]), float(values["body 2 angle (deg)"]), float(values["speed"])
        pose_key, poses = (closed, a1, a2), self._cache("_poses")     # q(0) and its speeds, kept
        pose = poses.get(pose_key) or tree_pose(model, math.radians(a1), 1.0, angle2=math.radians(a2))
        made = {"ck": [(pose[0], speed * pose[1])], "drift": [0.0], "events": []}
        run, t, (q, qd), drift, events = self.run_at(
            key, lambda: made, values["t (s)"],
            lambda budget: partial(self._step, model, budget, self._cache("_runs").get(key, made)),
            CHECKPOINT, UPDATE_EVALS)
        sol = tree_solve(model, q, qd)                               # 9.5 closed, 9.39-9.43 open
        E = float(sum(energy(model, data=sol.data)))
        if "E0" not in run:                                         # the energy at t = 0, once per run
            run["E0"] = E if t == 0.0 else float(sum(energy(model, *run["ck"][0])))
        E0 = run["E0"]
        pose_now = sol.data.pose
        tips = pose_now[:, :2] + L * np.column_stack([np.cos(pose_now[:, 2]), np.sin(pose_now[:, 2])])
        st = {"closed": closed, "model": model, "q": q, "qd": qd, "length": L, "dof": dof, "sol": sol,
              "a": sol.a.reshape(N, 3), "qdd": np.asarray(sol.qdd), "tips": tips, "t": t, "E": E, "E0": E0,
              "drift": drift, "events": list(events), "reactions": tree_reactions(model, sol), "speed": values["speed"]}
        if closed:
            st["F"] = sol.F.reshape(-1, 3)
            st["cond"] = float(sol.cond)
        cached(poses, pose_key, lambda: pose)          # the state is good: keep its pose
        return st

    def scene_picture(self, state, view=None):
        vals = self.values
        overlays = {k: bool(vals[k]) for k in ("reaction forces", "velocity poles", "acceleration poles")}
        contacts = [c.name for c in state["model"].contacts] if state["closed"] else []
        return trees_picture(state["sol"].data.pose, state["tips"], reactions=state["reactions"], contacts=contacts,
                             v=state["sol"].data.v, a=state["a"], overlays=overlays, focus=vals.get("focus", "all"),
                             view=view or self.held_view or self.view_of(state), size=self.figure_px)

    def readout_of(self, state):
        closed, model = state["closed"], state["model"]
        focus = self.values.get("focus", "all")
        reactions = {symbol_of(x.symbol): x for x in state["reactions"]}
        force = {k: float(np.hypot(x.wrench[0], x.wrench[1])) for k, x in reactions.items()}
        E0 = state["E0"]
        out = {"t": state["t"], "speed": state["speed"], "loops": "closed" if closed else "open",
               "degrees of freedom": state["dof"], "energy E": state["E"],
               "energy drift ΔE/E₀": (state["E"] - E0) / abs(E0) if E0 else 0.0,
               "closure drift |φ|": state["drift"]}
        if closed:
            for k, c in enumerate(model.contacts):
                out[f"|F{subscript(k + 1)}| (pin {c.name})"] = force[symbol_of(f"F_{k + 1}")]
            out["condition number"] = state["cond"]
        out["largest pin force"] = max(force[symbol_of(f"f_{i + 1}")] for i in range(N))
        if focus in reactions:
            x = reactions[focus]
            out["focus"] = focus
            out[f"|{focus}|"] = force[focus]
            out[f"moment of {focus} about its pin"] = x.moment
        qdd = state["qdd"]
        out["q̈₁ (body 1)"] = qdd[0]
        out["largest |q̈ᵢ|"] = float(np.max(np.abs(qdd)))
        ev = state["events"]
        out["singular poses"] = (f"{len(ev)}, the last at t = {ev[-1][0]:.2f} s" if ev else "none yet")
        self.units = dict(self.units)
        for k in out:
            if k.startswith("|") or k == "largest pin force":
                self.units[k] = "N"
            elif k.startswith("moment of"):
                self.units[k] = "N·m"
        return out

    def explain(self):
        out = super().explain()
        nine = [{"i": i, "s": subscript(i)} for i in range(1, N + 1)]                # bodies or pins
        contacts = [{"i": k, "s": subscript(k), "name": name} for k, name in enumerate(CONTACTS, start=1)]
        for part, each in (("bodies", nine), ("pins", nine), ("contacts", contacts), ("pin_forces", nine),
                           ("contact_forces", contacts)):
            for words in each:
                out.update({key.format(**words): m.format(**words) for key, m in _WORDS[part].items()})
        return out
