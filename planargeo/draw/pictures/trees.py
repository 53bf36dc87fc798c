"""The nine-link tree's picture (thesis Fig 9.1) and its closed loops (Fig 9.2): links, pins, forces.

The pin forces ``f₁ … f₉`` (9.61, 9.41) and contact forces ``F₁``, ``F₂`` (9.71) to scale,
the poles if asked, a scale bar; a focus on one force fades the others.

Examples
--------
>>> from types import SimpleNamespace
>>> pose = [[0.0, 0.0, 1.5708], [0.0, 1.0, 1.5708]]            # two links standing up
>>> tips = [[0.0, 1.0], [0.0, 2.0]]
>>> reactions = [SimpleNamespace(symbol="f_1", point=(0.0, 0.0), wrench=(0.0, 2.0, 0.0), moment=0.0),
...              SimpleNamespace(symbol="f_2", point=(0.0, 1.0), wrench=(0.0, 1.0, 0.0), moment=0.0)]
>>> d = trees_picture(pose, tips, reactions=reactions, v=np.zeros((2, 3)), a=np.zeros((2, 3)),
...                   overlays={"reaction forces": True}).to_dict()
>>> [e["symbol"] for e in d["elements"] if e["id"].startswith(("f", "F"))]
['f₁', 'f₂']
"""
from __future__ import annotations

import math

import numpy as np

from planargeo.draw.pictures.common import builder
from planargeo.draw.picture import PX_PER_PT, Picture
from planargeo.draw.pictures._words import SUB
from planargeo.draw.pictures.kit import (clearest_sides, ground, num, pin_force, pin_heads, pole_overlays, scale_bar,
                                        side_label)
from planargeo.draw.pictures.slider_crank import CONTACT_COLOR
from planargeo.draw.style import COLORS

__all__ = ["trees_picture", "symbol_of", "FORCE_LENGTH", "FADED", "VIEW"]

#: length (m) of the largest force's arrow
FORCE_LENGTH = 0.9
#: opacity of the forces outside the focus
FADED = 0.25
#: the view (m): every pose the links can reach (body 1 and three more links from the pivot)
VIEW = (-4.3, 4.3, -4.3, 4.3)


def symbol_of(sym: str) -> str:
    """``"f_2"`` -> ``"f₂"``: a reaction's symbol as drawn.

    Parameters
    ----------
    sym : str

    Returns
    -------
    str

    Examples
    --------
    >>> symbol_of("F_1")
    'F₁'
    """
    return sym.replace("_", "").translate(SUB)


@builder
def trees_picture(pose, tips, *, reactions, contacts=(), v, a, overlays: dict, focus: str = "all",
                  view=VIEW, size=(560, 560)) -> Picture:
    """The picture of one state of the nine links (module docstring).

    Parameters
    ----------
    pose : array_like (9, 3)
        ``[x, y, angle]`` of each body's joint.
    tips : array_like (9, 2)
        The far end of each link.
    reactions : sequence
        :func:`planargeo.scenes.trees.tree_reactions` (``symbol``, ``point``, ``wrench``, ``moment``).
    contacts : sequence of str
        Names of the loop-closing pins (``"4-7"``, ``"8-9"``).
    v, a : array_like (9, 3)
        Velocity and acceleration twists of the bodies.
    overlays : dict
        ``{"reaction forces", "velocity poles", "acceleration poles": shown}``.
    focus : str
        A force's symbol (``"f₄"``) drawn bold, the others faded; ``"all"`` for none.
    """
    pose = np.asarray(pose, dtype=float)
    tips = np.asarray(tips, dtype=float)
    n = len(pose)
    pic = Picture(view, size=size, ticks=False, margin=(6, 6, 6, 6))
    ground(pic, "ground", (0.0, 0.0), width=0.9, desc="the ground: body 1 turns about the pivot (0, 0) m")
    links = np.stack([pose[:, :2], tips], axis=1)                   # (n, 2, 2) segments
    sides = clearest_sides(links)                                   # each link's label off the others
    for i in range(n):
        pic.path(f"body {i + 1}", [pose[i, :2], tips[i]], role="body", symbol=str(i + 1),
                 color=COLORS["ground"], width=2.5 * PX_PER_PT, z=5,
                 desc=f"link (Fig 9.1): body {i + 1}, {math.hypot(*(tips[i] - pose[i, :2])):.3g} m long, "
                      f"at {math.degrees(pose[i, 2]):.4g}°")
        side_label(pic, pose[i, :2], tips[i], str(i + 1), None, gap=3.0, side=sides[i])
    pic.marks("joints", pose[:, :2], role="body", symbol="joints", color=COLORS["ground"], size=5.0, z=6,
              desc=f"the {n} joints: joint 1 at the pivot (0, 0) m")
    contact = [x for x in reactions if x.symbol.startswith("F")]
    if contact:
        pins = np.array([x.point for x in contact])
        pic.marks("pins", pins, role="reaction", symbol="pins", color=COLORS["reaction"], size=10.0, z=5,
                  desc="the pins closing the loops (Fig 9.2): " + ", ".join(
                      f"tips of bodies {c} at ({num(p[0])}, {num(p[1])}) m" for c, p in zip(contacts, pins)))
    if overlays.get("reaction forces"):
        size_of = {x.symbol: math.hypot(*np.asarray(x.wrench, float)[:2]) for x in reactions}
        fmax = max(size_of.values(), default=0.0)
        names = dict(zip((f"F_{k + 1}" for k in range(len(contacts))), contacts))
        heads = pin_heads(reactions, (0.4, -0.4, 0.25, -0.25), links)
        for x, head in zip(reactions, heads):
            sym = symbol_of(x.symbol)
            w = np.asarray(x.wrench, float)
            F = size_of[x.symbol]
            on = focus in ("all", sym)
            if x.symbol.startswith("f"):
                i = int(x.symbol[2:])
                meaning, eq, color = "pin force", "9.61", COLORS["reaction"]
                at = f"joint {i}, the wrench on body {i} from its parent"
            else:
                meaning, eq, color = "contact force", "9.71", CONTACT_COLOR
                at = f"the pin joining the tips of bodies {names[x.symbol]}"
            # drawn as the unit force's wrench times F / fmax: a ratio, never a scale 1/fmax that
            # overflows when the largest force is subnormal; labelled clearest of the links
            wn = w / F * (F / fmax) if F else w
            pin_force(pic, sym, x, wn, words=f"{meaning} ({eq}): {at}", about="pin",
                      tiny=1e-9 * max(fmax, 1e-300), head=head, scale=FORCE_LENGTH,
                      role="reaction" if sym[0] == "f" else "momentum", color=color, reach=0.45,
                      width=(2.4 if focus == sym else 1.0) * PX_PER_PT, z=9 if focus == sym else 8,
                      label=None if on else "", opacity=1.0 if on else FADED)
    pole_overlays(pic, v, a, overlays, [f"body {i + 1}" for i in range(n)])
    scale_bar(pic)
    return pic
