"""Hypothesis strategies for planargeo's arguments: each from its documented domain, or hostile.

Every argument has a pair :class:`Arg` ``(valid, hostile)``:

* ``valid`` draws from the documented domain, extremes included: ordinary numbers mostly,
  then both ends of a range and values just inside them, tiny in-range values (1e-300, 5e-324),
  huge ones (1e150, 1e300, 1.7e308), zero where allowed;
* ``hostile`` draws from outside it: NaN, ±inf, zero vectors where they mean nothing, wrong
  lengths and shapes, mismatched batches, strings, None, complex numbers, dicts, booleans.

:func:`call` builds a call: with probability :data:`HOSTILE_SHARE` one argument (chosen at
random) is hostile and the rest valid, else every argument is valid, so that most calls pass
validation and reach the computation while every validation path is still tried.

Examples
--------
>>> import numpy as np
>>> from hypothesis import find
>>> v = find(points.valid, lambda a: np.all(np.isfinite(a)))
>>> v.shape
(3,)
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import hypothesis.strategies as st
import numpy as np

NAN, INF = float("nan"), float("inf")
NONFINITE = (NAN, INF, -INF)
TINY = (1e-300, -1e-300, 5e-324, -5e-324, 1e-160, 1e-12)
HUGE = (1e6, -1e6, 1e150, -1e150, 1e300, -1e300, 1.7e308, -1.7e308)
EXTREME = TINY + HUGE + (0.0, -0.0)
JUNK = (None, "x", "", "1.5", b"ab", {}, {"a": 1}, [], [[1.0, 2.0], [3.0]], 1 + 2j, True, False,
        object())
#: Share of calls with one hostile argument.
HOSTILE_SHARE = 0.2

ordinary = st.floats(-10, 10, allow_nan=False, allow_infinity=False)
extreme = st.sampled_from(EXTREME)
nonfinite = st.sampled_from(NONFINITE)
junk = st.sampled_from(JUNK)
#: Any finite float: mostly ordinary, at times tiny or huge (the ends of the float range).
finite = st.one_of(*[ordinary] * 10, st.sampled_from(TINY), st.sampled_from(HUGE), st.just(0.0))
#: Positive finite floats, ends included.
positive_finite = st.one_of(*[st.floats(1e-3, 1e3)] * 10, st.sampled_from([1e-300, 5e-324, 1e-12]),
                            st.sampled_from([1e6, 1e150, 1e300, 1.7e308]))
#: Any float including NaN and infinity (hostile as an element).
reals = st.one_of(ordinary, ordinary, ordinary, ordinary, extreme, nonfinite)


@dataclass(frozen=True)
class Arg:
    """An argument's strategies: ``valid`` (its documented domain, extremes included) and ``hostile``."""

    valid: Any
    hostile: Any


def _array(shape, elem=finite):
    n = int(np.prod(shape))
    return st.lists(elem, min_size=n, max_size=n).map(lambda xs: np.array(xs, dtype=float).reshape(shape))


def _nonzero(a: np.ndarray) -> bool:
    return bool(np.any(a != 0))


def _put(t):
    a, i, x = t
    a = a.copy()
    a.flat[i % a.size] = x
    return a


def valid_array(shape, elem=ordinary):
    """Finite arrays: ordinary entries mostly; at times one entry at an end of the float range
    (1e-300, 5e-324, 1e300, 1.7e308...), or the whole array scaled by 1e±150 or 1e±300."""
    base = _array(shape, elem)
    n = int(np.prod(shape))
    if n == 0:
        return base
    one = st.tuples(base, st.integers(0, n - 1), st.sampled_from(EXTREME)).map(_put)
    scaled = st.tuples(base, st.sampled_from([1e-300, 1e-150, 1e150, 1e300])).map(lambda t: t[0] * t[1])
    return st.one_of(*[base] * 8, one, scaled)


def hostile_vec(n: int, elem=finite):
    """An ``(n,)``-ish value from outside a vector's domain."""
    bad_el = _array((n,), reals).filter(lambda a: not np.all(np.isfinite(a)))
    return st.one_of(
        bad_el, bad_el, st.just(np.zeros(n)),
        _array((n,), elem).map(lambda a: a + 1j),                                # complex
        st.sampled_from([n - 1, n + 1, 0]).flatmap(lambda k: _array((max(k, 0),), elem)),  # wrong length
        st.integers(1, 2).flatmap(lambda k: _array((k, 2, n), elem)),           # a deeper batch
        junk)


def vec(n: int, elem=finite, *, nonzero: bool = True) -> Arg:
    """An ``(n,)`` finite vector (not all zero when ``nonzero``), a plain list at times."""
    good = valid_array((n,)) if elem is finite else _array((n,), elem)
    if nonzero:
        good = good.filter(_nonzero)
    return Arg(st.one_of(good, good, good, good, good.map(list)), hostile_vec(n, elem))


def mat(rows: int, cols: int, elem=finite, *, symmetric: bool = False) -> Arg:
    base = valid_array((rows, cols)) if elem is finite else _array((rows, cols), elem)
    good = base.map(lambda a: 0.5 * a + 0.5 * a.T) if symmetric and rows == cols else base
    hostile = st.one_of(
        _array((rows, cols), reals).filter(lambda a: not np.all(np.isfinite(a))),
        good.map(lambda a: a + 1j),
        _array((rows, cols + 1), elem), _array((rows + 1, cols), elem), _array((rows,), elem), junk)
    return Arg(good, hostile)


def scalar(elem=finite) -> Arg:
    return Arg(elem, st.one_of(nonfinite, nonfinite, junk))


def positive() -> Arg:
    return Arg(positive_finite, st.one_of(st.sampled_from([0.0, -1.0, -1e-300]), nonfinite, junk))


#: Homogeneous points: from (x, y), at infinity, or any finite non-zero 3-vector.
points = Arg(st.one_of(
    st.tuples(finite, finite).map(lambda xy: np.array([xy[0], xy[1], 1.0])), vec(3).valid,
    st.tuples(finite, finite).filter(lambda d: d[0] or d[1]).map(lambda d: np.array([d[0], d[1], 0.0])),
    vec(3).valid), hostile_vec(3))
#: Lines (wrenches): any finite non-zero 3-vector, the line at infinity among them.
lines = Arg(st.one_of(vec(3).valid, st.just(np.array([0.0, 0.0, 1.0])),
                      st.tuples(ordinary, ordinary, ordinary).filter(lambda f: f[0] or f[1]).map(np.array)),
            hostile_vec(3))
#: Conics: circles, ellipses, hyperbolas, parabolas, degenerate pairs, any symmetric 3×3.
conics = Arg(st.one_of(
    st.just(np.diag([1.0, 1.0, -1.0])), st.just(np.diag([1.0, -1.0, 1.0])),
    st.just(np.array([[1.0, 0, 0], [0, 0, -0.5], [0, -0.5, 0]])),     # a parabola
    st.just(np.diag([1.0, 1.0, 0.0])), st.just(np.diag([1.0, 0.0, 0.0])),   # degenerate
    st.just(np.diag([1.0, 1.0, 1.0])),                                 # imaginary
    mat(3, 3, symmetric=True).valid, mat(3, 3, symmetric=True).valid), mat(3, 3).hostile)


def _inertia(m, cx, cy, Ic):
    return np.array([[m, 0.0, -m * cy], [0.0, m, m * cx], [-m * cy, m * cx, Ic + m * (cx * cx + cy * cy)]])


#: Planar rigid-body inertias (positive definite), ends of the ranges included.
inertias = Arg(st.one_of(
    *[st.builds(_inertia, st.floats(0.01, 100), st.floats(-5, 5), st.floats(-5, 5), st.floats(1e-3, 10))] * 6,
    st.builds(_inertia, st.sampled_from([1e-6, 1e-3, 1e3, 1e6]), st.floats(-5, 5), st.floats(-5, 5),
              st.sampled_from([1e-6, 1e-3, 1e3, 1e6])),
    st.builds(_inertia, positive_finite, finite, finite, positive_finite)),
    st.one_of(mat(3, 3).hostile, st.just(np.zeros((3, 3))), st.just(-np.eye(3))))

KINDS = ("revolute", "prismatic", "revolute_prismatic", "twin_prismatic", "plane", "fixed")


def _joint_spaces(kind, point, direction):
    from planargeo.mechanics.joints import motion_space, reaction_space

    return motion_space(kind, point, direction), reaction_space(kind, point, direction)


_dirs = st.tuples(ordinary, ordinary).filter(lambda d: abs(d[0]) + abs(d[1]) > 1e-3)
#: ``(s, R)`` of one joint (motion and reaction spaces).
joint_pair = st.builds(_joint_spaces, st.sampled_from(KINDS[:5]), st.tuples(ordinary, ordinary), _dirs)
#: Joint motion spaces (3, k) and reaction spaces.
spaces = Arg(st.one_of(joint_pair.map(lambda sr: sr[0]), joint_pair.map(lambda sr: sr[1]),
                       st.integers(1, 2).flatmap(lambda k: _array((3, k), ordinary))),
             st.one_of(st.just(np.zeros((3, 0))), st.just(np.zeros((3, 1))), mat(3, 1).hostile,
                       _array((4, 1)), junk))
xy = vec(2, nonzero=False)
direction = vec(2)
scalars = scalar()
#: Tolerances: the documented (0, 1), ends included.
tolerances = Arg(st.sampled_from([1e-15, 1e-13, 1e-12, 1e-9, 1e-6, 1e-3, 0.1, 0.5, 0.99]),
                 st.one_of(st.sampled_from([0.0, -1e-9, -1.0, 1.0, 2.0, 1e300]), nonfinite, junk))
#: Integers as users mistype them: floats, booleans, huge numbers, strings.
ints = Arg(st.integers(0, 5), st.sampled_from([1.5, 2.9, True, False, 10**7, 10**30, 1e300, -1, INF, NAN,
                                               "3", None, 2 + 0j]))


def choice(*options) -> Arg:
    """One of ``options``, or a wrong string, another type, or None."""
    return Arg(st.sampled_from(options), st.one_of(st.sampled_from(["", "nope", "REVOLUTE", " x"]), junk))


def just(value) -> Arg:
    return Arg(st.just(value), junk)


#: Argument by name (functions are fuzzed by their signature: see fuzz.targets).
BY_NAME: dict[str, Arg] = {
    **{k: points for k in ("p", "q", "P", "Q", "Q1", "Q2", "Q3", "twist", "v", "v1", "v2", "u", "v_a", "v_b",
                           "x", "a", "b")},
    **{k: lines for k in ("l", "m", "L", "l1", "l2", "line", "wrench", "f", "f1", "f2", "g")},
    **{k: conics for k in ("C", "S")},
    **{k: inertias for k in ("inertia", "I", "A")},
    **{k: spaces for k in ("s", "R", "T", "U")},
    **{k: xy for k in ("xy", "point", "centre", "about", "vertex", "com", "t")},
    **{k: direction for k in ("d", "direction")},
    "axes": vec(2, positive_finite),
    **{k: scalars for k in ("theta", "angle", "beta", "alpha", "qd", "omega", "tau", "cond")},
    **{k: positive() for k in ("radius", "focal_length", "mass", "inertia_about_com", "density", "smin",
                               "A_norm2", "s_norm2")},
    **{k: tolerances for k in ("rtol", "atol", "tol")},
    "cond_limit": Arg(st.sampled_from([1.0, 10.0, 1e6, 1e12, 1e300]), st.one_of(
        st.sampled_from([0.0, -1.0, 0.5]), nonfinite, junk)),
    **{k: ints for k in ("n", "n_bodies", "i", "body", "max_iter")},
    "kind": choice("revolute", "prismatic", "revolute_prismatic", "twin_prismatic", "plane", "fixed"),
    "on_interior": choice("raise", "nan"), "on_miss": choice("raise", "nan"),
    "imaginary": Arg(st.booleans(), junk), "what": Arg(st.sampled_from([None, "sᵀAs"]), junk),
    "name": Arg(st.just("geometry"), st.sampled_from([None, 3, b"x"])),
}
#: Arguments whose name says nothing.
anything = Arg(finite, st.one_of(reals, junk))


@st.composite
def call(draw, pos=(), req=None, opt=None, share: float = HOSTILE_SHARE):
    """``(args, kwargs)``: positional :class:`Arg` s ``pos``, required and optional keywords.

    With probability ``share`` exactly one argument is hostile (an optional one is then given);
    the others are valid.  Optional keywords are each given half the time.
    """
    req, opt = dict(req or {}), dict(opt or {})
    slots = list(range(len(pos))) + list(req) + list(opt)
    bad = draw(st.sampled_from(slots)) if slots and draw(st.integers(0, 999)) < 1000 * share else None
    args = tuple(draw(a.hostile if i == bad else a.valid) for i, a in enumerate(pos))
    kwargs = {k: draw(a.hostile if k == bad else a.valid) for k, a in req.items()}
    for k, a in opt.items():
        if k == bad:
            kwargs[k] = draw(a.hostile)
        elif draw(st.booleans()):
            kwargs[k] = draw(a.valid)
    return args, kwargs
