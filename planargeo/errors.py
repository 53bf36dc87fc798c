"""The package's exceptions: every error planargeo raises on purpose derives from :class:`PlanargeoError`.

Errors about bad input also derive from :class:`ValueError`; messages name the argument and
what was wrong (``"mass must be positive, got -1.0"``).

Hierarchy::

    PlanargeoError
    ├── InputError (ValueError)            bad argument values
    │   ├── ShapeError, NonFiniteError     wrong array shape; NaN or inf
    │   ├── InvalidPolygonError            shapely geometry not a valid area
    │   ├── TopologyError                  parent array not a tree (CyclicTopologyError)
    │   ├── SceneError                     scene parameters that cannot be built
    │   ├── NumericOverflowError (OverflowError)  a result beyond double precision's range
    │   └── SizeLimitError                 a job too big for memory or time (with an opt-in)
    ├── DegenerateGeometryError (ValueError)  e.g. the join of two coincident points
    ├── SingularError (numpy.linalg.LinAlgError)  carries ``cond``
    │   └── SingularInertiaError, SingularConfigurationError
    └── OutputError (OSError)              a file or folder that cannot be written
"""
from __future__ import annotations

import numpy as np

__all__ = ["PlanargeoError", "InputError", "ShapeError", "NonFiniteError", "InvalidPolygonError",
           "TopologyError", "SceneError", "NumericOverflowError", "SizeLimitError", "DegenerateGeometryError",
           "SingularError", "SingularInertiaError", "SingularConfigurationError", "CyclicTopologyError",
           "OutputError", "COND_LIMIT"]

#: The package's one condition limit: a result whose relative error can reach ``ε κ`` (``κ`` the
#: condition number of its problem) is refused when ``κ > COND_LIMIT`` (past it, fewer than about
#: four digits would be right); the error carries ``κ`` as ``.cond``.  It applies to ``join`` /
#: ``meet`` (:class:`DegenerateGeometryError`), a joint's ``sᵀAs`` in every dynamics method
#: (:func:`planargeo.mechanics.subspaces.joint_cond`), ``RᵀA⁻¹R`` and inertias to be inverted.
#: Three guards keep thresholds of their own: :data:`planargeo.algorithms.loops.SINGULAR_COND`
#: (``BᵀGΛ⁻¹GᵀB`` of 9.5), :data:`planargeo.algorithms.articulated_mobility.SOLVE_COND_LIMIT` and
#: :data:`planargeo.algorithms.crba.SINGULAR_RCOND`.
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

    Raised instead of returning ``inf`` or ``NaN``, naming the argument(s); where only an
    intermediate step would overflow, the functions rescale instead.
    """


class SizeLimitError(InputError):
    """A request too big to serve in memory or time; the message names the limit and how to lift it."""


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
        The condition number found (``inf``: exactly singular), kept as ``.cond``.
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

    Every body on the cycle is the parent of exactly one other, so its indicator ``e`` has
    ``eᵀ (1 - C) = 0`` and the trunk ``Δ^{-1} = (1 - C)^{-1}`` does not exist.

    Parameters
    ----------
    message : str
        What is cyclic; the condition number is appended.
    cond : float, optional
        Condition number of ``1 - C``, kept as ``.cond``.
    cycle : tuple of int, optional
        The bodies on the cycle in parent order (``cycle[k+1]`` is the parent of ``cycle[k]``), kept
        as ``.cycle``.
    """

    def __init__(self, message: str, cond: float = float("inf"), cycle: tuple = ()):
        super().__init__(f"{message} (condition number of 1 - C: {cond:.3g})")
        self.cond = float(cond)
        self.cycle = tuple(int(i) for i in cycle)


class OutputError(PlanargeoError, OSError):
    """A file or folder could not be written (the message names the path and the cause); what was there is left."""
