"""planargeo: planar rigid-body dynamics made visible.

Twists are points, wrenches are lines, inertias are conics that map one to
the other (after the thesis *Projective Articulated Dynamics*).
"""
from __future__ import annotations

from . import errors
from .errors import *  # noqa: F401,F403

__version__ = "0.1.0"
