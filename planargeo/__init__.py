"""planargeo: planar rigid-body dynamics made visible (after the thesis *Projective Articulated Dynamics*).

Twists are points, wrenches are lines, inertias are conics that map one to the other; functions
on arrays that broadcast over leading dimensions, with thin classes (:class:`Point`,
:class:`Twist`, :class:`Inertia`...) over them.  The main jobs load on first use, so ``import
planargeo`` imports neither numba, scipy nor matplotlib: :func:`forward_dynamics` (thesis 3.6),
:func:`inverse_dynamics` (3.9), :func:`simulate`, :func:`scene` and :mod:`scenes`.

>>> import planargeo as pg
>>> pg.Twist.rotation((1.0, 2.0), 3.0).pole
Point(x=1, y=2)
>>> pg.forward_dynamics(pg.chain_model(1), [0.0], [0.0], [0.0])    # a rod released horizontally: -3g/(2L)
array([-14.715])
"""
from __future__ import annotations

from planargeo import errors
from planargeo.errors import (COND_LIMIT, DegenerateGeometryError, InputError, InvalidPolygonError, NonFiniteError,
                     PlanargeoError, SceneError, ShapeError, SingularConfigurationError,
                     SingularError, SingularInertiaError, TopologyError)
from planargeo.geometry.projective import (from_standard, from_xy, incidence, is_ideal, join, meet, normalize,
                         pencil, signed_distance, to_standard, to_xy)
from planargeo.geometry.conics import (centre, classify, correlation, decompose_line, decompose_point,
                     drawable_conic, polar, polar_construction_exterior,
                     polar_construction_interior, pole, tangents_from_point)
from planargeo.geometry.elements import Conic, Line, Point
from planargeo.screws.twists import (X_P, X_P_inv_T, Twist, Wrench, add_twists, add_wrenches, bias_force, crf,
                     crm, inertia_at, kappa, kinetic_energy, momentum, power, rot)
from planargeo.screws.inertia import Inertia, percussion_axis, percussion_pole
from planargeo.mechanics import joints
from planargeo.mechanics.joints import R_of, fixed, plane, prismatic, revolute, revolute_prismatic, twin_prismatic
from planargeo.mechanics.subspaces import Decomposition, T_of, U_of
from planargeo.mechanics.model import Body, Joint, Model, chain_model
import planargeo.simulate as simulate

__version__ = "0.1.0"

__all__ = [
    # errors
    "errors", "PlanargeoError", "InputError", "ShapeError", "NonFiniteError",
    "InvalidPolygonError", "TopologyError", "SceneError", "DegenerateGeometryError",
    "SingularError", "SingularInertiaError", "SingularConfigurationError", "COND_LIMIT",
    # projective geometry
    "normalize", "is_ideal", "from_xy", "to_xy", "join", "meet", "incidence",
    "signed_distance", "pencil", "to_standard", "from_standard",
    "pole", "polar", "classify", "centre", "tangents_from_point", "polar_construction_exterior",
    "polar_construction_interior", "correlation", "decompose_point", "decompose_line",
    "drawable_conic", "Point", "Line", "Conic",
    # screws and inertia
    "Twist", "Wrench", "add_twists", "add_wrenches", "X_P", "X_P_inv_T", "rot", "crm", "crf",
    "kappa", "bias_force", "momentum", "power", "kinetic_energy", "inertia_at",
    "Inertia", "percussion_axis", "percussion_pole",
    # joints and subspaces
    "joints", "revolute", "prismatic", "revolute_prismatic", "twin_prismatic", "plane", "fixed",
    "R_of", "T_of", "U_of", "Decomposition",
    # mechanisms
    "Body", "Joint", "Model", "chain_model",
    # the main jobs, loaded on first use (module __getattr__ below)
    "forward_dynamics", "inverse_dynamics", "simulate", "scene", "scenes",
]

#: Public names loaded on first use: name -> (module, attribute; None for the module itself).
_LAZY = {
    "forward_dynamics": ("planargeo.algorithms.aba", "forward_dynamics"),
    "inverse_dynamics": ("planargeo.algorithms.rnea", "inverse_dynamics"),
    "scene": ("planargeo.scenes", "build"),
    "scenes": ("planargeo.scenes", None),
}


def __getattr__(name: str):
    """Load the main jobs on first use (PEP 562), so that ``import planargeo`` stays light."""
    try:
        module, attr = _LAZY[name]
    except KeyError:
        raise AttributeError(f"module 'planargeo' has no attribute {name!r}") from None
    import importlib

    mod = importlib.import_module(module)
    value = mod if attr is None else getattr(mod, attr)
    globals()[name] = value
    return value


class _CallableSubpackage(type(simulate)):
    """The subpackage :mod:`planargeo.simulate`, callable as :func:`planargeo.simulate.integrate.simulate`."""

    def __call__(self, *args, **kwargs):
        """Integrate a mechanism's motion: :func:`planargeo.simulate.integrate.simulate`."""
        return self._function()(*args, **kwargs)

    @property
    def __signature__(self):
        import inspect

        return inspect.signature(self._function())

    @staticmethod
    def _function():
        from planargeo.simulate.integrate import simulate as function

        return function


simulate.__class__ = _CallableSubpackage


def _show_pictures_in_notebooks() -> None:
    """Inside IPython, show the math objects as drawings (:func:`planargeo.draw.notebook.register`)."""
    import sys

    ipython = sys.modules.get("IPython")
    shell = ipython.get_ipython() if ipython is not None else None
    if shell is not None and hasattr(shell, "display_formatter"):
        from planargeo.draw.notebook import register

        register(shell)


_show_pictures_in_notebooks()


def __dir__() -> list[str]:
    return sorted(set(globals()) | set(_LAZY))

