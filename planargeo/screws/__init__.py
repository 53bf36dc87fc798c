"""Screws (thesis ch. 1, 4, 5.4), built on :mod:`planargeo.geometry` only.

Twists as points and wrenches as lines (:mod:`~planargeo.screws.twists`), inertias as conics
(:mod:`~planargeo.screws.inertia`).
"""
