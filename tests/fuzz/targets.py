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
from fuzz.harness import FOREIGN, NONFINITE, OK, PACKAGE, Target

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
    """``(args, kwargs)`` for ``fn``: its required arguments always, each optional one at times.

    Values from each argument's domain (:mod:`fuzz.strategies`), one hostile at times; where a
    function takes both a joint's motion space ``s`` and its reaction space ``R``, valid calls
    give the two of one joint (as the documentation asks).
    """
    overrides = overrides or {}
    req, opt = {}, {}
    for name, p in inspect.signature(fn).parameters.items():
        if p.kind in (p.VAR_POSITIONAL, p.VAR_KEYWORD):
            continue
        arg = overrides.get(name, S.BY_NAME.get(name, S.anything))
        (req if p.default is p.empty else opt)[name] = arg
    strat = S.call((), req, opt)
    if "s" in {**req, **opt} and "R" in {**req, **opt} and "s" not in overrides:
        def pair(t):
            (args, kw), (s, R), keep = t
            if keep or not all(isinstance(kw.get(k), np.ndarray) and np.all(np.isfinite(kw[k]))
                               for k in ("s", "R")):
                return args, kw
            return args, dict(kw, s=s, R=R)
        strat = st.tuples(strat, S.joint_pair, st.integers(0, 9).map(lambda k: k == 0)).map(pair)
    return strat


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
def _shapely(pts):
    from shapely.geometry import Polygon

    return Polygon(pts)


def _polygon(k, r, x0, y0):
    return [(x0 + r * math.cos(2 * math.pi * i / k + 0.3), y0 + r * math.sin(2 * math.pi * i / k + 0.3))
            for i in range(k)]


OVERRIDES = {
    "conic_from_coefficients": {k: S.scalars for k in "abcdef"},
    "conic_from_affine": {"A": S.mat(2, 2), "t": S.xy, "kind": S.choice("ellipse", "hyperbola", "parabola")},
    "normalize": {"kind": S.choice("point", "line")},
    "percussion_axis": {"point": S.points},
    "polygon_moments": {"geometry": S.Arg(st.one_of(
        st.just([(0.0, 0.0), (1.0, 0.0), (0.0, 1.0)]),
        st.builds(_polygon, st.integers(3, 9), st.sampled_from([1e-6, 0.01, 1.0, 100.0, 1e6]),
                  S.ordinary, S.ordinary)).map(_shapely),
        st.one_of(st.lists(st.tuples(S.reals, S.reals), max_size=2),
                  st.just([(0.0, 0.0), (1.0, 1.0), (2.0, 2.0)]), st.just([(0, 0), (1, 1), (1, 0), (0, 1)]),
                  st.just([(0.0, 0.0), (float("nan"), 1.0), (1.0, 0.0)]), S.junk))},
    "kappa": {"s": S.Arg(st.just(np.array([[0.0], [0.0], [1.0]])), S.spaces.hostile),
              "qd": S.Arg(st.one_of(S.finite, S.vec(1, nonzero=False).valid), S.scalars.hostile)},
    "polar_construction_interior": {"lines": S.Arg(st.one_of(st.none(), S.lines.valid), S.junk)},
}


# --------------------------------------------------------------------------- the thin classes
def _method(cls_factory, method, args, name, group):
    """Target ``getattr(make(), method)(*args)`` with ``make`` a valid object; ``args``: :class:`S.Arg` s."""
    def call(obj, *args):
        return getattr(obj, method)(*args)

    strat = S.call((S.Arg(cls_factory, cls_factory), *args))
    return Target(name, call, strat, group=group, nonfinite_ok=_any_ideal)


def _pos(*args):
    """``(args, {})`` strategy of positional :class:`S.Arg` s."""
    return S.call(tuple(args))


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
    P = S.Arg(st.one_of(good_point, S.points.valid), S.points.hostile)
    L = S.Arg(st.one_of(good_line, S.lines.valid), S.lines.hostile)
    G = "geometry"
    return [
        Target("Point", pg.Point, _pos(S.points), group=G),
        Target("Point.from_xy", pg.Point.from_xy, _pos(S.scalars, S.scalars), group=G),
        Target("Point.at_infinity", pg.Point.at_infinity, _pos(S.direction), group=G),
        Target("Line", pg.Line, _pos(S.lines), group=G),
        Target("Line.from_point_direction", pg.Line.from_point_direction, _pos(S.xy, S.direction), group=G),
        Target("Conic", pg.Conic, _pos(S.conics), group=G),
        Target("Conic.circle", pg.Conic.circle, _pos(S.xy, S.positive()), group=G),
        _method(good_point, "join", [P], "Point.join", G),
        _method(good_point, "distance_to", [L], "Point.distance_to", G),
        _method(good_line, "meet", [L], "Line.meet", G),
        _method(conic, "tangents_from", [P], "Conic.tangents_from", G),
        _method(conic, "pole", [L], "Conic.pole", G),
        _method(conic, "polar", [P], "Conic.polar", G),
        _method(conic, "contains", [S.points], "Conic.contains", G),
        Target("Twist.rotation", pg.Twist.rotation, _pos(S.xy, S.scalars), group="screws"),
        Target("Twist.translation", pg.Twist.translation, _pos(S.direction), group="screws"),
        Target("Wrench.force", pg.Wrench.force, _pos(S.xy, S.direction), group="screws"),
        Target("Wrench.couple", pg.Wrench.couple, _pos(S.scalars), group="screws"),
        Target("Inertia.from_mass", pg.Inertia.from_mass, _pos(S.positive(), S.xy, S.positive()), group="screws"),
        Target("Inertia", pg.Inertia, _pos(S.inertias), group="screws"),
        _method(inertia, "percussion_axis", [S.points], "Inertia.percussion_axis", "screws"),
        _method(inertia, "percussion_pole", [S.lines], "Inertia.percussion_pole", "screws"),
        _method(inertia, "kinetic_energy", [S.points], "Inertia.kinetic_energy", "screws"),
        _method(twist, "power", [S.lines], "Twist.power", "screws"),
        Target("add_twists", pg.add_twists, _pos(S.points, S.points), group="screws"),
        Target("add_wrenches", pg.add_wrenches, _pos(S.lines, S.lines), group="screws"),
    ]


# --------------------------------------------------------------------------- models, states, joints, contacts
KINDS = ("revolute", "prismatic", "revolute_prismatic", "twin_prismatic", "plane", "fixed")
#: Number of bodies: 1 up to the size limit (200 in chain_model without allow_large), ends included.
N_BODIES = S.Arg(st.one_of(st.integers(1, 6), st.integers(1, 6), st.sampled_from([1, 2, 50, 199, 200])),
                 S.ints.hostile)


def _models():
    from planargeo.mechanics.model import chain_model, random_model

    chains = st.builds(chain_model, st.integers(1, 4), st.floats(0.1, 10), st.floats(0.1, 3),
                       st.sampled_from(["revolute", "prismatic"]))
    rand = st.builds(lambda n, seed, kinds, tree: random_model(n, seed, kinds=kinds, tree=tree),
                     st.integers(1, 4), st.integers(0, 10**6),
                     st.lists(st.sampled_from(KINDS[:5]), min_size=1, max_size=3).map(tuple), st.booleans())
    return st.one_of(chains, chains, rand)


#: State entries: ordinary mostly, the ends of the float range at times.
STATE_EL = st.one_of(*[S.ordinary] * 30, st.sampled_from(S.TINY), st.sampled_from(S.HUGE))


def _state_vec(nq) -> S.Arg:
    good = S._array((nq,), STATE_EL)
    return S.Arg(st.one_of(good, good, good, st.just(np.zeros(nq))),
                 st.one_of(S._array((nq,), S.nonfinite), st.just(None), S.hostile_vec(nq),
                           st.integers(1, 3).flatmap(lambda k: S._array((k, nq + 1)))))


def _dyn(name, fn, group="kernels", extra=("qd", "tau")):
    """``fn(model, q, *extra)`` on a model with a state of the right length (hostile variants included)."""
    def strat(model):
        return S.call((S.Arg(st.just(model), st.just(model)),) + tuple(
            _state_vec(model.nq) for _ in ("q",) + tuple(extra)))

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
        Target("chain_model", chain_model, S.call((), {"n": N_BODIES}, {
            "mass": S.positive(), "length": S.positive(), "joint": S.choice(*KINDS), "gravity": S.xy}),
               group="kernels", timeout=10.0),
        Target("random_model", random_model, S.call((), {"n": N_BODIES}, {
            "seed": S.Arg(st.one_of(st.none(), st.integers(0, 2**32 - 1)), S.ints.hostile),
            "tree": S.Arg(st.booleans(), S.junk),
            "kinds": S.Arg(st.lists(st.sampled_from(KINDS), min_size=1, max_size=3, unique=True).map(tuple),
                           st.one_of(st.just(()), st.just(("glue",)), S.junk))}),
               group="kernels", timeout=10.0),
    ]


def mechanics_targets() -> list[Target]:
    from planargeo.mechanics.contacts import Contact

    contact = S.call((), {"kind": S.choice("pin", "slider", "weld"), "a": S.Arg(st.integers(0, 5), S.ints.hostile)},
                     {"b": S.Arg(st.integers(-1, 5), S.ints.hostile), "point_a": S.xy, "point_b": S.xy,
                      "direction": S.direction, "angle": S.scalars, "name": S.Arg(st.just("c"), st.just(3))})
    return [Target("Contact", Contact, contact, group="mechanics")]


# --------------------------------------------------------------------------- scenes
def _param_strategy(default, limit=None) -> S.Arg:
    """A scene parameter: near its default, same sign (a size up to its limit), or hostile."""
    if isinstance(default, bool):
        return S.Arg(st.booleans(), st.one_of(S.junk, S.reals))
    if isinstance(default, int):
        hi = limit or max(2 * default, 3)
        return S.Arg(st.one_of(st.integers(max(1, default // 2), max(default * 2, 2)),
                               st.sampled_from([1, max(1, default - 1), default + 1, hi])),
                     st.one_of(st.sampled_from([0, -1, 1.5, 10**30, 1e300, "3", None]),
                               st.just(hi + 1) if limit else S.junk))
    if isinstance(default, float):
        if default == 0.0:
            good = st.one_of(st.floats(-1, 1), st.sampled_from([0.0, 1e-300, -1e-300]))
        else:
            sign = math.copysign(1.0, default)
            good = st.one_of(st.floats(0.25, 4.0).map(lambda f: default * f), st.just(default),
                             st.sampled_from([2.0, 10.0, 0.5]).map(lambda f: default * f))
        return S.Arg(good, st.one_of(S.nonfinite, S.junk, st.sampled_from([10**400, 1e300, -1e300, -abs(default) - 1])))
    if isinstance(default, str):
        return S.Arg(st.sampled_from([default]), st.one_of(st.sampled_from(["nope", ""]), S.junk))
    return S.Arg(st.one_of(st.none(), st.integers(0, 10**6)), S.junk)        # None defaults (seed)


def scene_targets() -> list[Target]:
    from planargeo import scenes

    out = []
    for name in scenes.names():
        params, lim = scenes.parameters(name), scenes.limits(name)
        strat = S.call((), {}, {k: _param_strategy(v, lim.get(k)) for k, v in params.items()})
        out.append(Target(f"scenes.build('{name}')", lambda _n=name, **kw: scenes.build(_n, **kw),
                          strat, group="scenes", timeout=15.0))
    return out


# --------------------------------------------------------------------------- simulate
SIM_OPTIONS = {
    "method": S.choice("DOP853", "RK45", "RK23", "Radau", "BDF", "LSODA", "RK4"),
    "rtol": S.Arg(st.sampled_from([1e-6, 1e-8, 1e-10, 1e-3]), st.one_of(S.nonfinite, st.sampled_from([-1.0, 0.0]), S.junk)),
    "atol": S.Arg(st.sampled_from([1e-8, 1e-10, 1e-12, 1e-6]), st.one_of(S.nonfinite, st.just(-1.0), S.junk)),
    "dt": S.Arg(st.sampled_from([None, 0.01, 0.05, 0.002]), st.one_of(S.nonfinite, st.sampled_from([0.0, -0.1, 1e-300]), S.junk)),
    "max_step": S.Arg(st.sampled_from([0.01, 0.1, math.inf]), st.one_of(st.sampled_from([0.0, -1.0, float("nan")]), S.junk)),
    "cond_event": S.Arg(st.sampled_from([1e3, 1e6, 1e12]), st.one_of(S.nonfinite, st.just(-1.0), S.junk)),
}
#: Durations: short ones mostly (the run must be quick), tiny ones among them.
T_END = S.Arg(st.one_of(st.floats(0.01, 0.3), st.floats(0.01, 0.3), st.sampled_from([1e-300, 5e-324, 1e-9, 0.5])),
              st.one_of(S.nonfinite, st.sampled_from([0.0, -1.0, 1e300]), S.junk))


def simulate_targets() -> list[Target]:
    from planargeo.mechanics.model import chain_model
    from planargeo.simulate.integrate import simulate

    def run(model, q0, qd0, t_end, **kw):
        return simulate(model, q0, qd0, t_end, progress=False, **kw)

    def strat(model):
        return S.call((S.Arg(st.just(model), st.just(model)), _state_vec(model.nq), _state_vec(model.nq), T_END),
                      {}, SIM_OPTIONS)

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
    near = S._array((model.nq,), st.floats(-0.05, 0.05))
    vec = S.Arg(st.one_of(st.just(q0), near.map(lambda d: q0 + d), _state_vec(model.nq).valid),
                _state_vec(model.nq).hostile)
    vecd = S.Arg(st.one_of(st.just(qd0), near.map(lambda d: qd0 + 10 * d), _state_vec(model.nq).valid),
                 _state_vec(model.nq).hostile)
    gains = S.Arg(st.sampled_from([0.0, 1.0, 5.0, 50.0]), S.scalars.hostile)
    opts = dict(SIM_OPTIONS, stabilization=S.choice("projection", "baumgarte", "both", "none"),
                alpha=gains, beta=gains, tol=S.tolerances, trigger=S.tolerances)
    strat = S.call((vec, vecd, T_END), {}, opts)
    model_arg = S.Arg(st.just(model), st.just(model))
    closure = S.call((model_arg, vec, vecd), {}, {
        "fixed": S.Arg(st.lists(st.integers(0, model.nq - 1), max_size=1, unique=True), S.junk),
        "tol": S.tolerances, "max_iter": S.Arg(st.integers(1, 50), S.ints.hostile)})
    return [Target("simulate_loops", run, strat, group="simulate", timeout=20.0),
            Target("loops.project_state", project_state, closure, group="simulate"),
            Target("loops.closure_residual", closure_residual, S.call((model_arg, vec)), group="simulate"),
            Target("loops.baumgarte", lambda **kw: baumgarte(model, **kw)(0.0, q0, qd0, np.zeros(model.nq)),
                   S.call((), {}, {"alpha": gains, "beta": gains}), group="simulate")]


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


def _paths() -> S.Arg:
    """Output paths: new ones inside the scratch folder, or hostile ones that can never write elsewhere."""
    fresh = st.builds(lambda: tmpdir() / f"out{next(_counter)}")
    named = st.sampled_from(["afile", "full", "full/mine.txt", "no/such/dir", "x" * 300, "a\0b", ".", ""]).map(
        lambda n: tmpdir() / n)
    return S.Arg(st.one_of(fresh, fresh.map(str)),
                 st.one_of(named, st.sampled_from(["/dev/full", "/", "/proc/nonexistent/x"]),
                           st.sampled_from([None, 3, b"\0"])))


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


USER_TEXT = "the user's own notes\n"


def _bench_out(kind: str) -> list[str]:
    """``planargeo bench --out X`` where it must refuse at once: X holds the user's files, or cannot be made."""
    if kind == "user folder":                       # a folder of the user's, with files of the results' names
        d = tmpdir() / f"user{next(_counter)}"
        d.mkdir()
        for name in ("RESULTS.md", "batch.md", "notes.txt"):
            (d / name).write_text(USER_TEXT)
        out = str(d)
    else:
        out = {"under /proc": "/proc/nope", "under a file": str(tmpdir() / "afile" / "R"),
               "a file": str(tmpdir() / "afile"), "/dev/full": "/dev/full"}[kind]
    suite = Path(__file__).resolve().parents[2] / "benchmarks"
    return ["bench", "--suite", str(suite), "--out", out, "--quick", "--only", "dynamics", "--no-charts"]


def cli_process(argv, timeout: float = 15.0):
    """``planargeo ARGV`` in a new process group: ``(status, stdout, stderr)``; past ``timeout`` the
    whole group is killed and :class:`~fuzz.harness.Hang` raised (a benchmark run has children)."""
    import os
    import signal
    import subprocess
    import sys

    from fuzz.harness import Hang

    p = subprocess.Popen([sys.executable, "-m", "planargeo", *map(str, argv)], stdout=subprocess.PIPE,
                         stderr=subprocess.PIPE, text=True, start_new_session=True, cwd=tmpdir(),
                         env=dict(os.environ, MPLBACKEND="Agg"))
    try:
        out, err = p.communicate(timeout=timeout)
    except BaseException:
        with contextlib.suppress(ProcessLookupError):
            os.killpg(p.pid, signal.SIGKILL)
        p.communicate()
        raise Hang(f"no answer within {timeout:g} s (the process group was killed)") from None
    return p.returncode, out, err


def _bench_check(args, kwargs, result):
    """Refused: a non-zero status, one line, no traceback, no success line, the user's files as they were."""
    argv = args[0]
    code, out, err = result
    out_dir = Path(argv[argv.index("--out") + 1])
    if out_dir.is_dir() and (out_dir / "notes.txt").exists():
        changed = [f.name for f in out_dir.iterdir() if f.is_file() and f.read_text(errors="replace") != USER_TEXT]
        if changed:
            return FOREIGN, f"the user's files {changed} were replaced without --force (status {code})"
    verdict = _cli_check(args, kwargs, result)
    if verdict is not None and verdict[0] != PACKAGE:
        return verdict
    if code == 0:
        return FOREIGN, f"status 0 (a success) writing into {out_dir}: {out.strip()[-200:]!r}"
    return PACKAGE, ""


def cli_targets() -> list[Target]:
    from planargeo import scenes

    names = scenes.names()

    def value_text(v) -> str:
        return str(v).lower() if isinstance(v, bool) else ("none" if v is None else repr(v))

    def set_items(name, hostile):
        params, lim = scenes.parameters(name), scenes.limits(name)
        if not params:
            return st.just([])
        good = st.sampled_from(list(params)).flatmap(lambda k: _param_strategy(params[k], lim.get(k)).valid.map(
            lambda v: ["--set", f"{k}={value_text(v)}"]))
        bad_val = st.sampled_from(["nan", "inf", "-inf", "none", "[1, 2]", "[", "x", "", "1e400", "1j", "1e300"])
        bad = st.one_of(st.tuples(st.sampled_from(list(params)), bad_val),
                        st.tuples(st.sampled_from(["nope", "", "n=2"]), st.just("1"))).map(
            lambda kv: ["--set", f"{kv[0]}={kv[1]}"])
        items = st.lists(good, max_size=3)
        if hostile:
            items = st.tuples(items, bad).map(lambda t: t[0] + [t[1]])
        return items.map(lambda its: [x for it in its for x in it])

    def report(hostile):
        return st.tuples(st.sampled_from(names), st.booleans()).flatmap(
            lambda t: set_items(t[0], hostile).map(
                lambda sets: ["report", t[0], *sets] + (["--json"] if t[1] else [])))

    misc = st.sampled_from([["report", "nope"], ["report", ""], ["report"], [],
                            ["frobnicate"], ["report", "--set"], ["report", "chain", "--set", "n"],
                            ["bench", "--suite", "/nonexistent"], ["gallery", "--only", "no_such_figure"],
                            ["report", "chain", "--bogus"]])
    good_misc = st.sampled_from([["report", "--list"], ["report", "--list", "--json"], ["--version"]])
    argv = S.Arg(st.one_of(report(False), report(False), report(False), good_misc),
                 st.one_of(report(True), misc))
    gallery = S.Arg(_paths().valid.map(lambda p: ["gallery", "--out", p, "--only", "fig1_2"]),
                    _paths().hostile.filter(lambda p: isinstance(p, (str, Path))).map(   # never relative to the cwd
                        lambda p: ["gallery", "--out", p, "--only", "fig1_2"]))
    return [
        Target("planargeo report", cli_main, S.call((argv,)), group="cli", check=_cli_check, timeout=20.0),
        Target("planargeo gallery --out", cli_main, S.call((gallery,)), group="cli",
               check=_cli_check, timeout=20.0, weight=0.1),
        # only the refusals (a real benchmark run takes half a minute): each must come at once
        Target("planargeo bench --out", cli_process, st.sampled_from(
            ["user folder", "under /proc", "under a file", "a file", "/dev/full"]).map(
            lambda k: ((_bench_out(k),), {})), group="cli", check=_bench_check, timeout=20.0, weight=0.1),
    ]


# --------------------------------------------------------------------------- files
def _no_stray_temporaries(args, kwargs, result):
    left = list(tmpdir().rglob("*.tmp"))
    return (FOREIGN, f"temporary files left: {left[:3]}") if left else None


def file_targets() -> list[Target]:
    from planargeo.files import atomic_write

    data = S.Arg(st.one_of(st.binary(max_size=64), st.text(max_size=32)), S.junk)
    return [Target("files.atomic_write", atomic_write, S.call((_paths(), data)),
                   group="files", check=_no_stray_temporaries)]


# --------------------------------------------------------------------------- explorers
def explorer_targets() -> list[Target]:
    from planargeo import widgets

    holder = {}

    def export(path):
        holder.setdefault("ex", widgets.ScrewSumExplorer(display="agg", export_dir=tmpdir()))   # path=None
        return holder["ex"].export_svg(path)

    return [Target("Explorer.export_svg", export, S.call((_paths(),)), group="explorers",
                   check=_no_stray_temporaries, timeout=30.0, weight=0.1)]


def all_targets() -> list[Target]:
    out = []
    for mod, group in SIGNATURE_MODULES.items():
        out += signature_targets(mod, group, OVERRIDES)
    return (out + class_targets() + mechanics_targets() + kernel_targets() + scene_targets()
            + simulate_targets() + loops_targets() + cli_targets() + file_targets() + explorer_targets())
