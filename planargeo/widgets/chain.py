"""Chain explorer: an N-link planar chain with its geometric overlays (thesis ch. 4, 6, 7).

Controls set the number of links (1-20), the joint types (all revolute, all
prismatic, or alternating), the joint angles (first joint and a common bend
for the others), the joint speeds, a torque (on all joints, the first or the
last), and per joint (lists typed as ``30, -20, 10`` override those patterns joint by
joint), and
toggle overlays drawn with :mod:`planargeo.draw`:

* velocity poles ``v_i`` (points, 4.5) and acceleration poles ``a_i`` (4.6),
* bias terms: the bias accelerations ``κ_i`` (points) and bias forces ``p_i`` (lines),
* internal (joint) force lines ``f_i = A_i a_i + d_i`` (3.13),
* the per-joint T/U split: the force ``f_i = T_i Q_i + R_i μ_i`` (6.38, 6.104)
  into the active part along the percussion axis and the reaction through the
  joint, and the acceleration ``a_i = s_i ψ_i + U_i γ_i`` (6.44) into the
  part along the joint's motion space (``ψ_i = T_iᵀ a_i``, 6.100) and the
  reactive part (``γ_i = R_iᵀ a_i``, 6.101) in the quake space
  ``U_i = A_i⁻¹ R_i (R_iᵀ A_i⁻¹ R_i)⁻¹`` (6.45),
* the articulated inertias ``A_i`` (3.38) as conics.

The overlay checkboxes change the drawing only: toggling one re-renders the
last computed state (the split is derived from it once, when first shown).

Each state is solved once, by the articulated-body algorithm through the
scene (:func:`planargeo.scenes.chain.chain_workspace`: one kinematics pass);
the energies are read off that workspace.

*Simulate* integrates the motion ahead of time with
:func:`planargeo.simulate.simulate` (with a progress bar), then *play*
animates it; the readout shows the energy and its drift.  The trajectory
belongs to the shown state: a change of the initial state discards it (the
frame returns to 0), a refused change keeps it.
"""
from __future__ import annotations

import math

import ipywidgets as W
import numpy as np
from matplotlib.lines import Line2D

from planargeo.draw.artists import ConicArtist, LineArtist, PointArtist
from planargeo.draw.mechanism import draw_ground
from planargeo.draw.style import COLORS
from planargeo.errors import InputError, SingularConfigurationError
from planargeo.mechanics.model import Body, Joint, Model
from planargeo.mechanics.subspaces import T_of
from planargeo.scenes.chain import chain_workspace
from planargeo.simulate.integrate import energy
from planargeo.widgets.base import Explorer, Step

__all__ = ["ChainExplorer", "chain_for", "parse_list"]

NMAX = 20
OVERLAYS = ("velocity poles", "acceleration poles", "bias terms", "internal forces",
            "T/U split", "articulated inertias")
JOINT_SETS = ("revolute", "prismatic", "alternating")
TORQUE_ON = ("all joints", "first joint", "last joint")
#: controls that set the initial state (a change discards the simulated trajectory)
INITIAL = ("links", "joints", "angle", "bend", "slide", "speed", "torque", "torque on", "gravity",
           "joint values (deg / m)", "joint speeds", "joint torques")


def chain_for(n: int, joints: str = "revolute", gravity: bool = True, length: float = 1.0,
              mass: float = 1.0) -> Model:
    """The explorer's chain: ``n`` uniform slender links (mass ``mass``, length ``length``).

    ``joints`` is ``"revolute"``, ``"prismatic"`` or ``"alternating"``
    (revolute, prismatic, revolute...).  A prismatic joint slides along the
    parent link's axis.

    Examples
    --------
    >>> m = chain_for(3, "alternating")
    >>> [j.kind for j in m.joints], m.gravity
    (['revolute', 'prismatic', 'revolute'], (0.0, -9.81))
    """
    n = int(n)
    if not 1 <= n <= NMAX:
        raise InputError(f"n must be between 1 and {NMAX}, got {n}")
    if joints not in JOINT_SETS:
        raise InputError(f"joints must be one of {JOINT_SETS}, got {joints!r}")
    kinds = {"revolute": ["revolute"] * n, "prismatic": ["prismatic"] * n,
             "alternating": ["revolute" if i % 2 == 0 else "prismatic" for i in range(n)]}[joints]
    L, m = float(length), float(mass)
    bodies = [Body(m, (L / 2, 0.0), m * L * L / 12, name=f"link{i + 1}") for i in range(n)]
    js = [Joint(k, (0.0 if i == 0 else L, 0.0, 0.0), name=f"joint{i + 1}") for i, k in enumerate(kinds)]
    return Model(bodies, js, list(range(-1, n - 1)), (0.0, -9.81) if gravity else (0.0, 0.0))


def _list_text(description: str, placeholder: str) -> W.Text:
    return W.Text(value="", placeholder=placeholder, description=description,
                  continuous_update=False, style={"description_width": "initial"},
                  layout=W.Layout(width="310px"))


def parse_list(text: str, name: str) -> list[float]:
    """Numbers from ``"1, -2.5, 3"`` (empty text: no numbers); InputError naming ``name``.

    Examples
    --------
    >>> parse_list("30, -20,0.5", "joint values")
    [30.0, -20.0, 0.5]
    >>> parse_list("  ", "joint values")
    []
    """
    items = [t for t in text.replace(";", ",").split(",") if t.strip()]
    try:
        out = [float(t) for t in items]
    except ValueError:
        raise InputError(f"{name} must be numbers separated by commas, got {text!r}") from None
    if not all(math.isfinite(x) for x in out):
        raise InputError(f"{name} must be finite numbers, got {text!r}")
    return out


class ChainExplorer(Explorer):
    """Interactive N-link chain with velocity/acceleration poles, forces and inertias."""

    title = "Chain: poles, forces and articulated inertias"
    slug = "chain"
    figsize = (6.4, 5.6)
    limits = (-4.5, 4.5, -4.5, 4.5)
    grid = False
    display_controls = OVERLAYS

    def make_controls(self):
        c = {
            "links": Step(1, NMAX, 1, 4, "links", integer=True).make("links"),
            "joints": W.Dropdown(options=JOINT_SETS, value="revolute", description="joints"),
            "angle": Step(-180, 180, 1, -30, "angle (deg)").make("angle"),
            "bend": Step(-90, 90, 1, 20, "bend (deg)").make("bend"),
            "slide": Step(-0.5, 1.0, 0.05, 0.2, "slide (m)").make("slide"),
            "speed": Step(-5, 5, 0.1, 1.0, "speed").make("speed"),
            "torque": Step(-50, 50, 0.5, 0.0, "torque").make("torque"),
            "torque on": W.Dropdown(options=TORQUE_ON, value="all joints", description="torque on"),
            "gravity": W.Checkbox(value=True, description="gravity"),
            "joint values (deg / m)": _list_text("joint values (deg / m)", "e.g. 30, -20, 0.4"),
            "joint speeds": _list_text("joint speeds", "e.g. 1, 0, -2"),
            "joint torques": _list_text("joint torques", "e.g. 0, 5"),
        }
        for name in OVERLAYS:
            c[name] = W.Checkbox(value=name in ("velocity poles", "internal forces"), description=name,
                                 indent=False)
        c["frame"] = Step(0, 0, 1, 0, "frame", integer=True).make("frame")
        c["frame"].disabled = True
        return c

    def __init__(self, *, duration: float = 3.0, fps: int = 25, **kw):
        self.duration, self.fps = float(duration), int(fps)
        self._model_key = None
        self._model = None
        self._traj = None  # (t, q, qd, e0) of the shown state, computed by Simulate
        super().__init__(**kw)

    # -- widgets ---------------------------------------------------------------
    def extra_widgets(self):
        self.play_button = W.Button(description="Simulate", icon="play",
                                    tooltip="Integrate the motion from the current state, then animate it")
        self.progress = W.FloatProgress(value=0.0, min=0.0, max=1.0, description="",
                                        layout=W.Layout(width="150px"))
        self.player = W.Play(value=0, min=0, max=0, interval=int(1000 / self.fps), description="play")
        # a kernel-side link (not jslink): a frame the player shows is a frame the kernel drew,
        # and setting either from Python moves the other
        self._play_link = W.link((self.player, "value"), (self.controls["frame"], "value"))
        self.play_button.on_click(lambda _b: self.simulate())
        return [W.HBox([self.play_button, self.progress]), self.player]

    # -- figure ------------------------------------------------------------------
    def make_artists(self, ax):
        self.links_line = Line2D([], [], color=COLORS["ground"], lw=2.5, marker="o", ms=4,
                                 mfc="white", zorder=5)
        ax.add_line(self.links_line)
        draw_ground((0.0, 0.0), ax, width=0.8, zorder=4)
        z = np.array([0.0, 0.0, 1.0])
        zl = np.array([1.0, 0.0, 0.0])

        def pool(factory):
            out = [ax.add_artist(factory(i)) for i in range(NMAX)]
            for a in out:
                a.set_visible(False)
            return out

        self.v_art = pool(lambda i: PointArtist(z, role="twist", glyph_scale=4.0))
        self.a_art = pool(lambda i: PointArtist(z, role="accel", glyph_scale=1.0))
        self.kappa_art = pool(lambda i: PointArtist(z, role="accel", glyph=False, markersize=4,
                                                    color=COLORS["momentum"]))
        self.p_art = pool(lambda i: LineArtist(zl, role="momentum", scale=None, linewidth=1.0))
        self.f_art = pool(lambda i: LineArtist(zl, role="wrench", scale=0.02))
        self.t_art = pool(lambda i: LineArtist(zl, role="wrench", scale=None, linestyle=":",
                                               linewidth=1.2))
        self.r_art = pool(lambda i: LineArtist(zl, role="reaction", scale=0.02))
        # acceleration split (6.44): s ψ (along the joint) and U γ (reactive part)
        self.spsi_art = pool(lambda i: PointArtist(z, role="accel", glyph=False, markersize=5))
        self.ugam_art = pool(lambda i: PointArtist(z, role="accel", glyph=False, markersize=5,
                                                   color=COLORS["reaction"]))
        self.A_art = pool(lambda i: ConicArtist(np.eye(3), role="inertia", linewidth=0.8))
        self._scaled = set(self.f_art + self.r_art)
        self.time_text = ax.text(0.02, 0.97, "", transform=ax.transAxes, va="top", fontsize=9)

    # -- model / state -------------------------------------------------------------
    def model_for(self, v) -> Model:
        key = (v["links"], v["joints"], v["gravity"])
        if key != self._model_key:
            self._model = chain_for(*key)
            self._model_key = key
        return self._model

    def initial_state(self, v):
        model = self.model_for(v)
        q = np.empty(model.nq)
        for i, j in enumerate(model.joints):
            if j.kind == "revolute":
                q[i] = math.radians(v["angle"] if i == 0 else v["bend"])
            else:
                q[i] = v["slide"]
        qd = np.full(model.nq, float(v["speed"]))
        tau = np.zeros(model.nq)
        sel = {"all joints": slice(None), "first joint": slice(0, 1),
               "last joint": slice(model.nq - 1, None)}[v["torque on"]]
        tau[sel] = float(v["torque"])
        # per-joint values typed as lists override the patterns, joint by joint
        for i, x in enumerate(parse_list(v["joint values (deg / m)"], "joint values")[:model.nq]):
            q[i] = math.radians(x) if model.joints[i].kind == "revolute" else x
        for i, x in enumerate(parse_list(v["joint speeds"], "joint speeds")[:model.nq]):
            qd[i] = x
        for i, x in enumerate(parse_list(v["joint torques"], "joint torques")[:model.nq]):
            tau[i] = x
        return model, q, qd, tau

    def adjust(self, values, changed):
        """A new initial state starts at frame 0 (its trajectory is not simulated yet)."""
        return {"frame": 0} if changed & set(INITIAL) and values["frame"] != 0 else {}

    def compute(self, v, changed):
        traj = None if changed & set(INITIAL) else self._traj
        model, q, qd, tau = self.initial_state(v)
        t = 0.0
        frame = int(v["frame"])
        if traj is not None and 0 < frame < len(traj[0]):
            t, q, qd = traj[0][frame], traj[1][frame], traj[2][frame]
        w = chain_workspace(model, q, qd, tau)
        st = {"model": model, "w": w, "t": t, "tau": tau, "traj": traj}
        st["ke"], st["pe"] = (float(e) for e in energy(model, data=w))
        return st

    @staticmethod
    def tu_split(st) -> dict:
        """The per-joint T/U split of a computed state (derived once, kept in ``st``).

        Returns ``{"active": T Q, "reaction": R μ, "active_on": Q ≠ 0,
        "motion": s ψ, "reactive": U γ}`` (arrays of shape ``(N, 3)``): the
        force split 6.38 with ``Q = sᵀ f`` (6.49), ``R μ = f − T Q``, and the
        acceleration split 6.44 with ``ψ = Tᵀ a`` (6.100), ``U γ = a − s ψ``,
        ``T = A s (sᵀ A s)⁻¹`` (6.105) from each body's articulated inertia.
        """
        if "split" not in st:
            model, w = st["model"], st["w"]
            s = w.S.T.reshape(model.N, 3, 1)  # one-dof joints: column i is s_i
            T = T_of(w.A, s)[..., 0]
            Q = np.einsum("ij,ij->i", s[..., 0], w.f)
            active = T * Q[:, None]
            psi = np.einsum("ij,ij->i", T, w.a)
            motion = s[..., 0] * psi[:, None]
            st["split"] = {
                "active": active, "reaction": w.f - active,
                # an active part that is zero up to rounding (no joint torque) has no line to draw
                "active_on": np.abs(Q) > 1e-9 * np.maximum(1.0, np.abs(w.f).max(axis=1)),
                "motion": motion, "reactive": w.a - motion,
            }
        return st["split"]

    def render(self, st):
        model, w = st["model"], st["w"]
        n = model.N
        v = self.values
        split = self.tu_split(st) if v["T/U split"] else {}
        # links: joint origins then the tip
        ends = []
        for i in range(n):
            x, y, th = w.pose[i]
            ends.append((x + math.cos(th), y + math.sin(th)))
        chain = np.vstack([w.origin[:1]] + [np.vstack([w.pose[i, :2], ends[i]]) for i in range(n)])
        self.links_line.set_data(chain[:, 0], chain[:, 1])
        reach = n + 0.4
        if self.ax.get_xlim()[1] != reach:
            self.ax.set_xlim(-reach, reach)
            self.ax.set_ylim(-reach, reach)
        fscale = 0.5 / max(1.0, float(np.max(np.abs(w.f[:, :2]))))
        layers = [
            (self.v_art, "velocity poles", w.v, PointArtist.set_point),
            (self.a_art, "acceleration poles", w.a, PointArtist.set_point),
            (self.kappa_art, "bias terms", w.kappa, PointArtist.set_point),
            (self.p_art, "bias terms", w.p, LineArtist.set_line),
            (self.f_art, "internal forces", w.f, LineArtist.set_line),
            (self.t_art, "T/U split", split.get("active"), LineArtist.set_line),
            (self.r_art, "T/U split", split.get("reaction"), LineArtist.set_line),
            (self.spsi_art, "T/U split", split.get("motion"), PointArtist.set_point),
            (self.ugam_art, "T/U split", split.get("reactive"), PointArtist.set_point),
            (self.A_art, "articulated inertias", w.A, ConicArtist.set_conic),
        ]
        for arts, flag, arr, setter in layers:
            on = bool(v[flag]) and arr is not None
            for i, art in enumerate(arts):
                show = on and i < n
                if show:
                    setter(art, arr[i])
                    if isinstance(art, LineArtist) and art in self._scaled:
                        art.set_scale(fscale)
                    if arts is self.t_art:
                        show = bool(split["active_on"][i])
                if art.get_visible() != show:
                    art.set_visible(show)
        self._show_trajectory(st["traj"])
        self.time_text.set_text(f"t = {st['t']:.2f} s" if st["traj"] is not None else "")
        e = st["ke"] + st["pe"]
        out = {"links": n, "frame": int(v["frame"]), "t (s)": st["t"],
               "kinetic energy (J)": st["ke"], "potential energy (J)": st["pe"],
               "total energy (J)": e}
        if st["traj"] is not None:
            out["energy drift (J)"] = e - st["traj"][3]
        out["qdd[1]"] = float(w.qdd[0])
        out[f"qdd[{n}]"] = float(w.qdd[-1])
        out["|base force| (N)"] = float(np.hypot(*w.f[0, :2]))
        return out

    # -- simulation -----------------------------------------------------------------
    def _show_trajectory(self, traj) -> None:
        """Frame slider and player span the shown state's trajectory (none: frame 0 only)."""
        self._traj = traj
        last = 0 if traj is None else len(traj[0]) - 1
        fr = self.controls["frame"]
        if fr.max != last:
            fr.max = self.player.max = last
            fr.disabled = traj is None

    def simulate(self, duration: float | None = None) -> None:
        """Integrate from the current control state (progress bar), then enable the animation."""
        try:
            self._simulate(self.duration if duration is None else float(duration))
        except Exception as exc:  # noqa: BLE001 - a button callback must never raise
            self._set_message(f"simulation failed: {exc}")

    def _simulate(self, duration: float) -> None:
        model, q0, qd0, tau = self.initial_state(self.values)
        nframes = max(2, int(round(duration * self.fps)) + 1)
        times = np.linspace(0.0, duration, nframes)
        self.progress.value = 0.0
        t, q, qd = _integrate(model, q0, qd0, tau, times, progress=self._progress)
        self._traj = (t, q, qd, float(sum(energy(model, data=chain_workspace(model, q0, qd0, tau)))))
        self.progress.value = 1.0
        self._changed.add("frame")       # show the trajectory's range (the frame is unchanged)
        self._update()

    def _progress(self, frac: float) -> None:
        self.progress.value = float(frac)


def _integrate(model, q0, qd0, tau, times, progress=None, chunks: int = 10):
    """Integrate with :func:`planargeo.simulate.simulate` in ``chunks`` pieces (for the progress bar).

    ``times`` are equally spaced output frames starting at 0; returns
    ``(t, q, qd)`` sampled at them.
    """
    from planargeo.simulate.integrate import simulate

    n = len(times) - 1
    dt = float(times[1] - times[0])
    bounds = np.unique(np.linspace(0, n, min(chunks, n) + 1).round().astype(int))
    Q, QD = [np.array(q0, float)], [np.array(qd0, float)]
    for k0, k1 in zip(bounds[:-1], bounds[1:]):
        r = simulate(model, Q[-1], QD[-1], (k1 - k0) * dt, tau=tau, dt=dt, progress=False)
        if r.status != "ok":
            raise SingularConfigurationError(f"simulation stopped at t = {times[k0] + r.t[-1]:.3g} s: "
                                             f"{r.message}")
        Q.extend(r.q[1:k1 - k0 + 1])
        QD.extend(r.qd[1:k1 - k0 + 1])
        if progress is not None:
            progress(k1 / n)
    return np.asarray(times), np.asarray(Q), np.asarray(QD)
