"""Hypothesis strategies for planargeo's arguments, ordinary and hostile.

Hostile values: NaN, ±inf, 1e±300 (and 1.7e308, 5e-324), zero vectors, wrong lengths and
shapes, batches of mismatched shapes, strings, None, complex numbers, dicts, booleans.
Most draws are ordinary (so the deep code is reached), the rest hostile.

Examples
--------
>>> import numpy as np
>>> from hypothesis import find
>>> v = find(vec(3), lambda a: isinstance(a, np.ndarray) and np.all(a == 0))
>>> v.shape
(3,)
"""
from __future__ import annotations

import hypothesis.strategies as st
import numpy as np

NAN, INF = float("nan"), float("inf")
NONFINITE = (NAN, INF, -INF)
EXTREME = (1e300, -1e300, 1e200, -1e200, 1e160, -1e160, 1e-160, 1e-300, -1e-300, 5e-324,
           1.7e308, -1.7e308, 0.0, -0.0)
JUNK = (None, "x", "", "1.5", b"ab", {}, {"a": 1}, [], [[1.0, 2.0], [3.0]], 1 + 2j, True, False,
        object())

ordinary = st.floats(-10, 10, allow_nan=False, allow_infinity=False)
extreme = st.sampled_from(EXTREME)
nonfinite = st.sampled_from(NONFINITE)
junk = st.sampled_from(JUNK)
#: Finite numbers, ordinary or extreme.
finite = st.one_of(ordinary, ordinary, ordinary, extreme)
#: Any float: mostly ordinary, then extreme, then NaN/inf.
reals = st.one_of(ordinary, ordinary, ordinary, ordinary, extreme, nonfinite)


def hostile(s, junk_share: int = 4):
    """``s`` most of the time, else a junk value (None, a string, a dict, a complex number...)."""
    return st.one_of(*([s] * junk_share), junk)


def _array(shape, elem=reals):
    n = int(np.prod(shape))
    return st.lists(elem, min_size=n, max_size=n).map(lambda xs: np.array(xs, dtype=float).reshape(shape))


def vec(n: int, elem=reals):
    """An ``(n,)`` array, or a hostile variant: zeros, complex, wrong length, a batch, junk."""
    good = _array((n,), elem)
    return st.one_of(
        good, good, good, good, good, good,
        st.just(np.zeros(n)),
        good.map(lambda a: a + 1j),                                       # complex
        st.sampled_from([n - 1, n + 1, 0]).flatmap(lambda k: _array((max(k, 0),), elem)),  # wrong length
        st.integers(1, 3).flatmap(lambda k: _array((k, n), elem)),        # a batch
        st.integers(1, 2).flatmap(lambda k: _array((k, 2, n), elem)),     # a deeper batch
        good.map(list),                                                   # a plain list
        junk,
    )


def mat(rows: int, cols: int, elem=reals, *, symmetric: bool = False):
    """A ``(rows, cols)`` matrix (symmetrised if asked), or hostile variants."""
    base = _array((rows, cols), elem)
    good = base.map(lambda a: 0.5 * (a + a.T)) if symmetric and rows == cols else base
    return st.one_of(
        good, good, good, good, good,
        st.just(np.zeros((rows, cols))),
        _array((rows,), elem).map(lambda v: np.outer(v, v)) if rows == cols else base,  # rank one
        good.map(lambda a: a + 1j),
        _array((rows, cols + 1), elem), _array((rows + 1, cols), elem), _array((rows,), elem),
        st.integers(1, 3).flatmap(lambda k: _array((k, rows, cols), elem)),
        junk,
    )


#: Homogeneous points: from (x, y), at infinity, or any 3-vector (hostile included).
points = st.one_of(
    st.tuples(finite, finite).map(lambda xy: np.array([xy[1], -xy[0], 1.0])),
    st.tuples(finite, finite).map(lambda d: np.array([d[0], d[1], 0.0])),
    vec(3),
)
#: Lines (wrenches): through two points, the line at infinity, or any 3-vector.
lines = st.one_of(
    st.tuples(finite, finite, finite).map(lambda f: np.array(f)),
    st.just(np.array([0.0, 0.0, 1.0])),
    vec(3),
)
#: Conics: circles, ellipses, hyperbolas, parabolas, degenerate pairs, anything 3×3.
conics = st.one_of(
    st.just(np.diag([1.0, 1.0, -1.0])), st.just(np.diag([1.0, -1.0, 1.0])),
    st.just(np.array([[1.0, 0, 0], [0, 0, -0.5], [0, -0.5, 0]])),     # a parabola
    st.just(np.diag([1.0, 1.0, 0.0])), st.just(np.diag([1.0, 0.0, 0.0])),   # degenerate
    st.just(np.diag([1.0, 1.0, 1.0])),                                 # imaginary
    mat(3, 3, symmetric=True), mat(3, 3, symmetric=True), mat(3, 3),
)


def _inertia(m, cx, cy, Ic):
    return np.array([[m, 0.0, -m * cy], [0.0, m, m * cx], [-m * cy, m * cx, Ic + m * (cx * cx + cy * cy)]])


#: Planar rigid-body inertias (positive (semi-)definite) and hostile 3×3 matrices.
inertias = st.one_of(
    st.builds(_inertia, st.floats(0.01, 100), st.floats(-5, 5), st.floats(-5, 5), st.floats(0, 10)),
    st.builds(_inertia, st.floats(0.01, 100), st.floats(-5, 5), st.floats(-5, 5), st.floats(0, 10)),
    st.builds(_inertia, finite, finite, finite, finite),
    mat(3, 3, symmetric=True),
)
#: Joint motion spaces (3, k) and reaction spaces.
spaces = st.one_of(
    st.integers(1, 3).flatmap(lambda k: _array((3, k), finite)),
    st.just(np.array([[0.0], [0.0], [1.0]])), st.just(np.array([[1.0], [0.0], [0.0]])),
    st.just(np.zeros((3, 0))), st.just(np.zeros((3, 1))),
    mat(3, 1), mat(3, 2),
)
xy = vec(2)
scalars = hostile(reals)
positive = st.one_of(st.floats(1e-3, 1e3), st.floats(1e-3, 1e3), extreme, nonfinite, junk)
#: Integers as users mistype them: floats, booleans, huge numbers, strings.
ints = st.one_of(st.integers(-2, 8), st.integers(-2, 8),
                 st.sampled_from([0, 1.5, 2.9, 3.0, True, False, 10**7, 10**30, 1e300, -1, INF, NAN, "3",
                                  None, np.int64(2), 2 + 0j]))
tolerances = st.one_of(st.sampled_from([1e-12, 1e-9, 1e-6, 1e-3, 0.5]), scalars)


def choice(*options):
    """One of ``options`` mostly, else a wrong string, another type, or None."""
    return st.one_of(*([st.sampled_from(options)] * 4), st.sampled_from(["", "nope", "REVOLUTE", " x"]), junk)


#: Strategy per argument name (functions are fuzzed by their signature: see fuzz.targets).
BY_NAME = {
    **{k: points for k in ("p", "q", "P", "Q", "Q1", "Q2", "Q3", "twist", "v", "v1", "v2", "u", "v_a", "v_b",
                           "x", "a", "b")},
    **{k: lines for k in ("l", "m", "L", "l1", "l2", "line", "wrench", "f", "f1", "f2", "g")},
    **{k: conics for k in ("C", "S")},
    **{k: inertias for k in ("inertia", "I", "A")},
    **{k: spaces for k in ("s", "R", "T", "U")},
    **{k: xy for k in ("xy", "d", "point", "direction", "centre", "about", "vertex", "com", "axes", "t")},
    **{k: scalars for k in ("theta", "angle", "beta", "radius", "focal_length", "mass", "alpha", "inertia_about_com",
                            "smin", "A_norm2", "s_norm2", "cond", "qd", "omega", "tau", "density")},
    **{k: tolerances for k in ("rtol", "atol", "tol", "cond_limit")},
    **{k: ints for k in ("n", "n_bodies", "i", "body", "max_iter")},
    "kind": choice("revolute", "prismatic", "revolute_prismatic", "twin_prismatic", "plane", "fixed",
                   "ellipse", "hyperbola", "parabola", "point", "line"),
    "on_interior": choice("raise", "nan"), "on_miss": choice("raise", "nan"),
    "imaginary": st.one_of(st.booleans(), junk), "what": st.one_of(st.none(), st.just("sᵀAs"), junk),
    "name": st.one_of(st.just("geometry"), junk),
}
#: Arguments whose name says nothing: anything.
anything = st.one_of(reals, vec(2), vec(3), mat(3, 3), junk)
