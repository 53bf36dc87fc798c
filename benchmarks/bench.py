"""``planargeo bench``: forward dynamics benchmarks, measured side by side in one run.

Every planargeo forward dynamics method (ABA, projective, mobility/chain
splitting, stacked, dense CRBA) against Pinocchio's ``pin.aba`` and MuJoCo's
``mj_forward`` on identical models (:func:`to_pinocchio`, :func:`to_mujoco`),
for chains of ``N`` = 1 ... 200 links.  Written to ``--out`` (required), plus one
summary document (``--summary``, default ``RESULTS.md`` in ``--out``) and copies of
the SVG charts in ``--gallery`` (default: none).  Nothing outside ``--out`` is
written unless named: ``make bench`` passes ``--out benchmarks/results --summary
benchmarks/RESULTS.md --gallery gallery/benchmarks`` to rewrite the committed files.
Every file is written atomically (:func:`planargeo.files.atomic_write`):

``single_state``
    One state of a uniform chain of ``N`` links: time per call of every method
    and both peers; the headline is the *ratio* to Pinocchio (and MuJoCo),
    which is robust to machine speed and load.
``accuracy``, ``work_precision``, ``speed_accuracy``
    Error of every method and peer against an independent extended-precision
    reference (``reference_system`` of ``benchmarks/reference.py``: exact
    rational arithmetic for small N, ``np.longdouble`` beyond), with its time
    per call: one point (time, error) per method and N.
``batch``
    Throughput for 1, 100 and 10000 states (N = 10): our ABA on the batch (one
    call: the compiled kernel on blocks of states shared among threads), our ABA
    called state by state, ``pin.aba`` and ``mj_forward`` in a Python loop, and the
    batched dense CRBA, measured interleaved in wall-clock time (the batch kernel
    runs on several threads).
``startup``
    ``import planargeo``, and the first ``forward_dynamics`` call in a fresh process:
    compiling the kernels (an empty numba cache), then loading them from the cache.
``scaling``
    Time per call against N on log axes with O(N) and O(N³) guides, and
    ``t(200)/t(50)`` per method.

Single-call timings are in *thread CPU time* (``time.thread_time``: time the
process spends descheduled on a busy machine does not count); batch timings in
wall-clock time (``time.perf_counter``), since the batch kernel uses several threads.  The headline ratios are
measured by interleaving: every method, ``pin.aba`` and ``mj_forward`` (the peers
that are installed) alternate in short blocks over many rounds, and the tables give the ratio of the best
blocks and the median of the per-round ratios (both see the same machine state).
A method too slow to share the rounds (one call above ``2 budget / rounds``) is
timed on its own: best of several repeats of the mean over many calls, or over
1-3 single calls when slower than a fifth of the budget (the table says so).  BLAS runs single-threaded (as Pinocchio and MuJoCo do):
the command re-runs itself in a fresh process with ``OPENBLAS_NUM_THREADS=1``
(and OMP/MKL) if needed.  Progress goes to stderr, one line per step.
This module imports matplotlib (charts); the math modules never do.
"""
from __future__ import annotations

import argparse
import datetime as _dt
import importlib
import io
import json
import os
import platform
import subprocess
import sys
import time
import timeit
from pathlib import Path

import numpy as np

# the reference lives in the package (not in the tests) so the accuracy columns exist for an installed package too
from reference import reference_with_info, rel_err
from planargeo.files import atomic_write, atomic_write_many
from planargeo.mechanics.model import chain_model

__all__ = ["add_arguments", "main", "time_call", "time_interleaved", "to_pinocchio", "pinocchio_forward", "to_mujoco",
           "to_mujoco_xml", "mujoco_dofs", "mujoco_forward", "reference_qdd"]

SINGLE_SIZES = (1, 2, 5, 10, 20, 50, 100, 200)
QUICK_SIZES = (1, 10, 50, 200)
BATCH_SIZES = (1, 100, 10000)
QUICK_BATCH_SIZES = (1, 100, 1000)
PEERS = ("pinocchio", "mujoco")
#: groups of ``--only``; all but ``dynamics`` run a script of ``benchmarks/``
SCRIPTS = {"breakdown": "breakdown.py", "integrators": "integrators.py", "scenes": "scene_cost.py",
           "truncated": "truncated.py", "classroom": "classroom.py", "page": "page_latency.py"}
GROUPS = ("dynamics",) + tuple(SCRIPTS)
#: the exact (rational) reference up to this many coordinates, longdouble beyond (exact costs ~N^3 Fractions)
EXACT_MAX = 5
#: other result files linked from RESULTS.md (written by the scripts of the other groups)
OTHER_RESULTS = (("breakdown.md", "where each method breaks down (accuracy near singularities)"),
                 ("integrators.md", "integrators: work–precision of ODE solvers, energy and constraint drift"),
                 ("scene_cost.md", "scene cost: what each scene computes and what modelling less saves"),
                 ("truncated.md", "truncated articulated recursion: speed against accuracy (10.2.2)"),
                 ("classroom.md", "a classroom's load: k visitors of `make app`, memory per visitor, drag step "
                                  "against k, the seat limit"),
                 ("page_latency.md", "page latency: explorers drawn by the browser, against the floor F of "
                                     "an empty round trip, in Voila and JupyterLab"),
                 ("pixel_path_widget_latency.md", "record of 2026-11-26: the old pixel path's widget latency "
                                               "(Matplotlib redraws; replaced by page_latency.md)"),
                 ("pixel_path_browser_latency.md", "record of 2026-11-26: the old pixel path's latency in "
                                                "JupyterLab (PNG frames, ipympl; replaced by page_latency.md)"))
CHARTS = ("scaling", "work_precision", "speed_accuracy", "single_state", "batch")

_T0 = time.perf_counter()


def _progress(msg: str) -> None:
    """One progress line on stderr (flushed), with the wall time since the start."""
    print(f"[{time.perf_counter() - _T0:6.1f} s] {msg}", file=sys.stderr, flush=True)


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("--out", required=True,
                        help="output directory, also passed to the group scripts that take --out (default: %(default)s)")
    parser.add_argument("--quick", action="store_true",
                        help="fewer sizes, repeats and smaller batches (under a minute); passed on to the "
                             "group scripts that accept it")
    parser.add_argument("--no-charts", action="store_true", help="tables only")
    parser.add_argument("--sizes", default=None,
                        help="chain sizes N for the single-state tables (default: "
                             f"{','.join(map(str, SINGLE_SIZES))}; with --quick {','.join(map(str, QUICK_SIZES))})")
    parser.add_argument("--summary", default=None,
                        help="the summary document (default: RESULTS.md in --out)")
    parser.add_argument("--gallery", default="",
                        help="folder for copies of the SVG charts (default: none; make bench: gallery/benchmarks)")
    parser.add_argument("--only", choices=GROUPS, action="append",
                        help="run only these groups (repeatable; default: all). 'dynamics' is this module; "
                             "'breakdown' runs benchmarks/breakdown.py (accuracy study), "
                             "'integrators' benchmarks/integrators.py, "
                             "'scenes' benchmarks/scene_cost.py, 'truncated' benchmarks/truncated.py (truncated "
                             "articulated recursion), 'classroom' benchmarks/classroom.py (k visitors of the app "
                             "at once, in headless chromium), 'page' benchmarks/page_latency.py (explorers "
                             "drawn in the page, Voila and JupyterLab) (these need a source checkout)")


# --------------------------------------------------------------------------- timing
def _calls_for(fn, seconds: float, timer) -> int:
    """How many calls of ``fn`` take about ``seconds``."""
    fn()
    n, t = 1, 0.0
    while True:
        t = timeit.Timer(fn, timer=timer).timeit(number=n)
        if t > seconds / 10 or n > 1e6:
            break
        n *= 4 if t < seconds / 100 else 2
    return max(1, int(n * seconds / max(t, 1e-9)))


def time_call(fn, *, budget: float = 0.2, repeat: int = 5, timer=time.thread_time) -> float:
    """Seconds per call of ``fn()``: best over ``repeat`` runs of the mean over ~``budget`` seconds (thread CPU time)."""
    n = _calls_for(fn, budget / repeat, timer)
    return min(timeit.Timer(fn, timer=timer).repeat(number=n, repeat=repeat)) / n


def _time_method(fn, budget: float, timer=time.thread_time):
    """``(seconds per call, calls)``: :func:`time_call`, or for a slow ``fn`` (one call > budget/5) the best of 1-3 calls.

    ``calls`` is None for the normal path, else the number of single calls timed.
    """
    fn()
    fn()                      # warm-up: the kernels are compiled (or loaded) on first use
    t0 = timer()
    fn()
    t1 = timer() - t0
    if t1 > budget / 5:
        reps = int(max(1, min(3, budget // max(t1, 1e-9))))
        ts = [t1] + timeit.Timer(fn, timer=timer).repeat(number=1, repeat=reps - 1) if reps > 1 else [t1]
        return min(ts), len(ts)
    return time_call(fn, budget=budget, timer=timer), None


def time_interleaved(fns: dict, *, budget: float = 0.5, rounds: int = 25, timer=time.thread_time) -> dict:
    """Seconds per call of each ``fns[name]()``, measured in alternating blocks: ``{name: [per round]}``.

    Every round times one block of each function in turn, so the functions see
    the same machine state; ratios of the best blocks or medians of per-round
    ratios are robust to load.
    """
    per = budget / (rounds * len(fns))
    timers = {k: (timeit.Timer(f, timer=timer), _calls_for(f, per, timer)) for k, f in fns.items()}
    out = {k: [] for k in fns}
    for _ in range(rounds):
        for k, (t, n) in timers.items():
            out[k].append(t.timeit(number=n) / n)
    return out


def ratio_stats(times: dict, num: str, den: str) -> dict:
    """``{"best": min(num)/min(den), "median": median of per-round num/den}`` from :func:`time_interleaved`."""
    a, b = np.array(times[num]), np.array(times[den])
    return {"best": float(a.min() / b.min()), "median": float(np.median(a / b))}


# --------------------------------------------------------------------------- peers
#: Pinocchio's joints for each joint kind, applied in turn (a multi-dof joint is a composite joint)
_PIN_AXES = {"revolute": ("RZ",), "prismatic": ("PX",), "revolute_prismatic": ("PX", "RZ"),
             "twin_prismatic": ("PX", "PY"), "plane": ("PX", "PY", "RZ"), "fixed": ()}


def _pin_joints(model) -> list:
    """The Pinocchio joint id carrying each body: its own joint's, or its nearest moving ancestor's (0: the ground)."""
    ids, n = [], 0
    for j, p in zip(model.joints, model.parents):
        if j.kind != "fixed":
            n += 1
            ids.append(n)
        else:
            ids.append(0 if p < 0 else ids[p])
    return ids


def to_pinocchio(model):
    """The same planar mechanism as a Pinocchio model (None if pinocchio is missing).

    Planar joints become Pinocchio's ``RZ`` (revolute about z) and ``PX``/``PY``
    (prismatic along the joint frame's x/y), each placed by ``(px, py, θ)`` in its
    parent's frame; a multi-dof joint is a composite joint of these in the order of
    :class:`~planargeo.mechanics.model.Joint` (``plane``: PX, PY, RZ); a fixed joint
    adds its body to the joint that carries its parent.  Each body's inertia is given
    about its centre of mass (only ``izz`` matters in the plane); gravity is set
    explicitly.  Pinocchio numbers its coordinates in the order the joints are added,
    which is planargeo's.
    """
    try:
        import pinocchio as pin
    except ImportError:  # pragma: no cover
        return None
    pm = pin.Model()
    frames = []                   # per body: its frame in the frame of the Pinocchio joint carrying it
    for i, (b, j, p) in enumerate(zip(model.bodies, model.joints, model.parents)):
        px, py, th = j.placement
        R = np.array([[np.cos(th), -np.sin(th), 0.0], [np.sin(th), np.cos(th), 0.0], [0.0, 0.0, 1.0]])
        placement = (pin.SE3.Identity() if p < 0 else frames[p]) * pin.SE3(R, np.array([px, py, 0.0]))
        if j.kind == "fixed":
            jid, frame = _pin_joints(model)[i], placement
        else:
            axes = [getattr(pin, f"JointModel{a}")() for a in _PIN_AXES[j.kind]]
            jm = axes[0]
            if len(axes) > 1:
                jm = pin.JointModelComposite()
                for a in axes:
                    jm.addJoint(a)
            parent = 0 if p < 0 else _pin_joints(model)[p]
            jid, frame = pm.addJoint(parent, jm, placement, f"joint{i}"), pin.SE3.Identity()
        I3 = np.diag([1.0, 1.0, b.inertia])  # out-of-plane entries are irrelevant in the plane
        pm.appendBodyToJoint(jid, pin.Inertia(b.mass, np.array([b.com[0], b.com[1], 0.0]), I3), frame)
        frames.append(frame)
    pm.gravity = pin.Motion(np.array([model.gravity[0], model.gravity[1], 0.0, 0.0, 0.0, 0.0]))
    return pm


def pinocchio_forward(model, q, qd, tau, f_ext=None):
    """``q̈`` (..., nq) by Pinocchio's ``aba`` on :func:`to_pinocchio`'s model: the independent reference of the tests.

    ``f_ext`` (..., N, 3), world wrenches at the origin, enter as the generalized forces
    ``Jᵀ f`` with ``J`` Pinocchio's joint Jacobians in the world frame (rows vx, vy, ωz).
    Leading dimensions are looped over.
    """
    import pinocchio as pin

    pm = to_pinocchio(model)
    pd = pm.createData()
    joints = _pin_joints(model)
    q, qd, tau = np.broadcast_arrays(*(np.asarray(x, dtype=float) for x in (q, qd, tau)))
    shape = q.shape[:-1] if f_ext is None else np.broadcast_shapes(q.shape[:-1], np.shape(f_ext)[:-2])
    out = np.empty(shape + (model.nq,))
    for k in np.ndindex(shape):
        qk, qdk, tk = (np.broadcast_to(x, shape + (model.nq,))[k] for x in (q, qd, tau))
        force = np.array(tk, dtype=float)
        if f_ext is not None:
            fk = np.broadcast_to(f_ext, shape + (model.N, 3))[k]
            pin.computeJointJacobians(pm, pd, qk)
            for i, jid in enumerate(joints):
                if jid:
                    J = pin.getJointJacobian(pm, pd, jid, pin.ReferenceFrame.WORLD)[[0, 1, 5]]
                    force += J.T @ fk[i]
        out[k] = pin.aba(pm, pd, qk, qdk, force)
    return out


def _import(name):
    try:
        return importlib.import_module(name)
    except ImportError:
        return None


def _f(x) -> str:
    """A float as the shortest string that reads back exactly."""
    return repr(float(x))


def to_mujoco_xml(model) -> str:
    """MJCF of the same planar mechanism (revolute, prismatic and fixed joints; tree topology).

    Body ``i`` is ``<body name="body{i}">`` nested in its parent's body (MuJoCo
    body positions are relative to the parent body's frame), placed at the
    joint placement ``(px, py, θ)`` (``pos`` and a rotation ``quat`` about z);
    its joint sits at the body origin: a hinge about z (revolute) or a slide
    along the body's x axis (prismatic, i.e. the joint frame's x), or none
    (fixed).  ``<inertial pos=com mass diaginertia="I I I">`` with ``I`` the
    inertia about the centre of mass (only ``izz`` matters in the plane; the
    equal ``ixx, iyy`` keep it positive definite).  Gravity is set explicitly,
    contacts are disabled, armature and damping are zero, and there are no
    geoms.  Contacts of ``model`` (closed loops) are not represented.
    """
    kids = {i: [] for i in range(-1, model.N)}
    for i, p in enumerate(model.parents):
        kids[p].append(i)
    axis = {"revolute": ("hinge", "0 0 1"), "prismatic": ("slide", "1 0 0")}

    def body(i, ind):
        b, j = model.bodies[i], model.joints[i]
        if j.kind not in axis and j.kind != "fixed":
            raise ValueError(f"to_mujoco handles revolute, prismatic and fixed joints, not {j.kind!r}")
        px, py, th = j.placement
        s = " " * ind
        inertia = _f(b.inertia)
        out = [f'{s}<body name="body{i}" pos="{_f(px)} {_f(py)} 0" quat="{_f(np.cos(th / 2))} 0 0 {_f(np.sin(th / 2))}">',
               f'{s}  <inertial pos="{_f(b.com[0])} {_f(b.com[1])} 0" mass="{_f(b.mass)}" '
               f'diaginertia="{inertia} {inertia} {inertia}"/>']
        if j.kind in axis:
            kind, ax = axis[j.kind]
            out.append(f'{s}  <joint name="joint{i}" type="{kind}" axis="{ax}" pos="0 0 0" armature="0" damping="0" '
                       'stiffness="0" frictionloss="0" limited="false"/>')
        for c in kids[i]:
            out += body(c, ind + 2)
        out.append(f"{s}</body>")
        return out

    gx, gy = model.gravity
    lines = ['<mujoco model="planargeo">',
             '  <compiler angle="radian" inertiafromgeom="false" balanceinertia="false" boundmass="0" '
             'boundinertia="0" settotalmass="-1"/>',
             f'  <option gravity="{_f(gx)} {_f(gy)} 0">',
             '    <flag contact="disable"/>',
             '  </option>',
             '  <worldbody>']
    for c in kids[-1]:
        lines += body(c, 4)
    lines += ['  </worldbody>', '</mujoco>']
    return "\n".join(lines) + "\n"


def to_mujoco(model):
    """The same planar mechanism as a ``mujoco.MjModel`` (None if mujoco is missing); see :func:`to_mujoco_xml`."""
    mujoco = _import("mujoco")
    if mujoco is None:
        return None
    return mujoco.MjModel.from_xml_string(to_mujoco_xml(model))


def mujoco_dofs(mjm, model):
    """MuJoCo dof index of each of ``model``'s coordinates (in planargeo's order), or None if it is the identity.

    MuJoCo numbers dofs depth-first through the XML nesting; planargeo by body
    index, so the two differ for trees.
    """
    import mujoco

    idx = [int(mjm.jnt_dofadr[mujoco.mj_name2id(mjm, mujoco.mjtObj.mjOBJ_JOINT, f"joint{i}")])
           for i, j in enumerate(model.joints) if j.kind != "fixed"]
    idx = np.array(idx, dtype=int)
    return None if np.array_equal(idx, np.arange(len(idx))) else idx


def mujoco_forward(mjm, mjd, q, qd, tau, dofs=None):
    """q̈ from ``mj_forward`` with ``q, q̇`` as ``qpos, qvel`` and ``τ`` as ``qfrc_applied`` (planargeo's order)."""
    import mujoco

    sel = slice(None) if dofs is None else dofs
    mjd.qpos[sel] = q
    mjd.qvel[sel] = qd
    mjd.qfrc_applied[sel] = tau
    mujoco.mj_forward(mjm, mjd)
    return mjd.qacc[sel].copy()


def _mujoco_call(mjm, mjd, q, qd, tau):
    """A no-argument closure for timing: set ``qpos, qvel, qfrc_applied`` (a chain: identity order), ``mj_forward``."""
    import mujoco

    fwd, qpos, qvel, qfrc = mujoco.mj_forward, mjd.qpos, mjd.qvel, mjd.qfrc_applied

    def call():
        qpos[:] = q
        qvel[:] = qd
        qfrc[:] = tau
        fwd(mjm, mjd)
        return mjd.qacc
    return call


def _peers(m):
    """``{name: (callable(q, qd, tau) -> q̈, closure factory for timing)}`` for the peers that are installed."""
    out = {}
    pm = to_pinocchio(m)
    if pm is not None:
        import pinocchio as pin

        pd = pm.createData()
        out["pinocchio"] = (lambda q, qd, tau: pin.aba(pm, pd, q, qd, tau).copy(),
                            lambda q, qd, tau: (lambda: pin.aba(pm, pd, q, qd, tau)))
    mjm = to_mujoco(m)
    if mjm is not None:
        import mujoco

        mjd = mujoco.MjData(mjm)
        dofs = mujoco_dofs(mjm, m)
        if dofs is not None:  # pragma: no cover - the benchmarks use chains
            raise ValueError("benchmark peers expect a chain (identity dof order)")
        out["mujoco"] = (lambda q, qd, tau: mujoco_forward(mjm, mjd, q, qd, tau),
                         lambda q, qd, tau: _mujoco_call(mjm, mjd, q, qd, tau))
    return out


# --------------------------------------------------------------------------- reference
def reference_qdd(model, q, qd, tau):
    """``(q̈_ref, info)`` from the independent reference of the breakdown study (:mod:`planargeo._reference`).

    Exact rational arithmetic up to :data:`EXACT_MAX` coordinates, ``np.longdouble``
    beyond; ``info``: ``mode``, ``spread`` (longdouble: the change when the
    elimination order is reversed, an estimate of the reference's own error;
    exact: 0) and ``cond`` (2-norm condition number of H).
    """
    mode = "exact" if model.nq <= EXACT_MAX else "longdouble"
    x, spread, cond = reference_with_info(model, q, qd, tau, mode=mode)
    return x, {"mode": mode, "spread": spread, "cond": float(cond)}


# --------------------------------------------------------------------------- runs
def _methods() -> dict:
    from planargeo.scenes.chain import available_methods

    return available_methods()


def _state(N, seed=0, batch=()):
    rng = np.random.default_rng(seed)
    return rng.normal(size=(3,) + batch + (N,))


def _fmt_us(t):
    return "—" if t is None or not np.isfinite(t) else (f"{t * 1e6:.1f}" if t < 1e-2 else f"{t * 1e6:.0f}")


def _interleaved(m, budget, seed, rounds=40, label="", extra=None):
    """``aba``, ``pin.aba``, ``mj_forward`` (and ``extra``) on one model, interleaved.

    Returns ``(best times, ratio stats, median times)``.  ``extra`` maps more
    method names to ``fn(model, q, qd, tau)``, timed in the same rounds on the
    same state.  ``ratios`` maps ``"pinocchio"``/``"mujoco"`` to the stats of
    ``aba / peer``, ``"mujoco/pinocchio"`` to ``mj_forward / pin.aba`` and, with
    Pinocchio present, ``"<name>/pinocchio"`` to ``name / pin.aba`` for every
    planargeo method timed.
    """
    from planargeo.algorithms.aba import forward_dynamics

    q, qd, tau = _state(m.nq, seed=seed)
    fns = {"aba": lambda: forward_dynamics(m, q, qd, tau)}
    for name, fn in (extra or {}).items():
        if name != "aba":
            fns[name] = (lambda fn=fn: fn(m, q, qd, tau))
    for name, (_, make) in _peers(m).items():
        fns[name] = make(q, qd, tau)
    for f in fns.values():       # warm-up (the kernels are compiled or loaded on first use)
        f()
        f()
    _progress(f"[single] N={m.nq} interleaved {'/'.join(fns)} {label}...")
    t = time_interleaved(fns, budget=budget * len(fns), rounds=rounds)
    ratios = {p: ratio_stats(t, "aba", p) for p in PEERS if p in t}
    if "pinocchio" in t and "mujoco" in t:
        ratios["mujoco/pinocchio"] = ratio_stats(t, "mujoco", "pinocchio")
    if "pinocchio" in t:
        for name in fns:
            if name not in PEERS:
                ratios[f"{name}/pinocchio"] = ratio_stats(t, name, "pinocchio")
    return ({k: float(min(v)) for k, v in t.items()}, ratios,
            {k: float(np.median(v)) for k, v in t.items()})


def run_single(sizes, budget, rounds=40):
    """Time per call (s) of every method and peer for each N; their errors against the reference, CRBA and Pinocchio.

    Every method and the installed peers (none, one or both) are timed interleaved (:func:`time_interleaved`)
    in the same rounds on the same state, except a method whose single call
    takes more than ``2 budget / rounds`` (listed in ``alone``: timed on its own,
    :func:`_time_method`); ``times`` are the best blocks, ``times_median`` the
    medians, ``ratio_pin_all`` maps every interleaved method to the stats of
    ``method / pin.aba``.  ``ratio`` / ``ratio_mj`` hold the best and
    median ratios ``aba / pin.aba`` / ``aba / mj_forward`` on ``chain_model(N)``,
    ``ratio_random`` / ``ratio_mj_random`` on ``random_model(N)`` (no zero
    placements or offsets), ``ratio_mj_pin`` is ``mj_forward / pin.aba``.
    """
    from planargeo.mechanics.model import random_model

    methods = _methods()
    rows = []
    for N in sizes:
        m = chain_model(N)
        q, qd, tau = _state(N, seed=N)
        _progress(f"[single] N={N} reference ...")
        qdd_ref, info = reference_qdd(m, q, qd, tau)
        row = {"N": N, "times": {}, "calls": {}, "err_ref": {}, "err_crba": {}, "err_pin": {}, "ref": info}
        ref = methods["crba"](m, q, qd, tau)
        peers = _peers(m)
        outs = {}
        for name, (call, _) in peers.items():
            outs[name] = call(q, qd, tau)
        # every method that runs: fast ones join the interleaved rounds with the peers, a method whose
        # single call exceeds 2 budget / rounds (it would dominate the rounds) is timed on its own
        fast, slow = {}, {}
        for name, fn in methods.items():
            try:
                outs[name] = np.asarray(fn(m, q, qd, tau))
            except Exception as exc:  # report, don't die
                row["times"][name] = float("nan")
                row["err_crba"][name] = row["err_ref"][name] = f"{type(exc).__name__}"
                continue
            fn(m, q, qd, tau)
            t0 = time.thread_time()
            fn(m, q, qd, tau)
            (fast if name == "aba" or time.thread_time() - t0 <= 2 * budget / rounds else slow)[name] = fn
        # the fast methods share the rounds among themselves even when no peer is installed
        t, ratios, tmed = _interleaved(m, budget, N, rounds, "(chain_model)", extra=fast)
        row["times"].update(t)
        row["times_median"] = tmed
        row["ratio_pin_all"] = {k.split("/")[0]: v for k, v in ratios.items()
                                if k.endswith("/pinocchio") and k.split("/")[0] in methods}
        if peers:
            tr, ratios_r, _ = _interleaved(random_model(N, seed=N), budget, N, rounds, "(random_model)")
            row["times_random"] = tr
            if "pinocchio" in ratios:
                row["ratio"], row["ratio_random"] = ratios["pinocchio"], ratios_r["pinocchio"]
            if "mujoco" in ratios:
                row["ratio_mj"], row["ratio_mj_random"] = ratios["mujoco"], ratios_r["mujoco"]
            if "mujoco/pinocchio" in ratios:
                row["ratio_mj_pin"] = ratios["mujoco/pinocchio"]
        for name, fn in slow.items():
            _progress(f"[single] N={N} {name} (alone: too slow to interleave) ...")
            row["times"][name], calls = _time_method(lambda fn=fn: fn(m, q, qd, tau), budget)
            row.setdefault("alone", []).append(name)
            if calls is not None:
                row["calls"][name] = calls
        pin_ref = outs.get("pinocchio")
        for name, out in outs.items():
            if qdd_ref is not None:
                row["err_ref"][name] = rel_err(out, qdd_ref)
            row["err_crba"][name] = rel_err(out, ref)
            if pin_ref is not None and name != "pinocchio":
                row["err_pin"][name] = rel_err(out, pin_ref)
        # methods first, then the peers (the order of the tables)
        order = list(methods) + [p for p in PEERS if p in row["times"]]
        row["times"] = {k: row["times"][k] for k in order}
        rows.append(row)
    return rows


def run_batch(batch_sizes, budget, N=10, rounds=7):
    """Time per batch of B states (N-link chain) of our ABA and CRBA on the batch, our ABA state by state, and the peers looped.

    All five are measured interleaved (:func:`time_interleaved`) in wall-clock time (the
    batch kernel runs on several threads); ``ratio`` maps each peer to the stats of
    ``aba (batch) / peer (loop)``.
    """
    from planargeo.algorithms.aba import forward_dynamics
    from planargeo.algorithms.crba import forward_dynamics_crba

    m = chain_model(N)
    peers = _peers(m)
    rows = []
    for B in batch_sizes:
        q, qd, tau = _state(N, seed=B, batch=(B,))
        fns = {"aba (batch)": lambda: forward_dynamics(m, q, qd, tau)}

        def loop_ours():
            for k in range(B):
                forward_dynamics(m, q[k], qd[k], tau[k])

        fns["aba (state by state)"] = loop_ours
        fns["crba (batch)"] = lambda: forward_dynamics_crba(m, q, qd, tau)
        outs = {}
        for name, (call, make) in peers.items():
            calls = [make(q[k], qd[k], tau[k]) for k in range(B)]   # bound per state, outside the timing

            def loop(calls=calls):
                for c in calls:
                    c()

            fns[f"{name} (loop)"] = loop
            outs[name] = np.array([call(q[k], qd[k], tau[k]) for k in range(B)])
        _progress(f"[batch] B={B} (N={N}) interleaved: {', '.join(fns)} ...")
        for f in fns.values():   # warm-up (the kernels are compiled or loaded on first use)
            f()
        t = time_interleaved(fns, budget=budget * len(fns), rounds=rounds, timer=time.perf_counter)
        row = {"B": B, "times": {k: float(min(v)) for k, v in t.items()},
               "ratio": {p: ratio_stats(t, "aba (batch)", f"{p} (loop)") for p in peers}}
        # agreement of the batch call with the dense reference and the peers
        a, b = forward_dynamics(m, q, qd, tau), forward_dynamics_crba(m, q, qd, tau)
        row["err"] = rel_err(a, b)
        row["err_peer"] = {p: rel_err(a, o) for p, o in outs.items()}
        rows.append(row)
    return rows


# --------------------------------------------------------------------------- startup
_STARTUP = """
import sys, time
t0 = time.perf_counter()
import planargeo
t1 = time.perf_counter()
numba = "numba" in sys.modules
import numpy as np
from planargeo.algorithms.aba import forward_dynamics
from planargeo.mechanics.model import chain_model
m, q, Q = chain_model(10), np.zeros(10), np.zeros((10000, 10))
t2 = time.perf_counter()
forward_dynamics(m, q, q, q)
t3 = time.perf_counter()
forward_dynamics(m, Q, Q, Q)
t4 = time.perf_counter()
print(t1 - t0, t3 - t2, t4 - t3, numba)
"""
#: (key, description, goal in seconds or None) of the startup rows of the headline
STARTUP_ROWS = (("import", "`import planargeo` (fresh process)", 0.5),
                ("first_compile", "first `forward_dynamics` call in a fresh process, compiling (empty numba cache)", 2.0),
                ("first_cached", "first `forward_dynamics` call in a fresh process, from numba's cache", 0.3),
                ("batch_compile", "first batch call (10⁴ states) after it, compiling the batch kernel", None),
                ("batch_cached", "first batch call (10⁴ states) after it, from numba's cache", None))


def _startup_run(cache: str) -> list:
    env = dict(os.environ, NUMBA_CACHE_DIR=cache)
    out = subprocess.run([sys.executable, "-c", _STARTUP], capture_output=True, text=True, env=env, check=True,
                         cwd=str(Path(__file__).resolve().parents[1]))
    *times, numba = out.stdout.split()
    return [float(t) for t in times] + [numba == "True"]


def run_startup(repeat: int = 3) -> dict:
    """Seconds (wall clock, fresh processes) for ``import planargeo`` and the first calls, compiling and cached.

    Each repeat compiles into a new empty numba cache (``NUMBA_CACHE_DIR``), then runs
    again from that cache; best of ``repeat``.  ``import_loads_numba``: whether
    ``import planargeo`` imported numba (it should not).
    """
    import tempfile

    runs = []
    for _ in range(repeat):
        with tempfile.TemporaryDirectory(prefix="planargeo-numba-") as cache:
            _progress("[startup] a fresh process compiling the kernels, then one loading them from the cache ...")
            runs.append((_startup_run(cache), _startup_run(cache)))
    best = lambda k, c: min(r[c][k] for r in runs)  # noqa: E731
    return {"import": min(min(r[0][0], r[1][0]) for r in runs), "first_compile": best(1, 0),
            "first_cached": best(1, 1), "batch_compile": best(2, 0), "batch_cached": best(2, 1),
            "import_loads_numba": any(r[0][3] or r[1][3] for r in runs)}


def _threads() -> int:
    import numba

    return numba.get_num_threads()


def _block() -> int:
    from planargeo.algorithms import kernels

    return kernels.BLOCK


# --------------------------------------------------------------------------- tables
def _versions() -> dict:
    out = {"Python": platform.python_version(), "numpy": np.__version__}
    for name, mod in (("Pinocchio", "pinocchio"), ("MuJoCo", "mujoco")):
        m = _import(mod)
        out[name] = getattr(m, "__version__", "?") if m is not None else "not installed"
    return out


def _header(title):
    now = _dt.datetime.now(_dt.timezone.utc).strftime("%Y-%m-%d %H:%M UTC")
    v = ", ".join(f"{k} {x}" for k, x in _versions().items())
    return (f"# {title}\n\nGenerated by `planargeo bench` on {now}; {v}, {os.cpu_count()} CPU(s), "
            f"{platform.machine()}.\nTimes are per call (µs), best of repeats in thread CPU time; **ratios are the "
            "headline** (absolute times depend on the machine and its load).\n\n")


def _x(r) -> str:
    return f"{r:.2f}×" if r < 1 else f"{r:.1f}×"


def _peer_label(p):
    return {"pinocchio": "pin.aba", "mujoco": "mj_forward"}.get(p, p)


def _peer_text(peers) -> str:
    """The peers that took part, for the table headers: ``"the peers `pin.aba` and `mj_forward`"`` etc.

    >>> _peer_text(["pinocchio", "mujoco"])
    'both peers, `pin.aba` and `mj_forward` (setting `qpos`, `qvel`, `qfrc_applied`, then `mj_forward`),'
    >>> _peer_text(["pinocchio"])
    'the peer `pin.aba` (MuJoCo not installed)'
    """
    labels = {"pinocchio": "`pin.aba`",
              "mujoco": "`mj_forward` (setting `qpos`, `qvel`, `qfrc_applied`, then `mj_forward`)"}
    if len(peers) == 2:
        return f"both peers, {labels[peers[0]]} and {labels[peers[1]]},"
    if len(peers) == 1:
        other = {"pinocchio": "MuJoCo", "mujoco": "Pinocchio"}[peers[0]]
        return f"the peer {labels[peers[0]]} ({other} not installed)"
    return "no peer (neither Pinocchio nor MuJoCo installed)"


def _single_tables(rows) -> list:
    """Markdown lines: the interleaved headline ratios (the all-methods time table is :func:`_time_table`)."""
    peers = [p for p in PEERS if p in rows[0]["times"]]
    lines = []
    if "ratio" in rows[0] or "ratio_mj" in rows[0]:
        cols = ["N"] + [f"{_peer_label(p)} µs" for p in peers] + ["aba µs"]
        for key, lab in (("ratio", "pin.aba"), ("ratio_mj", "mj_forward")):
            if key in rows[0]:
                cols += [f"aba / {lab}: chain best", "median", "random_model best", "median"]
        if "ratio_mj_pin" in rows[0]:
            cols += ["mj_forward / pin.aba (median)"]
        lines += ["`aba` (`planargeo.algorithms.aba.forward_dynamics`, one state as float64 arrays: the compiled "
                  f"kernel) and {_peer_text(peers)} alternate in short blocks over many rounds (thread CPU "
                  "time). *best*: ratio of the best blocks; *median*: median of the per-round ratios. `chain_model(N)`: "
                  "unit links along x; `random_model(N)`: random placements, coms, revolute and prismatic joints "
                  "(the kernel does the same work for both).\n",
                  "| " + " | ".join(cols) + " |", "|" + "---:|" * len(cols)]
        for r in rows:
            cells = [str(r["N"])] + [_fmt_us(r["times"][p]) for p in peers] + [_fmt_us(r["times"]["aba"])]
            for key, key_r in (("ratio", "ratio_random"), ("ratio_mj", "ratio_mj_random")):
                if key in rows[0]:
                    a, b = r[key], r[key_r]
                    cells += [_x(a["best"]), _x(a["median"]), _x(b["best"]), _x(b["median"])]
            if "ratio_mj_pin" in rows[0]:
                cells.append(_x(r["ratio_mj_pin"]["median"]))
            lines.append("| " + " | ".join(cells) + " |")
        lines += [""]
    return lines


def _time_table(rows) -> list:
    names = [n for n in rows[0]["times"] if n not in PEERS]
    peers = [p for p in PEERS if p in rows[0]["times"]]
    cols = ["N"] + [f"{_peer_label(p)} µs" for p in peers] + [f"{n} µs" for n in names]
    cols += [f"{n} / pin" for n in names] if "pinocchio" in peers else []
    who = f"Every method and {_peer_text(peers)}" if peers else \
        "Every method (no peer installed: neither Pinocchio nor MuJoCo took part)"
    text = (f"{who} alternate in short blocks over the same rounds on the same state (thread CPU time): "
            "**µs** is the best block" + (", **/ pin** the median of the per-round ratios to `pin.aba`"
                                          if "pinocchio" in peers else "") + ".")
    if any(r.get("alone") for r in rows):
        text += (" `†`: a method too slow to share the rounds (one call > 2 budget / rounds), timed on its "
                 "own (best of several repeats" + ("; its ratio is best / best" if "pinocchio" in peers else "")
                 + ").")
    lines = [text, "", "| " + " | ".join(cols) + " |", "|" + "---:|" * len(cols)]
    slow = False
    for r in rows:
        t = r["times"]
        alone = r.get("alone", [])
        cells = [str(r["N"])] + [_fmt_us(t[p]) for p in peers]
        for n in names:
            c = _fmt_us(t[n]) + (" †" if n in alone else "")
            if n in r.get("calls", {}):
                c += f" ({r['calls'][n]}×1)"
                slow = True
            cells.append(c)
        if "pinocchio" in peers:
            rp = r.get("ratio_pin_all", {})
            cells += [(_x(rp[n]["median"]) if n in rp else _x(t[n] / t["pinocchio"]) + (" †" if n in alone else ""))
                      if np.isfinite(t[n]) else "—" for n in names]
        lines.append("| " + " | ".join(cells) + " |")
    if slow:
        lines += ["", "`(k×1)`: slower than a fifth of the budget per call, timed as the best of k single calls."]
    return lines + [""]


def write_single(rows, out: Path) -> str:
    lines = [_header("Single-state forward dynamics, uniform chain of N links"),
             "Model: `chain_model(N)` (unit links, revolute joints, gravity -9.81 y), random q, q̇, τ.\n"]
    head = _single_tables(rows)
    if head:
        lines += ["## Headline: ABA / pin.aba and ABA / mj_forward, measured interleaved\n"] + head
        lines += ["## All methods\n"]
    lines += _time_table(rows)
    text = "\n".join(lines) + "\n"
    atomic_write(out / "single_state.md", text)
    return text


def _err(e, spread=0.0) -> str:
    if e is None:
        return "—"
    if isinstance(e, str):
        return f"raises {e}"
    if e == 0:
        return "0"
    return ("≲ " if e < 3 * spread else "") + f"{e:.1e}"


def _accuracy_table(rows) -> list:
    names = list(rows[0]["times"])
    has_ref = bool(rows[0].get("ref"))
    if has_ref:
        cols = ["N", "ref", "cond(H)", "ε·cond(H)"] + [_peer_label(n) for n in names]
        lines = ["| " + " | ".join(cols) + " |", "|---:|---|" + "---:|" * (len(cols) - 2)]
        eps = float(np.finfo(float).eps)
        for r in rows:
            info = r["ref"]
            refc = "exact" if info["mode"] == "exact" else f"ld ±{info['spread']:.0e}"
            cells = [str(r["N"]), refc, f"{info['cond']:.1e}", f"{eps * info['cond']:.1e}"]
            cells += [_err(r["err_ref"].get(n), info["spread"]) for n in names]
            lines.append("| " + " | ".join(cells) + " |")
        return lines + [""]
    return ["(no reference errors were measured; see accuracy.md for the errors against the dense CRBA solve)", ""]


def write_accuracy(rows, out: Path) -> str:
    names = list(rows[0]["err_crba"])
    lines = [_header("Speed against accuracy"),
             "Largest relative error max|q̈ − q̈_ref| / max|q̈_ref| of every method and peer against the "
             "independent reference of the breakdown study (`reference_system` in `benchmarks/reference.py`: "
             f"the joint-space equations from world-frame Jacobians, solved exactly for N ≤ {EXACT_MAX} and in "
             "`np.longdouble` beyond, `ld ±` its own error estimated by reversing the elimination order; errors "
             "marked `≲` are below 3× that estimate, not resolved), against the dense CRBA solve (`H q̈ = τ − C`) "
             "and against Pinocchio's `pin.aba`, with the time per call.\n",
             "## Against the reference\n"]
    lines += _accuracy_table(rows)
    lines += ["## Time, and errors against the reference, CRBA and Pinocchio\n",
              "| N | method | µs per call | error vs reference | error vs CRBA | error vs Pinocchio |",
              "|---:|---|---:|---:|---:|---:|"]
    for r in rows:
        spread = r.get("ref", {}).get("spread", 0.0)
        for n in names:
            lines.append(f"| {r['N']} | {_peer_label(n)} | {_fmt_us(r['times'].get(n))} | "
                         f"{_err(r['err_ref'].get(n), spread)} | {_err(r['err_crba'].get(n))} | "
                         f"{_err(r['err_pin'].get(n))} |")
    text = "\n".join(lines) + "\n"
    atomic_write(out / "accuracy.md", text)
    return text


def _batch_table(rows) -> list:
    names = list(rows[0]["times"])
    peers = list(rows[0].get("ratio", {}))
    cols = ["B"] + [f"{n} µs/state" for n in names] + [f"batch / {_peer_label(p)} loop" for p in peers]
    cols += ["error vs CRBA"] + [f"error vs {_peer_label(p)}" for p in peers]
    lines = ["| " + " | ".join(cols) + " |", "|" + "---:|" * len(cols)]
    for r in rows:
        t = r["times"]
        cells = [str(r["B"])] + [_fmt_us(t[n] / r["B"]) for n in names]
        cells += [f"{_x(r['ratio'][p]['median'])} (best {_x(r['ratio'][p]['best'])})" for p in peers]
        cells += [f"{r['err']:.1e}"] + [f"{r['err_peer'][p]:.1e}" for p in peers]
        lines.append("| " + " | ".join(cells) + " |")
    return lines + [""]


def write_batch(rows, out: Path) -> str:
    lines = [_header("Batch throughput, chain of N = 10 links"),
             "Time per state (µs, wall clock) for a batch of B random states; `aba (batch)` is one call of "
             f"`forward_dynamics` on arrays of shape (B, 10): the compiled kernel on blocks of {_block()} states "
             f"shared among numba's threads ({_threads()} here); the peers are called state by state from a Python "
             "loop. All columns measured interleaved; ratios: median of per-round ratios (and of the best "
             "blocks).\n"]
    lines += _batch_table(rows)
    text = "\n".join(lines) + "\n"
    atomic_write(out / "batch.md", text)
    return text


def scaling_pair(rows):
    """``(a, b)``: the sizes for the scaling ratio t(b)/t(a): (50, 200) if measured, else the largest and ~b/4."""
    Ns = [r["N"] for r in rows]
    if 50 in Ns and 200 in Ns:
        return 50, 200
    if len(Ns) < 2:
        return None
    b = max(Ns)
    a = min((n for n in Ns if n < b), key=lambda n: abs(np.log(n / (b / 4))))
    return a, b


def scaling_ratios(rows) -> dict:
    """``{name: t(b)/t(a)}`` for every method and peer, with ``(a, b)`` from :func:`scaling_pair`."""
    pair = scaling_pair(rows)
    if pair is None:
        return {}
    by = {r["N"]: r for r in rows}
    ta, tb = by[pair[0]]["times"], by[pair[1]]["times"]
    return {n: float(tb[n] / ta[n]) for n in ta if n in tb and np.isfinite(ta[n]) and np.isfinite(tb[n])}


def _scaling_table(rows) -> list:
    pair = scaling_pair(rows)
    if pair is None:
        return ["(one size only: no scaling ratio)", ""]
    a, b = pair
    rat = scaling_ratios(rows)
    k = b / a
    lines = [f"t({b}) / t({a}) per method; O(N) would give {k:g}, O(N²) {k * k:g}, O(N³) {k ** 3:g}. "
             "The exponent is log(ratio) / log(" + f"{k:g}" + ").\n",
             f"| method | t({a}) µs | t({b}) µs | t({b}) / t({a}) | exponent |", "|---|---:|---:|---:|---:|"]
    by = {r["N"]: r for r in rows}
    for n, x in rat.items():
        lines.append(f"| {_peer_label(n)} | {_fmt_us(by[a]['times'][n])} | {_fmt_us(by[b]['times'][n])} | "
                     f"{x:.1f} | {np.log(x) / np.log(k):.2f} |")
    return lines + [""]


# --------------------------------------------------------------------------- RESULTS.md
def headline(single, batch, startup=None) -> dict:
    """The headline numbers.

    ``{"batch": {peer: stats}, "B": B, "single": {peer: stats}, "single_random": ...,
    "single_200": ..., "scaling": ..., "startup": ...}`` (N = 10 unless said).
    """
    h = {"startup": startup or {}}
    if batch:
        big = max(batch, key=lambda r: r["B"])
        h["B"], h["batch"] = big["B"], big.get("ratio", {})
    r10 = next((r for r in single if r["N"] == 10), None)
    if r10 is not None:
        h["single"] = {p: r10[k] for p, k in (("pinocchio", "ratio"), ("mujoco", "ratio_mj")) if k in r10}
        h["single_random"] = {p: r10[k] for p, k in (("pinocchio", "ratio_random"), ("mujoco", "ratio_mj_random"))
                              if k in r10}
        if "ratio_mj_pin" in r10:
            h["mujoco/pinocchio"] = r10["ratio_mj_pin"]
    r200 = next((r for r in single if r["N"] == 200), None)
    if r200 is not None and "ratio" in r200:
        h["single_200"] = r200["ratio"]
    h["scaling_pair"] = scaling_pair(single)
    h["scaling"] = scaling_ratios(single)
    return h


def _goal(x, goal):
    return f"≤ {goal:g}× ({'met' if x <= goal else 'not met'})"


def write_results(single, batch, out: Path, summary: Path, charts: bool = True, quick: bool = False,
                  startup=None) -> str:
    """The summary document ``summary`` (RESULTS.md): headline ratios, tables, links to charts and other results."""
    out, summary = Path(out), Path(summary)
    rel = Path(os.path.relpath(out, summary.parent)).as_posix()
    h = headline(single, batch, startup)
    L = [_header("Benchmark results: planargeo forward dynamics against Pinocchio and MuJoCo").rstrip(), ""]
    if quick:
        L += ["**Quick run** (`--quick`: fewer sizes, short budgets, smaller batches): numbers are rough.", ""]
    L += ["## Headline", "",
          "| quantity | measured (median of interleaved rounds; best blocks) | goal |", "|---|---|---|"]
    for p, st in h.get("batch", {}).items():
        L.append(f"| batch, N = 10, B = {h['B']}: one `forward_dynamics` call / {_peer_label(p)} "
                 f"looped, per state (wall clock, {_threads()} threads) | **{_x(st['median'])}** ({_x(st['best'])}) | "
                 + (_goal(st["median"], 0.10) if p == "pinocchio" else "—") + " |")
    for p, st in h.get("single", {}).items():
        rnd = h["single_random"].get(p)
        L.append(f"| single call, N = 10: `aba` / {_peer_label(p)}, `chain_model` | **{_x(st['median'])}** "
                 f"({_x(st['best'])}) | " + (_goal(st["median"], 1.0) if p == "pinocchio" else "—") + " |")
        if rnd:
            L.append(f"| single call, N = 10: `aba` / {_peer_label(p)}, `random_model` | {_x(rnd['median'])} "
                     f"({_x(rnd['best'])}); {rnd['median'] / st['median']:.2f}× the chain's | "
                     + (_goal(rnd["median"] / st["median"], 1.5) + " of the chain's" if p == "pinocchio" else "—")
                     + " |")
    if "single_200" in h:
        st = h["single_200"]
        L.append(f"| single call, N = 200: `aba` / pin.aba, `chain_model` | **{_x(st['median'])}** ({_x(st['best'])}) "
                 f"| {_goal(st['median'], 0.5)} |")
    if "mujoco/pinocchio" in h:
        st = h["mujoco/pinocchio"]
        L.append(f"| single call, N = 10: mj_forward / pin.aba (the peers against each other) | {_x(st['median'])} "
                 f"({_x(st['best'])}) | — |")
    if h["scaling"]:
        a, b = h["scaling_pair"]
        L.append(f"| t({b}) / t({a}) (O(N): {b / a:g}, O(N³): {(b / a) ** 3:g}) | "
                 + ", ".join(f"{_peer_label(n)} {x:.1f}" for n, x in h["scaling"].items()) + " | — |")
    for key, what, goal in STARTUP_ROWS:
        if key in h["startup"]:
            L.append(f"| {what} | {h['startup'][key]:.2f} s | " + (f"≤ {goal:g} s ({'met' if h['startup'][key] <= goal else 'not met'})" if goal else "—") + " |")
    if h["startup"]:
        L.append(f"| `import planargeo` imports numba | {h['startup']['import_loads_numba']} | no |")
    L += ["", "Ratios below 1 mean planargeo is faster. All ratios come from one run on one machine, so they are "
          "comparable with each other; absolute times are not comparable across runs.", ""]
    if charts:
        L += ["## Charts", "",
              f"* [scaling]({rel}/scaling.svg): time per call against N, every method and peer, with O(N) and "
              "O(N³) guides.",
              f"* [work–precision]({rel}/work_precision.svg): one panel per N, each method a point (time, error "
              "against the reference).",
              f"* [speed against accuracy]({rel}/speed_accuracy.svg): the same points, each method a line through N.",
              f"* [single state]({rel}/single_state.svg): time per call and ratio to Pinocchio.",
              f"* [batch]({rel}/batch.svg): time per state against batch size.",
              "", f"![scaling]({rel}/scaling.svg)", "", f"![work-precision]({rel}/work_precision.svg)", ""]
    L += ["## Single call: ratios to Pinocchio and MuJoCo (interleaved)", ""] + _single_tables(single)
    L += ["## Single call: time per call (µs)", "",
          "`chain_model(N)`, one random state; every planargeo method, `pin.aba` and `mj_forward`.", ""]
    L += _time_table(single)
    L += ["## Accuracy: error against the extended-precision reference", "",
          "max|q̈ − q̈_ref| / max|q̈_ref| for the states above. Reference: `reference_system` of "
          "`benchmarks/reference.py` (the breakdown study's independent reference: the joint-space equations "
          f"written from world-frame Jacobians, solved in exact rational arithmetic for N ≤ {EXACT_MAX}, in "
          "`np.longdouble` beyond; `ld ±e`: its own error estimated by reversing the elimination order; `≲`: "
          "below 3× that, not resolved). Errors against the dense solve and against Pinocchio: "
          f"[accuracy.md]({rel}/accuracy.md).", ""]
    L += _accuracy_table(single)
    L += ["## Batched sweeps (N = 10)", "",
          "Time per state (wall clock) for B random states: one planargeo call on the batch against the peers called state by "
          "state from a Python loop (all measured interleaved).", ""]
    L += _batch_table(batch) if batch else ["(not run)", ""]
    L += ["## Scaling", ""] + _scaling_table(single)
    L += ["## Other results", ""]
    for fname, what in (("single_state.md", "single call tables"), ("accuracy.md", "errors against the reference, "
                                                                                     "CRBA and Pinocchio"),
                        ("batch.md", "batch throughput")) + OTHER_RESULTS:
        L.append(f"* [{fname}]({rel}/{fname}): {what}")
    L += ["", "## How it is measured", "",
          "`planargeo bench` (`make bench`; `--quick` for a rough run under a minute). Single calls in thread CPU "
          "time (`time.thread_time`), batches in wall-clock time (the batch kernel runs on numba's threads), BLAS "
          "single-threaded. `aba`, `pin.aba` and `mj_forward` are interleaved in short blocks; the batched columns "
          "too. The startup rows are wall-clock times of fresh processes (best of 3): the first call compiles the "
          "kernels into an empty numba cache (`NUMBA_CACHE_DIR`), then a second process loads them from it. "
          "Models are identical: `to_pinocchio` and `to_mujoco` "
          "(`benchmarks/bench.py`) build the same mechanism (MuJoCo: explicit `<inertial>`, contacts disabled, "
          "gravity set explicitly, armature and damping zero, no geoms); the peers' q̈ are in the accuracy table. "
          "`mj_forward` is timed with setting `qpos`, `qvel`, `qfrc_applied` from the state, as `pin.aba` takes "
          "q, q̇, τ as arguments. Raw numbers: " + f"[dynamics.json]({rel}/dynamics.json).", ""]
    text = "\n".join(L)
    atomic_write(summary, text)
    return text


# --------------------------------------------------------------------------- charts
def _colours(names):
    import matplotlib.pyplot as plt

    cycle = plt.rcParams["axes.prop_cycle"].by_key()["color"]
    fixed = {"aba": 0, "projective": 1, "mobility_split": 2, "stacked": 3, "crba": 4, "pinocchio": 7, "mujoco": 9}
    return {n: cycle[fixed.get(n, k) % len(cycle)] for k, n in enumerate(names)}


MARKERS = {"aba": "o", "projective": "s", "mobility_split": "^", "stacked": "D", "crba": "x", "pinocchio": "P",
           "mujoco": "*"}


def _save(fig, out: Path, name: str, rect=(0, 0, 1, 1)):
    """Lay out (minor ticks off: on log axes they are thousands of labels to measure) and write SVG + PNG."""
    import matplotlib.pyplot as plt

    for a in fig.axes:
        a.minorticks_off()
    fig.tight_layout(rect=rect)
    svg, png = io.BytesIO(), io.BytesIO()
    with plt.rc_context({"svg.hashsalt": "planargeo"}):      # deterministic ids: identical bytes on a rerun
        fig.savefig(svg, format="svg", metadata={"Date": None})
    fig.savefig(png, format="png", dpi=110)
    plt.close(fig)
    atomic_write_many({out / f"{name}.svg": svg.getvalue(), out / f"{name}.png": png.getvalue()})


def _errors(r):
    """``{name: error}`` against the reference if there is one, else against CRBA (strings dropped)."""
    e = r["err_ref"] if r.get("ref") else r["err_crba"]
    return {k: v for k, v in e.items() if not isinstance(v, str)}


def write_charts(single, batch, out: Path) -> None:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    Ns = [r["N"] for r in single]
    names = list(single[0]["times"])
    colour = _colours(names)
    lab = {n: _peer_label(n) for n in names}

    # single state: time and ratio to Pinocchio
    fig, ax = plt.subplots(1, 2, figsize=(11, 4.2))
    for n in names:
        ts = np.array([r["times"][n] for r in single]) * 1e6
        ax[0].loglog(Ns, ts, MARKERS.get(n, "o") + "-", label=lab[n], color=colour[n])
        if "pinocchio" in names and n != "pinocchio":
            ax[1].loglog(Ns, ts / (np.array([r["times"]["pinocchio"] for r in single]) * 1e6),
                         MARKERS.get(n, "o") + "-", label=lab[n], color=colour[n])
    ax[0].set(xlabel="N (links)", ylabel="µs per call", title="Single state: time per call")
    ax[1].set(xlabel="N (links)", ylabel="time / pin.aba", title="Single state: ratio to Pinocchio")
    for a in ax:
        a.grid(True, which="major", alpha=0.3)
        a.legend(fontsize=8)
    _save(fig, out, "single_state")

    # scaling: time vs N with O(N) and O(N^3) guides
    fig, ax = plt.subplots(figsize=(7, 5))
    rat = scaling_ratios(single)
    pair = scaling_pair(single)
    for n in names:
        ts = np.array([r["times"][n] for r in single]) * 1e6
        extra = f"  (t{pair[1]}/t{pair[0]} = {rat[n]:.1f})" if n in rat else ""
        ax.loglog(Ns, ts, MARKERS.get(n, "o") + "-", label=lab[n] + extra, color=colour[n])
    all_t = np.array([[r["times"][n] for n in names] for r in single]) * 1e6
    lo, hi = np.nanmin(all_t), np.nanmax(all_t)
    if len(Ns) > 1:
        # guides through one point below the curves at the largest N: the slopes compare where it matters
        Ng = np.geomspace(min(Ns), max(Ns), 50)
        anchor = np.exp(np.nanmean(np.log(all_t[-1]))) / 3
        for p, ls, txt, at in ((1, "--", "O(N)", 25), (3, ":", "O(N³)", 38)):
            g = anchor * (Ng / Ng[-1]) ** p
            ax.loglog(Ng, g, "k" + ls, lw=1.2, alpha=0.6, label=f"{txt} guide")
            ax.annotate(txt, (Ng[at], g[at]), fontsize=9, color="0.3", xytext=(6, -4), textcoords="offset points")
    ax.set_ylim(lo / 2, hi * 4)
    ax.set(xlabel="N (links)", ylabel="µs per call (thread CPU time)",
           title="Forward dynamics of an N-link chain: time per call")
    ax.grid(True, which="major", alpha=0.3)
    ax.legend(fontsize=8, loc="upper left")
    _save(fig, out, "scaling")

    # batch throughput
    Bs = [r["B"] for r in batch]
    fig, ax = plt.subplots(figsize=(6.5, 4.5))
    for n in batch[0]["times"]:
        ax.loglog(Bs, [r["times"][n] / r["B"] * 1e6 for r in batch], "o-", label=n)
    ax.set(xlabel="batch size B (states)", ylabel="µs per state", title="Batch throughput, N = 10")
    ax.grid(True, which="major", alpha=0.3)
    ax.legend(fontsize=8)
    _save(fig, out, "batch")

    # speed against accuracy: each method a line through N
    floor = 1e-17
    ref_lab = "reference" if single[0].get("ref") else "CRBA"
    fig, ax = plt.subplots(figsize=(7, 5))
    for n in names:
        pts = [(r["times"][n] * 1e6, max(_errors(r)[n], floor)) for r in single
               if n in _errors(r) and np.isfinite(r["times"][n])]
        if pts:
            x, y = zip(*pts)
            ax.loglog(x, y, MARKERS.get(n, "o") + "-", label=lab[n], color=colour[n])
            ax.annotate(f"N={single[-1]['N']}" if len(pts) == len(single) else "", pts[-1], fontsize=7,
                        color=colour[n], xytext=(3, 3), textcoords="offset points")
    ax.set(xlabel="µs per call (N = " + ", ".join(map(str, Ns)) + ")", ylabel=f"relative error vs {ref_lab}",
           title="Speed against accuracy (each line: one method through N)")
    ax.grid(True, which="major", alpha=0.3)
    ax.legend(fontsize=8)
    _save(fig, out, "speed_accuracy")

    # work-precision: one panel per N, each method a point
    k = len(single)
    ncol = min(4, k)
    nrow = -(-k // ncol)
    fig, axes = plt.subplots(nrow, ncol, figsize=(3.3 * ncol, 3.0 * nrow + 0.6), squeeze=False)
    for a, r in zip(axes.flat, single):
        err = _errors(r)
        for n in names:
            if n in err and np.isfinite(r["times"][n]):
                a.loglog(r["times"][n] * 1e6, max(err[n], floor), MARKERS.get(n, "o"), color=colour[n],
                         label=lab[n], ms=7)
        spread = r.get("ref", {}).get("spread", 0.0)
        if spread:
            a.axhspan(floor, 3 * spread, color="0.85", zorder=0)
        a.set_title(f"N = {r['N']}" + (" (exact reference)" if r.get("ref", {}).get("mode") == "exact" else ""),
                    fontsize=10)
        a.grid(True, which="major", alpha=0.3)
        a.set_ylim(floor / 3, None)
    for a in axes.flat[k:]:
        a.axis("off")
    for a in axes[-1]:
        a.set_xlabel("µs per call")
    for a in axes[:, 0]:
        a.set_ylabel(f"rel. error vs {ref_lab}")
    handles, labels = axes.flat[0].get_legend_handles_labels()
    from matplotlib.patches import Patch

    handles.append(Patch(color="0.85"))
    labels.append("below 3× the reference's own error")
    fig.legend(handles, labels, loc="upper center", ncol=len(labels), fontsize=8, frameon=False)
    fig.text(0.005, 0.005, f"exact zeros plotted at {floor:g}", fontsize=7, color="0.4")
    _save(fig, out, "work_precision", rect=(0, 0, 1, 1 - 0.5 / (3.0 * nrow + 0.6)))


def copy_to_gallery(out: Path, gallery: Path, names=None) -> list:
    """Copy the SVG charts of ``out`` (``names``, default every ``*.svg``) into ``gallery``; return the copied names."""
    paths = [Path(out) / f"{n}.svg" for n in names] if names else sorted(Path(out).glob("*.svg"))
    paths = [p for p in paths if p.exists()]
    atomic_write_many({Path(gallery) / p.name: p.read_bytes() for p in paths})
    return [p.name for p in paths]


def _jsonable(x):
    if isinstance(x, dict):
        return {str(k): _jsonable(v) for k, v in x.items()}
    if isinstance(x, (list, tuple)):
        return [_jsonable(v) for v in x]
    if isinstance(x, (np.floating, float)):
        return float(x) if np.isfinite(x) else None
    if isinstance(x, np.integer):
        return int(x)
    return x


# --------------------------------------------------------------------------- main
_THREAD_VARS = ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS")


def _single_threaded_argv(args):
    """argv to re-run this benchmark with single-threaded BLAS, or None if it already is."""
    if all(os.environ.get(v) == "1" for v in _THREAD_VARS):
        return None
    argv = [sys.executable, str(Path(__file__).with_name("run.py")), "--out", str(args.out)]
    argv += ["--sizes", str(args.sizes)] if getattr(args, "sizes", None) else []
    argv += ["--quick"] * bool(args.quick) + ["--no-charts"] * bool(args.no_charts)
    for group in getattr(args, "only", None) or ():
        argv += ["--only", group]
    if getattr(args, "summary", None):
        argv += ["--summary", str(args.summary)]
    if getattr(args, "gallery", ""):
        argv += ["--gallery", str(args.gallery)]
    return argv


def run_dynamics(args, out: Path):
    """The dynamics group: startup, single-state, accuracy and batch tables, raw JSON and charts.

    Returns ``(single, batch, startup)``.
    """
    sizes = (tuple(int(s) for s in str(args.sizes).split(",") if s.strip()) if args.sizes
             else (QUICK_SIZES if args.quick else SINGLE_SIZES))
    budget = 0.04 if args.quick else 0.5
    rounds = 12 if args.quick else 40
    batches = QUICK_BATCH_SIZES if args.quick else BATCH_SIZES
    startup = run_startup(1 if args.quick else 3)
    single = run_single(sizes, budget, rounds=rounds)
    print(write_single(single, out))
    print(write_accuracy(single, out))
    batch = run_batch(batches, budget, rounds=3 if args.quick else 9)
    print(write_batch(batch, out))
    atomic_write(out / "dynamics.json", json.dumps(_jsonable({"versions": _versions(), "quick": bool(args.quick),
                                                              "single": single, "batch": batch,
                                                              "startup": startup}), indent=1))
    if not args.no_charts:
        _progress("[charts] scaling, work_precision, speed_accuracy, single_state, batch ...")
        write_charts(single, batch, out)
        print(f"charts written to {out}/" + ", ".join(f"{c}.svg" for c in CHARTS) + " (+ .png)")
    return single, batch, startup


def _summarise(args, out: Path, single, batch, startup) -> None:
    summary = Path(args.summary) if getattr(args, "summary", None) else out / "RESULTS.md"
    write_results(single, batch, out, summary, charts=not args.no_charts, quick=args.quick, startup=startup)
    _progress(f"[results] {summary}")
    h = headline(single, batch, startup)
    for key, what, _ in STARTUP_ROWS:
        _progress(f"[headline] {what}: {startup[key]:.2f} s")
    for p, st in h.get("batch", {}).items():
        _progress(f"[headline] batch N=10 B={h['B']}: aba / {_peer_label(p)} loop {_x(st['median'])}")
    for p, st in h.get("single", {}).items():
        _progress(f"[headline] single N=10: aba / {_peer_label(p)} {_x(st['median'])}")
    if h["scaling"]:
        a, b = h["scaling_pair"]
        _progress(f"[headline] t({b})/t({a}): " + ", ".join(f"{_peer_label(n)} {x:.1f}"
                                                           for n, x in h["scaling"].items()))


def main(args) -> int:
    # Pinocchio is single-threaded; multi-threaded BLAS on a busy machine makes small dense solves
    # (CRBA) erratic, so every method runs with one BLAS thread: re-run in a fresh process if needed.
    argv = _single_threaded_argv(args)
    if argv is not None:
        env = dict(os.environ, **{v: "1" for v in _THREAD_VARS})
        return subprocess.call(argv, env=env)
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    explicit = set(getattr(args, "only", None) or ())
    groups = explicit or set(GROUPS)
    rc = 0
    dynamics = run_dynamics(args, out) if "dynamics" in groups else None
    scripts = Path(__file__).resolve().parents[1] / "benchmarks"
    for group, script in SCRIPTS.items():
        if group not in groups:
            continue
        path = scripts / script
        if not path.exists():
            _progress(f"[{group}] skipping: {path} not found (not written yet, or not a source checkout)")
            continue
        cmd = [sys.executable, str(path)]
        source = path.read_text(encoding="utf-8")
        if '"--out"' in source:          # the script takes an output folder: the same as ours
            cmd += ["--out", str(out.resolve())]
        if args.quick:
            if '"--quick"' in source:
                cmd.append("--quick")
            elif group not in explicit:
                _progress(f"[{group}] skipping in --quick mode: {script} has no --quick "
                          f"(run `planargeo bench --only {group}`)")
                continue
            else:
                _progress(f"[{group}] {script} has no --quick: running it in full")
        _progress(f"[{group}] running python {' '.join(cmd[1:])} ...")
        code = subprocess.call(cmd, cwd=str(scripts.parent), env=dict(os.environ, MPLBACKEND="Agg"))
        if code:
            _progress(f"[{group}] {script} exited with {code}")
        rc |= code
    if dynamics is not None:     # last, so that it links the other groups' fresh results
        _summarise(args, out, *dynamics)
    if not args.no_charts and getattr(args, "gallery", ""):
        copied = copy_to_gallery(out, Path(args.gallery))
        if copied:
            _progress(f"[gallery] copied {len(copied)} SVG charts to {args.gallery}/")
    _progress("done")
    return rc


if __name__ == "__main__":  # pragma: no cover
    p = argparse.ArgumentParser()
    add_arguments(p)
    raise SystemExit(main(p.parse_args()))
