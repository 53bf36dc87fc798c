"""Each explorer's state as a :class:`planargeo.draw.picture.Picture`, built without matplotlib.

One module per explorer, ``<scene>_picture(state, ..., view, size) -> Picture``: plain elements,
each with its id, role, thesis symbol and one-line description, drawn live by the page
(:mod:`planargeo.widgets.canvas`) and by matplotlib for exports (:mod:`planargeo.draw.render`).
"""
