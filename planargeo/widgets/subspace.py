"""Subspace decomposition explorer: one body, one joint, one force (thesis ch. 6, figures 6.1–6.5).

A body at rest held by a joint and loaded by a force ``f``: the spaces ``s, R, T, U``, the splits
``f = T Q + R μ`` and ``I⁻¹f = s ψ + U γ``, ``sᵀIs`` and the power relations as residuals that
read 0 (:func:`planargeo.scenes.subspace.subspace_state`).

Examples
--------
>>> from planargeo.widgets import SubspaceExplorer
>>> ex = SubspaceExplorer(display="agg")
>>> ex.readout_values["Q = sᵀf"]                   # the moment of f about the pivot, 1 N × 1.6 m
1.6
>>> ex.set(joint="plane joint (4.79)").readout_values["U (meet of T₁, T₂)"]   # the centre of mass
(1.0, 0.0)
"""
from __future__ import annotations

import ipywidgets as W
import numpy as np

from planargeo.draw.pictures.subspace import BAR, COM, DIR_HANDLE, subspace_picture
from planargeo.scenes.subspace import subspace_state, unit_direction
from planargeo.screws.twists import inertia_matrix
from planargeo.geometry.projective import is_at_infinity, is_ideal
from planargeo.widgets.readout import point_value
from planargeo.widgets._explorer import arrow_handle, explorer_data, grown_view, shown, xy_handle
from planargeo.widgets.base import Explorer, Step

__all__ = ["SubspaceExplorer", "JOINT_OPTIONS", "SHOW_OPTIONS"]

#: The joint dropdown: shown name -> the package's joint kind (4.79's plane joint is ``twin_prismatic``).
JOINT_OPTIONS = {"revolute": "revolute", "prismatic": "prismatic",
                 "revolute + prismatic": "revolute_prismatic", "plane joint (4.79)": "twin_prismatic"}
_LABEL = {k: lab for lab, k in JOINT_OPTIONS.items()}
#: The "show" buttons: shown name -> what is drawn.
SHOW_OPTIONS = {"f = TQ + Rμ": "wrench", "I⁻¹f = sψ + Uγ": "twist", "s, R, T, U": "spaces"}
#: data length of the force arrow per newton (the force tip handle)
ARROW = 0.5
_SUB = "₁₂"

#: the heading row above the identity checks
CHECKS_HEADING = "identity checks of s, R, T, U (each reads 0)"
#: residual of the scene -> (readout row, unit, why it must read 0), kept as data
CHECK_ROWS = {k: tuple(v) for k, v in explorer_data("subspace")["checks"].items()}


class SubspaceExplorer(Explorer):
    """Subspaces ``s, R, T, U`` of one joint and the splits of one force (thesis 6.1–6.4, 6.63–6.97).
    """

    title = "Subspaces of a joint: s, R, T, U and the splits of a force (thesis 6.1–6.4)"
    slug = "subspace"
    figsize = (6.2, 5.0)          # beside the controls in JupyterLab with its file browser open
    limits = (-1.5, 3.5, -2.0, 2.0)
    display_controls = ()   # "show" recomputes (cheap): the generic test flips display controls as sliders

    def make_controls(self):
        return {
            "joint": W.Dropdown(options=list(JOINT_OPTIONS), value="revolute", description="joint"),
            "joint x": Step(-1.4, 3.4, 0.01, 0.0, "joint x (m)"),
            "joint y": Step(-1.9, 1.9, 0.01, 0.0, "joint y (m)"),
            "joint angle": Step(-180, 180, 1.0, 0.0, "joint angle (deg)"),
            "force x": Step(-1.4, 3.4, 0.01, 1.6, "force point x (m)"),
            "force y": Step(-1.9, 1.9, 0.01, 0.0, "force point y (m)"),
            "force angle": Step(-180, 180, 1.0, 90.0, "force angle (deg)"),
            "F": Step(-4.0, 4.0, 0.05, 1.0, "force F (N)"),
            "m": Step(0.2, 10.0, 0.1, 2.0, "mass m (kg)"),
            "rho": Step(0.05, 1.5, 0.01, 0.5, "ρ (m)", tip="radius of gyration ρ of the body (m)"),
            "show": W.ToggleButtons(options=list(SHOW_OPTIONS), value="f = TQ + Rμ", description="show",
                                    style={"button_width": "auto"}),
        }

    def disabled(self, values):
        if JOINT_OPTIONS[values["joint"]] == "revolute":
            return {"joint angle": "a revolute joint has no direction: only its pivot counts"}
        return {}

    def explain(self):
        st = self.state
        k = 1 if st is None else int(st["s"].shape[1])
        out = dict(explorer_data("subspace")["symbols"])
        sub = (lambda i: _SUB[i]) if k > 1 else (lambda i: "")
        rsub = (lambda j: _SUB[j]) if 3 - k > 1 else (lambda j: "")
        for i in range(k):
            out[f"Q{sub(i)} = s{sub(i)}ᵀf"] = "joint force: the power of f on the allowed motion (6.51)"
            out[f"ψ{sub(i)} = T{sub(i)}ᵀI⁻¹f"] = "joint acceleration of the held body (6.57)"
        for j in range(3 - k):
            out[f"μ{rsub(j)} = U{rsub(j)}ᵀf"] = "reaction: how much of f the joint takes (6.54)"
            out[f"γ{rsub(j)} = R{rsub(j)}ᵀI⁻¹f"] = "reactive acceleration component (6.60)"
        for i in range(2):
            out[f"s{_SUB[i]}"] = f"the {('first', 'second')[i]} allowed motion of a 2-dof joint (6.8)"
            out[f"R{_SUB[i]}"] = f"the {('first', 'second')[i]} reaction of a 1-dof joint (6.10)"
            out[f"T{_SUB[i]}"] = f"the axis of percussion of s{_SUB[i]} (6.36)"
            out[f"U{_SUB[i]}"] = f"the reactive acceleration of R{_SUB[i]} (6.37)"
        for row, _unit, why in CHECK_ROWS.values():
            out[row] = why
        return out

    def handles(self):
        slides = lambda: JOINT_OPTIONS[shown(self)["joint"]] != "revolute"
        return [xy_handle(self, "joint", "joint x", "joint y"),
                arrow_handle(self, "joint direction", "joint x", "joint y", "joint angle", arm=DIR_HANDLE,
                             when=slides),
                xy_handle(self, "force point", "force x", "force y"),
                arrow_handle(self, "force tip", "force x", "force y", "force angle", "F", per=ARROW / 2)]

    def compute(self, values, changed):
        m, rho = float(values["m"]), float(values["rho"])
        I = inertia_matrix(m, COM, m * rho * rho)
        e = float(values["F"]) * unit_direction(values["force angle"])
        a = (float(values["force x"]), float(values["force y"]))
        f = np.array([e[0], e[1], a[0] * e[1] - a[1] * e[0]])
        st = subspace_state(JOINT_OPTIONS[values["joint"]], (values["joint x"], values["joint y"]), unit_direction(values["joint angle"]), I, f)
        st["point"], st["direction"], st["force point"] = (np.array([values["joint x"], values["joint y"]]),
                                                           unit_direction(values["joint angle"]), np.array(a))
        return st

    def scene_picture(self, state, view=None):
        v = self.values
        return subspace_picture(state, show=SHOW_OPTIONS[v["show"]], m=float(v["m"]), rho=float(v["rho"]),
                                view=view or self._view(), size=self.figure_px)

    def mechanism_points(self):
        return np.vstack([super().mechanism_points(), BAR])

    def _view(self) -> tuple[float, float, float, float]:
        """The default limits grown to hold every handle with 0.3 m round them (the values alone decide it)."""
        return grown_view(self.limits, super().mechanism_points(), 0.3)

    def readout_of(self, state):
        st, k = state, int(state["s"].shape[1])
        s, R, sIs, reaction = st["s"], st["R"], st["sIs"], st["reaction"]
        rows = [("joint", _LABEL[st["joint"]], None), ("k (degrees of freedom)", k, "—")]
        for i in range(k):
            # a joint force and acceleration: of a translation (s ideal) or of a rotation
            fu, au = ("N", "m/s²") if bool(is_ideal(s[:, i])) else ("N·m", "rad/s²")
            sub = _SUB[i] if k > 1 else ""
            rows += [(f"Q{sub} = s{sub}ᵀf", float(st["Q"][i]), fu), (f"ψ{sub} = T{sub}ᵀI⁻¹f", float(st["psi"][i]), au)]
        for j in range(3 - k):
            # a reaction and reactive acceleration: of a couple (R at infinity) or of a force
            fu, au = ("N·m", "rad/s²") if bool(is_at_infinity(R[:, j])) else ("N", "m/s²")
            sub = _SUB[j] if 3 - k > 1 else ""
            rows += [(f"μ{sub} = U{sub}ᵀf", float(st["mu"][j]), fu), (f"γ{sub} = R{sub}ᵀI⁻¹f", float(st["gamma"][j]), au)]
        rot = [not bool(is_ideal(s[:, i])) for i in range(k)]   # sᵀIs: kg·m² rotation–rotation, kg·m mixed, else kg
        units = tuple({2: "kg·m²", 1: "kg·m", 0: "kg"}[rot[i] + rot[j]] for i in range(k) for j in range(k))
        rows += [("sᵀIs (6.67)", float(sIs[0, 0]) if k == 1 else tuple(float(x) for x in np.ravel(sIs)),
                  units[0] if k == 1 else units),
                 ("pole of sψ (held body)", point_value(st["s_psi"]) if np.any(st["s_psi"] != 0) else "at rest", "m"),
                 ("joint's push −Rμ, |force|", float(np.hypot(reaction[0], reaction[1])), "N")]
        if k == 2:
            rows.append(("U (meet of T₁, T₂)", point_value(st["U"][:, 0]), "m"))
        rows.append((CHECKS_HEADING, "", "—"))        # a heading: no value
        rows += [(CHECK_ROWS[name][0], val, CHECK_ROWS[name][1]) for name, val in st["residuals"].items()]
        self.units = {key: unit for key, _v, unit in rows if unit is not None}
        return {key: v for key, v, _u in rows}
