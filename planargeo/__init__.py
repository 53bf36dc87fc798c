"""planargeo: planar rigid-body dynamics made visible.

Twists are points, wrenches are lines, inertias are conics that map one to the
other (after the thesis *Projective Articulated Dynamics*).  The mathematics is
a set of functions on arrays that broadcast over leading dimensions; the
classes (:class:`Point`, :class:`Line`, :class:`Conic`, :class:`Twist`,
:class:`Wrench`, :class:`Inertia`) are thin wrappers over them.

>>> import planargeo as pg
>>> v = pg.Twist.rotation((1.0, 2.0), 3.0)
>>> v.pole
Point(x=1, y=2)
>>> f = pg.Wrench.force((0.0, 2.0), (1.0, 0.0))   # a force through the pole does no work
>>> float(v @ f)
0.0

Drawing (:mod:`planargeo.draw`) and widgets (:mod:`planargeo.widgets`) are
imported on demand; importing ``planargeo`` never imports matplotlib.
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
from planargeo.mechanics.model import Body, Joint, Model
from planargeo import scenes

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
    "Body", "Joint", "Model", "scenes",
]
