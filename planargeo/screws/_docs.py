"""The docstring entries many functions of the screws share, written once (private).

A docstring line such as ``{inertia twist}`` stands for those entries of :data:`SCREWS`;
:data:`documented` writes them in (:func:`planargeo.geometry._docs.entries`).
"""
from __future__ import annotations

from planargeo.geometry._docs import entries

#: The entries of the screws' docstrings: a name and its (parameter or raises) entry.
SCREWS = {
    "twist": "twist : Twist or array_like, shape (..., 3)\n    Twist ``[vx, vy, ω]`` (m/s, rad/s).",
    "wrench": "wrench : Wrench or array_like, shape (..., 3)\n    Wrench ``[fx, fy, τz]`` (N, N·m).",
    "point": "point : array_like, shape (..., 2)\n    Reference point ``(x, y)`` (m).",
    "inertia": "inertia : array_like, shape (..., 3, 3)\n"
               "    Symmetric inertia matrix at the origin (kg, kg·m, kg·m²).",
    "not_psd": "InputError, SingularInertiaError\n"
               "    ``inertia`` not symmetric positive semi-definite (see :func:`planargeo.screws.kinetic_energy`).",
    "bad_array": "ShapeError, NonFiniteError, InputError\n"
                 "    ``array`` without a last axis of 3, not finite, or not real numbers.",
}

#: The decorator of the screws' shared entries.
documented = entries(SCREWS)
