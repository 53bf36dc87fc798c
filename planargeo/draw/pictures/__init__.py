"""Each explorer's state as a picture (:class:`planargeo.draw.picture.Picture`), built without matplotlib.

One module per explorer: a function ``<scene>_picture(state, ..., view, size) -> Picture``
that turns the explorer's solved state into plain elements, each with its id, role,
thesis symbol and a one-line description (meaning, equation, value with unit).  The
page draws the picture live (:mod:`planargeo.widgets.canvas`); matplotlib draws the
same picture for exports (:mod:`planargeo.draw.render`).
"""
