"""What the drawing modules share (private): the picture check, a few words, the docstrings."""
from __future__ import annotations

import math

import numpy as np

from planargeo.draw.picture import _ENTRIES, Picture
from planargeo.draw.pictures._words import pair
from planargeo.errors import InputError
from planargeo.geometry._docs import entries

__all__ = ["as_picture", "added", "number", "texts", "bare_line", "inertia", "view_centre", "line_words", "ENTRIES",
           "documented"]


def as_picture(pic) -> Picture:
    """``pic`` itself if it is a :class:`Picture`, else an InputError naming it.

    >>> as_picture("a figure")
    Traceback (most recent call last):
    ...
    planargeo.errors.InputError: pic must be a Picture (planargeo.draw.picture.Picture), got str
    """
    if not isinstance(pic, Picture):
        raise InputError(f"pic must be a Picture (planargeo.draw.picture.Picture), got {type(pic).__name__}")
    return pic


def added(draw, *args, **kw) -> dict:
    """Call the picture's method ``draw`` (``pic.line``, ``pic.point``...) and return the element it added."""
    draw(*args, **kw)
    return draw.__self__.elements[-1]


def number(v, name: str, *, positive: bool = False) -> float:
    """``v`` as a finite float (> 0 with ``positive``, else >= 0), or an InputError naming ``name``."""
    try:
        f = float(v)
    except (TypeError, ValueError):
        f = float("nan")
    if not (math.isfinite(f) and (f > 0 if positive else f >= 0)):
        kind = "positive" if positive else "non-negative"
        raise InputError(f"{name} must be a {kind} finite number, got {v!r}")
    return f


def texts(x, n: int, name: str) -> tuple:
    """``x`` as a tuple of ``n`` entries (a label or offset per element), checked."""
    try:
        t = tuple(x)
    except TypeError:
        raise InputError(f"{name} must be a sequence of {n} entries, got {x!r}") from None
    if len(t) != n:
        raise InputError(f"{name} must have {n} entries, got {len(t)}")
    return t


def bare_line(pic: Picture, id: str, l, **kw) -> dict:
    """A line with neither sense arrow nor label (``pic.line`` with ``**kw``); the element."""
    return added(pic.line, id, l, arrow=False, label="", **kw)


def inertia(pic: Picture, id: str, I, desc: str) -> dict:
    """The inertia ``I`` as its circle of gyration (dashed, centre marked, no label)."""
    return added(pic.conic, id, I, role="inertia", symbol="I", label="", desc=desc)


def view_centre(pic: Picture) -> np.ndarray:
    """The centre of the picture's view (data units)."""
    x0, x1, y0, y1 = pic.box
    return np.array([(x0 + x1) / 2, (y0 + y1) / 2])


def line_words(l, digits: int = 4) -> str:
    """Where a line ``[fx, fy, τ]`` (4.27) runs, in words: its point nearest the origin and its direction.

    >>> line_words([0.0, 1.0, 2.0]), line_words([0.0, 0.0, 1.0])        # the line x = 2; a couple
    ('through (2, 0) m, along (0, 1)', 'the line at infinity')
    """
    fx, fy, tz = (float(v) for v in l)
    F = math.hypot(fx, fy)
    if F == 0.0:
        return "the line at infinity" if tz != 0.0 else "none (zero)"
    return (f"through {pair((fy * tz / (F * F), -fx * tz / (F * F)), digits)} m, "
            f"along {pair((fx / F, fy / F), digits)}")


#: Docstring entries the drawing functions share, written once: a line ``{pic id}`` in a
#: docstring stands for those entries (:data:`documented`; a module adds its own with
#: ``entries(ENTRIES, {...})``).
ENTRIES = {**_ENTRIES, "pic": "pic : Picture\n    Where to draw.",
           "desc": "desc : str\n    One-line description.",
           "prefix": "prefix : str\n    Put before every id (several drawings in one picture).",
           "element": "Returns\n-------\ndict\n    The element added."}


#: The decorator writing :data:`ENTRIES` into a docstring (:func:`planargeo.geometry._docs.entries`)
documented = entries(ENTRIES)
