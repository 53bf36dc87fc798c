"""Drawing: twists as points, wrenches as lines, inertias as conics.

A drawing is a :class:`~planargeo.draw.picture.Picture`: plain elements whose
geometry is computed once in Python (poles, clipped lines, conic curves, ideal
elements as edge arrows, placed labels).  The page draws it live; matplotlib draws
the same picture for the gallery, exports and stored pictures.  Math modules never
import matplotlib, and neither does ``import planargeo.draw``: only the modules
that render do.

* :mod:`~planargeo.draw.picture`: :class:`~planargeo.draw.picture.Picture`, the
  plain elements (point, line, conic, path, marks, text, handle);
* :mod:`~planargeo.draw.geometry`: drawing geometry without a renderer (poles,
  ``clip_line``, ``conic_geometry``, ``conic_curves``, the rotation glyph);
* :mod:`~planargeo.draw.render`: the matplotlib renderer of a picture
  (``draw_picture``, ``figure``, ``picture_bytes``);
* :mod:`~planargeo.draw.sketch`: the gallery's shared basics on a picture (a panel
  fitted to an axes, labels, dimensions, bodies, pins, ground, a whole model,
  joint splits, contacts);
* :mod:`~planargeo.draw.sums`, :mod:`~planargeo.draw.polars`,
  :mod:`~planargeo.draw.splits`: the thesis's constructions on a picture (sums of
  twists and wrenches, chapter 4; polars, percussion and power, chapter 5; the
  T/U splits of chapter 6);
* :mod:`~planargeo.draw.pictures`: each explorer's state as a picture;
* :mod:`~planargeo.draw.chain`: a chain's picture shared by explorers;
* :mod:`~planargeo.draw.notebook`: one value of a notebook cell drawn as a picture;
* :mod:`~planargeo.draw.charts`: curves over a parameter (matplotlib charts);
* :mod:`~planargeo.draw.layout`: views fitted to computed points, the legibility check;
* :mod:`~planargeo.draw.style`: the one visual language (Okabe-Ito roles, fixed
  rcParams, ``legend``).

Examples
--------
>>> import planargeo.draw
>>> pic = planargeo.draw.Picture((-1, 1, -1, 1), size=(100, 100))
>>> pic.point("v", [0.0, 0.0, 1.0], symbol="v")       # a unit rotation about the origin
>>> [part["p"] for part in pic.elements[0]["parts"]]
['mark', 'glyph', 'text']
>>> import planargeo.draw.style as style_module      # the module, not a function of the same name
>>> style_module.COLORS["twist"]
'#0072B2'
"""
from planargeo.draw.picture import Picture  # noqa: F401
from planargeo.draw.style import COLORS, OKABE_ITO, rc_context  # noqa: F401

# (the function style.style is not exported here: the name would hide the module planargeo.draw.style)
__all__ = ["Picture", "COLORS", "OKABE_ITO", "rc_context"]
