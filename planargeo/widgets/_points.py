"""Readout values of homogeneous points: numbers as numbers, ideal points as words.

A finite point reads as the numbers ``(x, y)`` (the base writes the unit after
them); a point at infinity reads as the words of
:func:`planargeo.widgets.readout.point_text`, "at infinity (direction (dx, dy))",
decided by the package's own exact test
(:func:`planargeo.geometry.projective.is_ideal`), never by a tolerance here.

Examples
--------
>>> point_value([2.0, -1.0, 1.0])
(1.0, 2.0)
>>> point_value([0.0, -1.0, 0.0])
'at infinity (direction (1, 0))'
"""
from __future__ import annotations

import numpy as np

from planargeo.geometry.projective import is_ideal
from planargeo.widgets.readout import point_text

__all__ = ["point_value"]


def point_value(p):
    """``(x, y)`` of a finite homogeneous point, or the words for a point at infinity.

    Parameters
    ----------
    p : array_like, shape (3,)
        ``[a, b, w]`` with ``x = −b/w``, ``y = a/w`` (thesis 5.49).

    Returns
    -------
    tuple of float or str
    """
    p = np.asarray(p, dtype=float)
    if bool(is_ideal(p)):
        return point_text(p)
    return (float(-p[1] / p[2]) + 0.0, float(p[0] / p[2]) + 0.0)
