"""The entry points the fuzz suite calls, grouped by area, each with its argument strategy.

Functions of the array modules are fuzzed by signature (:func:`signature_targets`: every public
function in the module's ``__all__``, its arguments drawn by name from
:data:`fuzz.strategies.BY_NAME`); the rest (classes, models and states, scenes, simulations, the
command line, the explorers, file output) are written out here.

>>> groups = {t.group for t in all_targets()}
>>> sorted(groups)  # doctest: +NORMALIZE_WHITESPACE
['algorithms', 'cli', 'explorers', 'files', 'geometry', 'kernels', 'mechanics', 'scenes', 'screws',
 'simulate']
"""
from __future__ import annotations

import atexit
import contextlib
import importlib
import inspect
import io
import itertools
import math
import shutil
import tempfile
from pathlib import Path

import hypothesis.strategies as st
import numpy as np

from fuzz import strategies as S
from fuzz.harness import FOREIGN, INCONSISTENT, NONFINITE, OK, PACKAGE, Target

#: Modules fuzzed by signature, with their group.
SIGNATURE_MODULES = {
    "planargeo.geometry.projective": "geometry",
    "planargeo.geometry.conics": "geometry",
    "planargeo.screws.twists": "screws",
    "planargeo.screws.inertia": "screws",
    "planargeo.mechanics.joints": "mechanics",
    "planargeo.mechanics.subspaces": "mechanics",
}


def _ideal_point(x) -> bool:
    a = np.asarray(x) if isinstance(x, (list, tuple, np.ndarray)) else None
    try:
        return a is not None and a.shape[-1:] == (3,) and bool(np.any(np.asarray(a[..., 2], float) == 0))
    except (TypeError, ValueError):
        return False


def _line_at_infinity(x) -> bool:
    a = np.asarray(x) if isinstance(x, (list, tuple, np.ndarray)) else None
    try:
        return a is not None and a.shape[-1:] == (3,) and bool(np.any(
            (np.asarray(a[..., 0], float) == 0) & (np.asarray(a[..., 1], float) == 0)))
    except (TypeError, ValueError):
        return False


def _any_ideal(args, kwargs, out) -> bool:
    """Documented: points at infinity / the line at infinity give NaN or ±inf coordinates."""
    vals = list(args) + list(kwargs.values())
    return any(_ideal_point(v) or _line_at_infinity(v) for v in vals)


def _always(args, kwargs, out) -> bool:
    """``direction`` of a finite point is NaN (documented)."""
    return True


def _nan_where_not_real(args, kwargs, out) -> bool:
    """``line_conic_intersections``: NaN rows exactly where ``real`` is False (documented)."""
    X, real = out
    X = np.asarray(X).reshape(np.shape(real) + (2, 3))
    return bool(np.all(np.isnan(X[~np.asarray(real)])) and np.all(np.isfinite(X[np.asarray(real)])))


def _asked_for_nan(args, kwargs, out) -> bool:
    """``on_interior="nan"`` / ``on_miss="nan"``: NaN elements were asked for."""
    return "nan" in (kwargs.get("on_interior"), kwargs.get("on_miss"))


#: Entry points whose documentation promises non-finite values for some finite input.
NONFINITE_OK = {
    "line_conic_intersections": _nan_where_not_real, "tangents_from_point": _asked_for_nan,
    "polar_construction_exterior": _asked_for_nan, "polar_construction_interior": _asked_for_nan,
    "to_xy": _any_ideal, "signed_distance": _any_ideal, "line_direction": _any_ideal,
    "foot_point": _any_ideal, "direction": _always, "pole_xy": _any_ideal,
    "wrench_axis": _any_ideal, "cross_cond": lambda a, k, out: bool(np.all(np.isinf(out) | np.isfinite(out))),
    "joint_cond": lambda a, k, out: bool(np.all(np.isinf(out) | np.isfinite(out))),   # inf: exactly singular
}


def _signature_strategy(fn, overrides=None):
    """``(args, kwargs)`` for ``fn``: its required arguments always, each optional one at times."""
    overrides = overrides or {}
    req, opt = {}, {}
    for name, p in inspect.signature(fn).parameters.items():
        if p.kind in (p.VAR_POSITIONAL, p.VAR_KEYWORD):
            continue
        strat = overrides.get(name, S.BY_NAME.get(name, S.anything))
        (req if p.default is p.empty else opt)[name] = strat
    return st.fixed_dictionaries(req, optional=opt).map(lambda kw: ((), kw))


def signature_targets(module: str, group: str, overrides=None) -> list[Target]:
    mod = importlib.import_module(module)
    out = []
    for name in getattr(mod, "__all__", ()):
        fn = getattr(mod, name, None)
        if not inspect.isfunction(fn):
            continue
        short = module.rsplit(".", 1)[1]
        out.append(Target(f"{short}.{name}", fn, _signature_strategy(fn, (overrides or {}).get(name)),
                          group=group, nonfinite_ok=NONFINITE_OK.get(name)))
    return out


#: Per-function argument overrides where a name means something else than usual.
OVERRIDES = {
    "conic_from_coefficients": {k: S.scalars for k in "abcdef"},
    "conic_from_affine": {"A": S.mat(2, 2), "t": S.xy},
    "polygon_moments": {"geometry": st.one_of(
        st.just([(0.0, 0.0), (1.0, 0.0), (0.0, 1.0)]), st.lists(st.tuples(S.reals, S.reals), max_size=5),
        S.junk)},
    "kappa": {"qd": st.one_of(S.scalars, S.vec(2))},
    "polar_construction_interior": {"lines": st.one_of(st.none(), S.lines, S.junk)},
    "joint_cond": {k: S.scalars for k in ("smin", "A_norm2", "s_norm2")},
}


# --------------------------------------------------------------------------- the thin classes
def _method(cls_factory, method, arg_strats, name, group):
    """Target ``getattr(make(), method)(*args)`` with ``make`` a valid object."""
    def call(obj, *args):
        return getattr(obj, method)(*args)

    strat = st.tuples(cls_factory, *arg_strats).map(lambda t: (t, {}))
    return Target(name, call, strat, group=group, nonfinite_ok=_any_ideal)


def class_targets() -> list[Target]:
    import planargeo as pg

    good_point = st.tuples(S.finite, S.finite).map(lambda xy: pg.Point.from_xy(*xy))
    good_line = st.tuples(S.finite, S.finite, S.finite).filter(lambda f: f[0] or f[1]).map(
        lambda f: pg.Line(np.array(f)))
    conic = st.sampled_from([pg.Conic.circle((0, 0), 1.0), pg.Conic.ellipse((1, 0), (2, 1), 0.3),
                             pg.Conic.hyperbola((0, 0), (1, 2)), pg.Conic.parabola((0, 0), 1.0),
                             pg.Conic(np.diag([1.0, 1.0, 0.0])), pg.Conic(np.diag([1.0, 0.0, 0.0]))])
    inertia = st.sampled_from([pg.Inertia.from_mass(1.0, (0.5, 0.0), 0.3), pg.Inertia.from_mass(2.0, (0.0, 0.0), 0.1)])
    twist = st.sampled_from([pg.Twist.rotation((1.0, 2.0), 3.0), pg.Twist.translation((1.0, 0.0))])
    G = "geometry"
    return [
        Target("Point", pg.Point, st.tuples(S.points).map(lambda t: (t, {})), group=G),
        Target("Point.from_xy", pg.Point.from_xy, st.tuples(S.scalars, S.scalars).map(lambda t: (t, {})), group=G),
        Target("Point.at_infinity", pg.Point.at_infinity, st.tuples(S.xy).map(lambda t: (t, {})), group=G),
        Target("Line", pg.Line, st.tuples(S.lines).map(lambda t: (t, {})), group=G),
        Target("Line.from_point_direction", pg.Line.from_point_direction,
               st.tuples(S.xy, S.xy).map(lambda t: (t, {})), group=G),
        Target("Conic", pg.Conic, st.tuples(S.conics).map(lambda t: (t, {})), group=G),
        Target("Conic.circle", pg.Conic.circle, st.tuples(S.xy, S.scalars).map(lambda t: (t, {})), group=G),
        _method(good_point, "join", [st.one_of(good_point, S.points)], "Point.join", G),
        _method(good_point, "distance_to", [st.one_of(good_line, S.lines)], "Point.distance_to", G),
        _method(good_line, "meet", [st.one_of(good_line, S.lines)], "Line.meet", G),
        _method(conic, "tangents_from", [st.one_of(good_point, S.points)], "Conic.tangents_from", G),
        _method(conic, "pole", [st.one_of(good_line, S.lines)], "Conic.pole", G),
        _method(conic, "polar", [st.one_of(good_point, S.points)], "Conic.polar", G),
        _method(conic, "contains", [S.points], "Conic.contains", G),
        Target("Twist.rotation", pg.Twist.rotation, st.tuples(S.xy, S.scalars).map(lambda t: (t, {})), group="screws"),
        Target("Twist.translation", pg.Twist.translation, st.tuples(S.xy).map(lambda t: (t, {})), group="screws"),
        Target("Wrench.force", pg.Wrench.force, st.tuples(S.xy, S.xy).map(lambda t: (t, {})), group="screws"),
        Target("Wrench.couple", pg.Wrench.couple, st.tuples(S.scalars).map(lambda t: (t, {})), group="screws"),
        Target("Inertia.from_mass", pg.Inertia.from_mass,
               st.tuples(S.positive, S.xy, S.positive).map(lambda t: (t, {})), group="screws"),
        Target("Inertia", pg.Inertia, st.tuples(S.inertias).map(lambda t: (t, {})), group="screws"),
        _method(inertia, "percussion_axis", [S.points], "Inertia.percussion_axis", "screws"),
        _method(inertia, "percussion_pole", [S.lines], "Inertia.percussion_pole", "screws"),
        _method(inertia, "kinetic_energy", [S.points], "Inertia.kinetic_energy", "screws"),
        _method(twist, "power", [S.lines], "Twist.power", "screws"),
        Target("add_twists", pg.add_twists, st.tuples(S.points, S.points).map(lambda t: (t, {})), group="screws"),
        Target("add_wrenches", pg.add_wrenches, st.tuples(S.lines, S.lines).map(lambda t: (t, {})), group="screws"),
    ]


# --------------------------------------------------------------------------- models, states, joints, contacts
KINDS = ("revolute", "prismatic", "revolute_prismatic", "twin_prismatic", "plane", "fixed")


def _models():
    from planargeo.mechanics.model import chain_model, random_model

    chains = st.builds(chain_model, st.integers(1, 4), st.floats(0.1, 10), st.floats(0.1, 3),
                       st.sampled_from(["revolute", "prismatic"]))
    rand = st.builds(lambda n, seed, kinds, tree: random_model(n, seed, kinds=kinds, tree=tree),
                     st.integers(1, 4), st.integers(0, 10**6),
                     st.lists(st.sampled_from(KINDS[:5]), min_size=1, max_size=3).map(tuple), st.booleans())
    return st.one_of(chains, chains, rand)


def _state_vec(nq):
    good = S._array((nq,), S.reals)
    return st.one_of(good, good, good, good, st.just(np.zeros(nq)), st.just(None), S.vec(nq),
                     st.integers(1, 3).flatmap(lambda k: S._array((k, nq), S.reals)))


def _dyn(name, fn, group="kernels", extra=("qd", "tau")):
    """``fn(model, q, *extra)`` on a model with a state of the right length (hostile variants included)."""
    def strat(model):
        vecs = [_state_vec(model.nq) for _ in ("q",) + tuple(extra)]
        return st.tuples(st.just(model), *vecs).map(lambda t: (t, {}))

    return Target(name, fn, _models().flatmap(strat), group=group, timeout=10.0)


def kernel_targets() -> list[Target]:
    from planargeo.algorithms.aba import articulated_body, forward_dynamics
    from planargeo.algorithms.chain_splitting import forward_dynamics_mobility_split
    from planargeo.algorithms.crba import bias_forces, forward_dynamics_crba, mass_matrix
    from planargeo.algorithms.projective import forward_dynamics_projective
    from planargeo.algorithms.rnea import inverse_dynamics
    from planargeo.algorithms.stacked import forward_dynamics_stacked
    from planargeo.mechanics.kinematics import kinematics
    from planargeo.mechanics.model import chain_model, random_model

    return [
        _dyn("forward_dynamics", forward_dynamics),
        _dyn("articulated_body", articulated_body),
        _dyn("inverse_dynamics", inverse_dynamics, extra=("qd", "qdd")),
        _dyn("forward_dynamics_crba", forward_dynamics_crba),
        _dyn("mass_matrix", mass_matrix, extra=()),
        _dyn("bias_forces", bias_forces, extra=("qd",)),
        _dyn("kinematics", kinematics, extra=("qd",)),
        _dyn("forward_dynamics_projective", forward_dynamics_projective, group="algorithms"),
        _dyn("forward_dynamics_stacked", forward_dynamics_stacked, group="algorithms"),
        _dyn("forward_dynamics_mobility_split", forward_dynamics_mobility_split, group="algorithms"),
        Target("chain_model", chain_model, st.fixed_dictionaries(
            {"n": S.ints}, optional={"mass": S.positive, "length": S.positive,
                                     "joint": S.choice(*KINDS), "gravity": S.vec(2)}).map(lambda kw: ((), kw)),
               group="kernels", timeout=10.0),
        Target("random_model", random_model, st.fixed_dictionaries(
            {"n": S.ints}, optional={"seed": S.ints, "tree": st.one_of(st.booleans(), S.junk),
                                     "kinds": st.one_of(st.lists(S.choice(*KINDS), max_size=3).map(tuple), S.junk)}
        ).map(lambda kw: ((), kw)), group="kernels", timeout=10.0),
    ]


def mechanics_targets() -> list[Target]:
    from planargeo.mechanics.contacts import Contact

    contact = st.fixed_dictionaries(
        {"kind": S.choice("pin", "slider", "weld", "point"), "a": S.ints},
        optional={"b": S.ints, "point_a": S.xy, "point_b": S.xy, "direction": S.xy, "angle": S.scalars})
    return [Target("Contact", Contact, contact.map(lambda kw: ((), kw)), group="mechanics")]


# --------------------------------------------------------------------------- scenes
def _param_strategy(default):
    if isinstance(default, bool):
        return st.one_of(st.booleans(), S.junk, S.reals)
    if isinstance(default, int):
        return S.ints
    if isinstance(default, float):
        near = st.floats(min_value=-3 * abs(default) - 1, max_value=3 * abs(default) + 1)
        return st.one_of(near, near, near, S.reals, S.junk, st.sampled_from([10**7, 10**400, 1e300]))
    if isinstance(default, str):
        return st.one_of(st.sampled_from([default, "revolute", "prismatic", "free", "constant-speed", ""]), S.junk)
    return st.one_of(S.ints, S.junk)        # None defaults (seed)


def scene_targets() -> list[Target]:
    from planargeo import scenes

    out = []
    for name in scenes.names():
        params = scenes.parameters(name)
        strat = st.fixed_dictionaries({}, optional={k: _param_strategy(v) for k, v in params.items()})
        out.append(Target(f"scenes.build('{name}')", lambda _n=name, **kw: scenes.build(_n, **kw),
                          strat.map(lambda kw: ((), kw)), group="scenes", timeout=15.0))
    return out


# --------------------------------------------------------------------------- simulate
SIM_OPTIONS = {
    "method": S.choice("DOP853", "RK45", "RK23", "Radau", "BDF", "LSODA", "RK4"),
    "rtol": st.one_of(st.sampled_from([1e-6, 1e-8]), S.scalars, st.just(-1.0)),
    "atol": st.one_of(st.sampled_from([1e-8, 1e-10]), S.scalars),
    "dt": st.one_of(st.sampled_from([None, 0.01, 0.05]), S.scalars, st.just(1e-300)),
    "max_step": st.one_of(st.sampled_from([0.01, math.inf]), S.scalars, st.just(0.0)),
    "cond_event": S.scalars,
}
T_END = st.one_of(st.floats(0.01, 0.3), st.floats(0.01, 0.3), st.floats(0.01, 0.3), S.scalars)


def simulate_targets() -> list[Target]:
    from planargeo.mechanics.model import chain_model
    from planargeo.simulate.integrate import simulate

    def run(model, q0, qd0, t_end, **kw):
        return simulate(model, q0, qd0, t_end, progress=False, **kw)

    def strat(model):
        return st.tuples(st.just(model), _state_vec(model.nq), _state_vec(model.nq), T_END).flatmap(
            lambda a: st.fixed_dictionaries({}, optional=SIM_OPTIONS).map(lambda kw: (a, kw)))

    models = st.sampled_from([chain_model(1), chain_model(2), chain_model(2, joint="prismatic")])
    return [Target("simulate", run, models.flatmap(strat), group="simulate", timeout=20.0)]


def loops_targets() -> list[Target]:
    from planargeo import scenes
    from planargeo.simulate.loops import baumgarte, closure_residual, project_state, simulate_loops

    sc = scenes.build("slider-crank")
    model = sc.model

    def run(q0, qd0, t_end, **kw):
        return simulate_loops(model, q0, qd0, t_end, progress=False, **kw)

    q0, qd0 = np.asarray(sc.state["q"], float), np.asarray(sc.state["qd"], float)
    vec = st.one_of(st.just(q0), st.just(q0), _state_vec(model.nq))
    vecd = st.one_of(st.just(qd0), st.just(qd0), _state_vec(model.nq))
    opts = dict(SIM_OPTIONS, stabilization=S.choice("projection", "baumgarte", "both", "none"),
                alpha=S.scalars, beta=S.scalars, tol=S.tolerances, trigger=S.tolerances)
    strat = st.tuples(vec, vecd, T_END).flatmap(
        lambda a: st.fixed_dictionaries({}, optional=opts).map(lambda kw: (a, kw)))
    closure = st.tuples(vec, vecd).flatmap(lambda a: st.fixed_dictionaries(
        {}, optional={"fixed": st.one_of(st.lists(S.ints, max_size=3), S.junk), "tol": S.tolerances,
                      "max_iter": S.ints}).map(lambda kw: ((model,) + a, kw)))
    return [Target("simulate_loops", run, strat, group="simulate", timeout=20.0),
            Target("loops.project_state", project_state, closure, group="simulate"),
            Target("loops.closure_residual", closure_residual, vec.map(lambda q: ((model, q), {})), group="simulate"),
            Target("loops.baumgarte", lambda **kw: baumgarte(model, **kw)(0.0, q0, qd0, np.zeros(model.nq)),
                   st.fixed_dictionaries({}, optional={"alpha": S.scalars, "beta": S.scalars}).map(lambda kw: ((), kw)),
                   group="simulate")]


# --------------------------------------------------------------------------- command line
_TMP = None


def tmpdir() -> Path:
    """One scratch folder per process for the file-writing entry points."""
    global _TMP
    if _TMP is None:
        _TMP = Path(tempfile.mkdtemp(prefix="planargeo-fuzz-"))
        atexit.register(shutil.rmtree, _TMP, ignore_errors=True)
        (_TMP / "afile").write_text("x")
        (_TMP / "full").mkdir()
        (_TMP / "full" / "mine.txt").write_text("keep")
    return _TMP


_counter = itertools.count()


def _paths():
    """Output paths inside the scratch folder, plus hostile ones that can never write elsewhere."""
    fresh = st.builds(lambda: tmpdir() / f"out{next(_counter)}")
    named = st.sampled_from(["afile", "full", "full/mine.txt", "no/such/dir", "x" * 300, "a\0b", ".", ""]).map(
        lambda n: tmpdir() / n)
    return st.one_of(fresh, fresh, named, st.sampled_from(["/dev/full", "/", "/proc/nonexistent/x"]),
                     st.sampled_from([None, 3, b"\0"]))


def cli_main(argv):
    """``planargeo ARGV`` in-process: ``(status, stdout, stderr)``; argparse's exit is a status too."""
    from planargeo.cli import main

    out, err = io.StringIO(), io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
        try:
            code = main([str(a) for a in argv])
        except SystemExit as e:
            code = e.code if isinstance(e.code, int) else 2
    return code, out.getvalue(), err.getvalue()


def _cli_check(args, kwargs, result):
    """Status 0 with finite numbers, or 1 with one line on stderr, or argparse's usage error (2)."""
    code, out, err = result
    if "Traceback" in err or "Traceback" in out:
        return FOREIGN, f"a traceback (status {code}): {err[-300:]}"
    if code not in (0, 1, 2, 130):
        return FOREIGN, f"status {code!r}"
    if code == 1 and len(err.strip().splitlines()) != 1:
        return FOREIGN, f"status 1 with not one line on stderr: {err[:300]!r}"
    if code == 0 and any(w in out for w in ("NaN", "Infinity", " nan", " inf")):
        return NONFINITE, f"non-finite numbers printed: {out[:300]!r}"
    return (OK, "") if code == 0 else (PACKAGE, "")


def cli_targets() -> list[Target]:
    from planargeo import scenes

    names = scenes.names()

    def set_item(name):
        keys = list(scenes.parameters(name)) + ["nope", "", "n=2"]
        vals = st.one_of(st.sampled_from(["1", "0", "-1", "2.5", "1e300", "1e-300", "nan", "inf", "-inf", "true",
                                          "none", "[1, 2]", "[", "x", "", "1000000", "1e400", "3.5", "1j"]),
                         st.floats(-10, 10).map(repr))
        return st.tuples(st.sampled_from(keys), vals).map(lambda kv: ["--set", f"{kv[0]}={kv[1]}"])

    report = st.sampled_from(names + ["nope", ""]).flatmap(
        lambda n: st.tuples(st.lists(set_item(n) if n in names else set_item(names[0]), max_size=3),
                            st.booleans()).map(
            lambda t: ["report", n] + [x for item in t[0] for x in item] + (["--json"] if t[1] else [])))
    misc = st.sampled_from([["report", "--list"], ["report", "--list", "--json"], ["report"], [],
                            ["frobnicate"], ["report", "--set"], ["report", "chain", "--set", "n"],
                            ["bench", "--suite", "/nonexistent"], ["gallery", "--only", "no_such_figure"],
                            ["--version"], ["report", "chain", "--bogus"]])
    gallery = _paths().filter(lambda p: isinstance(p, (str, Path))).map(   # never a path relative to the cwd
        lambda p: ["gallery", "--out", p, "--only", "fig1_2"])
    return [
        Target("planargeo report", cli_main, st.one_of(report, report, report, misc).map(lambda a: ((a,), {})),
               group="cli", check=_cli_check, timeout=20.0),
        Target("planargeo gallery --out", cli_main, gallery.map(lambda a: ((a,), {})), group="cli",
               check=_cli_check, timeout=20.0, weight=0.2),
    ]


# --------------------------------------------------------------------------- files
def _no_stray_temporaries(args, kwargs, result):
    left = list(tmpdir().rglob("*.tmp"))
    return (FOREIGN, f"temporary files left: {left[:3]}") if left else None


def file_targets() -> list[Target]:
    from planargeo.files import atomic_write

    data = st.one_of(st.binary(max_size=64), st.text(max_size=32), S.junk)
    return [Target("files.atomic_write", atomic_write, st.tuples(_paths(), data).map(lambda t: (t, {})),
                   group="files", check=_no_stray_temporaries)]


# --------------------------------------------------------------------------- explorers
def _control_value(w):
    import ipywidgets as W

    bad = st.one_of(S.nonfinite, S.junk, st.just(None))
    if isinstance(w, W.FloatSlider):
        inside = st.floats(w.min, w.max)
        outside = st.sampled_from([w.min - 1.0, w.max + 1.0, 1e300, -1e300])
        return st.one_of(inside, inside, inside, outside, bad)
    if isinstance(w, W.IntSlider):
        return st.one_of(st.integers(w.min, w.max), st.integers(w.min, w.max), st.sampled_from(
            [w.min - 1, w.max + 1, 10**7, 1.5]), bad)
    if isinstance(w, (W.Dropdown, W.ToggleButtons)):
        return st.one_of(st.sampled_from(list(w.options)), st.sampled_from(list(w.options)), bad)
    if isinstance(w, W.Checkbox):
        return st.one_of(st.booleans(), bad)
    if isinstance(w, W.Text):
        return st.one_of(st.just(w.value), st.text(max_size=20), st.sampled_from(
            ["1, 2", "nan", "1e300, 0", "0,0; 1,0; 0,1", "0,0; 0,0; 0,0", "", "1;2;3"]), bad)
    return bad


def fmt(x) -> str:
    from planargeo.widgets import fmt

    return fmt(x)


def _readouts_agree(a: dict, b: dict) -> bool:
    return a.keys() == b.keys() and all(fmt(a[k]) == fmt(b[k]) for k in a)


def explorer_target(cls_name: str) -> Target:
    """``explorer.set(**values)``; then controls, readout and message must agree.

    Consistent means: no exception escaped, no "internal error" shown, no NaN in a readout
    without a message, and a second explorer set to the first one's control values shows the
    same readout (so the readout is that of the controls, not of an older state).
    """
    from planargeo import widgets

    cls = getattr(widgets, cls_name)
    holder = {}

    def make():
        if "ex" not in holder:
            holder["ex"] = cls(display="agg")
            holder["ref"] = cls(display="agg")
        return holder["ex"], holder["ref"]

    probe = cls(display="agg")
    controls = {k: _control_value(w) for k, w in probe.controls.items()}
    probe.fig.clf()

    def call(**values):
        ex, ref = make()
        ex.set(**values)
        return ex

    def check(args, kwargs, ex):
        _, ref = make()
        if ex.message.startswith("internal error"):
            return INCONSISTENT, f"message {ex.message!r}"
        nan = [k for k, v in ex.readout_values.items()
               if isinstance(v, (float, np.floating)) and math.isnan(v)]
        if nan and not ex.message:
            return INCONSISTENT, f"readout {nan[0]!r} is NaN with no message"
        try:
            ref.set(**ex.values)
        except Exception as exc:  # noqa: BLE001
            return INCONSISTENT, f"the controls hold {ex.values}, which raise {type(exc).__name__}: {exc} when set"
        if not _readouts_agree(ex.readout_values, ref.readout_values):
            diff = [k for k in ex.readout_values if fmt(ref.readout_values.get(k)) != fmt(ex.readout_values[k])]
            return INCONSISTENT, (f"readout does not match the controls {ex.values} (e.g. {diff[:1]}), "
                                  f"message {ex.message!r}")
        return (PACKAGE, "") if ex.message else None

    strat = st.lists(st.sampled_from(list(controls)), min_size=1, max_size=3, unique=True).flatmap(
        lambda ks: st.fixed_dictionaries({k: controls[k] for k in ks})).map(lambda kw: ((), kw))
    return Target(f"{cls_name}.set", call, strat, group="explorers", check=check, timeout=30.0, weight=0.3)


def explorer_targets() -> list[Target]:
    from planargeo import widgets

    holder = {}

    def export(path):
        holder.setdefault("ex", widgets.ScrewSumExplorer(display="agg", export_dir=tmpdir()))   # path=None
        return holder["ex"].export_svg(path)

    return [explorer_target(n) for n in widgets.EXPLORERS] + [
        Target("Explorer.export_svg", export, _paths().map(lambda p: ((p,), {})), group="explorers",
               check=_no_stray_temporaries, timeout=30.0, weight=0.3)]


def all_targets() -> list[Target]:
    out = []
    for mod, group in SIGNATURE_MODULES.items():
        out += signature_targets(mod, group, OVERRIDES)
    return (out + class_targets() + mechanics_targets() + kernel_targets() + scene_targets()
            + simulate_targets() + loops_targets() + cli_targets() + file_targets() + explorer_targets())
