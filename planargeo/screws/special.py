"""Special cases of twists, wrenches and their pairs, named (thesis 4.2, 4.4, 5.69, 10.2.4).

The special cases of mechanics are special positions of projective geometry (:data:`CASES`).
Tests use the homogeneous coordinates themselves, so an element dragged to infinity (with the
handles of :func:`horizon_point`) passes through the ideal element without a jump.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from planargeo._validate import as_vec3, as_xy, check_positive, check_tolerance
from planargeo.errors import DegenerateGeometryError, ShapeError
from planargeo.geometry.projective import _fit
from planargeo.geometry._docs import entries

__all__ = ["SpecialCase", "CASES", "twist_case", "wrench_case", "pair_case", "twists_case",
           "wrenches_case", "horizon_point", "horizon_handle"]

#: The docstring entries the case functions share (:func:`planargeo.geometry._docs.entries`).
_documented = entries({
    "v": "v : Twist or array_like (3,)", "f": "f : Wrench or array_like (3,)",
    "v1_v2": "v1, v2 : Twist or array_like (3,)", "f1_f2": "f1, f2 : Wrench or array_like (3,)",
    "rtol": "rtol : float\n    Relative size below which a quantity counts as zero.",
    "disc": "centre : array_like (2,)\n    Centre of the disc.\n"
            "radius : float\n    Radius of the horizon (> 0).",
    "case": ("Returns\n-------\nSpecialCase\n    The case, named.\n\n"
             "Raises\n------\n"
             "ShapeError\n    A screw argument is not one (3,) twist or wrench.\n"
             "InputError\n    A negative or non-finite ``rtol``."),
})

#: name -> (readable text, thesis equation)
CASES = {
    "zero_twist": ("zero twist: no motion, no pole", "4.6"),
    "pure_translation": ("pure translation: the pole is at infinity", "4.10"),
    "pure_rotation": ("rotation about a finite pole", "4.10"),
    "zero_wrench": ("zero wrench: no load, no line", "4.21"),
    "pure_couple": ("pure couple: the line at infinity", "4.46"),
    "pure_force": ("force on a finite line", "4.27"),
    "workless": ("workless: the pole lies on the line, v·f = 0 (reciprocal screws)", "5.69"),
    "power": ("the force does work on the motion: v·f ≠ 0", "5.73"),
    "coincident_poles": ("coincident poles: the sum has the same pole", "4.11"),
    "opposite_rotations": ("opposite rotations: the sum is a translation", "4.13"),
    "rotations": ("two rotations: the sum's pole divides Q₁Q₂ by the lever rule", "4.12"),
    "rotation_translation": ("rotation plus translation: the pole shifts by u/ω", "4.16"),
    "translations": ("two translations: the sum is a translation", "4.10"),
    "zero_sum": ("the sum is zero", "4.6"),
    "same_line": ("forces on one line: the sum acts on it too", "4.4.1"),
    "parallel_forces": ("parallel forces: the lines meet at infinity, lever rule", "4.43"),
    "couple_from_forces": ("equal and opposite parallel forces: a pure couple", "4.4.2"),
    "concurrent": ("concurrent forces: the sum passes through their meet", "4.4.1"),
    "force_couple": ("force plus couple: the line shifts by τ/F", "4.46"),
    "couples": ("two couples: the sum is a couple", "4.46"),
}


@dataclass(frozen=True)
class SpecialCase:
    """A named case: ``name`` (a key of :data:`CASES`), ``text`` (ending with it) and ``equation``.

    Attributes
    ----------
    name : str
    text : str
    equation : str

    Examples
    --------
    >>> twist_case([1.0, 0.0, 0.0])
    SpecialCase(name='pure_translation', text='pure translation: the pole is at infinity (4.10)', equation='4.10')
    """

    name: str
    text: str
    equation: str

    def __str__(self) -> str:
        return self.text


def _case(name: str) -> SpecialCase:
    text, eq = CASES[name]
    return SpecialCase(name, f"{text} ({eq})", eq)


def _raw(x, name: str) -> np.ndarray:
    a = as_vec3(x, name)
    if a.shape != (3,):
        raise ShapeError(f"{name} must have shape (3,), got shape {a.shape}")
    return a + 0.0


def _single(x, name: str) -> np.ndarray:
    return _fit(_raw(x, name))      # rescaled exactly (a power of two): no overflow in products


def _small(x: float, scale: float, rtol: float) -> bool:
    return abs(x) <= rtol * scale


def _one(x, name: str, rtol, cases: tuple, part) -> SpecialCase:
    """The case of one twist or wrench among ``cases``: zero, ideal (``part(x)`` small), finite."""
    a, rtol = _single(x, name), check_tolerance(rtol)
    n = float(np.linalg.norm(a))
    if n == 0:
        return _case(cases[0])
    return _case(cases[1] if _small(part(a), n, rtol) else cases[2])


def _two(x1, x2, names: str, rtol) -> tuple:
    """``(A, B, A + B, max(|A|, |B|), rtol, whether the sum is zero)`` of two twists or two wrenches."""
    A, B, rtol = _raw(x1, names[:2]), _raw(x2, names[2:]), check_tolerance(rtol)
    s = A + B
    big = max(np.linalg.norm(A), np.linalg.norm(B))
    return A, B, s, big, rtol, _small(np.linalg.norm(s), big, rtol)


def _coincide(A: np.ndarray, B: np.ndarray, rtol) -> bool:
    """Whether two non-zero twists have one pole (wrenches one line): ``A × B`` vanishes."""
    a, b = _fit(A + 0.0), _fit(B + 0.0)
    return bool(np.any(a) and np.any(b) and _small(np.linalg.norm(np.cross(a, b)),
                                                   np.linalg.norm(a) * np.linalg.norm(b), rtol))


@_documented
def twist_case(v, rtol: float = 1e-12) -> SpecialCase:
    """Name the case of one twist: ``zero_twist``, ``pure_translation`` or ``pure_rotation``.

    A translation has ``|ω| <= rtol |v|``: its pole is at infinity.

    {parameters v rtol case}

    Examples
    --------
    >>> twist_case([0.0, 0.0, 0.0]).name, twist_case([1.0, 2.0, 1e-17]).name
    ('zero_twist', 'pure_translation')
    """
    return _one(v, "v", rtol, ("zero_twist", "pure_translation", "pure_rotation"), lambda a: a[2])


@_documented
def wrench_case(f, rtol: float = 1e-12) -> SpecialCase:
    """Name the case of one wrench: ``zero_wrench``, ``pure_couple`` (``F ≈ 0``) or ``pure_force``.

    {parameters f rtol case}

    Examples
    --------
    >>> wrench_case([0.0, 0.0, -2.0]).name, wrench_case([0.0, 1.0, 2.0]).name
    ('pure_couple', 'pure_force')
    """
    return _one(f, "f", rtol, ("zero_wrench", "pure_couple", "pure_force"), lambda a: np.hypot(a[0], a[1]))


@_documented
def pair_case(v, f, rtol: float = 1e-12) -> SpecialCase:
    """Name a twist and wrench ``workless`` (``|v·f| ≤ rtol |v| |f|``, thesis 5.69) or ``power``.

    {parameters v f rtol case}

    Examples
    --------
    >>> pair_case([0.0, 1.0, 0.0], [0.0, 0.0, 3.0]).name     # a couple on a translation
    'workless'
    """
    a, b, rtol = _single(v, "v"), _single(f, "f"), check_tolerance(rtol)
    if not np.any(a):
        return _case("zero_twist")
    if not np.any(b):
        return _case("zero_wrench")
    return _case("workless" if _small(a @ b, np.linalg.norm(a) * np.linalg.norm(b), rtol) else "power")


@_documented
def twists_case(v1, v2, rtol: float = 1e-12) -> SpecialCase:
    """Name the case of the sum of two twists (thesis 4.11–4.16).

    In order: ``zero_sum``, ``coincident_poles``, ``opposite_rotations``, ``translations``,
    ``rotation_translation``, ``rotations``.

    {parameters v1_v2 rtol case}

    Examples
    --------
    >>> twists_case([1.0, 0.0, 1.0], [2.0, 0.0, 2.0]).name      # one pole (0, 1), twice the rate
    'coincident_poles'
    """
    A, B, s, big, rtol, zero = _two(v1, v2, "v1v2", rtol)
    if zero:
        return _case("zero_sum")
    if _coincide(A, B, rtol):
        return _case("coincident_poles")
    r1 = bool(np.any(A)) and not _small(A[2], np.linalg.norm(A), rtol)
    r2 = bool(np.any(B)) and not _small(B[2], np.linalg.norm(B), rtol)
    if r1 and r2:
        return _case("opposite_rotations" if _small(s[2], big, rtol) else "rotations")
    if r1 or r2:
        return _case("rotation_translation")
    return _case("translations")


@_documented
def wrenches_case(f1, f2, rtol: float = 1e-12) -> SpecialCase:
    """Name the case of the sum of two wrenches (thesis 4.33–4.46).

    In order: ``zero_sum``, ``couples``, ``force_couple``, ``same_line``, ``couple_from_forces``,
    ``parallel_forces``, ``concurrent``.

    {parameters f1_f2 rtol case}

    Examples
    --------
    >>> wrenches_case([0.0, 1.0, 0.0], [0.0, -1.0, 2.0]).name   # up on x = 0, down on x = 2
    'couple_from_forces'
    """
    A, B, s, big, rtol, zero = _two(f1, f2, "f1f2", rtol)
    if zero:
        return _case("zero_sum")
    F1, F2 = float(np.hypot(A[0], A[1])), float(np.hypot(B[0], B[1]))
    c1 = not np.any(A) or _small(F1, np.linalg.norm(A), rtol)
    c2 = not np.any(B) or _small(F2, np.linalg.norm(B), rtol)
    if c1 and c2:
        return _case("couples")
    if c1 or c2:
        return _case("force_couple")
    if _coincide(A, B, rtol):
        return _case("same_line")
    if _small(A[0] * B[1] - A[1] * B[0], F1 * F2, rtol):
        return _case("couple_from_forces" if _small(np.hypot(s[0], s[1]), max(F1, F2), rtol)
                     else "parallel_forces")
    return _case("concurrent")


@_documented
def horizon_point(handle, centre=(0.0, 0.0), radius=1.0) -> np.ndarray:
    """The homogeneous point a drag handle at ``handle`` means, in the disc model (thesis 10.2.4).

    A handle at offset ``d`` from the centre means ``[cy w + dy, -(cx w + dx), w]`` with
    ``w = 1 − |d|/radius``: finite inside the horizon, ideal on it, back from the opposite side
    beyond it, continuously.

    Parameters
    ----------
    handle : array_like (..., 2)
        Handle positions.
    {disc}

    {returns_3}

    Raises
    ------
    InputError
        A radius that is not positive, or non-finite positions.

    Examples
    --------
    >>> horizon_point([0.5, 0.0])          # halfway to the horizon: the point (1, 0)
    array([ 0. , -0.5,  0.5])
    """
    h = as_xy(handle, "handle")
    c = as_xy(centre, "centre")
    R = float(check_positive(radius, "radius"))
    d = h - c
    w = 1.0 - np.hypot(d[..., 0], d[..., 1]) / R
    return np.stack([c[..., 1] * w + d[..., 1], -(c[..., 0] * w + d[..., 0]), w], axis=-1)


@_documented
def horizon_handle(p, centre=(0.0, 0.0), radius=1.0) -> np.ndarray:
    """Where the drag handle of :func:`horizon_point` sits for the point ``p`` (within the horizon).

    Parameters
    ----------
    p : array_like (3,)
        A homogeneous point (not zero).
    {disc}

    Returns
    -------
    ndarray (2,)

    Raises
    ------
    InputError, ShapeError, DegenerateGeometryError
        A radius that is not positive; ``p`` not one (3,) point, or zero.

    Examples
    --------
    >>> horizon_handle([0.0, 1.0, 0.0])              # the ideal point in direction (-1, 0)
    array([-1.,  0.])
    """
    a = _single(p, "p")
    if not np.any(a):
        raise DegenerateGeometryError("p is the zero vector, which is no point")
    c = as_xy(centre, "centre")
    R = float(check_positive(radius, "radius"))
    if a[2] < 0:
        a = -a
    # with the point c + e (homogeneous [..., w]): offset of the point from the centre, times w
    ew = np.array([-a[1] - c[0] * a[2], a[0] - c[1] * a[2]])       # = w e
    n = float(np.hypot(*ew))
    if n == 0:
        return c.copy()
    # d = e / (1 + |e|/R) = w e / (w + |w e|/R)
    return c + ew / (a[2] + n / R)
