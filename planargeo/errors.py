"""The package's exceptions.

Every error raised on purpose by planargeo derives from :class:`PlanargeoError`,
so ``except planargeo.PlanargeoError`` catches them all.  Errors about bad
*input* also derive from :class:`ValueError` (or :class:`TypeError`), so code
that already guards against those keeps working.

Messages always name the offending argument and say what was wrong with it,
e.g. ``"mass must be positive, got -1.0"``.

Hierarchy::

    PlanargeoError
    ├── InputError (ValueError)            bad argument values
    │   ├── ShapeError                     wrong array shape
    │   ├── NonFiniteError                 NaN or inf where numbers are needed
    │   ├── InvalidPolygonError            shapely geometry not a valid area
    │   ├── TopologyError                  parent array not a tree (e.g. a cycle)
    │   ├── SceneError                     scene parameters that cannot be built
    │   ├── NumericOverflowError (OverflowError)  a result beyond double precision's range
    │   └── SizeLimitError                 a job too big for memory or time (with an opt-in)
    ├── DegenerateGeometryError (ValueError)  e.g. the join of two coincident points
    └── SingularError (numpy.linalg.LinAlgError)  carries ``cond``
        ├── SingularInertiaError           an inertia that cannot be inverted
        └── SingularConfigurationError     s^T A s or B^T G Λ^-1 G^T B singular

One condition limit, :data:`COND_LIMIT`, decides what is too near singular to answer.
"""
from __future__ import annotations

import numpy as np

__all__ = [
    "PlanargeoError",
    "InputError",
    "ShapeError",
    "NonFiniteError",
    "InvalidPolygonError",
    "TopologyError",
    "SceneError",
    "NumericOverflowError",
    "SizeLimitError",
    "DegenerateGeometryError",
    "SingularError",
    "SingularInertiaError",
    "SingularConfigurationError",
    "CyclicTopologyError",
    "OutputError",
    "COND_LIMIT",
]

#: The package's one condition limit: a result whose relative error can reach about ``ε κ``
#: (``ε = 2.2e-16``, ``κ`` the condition number of the problem that produces it) is refused
#: when ``κ > COND_LIMIT``, because past ``1e12`` fewer than about four of its digits
#: (``ε κ ≈ 2e-4``) would be right.  The error raised carries ``κ`` as ``.cond``
#: (``inf`` when exactly singular).  Where it applies, with the ``κ`` of each problem:
#:
#: * :func:`planargeo.geometry.projective.join` / ``meet``: ``κ = |a| |b| / |a × b|``
#:   (:class:`DegenerateGeometryError`);
#: * a joint's ``sᵀAs`` in every dynamics method: ``κ = ‖A_P‖_F ‖s_P‖_F² / σ_min(sᵀAs)``,
#:   ``A`` and ``s`` at the joint's point ``P`` (:func:`planargeo.mechanics.subspaces.joint_cond`,
#:   :class:`SingularConfigurationError`);
#: * ``RᵀA⁻¹R`` (``κ = ‖R‖_F² / (σ_min(A) σ_min(RᵀA⁻¹R))``) and an inertia ``A`` to be
#:   inverted (``κ = |λ|_max / |λ|_min``) in :mod:`planargeo.mechanics.subspaces`
#:   (:class:`SingularConfigurationError`, :class:`SingularInertiaError`).
#:
#: Three guards measure other matrices and keep thresholds of their own (listed here, the one
#: place to read them): the loop matrix ``BᵀGΛ⁻¹GᵀB`` of 9.5
#: (:data:`planargeo.algorithms.loops.SINGULAR_COND`, ``1e10``: the slider-crank's refused states
#: are defined by it), the backstop ``cond ≥ 1/ε`` of the mobility recursion's 3×3 solves
#: (:data:`planargeo.algorithms.articulated_mobility.SOLVE_COND_LIMIT`) and the dense reference's
#: ``rcond(H)`` (:data:`planargeo.algorithms.crba.SINGULAR_RCOND`).
COND_LIMIT = 1e12


class PlanargeoError(Exception):
    """Base class of every error planargeo raises on purpose."""


class InputError(PlanargeoError, ValueError):
    """An argument has a value the function cannot accept."""


class ShapeError(InputError):
    """An array argument has the wrong shape."""


class NonFiniteError(InputError):
    """An array argument contains NaN or infinity."""


class InvalidPolygonError(InputError):
    """A shapely geometry is not a valid, non-empty area."""


class TopologyError(InputError):
    """A mechanism's parent structure is not a tree (cycle, bad parent index)."""


class SceneError(InputError):
    """Scene parameters describe a mechanism that cannot be built or assembled."""


class NumericOverflowError(InputError, OverflowError):
    """Finite arguments whose result lies beyond double precision's range (about 1.8e308).

    Raised instead of returning ``inf`` or ``NaN``; the message names the argument(s) too large
    (or too small).  Where only an intermediate step would overflow, the functions rescale
    instead and return the finite result.
    """


class SizeLimitError(InputError):
    """A request too big to serve in memory or time (a model of 10⁷ bodies, 10³⁰⁰ steps).

    The message states the limit and the argument that lifts it for a deliberate big job.
    """


class DegenerateGeometryError(PlanargeoError, ValueError):
    """A construction has no unique answer (e.g. the join of two coincident points).

    Points and lines at infinity are *not* degenerate: they are ordinary values.
    """


class SingularError(PlanargeoError, np.linalg.LinAlgError):
    """A matrix that must be inverted is singular (or numerically so).

    Parameters
    ----------
    message : str
        What is singular; the condition number is appended.
    cond : float, optional
        The condition number found.

    Attributes
    ----------
    cond : float
        The condition number found (``inf`` when exactly singular).
    """

    def __init__(self, message: str, cond: float = float("inf")):
        super().__init__(f"{message} (condition number {cond:.3g})")
        self.cond = float(cond)


class SingularInertiaError(SingularError):
    """An inertia (or articulated inertia) is singular or not positive definite."""


class SingularConfigurationError(SingularError):
    """A mechanism is in a singular configuration (e.g. a slider-crank dead centre)."""


class CyclicTopologyError(TopologyError):
    """A parent structure contains a cycle, so ``1 - C`` (thesis 9.12) is singular.

    The cycle's indicator vector ``e`` satisfies ``eᵀ (1 - C) = 0`` exactly
    (every body on the cycle is the parent of exactly one other one), so the
    trunk ``Δ^{-1} = (1 - C)^{-1}`` does not exist.

    Parameters
    ----------
    message : str
        What is cyclic; the condition number is appended.
    cond : float, optional
        Condition number of ``1 - C``.
    cycle : tuple of int, optional
        The bodies on the cycle.

    Attributes
    ----------
    cond : float
        Condition number of ``1 - C`` (``inf``: exactly singular).
    cycle : tuple of int
        The bodies on the cycle, in parent order (``cycle[k+1]`` is the parent of ``cycle[k]``).
    """

    def __init__(self, message: str, cond: float = float("inf"), cycle: tuple = ()):
        super().__init__(f"{message} (condition number of 1 - C: {cond:.3g})")
        self.cond = float(cond)
        self.cycle = tuple(int(i) for i in cycle)


class OutputError(PlanargeoError, OSError):
    """A file or folder could not be written (the message names the path and the cause).

    Whatever was there before is left as it was (writes are atomic: see :mod:`planargeo.files`).
    """
