"""Screws: twists as points, wrenches as lines, inertias as conics (thesis ch. 1, 4, 5.4).

* :mod:`planargeo.screws.twists` -- transforms, twists, wrenches, power and their sums;
* :mod:`planargeo.screws.inertia` -- planar inertias, the axis of percussion and its pole.

Builds on :mod:`planargeo.geometry` only.
"""
