"""Words for the one-line descriptions of picture elements: where a point is, what a force is.

Shared by the explorers' picture builders (:mod:`planargeo.draw.pictures`).  A point
at infinity is told by :func:`planargeo.geometry.projective.is_ideal` (weight
exactly zero), never by a size threshold.

Examples
--------
>>> num(0.123456), num(-0.0), num(2.0)
('0.1235', '0', '2')
>>> where([4.0, -2.0, 2.0]), where([0.0, 1.0, 0.0])
('at (1, 2) m', 'at infinity, direction (-1, 0)')
>>> force([0.0, 2.0, 2.0]), force([0.0, 0.0, -0.5])
('2 N, through (1, 0) m', 'a couple of -0.5 N·m')
"""
from __future__ import annotations

import math

import numpy as np

from planargeo.geometry.projective import is_ideal

__all__ = ["num", "pair", "where", "force", "SUB"]

#: subscript digits
SUB = str.maketrans("0123456789", "₀₁₂₃₄₅₆₇₈₉")


def num(x: float, digits: int = 4) -> str:
    """A number with ``digits`` significant digits, minus zero read as 0.

    Parameters
    ----------
    x : float
    digits : int

    Returns
    -------
    str
    """
    x = float(x)
    if not math.isfinite(x):
        return "∞" if x > 0 else "−∞" if x < 0 else "undefined"
    s = f"{x:.{digits}g}"
    return "0" if float(s) == 0.0 else s


def pair(xy, digits: int = 4) -> str:
    """``(x, y)`` with :func:`num`.

    Parameters
    ----------
    xy : (float, float)
    digits : int

    Returns
    -------
    str
    """
    return f"({num(xy[0], digits)}, {num(xy[1], digits)})"


def where(p, unit: str = "m") -> str:
    """Where a homogeneous point ``[a, b, w]`` (thesis 5.49) is: ``at (x, y) m`` or at infinity.

    Parameters
    ----------
    p : array_like (3,)
    unit : str

    Returns
    -------
    str
    """
    p = np.asarray(p, dtype=float).reshape(3)
    if not np.any(p):
        return "none (zero)"
    if bool(is_ideal(p)):
        d = np.array([-p[1], p[0]]) / math.hypot(p[0], p[1])
        return f"at infinity, direction {pair(d)}"
    return f"at {pair((-p[1] / p[2], p[0] / p[2]))} {unit}"


def force(l, unit: str = "N") -> str:
    """A force ``[fx, fy, τ]`` in words: its size and the foot of the origin on its line, or a couple.

    Parameters
    ----------
    l : array_like (3,)
    unit : str
        Unit of the force (the couple's is ``unit·m``).

    Returns
    -------
    str
    """
    fx, fy, tz = (float(v) for v in np.asarray(l, dtype=float).reshape(3))
    F = math.hypot(fx, fy)
    if F == 0.0:
        return "zero" if tz == 0.0 else f"a couple of {num(tz)} {unit}·m"
    foot = (fy * tz / (F * F), -fx * tz / (F * F))
    return f"{num(F)} {unit}, through {pair(foot)} m"
