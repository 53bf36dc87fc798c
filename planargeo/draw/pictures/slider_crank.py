"""The slider-crank's picture (thesis 9.3–9.6, 9.61, Fig 9.3): links, piston, pin forces to scale.

The crank ``1``, rod ``2`` and piston ``3`` on the slide, the joint angles (9.6), the pin and
bearing forces (9.61, 9.71) with their lever arms, the poles if asked, a scale bar and a
banner at a dead centre.

Examples
--------
>>> from types import SimpleNamespace
>>> def through(p, f):                    # a force through the point p: its moment about the origin
...     return SimpleNamespace(point=p, wrench=(f[0], f[1], p[0] * f[1] - p[1] * f[0]), moment=0.0)
>>> pose = [[0.0, 0.0, 0.4], [2.108, 0.895, 2.006], [0.0, 5.429, 1.571]]
>>> reactions = {"f_1": through((0.0, 0.0), (-126.4, -50.0)), "f_2": through((2.108, 0.895), (-40.4, -21.9)),
...              "f_3": through((0.0, 5.429), (24.0, 1.1)), "F_1": through((0.0, 5.929), (-24.0, 0.0))}
>>> twists = [[0.0, 0.0, 20.0], [1.0, 2.0, 3.0], [0.0, 50.5, 0.0]]
>>> pic = slider_crank_picture(pose, r=2.29, t=0.5, q=[0.4, 1.6, -0.44], reactions=reactions, v=twists,
...                            a=twists, h=5.929, overlays={"reaction forces": True},
...                            view=slider_crank_view(2.29, 5.0, 0.5))
>>> sorted(e["symbol"] for e in pic.to_dict()["elements"] if e["role"] in ("reaction", "momentum"))
['F₃', 'f₁', 'f₂', 'f₃']
"""
from __future__ import annotations

import math

import numpy as np

from planargeo.draw.pictures.common import builder
from planargeo.draw.picture import PX_PER_PT, Picture
from planargeo.draw.pictures.kit import (clearest_sides, ground, label_at, num, pin_force, pin_heads, pole_overlays,
                                        scale_bar, side_label)
from planargeo.draw.style import COLORS, OKABE_ITO

__all__ = ["slider_crank_picture", "slider_crank_view", "CONTACT_COLOR", "REACTIONS", "FORCE_LENGTH"]

#: colour of contact (loop-closing) forces, apart from the joints' reaction green (Okabe-Ito purple)
CONTACT_COLOR = OKABE_ITO["purple"]
#: the reactions drawn: (key of the state's reactions, symbol, kind, equation, where it acts, colour)
REACTIONS = (
    ("f_1", "f₁", "pin force", "9.61", "at the crank pivot, on the crank from the ground", COLORS["reaction"]),
    ("f_2", "f₂", "pin force", "9.61", "at the crank pin, on the rod from the crank", COLORS["reaction"]),
    ("f_3", "f₃", "pin force", "9.61", "at the wrist pin, on the piston from the rod", COLORS["reaction"]),
    ("F_1", "F₃", "bearing force", "9.71", "of the slide on the piston", CONTACT_COLOR),
)
#: length (m) of the largest force's arrow
FORCE_LENGTH = 2.4
#: half width of the slide (m)
BORE = 0.35
_BODIES = ("crank", "rod", "piston")
#: radii (m) of the arcs of ψ, θ, φ at the crank pivot, the crank pin and the wrist pin
ARC_RADII = (0.8, 0.7, 0.9)


def _angle_arc(pic: Picture, sym: str, centre, start: float, turn: float, radius: float, desc: str,
               ray: float | None = None, ray_desc: str = "") -> None:
    """The angle ``sym``: an arc of ``radius`` (m) about ``centre`` from the direction ``start`` (rad)
    turning ``turn`` (rad, counter-clockwise positive), a dashed ray along ``ray`` (rad; default ``start``:
    the side that is no link), its symbol just outside the arc's middle."""
    c = np.asarray(centre, dtype=float)
    along = start if ray is None else ray
    line = np.array([c, c + 1.3 * radius * np.array([math.cos(along), math.sin(along)])])
    pic.path(f"angle {sym} from", line, role="construct", symbol=f"{sym} side", color=ANGLE_COLOR,
             width=0.7 * PX_PER_PT, dash=[2.0, 2.0], z=3,
             desc=f"{ray_desc or 'the side'}: {sym} is measured from it, at "
                  f"{num(180.0 - (180.0 - math.degrees(along)) % 360.0, 4)}° from the x axis")
    n = max(2, int(math.ceil(abs(turn) / math.radians(4.0))) + 1)
    ts = start + np.linspace(0.0, turn, n)
    arc = c + radius * np.column_stack([np.cos(ts), np.sin(ts)])
    pic.path(f"angle {sym}", arc, role="construct", symbol=sym, color=ANGLE_COLOR, width=0.9 * PX_PER_PT, z=3,
             desc=desc)
    mid = start + 0.5 * turn
    label_at(pic, c + radius * np.array([math.cos(mid), math.sin(mid)]), sym, gap=3.0,
             dy=3.0 * math.sin(mid), ha="left" if math.cos(mid) >= 0 else "right", va="center")


#: colour of the joint angles' arcs and symbols
ANGLE_COLOR = "#303030"


def slider_crank_view(r: float, l: float, t: float):
    """The view ``(x0, x1, y0, y1)`` (m): the crank's circle and the piston at its highest, with room.

    Parameters
    ----------
    r, l, t : float
        Crank radius, rod length, half height of the piston (m).

    Returns
    -------
    tuple of float

    Examples
    --------
    >>> slider_crank_view(2.29, 5.0, 0.5)
    (-4.5, 4.5, -3.49, 9.29)
    """
    return (-4.5, 4.5, -r - 1.2, max(9.0, r + l + 2 * t + 1.0))


@builder
def slider_crank_picture(pose, *, r: float, t: float, q, reactions: dict, v, a, h: float,
                         overlays: dict, view, banner: str = "", psi: float | None = None,
                         size=(560, 620)) -> Picture:
    """The picture of one state of the slider-crank (module docstring).

    Parameters
    ----------
    pose : array_like (3, 3)
        ``[x, y, angle]`` of the crank, rod and piston joints.
    r, t, h : float
        Crank radius, half height and height of the piston (m).
    q : array_like (3,)
        Joint angles ``ψ, θ, φ`` (rad).
    reactions : dict
        ``{"f_1", "f_2", "f_3", "F_1": reaction}`` with ``point``, ``wrench``, ``moment``.
    v, a : array_like (3, 3)
        Velocity and acceleration twists of the three bodies.
    overlays : dict
        ``{"reaction forces", "velocity poles", "acceleration poles": shown}``.
    banner : str
        A dead centre named ("" for none).
    psi : float, optional
        The crank angle ψ (degrees) as the readout reads it (the slider's −180° at the start); default
        ``q[0]`` in (−180°, 180°].
    """
    pose = np.asarray(pose, dtype=float)
    pic = Picture(view, size=size, ticks=False, margin=(6, 6, 6, 6))
    x0, x1, y0, y1 = pic.box
    pivot, pin, wrist = pose[0, :2], pose[1, :2], pose[2, :2]
    read_psi = psi
    psi, theta, phi = (180.0 - (180.0 - math.degrees(float(x))) % 360.0 for x in q)    # in (−180°, 180°]
    if read_psi is not None:
        psi = float(read_psi)
    pic.path("slide", [[-BORE, y0], [-BORE, y1], [np.nan, np.nan], [BORE, y0], [BORE, y1]], role="construct",
             symbol="slide", color=COLORS["ground"], width=1.0 * PX_PER_PT, dash=[4.0, 3.0], z=1,
             desc=f"the slide (9.6): the piston moves along it, {2 * BORE:.3g} m wide")
    ground(pic, "ground", (0.0, -0.15), width=0.9, desc="the ground: the crank turns about the pivot (0, 0) m")
    pic.path("crank", [pivot, pin], role="body", symbol="1", color=COLORS["ground"], width=4.0 * PX_PER_PT, z=5,
             desc=f"crank, body 1 (9.6): r = {r:.3g} m, at ψ = {num(psi, 4)}°")
    links = np.array([[pivot, pin], [pin, wrist]])
    sides = clearest_sides(links)                                   # each beside its link, away from the other
    side_label(pic, pivot, pin, "1", None, gap=4.0, side=sides[0])
    pic.path("rod", [pin, wrist], role="body", symbol="2", color=COLORS["body"], width=3.0 * PX_PER_PT, z=5,
             desc=f"rod, body 2 (9.6): l = {math.hypot(*(wrist - pin)):.3g} m, at θ = {num(theta, 4)}°")
    side_label(pic, pin, wrist, "2", None, gap=4.0, side=sides[1])
    box = np.array([[-0.3, 0.0], [0.3, 0.0], [0.3, 2 * t], [-0.3, 2 * t]]) + wrist
    pic.path("piston", box, role="body", symbol="3", closed=True, fill=COLORS["body"], alpha=0.6,
             color="#000000", width=1.0 * PX_PER_PT, z=4,
             desc=f"piston, body 3 (9.73): height h = {h:.4g} m, speed {num(float(v[2][1]), 4)} m/s")
    label_at(pic, wrist + np.array([0.3, t]), "3", gap=4.0, dy=0.0, va="center")     # beside it, clear of its top
    pic.marks("pins", [pivot, pin, wrist], role="body", symbol="pins", color=COLORS["ground"], size=7.0, z=6,
              desc=f"the pins: crank pivot (0, 0) m, crank pin ({num(pin[0])}, {num(pin[1])}) m, "
                   f"wrist pin ({num(wrist[0])}, {num(wrist[1])}) m")
    # the joint angles (9.6) as arcs at their joints, each from the direction it is measured from (a short
    # dashed ray: the x axis, the crank produced, the rod produced) to its link, the symbol by the arc
    a_crank = math.atan2(pin[1] - pivot[1], pin[0] - pivot[0])
    a_rod = math.atan2(wrist[1] - pin[1], wrist[0] - pin[0])
    # (φ, from the rod produced to the piston's axis, is drawn as its vertical angle below the wrist pin:
    # from the rod to the piston's axis produced downwards, clear of the piston)
    for sym, centre, start, val, radius, ray, meaning, ray_desc in (
            ("ψ", pivot, 0.0, psi, ARC_RADII[0], None, "crank angle, from the x axis to the crank", "the x axis"),
            ("θ", pin, a_crank, theta, ARC_RADII[1], None, "turn of the rod from the crank produced, at the crank "
             "pin (from closing the loop)", "the crank produced beyond the crank pin"),
            ("φ", wrist, a_rod + math.pi, phi, ARC_RADII[2], -math.pi / 2, "turn of the piston from the rod, at "
             "the wrist pin (the piston itself stays upright; drawn below the pin, between the rod and the "
             "piston's axis produced)", "the piston's axis produced below the wrist pin")):
        _angle_arc(pic, sym, centre, start, math.radians(val), radius,
                   f"joint angle (9.6): {meaning}, {sym} = {num(val, 4)}°", ray, ray_desc)
    if overlays.get("reaction forces"):
        size_of = {k: math.hypot(*np.asarray(x.wrench, float)[:2]) for k, x in reactions.items()}
        fmax = max(size_of.values(), default=0.0)
        scale = FORCE_LENGTH / fmax if fmax > 0 else 0.0
        obstacles = np.concatenate([links, np.stack([box, np.roll(box, -1, axis=0)], axis=1)])
        # the labels on the lines 0.9 to 1.2 m from the joints, clearest of the links and the piston
        heads = pin_heads([reactions[r[0]] for r in REACTIONS], (0.9, -0.9, 1.2, -1.2), obstacles)
        for (key, sym, meaning, eq, at, color), head in zip(REACTIONS, heads):
            x = reactions[key]
            foot = pin_force(pic, sym, x, x.wrench, words=f"{meaning} ({eq}): {at}", about="joint",
                             tiny=1e-9 * max(fmax, 1.0), head=head, scale=scale, color=color, reach=1.2,
                             role="reaction" if key.startswith("f") else "momentum", width=1.0 * PX_PER_PT, z=8)
            if foot is not None and math.hypot(*(foot - np.asarray(x.point))) > 1e-9:
                pic.path(f"{sym} lever", [x.point, foot], role="construct", symbol=f"{sym} arm", color=color,
                         width=0.8 * PX_PER_PT, dash=[1.0, 2.0], z=8,
                         desc=f"lever arm of {sym} about its joint: {math.hypot(*(foot - x.point)):.3g} m "
                              f"(a couple the joint carries)")
    pole_overlays(pic, v, a, overlays, [f"of the {b}" for b in _BODIES[:3]], scales=(0.5, 0.05))
    scale_bar(pic)
    if banner:
        pic.text("banner", (x1, y1), banner, color="#7a3d00", ha="right", va="top", dx=-8.0, dy=-8.0,
                 symbol="dead centre", desc=f"{banner}: the crank and the rod in line, ψ = {num(psi, 4)}°")
    return pic
