"""Projective geometry of the plane (thesis ch. 5): the lowest layer.

* :mod:`planargeo.geometry.projective` -- points and lines in homogeneous coordinates:
  join, meet, incidence, normalisation, points and lines at infinity (5.1-5.2);
* :mod:`planargeo.geometry.conics` -- conics as symmetric 3×3 matrices: pole, polar,
  classification, tangents, the correlation theorem and decompositions (5.3);
* :mod:`planargeo.geometry.elements` -- the thin classes :class:`Point`, :class:`Line`,
  :class:`Conic` over those functions.

Nothing here knows about mechanics; everything above builds on it.
"""
