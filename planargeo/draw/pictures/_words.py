"""Words for the picture elements' descriptions: numbers, where a point is, what a force is.

A point at infinity is told by :func:`~planargeo.geometry.projective.is_ideal`, never by a size.

Examples
--------
>>> num(0.123456), num(-0.0), num(2.0), num(5.8e-19)
('0.1235', '0', '2', '0')
>>> where([4.0, -2.0, 2.0]), where([0.0, 1.0, 0.0])
('at (1, 2) m', 'at infinity, direction (-1, 0)')
>>> force([0.0, 2.0, 2.0]), force([0.0, 0.0, -0.5])
('2 N, through (1, 0) m', 'a couple of -0.5 N·m')

Tiny and huge values keep their geometry (no ``F * F`` to underflow, no weight to overflow):

>>> force([1e-300, 1e-300, -1e-300])
'0 N, through (-0.5, 0.5) m'
>>> force([5e-324, 0.0, 1.0])
'0 N, its line far off: nearly a couple of 1 N·m'
>>> where([1.0, 0.0, 5e-324])
'far off, direction (0, 1)'
"""
from __future__ import annotations

import math

import numpy as np

from planargeo.files import package_words
from planargeo.geometry.projective import is_ideal

__all__ = ["num", "pair", "where", "force", "SUB", "subscript", "words_data"]

#: subscript digits
SUB = str.maketrans("0123456789", "₀₁₂₃₄₅₆₇₈₉")


def subscript(i) -> str:
    """``i`` (a whole number or its digits) in subscript digits: ``subscript(12)`` is ``'₁₂'``."""
    return str(i).translate(SUB)


def words_data(explorer: str) -> dict:
    """The ``[explorer.<name>]`` table of the package's words (:func:`planargeo.files.package_words`)."""
    return package_words("explorer").get(explorer, {})


def num(x: float, digits: int = 4, zero: float = 1e-9) -> str:
    """``x`` with ``digits`` significant digits; round-off (``|x| < zero``) and minus zero read 0."""
    x = float(x)
    if not math.isfinite(x):
        return "∞" if x > 0 else "−∞" if x < 0 else "undefined"
    if abs(x) < zero:
        return "0"
    s = f"{x:.{digits}g}"
    return "0" if float(s) == 0.0 else s


def pair(xy, digits: int = 4) -> str:
    """``(x, y)`` with :func:`num`."""
    return f"({num(xy[0], digits)}, {num(xy[1], digits)})"


def where(p, unit: str = "m") -> str:
    """Where a homogeneous point ``[a, b, w]`` (thesis 5.49) is: ``at (x, y) m`` or at infinity."""
    p = np.asarray(p, dtype=float).reshape(3)
    if not np.all(np.isfinite(p)):
        return "undefined (not a finite point)"
    if not np.any(p):
        return "none (zero)"
    if bool(is_ideal(p)):
        return f"at infinity, direction {pair(_unit(-p[1], p[0]))}"
    with np.errstate(over="ignore", under="ignore"):
        xy = (-p[1] / p[2], p[0] / p[2])
    if not (math.isfinite(xy[0]) and math.isfinite(xy[1])):   # a weight so small the point leaves the floats
        return f"far off, direction {pair(_unit(-p[1] * np.sign(p[2]), p[0] * np.sign(p[2])))}"
    return f"at {pair(xy)} {unit}"


def _unit(x: float, y: float) -> tuple[float, float]:
    """``(x, y)`` scaled to length 1 (by its largest part first: no overflow, no underflow)."""
    x, y = float(x), float(y)
    big = max(abs(x), abs(y))
    x, y = x / big, y / big
    n = math.hypot(x, y)
    return x / n, y / n


def force(l, unit: str = "N") -> str:
    """A force ``[fx, fy, τ]`` in ``unit``: its size and the origin's foot on its line, or a couple."""
    fx, fy, tz = (float(v) for v in np.asarray(l, dtype=float).reshape(3))
    if not all(map(math.isfinite, (fx, fy, tz))):
        return "undefined (not a finite force)"
    F = math.hypot(fx, fy)
    if F == 0.0:
        return "zero" if tz == 0.0 else f"a couple of {num(tz)} {unit}·m"
    arm = tz / F                       # the foot's distance from the origin (F * F would underflow)
    if not math.isfinite(arm):         # a force so small beside its moment that its line leaves the floats
        return f"{num(F)} {unit}, its line far off: nearly a couple of {num(tz)} {unit}·m"
    foot = ((fy / F) * arm, -(fx / F) * arm)
    return f"{num(F)} {unit}, through {pair(foot)} m"

