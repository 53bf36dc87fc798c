"""Chain explorer: an N-link planar chain with its geometric overlays (thesis ch. 4, 6, 7).

Controls set the links (1-20), joint kinds, angles, speeds, a torque and the base; typed lists
(``30, -20, 10``) override them joint by joint.  Overlays: velocity and acceleration poles
(4.5, 4.6), bias terms, joint force lines (3.13), the per-joint T/U split of force and
acceleration (6.38, 6.44, 6.45) and the articulated inertias (3.38) as conics; *focus* picks
one link or joint.  Drag a link's end to set its joint, the base to move the chain.  The
``time (s)`` slider and Play show the motion from the state the controls set, integrated once
per initial state in chunks of :data:`CHUNK` s (the state at ``t`` depends on ``t`` alone).
"""
from __future__ import annotations

import math

import ipywidgets as W
import numpy as np

from planargeo.draw.chain import chain_picture
from planargeo.draw.pictures._words import subscript
from planargeo.errors import InputError, SizeLimitError
from planargeo.mechanics.model import Body, Joint, Model
from planargeo.mechanics.subspaces import T_of
from planargeo.scenes.chain import chain_workspace
from planargeo.simulate.integrate import energy
from planargeo.widgets._explorer import Described, explorer_data, state_handle, time_step, xy_handle
from planargeo.widgets._motion import Motion, refusal_on_picture
from planargeo.widgets.base import Explorer, Step, Toggle, cached
from planargeo.widgets.play import check_duration

__all__ = ["ChainExplorer", "chain_for", "parse_list"]

NMAX = 20
OVERLAYS = ("velocity poles", "acceleration poles", "bias terms", "internal forces",
            "T/U split", "articulated inertias")
JOINT_SETS = ("revolute", "prismatic", "alternating")
TORQUE_ON = ("all joints", "first joint", "last joint")
LIST_Q = "joint values (deg / m)"
#: controls that set the initial state (a change starts the motion again at t = 0)
INITIAL = ("links", "joints", "angle", "bend", "slide", "speed", "torque", "torque on", "gravity",
           "base x (m)", "base y (m)", LIST_Q, "joint speeds", "joint torques")
#: the time control
TIME = "time (s)"
#: seconds of motion integrated per chunk (the state at t is read from its chunk's interpolant)
CHUNK = 1.0
#: longest time range an explorer takes (its ``duration``, s)
DURATION_MAX = 3600.0
#: largest magnitude of a typed joint speed (rad/s or m/s) and of a typed joint force (N·m or N)
SPEED_LIMIT = 100.0
TORQUE_LIMIT = 1e4
#: largest magnitude of a typed revolute joint angle (deg)
ANGLE_LIMIT = 3600.0
#: slide range of a prismatic joint (m), the slide slider's
SLIDE = (-0.5, 1.0)
#: unit of a joint's acceleration by joint kind
QDD_UNIT = {"revolute": "rad/s²", "prismatic": "m/s²"}
#: how a symbol of each link or joint is named in the figure (``{i}``: 1 … n, ``{s}``: in subscript digits)
_IN_FIGURE = explorer_data("chain")["in_figure"]
#: the rows of the first and last joints (``{kind}``, ``{unit}``: the joint's own)
_EACH_JOINT = explorer_data("chain")["each_joint"]


def chain_for(n: int, joints: str = "revolute", gravity: bool = True, length: float = 1.0,
              mass: float = 1.0, base=(0.0, 0.0)) -> Model:
    """The explorer's chain: ``n`` uniform slender links (mass ``mass``, length ``length``).

    Parameters
    ----------
    n : int
        Number of links, 1 to 20.
    joints : {"revolute", "prismatic", "alternating"}
        Joint kinds; a prismatic joint slides along the parent link's axis.
    gravity : bool
        Gravity ``(0, -9.81)`` or none.
    length, mass : float
        Length (m) and mass (kg) of every link.
    base : (float, float)
        Position of the first joint (m).

    Returns
    -------
    Model
        The chain, its first joint at ``base`` on the ground.

    Raises
    ------
    InputError
        ``n`` out of range or an unknown joint set.

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
    bx, by = (float(v) for v in base)
    bodies = [Body(m, (L / 2, 0.0), m * L * L / 12, name=f"link{i + 1}") for i in range(n)]
    js = [Joint(k, (bx, by, 0.0) if i == 0 else (L, 0.0, 0.0), name=f"joint{i + 1}")
          for i, k in enumerate(kinds)]
    return Model(bodies, js, list(range(-1, n - 1)), (0.0, -9.81) if gravity else (0.0, 0.0))


def _list_text(description: str, placeholder: str) -> W.Text:
    return W.Text(value="", placeholder=placeholder, description=description,
                  continuous_update=False, style={"description_width": "initial"},
                  layout=W.Layout(width="310px"))


def parse_list(text: str, name: str) -> list[float]:
    """Numbers from ``"1, -2.5, 3"`` (empty text: no numbers).

    Parameters
    ----------
    text : str
        Numbers separated by commas or semicolons.
    name : str
        What the list is (named in the error).

    Returns
    -------
    list of float

    Raises
    ------
    InputError
        A part is not a finite number: the message names the list
        and quotes the text.

    Examples
    --------
    >>> parse_list("30, -20,0.5", "joint values")
    [30.0, -20.0, 0.5]
    """
    items = [t for t in text.replace(";", ",").split(",") if t.strip()]
    try:
        out = [float(t) for t in items]
    except ValueError:
        raise InputError(f"{name} must be numbers separated by commas, got {text!r}") from None
    if not all(math.isfinite(x) for x in out):
        raise InputError(f"{name} must be finite numbers, got {text!r}")
    return out


def _check_typed(field: str, i: int, x: float, limit: float, unit: str) -> None:
    """Refuse a typed per-joint number beyond ``limit`` in magnitude, naming the field, joint and limit."""
    if not abs(x) <= limit:
        raise InputError(f"{field}: joint {i + 1} takes at most {limit:g}{unit} in magnitude, got {x:g}")


def _count(n: int) -> str:
    """``"1 value"``, ``"4 values"``."""
    return f"{n} value" if n == 1 else f"{n} values"


def _kinds(n: int, joints: str) -> list[str]:
    """The joint kinds of a chain of ``n`` links with ``joints`` (a :data:`JOINT_SETS` option)."""
    return ["revolute" if joints == "revolute" or (joints == "alternating" and i % 2 == 0) else "prismatic"
            for i in range(n)]


#: the sliders that set each kind of joint when no value is typed
_SET_BY = {"revolute": "the angle and bend sliders", "prismatic": "the slide slider",
           "alternating": "the angle, bend and slide sliders"}


def _num(x: float, decimals: int = 2) -> str:
    """A list entry as a student types it: to ``decimals`` places (a drag sets the value so rounded).

    >>> _num(49.13529911), _num(-0.0001), _num(0.6999999, 3)
    ('49.14', '0', '0.7')
    """
    return f"{round(float(x), decimals) + 0.0:g}"


class ChainExplorer(Described, Explorer):
    """Interactive N-link chain with velocity/acceleration poles, forces and inertias.

    Parameters
    ----------
    duration : float
        Range of the ``time (s)`` slider (s), at most :data:`DURATION_MAX`.
    fps : int
        Frames per second of Play, 1 to 100.
    **kw
        :class:`~planargeo.widgets.base.Explorer` options and initial control values.

    Raises
    ------
    InputError
        An unknown control or a value it does not take; a duration or fps out of range.
    """

    title = "Chain: poles, forces and articulated inertias"
    slug = "chain"
    figsize = (6.2, 5.4)          # beside the controls in JupyterLab with its file browser open
    limits = (-4.5, 4.5, -4.5, 4.5)
    grid = False
    display_controls = OVERLAYS
    scale = 1.0

    def make_controls(self):
        c = {
            "links": Step(1, NMAX, 1, 4, "links", integer=True),
            "joints": W.Dropdown(options=JOINT_SETS, value="revolute", description="joints"),
            "angle": Step(-180, 180, 1, -30, "angle (deg)"),
            "bend": Step(-90, 90, 1, 20, "bend (deg)"),
            "slide": Step(*SLIDE, 0.05, 0.2, "slide (m)"),
            "speed": Step(-5, 5, 0.1, 1.0, "speed (rad/s, m/s)"),
            "torque": Step(-50, 50, 0.5, 0.0, "torque (N·m, N)"),
            "torque on": W.Dropdown(options=TORQUE_ON, value="all joints", description="torque on"),
            "gravity": W.Checkbox(value=True, description="gravity"),
            "base x (m)": Step(-3, 3, 0.1, 0.0, "base x (m)"),
            "base y (m)": Step(-3, 3, 0.1, 0.0, "base y (m)"),
            LIST_Q: _list_text(LIST_Q, "one per joint, e.g. 30, -20, 10, -10"),
            "joint speeds": _list_text("joint speeds", "e.g. 1, 0, -2"),
            "joint torques": _list_text("joint torques", "e.g. 0, 5"),
        }
        for name in OVERLAYS:
            c[name] = Toggle(name in ("velocity poles", "internal forces"), name)
        c[TIME] = Step(0.0, self.duration, 0.01, 0.0, "time t (s)")
        return c

    def __init__(self, *, duration: float = 60.0, fps: int = 25, **kw):
        d = float(duration) if isinstance(duration, (int, float)) and not isinstance(duration, bool) \
            else math.nan
        if not 0.0 < d <= DURATION_MAX:
            raise InputError(f"duration must be a number of seconds above 0 and at most {DURATION_MAX:g}, "
                             f"got {duration!r}")
        if isinstance(fps, bool) or not isinstance(fps, int) or not 1 <= fps <= 100:
            raise InputError(f"fps must be an integer from 1 to 100, got {fps!r}")
        self.duration, self.fps = d, int(fps)
        self.play_fps = self.fps             # Play at 1×: a frame of 1 / fps s per tick
        self._model_key = None
        self._model = None
        super().__init__(**kw)

    @property
    def player(self):
        """The time slider (what Play moves)."""
        return self.controls[TIME]

    # -- model / state -------------------------------------------------------------
    def _model_for(self, v) -> Model:
        """The chain of the control values ``v`` (kept while they do not change)."""
        key = (v["links"], v["joints"], v["gravity"], v["base x (m)"], v["base y (m)"])
        if key != self._model_key:
            self._model = chain_for(*key[:3], base=key[3:])
            self._model_key = key
        return self._model

    def initial_state(self, v):
        """``(model, q, qd, tau)`` the control values ``v`` describe (lists override patterns).

        Parameters
        ----------
        v : dict
            The control values.

        Returns
        -------
        tuple

        Raises
        ------
        InputError
            A per-joint list that is not a list of numbers.
        """
        model = self._model_for(v)
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
        # per-joint values typed as lists override the patterns: the joint values one per joint
        # (a links change pads or cuts them, see adjust), speeds and forces the first joints'
        typed_q = parse_list(v[LIST_Q], "joint values")
        for i, x in enumerate(typed_q[:model.nq]):
            if model.joints[i].kind == "revolute":
                _check_typed(LIST_Q, i, x, ANGLE_LIMIT, "°")
                q[i] = math.radians(x)
            else:
                if not SLIDE[0] <= x <= SLIDE[1]:
                    raise InputError(f"{LIST_Q}: joint {i + 1} (prismatic) slides between {SLIDE[0]:g} and "
                                     f"{SLIDE[1]:g} m, got {x:g}")
                q[i] = x
        if typed_q and len(typed_q) != model.nq:
            raise InputError(f"{LIST_Q} needs {_count(model.nq)}, one per joint, got {_count(len(typed_q))}: "
                             f"type {model.nq} numbers, or empty the box to set the joints by the sliders")
        for field, typed, limit, units in (("joint speeds", qd, SPEED_LIMIT, (" rad/s", " m/s")),
                                           ("joint torques", tau, TORQUE_LIMIT, (" N·m", " N"))):
            said = parse_list(v[field], field)
            for i, x in enumerate(said[:model.nq]):
                _check_typed(field, i, x, limit, units[model.joints[i].kind != "revolute"])
                typed[i] = x
            if len(said) > model.nq:
                raise InputError(f"{field} takes at most {_count(model.nq)}, one per joint, got "
                                 f"{_count(len(said))} (the joints not typed take the slider's value)")
        return model, q, qd, tau

    def adjust(self, values, changed):
        # a new initial state starts at t = 0; with a typed list, "angle" still moves joint 1 and
        # "bend" / "slide" empty the list, so that no slider is ever dead
        out = {}
        self._note = ""
        if changed & set(INITIAL) and TIME not in changed and values[TIME] != 0:
            out[TIME] = 0.0
        was = self.shown_values if self.state is not None else None
        if was and "joints" in changed and values["joints"] != was.get("joints"):
            # another joint type: typed values of the old kinds (degrees or metres, rad/s or m/s,
            # N·m or N) mean nothing now; the joints start from the type's sliders, said in a note
            cleared = [f for f in (LIST_Q, "joint speeds", "joint torques")
                       if values[f].strip() and f not in changed]
            out.update({f: "" for f in cleared})
            values = {**values, **out}
            if cleared:
                words = {LIST_Q: "joint values", "joint speeds": "joint speeds",
                         "joint torques": "joint torques"}
                said = [words[f] for f in cleared]
                said = said[0] if len(said) == 1 else ", ".join(said[:-1]) + " and " + said[-1]
                self._note = (f"joints are now {values['joints']}: the typed {said} were for the old "
                              f"joints and are cleared; the joints start from {_SET_BY[values['joints']]}")
        elif was and "links" in changed and int(values["links"]) != int(was.get("links", 0)):
            n = int(values["links"])
            kinds = _kinds(n, values["joints"])
            for f in (LIST_Q, "joint speeds", "joint torques"):
                if f in changed or not values[f].strip():
                    continue
                items = [t.strip() for t in values[f].replace(";", ",").split(",") if t.strip()]
                if f == LIST_Q:    # one per joint: a new joint takes its slider's value
                    items += [_num(values["bend"]) if k == "revolute" else _num(values["slide"], 3)
                              for k in kinds[len(items):]]
                if len(items) > n or f == LIST_Q:
                    out[f] = ", ".join(items[:n])
            values = {**values, **out}
        text = values[LIST_Q]
        if text.strip() and LIST_Q not in changed:
            if changed & {"bend", "slide"}:
                out[LIST_Q] = ""
            elif "angle" in changed and values["joints"] != "prismatic":
                items = [t.strip() for t in text.replace(";", ",").split(",") if t.strip()]
                items[0] = _num(values["angle"])
                out[LIST_Q] = ", ".join(items)
        return out

    def motion_for(self, model, q0, qd0, tau) -> Motion:
        """The motion from ``(q0, qd0)`` under the constant joint forces ``tau`` (kept per initial state).

        Parameters
        ----------
        model : Model
        q0, qd0, tau : ndarray

        Returns
        -------
        Motion
        """
        from planargeo.scenes.chain import chain_accelerations as forward_dynamics

        n = model.nq
        key = (self._model_key, tuple(q0), tuple(qd0), tuple(tau))

        def rhs(_t, y):
            return np.concatenate([y[n:], forward_dynamics(model, y[:n], y[n:], tau)])

        return cached(self._cache("_motions"), key,
                      lambda: Motion(rhs, np.concatenate([q0, qd0]), CHUNK, rtol=1e-8, atol=1e-10))

    def play_ahead(self, values, seconds: float) -> bool:
        # the motion one chunk past the time shown, by the same steps
        model, q0, qd0, tau = self.initial_state(values)
        return self.motion_for(model, q0, qd0, tau).work_ahead(float(values[TIME]) + CHUNK, seconds)

    def compute(self, values, changed):
        model, q0, qd0, tau = self.initial_state(values)
        t = float(values[TIME])
        q, qd = q0, qd0
        if t > 0.0:
            y = self.motion_for(model, q0, qd0, tau).at(t)
            q, qd = y[:model.nq], y[model.nq:]
        w = chain_workspace(model, q, qd, tau)
        st = {"model": model, "w": w, "t": t, "tau": tau, "q0": q0,
              "message": getattr(self, "_note", "")}      # a joint type's note (not a refusal)
        st["ke"], st["pe"] = (float(e) for e in energy(model, data=w))
        # the starting energy, kept per starting state: a frame at t > 0 costs one kinematics pass
        e0s, key = self._cache("_e0s"), (self._model_key, tuple(q0), tuple(qd0))
        if t == 0.0:
            e0s.pop(key, None)
        st["e0"] = cached(e0s, key, lambda: st["ke"] + st["pe"] if t == 0.0
                          else float(sum(energy(model, q0, qd0))))
        return st

    @staticmethod
    def tu_split(st) -> dict:
        """The per-joint T/U split of a computed state (derived once, kept in ``st``).

        The force split 6.38 with ``Q = sᵀ f`` (6.49), ``R μ = f − T Q``, and
        the acceleration split 6.44 with ``ψ = Tᵀ a`` (6.100), ``U γ = a − s ψ``,
        ``T = A s (sᵀ A s)⁻¹`` (6.105) from each body's articulated inertia.

        Parameters
        ----------
        st : dict
            A state of :meth:`compute`.

        Returns
        -------
        dict
            ``active`` (T Q), ``reaction`` (R μ), ``motion`` (s ψ), ``reactive`` (U γ): ``(N, 3)``;
            ``active_on`` (Q ≠ 0): ``(N,)``.
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

    def figure_message(self, exc: Exception) -> str:
        # a time too far in its short form (the picture wraps it within the figure)
        return refusal_on_picture(str(exc)) or super().figure_message(exc)

    # -- focus, handles, play ------------------------------------------------------
    def focus_options(self) -> list[str]:
        # before the first state every link of the longest chain (a focus given with "links")
        w = getattr(self, "controls", {}).get("links")
        n = NMAX if w is None or getattr(self, "state", None) is None else int(w.value)
        return [f"link {i}" for i in range(1, n + 1)] + [f"joint {i}" for i in range(1, n + 1)]

    def disabled(self, values: dict) -> dict:
        n = int(values["links"])
        kind = _kinds(n, values["joints"])

        def typed(name):
            try:
                return len(parse_list(values[name], name))
            except InputError:
                return 0

        out = {}
        if "prismatic" not in kind:
            out["slide"] = "only prismatic joints slide: every joint is revolute (choose prismatic or alternating)"
        if kind[0] != "revolute":
            out["angle"] = "the first joint is prismatic: it has no angle (its slide is set by 'slide')"
        if "revolute" not in kind[1:]:
            out["bend"] = ("'bend' sets the revolute joints after the first: this chain has none "
                           "(add links or choose revolute or alternating)")
        if typed("joint speeds") >= n:
            out["speed"] = "every joint's speed is typed in 'joint speeds' (empty it to use the slider)"
        if typed("joint torques") >= n:
            out["torque"] = "every joint's force is typed in 'joint torques' (empty it to use the slider)"
            out["torque on"] = out["torque"]
        elif float(values["torque"]) == 0.0:
            out["torque on"] = "the torque is 0: there is nothing to put on the joints"
        elif n == 1:
            out["torque on"] = "one link: its joint is the first, the last and all joints"
        return out

    def explain(self) -> dict:
        st = getattr(self, "state", None)
        n = st["model"].N if st is not None else int(self.values["links"])
        # the meanings depend on the links and the first and last joints' kinds alone: kept for them
        key = (n, None if st is None else (st["model"].joints[0].kind, st["model"].joints[n - 1].kind))
        last = getattr(self, "_explained", None)
        if last is not None and last[0] == key:
            return dict(last[1])

        subs = [(i, subscript(i)) for i in range(1, n + 1)]

        def here(form):
            return "; in the figure: " + ", ".join([form.format(i=i, s=s) for i, s in subs])

        out = {k: m + here(_IN_FIGURE[k]) if k in _IN_FIGURE else m for k, m in self.symbols.items()}
        out.update(self.meanings)
        if st is not None:
            for k in sorted({0, n - 1}):
                j = st["model"].joints[k].kind
                words = {"i": k + 1, "s": subscript(k + 1), "kind": j, "unit": QDD_UNIT[j]}
                out.update({row.format(**words): m.format(**words) for row, m in _EACH_JOINT.items()})
        self._explained = (key, out)
        return dict(out)

    def _focus(self, n: int):
        """``("link" | "joint", index)`` of the focus, or None (all; or beyond the chain)."""
        focus = self.controls.get("focus")
        name = "all" if focus is None else str(focus.value)
        for kind in ("link", "joint"):
            if name.startswith(kind + " ") and name[len(kind) + 1:].isdigit():
                i = int(name[len(kind) + 1:]) - 1
                return (kind, i) if 0 <= i < n else None
        return None

    def _state_ends(self, st) -> np.ndarray:
        """The links' far ends of a computed state (kept in it: every handle and the picture ask)."""
        if "ends" not in st:
            st["ends"] = self._ends(st["w"])
        return st["ends"]

    def _ends(self, w) -> np.ndarray:
        """World positions of the links' far ends (N, 2)."""
        return w.pose[:, :2] + np.column_stack([np.cos(w.pose[:, 2]), np.sin(w.pose[:, 2])])

    def handles(self) -> list:
        # the base, and each link's end: it sets its joint (angle or slide), keeping the others;
        # they read the shown state when asked, so they are made once (every update lists them)
        made = self.__dict__.get("_handles_made")
        if made is not None:
            return list(made)

        def end(i):
            def at(st):
                ends = self._state_ends(st)
                return tuple(float(c) for c in ends[i]) if i < st["model"].N else None
            return at

        self._handles_made = [xy_handle(self, "base", "base x (m)", "base y (m)")] + [
            state_handle(self, f"link {i + 1} end", end(i), self._end_drag(i)) for i in range(NMAX)]
        return list(self._handles_made)

    def _end_drag(self, i: int):
        def drag(x: float, y: float) -> dict:
            st = self.state
            model, w = st["model"], st["w"]
            if i >= model.N:
                raise InputError(f"link {i + 1} is not in a chain of {model.N} links")
            px, py, th = (float(c) for c in w.pose[i])
            q = [float(c) for c in w.q]
            if model.joints[i].kind == "revolute":
                dx, dy = float(x) - px, float(y) - py
                if math.hypot(dx, dy) < 1e-9:
                    raise InputError(f"link {i + 1}'s end cannot be dragged onto joint {i + 1} "
                                     "(no direction for the link)")
                parent = th - q[i]
                new = math.atan2(dy, dx) - parent
                new = math.atan2(math.sin(new), math.cos(new))        # (-π, π]
                if i == 0 and not self.values[LIST_Q].strip() and not self.values[TIME]:
                    return {"angle": math.degrees(new)}
                q[i] = new
            else:
                e = np.array([math.cos(th), math.sin(th)])              # slides along the parent's axis
                foot = np.array([px, py]) - q[i] * e
                s = float((np.array([x, y], float) - e - foot) @ e)
                if not SLIDE[0] <= s <= SLIDE[1]:
                    raise InputError(f"joint {i + 1} slides between {SLIDE[0]:g} and {SLIDE[1]:g} m, "
                                     f"the drag asks for {s:.3g} m")
                q[i] = s
            # to 0.01° and 1 mm: the state is the one the list says (a fresh explorer shows it)
            return {LIST_Q: ", ".join(_num(math.degrees(v)) if j.kind == "revolute" else _num(v, 3)
                                      for v, j in zip(q, model.joints))}
        return drag

    def play_step(self, values: dict, dt: float):
        # the state at t depends on t alone, so any dt is exact
        return time_step(values, dt, TIME, float(self.controls[TIME].max))

    def simulate(self, duration: float | None = None, *, allow_long: bool = False) -> float:
        """Integrate the motion of the shown initial state ahead of time (what Play and the time slider show).

        Parameters
        ----------
        duration : float, optional
            Seconds of motion from ``t = 0``: a frame to the explorer's ``duration`` (the default).
        allow_long : bool
            Integrate beyond ``duration`` (Ctrl-C stops it and keeps what was computed).

        Returns
        -------
        float
            The time up to which the motion is now computed (s).

        Raises
        ------
        InputError
            A duration that is not a finite number of at least one frame.
        SizeLimitError
            A duration beyond the explorer's ``duration`` without ``allow_long``.
        """
        d = check_duration("duration", self.duration if duration is None else duration, math.inf)
        if d < 1.0 / self.fps:
            raise InputError(f"duration must be at least one frame (1/fps = {1.0 / self.fps:g} s), "
                             f"got {duration!r}")
        if d > self.duration and not allow_long:
            raise SizeLimitError(f"duration must be at most {self.duration:g} s (the explorer's duration, "
                                 f"the time slider's range), got {d:g}; pass allow_long=True to integrate "
                                 f"further (Ctrl-C stops it and keeps what was computed)")
        model, q0, qd0, tau = self.initial_state(self.shown_values or self.values)
        motion = self.motion_for(model, q0, qd0, tau)
        try:
            motion.extend(d)
        except KeyboardInterrupt:
            self._set_message(f"simulation stopped by Ctrl-C: the motion up to t = {motion.reached:g} s "
                              f"is kept")
        except Exception as exc:  # noqa: BLE001 - shown, like any refused update
            self._set_message(f"simulation stopped at t = {motion.reached:g} s: {self._reason(exc)}")
        return min(motion.reached, d)

    # -- drawing ---------------------------------------------------------------------
    def _view(self, st) -> tuple[float, float, float, float]:
        """The view: the whole chain's reach about the ground origin (with or without a focus)."""
        model, w = st["model"], st["w"]
        chain = np.vstack([np.asarray(w.origin[0], float)[None, :], w.pose[:, :2], self._state_ends(st)])
        reach = max(model.N + 0.4, float(np.max(np.hypot(*chain.T))) + 0.4)
        reach = math.ceil(2.0 * reach - 1e-9) / 2.0
        return (-reach, reach, -reach, reach)

    def readout_of(self, state):
        model, w = state["model"], state["w"]
        n = model.N
        e = state["ke"] + state["pe"]
        work = float(np.dot(state["tau"], w.q - state["q0"]))     # constant joint forces: work τ·(q − q₀)
        out = {"links": n, "t (s)": state["t"],
               "kinetic energy (J)": state["ke"], "potential energy (J)": state["pe"],
               "total energy (J)": e, "work of the joint forces (J)": work,
               "energy drift (J)": e - state["e0"] - work}
        out["q̈₁"] = float(w.qdd[0])
        out[f"q̈{subscript(n)}"] = float(w.qdd[-1])
        # a joint's acceleration: angular (revolute) or linear (prismatic)
        self.units = {**type(self).units, **{f"q̈{subscript(k + 1)}": QDD_UNIT[model.joints[k].kind]
                                             for k in (0, n - 1)}}
        out["|base force| (N)"] = float(np.hypot(*w.f[0, :2]))
        return out

    def scene_picture(self, state, view=None):
        v = self.values
        w = state["w"]
        overlays = {k: bool(v[k]) for k in OVERLAYS}
        view = tuple(view) if view else self._view(state)
        focus = self._focus(state["model"].N)
        size = self.figure_px
        # the same state drawn again (the base asks twice per update: the page, the key): built once
        key = (tuple(overlays.values()), view, focus, size)
        last = getattr(self, "_last_picture", None)
        if last is not None and last[0] is state and last[1] == key:
            return last[2].copy()
        split = self.tu_split(state) if v["T/U split"] else None
        pic = chain_picture(w, overlays=overlays, view=view, split=split, focus=focus, size=size,
                            ends=self._state_ends(state), time=state["t"])
        self._last_picture = (state, key, pic)
        return pic.copy()
