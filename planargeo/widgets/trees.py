"""Trees and loops explorer: the nine-link system of thesis Fig 9.1 / 9.2.

Open the two loops and the nine links form a tree (Fig 9.1, solved in stacked
form, 9.1-9.2); close them with pins between the tips of bodies 4 and 7 and
of bodies 8 and 9 (Fig 9.2) and the constrained algorithm (9.4-9.5) adds the
contact forces, drawn as lines through the pins.  Controls: joint speed
scale, gravity, link mass, loops open or closed, and the pole overlays.

The explorer computes only what it draws: the pose, the unit speed pattern
(projected onto the velocities the loops allow) and the degrees of freedom
come from one build of the scene per loop setting, the model is kept per mass
and gravity, and a change of speed runs a single solve through the scene
(:func:`planargeo.scenes.trees.tree_solve`: ``stacked_solve`` for
the open tree, ``loop_solve`` for the loops), never the scene's cross-check by
the direct solution 9.48.  The overlay checkboxes only redraw.
"""
from __future__ import annotations

import ipywidgets as W
import numpy as np
from matplotlib.lines import Line2D

from planargeo import scenes
from planargeo.scenes.trees import tree_dof, tree_model, tree_solve
from planargeo.draw.artists import LineArtist, PointArtist
from planargeo.draw.mechanism import draw_ground
from planargeo.draw.style import COLORS
from planargeo.widgets.base import Explorer, Step, cached

__all__ = ["TreeExplorer"]

N = 9


class TreeExplorer(Explorer):
    """The tree of Fig 9.1 and the constrained tree of Fig 9.2 with its contact forces."""

    title = "Trees and loops: Fig 9.2 and its contact forces"
    slug = "trees"
    figsize = (5.6, 5.6)
    limits = (-2.8, 2.8, -0.6, 5.0)
    display_controls = ("velocity poles", "acceleration poles", "contact forces")

    def __init__(self, **kw):
        self._geometry: dict = {}   # closed -> (contacts, q, unit speed pattern, length, dof)
        self._models: dict = {}     # (closed, mass, g) -> Model
        super().__init__(**kw)

    def make_controls(self):
        return {
            "speed": Step(-3, 3, 0.05, 1.0, "speed").make("speed"),
            "loops": W.ToggleButtons(options=("closed (Fig 9.2)", "open (Fig 9.1)"),
                                     value="closed (Fig 9.2)", description="loops"),
            "gravity": Step(0, 20, 0.1, 9.81, "g").make("gravity"),
            "mass": Step(0.1, 5, 0.1, 1.0, "link mass").make("mass"),
            "velocity poles": W.Checkbox(value=False, description="velocity poles", indent=False),
            "acceleration poles": W.Checkbox(value=False, description="acceleration poles",
                                             indent=False),
            "contact forces": W.Checkbox(value=True, description="contact forces", indent=False),
        }

    def make_artists(self, ax):
        self.links = Line2D([], [], color=COLORS["ground"], lw=2.5, solid_capstyle="round", zorder=5)
        self.joints = Line2D([], [], ls="none", marker="o", ms=4, mfc="white", mec="black", zorder=6)
        self.pins = Line2D([], [], ls="none", marker="o", ms=8, mfc="none", mec=COLORS["reaction"],
                           mew=2, zorder=6)
        for a in (self.links, self.joints, self.pins):
            ax.add_line(a)
        draw_ground((0.0, 0.0), ax, width=0.9, zorder=1)
        self.labels = [ax.text(0, 0, str(i + 1), fontsize=7, color="#404040", zorder=7)
                       for i in range(N)]
        z = np.array([0.0, 0.0, 1.0])
        self.v_art = [ax.add_artist(PointArtist(z, role="twist", glyph_scale=3.0)) for _ in range(N)]
        self.a_art = [ax.add_artist(PointArtist(z, role="accel", glyph_scale=0.3)) for _ in range(N)]
        self.F_art = [ax.add_artist(LineArtist([1.0, 0, 0], role="reaction", scale=0.15,
                                               text=f"F{k + 1}")) for k in range(2)]

    def geometry(self, closed: bool):
        """Contacts, pose ``q``, unit speed pattern, link length and degrees of freedom (cached).

        Taken once from the scene (``speed = 1``): the pattern projected onto the
        loops' allowed velocities is linear in the speed.  The degrees of freedom
        are ``nq − rank J_c`` with the closure Jacobian ``J_c`` (9.54, 9.60).
        """
        if closed not in self._geometry:
            res = scenes.get("constrained-tree" if closed else "tree")(speed=1.0)
            model = res.model
            q = np.array(res.state["q"], dtype=float)
            self._geometry[closed] = (tuple(model.contacts), q, np.array(res.state["qd"], dtype=float),
                                      float(res.params["length"]), tree_dof(model, q))
        return self._geometry[closed]

    def model_for(self, closed: bool, mass: float, g: float):
        """The nine-link model (with the pins when ``closed``), kept per (mass, g)."""
        def build():
            contacts, _q, _u, L, _dof = self.geometry(closed)
            return tree_model(mass, L, g, contacts)

        return cached(self._models, (closed, mass, g), build)

    def compute(self, v, changed):
        closed = v["loops"].startswith("closed")
        model = self.model_for(closed, float(v["mass"]), float(v["gravity"]))
        _c, q, unit, L, dof = self.geometry(closed)
        qd = float(v["speed"]) * unit
        sol = tree_solve(model, q, qd)                               # 9.5 closed, 9.39-9.43 open
        st = {"closed": closed, "model": model, "q": q, "qd": qd, "length": L, "dof": dof, "sol": sol,
              "a": sol.a.reshape(N, 3), "qdd": np.asarray(sol.qdd)}
        if closed:
            st["F"] = sol.F.reshape(-1, 3)
            st["cond"] = float(sol.cond)
        return st

    def render(self, st):
        closed, model = st["closed"], st["model"]
        d = st["sol"].data
        L = st["length"]
        pose = d.pose
        tips = pose[:, :2] + L * np.column_stack([np.cos(pose[:, 2]), np.sin(pose[:, 2])])
        xs, ys = [], []
        for i in range(N):
            xs += [pose[i, 0], tips[i, 0], np.nan]
            ys += [pose[i, 1], tips[i, 1], np.nan]
        self.links.set_data(xs, ys)
        self.joints.set_data(pose[:, 0], pose[:, 1])
        for i, t in enumerate(self.labels):
            mid = 0.5 * (pose[i, :2] + tips[i])
            t.set_position((mid[0] + 0.05, mid[1] + 0.05))
        vals = self.values
        a = st["a"]
        for i in range(N):
            self.v_art[i].set_visible(bool(vals["velocity poles"]))
            self.v_art[i].set_point(d.v[i])
            self.a_art[i].set_visible(bool(vals["acceleration poles"]))
            self.a_art[i].set_point(a[i])
        out = {"speed": vals["speed"], "loops": "closed" if closed else "open",
               "degrees of freedom": st["dof"]}
        if closed:
            F = st["F"]
            pins = []
            for k, c in enumerate(model.contacts):
                p = tips[c.a]
                pins.append(p)
                self.F_art[k].set_line(F[k])
                self.F_art[k].set_anchor(p)
                self.F_art[k].set_visible(bool(vals["contact forces"]) and bool(np.any(F[k])))
                out[f"contact {c.name}: |force| (N)"] = float(np.hypot(F[k, 0], F[k, 1]))
            pins = np.array(pins)
            self.pins.set_data(pins[:, 0], pins[:, 1])
            out["condition number"] = st["cond"]
        else:
            for art in self.F_art:
                art.set_visible(False)
            self.pins.set_data([], [])
        qdd = st["qdd"]
        out["qdd[1] (root)"] = qdd[0]
        out["max |qdd|"] = float(np.max(np.abs(qdd)))
        return out
