"""Projective geometry of the plane (thesis ch. 5), the lowest layer, knowing nothing of mechanics.

Points and lines (:mod:`~planargeo.geometry.projective`), conics (:mod:`~planargeo.geometry.conics`)
and the classes :class:`Point`, :class:`Line`, :class:`Conic` (:mod:`~planargeo.geometry.elements`).
"""
