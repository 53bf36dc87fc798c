"""Drawing: twists as points, wrenches as lines, inertias as conics.

A drawing is a :class:`~planargeo.draw.picture.Picture`, drawn live by the page and by
matplotlib (:mod:`~planargeo.draw.render`; ``import planargeo.draw`` does not import it).  The
gallery's basics are in :mod:`~planargeo.draw.sketch`, the thesis's constructions in
:mod:`~planargeo.draw.sums` (chapter 4), :mod:`~planargeo.draw.polars` (5) and
:mod:`~planargeo.draw.splits` (6), the explorers' pictures in :mod:`~planargeo.draw.pictures` and
:mod:`~planargeo.draw.chain`, a notebook value's in :mod:`~planargeo.draw.notebook`;
:mod:`~planargeo.draw.style` holds the one visual language, :mod:`~planargeo.draw.layout` view
fitting and the legibility check.

Examples
--------
>>> import planargeo.draw
>>> pic = planargeo.draw.Picture((-1, 1, -1, 1), size=(100, 100))
>>> pic.point("v", [0.0, 0.0, 1.0], symbol="v")       # a unit rotation about the origin
>>> [part["p"] for part in pic.elements[0]["parts"]]
['mark', 'glyph', 'text']
"""
from planargeo.draw.picture import Picture  # noqa: F401
from planargeo.draw.style import COLORS, OKABE_ITO, rc_context  # noqa: F401

# (the function style.style is not exported here: the name would hide the module planargeo.draw.style)
__all__ = ["Picture", "COLORS", "OKABE_ITO", "rc_context"]
